"""The heat balance of the thermal calculation and its sheet panels.

Golden values are identities of the courses' definitions written out independently here: the
effective share is η_e (Q_e/Q0 = N_e/(H_u·g_e·N_e)), incomplete combustion's share is ΔH_u/H_u,
the coolant's heat is the empirical formula evaluated by hand, the exhaust's heat is the products'
internal energy plus pV at t_r less the fresh charge's at t0 written gas by gas, and the shares
sum to 100 %. The panel's points lie on the calculation's polytropes at the drawn scale.
"""

from __future__ import annotations

import math

import pytest
from helpers import diesel_2600

from mechplan.drafting.primitives import Circle, Table, Text
from mechplan.i18n import number
from mechplan.model.engine_heat_balance import cycle_points, heat_balance
from mechplan.model.engine_thermal import LOW, CycleSpec, thermal_cycle
from mechplan.scene.engine import parse_engine_scene
from mechplan.sheet.engine import _thermal_panels
from mechplan.studies.engine import EngineStudy


def petrol(alpha: float = 0.9) -> CycleSpec:
    return CycleSpec(False, 0.855, 0.145, 0.0, 43.93e3, 115.0, alpha, 8.5, 5600, 0.1e6, 293.0,
                     8.0, 0.085e6, 0.118e6, 1070.0, 1.377, 1.251, 0.91, 0.0, 0.5, 0.96, 0.85, 4, 4,
                     None, 1.0, 0.48, 0.62)


def diesel(alpha: float = 1.4) -> CycleSpec:
    return CycleSpec(True, 0.870, 0.126, 0.004, 42.44e3, 0.0, alpha, 17.0, 2600, 0.1e6, 293.0,
                     15.0, 0.088e6, 0.11e6, 750.0, 1.37, 1.26, 0.82, 1.7, 0.5, 0.95, 0.8, 4, 8)


@pytest.mark.parametrize("spec,bore", [(petrol(0.9), 0.082), (petrol(1.05), 0.082),
                                       (diesel(1.4), 0.12), (diesel(1.8), 0.12)])
def test_heat_balance_against_its_definitions(spec, bore):
    c = thermal_cycle(spec)
    N_e = c.power(math.pi / 4.0 * bore ** 3)           # S = D
    b = heat_balance(c, N_e, bore, spec.cylinders)
    # fuel per hour and the heat it brings
    G_T = c.g_e * (N_e / 1e3) / 1e3
    assert b.G_T == pytest.approx(G_T, rel=1e-12)
    assert b.Q0 == pytest.approx(spec.H_u * 1e3 * G_T / 3600.0, rel=1e-12)
    q = b.shares
    assert sum(q.values()) == pytest.approx(100.0, abs=1e-9)
    assert q["e"] == pytest.approx(100.0 * c.eta_e, rel=1e-12)
    assert q["ic"] == pytest.approx(100.0 * c.dH_u / spec.H_u, abs=1e-12)
    assert (q["ic"] > 0) == (spec.alpha < 1.0)
    # coolant: c·i·D^(1+2m)·n^m/α (D in cm), times (H_u − ΔH_u)/H_u for spark ignition
    D = bore * 100.0
    Qw = spec.coolant_c * spec.cylinders * D ** (1 + 2 * spec.coolant_m) \
        * spec.speed_rpm ** spec.coolant_m / spec.alpha
    if not spec.diesel:
        Qw *= 1.0 - c.dH_u / spec.H_u
    assert b.flows["w"] == pytest.approx(Qw, rel=1e-12)
    # exhaust: products' (u + RT) at t_r less the charge's at t0, gas by gas
    t_r, t0 = spec.T_r - 273.0, spec.T0 - 273.0
    products = sum(n * ((LOW[g][0] + LOW[g][1] * t_r + LOW[g][2] * t_r ** 2) + 8.315) * t_r
                   for g, n in c.products.items())
    charge = c.M1 * (20.6 + 2.638e-3 * t0 + 8.315) * t0
    assert b.flows["r"] == pytest.approx(G_T / 3.6 * (products - charge), rel=1e-12)
    # the courses' ranges: work, coolant and exhaust take the larger parts, the rest is positive
    assert all(v > 0 for k, v in q.items() if k != "ic")


