"""Parse a linkage-synthesis scene (``kind = "synthesis"``) into a
:class:`~mechplan.model.synthesis.SynthesisSpec`."""

from __future__ import annotations

import itertools
import math
from typing import Any

from ..drafting.fields import SHEETS, STANDARDS, TITLE_BLOCK_FIELDS
from ..errors import SceneError
from ..i18n import LANGUAGES, Text
from ..model.synthesis import FUNCTIONS, PROBLEMS, SynthesisSpec
from .document import parse_toml
from .reader import Table

TOP_KEYS = ("kind", "title", "language", "description", "synthesis", "drive", "positions",
            "drawing", "title_block")
#: the keys each problem takes besides ``problem``, ``K`` and ``gamma_min``
PROBLEM_KEYS = {
    "crank_rocker": ("swing", "rocker", "frame", "frame_angle", "lambda"),
    "slider_crank": ("stroke", "offset", "lambda", "gamma"),
    "coulisse": ("frame", "crank", "coulisse", "stroke"),
    "shaper": ("frame", "crank", "stroke", "rod"),
    "guidance": ("B", "C", "pivot_line"),
    "path": ("points", "crank_rotations", "coupler_rotations", "rocker_rotations"),
    "function": ("function", "x_range", "points", "count", "input_start", "input_range",
                 "output_start", "output_range", "frame"),
}
LENGTHS = ("rocker", "frame", "stroke", "offset", "crank", "coulisse", "rod")
MAX_K = 1e3


def _error(t: Table, key: str, msgid: str, **values: str) -> SceneError:
    return t.error(key, Text(f"synth.error.{msgid}", values))


def parse_synthesis(text: str, file: str = "<scene>") -> SynthesisSpec:
    """Parse the text of a synthesis scene; every error names the file and the key."""
    top = Table(parse_toml(text, file), "", file)
    top.check_keys(TOP_KEYS)
    s = top.table("synthesis", required=True)
    assert s is not None
    problem = s.string("problem", required=True, choices=PROBLEMS) or ""
    if problem in ("function", "guidance", "path"):
        s.check_keys(("problem", *PROBLEM_KEYS[problem]))
        k = 1.0
    else:
        s.check_keys(("problem", "K", "gamma_min", *PROBLEM_KEYS[problem]))
        k_raw = s.raw("K", required=True)
        k = s.quantity("K", "dimensionless", required=True) or 0.0
        if not 1.0 <= k < MAX_K or not math.isfinite(k):
            raise _error(s, "K", "k_range", value=repr(k_raw))
    fg: dict[str, Any] = _function_keys(s) if problem == "function" else {}
    if problem == "guidance":
        fg = {"guide_b": _positions(s, "B"), "guide_c": _positions(s, "C"),
              "pivot_line": _line(s)}
        if len(fg["guide_b"]) != len(fg["guide_c"]):
            raise _error(s, "C", "same_count")
    if problem == "path":
        from .synthesis_path import path_keys

        fg = path_keys(s)
    values: dict[str, float | None] = {}
    for key in LENGTHS:
        if key in PROBLEM_KEYS[problem]:
            values[key] = s.quantity(key, "length", positive=True)
    swing = s.quantity("swing", "angle", positive=True) if problem == "crank_rocker" else None
    frame_angle = (s.quantity("frame_angle", "angle", positive=True)
                   if problem == "crank_rocker" else None)
    if values.get("frame") is not None and frame_angle is not None:
        raise _error(s, "frame_angle", "frame_or_angle")
    lam = s.quantity("lambda", "dimensionless", positive=True) \
        if problem in ("slider_crank", "crank_rocker") else None
    if values.get("offset") is not None and lam is not None:
        raise _error(s, "lambda", "offset_or_lambda")
    if lam is not None and (values.get("frame") is not None or frame_angle is not None):
        raise _error(s, "lambda", "frame_or_lambda")
    gamma = s.quantity("gamma_min", "angle", positive=True)
    gamma_target = s.quantity("gamma", "angle", positive=True) if problem == "slider_crank" \
        else None
    if gamma_target is not None and (values.get("offset") is not None or lam is not None):
        raise _error(s, "gamma", "offset_or_lambda")
    speed, sense = 10.0, 1
    d = top.table("drive")
    if d is not None:
        d.check_keys(("speed", "sense"))
        speed = d.quantity("speed", "angular_velocity", 10.0, positive=True) or 10.0
        sense = 1 if d.string("sense", "ccw", choices=("ccw", "cw")) == "ccw" else -1
    count = 12
    p = top.table("positions")
    if p is not None:
        p.check_keys(("count",))
        count = p.raw("count", 12)
        if not isinstance(count, int) or isinstance(count, bool) or not 1 <= count <= 360:
            raise _error(p, "count", "count", value=repr(count))
    sheet = standard = None
    dr = top.table("drawing")
    if dr is not None:
        dr.check_keys(("sheet", "standard"))
        sheet = dr.string("sheet", None, choices=SHEETS)
        standard = dr.string("standard", None, choices=STANDARDS)
    fields: dict[str, str] = {}
    tb = top.table("title_block")
    if tb is not None:
        tb.check_keys(TITLE_BLOCK_FIELDS)
        for key in tb.data:
            fields[key] = tb.string(key) or ""
    return SynthesisSpec(
        problem=problem, k=k, title=top.string("title", "") or "",
        language=top.string("language", "en", choices=LANGUAGES) or "en", path=file,
        swing=swing, rocker=values.get("rocker"), frame=values.get("frame"),
        frame_angle=frame_angle, stroke=values.get("stroke"), offset=values.get("offset"),
        rod_ratio=lam, crank=values.get("crank"), coulisse=values.get("coulisse"),
        rod=values.get("rod"), gamma_limit=gamma, gamma_target=gamma_target, speed=speed,
        sense=sense, positions=count, sheet=sheet, standard=standard, title_block=fields, **fg)


