"""Labels never overprint each other or a line's end: the drawn text boxes (advance widths of the
sheet fonts, capital height and descender) of every plan panel of every linkage template at every
sheet size, checked with shapely."""

from __future__ import annotations

import functools

import pytest
from scenes import ROOT, TEMPLATES
from shapely import box
from shapely.geometry import Point

from mechplan.drafting.fonts import font_of, text_width_mm
from mechplan.drafting.labels import LabelPlacer
from mechplan.drafting.primitives import Arrow, HAlign, Line, Polyline, Text, VAlign
from mechplan.scene import load_scene
from mechplan.sheet.compose import compose
from mechplan.solve import solve

SIZES = ("A4", "A3", "A2", "A1", "A0")
#: overlap (mm²) and depth (mm) below which two boxes or a box and a point merely touch
TOUCH_MM2 = 0.01
TOUCH_MM = 0.1


@functools.cache
def _solved(stem: str):
    return solve(load_scene(ROOT / "templates" / f"{stem}.toml"))


def _text_box(t: Text):
    """The box a text covers on paper, measured independently of the placer."""
    w = text_width_mm(t.string, t.height_mm, font_of(t))
    x = t.position[0] - {HAlign.LEFT: 0.0, HAlign.CENTER: w / 2, HAlign.RIGHT: w}[t.halign]
    base = t.position[1] - {VAlign.MIDDLE: t.height_mm / 2, VAlign.TOP: t.height_mm}.get(
        t.valign, 0.0)
    return box(x, base - 0.3 * t.height_mm, x + w, base + t.height_mm)


def _line_ends(panel) -> list[Point]:
    out = []
    for p in panel.primitives:
        if isinstance(p, (Line, Arrow)):
            out += [Point(p.start), Point(p.end)]
        elif isinstance(p, Polyline) and not p.closed:
            out += [Point(p.points[0]), Point(p.points[-1])]
    return out


def overprints(panel) -> list[tuple[str, ...]]:
    """Pairs of texts that overlap and texts that cover a line's end, in one panel."""
    texts = [t for t in panel.primitives if isinstance(t, Text)]
    boxes = [_text_box(t) for t in texts]
    bad: list[tuple[str, ...]] = []
    for i, a in enumerate(boxes):
        for j in range(i + 1, len(boxes)):
            if a.intersection(boxes[j]).area > TOUCH_MM2:
                bad.append(("texts", texts[i].string, texts[j].string))
    ends = _line_ends(panel)
    for t, b in zip(texts, boxes):
        inner = b.buffer(-TOUCH_MM)
        if any(inner.contains(e) for e in ends):
            bad.append(("line end", t.string))
    return bad


def _plan_panels(comp):
    for placed in comp.placements:
        for panel, _ in placed:
            if panel.plan is not None or panel.name.startswith("velocity-all"):
                yield panel


@pytest.mark.parametrize("path", TEMPLATES, ids=lambda p: p.stem)
def test_no_label_overprints_another_or_a_line_end_at_any_size(path):
    sol = _solved(path.stem)
    found = {}
    for size in SIZES:
        for panel in _plan_panels(compose(sol, size=size)):
            bad = overprints(panel)
            if bad:
                found[(size, panel.name)] = bad
    assert not found, found


def test_a_crowded_cluster_gets_its_labels_apart_with_leaders():
    # five points within 3 mm (v_engine's acceleration plan on A4), the ends of lines through
    # them: every label finds a clear spot
    pts = [(0.0, 0.0), (1.2, 0.6), (2.4, -0.9), (0.6, 2.1), (3.0, 1.5)]
    lines = [Line(p, (p[0] + 6.0, p[1] - 4.0)) for p in pts]
    placer = LabelPlacer(lines, 3.5, pts)
    texts = [placer.place(p, name) for p, name in zip(pts, ("s2′", "n_ED", "d′", "n_CB≡c′", "b′"))]
    from mechplan.sheet.panels import Panel

    panel = Panel("cluster", [*lines, *texts, *placer.leaders])
    assert overprints(panel) == []
    assert placer.leaders                # the far ones are tied to their points
    # a reader gives each label to its own point: nearest to it, or tied to it by a leader
    for t, p in zip(texts, pts):
        d = _text_box(t).distance(Point(p))
        nearest = all(d < _text_box(t).distance(Point(q)) for q in pts if q != p)
        tied = any(Point(ld.start).distance(Point(p)) < 1.0 for ld in placer.leaders)
        assert nearest or tied, t.string


@pytest.mark.parametrize("stem", ["v_engine", "slider_crank"])
def test_labels_with_leaders_are_read_at_their_points_by_the_checker(stem, tmp_path):
    """A label moved away from a crowded point is tied to it by a leader (layer DIMENSION), and
    `mechplan check` of the A4 sheets reads every label at its point: nothing wrong."""
    from mechplan.check import Options, check
    from mechplan.check.report import WRONG
    from mechplan.render import write

    leaders = 0
    comp = compose(_solved(stem), size="A4")
    for sheet, placed in zip(comp.sheets, comp.placements):
        leaders += sum(isinstance(p, Line) and p.role.layer == "DIMENSION"
                       for p in sheet.primitives)
        if not any(panel.plan is not None for panel, _ in placed):
            continue                    # diagrams and tables only: nothing for the checker
        (dxf,) = write(sheet, tmp_path, ["dxf"])
        report = check(ROOT / "templates" / f"{stem}.toml", dxf, Options())
        wrong = [(p.name, s.start, s.end) for p in report.plans for s in p.segments
                 if s.verdict == WRONG]
        assert not wrong, (sheet.name, wrong)
    assert leaders > 0
