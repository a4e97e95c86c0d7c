"""Structured terms of a construction: directions of vector-equation terms.

The construction stores what a direction *is* (⊥ a link, ∥ a guide, towards a point, opposite to an
image); the words are chosen by the reader's language from the catalogues
(``protocol.direction.*``).
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

from ..i18n import message


class Relation(enum.Enum):
    """How the direction of a vector-equation term is known."""

    GIVEN = "given"  # ✓: known from an earlier plan
    UNKNOWN = "unknown"  # ?: found by the construction
    PERP = "perp"  # ⊥ ref
    PARALLEL = "parallel"  # ∥ ref
    FROM_TO = "from_to"  # start → ref
    TOWARDS = "towards"  # towards the point ref
    OPPOSITE = "opposite"  # opposite to the vector ref
    AGAINST = "against"  # against the sense of ref (a couple)
    SYMBOL = "symbol"  # a drawn symbol: ↓, ↑, →, ←, or a formula


_WORDS = (Relation.TOWARDS, Relation.OPPOSITE, Relation.AGAINST)


@dataclass(frozen=True, slots=True)
class Direction:
    """The direction column of a vector-equation row: a relation, its reference and more."""

    relation: Relation
    ref: str = ""
    start: str = ""  # FROM_TO: where the arrow starts
    then: Direction | None = None  # a second clause: "∥ Ax, towards A"

    def text(self, language: str) -> str:
        """The direction as written in ``language`` (pole π written p′ in Chinese)."""
        r = self.relation
        if r is Relation.GIVEN:
            out = "✓"
        elif r is Relation.UNKNOWN:
            out = "?"
        elif r in (Relation.PERP, Relation.PARALLEL):
            sym = "⊥" if r is Relation.PERP else "∥"
            out = f"{sym} {self.ref}" if self.ref else sym
        elif r is Relation.FROM_TO:
            out = f"{self.start} → {self.ref}"
        elif r in _WORDS:
            out = message(f"protocol.direction.{r.value}", language, ref=self.ref)
        else:
            out = self.ref
        if self.then is not None:
            out += ", " + self.then.text(language)
        return pole_label(out, language)

    def __str__(self) -> str:
        return self.text("en")


GIVEN = Direction(Relation.GIVEN)
UNKNOWN = Direction(Relation.UNKNOWN)


def perp(ref: str = "") -> Direction:
    """⊥ ref."""
    return Direction(Relation.PERP, ref)


def parallel(ref: str = "") -> Direction:
    """∥ ref."""
    return Direction(Relation.PARALLEL, ref)


def from_to(start: str, end: str) -> Direction:
    """start → end."""
    return Direction(Relation.FROM_TO, end, start)


def pole_label(label: str, language: str) -> str:
    """Chinese texts call the acceleration pole p′ (``protocol.pole.acceleration``)."""
    if "π" not in label:
        return label
    return label.replace("π", message("protocol.pole.acceleration", language))


#: a row of a vector-equation table: term, direction, magnitude
Row = tuple[str, Direction, str]
