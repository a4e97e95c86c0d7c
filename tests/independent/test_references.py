"""Cross-checks of the independent references (mpref: Newton + mpmath.diff; closed_form: numpy).

Neither module imports mechplan.  Run: ``python -m pytest tests/independent -q``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import pytest
from mpmath import mp, mpf

from . import closed_form, mpref

SHARED = ["slider_crank", "offset_slider_crank", "machine_unit", "four_bar"]
THETAS = np.linspace(0.0, 2.0 * math.pi, 20, endpoint=False)  # includes 0, pi, 3pi/2 exactly
FEW_THETAS = [0.0, 0.3, 1.9, math.pi, -2.2, 4.4]

# rigid links (all points of each link) and sliding constraints of every preset
MEMBERS: dict[str, dict[str, Sequence[str]]] = {
    "slider_crank": {"1": ("O", "A"), "2": ("A", "B", "S2")},
    "offset_slider_crank": {"1": ("O", "A"), "2": ("A", "B", "S2")},
    "machine_unit": {"1": ("O", "A"), "2": ("A", "B", "S2")},
    "four_bar": {"1": ("A", "B"), "2": ("B", "C", "E"), "3": ("D", "C")},
    "v_engine": {"1": ("A", "B"), "2": ("B", "C", "D", "S2"), "4": ("D", "E")},
    "quick_return": {"1": ("O1", "A"), "3": ("O3", "B")},
    "shaper": {"1": ("O1", "A"), "3": ("O3", "B"), "4": ("B", "C")},
}
ALL_PRESETS = list(MEMBERS)

TOL_POS = mpf("1e-35")  # position-level residuals (40-digit arithmetic)
TOL_DER = mpf("1e-30")  # velocity / acceleration-level identities (relative to rw, rw^2)


@pytest.fixture(scope="module")
def ref_arrays() -> dict[str, dict[str, np.ndarray]]:
    """mpref evaluated (once) at THETAS for every preset shared with closed_form."""
    return {name: mpref.reference(name, THETAS) for name in SHARED}


@pytest.fixture(scope="module")
def ref_mp() -> dict[str, list[dict[str, tuple]]]:
    """mpf-valued solutions of every preset at a few angles."""
    return {name: [mpref.solve(name, th) for th in FEW_THETAS] for name in ALL_PRESETS}


def _wrap(a: np.ndarray) -> np.ndarray:
    return (a + np.pi) % (2.0 * np.pi) - np.pi


# ---------------------------------------------------------------------------------------------
# mpref vs closed_form
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("name", SHARED)
def test_mpref_matches_closed_form(name: str, ref_arrays: dict) -> None:
    ref = ref_arrays[name]
    cf = closed_form.preset(name, THETAS)
    assert set(ref) == set(cf)
    points = [k for k in ref if ref[k].shape[1] == 6]
    links = [k for k in ref if ref[k].shape[1] == 3]
    assert points and links
    # characteristic magnitudes: position, velocity, acceleration; omega, epsilon
    scale = {
        cols: max(np.abs(ref[k][:, cols]).max() for k in points)
        for cols in ((0, 1), (2, 3), (4, 5))
    }
    for k in points:
        assert cf[k].shape == (len(THETAS), 6) and cf[k].dtype == np.float64
        for cols, s in scale.items():
            err = np.abs(cf[k][:, cols] - ref[k][:, cols]).max()
            assert err <= 1e-12 * s, (name, k, cols, err, s)
    for col in (1, 2):
        s = max(np.abs(ref[k][:, col]).max() for k in links)
        for k in links:
            err = np.abs(cf[k][:, col] - ref[k][:, col]).max()
            assert err <= 1e-12 * s, (name, k, col, err, s)
    for k in links:
        assert np.abs(_wrap(cf[k][:, 0] - ref[k][:, 0])).max() <= 1e-12, (name, k)


def test_closed_form_is_vectorised_over_any_shape() -> None:
    th = THETAS.reshape(4, 5)
    for name in SHARED:
        out = closed_form.preset(name, th)
        flat = closed_form.preset(name, THETAS)
        for k, v in out.items():
            assert v.shape[:2] == (4, 5)
            np.testing.assert_array_equal(v.reshape(20, -1), flat[k])
    assert closed_form.preset("four_bar", 0.5)["C"].shape == (6,)


# ---------------------------------------------------------------------------------------------
# mpref self-consistency: loop closure, rigid bodies, sliding pairs
# ---------------------------------------------------------------------------------------------
def _dist(p: tuple, q: tuple) -> mpf:
    return mp.hypot(q[0] - p[0], q[1] - p[1])


def _closure_residuals(name: str, s: dict) -> list[mpf]:
    """Loop-closure residuals evaluated from the returned point coordinates."""
    P = mpref.PRESET_PARAMS[name]
    if name in ("slider_crank", "offset_slider_crank", "machine_unit"):
        return [
            _dist(s["O"], s["A"]) - mpf(P["r"]),
            _dist(s["A"], s["B"]) - mpf(P["l"]),
            s["B"][1] - mpf(P["e"]),  # guide_angle = 0: guide y = e
        ]
    if name == "four_bar":
        return [
            _dist(s["A"], s["B"]) - mpf(P["lAB"]),
            _dist(s["B"], s["C"]) - mpf(P["lBC"]),
            _dist(s["D"], s["C"]) - mpf(P["lCD"]),
            _dist(s["B"], s["E"]) - mpf(P["lBE"]),
            _dist(s["C"], s["E"]) - mpf(P["lCE"]),
        ]
    if name == "v_engine":
        ux, uy = (mp.cospi(mpf(1) / 3), mp.sinpi(mpf(1) / 3)), (-mp.cospi(mpf(1) / 3),
                                                                 mp.sinpi(mpf(1) / 3))
        return [
            _dist(s["A"], s["B"]) - mpf("0.08"),
            _dist(s["B"], s["C"]) - mpf("0.248"),
            _dist(s["B"], s["D"]) - mpf("0.062"),
            _dist(s["C"], s["D"]) - mpf("0.218"),
            _dist(s["D"], s["E"]) - mpf("0.218"),
            ux[0] * s["C"][1] - ux[1] * s["C"][0],  # C on Ax
            uy[0] * s["E"][1] - uy[1] * s["E"][0],  # E on Ay
        ]
    # quick_return / shaper
    O3, A, B = s["O3"], s["A"], s["B"]
    res = [
        _dist(s["O1"], A) - mpf("0.1"),
        _dist(O3, B) - mpf("0.6"),
        (A[0] - O3[0]) * (B[1] - O3[1]) - (A[1] - O3[1]) * (B[0] - O3[0]),  # A on O3B
        _dist(O3, A) - s["s3"][0],
    ]
    if name == "shaper":
        res += [_dist(B, s["C"]) - mpf("0.15"), s["C"][1] - mpf("0.32")]
    return res


@pytest.mark.parametrize("name", ALL_PRESETS)
def test_loop_closure_and_branches(name: str, ref_mp: dict) -> None:
    for th, s in zip(FEW_THETAS, ref_mp[name]):
        for r in _closure_residuals(name, s):
            assert abs(r) < TOL_POS, (name, th, r)
        # assembly branches
        if name == "four_bar":
            B, C, D, E = s["B"], s["C"], s["D"], s["E"]
            assert (D[0] - B[0]) * (C[1] - B[1]) - (D[1] - B[1]) * (C[0] - B[0]) > 0
            assert (C[0] - B[0]) * (E[1] - B[1]) - (C[1] - B[1]) * (E[0] - B[0]) > 0
        elif name == "v_engine":
            B, C, D = s["B"], s["C"], s["D"]
            assert (C[0] - B[0]) * (D[1] - B[1]) - (C[1] - B[1]) * (D[0] - B[0]) > 0
            assert C[1] > 0 and s["E"][1] > 0  # + sides of Ax (60 deg) and Ay (120 deg)
        elif name in ("quick_return", "shaper"):
            assert s["s3"][0] > 0 and s["B"][1] > s["O3"][1]
            if name == "shaper":
                assert s["C"][0] > s["B"][0]
        else:
            assert s["B"][0] > s["A"][0]


def _scale(s: dict, lo: int, hi: int) -> mpf:
    return max(max(abs(v[i]) for i in range(lo, hi)) for v in s.values() if len(v) == 6)


@pytest.mark.parametrize("name", ALL_PRESETS)
def test_rigid_body_velocity_and_acceleration(name: str, ref_mp: dict) -> None:
    """vQ - vP = w k x PQ and aQ - aP = eps k x PQ - w^2 PQ for all point pairs of each link."""
    omega = mpref.preset_omega(name)
    for th, s in zip(FEW_THETAS, ref_mp[name]):
        sv, sa = _scale(s, 2, 4), _scale(s, 4, 6)
        _, w1, e1 = s["1"]
        assert abs(w1 - omega) < TOL_DER * abs(omega) and abs(e1) < TOL_DER * omega**2
        for link, members in MEMBERS[name].items():
            _, w, eps = s[link]
            P = s[members[0]]
            for qn in members[1:]:
                Q = s[qn]
                dx, dy = Q[0] - P[0], Q[1] - P[1]
                assert abs(Q[2] - P[2] - (-w * dy)) < TOL_DER * sv, (name, th, link, qn)
                assert abs(Q[3] - P[3] - (w * dx)) < TOL_DER * sv, (name, th, link, qn)
                assert abs(Q[4] - P[4] - (-eps * dy - w * w * dx)) < TOL_DER * sa
                assert abs(Q[5] - P[5] - (eps * dx - w * w * dy)) < TOL_DER * sa


@pytest.mark.parametrize("name", ALL_PRESETS)
def test_sliding_pairs(name: str, ref_mp: dict) -> None:
    """Sliders move along their guides; the coulisse slider obeys the Coriolis relation."""
    for th, s in zip(FEW_THETAS, ref_mp[name]):
        sv, sa = _scale(s, 2, 4), _scale(s, 4, 6)
        if name in ("slider_crank", "offset_slider_crank", "machine_unit"):
            assert abs(s["B"][3]) < TOL_DER * sv and abs(s["B"][5]) < TOL_DER * sa
        elif name == "v_engine":
            for p, ang in (("C", mpf(1) / 3), ("E", mpf(2) / 3)):
                u = (mp.cospi(ang), mp.sinpi(ang))
                assert abs(u[0] * s[p][3] - u[1] * s[p][2]) < TOL_DER * sv
                assert abs(u[0] * s[p][5] - u[1] * s[p][4]) < TOL_DER * sa
        elif name in ("quick_return", "shaper"):
            sA, sd, sdd = s["s3"]
            phi, w3, e3 = s["3"]
            u = (mp.cos(phi), mp.sin(phi))
            n = (-u[1], u[0])
            A = s["A"]
            # vA = sd u + s w3 n ; aA = (sdd - s w3^2) u + (s e3 + 2 sd w3) n
            assert abs(A[2] - (sd * u[0] + sA * w3 * n[0])) < TOL_DER * sv
            assert abs(A[3] - (sd * u[1] + sA * w3 * n[1])) < TOL_DER * sv
            at, an = sdd - sA * w3**2, sA * e3 + 2 * sd * w3
            assert abs(A[4] - (at * u[0] + an * n[0])) < TOL_DER * sa
            assert abs(A[5] - (at * u[1] + an * n[1])) < TOL_DER * sa
            if name == "shaper":
                assert abs(s["C"][3]) < TOL_DER * sv and abs(s["C"][5]) < TOL_DER * sa


def test_guesses_agree_with_newton() -> None:
    """The float closed-form guesses land on the same assembly as the Newton solution."""
    for th in FEW_THETAS:
        s = mpref.shaper(th)
        _phi3, sA, phi4, xC = mpref.guess_shaper(th)
        assert abs(sA - float(s["s3"][0])) < 1e-12 and abs(xC - float(s["C"][0])) < 1e-12
        assert abs(math.remainder(phi4 - float(s["4"][0]), 2 * math.pi)) < 1e-12
        v = mpref.v_engine(th)
        _phi2, sC, _, sE = mpref.guess_v_engine(th)
        assert abs(sC - float(mp.hypot(v["C"][0], v["C"][1]))) < 1e-12
        assert abs(sE - float(mp.hypot(v["E"][0], v["E"][1]))) < 1e-12


# ---------------------------------------------------------------------------------------------
# V-engine dead centre (WORKED_EXAMPLES section 1)
# ---------------------------------------------------------------------------------------------
def test_v_engine_bottom_dead_centre() -> None:
    with mp.workdps(mpref.DPS):
        theta = -2 * mp.pi / 3  # project's phi1 = 180 deg; must be exact to 40 digits
        s = mpref.v_engine(theta)
    C, B = s["C"], s["B"]
    assert abs(C[2]) < 1e-30 and abs(C[3]) < 1e-30
    # A lies between B and C on the Ax line
    assert B[0] < 0 and B[1] < 0 and C[0] > 0 and C[1] > 0
    assert abs(mp.hypot(C[0], C[1]) - (mpf("0.248") - mpf("0.08"))) < 1e-35
    # S2 image is the midpoint of bc (not of pc)
    S2 = s["S2"]
    for i in range(6):
        assert abs(S2[i] - (B[i] + C[i]) / 2) < 1e-30 * (1 + abs(B[i]))
    assert abs(s["1"][1] - mpref.rpm(-800)) < 1e-30


def test_reference_format() -> None:
    out = mpref.reference("quick_return", [0.1, 0.2, 0.3])
    assert set(out) == {"O1", "A", "O3", "B", "1", "3", "s3"}
    assert out["A"].shape == (3, 6) and out["3"].shape == (3, 3) and out["s3"].shape == (3, 3)
    assert all(v.dtype == np.float64 for v in out.values())
    with pytest.raises(KeyError):
        mpref.reference("no_such_mechanism", [0.0])


def test_unreachable_position_raises() -> None:
    with pytest.raises(mpref.ConvergenceError):
        mpref.slider_crank("0.1", "0.05", "0", 1, math.pi / 2)
