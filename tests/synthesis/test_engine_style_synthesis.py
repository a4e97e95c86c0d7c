"""Engine-style synthesis by the rod ratio λ = r/l (issue 31): the central slider-crank by λ and
H, the central crank-rocker (K = 1) by λ and the swing, and a crank-rocker of the K family chosen
by λ — checked against the law of cosines in the two dead-centre triangles and by the analysis."""

from __future__ import annotations

import math

import pytest

from mechplan.errors import SceneError
from mechplan.studies import solve_text
from mechplan.studies.synthesis import SynthesisStudy

DEG = math.pi / 180


def study(problem: str, **keys: object) -> SynthesisStudy:
    lines = ['kind = "synthesis"', "[synthesis]", f'problem = "{problem}"']
    lines += [f'{k} = "{v}"' if isinstance(v, str) else f"{k} = {v!r}" for k, v in keys.items()]
    s = solve_text("\n".join(lines) + "\n", "t.toml")
    assert isinstance(s, SynthesisStudy)
    return s


def dead_centre_angles(r, l, c, d):
    """θ at A and ψ at D between the two dead-centre triangles (AC = l − r and l + r)."""
    def at_a(ac):
        return math.acos((ac * ac + d * d - c * c) / (2 * ac * d))

    def at_d(ac):
        return math.acos((c * c + d * d - ac * ac) / (2 * c * d))

    return abs(at_a(l - r) - at_a(l + r)), abs(at_d(l + r) - at_d(l - r))


@pytest.mark.parametrize("lam, stroke", [(0.25, 160.0), (0.3, 90.0)])
def test_central_slider_crank_by_lambda_and_stroke(lam, stroke):
    s = study("slider_crank", K=1, stroke=f"{stroke} mm", **{"lambda": lam})
    n = s.design.lengths
    assert n["r"] * 1e3 == pytest.approx(stroke / 2, abs=1e-9)
    assert n["l"] * 1e3 == pytest.approx(stroke / 2 / lam, abs=1e-9)
    assert s.check.k == pytest.approx(1.0, abs=1e-9)
    assert s.check.output * 1e3 == pytest.approx(stroke, abs=1e-6)


@pytest.mark.parametrize("lam, psi, c", [(0.3, 45.0, 300.0), (0.2, 60.0, 150.0),
                                         (0.4, 30.0, 200.0)])
def test_central_crank_rocker_by_lambda(lam, psi, c):
    s = study("crank_rocker", K=1, swing=f"{psi} deg", rocker=f"{c} mm", **{"lambda": lam})
    n = s.design.lengths
    r, l, d = n["r"] * 1e3, n["l"] * 1e3, n["d"] * 1e3
    assert r / l == pytest.approx(lam, abs=1e-12)
    theta, swing = dead_centre_angles(r, l, c, d)
    assert theta == pytest.approx(0.0, abs=1e-7)         # K = 1: the crank's dead centres 180°
    assert swing == pytest.approx(psi * DEG, abs=1e-12)
    assert s.check.k == pytest.approx(1.0, abs=1e-9)
    assert s.check.output == pytest.approx(psi * DEG, abs=1e-9)
    # γmin in closed form: at the crank folded onto and stretched along the frame
    mu = [math.acos((l * l + c * c - bd * bd) / (2 * l * c)) for bd in (d - r, d + r)]
    assert s.design.conditions["gamma_min"] == pytest.approx(
        min(min(m, math.pi - m) for m in mu), abs=1e-12)
    assert s.check.gamma_min == pytest.approx(s.design.conditions["gamma_min"], abs=1e-3)


@pytest.mark.parametrize("k, lam", [(1.2, 0.3), (1.4, 0.35)])
def test_crank_rocker_of_the_k_family_chosen_by_lambda(k, lam):
    s = study("crank_rocker", K=k, swing="45 deg", rocker="300 mm", **{"lambda": lam})
    n = s.design.lengths
    r, l, c, d = (n[x] * 1e3 for x in ("r", "l", "c", "d"))
    assert r / l == pytest.approx(lam, abs=1e-9)
    theta, swing = dead_centre_angles(r, l, c, d)
    assert theta == pytest.approx(math.pi * (k - 1) / (k + 1), abs=1e-9)
    assert swing == pytest.approx(45 * DEG, abs=1e-9)
    assert s.check.k == pytest.approx(k, abs=1e-9)


def test_lambda_errors_name_the_key():
    with pytest.raises(SceneError, match="lambda"):
        study("crank_rocker", K=1, swing="45 deg", rocker="300 mm", **{"lambda": 1.5})
    with pytest.raises(SceneError, match="lambda"):
        study("crank_rocker", K=1.2, swing="45 deg", rocker="300 mm", frame="400 mm",
              **{"lambda": 0.3})
    with pytest.raises(SceneError, match="lambda"):
        study("crank_rocker", K=1.2, swing="45 deg", rocker="300 mm", **{"lambda": 0.01})
    with pytest.raises(SceneError, match="K"):             # K = 1 without λ: no K circle
        study("crank_rocker", K=1, swing="45 deg", rocker="300 mm")
