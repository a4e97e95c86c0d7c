"""Read a DXF submission as AutoCAD, LibreCAD or a student's script saves it (R12 to R2018):
lines and polylines on any layer, point markers, TEXT/MTEXT/ATTRIB labels (also inside blocks),
DIMENSION texts naming a segment, legacy Vietnamese encodings; damaged files are recovered."""

from __future__ import annotations

import itertools
import logging
import math
import re
import unicodedata
from collections.abc import Iterable
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np
from ezdxf import DXFError
from ezdxf.enums import MAP_TEXT_ENUM_TO_ALIGN_FLAGS, TextHAlign

from ..drafting.fonts import text_width_mm
from ..errors import CheckError
from ..i18n import Text
from ..limits import DXF_MAX_INSERT_DEPTH
from ..userfiles import DXF, read_bytes
from .dxf_open import (
    DAMAGE,
    ENTITY_DAMAGE,
    RECOVER_DAMAGE,
    Budget,
    Repairs,
    brief,
    load_document,
    refuse_before_loading,
    refuse_bombs,
)
from .notation import decode_legacy
from .read import DrawnLine, Note, Point, SheetText, Submission, parse_assignments
from .texts import T, has
from .texts import where as place

INSUNITS_MM = {0: 1.0, 1: 25.4, 2: 304.8, 4: 1.0, 5: 10.0, 6: 1000.0, 14: 100.0}


def read_dxf(path: Path, raw: bytes | None = None) -> Submission:
    """Read lines, polylines, point markers and texts of a DXF's model space (recovering damage);
    ``raw``: the file's bytes when they were read already."""
    import ezdxf

    sub = Submission(str(path), "dxf")
    if raw is None:
        raw = read_bytes(path, DXF, error=CheckError)
    if not raw.strip():
        raise CheckError(T("error.empty"), file=str(path))
    truncated = not raw.startswith(b"AutoCAD Binary DXF") and \
        raw.rstrip()[-3:].upper() != b"EOF"
    if truncated:
        sub.notes.append(Note("warning", T("note.truncated"), str(path)))
    repairs = Repairs()
    log = logging.getLogger("ezdxf")
    log.addHandler(repairs)   # the repair messages become notes, not lines on stderr
    try:
        refuse_before_loading(raw, str(path))
        doc, auditor = load_document(raw, repairs)
    except ezdxf.DXFStructureError as exc:
        raise CheckError(T("error.not_dxf", detail=brief(exc)), file=str(path)) from None
    except (ezdxf.DXFError, *DAMAGE, *RECOVER_DAMAGE) as exc:
        raise CheckError(T("error.damaged", detail=f"{exc.__class__.__name__}: {brief(exc)}"),
                         file=str(path)) from None
    finally:
        log.removeHandler(repairs)
    if repairs.messages:
        sub.notes.append(Note("warning", T("note.repaired_values", n=len(repairs.messages),
                                           example=repairs.messages[0]), str(path)))
    if auditor.has_errors:
        sub.notes.append(Note("warning", T("note.repaired_dxf", n=len(auditor.errors),
                                           example=auditor.errors[0].message), str(path)))
    try:
        code = int(doc.header.get("$INSUNITS", 0))
    except (TypeError, ValueError):
        code = 0
    scale = INSUNITS_MM.get(code)
    if scale is None:
        sub.notes.append(Note("warning", T("note.insunits", code=code), str(path)))
        scale = 1.0
        sub.units = T("units.insunits", code=code)
    elif code == 0:
        sub.units = T("units.unitless")
    else:
        sub.units = (unit_name(code) if code == 4 else
                     T("units.scaled", unit=unit_name(code), scale=scale))
    budget = Budget(str(path))
    try:
        refuse_bombs(doc, str(path))
        _collect(sub, doc.modelspace(), 1.0, depth=0, budget=budget)
        if not sub.lines:
            for layout in doc.layouts:
                if layout.name.lower() == "model":
                    continue
                _collect(sub, layout, 1.0, depth=0, budget=budget)
                if sub.lines:
                    sub.notes.append(Note("info", T("note.layout", name=layout.name), str(path)))
                    break
    except (DXFError, *DAMAGE, *RECOVER_DAMAGE) as exc:   # a damaged table of layouts, blocks
        raise CheckError(T("error.damaged", detail=f"{exc.__class__.__name__}: {brief(exc)}"),
                         file=str(path)) from None
    if sub.skipped:
        sub.notes.append(Note("info", T("note.skipped", n=sub.skipped), str(path)))
    _follow_leaders(sub)
    xs = [v for ln in sub.lines for v in (ln.start[0], ln.end[0])]
    ys = [v for ln in sub.lines for v in (ln.start[1], ln.end[1])]
    extent = max(max(xs) - min(xs), max(ys) - min(ys)) if xs else 0.0
    if scale != 1.0 and extent * scale > SHEET_MAX_MM and extent <= SHEET_MAX_MM:
        sub.notes.append(Note("warning", T("note.units_too_big", unit=unit_name(code),
                                           m=extent * scale / 1000, mm=extent), str(path)))
        sub.units = T("units.header", unit=unit_name(code))
        scale = 1.0
    for measured, t in sub.dimensions:       # "pb = <>": the measured length, in mm
        sub.texts.append(replace(t, text=f"{t.text} = {measured * scale:.3f}"))
    if scale != 1.0:
        _rescale(sub, scale)
    if not sub.lines and not sub.texts:
        raise CheckError(T("error.dxf_empty", truncated=T("error.truncated") if truncated else ""),
                         file=str(path))
    for text in sub.texts:
        for i, line in enumerate(text.text.splitlines(), start=1):
            where = T("where.text_line", where=text.where, n=i) if "\n" in text.text \
                else text.where
            sub.entries.extend(parse_assignments(line, where, at=text.centre))
    return sub


