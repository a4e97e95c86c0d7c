"""Overlay sheet of a check: the submission in blue, the exact plans (placed by the poles) in
green, each wrong segment marked in red with its error. SVG (svgwrite), DXF (ezdxf), PDF
(matplotlib); every file is written atomically."""

from __future__ import annotations

import io
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..errors import CheckError
from .report import SLIP, WRONG, CheckReport, SegmentRow
from .texts import T, tr, word

Point = tuple[float, float]

SUBMISSION_RGB, EXACT_RGB, ERROR_RGB = "#1f4fd6", "#13a03c", "#d62020"
CJK_STYLE = "CJK"       # DXF text style of Chinese texts
LAYERS = {"SUBMISSION": 5, "EXACT": 3, "ERRORS": 1, "NOTES": 7}     # DXF colour indices


@dataclass(frozen=True, slots=True)
class Mark:
    """One primitive of the overlay (mm of the submission's sheet, y up)."""

    layer: str                 # SUBMISSION, EXACT, ERRORS, NOTES
    start: Point
    end: Point | None = None   # None: a text at ``start``
    text: str = ""
    height: float = 2.5


def marks(report: CheckReport, lang: str = "en") -> list[Mark]:
    """The overlay's primitives, their texts in a language (en, ru, vi, zh)."""
    out: list[Mark] = []
    for plan in report.plans:
        if not plan.drawn_lines and not plan.exact_segments:
            continue
        start = len(out)
        for a, b in plan.drawn_lines:
            out.append(Mark("SUBMISSION", a, b))
        for _, a, b in plan.exact_segments:
            out.append(Mark("EXACT", a, b))
        for label, at in plan.exact_mm.items():
            out.append(Mark("EXACT", (at[0] - 3.0, at[1] - 3.5), None, label, 2.0))
        points = {p.step: p.at_mm for p in plan.points}
        for row in plan.segments:
            if row.verdict not in (WRONG, SLIP):
                continue
            pa, pb = points.get(row.start), points.get(row.end)
            if pa is None or pb is None:
                continue
            a, b = pa, pb
            out.append(Mark("ERRORS", a, b))
            mid = ((a[0] + b[0]) / 2 + 1.0, (a[1] + b[1]) / 2 + 1.0)
            out.append(Mark("ERRORS", mid, None, _error_text(row, lang), 2.0))
        xs = [p[0] for m in out[start:] for p in (m.start, m.end) if p is not None] or [0.0]
        ys = [p[1] for m in out[start:] for p in (m.start, m.end) if p is not None] or [0.0]
        title = (T("overlay.title", plan=plan.name, mu=plan.mu, unit=plan.mu_unit).tr(lang)
                 if plan.mu else tr(plan.name, lang))
        out.append(Mark("NOTES", (min(xs), max(ys) + 6.0), None, title, 3.0))
    if not out:
        raise CheckError("an overlay needs a drawn submission (a DXF with labelled plans); "
                         "a table of values has no drawing", file=report.submission)
    xs = [p[0] for m in out for p in (m.start, m.end) if p is not None]
    ys = [p[1] for m in out for p in (m.start, m.end) if p is not None]
    legend = (min(xs), min(ys) - 8.0)
    out.append(Mark("NOTES", legend, None, T("overlay.legend").tr(lang), 3.0))
    return out


def _error_text(row: SegmentRow, lang: str = "en") -> str:
    parts = [row.name]
    if row.error_mm is not None:
        parts.append(T("overlay.err_mm", v=row.error_mm).tr(lang))
    if row.error_pct is not None:
        parts.append(T("overlay.err_pct", v=row.error_pct).tr(lang))
    if row.direction_deg is not None and row.tolerance_deg is not None and \
            abs(row.direction_deg) > row.tolerance_deg:
        parts.append(T("overlay.err_deg", v=row.direction_deg).tr(lang))
    if row.cause:
        parts.append(word("cause", row.cause, lang))
    return " ".join(parts)


def has_cjk(text: str) -> bool:
    """True when a text needs a CJK font (Chinese overlays)."""
    from ..sheet.fonts import has_cjk as needs_cjk

    return bool(text) and needs_cjk(text)


def families_for(text: str) -> tuple[str, ...]:
    """Font families for a text, its own font first (the sheet's choice)."""
    from ..sheet.fonts import families_for as sheet_families

    return sheet_families(text)


def _css_family(text: str) -> str:
    if not has_cjk(text):
        return "DejaVu Sans, sans-serif"
    return ", ".join([*(f"'{f}'" if " " in f else f for f in families_for(text)), "sans-serif"])


def _bounds(ms: list[Mark]) -> tuple[float, float, float, float]:
    xs, ys = [], []
    for m in ms:
        for p in (m.start, m.end):
            if p is not None:
                xs.append(p[0])
                ys.append(p[1])
        if m.end is None:
            wide = sum(1 for ch in m.text if ord(ch) >= 0x2E80)
            xs.append(m.start[0] + 0.6 * m.height * (len(m.text) + wide))
            ys.append(m.start[1] + m.height)
    return min(xs), min(ys), max(xs), max(ys)