SCENE = diesel_2600(engine_extra="cylinders = 8\nfiring_order = [1, 5, 4, 2, 6, 3, 7, 8]",
                    thermal_extra="coolant_c = 0.47\ncoolant_m = 0.68")


@pytest.fixture(scope="module")
def study() -> EngineStudy:
    return EngineStudy(parse_engine_scene(SCENE, "d.toml"))


def test_balance_in_json_and_report(study):
    c, spec = study.scene.cycle, study.scene.engine
    doc = study.to_json()["thermal"]["heat_balance"]
    N_e = c.p_e * spec.V_h * 8 * 2600 / 60.0 / 2.0       # p_e·V_h·i·n/(30τ), τ = 4
    assert doc["N_e"] == pytest.approx(N_e, rel=1e-9)
    assert (doc["c"], doc["m"]) == (0.47, 0.68)
    assert sum(doc["q"].values()) == pytest.approx(100.0, abs=1e-9)
    assert doc["Q0"] == pytest.approx(sum(doc["Q"].values()), rel=1e-12)
    text = study.report("ru")
    assert "Тепловой баланс" in text and number(doc["q"]["w"], 2, "ru") in text


def test_thermal_panels_draw_the_calculated_points(study):
    c, spec = study.scene.cycle, study.scene.engine
    panels = {p.name: p for p in _thermal_panels(study, "en", 1.0)}
    assert set(panels) == {"thermal_indicator", "thermal_results", "thermal_balance"}
    ind = panels["thermal_indicator"].primitives
    labels = {t.string: t.position for t in ind if isinstance(t, Text)}
    assert {"a", "c", "z′", "z", "b"} <= set(labels)
    circles = [p.center for p in ind if isinstance(p, Circle) and p.radius == 0.6]
    pts = cycle_points(c, spec.V_h).points
    # the drawing's scales from two of the points; every other point must sit at them
    (Va, pa), (Vc, pc) = pts["a"], pts["c"]
    xa, ya = circles[0]
    xc, yc = circles[1]
    mu_x = (Va - Vc) * 1e6 / (xa - xc)
    mu_y = (pc - pa) * 1e-6 / (yc - ya)
    assert Va * 1e6 / mu_x == pytest.approx(xa, abs=1e-9)
    for (V, p), (x, y) in zip(pts.values(), circles):
        assert (V * 1e6 / mu_x, p * 1e-6 / mu_y) == pytest.approx((x, y), abs=1e-9)
    # the points are the calculation's: c on the compression polytrope, b on the expansion one
    eps = c.spec.epsilon
    assert pts["c"][1] == pytest.approx(c.spec.p_a * eps ** c.spec.n1, rel=1e-12)
    assert pts["b"][1] == pytest.approx(c.p_z * (c.rho / eps) ** c.spec.n2, rel=1e-12)
    assert pts["z"][0] / pts["c"][0] == pytest.approx(c.rho, rel=1e-12)
    # the tables print the model's numbers through the language's writer
    def cells(name: str) -> set[str]:
        table = next(p for p in panels[name].primitives if isinstance(p, Table))
        return {cell for row in table.cells for cell in row}

    texts = cells("thermal_results")
    assert number(c.p_z * 1e-6, 4, "en") in texts and number(c.T_z, 1, "en") in texts
    assert number(100.0 * c.eta_e, 2, "en") in cells("thermal_balance")
    assert math.isclose(sum(heat_balance(c, c.power(spec.V_h), spec.bore, 8).shares.values()),
                        100.0)
