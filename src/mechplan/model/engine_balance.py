"""What an engine scene's ``[balance]`` table asks for: throw positions along the crankshaft, the
orders of the harmonic analysis, the counterweights and the balance shafts."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class BalanceSpec:
    """Balancing inputs (SI units)."""

    positions: tuple[float, ...] | None = None   # axial position of each throw (pin), m
    orders: int = 6                              # highest harmonic order reported
    share: float = 0.5                           # reciprocating share on the counterweights
    cw_radius: float | None = None               # radius of a cheek's counterweight centre, m
    shafts: bool = False                         # size Lanchester balance shafts for the 2nd order
    rod_offset: float = 0.0                      # side-by-side rods: distance between their planes
