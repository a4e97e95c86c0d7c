"""`Construction.evaluate(phi, overrides=...)`: a plan re-derived from given (a student's)
points."""

from __future__ import annotations

import numpy as np
import pytest

from .sheets import solved


def test_overrides_re_derive_the_steps_built_on_them() -> None:
    _scene, sol = solved("four_bar", 60)
    c = sol.construction
    b, cc = c.position("B"), c.position("C")
    # give B the place it has at φ = 100°: C found from it must be C at φ = 100°, since C depends
    # on the crank only through B (closed form: the same circle–circle meet, evaluated apart)
    other = c.evaluate(np.radians([100.0]))
    ev = c.evaluate(sol.phi, overrides={b: np.asarray(other[b])})
    assert np.asarray(ev[cc]) == pytest.approx(np.asarray(other[cc]), abs=1e-12)
    assert np.asarray(ev[b]) == pytest.approx(np.asarray(other[b]), abs=0)
    # steps not built on B keep their exact values
    a = c.position("A")
    assert np.asarray(ev[a]) == pytest.approx(np.asarray(sol.ev[a]), abs=0)


def test_an_override_must_have_one_value_per_position() -> None:
    _scene, sol = solved("four_bar", 60)
    c = sol.construction
    ev = c.evaluate(sol.phi, overrides={c.position("B"): np.zeros((3, 2))})
    with pytest.raises(ValueError, match="1 positions"):
        ev[c.position("C")]
