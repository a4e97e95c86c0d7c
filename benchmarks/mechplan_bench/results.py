"""What a method produces (:class:`Result`) and what a run records of it (:class:`Row`)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np


@dataclass
class Result:
    """Kinematics a method produced at N positions: points (N, 2) and link scalars (N,)."""

    r: dict[str, np.ndarray] = field(default_factory=dict)
    v: dict[str, np.ndarray] = field(default_factory=dict)
    a: dict[str, np.ndarray] = field(default_factory=dict)
    omega: dict[str, np.ndarray] = field(default_factory=dict)
    epsilon: dict[str, np.ndarray] = field(default_factory=dict)


@dataclass
class Row:
    """One measurement: a method on a mechanism at N positions."""

    mechanism: str
    method: str
    n: int
    seconds: float              # best of ``repeats`` for all N positions
    repeats: int
    compared: int               # positions compared with the reference
    errors: dict[str, float] = field(default_factory=dict)   # kind → relative error
    note: str = ""

    @property
    def ns_per_position(self) -> float:
        """Time per position in nanoseconds."""
        return self.seconds / self.n * 1e9

    @property
    def max_error(self) -> float:
        """Largest relative error over the kinds this method gives (inf if it failed)."""
        return max(self.errors.values()) if self.errors else math.nan
