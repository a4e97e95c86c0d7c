"""Velocities by instant centres as a drawn construction (line of centres, МЦС): every step an
operation; the values against closed forms, finite differences of positions and the velocity
plan; the protocol in four languages; the drawing measured back."""

from __future__ import annotations

import math

import numpy as np
import pytest

from mechplan.construct.centre_drawn import drawn, measured_agreement
from mechplan.construct.centre_protocol import measure, protocol
from mechplan.construct.ops import SPECS
from mechplan.construct.plans.centre_velocity import KENNEDY, PIN, SLIDE
from mechplan.construct.plans.centres import centres_at
from mechplan.i18n import LANGUAGES
from mechplan.scene import load_scene, parse_scene
from mechplan.solve import solve
from tests.scenes import (
    SCOTCH_YOKE,
    SLOTTED_CRANK_PRP,
    TEMPLATES,
    TWO_INPUT_TEMPLATES,
    four_bar_text,
    slider_crank_text,
)

CRANKS = [p for p in TEMPLATES if p not in TWO_INPUT_TEMPLATES]


def _drawn(scene, count=None, at_deg=None):
    sol = solve(scene, at_deg=at_deg, count=count, plans=("position", "velocity"),
                scales=False)
    c, ev, mech = sol.construction, sol.ev, scene.mechanism
    return sol, drawn(c, ev, mech, centres_at(c, ev, mech))


def _loop_four_bar(sol, omega1):
    """ω2, ω3 of a four-bar from the derivative of its loop closure (independent of the plans):
    ω1 × AB + ω2 × BC = ω3 × DC, a 2 × 2 linear system per position."""
    c, ev = sol.construction, sol.ev
    a, b, cc, d = (ev[c.position(p)] for p in "ABCD")
    ab, bc, dc = b - a, cc - b, cc - d
    out = []
    for k in range(ev.n):
        # ω2·perp(BC) − ω3·perp(DC) = −ω1·perp(AB)
        m = np.array([[-bc[k, 1], dc[k, 1]], [bc[k, 0], -dc[k, 0]]])
        rhs = -omega1 * np.array([-ab[k, 1], ab[k, 0]])
        out.append(np.linalg.solve(m, rhs))
    return np.array(out)


def test_four_bar_against_its_loop_closure():
    scene = parse_scene(four_bar_text())
    sol, dv = _drawn(scene, count=72)
    w = _loop_four_bar(sol, 10.0)
    assert dv is not None
    np.testing.assert_allclose(dv.ev[dv.cv.omega["2"]], w[:, 0], rtol=0, atol=1e-12)
    np.testing.assert_allclose(dv.ev[dv.cv.omega["3"]], w[:, 1], rtol=0, atol=1e-12)
    c, ev = sol.construction, sol.ev
    v_c = w[:, 1, None] * np.stack([-(ev[c.position("C")] - ev[c.position("D")])[:, 1],
                                    (ev[c.position("C")] - ev[c.position("D")])[:, 0]], axis=1)
    np.testing.assert_allclose(dv.ev[dv.cv.v["C"]], v_c, rtol=0, atol=1e-12)
    # the textbook's picture: the coupler through the pin B by the line of centres (C carried
    # about I02), the rocker through the pin C
    routes = {r.link: (r.source, r.centre, r.kind, r.carried) for r in dv.cv.routes}
    assert routes == {"2": ("1", ("1", "2"), PIN, "C"), "3": ("2", ("2", "3"), PIN, None)}
    ops = [s.op.value for s in dv.cv.construction if s.op.message]
    assert ops[:4] == ["ic_drive_velocity", "ic_carry", "ic_similar_velocity", "ic_arc_velocity"]
    assert "ic_pole_omega" in ops and "ic_pole_velocity" in ops


def test_centred_slider_crank_closed_form_and_dead_centres():
    r, l_, omega = 0.1, 0.4, 1500 * 2 * math.pi / 60
    scene = parse_scene(slider_crank_text(r_mm=100.0, l_mm=400.0))
    phi = np.radians(np.arange(0.0, 360.0, 5.0))
    _sol, dv = _drawn(scene, at_deg=list(np.degrees(phi)))
    assert dv is not None
    slider = "B"                        # the slider's point (slider_crank_text: O, A, B)
    s = np.sin(phi)
    speed = r * omega * s * (1.0 + r * np.cos(phi) / np.sqrt(l_ * l_ - r * r * s * s))
    got = dv.ev[dv.cv.v[slider]]
    np.testing.assert_allclose(np.abs(got[:, 0]), np.abs(speed), rtol=0, atol=1e-11)
    np.testing.assert_allclose(got[:, 1], 0.0, atol=1e-11)
    # at the dead centres I02 is the slider's pin: its v = 0, no NaN
    dead = np.isclose(np.sin(phi), 0.0, atol=1e-12)
    assert np.all(np.isfinite(got)) and np.all(np.abs(got[dead]) < 1e-12)
    assert np.nanmax(dv.agreement) < 1e-12