#: leader lines (a label tied to its point) are on a layer named like these
_LEADER_LAYER = re.compile(r"^(dimension|leader|выноск)", re.IGNORECASE)
#: a leader's end this near (drawing units) a text's box ties the text to the leader (the
#: box a reader estimates differs from the one drawn by about a millimetre)
LEADER_TOUCH = 2.5
#: how far (drawing units) past its end a leader is followed to see which text it points into,
#: and how near that line a text's box must come
LEADER_RAY = 5.0
LEADER_AIM = 0.3


def _follow_leaders(sub: Submission) -> None:
    """Leader lines are not lines of a plan: each runs from a point to its label (as a DXF
    LEADER does) and moves the text it points into (else the nearest one) near its end to its
    start — a label placed away from a crowded point is read at that point."""
    leaders = [ln for ln in sub.lines if _LEADER_LAYER.match(ln.layer)]
    if not leaders:
        return
    sub.lines = [ln for ln in sub.lines if not _LEADER_LAYER.match(ln.layer)]
    for ln in leaders:
        (x0, y0), (x1, y1) = ln.start, ln.end
        along = (x1 - x0) ** 2 + (y1 - y0) ** 2
        # the label lies beyond the leader's end, not beside it (a neighbour's label)
        ahead = [(t.distance(ln.end), i) for i, t in enumerate(sub.texts)
                 if (t.centre[0] - x0) * (x1 - x0) + (t.centre[1] - y0) * (y1 - y0) > along]
        # the width a reader estimates for a text may be off by a part of it
        near = [(d, i) for d, i in ahead if d <= LEADER_TOUCH + 0.5 * sub.texts[i].half[0]]
        if not near:
            continue
        # of the texts near its end, the one the leader points into (two labels may both be
        # near the end of a short leader: the one it runs toward is its own)
        norm = math.sqrt(along) or 1.0
        ray = np.asarray(ln.end) + np.outer(np.linspace(0.0, LEADER_RAY, 25),
                                            [(x1 - x0) / norm, (y1 - y0) / norm])
        _, _, i = min((float(sub.texts[i].distance(ray).min()) > LEADER_AIM, d, i)
                      for d, i in near)
        sub.texts[i] = replace(sub.texts[i], centre=ln.start, anchor=ln.start,
                               half=(0.05, 0.05), rotation=0.0)


#: a plan drawn on paper is smaller than an A0 sheet's long side with margin
SHEET_MAX_MM = 2000.0


