"""A linkage solved at its positions: plans, forces and what its sections ask for."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ..drafting.primitives import Sheet
    from ..dynamics.machine import MachineDynamics
    from ..sheet.scales import Decision
    from ..solve import Solution
    from .answers import Keys


@dataclass(frozen=True)
class MechanismStudy:
    """A linkage solved at its positions (plans, forces and what its sections ask for).

    ``dynamics``: the machine's dynamics over its cycle when the scene has ``[dynamics]``.
    """

    solution: Solution
    dynamics: MachineDynamics | None = None

    def report(self, language: str | None = None) -> str:
        from ..report import text_report

        text = text_report(self.solution, language)
        if "centres" in self.solution.plans:
            from .centres_report import centres_report

            text = (text.rstrip("\n") + "\n\n"
                    + centres_report(self.solution, language or self.solution.scene.language))
        if self.dynamics is not None:
            from .machine import dynamics_report

            lang = language or self.solution.scene.language
            text = (text.rstrip("\n") + "\n\n"
                    + dynamics_report(self.dynamics, lang, self._enlargement()) + "\n")
        said = self.scale_notes(language)
        if said:
            from ..i18n import message

            d = self.scale_decision()
            lang = language or self.solution.scene.language
            heading = message("scales.heading", lang, size=d.size, standard=d.standard.upper())
            text = (text.rstrip("\n") + f"\n\n{heading}\n"
                    + "".join(f"  - {line}\n" for line in said))
        return text

    def scale_decision(self, size: str | None = None, standard: str | None = None) -> Decision:
        """The scale factors of a sheet with their reasons (by default the sheet the solution's
        scales are for: ``extras["sheet"]``, else the scene's own)."""
        from ..sheet.scales import decide

        sol = self.solution
        size_, standard_ = sol.extras.get("sheet", (None, None))
        return decide(sol.scene, sol.construction, sol.ev, sol.plans, size or size_,
                      standard or standard_)

    def scale_notes(self, language: str | None = None, size: str | None = None,
                    standard: str | None = None) -> list[str]:
        """What the scale factors of a sheet could not do as asked: fixed values not kept,
        plans enlarged so their segments are readable, segments still shorter than 2 mm."""
        from ..sheet.scales import notes

        sol = self.solution
        return notes(self.scale_decision(size, standard), language or sol.scene.language,
                     sol.scene, sol.construction, sol.ev)

    def warnings(self, language: str | None = None) -> list[str]:
        """Warnings for positions not built and results whose error estimate is poor."""
        from ..trust_report import warning_lines

        return warning_lines(self.solution, language)

    def to_json(self) -> dict[str, Any]:
        from ..solve import to_json

        doc = to_json(self.solution)
        if "centres" in self.solution.plans:
            from .centres import centres_json

            doc["centres"] = centres_json(self.solution)
        if self.dynamics is not None:
            from .machine import dynamics_json

            doc["dynamics"] = dynamics_json(self.dynamics, self._enlargement())
        from ..sheet.scales import decision_json

        doc["scale_decision"] = decision_json(self.scale_decision())
        return doc

    def answers(self) -> Keys:
        """The exact answers of the machine's dynamics (a scene with ``[dynamics]``), else the
        linkage's textbook answers (strokes, K, γ, sliding and rubbing velocities …)."""
        if self.dynamics is None:
            from .linkage import linkage_answers

            return linkage_answers(self.solution)
        from .machine import dynamics_answers

        return dynamics_answers(self.to_json()["dynamics"])

    def _enlargement(self) -> float:
        """The enlargement of the dynamics diagrams on the scene's own sheet."""
        from ..sheet.dynamics import dynamics_enlargement

        assert self.dynamics is not None
        return dynamics_enlargement(self.dynamics, self.solution.scene)

    def sheets(self, size: str | None, standard: str | None, language: str | None,
               name: str) -> list[Sheet]:
        from ..sheet.compose import compose_sheets

        sheets = compose_sheets(self.solution, size, standard, language, name=name)
        if self.dynamics is not None:
            from ..sheet.dynamics import dynamics_sheets

            scene = self.solution.scene
            sheets += dynamics_sheets(self.dynamics, scene, size or scene.drawing.sheet,
                                      standard or scene.drawing.standard,
                                      language or scene.language, f"{name}-dynamics")
        return sheets