MAX_POINTS = 50


def _numbers(s: Table, key: str, count: int | None) -> tuple[float, ...] | None:
    """A list of plain numbers (``count`` of them; None: from 3 to MAX_POINTS)."""
    raw = s.raw(key)
    if raw is None:
        return None
    want = count or 3
    sized = isinstance(raw, list) and (len(raw) == want if count
                                       else 3 <= len(raw) <= MAX_POINTS)
    if not isinstance(raw, list) or not sized or not all(
            isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
            for v in raw):
        raise _error(s, key, "numbers", n=str(want), value=repr(raw))
    return tuple(float(v) for v in raw)


def _function_keys(s: Table) -> dict[str, Any]:
    """The keys of a function generator."""
    s.string("function", required=True, choices=FUNCTIONS)
    x_range = _numbers(s, "x_range", 2)
    if x_range is None:
        raise _error(s, "x_range", "numbers", n="2", value="—")
    if not x_range[0] < x_range[1]:
        raise _error(s, "x_range", "x_order", value=repr(list(x_range)))
    points = _numbers(s, "points", None)
    if points is not None and not (x_range[0] <= points[0] and points[-1] <= x_range[1] and all(
            p < q for p, q in itertools.pairwise(points))):
        raise _error(s, "points", "points_order", value=repr(list(points)))
    count = s.raw("count", 3)
    if not isinstance(count, int) or isinstance(count, bool) or not 3 <= count <= MAX_POINTS:
        raise _error(s, "count", "numbers", n=f"3…{MAX_POINTS}", value=repr(count))
    if points is not None and s.has("count"):
        raise _error(s, "count", "points_or_count")
    return {"function": s.string("function"), "x_range": x_range, "points": points,
            "point_count": count,
            "input_start": s.quantity("input_start", "angle", 0.0) or 0.0,
            "input_range": s.quantity("input_range", "angle", required=True),
            "output_start": s.quantity("output_start", "angle", 0.0) or 0.0,
            "output_range": s.quantity("output_range", "angle", required=True)}




def _positions(s: Table, key: str) -> tuple[tuple[float, float], ...]:
    """Three positions of a point: [["x mm", "y mm"], …]."""
    raw = s.raw(key, required=True)
    if not isinstance(raw, list) or len(raw) not in (2, 3) or not all(
            isinstance(p, list) and len(p) == 2 for p in raw):
        raise _error(s, key, "three_points", value=repr(raw)[:80])
    return tuple((s.value_quantity(p[0], f"{key}[{i}][0]", "length"),
                  s.value_quantity(p[1], f"{key}[{i}][1]", "length"))
                 for i, p in enumerate(raw))


def _line(s: Table) -> tuple[tuple[float, float], float] | None:
    """``pivot_line = { through = ["x mm", "y mm"], angle = "0 deg" }``."""
    t = s.table("pivot_line")
    if t is None:
        return None
    t.check_keys(("through", "angle"))
    raw = t.raw("through", required=True)
    if not isinstance(raw, list) or len(raw) != 2:
        raise _error(t, "through", "three_points", value=repr(raw)[:80])
    point = (t.value_quantity(raw[0], "through[0]", "length"),
             t.value_quantity(raw[1], "through[1]", "length"))
    return point, t.quantity("angle", "angle", 0.0) or 0.0
