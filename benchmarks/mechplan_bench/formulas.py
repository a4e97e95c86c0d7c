"""Other ways of computing the same: the engine λ-series and the hand-written numpy closed form."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from .model import Model
from .reference import independent, reference_result
from .results import Result


def lambda_series(model: Model, phi: np.ndarray) -> Callable[[], Result]:
    """The engine formulas to first order in λ = r/l (central slider-crank): slider B only."""
    mech = model.scene.mechanism
    r = mech.links["1"].distance("O", "A")
    length = mech.links["2"].distance("A", "B")
    lam, omega = r / length, mech.drive.omega
    theta = model.theta(phi)

    def run() -> Result:
        c1, s1, c2, s2 = np.cos(theta), np.sin(theta), np.cos(2 * theta), np.sin(2 * theta)
        zero = np.zeros_like(theta)
        out = Result()
        out.r["B"] = np.stack((r * c1 + length - 0.25 * lam * r * (1.0 - c2), zero), axis=-1)
        out.v["B"] = np.stack((-r * omega * (s1 + 0.5 * lam * s2), zero), axis=-1)
        out.a["B"] = np.stack((-r * omega * omega * (c1 + lam * c2), zero), axis=-1)
        return out
    return run


def closed_form(model: Model, phi: np.ndarray) -> Callable[[], Result] | None:
    """The hand-written vectorised numpy closed form (slider-crank, four-bar)."""
    cf = independent("closed_form")
    if model.case.name not in cf.PRESETS:
        return None
    theta = model.theta(phi)
    case = model.case

    def run() -> Result:
        res = cf.preset(case.name, theta)
        return reference_result(case, res)
    return run
