"""The explanatory note as content, independent of the writer (DOCX, Typst → PDF).

A note is a title page (:class:`Meta`) and a flat list of blocks: headings, paragraphs, numbered
lists, equations (written symbolically, with the numbers substituted, and the result), tables and
figures. Every string is already said in the note's language; the writers only lay it out.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True, slots=True)
class Heading:
    """A section heading; ``level`` 1 is a chapter, 2 a section, 3 a subsection."""

    text: str
    level: int = 1
    key: str = ""      # which study or part it opens ("structure", "gears", …): for tests, links


@dataclass(frozen=True, slots=True)
class Paragraph:
    """A paragraph of running text."""

    text: str


@dataclass(frozen=True, slots=True)
class Steps:
    """A numbered list (a construction protocol)."""

    items: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class Equation:
    """A formula as a student writes it: ``lhs = symbolic = substituted = result unit``.

    ``substituted`` is empty when the formula has no numbers to put in (a definition); the
    writer numbers equations in order.
    """

    lhs: str
    symbolic: str
    substituted: str
    result: str
    unit: str = ""

    def line(self) -> str:
        """The whole formula on one line."""
        parts = [self.lhs, self.symbolic]
        if self.substituted and self.substituted != self.symbolic:
            parts.append(self.substituted)
        if self.result and self.result != parts[-1]:
            parts.append(self.result + (f" {self.unit}" if self.unit else ""))
        elif self.unit:
            parts[-1] += f" {self.unit}"
        return " = ".join(p for p in parts if p)


@dataclass(frozen=True, slots=True)
class Table:
    """A table with a caption above it (the traditions number tables apart from figures)."""

    caption: str
    header: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]


@dataclass(frozen=True, slots=True)
class Figure:
    """A drawing: SVG (vector, for the PDF) and PNG (for the DOCX) of one sheet."""

    caption: str
    svg: bytes
    png: bytes
    width_mm: float
    height_mm: float


Block = Heading | Paragraph | Steps | Equation | Table | Figure


@dataclass(frozen=True, slots=True)
class Meta:
    """The title page and the frames' main inscription."""

    title: str
    language: str
    tradition: str                  # "gost" | "tcvn" | "gb" | "plain"
    student: str = ""
    group: str = ""
    variant: str = ""
    instructor: str = ""
    school: str = ""
    year: str = ""
    code: str = ""                  # document designation in the main inscription (ГОСТ 2.104)
    labels: dict[str, str] = field(default_factory=dict)   # said words of the title page/frame


@dataclass(frozen=True, slots=True)
class Note:
    """A whole note: the title page and the blocks in reading order."""

    meta: Meta
    blocks: tuple[Block, ...]

    def headings(self, level: int | None = None) -> list[Heading]:
        """The headings (of one level)."""
        return [b for b in self.blocks if isinstance(b, Heading)
                and (level is None or b.level == level)]
