"""Synthetic drawn submissions with known injected errors: the checker finds exactly those."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from mechplan.check import Options, Tolerance, check
from mechplan.check.report import CARRIED, NEW, OK, REFERENCE, SLIP, SWAPPED, WRONG
from mechplan.model.plans import Plan
from mechplan.solve import build, crank_positions

from .sheets import PlanSpec, exact_sheet, move, rotate_about, solved, swap, write_dxf

V, A, P = Plan.VELOCITY, Plan.ACCELERATION, Plan.POSITION

FOUR_BAR = {V: PlanSpec(0.01, (50, 50), "μv = 0,01 m/s/mm"),
            A: PlanSpec(0.1, (250, 60), "μa = 0.1 (m/s²)/mm")}


def _run(tmp_path: Path, name: str, at: float, specs, mutate=None, style: str = "mixed",
         options: Options | None = None, **kw):
    scene, sol = solved(name, at)
    st = exact_sheet(sol, specs)
    if mutate is not None:
        mutate(st)
    path = write_dxf(tmp_path / f"{name}.dxf", sol, specs, st, style=style, **kw)
    return check(scene, path, options or Options(at_deg=at))


def _wrong(report) -> dict[str, str]:
    return {f"{p.plan}:{s.name}": s.cause for p in report.plans for s in p.segments
            if s.verdict in (WRONG, SLIP)}


def _findings(report) -> set[tuple[str, str, str]]:
    return {(f.kind, f.subject, f.error) for f in report.findings}


def _unit(v):
    return v / np.linalg.norm(v)


# -- round trip --------------------------------------------------------------------------------
ROUND_TRIP = [("four_bar", 60.0), ("slider_crank", 35.0), ("shaper", 100.0),
              ("v_engine", 200.0), ("quick_return", 250.0), ("offset_slider_crank", 300.0),
              ("machine_unit", 10.0)]
MU_TEXT = {P: "μl = {} m/mm", V: "μv = {} m/s/mm", A: "mu_a = {} (m/s^2)/mm"}
ORIGIN = {P: (0.0, 300.0), V: (60.0, 60.0), A: (320.0, 80.0)}


def _specs(sol) -> dict[Plan, PlanSpec]:
    """The solver's own round scale factors, written on the sheet (decimal comma for μv)."""
    out = {}
    for plan in (P, V, A):
        mu = sol.scales[plan]
        text = MU_TEXT[plan].format(f"{mu:g}")
        out[plan] = PlanSpec(mu, ORIGIN[plan], text.replace(".", ",") if plan is V else text)
    return out


@pytest.mark.parametrize("name, at", ROUND_TRIP, ids=[r[0] for r in ROUND_TRIP])
@pytest.mark.parametrize("style", ["text", "mixed"])
def test_round_trip_passes_within_a_hundredth(tmp_path, name, at, style) -> None:
    _scene, sol = solved(name, at)
    specs = _specs(sol)
    report = _run(tmp_path, name, at, specs, style=style, arrows=True,
                  polylines=(style == "mixed"))
    assert report.passed, report.text()
    assert not report.findings
    rows = [s for p in report.plans for s in p.segments]
    n_segments = sum(1 for p in report.plans for s in p.segments if s.in_construction)
    assert n_segments == sum(1 for s in sol.construction.segments if s.plan in specs)
    for row in rows:
        assert row.verdict in (OK, REFERENCE)
        assert abs(row.error_mm) < 0.01, row
        if row.direction_deg is not None:
            across = row.exact_mm * math.sin(math.radians(row.direction_deg))
            assert abs(across) < 0.01, row
    assert {p.plan for p in report.plans} == {p.value for p in specs}


