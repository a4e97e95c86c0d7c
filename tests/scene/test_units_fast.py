"""Common units are read without pint (issue 35, latency) — to the last bit as pint reads them."""

from __future__ import annotations

import random

import pytest

from mechplan import units
from mechplan.units import DIMENSIONS, FAST_UNITS, parse_quantity, registry

VALUES = [80, 0.1, 250, 1500, 800, 83.8, 0, 1, 12.5, 0.001, 7800, 3.14159, 123.456, -30, 1e-3,
          2.5e2]


def _pint(text: str, dimension: str) -> float:
    si = DIMENSIONS[dimension][1]
    return float(registry().Quantity(text.replace("^", "**")).to(si).magnitude)


@pytest.mark.parametrize("unit", sorted(FAST_UNITS))
def test_fast_units_equal_pint_to_the_last_bit(unit):
    dimension, _ = FAST_UNITS[unit]
    rng = random.Random(unit)
    for value in VALUES + [rng.uniform(-1e4, 1e4) for _ in range(200)]:
        text = f"{value!r} {unit}"
        assert parse_quantity(text, dimension) == _pint(text, dimension), text


def test_other_texts_go_to_pint(monkeypatch):
    calls = []
    original = units.registry

    def counted():
        calls.append(1)
        return original()

    monkeypatch.setattr(units, "registry", counted)
    assert parse_quantity("80 mm", "length") == 0.08 and not calls
    assert parse_quantity("3 ft", "length") == pytest.approx(0.9144) and calls
    with pytest.raises(units.SceneError, match="is not a length"):
        parse_quantity("80 kg", "length")          # a fast unit of another dimension: pint says why
    assert parse_quantity("2 (m/s^2)/mm", "mu_acceleration") == pytest.approx(2.0)
