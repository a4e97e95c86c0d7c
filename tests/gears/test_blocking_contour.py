"""The blocking contour and specific sliding against closed-form involute formulas written here."""

from __future__ import annotations

import math

import numpy as np
import pytest

from mechplan.model.gears import PairSpec
from mechplan.synthesis.gears.contour import (
    ContourSpec,
    admissible,
    blocking_contour,
    specific_sliding,
)

M = 0.004
ALPHA = math.radians(20.0)


def _inv(a: float) -> float:
    return math.tan(a) - a


def _alpha_w(z1: int, z2: int, x1: float, x2: float) -> float:
    target = 2 * (x1 + x2) * math.tan(ALPHA) / (z1 + z2) + _inv(ALPHA)
    lo, hi = 1e-6, 1.5
    for _ in range(200):                     # bisection, not Newton: a second method
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if _inv(mid) < target else (lo, mid)
    return 0.5 * (lo + hi)


def _closed_form(z1: int, z2: int, x1: float, x2: float) -> dict[str, float]:
    """ε_α, top lands s_a1, s_a2 and the slidings at B1, B2 (textbook formulas)."""
    aw = _alpha_w(z1, z2, x1, x2)
    a = M * (z1 + z2) / 2
    a_w = a * math.cos(ALPHA) / math.cos(aw)
    dy = x1 + x2 - (a_w - a) / M
    out: dict[str, float] = {}
    tips = []
    for j, (z, x) in enumerate(((z1, x1), (z2, x2)), start=1):
        d = M * z
        da = d + 2 * M * (1 + x - dy)
        db = d * math.cos(ALPHA)
        aa = math.acos(db / da)
        out[f"s_a{j}"] = da * ((math.pi / 2 + 2 * x * math.tan(ALPHA)) / z + _inv(ALPHA) - _inv(aa))
        tips.append(da / 2 * math.sin(aa))
        # where the generated involute starts, from the rack's addendum line
        out[f"rho_l{j}"] = d / 2 * math.sin(ALPHA) - (1 - x) * M / math.sin(ALPHA)
    g = a_w * math.sin(aw)
    out["eps"] = (tips[0] + tips[1] - g) / (math.pi * M * math.cos(ALPHA))
    u1 = g - tips[1]                 # B1 from N1
    u2 = tips[0]                     # B2 from N1
    out["rho_p1"], out["rho_p2"] = u1, g - u2
    out["eta1_B1"] = 1 - (z1 / z2) * (g - u1) / u1
    out["eta2_B2"] = 1 - (z2 / z1) * u2 / (g - u2)
    return out


def _pair(z1: int, z2: int) -> PairSpec:
    return PairSpec(module=M, z1=z1, z2=z2)


@pytest.mark.parametrize("z1, z2", [(12, 30), (10, 25), (14, 14)])
def test_undercut_lines_are_the_course_limit(z1: int, z2: int) -> None:
    c = blocking_contour(_pair(z1, z2), n=61)
    for j, z in ((0, z1), (1, z2)):
        line = c.lines[f"undercut{j + 1}"]
        pts = line[np.isfinite(line[:, 0])]
        assert pts.size
        assert np.allclose(pts[:, j], (17 - z) / 17, atol=1e-10)