# -- injected errors on the velocity plan -------------------------------------------------------
def test_wrong_length(tmp_path) -> None:
    def mutate(st):
        pc = st.points[(V, "c")] - st.points[(V, "p")]
        move(st, V, "c", 4.0 * _unit(pc))

    report = _run(tmp_path, "four_bar", 60, FOUR_BAR, mutate)
    assert _findings(report) == {("wrong point", "c", "length")}
    assert _wrong(report) == {"velocity:bc": NEW, "velocity:pc": NEW}
    pc = next(s for p in report.plans for s in p.segments if s.name == "pc")
    assert pc.error_mm == pytest.approx(4.0, abs=1e-6)
    assert abs(pc.direction_deg) < 1e-6
    assert "⊥BC" in pc.hint and "⊥DC" in pc.hint
    assert pc.depends_on and "b" in pc.depends_on


def test_wrong_direction(tmp_path) -> None:
    report = _run(tmp_path, "four_bar", 60, FOUR_BAR,
                  lambda st: rotate_about(st, V, "c", "p", 6.0))
    assert _findings(report) == {("wrong point", "c", "direction")}
    pc = next(s for p in report.plans for s in p.segments if s.name == "pc")
    assert pc.direction_deg == pytest.approx(6.0, abs=1e-6)
    assert abs(pc.error_mm) < 1e-6
    assert set(_wrong(report)) == {"velocity:bc", "velocity:pc"}


def test_swapped_labels(tmp_path) -> None:
    report = _run(tmp_path, "four_bar", 60, FOUR_BAR, lambda st: swap(st, V, "b", "c"))
    assert _findings(report) == {("swapped labels", "b/c", "")}
    assert set(_wrong(report).values()) == {SWAPPED}
    assert "velocity:pe" not in _wrong(report)        # e is built from b and c, drawn right


def test_carried_error_within_the_plan(tmp_path) -> None:
    def mutate(st):       # pb drawn 10 % long, the rest built right from it
        p0 = st.points[(V, "p")]
        for key, at in list(st.points.items()):
            if key[0] is V:
                st.points[key] = p0 + 1.1 * (at - p0)

    report = _run(tmp_path, "four_bar", 60, FOUR_BAR, mutate)
    assert _findings(report) == {("wrong point", "b", "length")}
    wrong = _wrong(report)
    assert wrong.pop("velocity:pb") == NEW
    assert wrong and set(wrong.values()) == {CARRIED}
    for p in report.plans:
        for s in p.segments:
            if s.cause == CARRIED:
                assert s.carried_from == ["b"]


def _four_bar_acceleration(sol, st, mu_v: float, mu_a: float) -> None:
    """Redraw the acceleration plan as a student would from their own velocity plan (closed
    form, independent of the construction engine)."""
    ev = sol.ev
    P_ = {x: ev[f"pos.{x}"][0] for x in "ABCDE"}
    perp = lambda r: np.array([-r[1], r[0]])
    cross = lambda a, b: a[0] * b[1] - a[1] * b[0]
    p0 = st.points[(V, "p")]
    vb, vc = (st.points[(V, "b")] - p0) * mu_v, (st.points[(V, "c")] - p0) * mu_v
    bc, dc = P_["C"] - P_["B"], P_["C"] - P_["D"]
    w2, w3 = cross(bc, vc - vb) / bc.dot(bc), cross(dc, vc) / dc.dot(dc)
    pi0 = st.points[(A, "π")]
    ab = (st.points[(A, "b′")] - pi0) * mu_a
    ncb, ncd = ab - w2 ** 2 * bc, -w3 ** 2 * dc
    e2, _ = np.linalg.solve(np.column_stack([perp(bc), -perp(dc)]), ncd - ncb)
    ac = ncb + e2 * perp(bc)
    be = P_["E"] - P_["B"]
    ae = ab + e2 * perp(be) - w2 ** 2 * be
    for label, a in (("n_CB", ncb), ("n_CD", ncd), ("c′", ac), ("e′", ae)):
        st.points[(A, label)] = pi0 + a / mu_a