@pytest.mark.parametrize("path", CRANKS, ids=lambda p: p.stem)
def test_every_template_agrees_with_the_plan_and_finite_differences(path):
    scene = load_scene(path)
    sol, dv = _drawn(scene, count=360)
    assert dv is not None
    assert not any(lk not in dv.cv.omega for lk in scene.mechanism.moving), path.stem
    ok = np.isfinite(dv.agreement)
    assert ok.sum() >= 350 and float(dv.agreement[ok].max()) < 1e-12, path.stem
    # an independent check of the plan itself: central differences of the positions
    c = sol.construction
    phi0 = np.radians(np.arange(3.0, 360.0, 37.0))
    h = 1e-6
    drive = scene.mechanism.drive
    e_plus, e_minus = c.evaluate(phi0 + h), c.evaluate(phi0 - h)
    dphi_dt = abs(drive.omega)
    _, dv0 = _drawn(scene, at_deg=list(np.degrees(phi0)))
    assert dv0 is not None
    scale = max(float(np.max(np.hypot(*dv0.ev[s].T))) for s in dv0.cv.v.values())
    for p, sid in dv0.cv.v.items():
        fd = (e_plus[c.position(p)] - e_minus[c.position(p)]) / (2 * h) * dphi_dt
        np.testing.assert_allclose(np.hypot(*dv0.ev[sid].T), np.hypot(*fd.T), rtol=0,
                                   atol=1e-6 * scale, err_msg=f"{path.stem} v_{p}")


@pytest.mark.parametrize("text, kinds", [(SCOTCH_YOKE, {SLIDE, PIN}),
                                         (SLOTTED_CRANK_PRP, None)])
def test_prismatic_routes(text, kinds):
    scene = parse_scene(text)
    _sol, dv = _drawn(scene, count=90)
    assert dv is not None
    ok = np.isfinite(dv.agreement)
    assert ok.sum() >= 80 and float(dv.agreement[ok].max()) < 1e-12
    if kinds is not None:
        assert {r.kind for r in dv.cv.routes} <= kinds | {KENNEDY}


def test_every_step_is_a_registered_operation():
    scene = load_scene(next(p for p in CRANKS if p.stem == "shaper"))
    _, dv = _drawn(scene, at_deg=[30.0])
    assert dv is not None
    for step in dv.cv.construction:
        assert SPECS[step.op.value] is step.op
    assert {s.op.value for s in dv.cv.construction} >= {
        "ic_carry", "ic_similar_velocity", "ic_arc_velocity", "ic_pole_omega",
        "ic_drive_velocity"}
    # the quick-return's lever is reached through I13 (Kennedy): a point of the crank carried
    assert any(r.kind == KENNEDY for r in dv.cv.routes)


def test_protocol_in_four_languages_measures_the_arrows():
    scene = parse_scene(four_bar_text())
    _sol, dv = _drawn(scene, at_deg=[60.0])
    assert dv is not None
    mu_l, mu_v = 0.002, 0.02
    v_b = float(np.hypot(*dv.ev[dv.cv.v["B"]][0]))
    assert v_b == pytest.approx(10.0 * 0.08, rel=1e-12)
    for lang in LANGUAGES:
        lines = protocol(dv.cv, dv.ev, 0, lang, mu_l, mu_v)
        assert len(lines) == sum(1 for s in dv.cv.construction if s.op.message)
        text = "\n".join(lines)
        sym = "I" if lang == "en" else "P"
        assert f"{sym}01B" in text and f"{sym}02" in text
        assert ("40.0" in text) if lang in ("en", "zh") else ("40,0" in text)   # 0.8 / 0.02
        assert "{" not in text
    assert "МЦС" in "\n".join(protocol(dv.cv, dv.ev, 0, "ru", mu_l, mu_v))


def test_measured_arrows_agree_to_the_drawing_precision():
    scene = parse_scene(four_bar_text())
    sol, dv = _drawn(scene, at_deg=[40.0])
    assert dv is not None
    mu_v = 0.01
    m = measure(dv.ev[dv.cv.v["C"]][0], mu_v)
    assert abs(m.mm * mu_v - m.exact) <= 0.05 * mu_v + 1e-15
    got = measured_agreement(sol.construction, sol.ev, dv, 0, mu_v)
    top = max(float(np.hypot(*sol.ev[sol.construction.velocity_image(p)][0]))
              for p in dv.cv.v)
    assert 0.0 <= got <= 0.05 * mu_v / top + 1e-12


def test_two_drivers_draw_what_the_centres_determine_and_name_the_rest():
    """W = 2 (five-bar): Kennedy's theorem finds only the pairs' centres; both cranks are drawn
    from their own ω, the dyad's links are named as not determined by centres."""
    from mechplan.studies.centres_report import centres_report
    from tests.scenes import ROOT

    text = (ROOT / "templates" / "five_bar_two_cranks.toml").read_text(encoding="utf-8")
    scene = parse_scene(text + '\n[centres]\nlinks = ["2"]\n', "five.toml")
    sol = solve(scene, count=36, plans=("position", "velocity", "centres"))
    c, ev, mech = sol.construction, sol.ev, scene.mechanism
    dv = drawn(c, ev, mech, centres_at(c, ev, mech))
    assert dv is not None and set(dv.cv.omega) == {"1", "4"}
    for p in ("B", "D"):           # the cranks' pins: ω·r about their pivots, as the plan
        np.testing.assert_allclose(dv.ev[dv.cv.v[p]], ev[c.velocity_image(p)], rtol=0,
                                   atol=1e-13)
    assert np.nanmax(dv.agreement) < 1e-12
    for lang in LANGUAGES:
        text = centres_report(sol, lang)
        sym = "I" if lang == "en" else "P"
        assert f"{sym}02" in text and f"{sym}03" in text
    en = centres_report(sol, "en")
    assert "link 2: its absolute centre I02 is not found" in en
    assert "link 3: its absolute centre I03 is not found" in en
    assert "link 2: its absolute centre I02 is not found by Kennedy's theorem (two drivers" in en