def _rescale(sub: Submission, f: float) -> None:
    def q(p: Point) -> Point:
        return (p[0] * f, p[1] * f)

    sub.lines = [DrawnLine(q(ln.start), q(ln.end), ln.where, ln.layer) for ln in sub.lines]
    sub.markers = [(q(p), w) for p, w in sub.markers]
    sub.texts = [SheetText(t.text, q(t.centre), t.height * f, t.where, t.layer, q(t.anchor),
                           (t.half[0] * f, t.half[1] * f), t.rotation) for t in sub.texts]


def unit_name(code: int) -> str:
    """The name of a $INSUNITS code ("millimetres"), or the code itself when it has none."""
    return T(f"unit.{code}") if has(f"unit.{code}") else str(code)


def _where(e: Any, extra: str = "") -> str:
    handle = str(getattr(e.dxf, "handle", None) or "?")
    layer = str(getattr(e.dxf, "layer", "") or "")
    if layer not in ("", "0"):
        return place("entity_layer", type=e.dxftype(), handle=handle, layer=layer, extra=extra)
    return place("entity", type=e.dxftype(), handle=handle, extra=extra)


_SKIP_LINETYPE = re.compile(r"center|dashdot|dash_dot|chain|phantom|divide|border",
                            re.IGNORECASE)
_SKIP_LAYER = re.compile(r"^(frame|table|title|border|рамка|штамп|таблиц)", re.IGNORECASE)


def _skipped(e: Any, seen: dict[tuple[str, str], bool] | None = None) -> bool:
    """Axes and trajectories (dash-dot lines) and sheet frames and tables are not plan lines;
    ``seen`` remembers the answer for each layer and line type of one sheet."""
    layer_name = e.dxf.get("layer", "0") or "0"
    linetype = e.dxf.get("linetype", "BYLAYER") or "BYLAYER"
    key = (layer_name, linetype)
    if seen is not None and key in seen:
        return seen[key]
    if _SKIP_LAYER.match(layer_name):
        skip = True
    else:
        if linetype.upper() == "BYLAYER" and e.doc is not None:
            layer = e.doc.layers.get(layer_name) if layer_name in e.doc.layers else None
            linetype = (layer.dxf.get("linetype", "CONTINUOUS") if layer is not None
                        else "CONTINUOUS")
        skip = bool(_SKIP_LINETYPE.search(linetype))
    if seen is not None:
        seen[key] = skip
    return skip


def _collect(sub: Submission, space: Iterable[Any], scale: float, depth: int,
             via: str = "", budget: Budget | None = None, blocks: tuple[str, ...] = ()) -> None:
    """Read the entities of a layout or of an inserted block (``blocks``: the names of the blocks
    it stands in, outermost first)."""
    budget = budget or Budget(sub.path)
    for e in space:
        budget.take()
        kind = e.dxftype()
        if kind == "INSERT":
            _insert(sub, e, scale, depth, via, budget, blocks)
            continue
        try:
            if kind in ("LINE", "LWPOLYLINE", "POLYLINE") and _skipped(e, budget.skipped):
                sub.skipped += 1
                continue
            if kind == "LINE":
                a, b = e.dxf.start, e.dxf.end
                _add_line(sub, (a.x, a.y), (b.x, b.y), scale, _where(e, via), e.dxf.layer)
            elif kind == "LWPOLYLINE":
                pts = [(v.x, v.y) for v in e.vertices_in_wcs()]
                _add_polyline(sub, pts, bool(e.closed), scale, _where(e, via), e.dxf.layer,
                              any(b for *_, b in e.get_points("xyb")))
            elif kind == "POLYLINE":
                if e.is_polygon_mesh or e.is_poly_face_mesh:
                    continue
                pts = [(v.x, v.y) for v in e.points_in_wcs()]
                _add_polyline(sub, pts, bool(e.is_closed), scale, _where(e, via), e.dxf.layer,
                              any(v.dxf.bulge for v in e.vertices))
            elif kind in ("SOLID", "TRACE"):
                _add_arrowhead(sub, e, scale, _where(e, via))
            elif kind == "POINT":
                p = e.dxf.location
                _add_marker(sub, (p.x, p.y), scale, _where(e, via))
            elif kind == "CIRCLE" and e.dxf.radius * scale <= 2.0:
                p = e.dxf.center
                if e.dxf.extrusion.z < 0:
                    p = e.ocs().to_wcs(p)
                _add_marker(sub, (p.x, p.y), scale, _where(e, via))
            elif kind in ("TEXT", "ATTRIB"):
                _add_text(sub, _text_box(e, scale), e, via)
            elif kind == "MTEXT":
                _add_text(sub, _mtext_box(e, scale), e, via)
            elif kind == "DIMENSION":
                _add_dimension(sub, e, scale, via)
        except (DXFError, *DAMAGE, *ENTITY_DAMAGE) as exc:   # one damaged entity must not lose
            sub.notes.append(Note("warning", T("note.unreadable_entity", kind=kind,  # the sheet
                                               error=f"{exc.__class__.__name__}: {brief(exc)}"),
                                  _where(e, via)))


