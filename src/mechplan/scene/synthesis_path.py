"""The keys of a path-generation synthesis (``problem = "path"``)."""

from __future__ import annotations

from typing import Any

from ..errors import SceneError
from ..i18n import Text
from .reader import Table

MAX_PATH_POINTS = 50


def _error(t: Table, key: str, msgid: str, **values: str) -> SceneError:
    return t.error(key, Text(f"synth.error.{msgid}", values))


def _angles(s: Table, key: str, count: int) -> tuple[float, ...]:
    """``count`` angles, e.g. ``["30 deg", "60 deg"]``."""
    raw = s.raw(key, required=True)
    if not isinstance(raw, list) or len(raw) != count:
        raise _error(s, key, "numbers", n=str(count), value=repr(raw)[:80])
    return tuple(s.value_quantity(v, f"{key}[{i}]", "angle") for i, v in enumerate(raw))


def path_keys(s: Table) -> dict[str, Any]:
    """The points P1…Pn (3…50), the crank rotations β2…βn, and the coupler and rocker rotations
    at the second and last points (exact for three points; the start of the least squares)."""
    raw = s.raw("points", required=True)
    if not isinstance(raw, list) or not 3 <= len(raw) <= MAX_PATH_POINTS or not all(
            isinstance(p, list) and len(p) == 2 for p in raw):
        raise _error(s, "points", "path_points", n=str(MAX_PATH_POINTS), value=repr(raw)[:80])
    pts = tuple((s.value_quantity(p[0], f"points[{i}][0]", "length"),
                 s.value_quantity(p[1], f"points[{i}][1]", "length"))
                for i, p in enumerate(raw))
    beta = _angles(s, "crank_rotations", len(pts) - 1)
    alpha = _angles(s, "coupler_rotations", 2)
    gamma = _angles(s, "rocker_rotations", 2)
    return {"path_points": pts, "crank_rotations": beta,
            "coupler_rotations": (alpha[0], alpha[1]), "rocker_rotations": (gamma[0], gamma[1])}
