"""One entry for every kind of scene: read it, solve what it asks for, report, JSON and sheets.

A scene file says what it describes with its top-level ``kind`` key: ``"mechanism"`` (the default: a
linkage, optionally with ``[dynamics]``/``[engine]`` sections), ``"cam"``, ``"gears"``,
``"engine"`` or ``"synthesis"`` (a linkage from K and its stroke or swing). Each kind is solved by
its own package and presented by its module here (``studies/<kind>.py``); the CLI and the public
API only see :class:`Study`.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

from ..errors import SceneError
from ..i18n import Text
from ..scene.document import parse_toml, read_text, scene_kind

if TYPE_CHECKING:
    from ..drafting.primitives import Sheet
    from .answers import Keys


class Study(Protocol):
    """A solved scene of any kind."""

    def report(self, language: str | None = None) -> str:
        """Return the text report in ``language`` (default: the scene's)."""
        ...

    def to_json(self) -> dict[str, Any]:
        """Return the JSON document (SI units)."""
        ...

    def sheets(self, size: str | None, standard: str | None, language: str | None,
               name: str) -> list[Sheet]:
        """Return the drawing sheets."""
        ...

    def answers(self) -> Keys:
        """Return the study's named answers and the course formulas between them (what an
        answer table is checked against; a linkage study: those of its ``[dynamics]``)."""
        ...


def solve_text(text: str, file: str, *, at_deg: list[float] | None = None,
               count: int | None = None, data_dir: str | Path | None = None) -> Study:
    """Solve a scene given as text; ``at_deg``/``count`` choose crank positions of a mechanism;
    the data files it names are read inside ``data_dir`` (default: the scene's folder)."""
    data = parse_toml(text, file)
    kind = scene_kind(data, file)
    if kind == "mechanism":
        from ..scene import parse_scene
        from ..scene.dynamics import parse_dynamics
        from ..solve import solve
        from .mechanism import MechanismStudy

        scene = parse_scene(text, file)
        spec = parse_dynamics(data, file, scene.mechanism)
        solution = solve(scene, at_deg=at_deg, count=count)
        if spec is None:
            return MechanismStudy(solution)
        from .machine import solve_dynamics

        return MechanismStudy(solution, solve_dynamics(solution, spec))
    if kind == "engine":
        from .engine import solve_engine_text

        return solve_engine_text(text, file, data_dir=data_dir)
    if kind == "cam":
        from .cam import solve_cam

        return solve_cam(text, file)
    if kind == "gears":
        from .gears import solve_gear_text

        return solve_gear_text(text, file)
    if kind == "cycle":
        from .cycle import solve_cycle_text

        return solve_cycle_text(text, file, data_dir=data_dir)
    if kind == "synthesis":
        from .synthesis import solve_synthesis_text

        return solve_synthesis_text(text, file)
    raise SceneError(Text("errmsg.studies.scenes_kind_kind", {"kind": repr(kind)}), file=file,
                     key="kind")


def solve_file(path: str | Path, *, at_deg: list[float] | None = None,
               count: int | None = None, data_dir: str | Path | None = None) -> Study:
    """Read and solve a scene file of any kind (``data_dir``: see :func:`solve_text`)."""
    return solve_text(read_text(path), str(path), at_deg=at_deg, count=count, data_dir=data_dir)