def _insert(sub: Submission, e: Any, scale: float, depth: int, via: str, budget: Budget,
            blocks: tuple[str, ...]) -> None:
    """A block INSERT: the block's entities where it is inserted, and its ATTRIBs. A block nested
    deeper than :data:`~mechplan.limits.DXF_MAX_INSERT_DEPTH`, or inside itself, is refused."""
    try:
        name = str(e.dxf.name)
        if name in blocks or depth >= DXF_MAX_INSERT_DEPTH:
            raise CheckError(Text("readers.error.dxf_depth", {"name": name[:60],
                                                              "limit": DXF_MAX_INSERT_DEPTH}),
                             file=sub.path)
        inner = list(e.virtual_entities())
        attribs = list(getattr(e, "attribs", []))
    except (DXFError, *DAMAGE, *ENTITY_DAMAGE) as exc:
        sub.notes.append(Note("warning", T("note.unreadable_entity", kind="INSERT",
                                           error=f"{exc.__class__.__name__}: {brief(exc)}"),
                              _where(e, via)))
        return
    _collect(sub, inner, scale, depth + 1, T("where.block", name=name, handle=e.dxf.handle),
             budget, (*blocks, name))
    for attrib in attribs:
        budget.take()
        try:
            _add_text(sub, _text_box(attrib, scale), attrib, via)
        except (DXFError, *DAMAGE, *ENTITY_DAMAGE) as exc:
            sub.notes.append(Note("warning", T("note.unreadable_entity", kind="ATTRIB",
                                               error=f"{exc.__class__.__name__}: {brief(exc)}"),
                                  _where(attrib, via)))


def _add_arrowhead(sub: Submission, e: Any, scale: float, where: str) -> None:
    """A filled triangle (an arrowhead): its tip is a point of the plan, joined to the middle of
    its base, where the vector's shaft ends."""
    ocs = e.ocs()
    pts = [ocs.to_wcs(e.dxf.get(f"vtx{i}")) for i in range(4) if e.dxf.hasattr(f"vtx{i}")]
    if not _finite(*(v for p in pts for v in (p.x, p.y))):
        sub.notes.append(Note("warning", T("note.nonfinite_point"), where))
        return
    corners: list[Point] = []
    for p in pts:
        q = (p.x, p.y)
        if all(math.dist(q, r) > 1e-9 for r in corners):
            corners.append(q)
    if len(corners) != 3:
        return
    sides = [math.dist(corners[(i + 1) % 3], corners[(i + 2) % 3]) for i in range(3)]
    tip = corners[sides.index(min(sides))]
    b1, b2 = (corners[i] for i in range(3) if corners[i] != tip)
    base = ((b1[0] + b2[0]) / 2, (b1[1] + b2[1]) / 2)
    _add_line(sub, tip, base, scale, where, e.dxf.get("layer", ""))
    sub.markers.append(((tip[0] * scale, tip[1] * scale), where))
    sub.heads.append(((tip[0] * scale, tip[1] * scale), (base[0] * scale, base[1] * scale)))


def _finite(*values: float) -> bool:
    return all(math.isfinite(v) for v in values)


