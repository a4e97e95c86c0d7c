"""Engines with several cylinders on one pin, compared with their idealised form.

The idealised engine has the same masses and cylinder axes, every piston on a central slider-crank
of the master rod's R and L (equal rods). For a radial engine of n ≥ 3 cylinders at equal angles
with equal reciprocating masses m_j, its 1st-order free force is (n/2)·m_j·R·ω² turning with the
crank (a counterweight of (n/2)·m_j at R cancels it) and order k has a part turning with the crank
only when n divides k − 1, against it only when n divides k + 1. The articulated rods move their
pistons off the slider-crank law; the difference is what this module reports.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .balance import N_FFT, Balance, axis_of, harmonics, turning
from .model import EngineModel

Array = np.ndarray


@dataclass(frozen=True)
class OrderDeviation:
    """One order's free force of the engine against its idealised form: parts turning with and
    against the crank (N)."""

    k: int
    forward: float
    backward: float
    forward_ideal: float
    backward_ideal: float


def ideal_orders(model: EngineModel, orders: int) -> dict[int, Array]:
    """C of each order's free force of the idealised engine (equal rods)."""
    grid = np.arange(N_FFT) * 2.0 * math.pi / N_FFT
    out = {k: np.zeros(2, complex) for k in range(1, orders + 1)}
    by_number = {c.number: c for c in model.spec.cylinders}
    for n, c in by_number.items():
        lag = c.throw + c.bank - by_number[1].throw - by_number[1].bank
        a = model.kin.a(grid - lag, model.omega)
        coeff = harmonics(a)
        u = axis_of(model, n) * model.m_j[n]
        for k, C in out.items():
            out[k] = C + coeff[k] * u
    return out


def deviations(model: EngineModel, b: Balance) -> list[OrderDeviation]:
    """Every reported order's with/against parts, exact and idealised."""
    ideal = ideal_orders(model, max(b.orders))
    out = []
    for k, o in b.orders.items():
        f, bk = turning(o.F)
        fi, bi = turning(ideal[k])
        out.append(OrderDeviation(k, abs(f), abs(bk), abs(fi), abs(bi)))
    return out
