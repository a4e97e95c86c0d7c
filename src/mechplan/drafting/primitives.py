"""Drawing primitives in sheet millimetres (origin bottom-left, y up) and the `Sheet` that holds
them.

Renderers draw exactly these and nothing else; every primitive carries a layer `Role` that fixes its
ISO 128 line width and line type, so a backend never decides how a line looks.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from enum import Enum
from types import MappingProxyType
from typing import Any

from mechplan.errors import DrawingError
from mechplan.i18n import LANGUAGES

Point = tuple[float, float]

#: Baseline pitch of lines of text, in capital heights (ISO 3098-0 type B: at least 1.43 h).
LINE_SPACING = 1.6

#: Lettering heights of ISO 3098-0 (capital height in mm).
ISO_3098_HEIGHTS_MM: tuple[float, ...] = (1.8, 2.5, 3.5, 5.0, 7.0, 10.0, 14.0, 20.0)


class LineType(Enum):
    """ISO 128-20 line types used on the sheets."""

    CONTINUOUS = "continuous"
    DASHED = "dashed"  # ISO 128 type 02
    DASH_DOT = "dash_dot"  # ISO 128 type 04, long-dash dotted (chain)


#: Dash patterns in mm at sheet scale: (dash, gap, ...), ISO 128 element lengths 12d/3d and
#: 24d/3d/0.5d/3d with d = 0.5 mm. Also within ГОСТ 2.303 limits for the dashed line.
DASH_PATTERNS_MM: Mapping[LineType, tuple[float, ...]] = MappingProxyType(
    {
        LineType.CONTINUOUS: (),
        LineType.DASHED: (6.0, 1.5),
        LineType.DASH_DOT: (12.0, 1.5, 0.25, 1.5),
    }
)


@dataclass(frozen=True, slots=True)
class RoleStyle:
    """How one layer role looks: ISO 128 line width, line type, DXF colour index."""

    lineweight_mm: float
    linetype: LineType
    aci: int
    ink: str = "black"  # colour in SVG and PDF (CSS name or #rrggbb)


class Role(Enum):
    """Layer role of a primitive; one DXF layer per role."""

    FRAME = "FRAME"  # sheet frame and title-block main lines, 0.7 mm
    OUTLINE = "OUTLINE"  # links, result vectors, 0.5 mm
    THICK = "OUTLINE"  # noqa: PIE796 - deliberate alias of OUTLINE
    THIN = "THIN"  # given and auxiliary lines, 0.25 mm
    DASHED = "DASHED"  # auxiliary construction lines, ISO dashed
    CHAIN = "CHAIN"  # guide axes, trajectories, dash-dot
    TEXT = "TEXT"  # labels and notes
    DIMENSION = "DIMENSION"  # dimension and leader lines
    TABLE = "TABLE"  # thin grid lines of tables and the title block
    FILL = "FILL"  # solid fills (filled polygons)
    SUBMISSION = "SUBMISSION"  # a checked student's drawing, blue
    EXACT = "EXACT"  # the exact construction beside it, green dashed
    ERRORS = "ERRORS"  # wrong segments and their errors, red

    @property
    def style(self) -> RoleStyle:
        """Return the line width, line type and colour of this role."""
        return ROLE_STYLES[self]

    @property
    def layer(self) -> str:
        """Return the DXF layer name of this role."""
        return self.value


ROLE_STYLES: Mapping[Role, RoleStyle] = MappingProxyType(
    {
        Role.FRAME: RoleStyle(0.70, LineType.CONTINUOUS, 7),
        Role.OUTLINE: RoleStyle(0.50, LineType.CONTINUOUS, 7),
        Role.THIN: RoleStyle(0.25, LineType.CONTINUOUS, 8),
        Role.DASHED: RoleStyle(0.25, LineType.DASHED, 8),
        Role.CHAIN: RoleStyle(0.25, LineType.DASH_DOT, 1),
        Role.TEXT: RoleStyle(0.25, LineType.CONTINUOUS, 7),
        Role.DIMENSION: RoleStyle(0.25, LineType.CONTINUOUS, 3),
        Role.TABLE: RoleStyle(0.25, LineType.CONTINUOUS, 7),
        Role.FILL: RoleStyle(0.25, LineType.CONTINUOUS, 7),
        Role.SUBMISSION: RoleStyle(0.35, LineType.CONTINUOUS, 5, "#1f4fd6"),
        Role.EXACT: RoleStyle(0.25, LineType.DASHED, 3, "#13a03c"),
        Role.ERRORS: RoleStyle(0.70, LineType.CONTINUOUS, 1, "#d62020"),
    }
)


class HAlign(Enum):
    """Horizontal text alignment relative to the text position."""

    LEFT = "left"
    CENTER = "center"
    RIGHT = "right"


class VAlign(Enum):
    """Vertical text alignment: baseline, descender line, half the capital height, capital top."""

    BASELINE = "baseline"
    BOTTOM = "bottom"
    MIDDLE = "middle"
    TOP = "top"


def _point(value: object, what: str) -> Point:
    try:
        seq: tuple[Any, ...] = tuple(value)  # type: ignore[arg-type]
        if len(seq) != 2:
            raise ValueError(len(seq))
        p = (float(seq[0]), float(seq[1]))
    except (TypeError, ValueError) as exc:
        raise DrawingError(f"{what} must be a pair of numbers in mm (got {value!r})") from exc
    if not (math.isfinite(p[0]) and math.isfinite(p[1])):
        raise DrawingError(f"{what} must be finite (got {p}); a construction produced NaN")
    return p


def _positive(value: float, what: str) -> float:
    v = float(value)
    if not (math.isfinite(v) and v > 0.0):
        raise DrawingError(f"{what} must be a positive number of mm (got {value!r})")
    return v


@dataclass(frozen=True, slots=True)
class Line:
    """A straight segment from `start` to `end`."""

    start: Point
    end: Point
    role: Role = Role.THIN

    def __post_init__(self) -> None:
        object.__setattr__(self, "start", _point(self.start, "Line start"))
        object.__setattr__(self, "end", _point(self.end, "Line end"))

    @property
    def length(self) -> float:
        """Return the length in mm."""
        return math.dist(self.start, self.end)


@dataclass(frozen=True, slots=True)
class Polyline:
    """An open or closed chain of straight segments; `filled` closed polylines are solid areas."""

    points: tuple[Point, ...]
    role: Role = Role.THIN
    closed: bool = False
    filled: bool = False

    def __post_init__(self) -> None:
        pts = tuple(_point(p, f"Polyline point {i}") for i, p in enumerate(self.points))
        if len(pts) < 2:
            raise DrawingError(f"Polyline must have at least 2 points (got {len(pts)})")
        if self.filled and (not self.closed or len(pts) < 3):
            raise DrawingError("a filled Polyline must be closed and have at least 3 points")
        object.__setattr__(self, "points", pts)


@dataclass(frozen=True, slots=True)
class Circle:
    """A full circle."""

    center: Point
    radius: float
    role: Role = Role.THIN

    def __post_init__(self) -> None:
        object.__setattr__(self, "center", _point(self.center, "Circle center"))
        object.__setattr__(self, "radius", _positive(self.radius, "Circle radius"))


@dataclass(frozen=True, slots=True)
class Arc:
    """A circular arc drawn counter-clockwise from `start_deg` to `end_deg`."""

    center: Point
    radius: float
    start_deg: float
    end_deg: float
    role: Role = Role.THIN

    def __post_init__(self) -> None:
        object.__setattr__(self, "center", _point(self.center, "Arc center"))
        object.__setattr__(self, "radius", _positive(self.radius, "Arc radius"))
        for name in ("start_deg", "end_deg"):
            v = float(getattr(self, name))
            if not math.isfinite(v):
                raise DrawingError(f"Arc {name} must be finite (got {v})")
            object.__setattr__(self, name, v)

    @property
    def sweep_deg(self) -> float:
        """Return the counter-clockwise sweep in degrees, in (0, 360]."""
        sweep = (self.end_deg - self.start_deg) % 360.0
        return 360.0 if sweep == 0.0 else sweep


@dataclass(frozen=True, slots=True)
class Text:
    """One line of text; `height_mm` is the ISO 3098 capital height.

    `width_factor` < 1 condenses the letters horizontally (DXF width factor) to fit a cell.

    `tag` names a title-block attribute when the text sits inside a `Block` (DXF ATTRIB); an
    attribute may be empty, a plain text may not.

    `font` names the sheet font (``SheetFont`` member: "ISO", "SYMBOL", "CJK") the lines of one
    paragraph share; None: the font the string itself needs (`drafting.fonts.font_of`).
    """

    position: Point
    string: str
    height_mm: float = 3.5
    rotation_deg: float = 0.0
    halign: HAlign = HAlign.LEFT
    valign: VAlign = VAlign.BASELINE
    role: Role = Role.TEXT
    tag: str | None = None
    width_factor: float = 1.0
    font: str | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "position", _point(self.position, "Text position"))
        if not isinstance(self.string, str) or "\n" in self.string or "\r" in self.string:
            raise DrawingError(
                f"Text string must be a single line of text (got {self.string!r}); "
                "use one Text per line"
            )
        if not self.string and self.tag is None:
            raise DrawingError("Text string must not be empty (only attributes may be empty)")
        h = float(self.height_mm)
        if not any(math.isclose(h, s) for s in ISO_3098_HEIGHTS_MM):
            raise DrawingError(
                f"Text height must be an ISO 3098 height {ISO_3098_HEIGHTS_MM} mm (got {h})"
            )
        object.__setattr__(self, "height_mm", h)
        rot = float(self.rotation_deg)
        if not math.isfinite(rot):
            raise DrawingError(f"Text rotation must be finite (got {rot})")
        object.__setattr__(self, "rotation_deg", rot)
        wf = float(self.width_factor)
        if not (0.3 <= wf <= 2.0):
            raise DrawingError(f"Text width factor must be within 0.3…2 (got {wf})")
        object.__setattr__(self, "width_factor", wf)
        if self.font not in (None, "ISO", "SYMBOL", "CJK"):
            raise DrawingError(f"Text font must be ISO, SYMBOL or CJK (got {self.font!r})")
        if self.tag is not None and not _valid_tag(self.tag):
            raise DrawingError(
                f"attribute tag must be letters, digits and '_' without spaces (got {self.tag!r})"
            )


def _valid_tag(tag: str) -> bool:
    return bool(tag) and all(c.isascii() and (c.isalnum() or c == "_") for c in tag)


@dataclass(frozen=True, slots=True)
class Arrow:
    """A vector from `start` to `end` with a solid filled arrowhead at `end`."""

    start: Point
    end: Point
    role: Role = Role.OUTLINE
    head_length_mm: float = 4.0
    head_width_mm: float = 1.4

    def __post_init__(self) -> None:
        object.__setattr__(self, "start", _point(self.start, "Arrow start"))
        object.__setattr__(self, "end", _point(self.end, "Arrow end"))
        object.__setattr__(
            self, "head_length_mm", _positive(self.head_length_mm, "Arrow head length")
        )
        object.__setattr__(self, "head_width_mm", _positive(self.head_width_mm, "Arrow head width"))
        if math.dist(self.start, self.end) <= 1e-9:
            raise DrawingError(
                f"Arrow must have a positive length (got start = end = {self.start}); "
                "leave zero vectors out of the plan"
            )

    def head(self) -> tuple[Point, Point, Point]:
        """Return the arrowhead triangle (tip, left base corner, right base corner)."""
        (x0, y0), (x1, y1) = self.start, self.end
        length = math.hypot(x1 - x0, y1 - y0)
        ux, uy = (x1 - x0) / length, (y1 - y0) / length
        hl = min(self.head_length_mm, length)
        bx, by = x1 - ux * hl, y1 - uy * hl
        hw = self.head_width_mm / 2.0
        return (x1, y1), (bx - uy * hw, by + ux * hw), (bx + uy * hw, by - ux * hw)

    def shaft(self) -> Line | None:
        """Return the shaft from `start` to the arrowhead base, or None if the head fills it."""
        (x0, y0), (x1, y1) = self.start, self.end
        length = math.hypot(x1 - x0, y1 - y0)
        if length <= self.head_length_mm:
            return None
        k = (length - self.head_length_mm) / length
        return Line(self.start, (x0 + (x1 - x0) * k, y0 + (y1 - y0) * k), self.role)


@dataclass(frozen=True, slots=True)
class Block:
    """A named group drawn as one DXF BLOCK inserted at `origin`; tagged texts become ATTRIBs.

    Contents are in sheet coordinates like everything else (not relative to `origin`).
    """

    name: str
    origin: Point
    primitives: tuple[Primitive, ...]

    def __post_init__(self) -> None:
        if not _valid_tag(self.name):
            raise DrawingError(f"Block name must be letters, digits and '_' (got {self.name!r})")
        object.__setattr__(self, "origin", _point(self.origin, "Block origin"))
        prims = tuple(self.primitives)
        tags: set[str] = set()
        for p in prims:
            if isinstance(p, Block):
                raise DrawingError(f"Block '{self.name}' must not contain another block")
            if not isinstance(p, PRIMITIVE_TYPES):
                raise DrawingError(f"Block '{self.name}' holds a non-primitive {p!r}")
            if isinstance(p, Text) and p.tag is not None:
                if p.tag in tags:
                    raise DrawingError(f"Block '{self.name}' repeats attribute tag {p.tag!r}")
                tags.add(p.tag)
        object.__setattr__(self, "primitives", prims)

    @property
    def attributes(self) -> dict[str, str]:
        """Return the attribute values by tag."""
        return {
            p.tag: p.string for p in self.primitives if isinstance(p, Text) and p.tag is not None
        }


Primitive = Line | Polyline | Circle | Arc | Text | Arrow | Block
PRIMITIVE_TYPES = (Line, Polyline, Circle, Arc, Text, Arrow, Block)


@dataclass(frozen=True, slots=True)
class Table:
    """A grid of text cells; `expand()` turns it into lines and texts.

    `origin` is the top-left corner; rows run downwards. `cells[r][c]` is the text of a cell ("" for
    none; lines separated by "\n" are drawn one under the other, :data:`LINE_SPACING` apart, centred
    in the row). The outer border uses `border_role`, inner lines `grid_role`.
    """

    origin: Point
    column_widths_mm: tuple[float, ...]
    row_heights_mm: tuple[float, ...]
    cells: tuple[tuple[str, ...], ...]
    text_height_mm: float = 2.5
    border_role: Role = Role.OUTLINE
    grid_role: Role = Role.TABLE
    halign: HAlign = HAlign.CENTER

    def __post_init__(self) -> None:
        object.__setattr__(self, "origin", _point(self.origin, "Table origin"))
        cols = tuple(_positive(w, "Table column width") for w in self.column_widths_mm)
        rows = tuple(_positive(h, "Table row height") for h in self.row_heights_mm)
        cells = tuple(tuple(r) for r in self.cells)
        if len(cells) != len(rows) or any(len(r) != len(cols) for r in cells):
            raise DrawingError(
                f"Table cells must be {len(rows)} rows × {len(cols)} columns "
                f"(got {len(cells)} rows of {[len(r) for r in cells]})"
            )
        object.__setattr__(self, "column_widths_mm", cols)
        object.__setattr__(self, "row_heights_mm", rows)
        object.__setattr__(self, "cells", cells)

    def expand(self) -> tuple[Primitive, ...]:
        """Return the table's lines and texts."""
        x0, y0 = self.origin
        xs = [x0]
        for w in self.column_widths_mm:
            xs.append(xs[-1] + w)
        ys = [y0]
        for h in self.row_heights_mm:
            ys.append(ys[-1] - h)
        out: list[Primitive] = [
            Polyline(
                ((xs[0], ys[0]), (xs[-1], ys[0]), (xs[-1], ys[-1]), (xs[0], ys[-1])),
                self.border_role,
                closed=True,
            )
        ]
        out += [Line((x, ys[0]), (x, ys[-1]), self.grid_role) for x in xs[1:-1]]
        out += [Line((xs[0], y), (xs[-1], y), self.grid_role) for y in ys[1:-1]]
        for r, row in enumerate(self.cells):
            ym = (ys[r] + ys[r + 1]) / 2.0
            for c, cell in enumerate(row):
                lines = [ln for ln in cell.split("\n") if ln]
                pitch = LINE_SPACING * self.text_height_mm
                for i, s in enumerate(lines):
                    y = ym + pitch * ((len(lines) - 1) / 2.0 - i)
                    if self.halign is HAlign.LEFT:
                        x = xs[c] + 1.0
                    elif self.halign is HAlign.RIGHT:
                        x = xs[c + 1] - 1.0
                    else:
                        x = (xs[c] + xs[c + 1]) / 2.0
                    out.append(Text((x, y), s, self.text_height_mm, halign=self.halign,
                                    valign=VAlign.MIDDLE))
        return tuple(out)


