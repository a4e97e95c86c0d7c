"""Link shapes from the lengths people write: triangulation, midpoints, fractions, sides."""

from __future__ import annotations

import math
import re

from ..i18n import Text
from .reader import Table

POINT_NAME = re.compile(r"^[A-Z][0-9a-z_']*$")
_TOKEN = re.compile(r"[A-Z][0-9a-z_']*")
_SIDE = re.compile(r"^\s*(left|right)\s+of\s+(\S+?)\s*(?:->|→|-|\s)\s*(\S+)\s*$")
_MIDPOINT = re.compile(r"^\s*midpoint\s+(?:of\s+)?(\S+?)\s*(?:->|-|\s)\s*(\S+)\s*$")
_FRACTION = re.compile(r"^\s*([0-9.,]+)\s+of\s+(\S+?)\s*(?:->|-|\s)\s*(\S+)\s*$")


def split_pair(key: str) -> tuple[str, str] | None:
    """Split "AB", "O1A", "B-C", "O1 A" into two point names."""
    parts = [p for p in re.split(r"[\s\-–>→]+", key.strip()) if p]
    if len(parts) == 2 and all(POINT_NAME.match(p) for p in parts):
        return parts[0], parts[1]
    tokens = _TOKEN.findall(key)
    if len(tokens) == 2 and "".join(tokens) == key.strip():
        return tokens[0], tokens[1]
    return None


def parse_side(text: str) -> tuple[str, str, int] | None:
    """Parse "left of B->C" into (B, C, +1); right gives -1."""
    m = _SIDE.match(text)
    if not m:
        return None
    return m.group(2), m.group(3), 1 if m.group(1) == "left" else -1


def triangulate(table: Table, lengths: dict[str, float], keys: dict[str, str],
                sides: dict[str, tuple[str, str, int]]) -> dict[str, tuple[float, float]]:
    """Place the points of a link in its frame from pairwise distances.

    ``lengths`` maps (sorted) "P|Q" to metres; the first key's points define the x axis.
    """
    pairs = [tuple(k.split("|")) for k in lengths]
    order: list[str] = []
    for p, q in pairs:
        for x in (p, q):
            if x not in order:
                order.append(x)
    first = pairs[0]
    local: dict[str, tuple[float, float]] = {
        first[0]: (0.0, 0.0),
        first[1]: (lengths["|".join(first)], 0.0),
    }

    def dist(a: str, b: str) -> float | None:
        return lengths.get(f"{a}|{b}", lengths.get(f"{b}|{a}"))

    progress = True
    while progress and len(local) < len(order):
        progress = False
        for x in order:
            if x in local:
                continue
            known = [(p, dist(x, p)) for p in local if dist(x, p) is not None]
            if len(known) < 2:
                continue
            (a, ra), (b, rb) = known[0], known[1]
            local[x] = _place_third(table, x, local, a, ra, b, rb, sides, keys)  # type: ignore[arg-type]
            progress = True
    missing = [x for x in order if x not in local]
    if missing:
        raise table.error("lengths", Text(
            "errmsg2.scene_geometry.needs_triangle",
            {"point": missing[0]}))
    for key, value in lengths.items():
        p, q = key.split("|")
        (x1, y1), (x2, y2) = local[p], local[q]
        got = math.hypot(x2 - x1, y2 - y1)
        if abs(got - value) > 1e-9 * max(value, 1e-12):
            raise table.error(f"lengths.{keys[key]}", Text(
                "errmsg2.scene_geometry.inconsistent_length",
                {"triangle": f'{got * 1000:.6g}', "value": f'{value * 1000:.6g}'}))
    return local


def _place_third(table: Table, x: str, local: dict[str, tuple[float, float]], a: str, ra: float,
                 b: str, rb: float, sides: dict[str, tuple[str, str, int]],
                 keys: dict[str, str]) -> tuple[float, float]:
    (ax, ay), (bx, by) = local[a], local[b]
    d = math.hypot(bx - ax, by - ay)
    if d == 0 or ra + rb < d * (1 - 1e-12) or abs(ra - rb) > d * (1 + 1e-12):
        raise table.error(
            "lengths",
            Text(
            "errmsg2.scene_geometry.no_triangle",
            {"a": a, "b": b, "x": x, "ra": f'{ra * 1000:.6g}', "rb": f'{rb * 1000:.6g}',
             "d": f'{d * 1000:.6g}'}),
        )
    u = ((bx - ax) / d, (by - ay) / d)
    along = (ra * ra - rb * rb + d * d) / (2 * d)
    h = math.sqrt(max(ra * ra - along * along, 0.0))
    cand = {
        s: (ax + along * u[0] - s * h * u[1], ay + along * u[1] + s * h * u[0]) for s in (1, -1)
    }
    if h <= 1e-12 * d:
        return cand[1]
    if x not in sides:
        raise table.error("side", Text(
            "errmsg2.scene_geometry.either_side",
            {"x": x, "a": a, "b": b}))
    p, q, s = sides[x]
    if p not in local or q not in local:
        raise table.error(f"side.{x}", Text(
            "errmsg2.scene_geometry.place_before",
            {"p": p, "q": q, "x": x}))
    (px, py), (qx, qy) = local[p], local[q]
    for sign, (cx, cy) in cand.items():
        c = (qx - px) * (cy - py) - (qy - py) * (cx - px)
        if c * s > 0:
            return cand[sign]
    raise table.error(f"side.{x}", Text(
        "errmsg2.scene_geometry.on_line",
        {"x": x, "p": p, "q": q}))


def extra_point(table: Table, name: str, spec: object,
                local: dict[str, tuple[float, float]]) -> tuple[float, float]:
    """Place a point given as "midpoint B C", "0.35 of A B" or [x, y] in the link frame."""
    key = f"points.{name}"
    if isinstance(spec, list):
        if len(spec) != 2:
            raise table.error(key, Text("errmsg2.scene_geometry.xy_units"))
        return (
            table.value_quantity(spec[0], key, "length"),
            table.value_quantity(spec[1], key, "length"),
        )
    if not isinstance(spec, str):
        raise table.error(key, Text(
            "errmsg2.scene_geometry.extra_spec",
            {"value": repr(spec)}))
    m = _MIDPOINT.match(spec)
    frac: float
    if m:
        p, q, frac = m.group(1), m.group(2), 0.5
    else:
        m = _FRACTION.match(spec)
        if not m:
            raise table.error(
                key, Text("errmsg2.scene_geometry.extra_spec2", {"value": repr(spec)})
            )
        frac = float(m.group(1).replace(",", "."))
        p, q = m.group(2), m.group(3)
    for r in (p, q):
        if r not in local:
            raise table.error(key, Text(
                "errmsg2.scene_geometry.not_of_link",
                {"point": r, "points": ', '.join(local)}))
    (x1, y1), (x2, y2) = local[p], local[q]
    return (x1 + frac * (x2 - x1), y1 + frac * (y2 - y1))
