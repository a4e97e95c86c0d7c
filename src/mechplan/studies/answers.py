"""The exact answers of a study and the student's own arithmetic between their answers.

``study.answers()`` gives a :class:`Keys` of one kind (dynamics, engine, cam, gears): ``exact(name,
phi)`` is the study's value (SI) and the magnitude a diagram of it spans (for the tolerance floor);
``own(name, phi, written)`` is what the student's own other answers give by the course's formula
(δ = (ω_max − ω_min)/ω_m, P = P_г + P_j, T = P·sin(φ+β)/cos β, M = T·R, tan α = s′/(s₀ + s),
u by Willis from their own tooth numbers …), with the formula and the names it uses. Each study
builds its own (``answers()`` on the study; the formulas live next to it in ``studies/<kind>.py``).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

Written = dict[tuple[str, float | None], float]     # (canonical, φ deg) → SI value
Own = tuple[float, str, tuple[str, ...]]           # value, formula, the names it uses
Formulas = Callable[["Keys", str, float | None, Written], Own | None]


@dataclass
class Keys:
    """The exact answers of one study."""

    kind: str                                       # dynamics | engine | cam | gears
    scalars: dict[str, float] = field(default_factory=dict)
    columns: dict[str, dict[float, float]] = field(default_factory=dict)   # name → φ → value
    spans: dict[str, float] = field(default_factory=dict)
    any_angle: Any = None                           # cam: φ (deg) → {name: value}
    dimensions: dict[str, str] = field(default_factory=dict)   # where the catalogue's differs
    study: Any = None
    geometry: Any = None                            # cam: the synthesised geometry
    formulas: Formulas | None = None                # the study's own formulas (see ``own``)

    def exact(self, name: str, phi: float | None) -> float | None:
        """The exact value of ``name`` (at ``phi`` degrees for a per-angle quantity)."""
        if phi is None:
            return self.scalars.get(name)
        if self.any_angle is not None:
            return self.any_angle(phi).get(name)
        col = self.columns.get(name, {})
        return next((v for a, v in col.items() if abs(a - phi) < 1e-6), None)

    def angles(self, name: str) -> list[float]:
        """The angles a per-angle quantity is known at."""
        return sorted(self.columns.get(name, {}))

    def own(self, name: str, phi: float | None, w: Written) -> Own | None:
        """What the student's own other answers give for ``name``, or None."""
        fn = self.formulas
        return fn(self, name, phi, w) if fn else None


def span(col: dict[float, float]) -> float:
    """The largest magnitude in a per-angle column (0 when empty)."""
    return max((abs(v) for v in col.values()), default=0.0)


def written_all(w: Written, phi: float | None, *names: str) -> list[float] | None:
    """The student's values of ``names`` (at ``phi``), or None when one is missing."""
    vals = [w.get((n, phi)) for n in names]
    return [v for v in vals if v is not None] if all(v is not None for v in vals) else None


def valid_sets(k: Keys) -> dict[tuple[int, ...], Any]:
    """The tooth-number sets that meet every condition of the planetary scene."""
    pl = k.study.planetary
    if pl is None:
        return {}
    return {tuple(int(z) for z in c.z): c for c in (pl.chosen, *pl.others) if c.valid}
