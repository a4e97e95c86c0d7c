"""Typed, read-only results of the public API: solutions, forces, mappings by name."""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from typing import Any, TypeVar

import numpy as np


def _frozen(a: Any) -> np.ndarray:
    """A read-only float array: the evaluation's own read-only arrays are shared, not copied."""
    if isinstance(a, np.ndarray) and a.dtype == float and not a.flags.writeable:
        return a
    out = np.array(a, dtype=float, copy=True)
    out.flags.writeable = False
    return out


V = TypeVar("V")


class ByName(Mapping[str, V]):
    """A read-only mapping from a point or link name to its values over the positions."""

    def __init__(self, values: dict[str, V], what: str) -> None:
        self._values = values
        self._what = what

    def __getitem__(self, name: object) -> V:
        key = str(name)
        if key not in self._values:
            known = ", ".join(self._values) or "none"
            raise KeyError(f"no {self._what} of {key!r}; known: {known}")
        return self._values[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._values)

    def __len__(self) -> int:
        return len(self._values)

    def __repr__(self) -> str:
        return f"<{self._what} of {', '.join(self._values)}>"


class _Columns(ByName[np.ndarray]):
    """A :class:`ByName` over the columns of one read-only block: views made on first access."""

    __slots__ = ("_block", "_values", "_views", "_what")

    def __init__(self, block: np.ndarray, columns: dict[str, slice | int], what: str) -> None:
        # ByName's fields set here directly: six of these are made per solve call
        self._values = columns          # type: ignore[assignment]
        self._what = what
        self._block = block
        self._views: dict[str, np.ndarray] = {}

    def __getitem__(self, name: object) -> np.ndarray:
        key = str(name)
        view = self._views.get(key)
        if view is None:
            col = self._values.get(key)
            if col is None:
                return super().__getitem__(key)      # raises the KeyError naming the known ones
            view = self._views[key] = self._block[:, col]
        return view


@dataclass(frozen=True, slots=True)
class InertiaLoad:
    """Inertia of a link over the positions: force ``Q`` (N, 2) in N, moment ``M_q`` (N,) in N·m."""

    link: str
    Q: np.ndarray
    M_q: np.ndarray


@dataclass(frozen=True, slots=True)
class PairReaction:
    """Reaction ``R_ij`` (N, 2), in N: the force of link ``i`` on link ``j`` at their pair.

    For a prismatic pair ``guide`` names the guide and ``offset`` (N,), in m, is where the line of
    action crosses the guide, measured from ``point`` (NaN where the reaction is a pure couple).
    """

    key: str
    i: str
    j: str
    point: str
    R: np.ndarray
    guide: str | None = None
    offset: np.ndarray | None = None


@dataclass(frozen=True, slots=True)
class Forces:
    """Kinetostatics over the positions (SI units, moments counter-clockwise positive).

    Attributes
    ----------
    inertia : Mapping[str, InertiaLoad]
        Inertia force and moment of each link with mass data.
    reactions : Mapping[str, PairReaction]
        Reactions of revolute pairs, keyed ``"ij"`` (``"01"``, ``"12"`` …).
    guide_reactions : Mapping[str, PairReaction]
        Reactions of prismatic pairs.
    M_b, M_b_zhukovsky : np.ndarray
        Balancing moment on the crank (N,) from the force polygons and from Zhukovsky's lever.
    M_red, J_red : np.ndarray
        Reduced moment (N·m) and reduced moment of inertia (kg·m²), shape (N,).
    friction : FrictionAnalysis or None
        With ``[friction]``: M_b without friction, the efficiency η, the iteration and each
        pair's friction load (``mechplan.dynamics.friction``; docs/forces.md).
    """

    inertia: Mapping[str, InertiaLoad]
    reactions: Mapping[str, PairReaction]
    guide_reactions: Mapping[str, PairReaction]
    M_b: np.ndarray
    M_b_zhukovsky: np.ndarray
    M_red: np.ndarray
    J_red: np.ndarray
    friction: Any = None


@dataclass(frozen=True, slots=True)
class Solution:
    """A mechanism solved at N crank positions; every array is read-only, SI units.

    Attributes
    ----------
    phi_deg : np.ndarray
        Crank angles φ (N,) in degrees, in the scene's convention (from ``drive.from``, in the
        sense of rotation).
    r, v, a : Mapping[str, np.ndarray]
        Position (m), velocity (m/s) and acceleration (m/s²) of each point, shape (N, 2).
    angle, omega, epsilon : Mapping[str, np.ndarray]
        Angle (rad), angular velocity (rad/s) and acceleration (rad/s²) of each moving link
        (keys ``"1"``, ``"2"`` …), shape (N,), counter-clockwise positive.
    forces : Forces or None
        Kinetostatics when the force plan was asked for (a scene with masses or loads).
    flags : tuple of (position, quantity, subject, estimate)
        Results whose estimated relative error exceeds the tolerance (see docs/estimates.md).
    textbook : TextbookAnswers or None
        The textbook answers the scene's ``[answers]`` asks for (docs/textbook.md): sliding,
        relative, rubbing, transmission, strokes, least velocity.
    """

    phi_deg: np.ndarray
    r: Mapping[str, np.ndarray]
    v: Mapping[str, np.ndarray]
    a: Mapping[str, np.ndarray]
    angle: Mapping[str, np.ndarray]
    omega: Mapping[str, np.ndarray]
    epsilon: Mapping[str, np.ndarray]
    forces: Forces | None
    flags: tuple[tuple[int, str, str, float], ...] = ()
    textbook: Any = None

    @property
    def positions(self) -> int:
        """Number of positions N."""
        return int(self.phi_deg.shape[0])