def write_overlay(report: CheckReport, path: str | Path, lang: str = "en") -> Path:
    """Write the overlay as SVG, DXF or PDF (by the file's suffix), its texts in a language."""
    p = Path(path)
    suffix = p.suffix.lower()
    ms = marks(report, lang)
    if suffix == ".svg":
        data = svg_bytes(ms)
    elif suffix == ".dxf":
        data = dxf_bytes(ms)
    elif suffix == ".pdf":
        data = pdf_bytes(ms)
    else:
        raise CheckError(f"an overlay is written as .svg, .dxf or .pdf (got {suffix or 'no suffix'})",
                         file=str(p))
    return _write_atomic(p, data)


def _write_atomic(path: Path, data: bytes) -> Path:
    from ..errors import DrawingError
    from ..render.atomic import write_atomic

    try:
        return write_atomic(path, data)
    except DrawingError as exc:
        raise CheckError(exc.detail, file=str(path)) from None
    except OSError as exc:
        raise CheckError(f"cannot write the file ({exc.strerror or exc})", file=str(path)) from None


def svg_bytes(ms: list[Mark], margin: float = 10.0) -> bytes:
    """The overlay as an SVG document in millimetres."""
    import svgwrite

    x0, y0, x1, y1 = _bounds(ms)
    w, h = x1 - x0 + 2 * margin, y1 - y0 + 2 * margin

    def q(p: Point) -> tuple[float, float]:
        return (round(p[0] - x0 + margin, 4), round(y1 - p[1] + margin, 4))

    dwg = svgwrite.Drawing(size=(f"{w:.2f}mm", f"{h:.2f}mm"), viewBox=f"0 0 {w:.3f} {h:.3f}",
                           profile="full")
    colours = {"SUBMISSION": SUBMISSION_RGB, "EXACT": EXACT_RGB, "ERRORS": ERROR_RGB,
               "NOTES": "#000000"}
    widths = {"SUBMISSION": 0.35, "EXACT": 0.25, "ERRORS": 0.6, "NOTES": 0.25}
    groups = {}
    for layer in ("EXACT", "SUBMISSION", "ERRORS", "NOTES"):
        g = dwg.g(id=layer.lower(), stroke=colours[layer], fill="none",
                  stroke_width=widths[layer])
        if layer == "EXACT":
            g["stroke-dasharray"] = "2,1"
        groups[layer] = g
        dwg.add(g)
    for m in ms:
        g = groups[m.layer]
        if m.end is not None:
            g.add(dwg.line(q(m.start), q(m.end)))
        else:
            g.add(dwg.text(m.text, insert=q(m.start), fill=colours[m.layer], stroke="none",
                           font_size=m.height, font_family=_css_family(m.text)))
    buf = io.StringIO()
    dwg.write(buf, pretty=True)
    return buf.getvalue().encode("utf-8")


def dxf_bytes(ms: list[Mark]) -> bytes:
    """The overlay as a DXF R2010 document (one layer per colour)."""
    import ezdxf

    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = 4
    for name, colour in LAYERS.items():
        doc.layers.add(name, color=colour)
    doc.layers.get("EXACT").dxf.linetype = "DASHED" if "DASHED" in doc.linetypes else "CONTINUOUS"
    if any(has_cjk(m.text) for m in ms):
        from ..sheet.fonts import SheetFont

        doc.styles.add(CJK_STYLE, font=SheetFont.CJK.file_name)
    msp = doc.modelspace()
    for m in ms:
        attribs = {"layer": m.layer}
        if m.end is not None:
            msp.add_line(m.start, m.end, dxfattribs=attribs)
        else:
            if has_cjk(m.text):
                attribs["style"] = CJK_STYLE
            msp.add_text(m.text, height=m.height, dxfattribs=attribs).set_placement(m.start)
    buf = io.StringIO()
    doc.write(buf)
    return buf.getvalue().encode(doc.output_encoding or "utf-8", errors="replace")


def pdf_bytes(ms: list[Mark], margin: float = 10.0) -> bytes:
    """The overlay as a one-page PDF at true scale (matplotlib, no global state)."""
    from matplotlib.backends.backend_pdf import FigureCanvasPdf
    from matplotlib.figure import Figure

    x0, y0, x1, y1 = _bounds(ms)
    w, h = x1 - x0 + 2 * margin, y1 - y0 + 2 * margin
    fig = Figure(figsize=(w / 25.4, h / 25.4))
    FigureCanvasPdf(fig)
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(x0 - margin, x1 + margin)
    ax.set_ylim(y0 - margin, y1 + margin)
    ax.set_aspect("equal")
    ax.axis("off")
    colours = {"SUBMISSION": SUBMISSION_RGB, "EXACT": EXACT_RGB, "ERRORS": ERROR_RGB,
               "NOTES": "#000000"}
    for m in ms:
        if m.end is not None:
            ax.plot([m.start[0], m.end[0]], [m.start[1], m.end[1]], color=colours[m.layer],
                    linewidth=1.6 if m.layer == "ERRORS" else 0.8,
                    linestyle="--" if m.layer == "EXACT" else "-")
        else:
            family: Any = list(families_for(m.text)) if has_cjk(m.text) else None
            ax.text(m.start[0], m.start[1], m.text, color=colours[m.layer],
                    fontsize=m.height / 0.3528, fontfamily=family)
    buf = io.BytesIO()
    fig.savefig(buf, format="pdf")
    return buf.getvalue()

