"""PDF and PNG backend (matplotlib, Agg): true scale, fonts embedded as TrueType (fonttype 42).

The figure is exactly the sheet (figsize = mm / 25.4, axes filling it, no tight bounding box), so
one sheet millimetre is one millimetre on the page. Uses `Figure` directly: no pyplot state.
"""

from __future__ import annotations

import contextlib
import dataclasses
import io
import warnings
from collections.abc import Iterator
from typing import Any, cast

import matplotlib
from matplotlib import font_manager, ft2font
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure
from matplotlib.font_manager import FontProperties
from matplotlib.patches import Arc as ArcPatch
from matplotlib.patches import Circle as CirclePatch
from matplotlib.patches import PathPatch
from matplotlib.patches import Polygon as PolygonPatch
from matplotlib.textpath import TextPath, TextToPath
from matplotlib.transforms import Affine2D

from mechplan.drafting.fonts import (
    SheetFont,
    baseline_point,
    em_size_mm,
    face_index,
    families_for,
    font_of,
    font_path,
)
from mechplan.drafting.primitives import (
    DASH_PATTERNS_MM,
    Arc,
    Arrow,
    Circle,
    HAlign,
    Line,
    Polyline,
    Role,
    Sheet,
    Text,
)
from mechplan.drafting.typography import (
    SCRIPT_SIZE,
    SUB_SHIFT,
    SUP_SHIFT,
    has_scripts,
    plain,
    runs,
)
from mechplan.errors import DrawingError

PT_PER_MM = 72.0 / 25.4
INK = "black"
_RC = {"pdf.fonttype": 42, "ps.fonttype": 42, "lines.scale_dashes": False,
       "path.simplify": False, "svg.fonttype": "none"}


def _sheet_font_entries() -> list[Any]:
    """matplotlib's font entries of the sheet fonts' files, named by their sheet family."""
    entries = []
    for font in SheetFont:
        path = font_path(font)
        if path is None:
            continue
        index = face_index(path, font)
        try:        # a collection's face (a system .ttc): matplotlib ≥ 3.10 reads any face
            ft = ft2font.FT2Font(str(path), face_index=index) if index else ft2font.FT2Font(
                str(path))
        except TypeError:
            ft = ft2font.FT2Font(str(path))
        prop = font_manager.ttfFontProperty(ft)
        entries.append(dataclasses.replace(prop, name=font.family))
    return entries


@contextlib.contextmanager
def _sheet_fonts() -> Iterator[None]:
    """Map the sheet families to mechplan's font files while drawing, then restore.

    matplotlib's font list also holds the system's fonts (a Debian Noto Sans CJK SC, DejaVu Sans),
    and it would draw with whichever scores first: the sheet's own files must win, or a PDF would
    embed different fonts on different machines.
    """
    manager = cast(Any, font_manager.fontManager)   # its find cache is private
    saved = manager.ttflist
    ours = _sheet_font_entries()
    names = {e.name for e in ours}
    manager.ttflist = [*ours, *(e for e in saved if e.name not in names)]
    manager._findfont_cached.cache_clear()
    try:
        yield
    finally:
        manager.ttflist = saved
        manager._findfont_cached.cache_clear()


def _style(role: Role) -> dict[str, Any]:
    st = role.style
    pattern = DASH_PATTERNS_MM[st.linetype]
    linestyle: Any = (0, tuple(v * PT_PER_MM for v in pattern)) if pattern else "solid"
    return {"linewidth": st.lineweight_mm * PT_PER_MM, "linestyle": linestyle,
            "capstyle": "butt", "joinstyle": "miter", "color": st.ink}


def _draw(ax: Any, sheet: Sheet) -> None:
    paths: dict[Role, list[list[tuple[float, float]]]] = {}
    for p in sheet.flat():
        if isinstance(p, Line):
            paths.setdefault(p.role, []).append([p.start, p.end])
        elif isinstance(p, Polyline):
            if p.filled:
                ax.add_patch(PolygonPatch(p.points, closed=True, facecolor=INK, edgecolor="none",
                                          linewidth=0))
            else:
                pts = list(p.points) + ([p.points[0]] if p.closed else [])
                paths.setdefault(p.role, []).append(pts)
        elif isinstance(p, Circle):
            st = _style(p.role)
            ax.add_patch(CirclePatch(p.center, p.radius, fill=False, linewidth=st["linewidth"],
                                     linestyle=st["linestyle"], capstyle="butt", edgecolor=INK))
        elif isinstance(p, Arc):
            st = _style(p.role)
            ax.add_patch(ArcPatch(p.center, 2 * p.radius, 2 * p.radius, theta1=p.start_deg,
                                  theta2=p.start_deg + p.sweep_deg, linewidth=st["linewidth"],
                                  linestyle=st["linestyle"], capstyle="butt", edgecolor=INK))
        elif isinstance(p, Arrow):
            shaft = p.shaft()
            if shaft is not None:
                paths.setdefault(p.role, []).append([shaft.start, shaft.end])
            ax.add_patch(PolygonPatch(p.head(), closed=True, facecolor=INK, edgecolor="none",
                                      linewidth=0))
        elif isinstance(p, Text):
            _text(ax, p)
        else:
            raise DrawingError(f"PDF/PNG backend cannot draw {type(p).__name__}")
    for role, segs in paths.items():
        st = _style(role)
        ax.add_collection(LineCollection(segs, linewidths=st["linewidth"],
                                         linestyles=[st["linestyle"]], colors=st["color"],
                                         capstyle="butt", joinstyle="miter"))