def _add_marker(sub: Submission, p: Point, scale: float, where: str) -> None:
    """A point marker (POINT, a small CIRCLE); one with non-finite coordinates is skipped."""
    if not _finite(*p):
        sub.notes.append(Note("warning", T("note.nonfinite_point"), where))
        return
    sub.markers.append(((p[0] * scale, p[1] * scale), where))


def _add_line(sub: Submission, a: Point, b: Point, scale: float, where: str, layer: str) -> None:
    if not _finite(*a, *b):
        sub.notes.append(Note("warning", T("note.nonfinite_line"), where))
        return
    sa, sb = (a[0] * scale, a[1] * scale), (b[0] * scale, b[1] * scale)
    if math.hypot(sb[0] - sa[0], sb[1] - sa[1]) < 1e-9:
        return
    sub.lines.append(DrawnLine(sa, sb, where, layer))


def _add_polyline(sub: Submission, pts: list[Point], closed: bool, scale: float, where: str,
                  layer: str, bulges: bool) -> None:
    if closed and len(pts) > 2:
        pts = pts + [pts[0]]
    for i, (a, b) in enumerate(itertools.pairwise(pts), start=1):
        _add_line(sub, a, b, scale, T("where.segment", where=where, n=i), layer)
    if bulges:
        sub.notes.append(Note("info", T("note.arc_chords"), where))


Box = tuple[str, Point, float, Point, tuple[float, float], float]
#: a TEXT's horizontal alignment flag → where its anchor is along the text (× width from the left)
_H_FRAC = (0.0, -0.5, -1.0, 0.0, -0.5, 0.0)    # LEFT CENTER RIGHT ALIGNED MIDDLE FIT
_V_FRAC = (0.0, 0.0, -0.5, -1.0)               # BASELINE BOTTOM MIDDLE TOP


def _box(plain: str, anchor: Any, w: float, h: float, total: float, hx: float, vy: float,
         rot: float, scale: float) -> Box:
    """The box of a text ``w`` × ``total`` whose anchor is at (hx, vy) of its size from the
    centre's (−½, −½), turned by ``rot`` (radians)."""
    lx, ly = (hx + 0.5) * w, (vy + 0.5) * total
    cx = anchor.x + lx * math.cos(rot) - ly * math.sin(rot)
    cy = anchor.y + lx * math.sin(rot) + ly * math.cos(rot)
    return (plain, (cx * scale, cy * scale), h * scale, (anchor.x * scale, anchor.y * scale),
            (w / 2 * scale, total / 2 * scale), math.degrees(rot))


def _text_box(e: Any, scale: float) -> Box:
    plain = clean_text(e.dxf.text, mtext=False)
    h = float(e.dxf.get("height", 2.5)) or 2.5
    w = text_width_mm(plain or " ", h) * (float(e.dxf.get("width", 1.0)) or 1.0)
    halign, valign = MAP_TEXT_ENUM_TO_ALIGN_FLAGS[e.get_align_enum()]
    ocs = e.ocs()
    insert = ocs.to_wcs(e.dxf.insert)
    if halign in (TextHAlign.ALIGNED, TextHAlign.FIT) and e.dxf.hasattr("align_point"):
        end = ocs.to_wcs(e.dxf.align_point)      # the text fills insert → align point
        return _box(plain, insert, (end - insert).magnitude, h, h, 0.0, 0.0,
                    math.atan2(end.y - insert.y, end.x - insert.x), scale)
    aligned = (halign, valign) != (TextHAlign.LEFT, 0) and e.dxf.hasattr("align_point")
    anchor = ocs.to_wcs(e.dxf.align_point) if aligned else insert
    vy = -0.5 if halign == TextHAlign.MIDDLE else _V_FRAC[valign]
    return _box(plain, anchor, w, h, h, _H_FRAC[halign], vy,
                math.radians(float(e.dxf.get("rotation", 0.0))), scale)