def test_error_carried_into_the_acceleration_plan(tmp_path) -> None:
    _scene, sol = solved("four_bar", 60)

    def mutate(st):
        move(st, V, "c", (3.0, -4.0))
        _four_bar_acceleration(sol, st, 0.01, 0.1)

    report = _run(tmp_path, "four_bar", 60, FOUR_BAR, mutate)
    assert _findings(report) == {("wrong point", "c", "length and direction")}
    acc = {k: v for k, v in _wrong(report).items() if k.startswith("acceleration")}
    assert len(acc) >= 4 and set(acc.values()) == {CARRIED}
    plan = next(p for p in report.plans if p.plan == "acceleration")
    for s in plan.segments:
        if s.cause == CARRIED:
            assert s.carried_from == ["c (velocity plan)"]
    bn = next(s for s in plan.segments if s.name == "b′n_CB")
    assert bn.verdict == WRONG and bn.error_mm > 1.0


def test_several_independent_errors(tmp_path) -> None:
    def mutate(st):
        rotate_about(st, V, "e", "p", -8.0)
        move(st, A, "c′", (3.0, -2.0))
        move(st, A, "n_CD", (0.0, 2.5))

    report = _run(tmp_path, "four_bar", 60, FOUR_BAR, mutate)
    kinds = {(f.plan, f.subject) for f in report.findings}
    assert kinds == {("velocity plan", "e"), ("acceleration plan", "c′"),
                     ("acceleration plan", "n_CD")}
    assert "velocity:pe" in _wrong(report)
    assert "acceleration:πe′" not in _wrong(report)


def test_swapped_normals_on_the_acceleration_plan(tmp_path) -> None:
    report = _run(tmp_path, "four_bar", 60, FOUR_BAR,
                  lambda st: swap(st, A, "n_CB", "n_CD"))
    assert _findings(report) == {("swapped labels", "n_CB/n_CD", "")}


def test_coriolis_error_and_other_notations(tmp_path) -> None:
    specs = {V: PlanSpec(0.02, (50, 50), "μv = 0,02 м/с/мм"),
             A: PlanSpec(0.1, (250, 60), "μa=0.1")}

    def mutate(st):
        move(st, A, "k_A3A2", (2.5, 1.0))
        st.written.update({(A, "k_A3A2"): "k", (A, "n_A3O3"): "n3", (A, "π"): "p'",
                           (A, "b′"): "b1", (A, "c′"): "c'", (V, "a3"): "a_3"})

    report = _run(tmp_path, "shaper", 100, specs, mutate, arrows=True)
    assert _findings(report) == {("wrong point", "k_A3A2", "length and direction")}
    finding = report.findings[0]
    assert "Coriolis" in finding.message
    acc = next(p for p in report.plans if p.plan == "acceleration")
    assert "link number" in acc.convention
    written = {pt.label: pt.written for pt in acc.points}
    assert written["π"] == "p'" and written["b′"] == "b1" and written["k_A3A2"] == "k"


def test_position_plan_error(tmp_path) -> None:
    specs = {P: PlanSpec(0.002, (100, 250), "μl = 0.002 m/mm")}
    report = _run(tmp_path, "four_bar", 60, specs, lambda st: move(st, P, "E", (0.0, 3.0)))
    assert {(f.kind, f.subject) for f in report.findings} == {("wrong point", "E")}
    assert set(_wrong(report)) == {"position:BE"}
    be = report.plans[0].segments[2]
    assert be.name == "BE" and be.verdict == WRONG


def test_arithmetic_slip_on_the_sheet(tmp_path) -> None:
    _scene, sol = solved("four_bar", 60)
    vc = float(np.linalg.norm(sol.ev["vel.C"][0]))
    w2 = abs(float(sol.ev["vel.omega.2"][0]))
    ac = float(np.linalg.norm(sol.ev["acc.C"][0]))

    def mutate(st):
        st.texts += [(f"v_C = {1.3 * vc:.3f} m/s".replace(".", ","), (40, 0)),
                     (f"ω2 = {w2:.2f} rad/s", (40, -6)), (f"a_C = {ac:.2f} m/s²", (40, -12))]

    report = _run(tmp_path, "four_bar", 60, FOUR_BAR, mutate)
    assert _findings(report) == {("arithmetic slip", "v_C", "")}
    verdicts = {v.name: v.verdict for v in report.values}
    assert verdicts == {"v_C": SLIP, "ω2": OK, "a_C": OK}
    assert not _wrong(report).keys() - {"velocity:v_C"}