@dataclass(frozen=True, slots=True)
class Sheet:
    """A drawing sheet: paper size in mm, primitives in sheet mm, title-block fields, language."""

    width_mm: float
    height_mm: float
    primitives: tuple[Primitive, ...] = ()
    attributes: Mapping[str, str] = field(default_factory=dict)
    language: str = "en"
    name: str = "sheet"

    def __post_init__(self) -> None:
        object.__setattr__(self, "width_mm", _positive(self.width_mm, "Sheet width"))
        object.__setattr__(self, "height_mm", _positive(self.height_mm, "Sheet height"))
        prims = tuple(self.primitives)
        for p in prims:
            if not isinstance(p, PRIMITIVE_TYPES):
                hint = "; call Table.expand()" if isinstance(p, Table) else ""
                raise DrawingError(f"Sheet primitives must be drawing primitives (got {p!r}){hint}")
        names = [p.name for p in prims if isinstance(p, Block)]
        if len(names) != len(set(names)):
            raise DrawingError(f"Sheet block names must be unique (got {names})")
        object.__setattr__(self, "primitives", prims)
        if self.language not in LANGUAGES:
            raise DrawingError(f"Sheet language must be one of {LANGUAGES} (got {self.language!r})")
        if not self.name or any(c in self.name for c in "/\\\0"):
            raise DrawingError(f"Sheet name must be a plain file stem (got {self.name!r})")
        object.__setattr__(
            self,
            "attributes",
            MappingProxyType({str(k): str(v) for k, v in self.attributes.items()}),
        )

    def flat(self) -> Iterator[Primitive]:
        """Yield every primitive with blocks opened (blocks themselves are not yielded)."""
        for p in self.primitives:
            if isinstance(p, Block):
                yield from p.primitives
            else:
                yield p
