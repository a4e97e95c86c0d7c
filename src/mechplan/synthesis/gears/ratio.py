"""The exact ratio u = ω_in/ω_out of a solved gear scene (a train between a motor and a shaft):
its planetary stage by Willis in fractions, times its ordinary stage −z6/z5, or its pair alone."""

from __future__ import annotations

from fractions import Fraction

from ...errors import SceneError
from ...i18n import Text
from ...model.gears import Scheme
from .solve import GearSolution
from .train import willis_exact


def planetary_fraction(scheme: Scheme, z: tuple[int, ...], fixed: str, inp: str, out: str
                       ) -> Fraction | None:
    """u_in,out with ``fixed`` held, exact (None at a pole: the output cannot turn)."""
    i = willis_exact(scheme, z)
    a, b, h = scheme.links
    if fixed == h:
        if (inp, out) == (a, b):
            return i
        return 1 / i if i else None
    i_xy = i if fixed == b else 1 / i        # x = the moving central gear, y = the held one
    if out == h:
        return 1 - i_xy                      # ω_x/ω_h = 1 − i_xy^h
    return 1 / (1 - i_xy) if i_xy != 1 else None


def train_fraction(sol: GearSolution) -> list[tuple[str, Fraction]]:
    """The stages of the scene's train in order, each (name, exact u): "planetary" (its chosen
    set), "ordinary" (u56 = −z6/z5), or "pair" (u12 = −z2/z1) when the scene has only a pair.
    A differential (two inputs) or a stage at a pole is refused."""
    stages: list[tuple[str, Fraction]] = []
    res = sol.planetary
    if res is not None:
        s = res.spec
        if s.speeds is not None:
            raise SceneError(Text("machine.error.differential"), key="planetary.speeds")
        u = planetary_fraction(s.scheme, tuple(res.chosen.z), s.fixed, s.input, s.output)
        if u is None or u == 0:
            raise SceneError(Text("machine.error.pole"), key="planetary")
        stages.append(("planetary", u))
    if sol.ordinary is not None:
        stages.append(("ordinary", Fraction(-sol.ordinary.z6, sol.ordinary.z5)))
    if not stages and sol.pair is not None:
        stages.append(("pair", Fraction(-sol.pair.spec.z2, sol.pair.spec.z1)))
    if not stages and sol.internal is not None:      # a ring turns with its pinion: + z2/z1
        stages.append(("pair", Fraction(sol.internal.spec.z2, sol.internal.spec.z1)))
    if not stages:
        raise SceneError(Text("machine.error.no_train"), key="planetary")
    return stages
