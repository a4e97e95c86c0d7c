"""A linkage solved at its positions: plans, forces and what its sections ask for."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ..sheet.primitives import Sheet
    from ..solve import Solution


@dataclass(frozen=True)
class MechanismStudy:
    """A linkage solved at its positions (plans, forces and what its sections ask for)."""

    solution: Solution

    def report(self, language: str | None = None) -> str:
        from ..report import text_report

        return text_report(self.solution, language)

    def warnings(self, language: str | None = None) -> list[str]:
        """Warnings for positions not built and results whose error estimate is poor."""
        from ..trust_report import warning_lines

        return warning_lines(self.solution, language)

    def to_json(self) -> dict[str, Any]:
        from ..solve import to_json

        return to_json(self.solution)

    def sheets(self, size: str | None, standard: str | None, language: str | None,
               name: str) -> list[Sheet]:
        from ..sheet.compose import compose_sheets

        return compose_sheets(self.solution, size, standard, language, name=name)