def _mtext_box(e: Any, scale: float) -> Box:
    plain = clean_text(e.text, mtext=True)
    h = float(e.dxf.get("char_height", 2.5)) or 2.5
    lines = plain.splitlines() or [""]
    w = max(text_width_mm(s or " ", h) for s in lines)
    row, col = divmod(int(e.dxf.get("attachment_point", 1)) - 1, 3)     # 1 top left … 9
    return _box(plain, e.dxf.insert, w, h, h * (1 + 1.67 * (len(lines) - 1)), -col / 2,
                row / 2 - 1, math.radians(e.get_rotation()), scale)


def _add_text(sub: Submission, box: Box, e: Any, via: str) -> None:
    plain, centre, h, anchor, half, rot = box
    if not plain or not _finite(*centre):
        return
    where = _where(e, via)
    decoded, legacy = decode_legacy(plain, _font_of(e))
    if legacy == "tcvn3":
        sub.notes.append(Note("info", T("note.tcvn3", raw=plain, text=decoded), where))
    elif legacy == "vni":
        sub.notes.append(Note("warning", T("note.vni", raw=plain), where))
    sub.texts.append(SheetText(decoded, centre, h, where, e.dxf.get("layer", ""), anchor, half,
                               rot))


def _font_of(e: Any) -> str:
    """The font file or family of a text's style ("" when unknown)."""
    doc, name = e.doc, e.dxf.get("style", "Standard")
    if doc is None or name not in doc.styles:
        return ""
    style = doc.styles.get(name)
    return str(style.dxf.get("font", "") or "") + " " + str(style.dxf.get("name", ""))


def _add_dimension(sub: Submission, e: Any, scale: float, via: str) -> None:
    """A dimension whose text names a segment ("pb = <>", "pb <>"): its measured length."""
    raw = clean_text(e.dxf.get("text", "") or "", mtext=True)
    if "<>" not in raw or not re.search(r"[^\W\d_]", raw.replace("<>", "")):
        return
    mid = e.dxf.get("text_midpoint") or e.dxf.get("defpoint")
    measured = float(e.get_measurement())
    name = re.sub(r"\s*[=:]?\s*<>.*$", "", raw).strip()
    if not name or mid is None or not _finite(measured, mid.x, mid.y):
        return
    h = float(e.get_dim_style().dxf.get("dimtxt", 2.5) or 2.5)
    sub.dimensions.append((measured, SheetText(
        name, (mid.x * scale, mid.y * scale), h * scale, _where(e, via), e.dxf.get("layer", ""),
        (mid.x * scale, mid.y * scale), (text_width_mm(name, h) / 2 * scale, h / 2 * scale))))


# -- MTEXT and TEXT formatting -----------------------------------------------------------------
_MTEXT_STACK = re.compile(r"\\S([^;^/#]*)[\^/#]([^;]*);")
_MTEXT_CODE = re.compile(r"\\[fFcCHhWwQqTtAap][^;]*;|\\[LlOoKkNX~]")
_TEXT_CODE = re.compile(r"%%([dDpPcCuUoOkK%]|\d{3})")
_TEXT_SPECIAL = {"d": "°", "p": "±", "c": "Ø", "%": "%"}
_UNICODE_CODE = re.compile(r"\\U\+([0-9A-Fa-f]{4})")


def clean_text(raw: str, mtext: bool = False) -> str:
    """Strip DXF formatting codes and return the plain text (lines joined by newlines)."""
    text = raw
    if mtext:
        text = text.replace("\\P", "\n").replace("\\~", " ")
        text = _MTEXT_STACK.sub(lambda m: f"{m.group(1)}{m.group(2)}", text)
        text = _MTEXT_CODE.sub("", text)
        text = text.replace("\\\\", "\x00").replace("\\{", "\x01").replace("\\}", "\x02")
        text = text.replace("{", "").replace("}", "")
        text = text.replace("\x00", "\\").replace("\x01", "{").replace("\x02", "}")

    def special(m: re.Match[str]) -> str:
        code = m.group(1)
        if code.isdigit():
            return chr(int(code))
        return _TEXT_SPECIAL.get(code.lower(), "")

    text = _TEXT_CODE.sub(special, text)
    text = _UNICODE_CODE.sub(lambda m: chr(int(m.group(1), 16)), text)
    text = unicodedata.normalize("NFC", text)
    return "\n".join(line.strip() for line in text.splitlines()).strip()
