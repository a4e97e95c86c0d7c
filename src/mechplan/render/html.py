"""The live page: one self-contained HTML file (script, styles and font subsets inlined) that
replays the drawing step by step and animates the mechanism over the crank angle.

The document comes from ``sheet/live.py``; this backend only turns its drafting primitives into
compact SVG drawing instructions (y down, paper millimetres rounded to 0.01 mm) and embeds the
JSON beside the page's script (``render/page/``). The script shows, hides and moves; it computes
no geometry.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from importlib import resources
from typing import Any

import numpy as np

from mechplan.drafting.fonts import baseline_point, em_size_mm
from mechplan.drafting.primitives import (
    DASH_PATTERNS_MM,
    ROLE_STYLES,
    Arc,
    Arrow,
    Circle,
    HAlign,
    Line,
    Polyline,
    Primitive,
    Sheet,
    Text,
)
from mechplan.errors import DrawingError
from mechplan.render.svg import font_family_css
from mechplan.render.svg_fonts import font_faces_css

#: paper precision of the page's coordinates, mm
DIGITS = 2
DRAWN = (Line, Polyline, Arc, Circle, Text, Arrow)
_ANCHOR = {HAlign.LEFT: "start", HAlign.CENTER: "middle", HAlign.RIGHT: "end"}


#: the font family of most texts (Latin, Cyrillic, digits): set once by the page's style
#: (``svg text``) rather than written with each of the thousands of texts of a sheet
TEXT_FONT = font_family_css("0")


def _r(v: float) -> float:
    r = round(float(v), DIGITS)
    return 0.0 if r == 0 else r


def _xy(p: tuple[float, float]) -> str:
    return f"{_r(p[0])} {_r(-p[1])}"


def _significant(v: float) -> float | None:
    """A value of the data (machine format, not text for a reader): 7 significant digits."""
    return float(f"{v:.7g}") if math.isfinite(v) else None


def _path(p: Primitive) -> tuple[str, bool]:
    """SVG path data of a line-like primitive (y down) and whether it is filled."""
    if isinstance(p, Line):
        return f"M{_xy(p.start)}L{_xy(p.end)}", False
    if isinstance(p, Polyline):
        d = "M" + "L".join(_xy(v) for v in p.points) + ("Z" if p.closed else "")
        return d, p.filled
    if isinstance(p, Arc):
        sweep = (p.end_deg - p.start_deg) % 360.0 or 360.0
        t0, t1 = math.radians(p.start_deg), math.radians(p.start_deg + sweep)
        cx, cy = p.center
        a = (cx + p.radius * math.cos(t0), cy + p.radius * math.sin(t0))
        b = (cx + p.radius * math.cos(t1), cy + p.radius * math.sin(t1))
        r = _r(p.radius)
        # counter-clockwise with y up is sweep-flag 0 with y down
        return f"M{_xy(a)}A{r} {r} 0 {1 if sweep > 180 else 0} 0 {_xy(b)}", False
    raise DrawingError(f"the HTML page cannot draw {type(p).__name__}")


def primitive(p: Primitive) -> dict[str, Any]:
    """One primitive as the page draws it: ``d`` (path), ``c`` (circle) or ``t`` (text)."""
    if not isinstance(p, DRAWN):
        raise DrawingError(f"the HTML page cannot draw {type(p).__name__}")
    role = p.role.value.lower()
    if isinstance(p, Circle):
        return {"c": [_r(p.center[0]), _r(-p.center[1]), _r(p.radius)], "r": role}
    if isinstance(p, Text):
        x, y = baseline_point(p)
        out: dict[str, Any] = {"t": p.string, "x": _r(x), "y": _r(-y), "s": _r(em_size_mm(p)),
                               "a": _ANCHOR[p.halign]}
        family = font_family_css(p.string)
        if family != TEXT_FONT:             # the page's style gives every other text its font
            out["f"] = family
        if p.rotation_deg:
            out["o"] = _r(-p.rotation_deg)
        return out
    if isinstance(p, Arrow):
        shaft = p.shaft()
        head = "M" + "L".join(_xy(v) for v in p.head()) + "Z"
        return {"d": (f"M{_xy(shaft.start)}L{_xy(shaft.end)}" if shaft else ""), "h": head,
                "r": role}
    d, filled = _path(p)
    return {"d": d, "r": role, **({"fill": 1} if filled else {})}


def _frames(frames: list[list[Primitive]]) -> list[str]:
    """One path per frame (the arrow heads joined in as closed sub-paths)."""
    out = []
    for prims in frames:
        parts = []
        for p in prims:
            if isinstance(p, Arrow):
                shaft = p.shaft()
                parts.append((f"M{_xy(shaft.start)}L{_xy(shaft.end)}" if shaft else "")
                             + "M" + "L".join(_xy(v) for v in p.head()) + "Z")
            elif isinstance(p, Circle):
                (cx, cy), r = p.center, _r(p.radius)
                parts.append(f"M{_xy((cx - p.radius, cy))}A{r} {r} 0 1 0 {_xy((cx + p.radius, cy))}"
                             f"A{r} {r} 0 1 0 {_xy((cx - p.radius, cy))}")
            else:
                parts.append(_path(p)[0])
        out.append("".join(parts))
    return out


def _plain(value: Any) -> Any:
    """The document as JSON values: primitives drawn, arrays rounded to paper precision."""
    if isinstance(value, DRAWN):
        return primitive(value)
    if isinstance(value, np.ndarray):
        arr = np.asarray(value, dtype=float)
        if arr.ndim == 2:          # (frames, 2) points in paper mm: y down, NaN as null
            arr = np.round(arr * np.array([1.0, -1.0]), DIGITS)
            return [v if math.isfinite(v) else None for v in arr.ravel().tolist()]
        return [_significant(v) for v in arr.ravel().tolist()]    # values, angles
    if isinstance(value, Mapping):
        if "frames" in value and value.get("kind") in ("link", "segment"):
            return {**{k: _plain(v) for k, v in value.items() if k != "frames"},
                    "d": _frames(value["frames"])}
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, tuple) and len(value) == 2 and isinstance(value[0], DRAWN):
        return {**primitive(value[0]), "k": value[1]}           # (primitive, replay step)
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, np.generic):
        return _plain(value.item())
    return value


def _strings(value: Any) -> list[str]:
    if isinstance(value, str):
        return [value]
    if isinstance(value, Mapping):
        return [s for v in value.values() for s in _strings(v)]
    if isinstance(value, (list, tuple)):
        return [s for v in value for s in _strings(v)]
    return []


def _role_css() -> str:
    rules = []
    for role, st in ROLE_STYLES.items():
        dash = " ".join(str(v) for v in DASH_PATTERNS_MM[st.linetype]) or "none"
        rules.append(f".role-{role.value.lower()} {{ stroke: {st.ink}; stroke-width: "
                     f"{st.lineweight_mm}; stroke-dasharray: {dash}; }}")
    return "\n".join(rules)


def _asset(name: str) -> str:
    return (resources.files("mechplan.render") / "page" / name).read_text(encoding="utf-8")


def _script_json(doc: Any) -> str:
    """JSON safe inside a <script> element (no "</" can end it)."""
    text = json.dumps(doc, ensure_ascii=False, separators=(",", ":"), allow_nan=False)
    return text.replace("</", "<\\/").replace("<!--", "<\\!--")


def to_html(doc: Mapping[str, Any]) -> str:
    """Return the live page of a document from :func:`mechplan.sheet.live.live_document`."""
    data = _plain(doc)
    chars = "".join(sorted(set("".join(_strings(data))) - {" "}))
    fonts = font_faces_css(Sheet(10.0, 10.0, (Text((0.0, 0.0), chars),), name="page"))
    title = str(doc.get("title") or doc.get("name") or "mechplan")
    title = title.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    page = _asset("page.html")
    return (page.replace("{{lang}}", str(doc.get("lang", "en")))
            .replace("{{title}}", title)
            .replace("/*{{fonts}}*/", fonts)
            .replace("/*{{roles}}*/", f"{_role_css()}\nsvg text {{ font-family: {TEXT_FONT}; }}")
            .replace("/*{{css}}*/", _asset("page.css"))
            .replace("{{data}}", _script_json(data))
            .replace("/*{{js}}*/", _asset("page.js")))


__all__ = ["DIGITS", "primitive", "to_html"]
