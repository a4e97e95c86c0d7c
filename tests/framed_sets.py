"""The sets of sheets a study frames, caught as the layout hands them to the frame, and their
coverage measured independently of the layout's own number (shapely union of the placed boxes)."""

from __future__ import annotations

from shapely import box, unary_union

from mechplan.sheet import compose as compose_module
from mechplan.sheet import layout
from mechplan.sheet.frame import make_frame


def framed_sets(study, name: str, size: str, monkeypatch) -> list[tuple[list, object]]:
    """Every set of sheets the study frames at ``size``: (placements per sheet, drawing area)."""
    sets: list = []
    original = layout.framed

    def framed(placements, *, size, standard, language, name, fields):
        area = layout.drawing_area(make_frame(size, standard, dict(fields), language=language))
        sets.append(([list(p) for p in placements], area))
        return original(placements, size=size, standard=standard, language=language, name=name,
                        fields=fields)

    monkeypatch.setattr(layout, "framed", framed)
    monkeypatch.setattr(compose_module, "framed", framed)
    study.sheets(size, None, None, name)
    return sets


def covered(placed, area) -> float:
    """The share of the drawing area under the placed panels' boxes, each inside the area."""
    boxes = []
    for panel, (dx, dy) in placed:
        x0, y0, x1, y1 = panel.bounds()
        b = box(x0 + dx, y0 + dy, x1 + dx, y1 + dy)
        assert b.difference(area).area < 1e-6 * b.area, panel.name     # inside the area
        boxes.append(b)
    return unary_union(boxes).area / area.area