def _scripted(ax: Any, t: Text, x: float, y: float, size_mm: float, families: list[str],
              ha: str) -> None:
    """A label with sub- and superscripts: each run placed after the advance of the ones before."""
    measure = TextToPath()
    parts = []
    for run, shift in runs(t.string):
        size = size_mm * (SCRIPT_SIZE if shift else 1.0)
        prop = FontProperties(family=families, size=size)
        width = measure.get_text_width_height_descent(run, prop, ismath=False)[0]
        rise = {1: SUP_SHIFT, -1: SUB_SHIFT, 0: 0.0}[shift] * t.height_mm
        parts.append((run, size, width, rise))
    total = sum(w for _, _, w, _ in parts)
    cursor = x - {"left": 0.0, "center": total / 2, "right": total}[ha]
    for run, size, width, rise in parts:
        ax.text(cursor, y + rise, run, fontsize=size * PT_PER_MM, fontfamily=families,
                ha="left", va="baseline", color=t.role.style.ink, transform=ax.transData)
        cursor += width


def _text(ax: Any, t: Text) -> None:
    if not t.string:
        return
    x, y = baseline_point(t)
    size_mm = em_size_mm(t)
    families = list(families_for(t.string, font_of(t)))
    ha = {HAlign.LEFT: "left", HAlign.CENTER: "center", HAlign.RIGHT: "right"}[t.halign]
    if t.width_factor == 1.0 and not t.rotation_deg and has_scripts(t.string):
        _scripted(ax, t, x, y, size_mm, families, ha)
        return
    if t.width_factor == 1.0:
        ax.text(x, y, plain(t.string) if has_scripts(t.string) else t.string,
                fontsize=size_mm * PT_PER_MM, fontfamily=families,
                rotation=t.rotation_deg, rotation_mode="anchor", ha=ha, va="baseline",
                color=t.role.style.ink, transform=ax.transData)
        return
    # Condensed text has no font-level equivalent: draw the glyph outlines, scaled.
    path = TextPath((0, 0), t.string, size=1.0, prop=FontProperties(family=families))
    width = path.get_extents().x1 if len(path.vertices) else 0.0
    shift = {HAlign.LEFT: 0.0, HAlign.CENTER: -width / 2, HAlign.RIGHT: -width}[t.halign]
    transform = (Affine2D().translate(shift, 0).scale(size_mm * t.width_factor, size_mm)
                 .rotate_deg(t.rotation_deg).translate(x, y))
    ax.add_patch(PathPatch(transform.transform_path(path), facecolor=INK, edgecolor="none",
                           linewidth=0))


def figure(sheet: Sheet) -> Figure:
    """Return a matplotlib figure of `sheet` at true scale (call inside `render_context()`)."""
    w, h = sheet.width_mm, sheet.height_mm
    fig = Figure(figsize=(w / 25.4, h / 25.4), facecolor="white")
    FigureCanvasAgg(fig)
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, w)
    ax.set_ylim(0, h)
    ax.set_aspect("equal")
    ax.set_axis_off()
    _draw(ax, sheet)
    return fig


@contextlib.contextmanager
def render_context() -> Iterator[None]:
    """Build and save figures in this context: the rcParams and the sheet's font files.

    matplotlib's own warning per missing glyph is silenced: `render.write` names them once.
    """
    with matplotlib.rc_context(cast(Any, _RC)), _sheet_fonts(), warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=r"Glyph \d+ .*missing from font", 
                                category=UserWarning)
        yield


def to_bytes(sheet: Sheet, fmt: str, *, dpi: float = 150.0) -> bytes:
    """Return `sheet` rendered as "pdf" or "png" (PNG at `dpi`)."""
    if fmt not in ("pdf", "png"):
        raise DrawingError(f"matplotlib format must be 'pdf' or 'png' (got {fmt!r})")
    buf = io.BytesIO()
    with render_context():
        fig = figure(sheet)
        if fmt == "pdf":
            meta = {"Title": sheet.attributes.get("title", sheet.name), "Creator": "mechplan",
                    "Author": sheet.attributes.get("author", ""), "CreationDate": None}
            fig.savefig(buf, format="pdf", metadata=meta)
        else:
            fig.savefig(buf, format="png", dpi=dpi, metadata={"Software": "mechplan"})
    return buf.getvalue()