@pytest.mark.parametrize("z1, z2", [(12, 30), (18, 40)])
def test_tip_land_and_contact_lines(z1: int, z2: int) -> None:
    spec = ContourSpec(tip_land=0.4, eps_min=1.2)
    c = blocking_contour(_pair(z1, z2), spec, n=41)
    for name, key, want in (("tip1", "s_a1", 0.4 * M), ("tip2", "s_a2", 0.4 * M),
                            ("contact", "eps", 1.2)):
        pts = c.lines[name][np.isfinite(c.lines[name][:, 0])]
        assert len(pts) > 5, name
        for x1, x2 in pts[:: max(1, len(pts) // 7)]:
            got = _closed_form(z1, z2, float(x1), float(x2))[key]
            assert got == pytest.approx(want, rel=1e-7, abs=1e-12), (name, x1, x2)


def test_recommended_is_admissible_and_balanced() -> None:
    p = _pair(12, 30)
    c = blocking_contour(p, n=81)
    x1, x2 = c.recommended
    assert c.rule == "balanced_max_eps"
    assert bool(admissible(p, c.spec, x1, x2))
    f = _closed_form(12, 30, x1, x2)
    assert f["eta1_B1"] == pytest.approx(f["eta2_B2"], abs=1e-7)
    assert f["eps"] >= 1.2 and f["s_a1"] >= 0.25 * M and x1 >= 5 / 17 - 1e-12
    assert c.eps == pytest.approx(f["eps"], rel=1e-10)
    # no admissible balanced point has a larger contact ratio (checked on a fine line)
    pts = c.balanced[np.isfinite(c.balanced[:, 0])]
    ok = admissible(p, c.spec, pts[:, 0], pts[:, 1])
    best = max(_closed_form(12, 30, float(a), float(b))["eps"] for a, b in pts[ok])
    assert c.eps >= best - 1e-9
    # ε_α grows as x1 + x2 falls: the best balanced point is where the line leaves the contour,
    # on one limit (here interference of gear 1: B1 at the start of its involute, ρ_p1 = ρ_l1)
    f_b = _closed_form(12, 30, x1, x2)
    assert f_b["rho_p1"] == pytest.approx(f_b["rho_l1"], abs=1e-9 * M)


def test_mask_matches_the_closed_forms() -> None:
    p = _pair(12, 30)
    c = blocking_contour(p, n=21)
    rng = np.random.default_rng(3)
    checked = 0
    for i, j in rng.integers(0, 21, size=(40, 2)):
        x1, x2 = float(c.x1[i]), float(c.x2[j])
        try:
            f = _closed_form(12, 30, x1, x2)
        except ValueError:            # a tip circle below the base circle: not admissible
            assert not c.mask[i, j]
            continue
        ok = (x1 >= 5 / 17 and x2 >= -13 / 17 and f["s_a1"] >= 0.25 * M
              and f["s_a2"] >= 0.25 * M and f["eps"] >= 1.2
              and f["rho_p1"] >= max(f["rho_l1"], 0) and f["rho_p2"] >= max(f["rho_l2"], 0))
        assert bool(c.mask[i, j]) == ok, (x1, x2, f)
        checked += 1
    assert checked > 20


def test_specific_sliding_ends() -> None:
    p = _pair(12, 30)
    s = specific_sliding(p, 0.3, 0.2)
    assert s.eta1[0] == -math.inf and s.eta1[-1] == pytest.approx(1.0, abs=1e-15)
    assert s.eta2[-1] == -math.inf and s.eta2[0] == pytest.approx(1.0, abs=1e-15)
    f = _closed_form(12, 30, 0.3, 0.2)
    u = np.array([s.b1, s.b2])
    eta1 = 1 - (12 / 30) * (s.g - u[0]) / u[0]
    eta2 = 1 - (30 / 12) * u[1] / (s.g - u[1])
    assert eta1 == pytest.approx(f["eta1_B1"], rel=1e-9)
    assert eta2 == pytest.approx(f["eta2_B2"], rel=1e-9)
    # at the pitch point both slidings vanish: u = r_b1·tan α_w
    aw = _alpha_w(12, 30, 0.3, 0.2)
    k = np.argmin(np.abs(s.eta1))
    assert s.u[k] == pytest.approx(M * 12 / 2 * math.cos(ALPHA) * math.tan(aw), abs=s.g / 100)


def test_scene_contour_rule_json_and_sheet() -> None:
    from mechplan.studies.gears import solve_gear_text

    text = ('kind = "gears"\n[pair]\nmodule = "4 mm"\nteeth = [12, 30]\nshift_rule = "contour"\n'
            'tip_land = 0.4\nmin_contact_ratio = 1.25\n')
    study = solve_gear_text(text, "pair.toml")
    doc = study.to_json()["pair"]
    x1, x2 = doc["x"]
    assert doc["contour"]["recommended"] == [x1, x2]
    f = _closed_form(12, 30, x1, x2)
    assert f["s_a1"] >= 0.4 * M - 1e-12 and f["eps"] >= 1.25 and x1 >= 5 / 17
    assert doc["contact_ratio"] == pytest.approx(f["eps"], rel=1e-10)
    s = doc["contour"]["specific_sliding"]
    assert s["eta1"][0] is None and s["eta2"][-1] is None
    assert "blocking contour" in study.report("en")
    texts = " ".join(getattr(p, "string", "") for sh in study.sheets(None, None, "ru", "pair")
                     for p in sh.primitives)
    assert "Блокирующий" in texts and "Удельные скольжения" in texts


def test_scene_rejects_bad_contour_keys() -> None:
    from mechplan.errors import SceneError
    from mechplan.studies.gears import solve_gear_text

    base = 'kind = "gears"\n[pair]\nmodule = "4 mm"\nteeth = [12, 30]\n'
    for bad in ('contour = "yes"\n', 'tip_land = -1\n', 'min_contact_ratio = true\n'):
        with pytest.raises(SceneError):
            solve_gear_text(base + bad, "pair.toml")


def test_an_empty_contour_is_an_error_in_every_language() -> None:
    from mechplan.errors import SceneError
    from mechplan.studies.gears import solve_gear_text

    text = ('kind = "gears"\n[pair]\nmodule = "4 mm"\nteeth = [12, 30]\nshift_rule = "contour"\n'
            'min_contact_ratio = 2.5\n')
    with pytest.raises(SceneError) as err:
        solve_gear_text(text, "pair.toml")
    assert err.value.key == "pair.shift_rule"
    assert "blocking contour" in err.value.text("en") and "контура" in err.value.text("ru")


def test_contour_drawn_beside_another_rule() -> None:
    from mechplan.studies.gears import solve_gear_text

    text = ('kind = "gears"\n[pair]\nmodule = "4 mm"\nteeth = [12, 30]\n'
            'shift_rule = "no_undercut"\ncontour = true\n')
    doc = solve_gear_text(text, "pair.toml").to_json()["pair"]
    assert doc["x"] == [pytest.approx(5 / 17), 0.0]           # the rule's shifts, not the contour's
    assert doc["contour"]["recommended"] != doc["x"]