def test_best_fit_position_without_at(tmp_path) -> None:
    scene, _ = solved("shaper", 0)
    _, c = build(scene, ("position", "velocity"))
    at = float(np.degrees(crank_positions(scene, c))[4])
    specs = {V: PlanSpec(0.02, (50, 50), "μv = 0.02 m/s/mm")}
    report = _run(tmp_path, "shaper", at, specs, options=Options())
    assert report.phi_deg == pytest.approx(at)
    assert "best fit" in report.phi_source
    assert report.passed


def test_crank_angle_written_on_the_sheet(tmp_path) -> None:
    def mutate(st):
        st.texts.append(("φ = 60°", (0, -30)))

    report = _run(tmp_path, "four_bar", 60, FOUR_BAR, mutate, options=Options())
    assert report.phi_deg == pytest.approx(60.0)
    assert "φ = 60°" in report.phi_source


def test_tolerance_per_plan(tmp_path) -> None:
    def mutate(st):
        move(st, V, "c", 2.0 * _unit(st.points[(V, "c")] - st.points[(V, "p")]))
        move(st, A, "c′", (1.5, 0.0))

    loose = Options(at_deg=60, tolerance={Plan.VELOCITY: Tolerance(mm=3.0, pct=2.0)})
    report = _run(tmp_path, "four_bar", 60, FOUR_BAR, mutate, options=loose)
    assert {f.subject for f in report.findings} == {"c′"}
    tight = _run(tmp_path, "four_bar", 60, FOUR_BAR, mutate)
    assert {f.subject for f in tight.findings} == {"c", "c′"}


def test_scale_inferred_from_the_driving_vector(tmp_path) -> None:
    specs = {V: PlanSpec(0.01, (50, 50), None), A: PlanSpec(0.1, (250, 60), None)}
    report = _run(tmp_path, "four_bar", 60, specs, lambda st: move(st, V, "c", (0.0, 3.0)))
    vel = next(p for p in report.plans if p.plan == "velocity")
    assert vel.mu == pytest.approx(0.01)
    assert "inferred from pb" in vel.mu_source
    pb = next(s for s in vel.segments if s.name == "pb")
    assert pb.verdict == REFERENCE
    assert {f.subject for f in report.findings} == {"c"}


def test_scale_on_the_command_line_wins(tmp_path) -> None:
    specs = {V: PlanSpec(0.01, (50, 50), "μv = 0.02 m/s/mm")}     # a wrong text
    report = _run(tmp_path, "four_bar", 60, specs,
                  options=Options(at_deg=60, mu={Plan.VELOCITY: 0.01}))
    assert report.passed
    assert report.plans[0].mu_source == "given on the command line"


def test_zhukovsky_lever_turned_velocity_plan(tmp_path) -> None:
    """A velocity plan drawn turned by 90° is read as Zhukovsky's lever and checked turned back."""
    def mutate(st):
        p0 = st.points[(V, "p")]
        for key, at in list(st.points.items()):
            if key[0] is V:
                d = at - p0
                st.points[key] = p0 + np.array([-d[1], d[0]])
        rotate_about(st, V, "e", "p", 5.0)

    specs = {V: FOUR_BAR[V]}
    report = _run(tmp_path, "four_bar", 60, specs, mutate)
    plan = report.plans[0]
    assert "turned by +90°" in plan.convention and "Zhukovsky" in plan.convention
    assert {(f.subject, f.error) for f in report.findings} == {("e", "direction")}
    pe = next(s for s in plan.segments if s.name == "pe")
    assert pe.direction_deg == pytest.approx(5.0, abs=1e-6)
