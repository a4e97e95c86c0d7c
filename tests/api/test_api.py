"""The public API against a closed-form slider-crank (independent of the construction)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import mechplan
from mechplan import solve as solve_module

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "templates" / "slider_crank.toml"
R, L = 0.100, 0.400                      # template: OA = 100 mm, AB = 400 mm, S2 = 0.3 of A B
W1 = 1500 * 2 * math.pi / 60             # 1500 rpm counter-clockwise, φ from +x
M2, J2, M3 = 4.0, 0.06, 3.0


def closed_form(phi_deg: np.ndarray) -> dict[str, np.ndarray]:
    """Slider-crank by hand: x_B = r cos θ + √(l² − r² sin² θ), derivatives in θ, times ω1."""
    t = np.radians(phi_deg)
    s, c = np.sin(t), np.cos(t)
    root = np.sqrt(L**2 - R**2 * s**2)
    root_t = -R**2 * s * c / root
    x = R * c + root
    x_t = -R * s + root_t
    x_tt = -R * c - R**2 * (c**2 - s**2) / root - R**4 * s**2 * c**2 / root**3
    psi = np.arctan2(-R * s, root)
    psi_t = -R * c / root
    psi_tt = R * s / root - R**3 * s * c**2 / root**3
    a_pt = np.stack([R * c, R * s], axis=1)
    va = np.stack([-R * s, R * c], axis=1) * W1
    aa = -a_pt * W1**2
    b = np.stack([x, 0 * x], axis=1)
    vb = np.stack([x_t * W1, 0 * x], axis=1)
    ab = np.stack([x_tt * W1**2, 0 * x], axis=1)
    vs, as_ = 0.7 * va + 0.3 * vb, 0.7 * aa + 0.3 * ab
    omega2, eps2 = psi_t * W1, psi_tt * W1**2
    # virtual power: M_b ω1 + Σ(−m a_S · v_S) + (−J ε ω) = 0 (no gravity, no external load)
    m_b = (M2 * np.sum(as_ * vs, axis=1) + J2 * eps2 * omega2 + M3 * np.sum(ab * vb, axis=1)) / W1
    return {"A": a_pt, "B": b, "vA": va, "vB": vb, "aB": ab, "aS2": as_, "psi": psi,
            "omega2": omega2, "eps2": eps2, "M_b": m_b}


PHI = np.array([0.0, 17.0, 30.0, 95.0, 200.0, 333.3])


@pytest.fixture(scope="module")
def mech() -> mechplan.Mechanism:
    m = mechplan.load(SCENE)
    assert isinstance(m, mechplan.Mechanism)
    return m


def test_kinematics_match_the_closed_form(mech: mechplan.Mechanism) -> None:
    sol = mech.solve(phi_deg=PHI)
    ref = closed_form(PHI)
    assert sol.positions == PHI.size
    np.testing.assert_allclose(sol.phi_deg, PHI)
    assert sol.r["B"].shape == (PHI.size, 2) and sol.omega["2"].shape == (PHI.size,)
    np.testing.assert_allclose(sol.r["A"], ref["A"], atol=1e-12)
    np.testing.assert_allclose(sol.r["B"], ref["B"], atol=1e-12)
    np.testing.assert_allclose(sol.v["A"], ref["vA"], atol=1e-9)
    np.testing.assert_allclose(sol.v["B"], ref["vB"], atol=1e-9)
    np.testing.assert_allclose(sol.a["B"], ref["aB"], rtol=1e-9, atol=1e-6)
    np.testing.assert_allclose(sol.a["S2"], ref["aS2"], rtol=1e-9, atol=1e-6)
    np.testing.assert_allclose(np.remainder(sol.angle["2"] - ref["psi"] + np.pi, 2 * np.pi),
                               np.pi, atol=1e-12)
    np.testing.assert_allclose(sol.omega["2"], ref["omega2"], atol=1e-9)
    np.testing.assert_allclose(sol.epsilon["2"], ref["eps2"], rtol=1e-9, atol=1e-6)
    np.testing.assert_allclose(sol.omega["1"], W1, rtol=1e-15)
    assert sol.omega[2] is sol.omega["2"]                 # a link may be named by its number


def test_forces_are_typed_and_satisfy_virtual_power(mech: mechplan.Mechanism) -> None:
    sol = mech.solve(phi_deg=PHI)
    assert isinstance(sol.forces, mechplan.Forces)
    np.testing.assert_allclose(sol.forces.M_b, closed_form(PHI)["M_b"], rtol=1e-8, atol=1e-7)
    np.testing.assert_allclose(sol.forces.M_b_zhukovsky, sol.forces.M_b, rtol=1e-8, atol=1e-7)
    r12 = sol.forces.reactions["12"]
    assert isinstance(r12, mechplan.PairReaction) and r12.R.shape == (PHI.size, 2)
    inertia = sol.forces.inertia["3"]
    assert isinstance(inertia, mechplan.InertiaLoad)
    np.testing.assert_allclose(inertia.Q, -M3 * closed_form(PHI)["aB"], rtol=1e-9, atol=1e-6)


def test_arrays_are_read_only_and_mappings_name_the_unknown(mech: mechplan.Mechanism) -> None:
    sol = mech.solve(phi_deg=30)
    with pytest.raises(ValueError):
        sol.r["B"][0, 0] = 1.0
    with pytest.raises(ValueError):
        sol.omega["2"][0] = 1.0
    with pytest.raises(KeyError, match="'Z'"):
        sol.r["Z"]
    with pytest.raises(TypeError):
        sol.r["B"] = np.zeros((1, 2))          # type: ignore[index]


def test_construction_is_built_once_and_reused(mech: mechplan.Mechanism, monkeypatch) -> None:
    m = mechplan.load(SCENE)
    calls = []
    real = solve_module.build
    monkeypatch.setattr(solve_module, "build", lambda *a, **k: calls.append(1) or real(*a, **k))
    first = m.solve(phi_deg=[10.0])
    second = m.solve(phi_deg=[10.0, 20.0])
    m.solve(positions=6)
    assert len(calls) == 1
    np.testing.assert_array_equal(first.r["B"][0], second.r["B"][0])
    m.solve(phi_deg=5, plans=["position"])
    assert len(calls) == 2
    assert m.construction(["position"]) is m.construction(["position"])


def test_no_scale_factors_are_chosen_when_nothing_is_drawn(mech, monkeypatch) -> None:
    def refuse(*args, **kwargs):
        raise AssertionError("choose_scales called")

    monkeypatch.setattr(solve_module, "choose_scales", refuse)
    mech.solve(phi_deg=[0, 90])


def test_positions_count_from_the_scene_start(mech: mechplan.Mechanism) -> None:
    sol = mech.solve(positions=8)
    # the template starts at the outer dead centre (B farthest): φ = 0 for a central slider-crank
    np.testing.assert_allclose(sol.phi_deg, np.arange(8) * 45.0, atol=1e-6)
    default = mech.solve()
    assert default.positions == 12


def test_only_asked_plans(mech: mechplan.Mechanism) -> None:
    sol = mech.solve(phi_deg=[10], plans=["position"])
    assert "B" in sol.r and len(sol.v) == 0 and len(sol.omega) == 0 and sol.forces is None


@pytest.mark.parametrize("kwargs, match", [
    ({"positions": 0}, "positions must be a whole number"),
    ({"phi_deg": [float("nan")]}, "phi_deg must be finite"),
    ({"phi_deg": 10, "positions": 3}, "either phi_deg or positions"),
    ({"plans": ["speed"]}, "plans must be among"),
])
def test_bad_arguments_are_user_errors(mech, kwargs, match) -> None:
    with pytest.raises(mechplan.MechplanError, match=match):
        mech.solve(**kwargs)


def test_loads_from_text_and_dict_agree_with_the_file() -> None:
    import tomllib

    text = SCENE.read_text(encoding="utf-8")
    from_text = mechplan.loads(text)
    from_dict = mechplan.load(tomllib.loads(text))
    a = from_text.solve(phi_deg=[40]).v["B"]
    b = from_dict.solve(phi_deg=[40]).v["B"]
    np.testing.assert_array_equal(a, b)
    np.testing.assert_allclose(a, closed_form(np.array([40.0]))["vB"], atol=1e-9)


def test_dict_errors_name_the_key() -> None:
    import tomllib

    data = tomllib.loads(SCENE.read_text(encoding="utf-8"))
    data["links"]["1"]["lengths"]["OA"] = "-5 mm"
    with pytest.raises(mechplan.SceneError, match=r"<dict>.*links\.1\.lengths"):
        mechplan.load(data)


def test_draw_writes_the_sheet(tmp_path: Path) -> None:
    written = mechplan.draw(SCENE, tmp_path / "out", formats=["svg"])
    # kinematics and kinetostatics share the A1 sheet (no wasted second sheet)
    assert written == [tmp_path / "out" / "slider_crank.svg"]
    assert written[0].read_text(encoding="utf-8").lstrip().startswith("<?xml")


def test_draw_into_a_file_is_a_user_error(tmp_path: Path) -> None:
    blocker = tmp_path / "out"
    blocker.write_text("x")
    with pytest.raises(mechplan.DrawingError, match="must be a folder"):
        mechplan.draw(SCENE, blocker, formats=["svg"])
