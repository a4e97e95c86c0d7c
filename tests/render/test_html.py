"""The live page (``draw --format html``): one self-contained file whose embedded data are the
construction's own values, its replay steps in the order of the protocol, in every language."""

from __future__ import annotations

import json
import math
import re
from html.parser import HTMLParser
from pathlib import Path

import numpy as np
import pytest
from scenes import ALL_TEMPLATES, ROOT

from mechplan import api
from mechplan.construct.protocol import protocol
from mechplan.errors import MechplanError
from mechplan.i18n import LANGUAGES, number
from mechplan.live_page import page_text
from mechplan.model.plans import Plan
from mechplan.sheet.live import UI
from mechplan.studies import solve_file

SVG_NS = "http://www.w3.org/2000/svg"       # a namespace name, not a reference to fetch


def _data(page: str) -> dict:
    m = re.search(r'<script type="application/json" id="data">(.*?)</script>', page, re.DOTALL)
    assert m, "the page embeds its document"
    return json.loads(m.group(1).replace("<\\/", "</"))


@pytest.fixture(scope="module")
def four_bar():
    study = solve_file(str(ROOT / "templates" / "four_bar.toml"))
    page = page_text(study, name="four_bar")
    return study, page, _data(page)


class _Refs(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.refs: list[tuple[str, str, str]] = []
        self.tags: list[str] = []

    def handle_starttag(self, tag, attrs):
        self.tags.append(tag)
        for name, value in attrs:
            if name in ("src", "href", "action", "srcset", "data", "poster", "xlink:href"):
                self.refs.append((tag, name, value or ""))


def test_one_file_without_external_references(four_bar):
    _study, page, _doc = four_bar
    parser = _Refs()
    parser.feed(page)
    assert parser.refs == []                        # no script, style, font or image fetched
    assert "link" not in parser.tags and "iframe" not in parser.tags
    body = page.replace(SVG_NS, "")
    assert not re.search(r"https?://", body), "no URL anywhere but the SVG namespace"
    assert not re.search(r"\bfetch\s*\(|XMLHttpRequest|\bimport\s*\(|WebSocket|EventSource",
                         body)
    assert re.search(r"url\(data:font/", page), "the fonts are inlined as data"
    assert "default-src 'none'" in page              # and the page forbids any other load


def test_positions_are_the_constructions_own(four_bar):
    """The animation's points equal the construction evaluated at the same crank angles, and
    close the loop: |BC|, |DC| and the crank pin on its circle, from the scene's lengths."""
    study, _page, doc = four_bar
    sol = study.solution
    c = sol.construction
    mu = sol.scales[Plan.POSITION]
    a = doc["animation"]
    phi = np.radians(np.asarray(a["phi_deg"]))
    ev = c.evaluate(phi)
    pos = next(p for p in a["panels"] if p["id"] == "position")["points"]

    def xy(name):
        v = np.asarray(pos[name]["xy"], dtype=float).reshape(-1, 2)
        return v * np.array([1.0, -1.0]) * mu          # the page's y runs down; back to m

    for name in ("B", "C", "E"):
        exact = np.asarray(ev[c.position(name)])
        assert np.abs(xy(name) - exact).max() <= 0.006 * mu   # paper precision 0.01 mm
    # independent: the crank pin at (80 mm)(cos φ, sin φ) about A = (0, 0), φ the slider's angle
    pin = 0.080 * np.column_stack([np.cos(phi), np.sin(phi)])
    assert np.abs(xy("B") - pin).max() <= 0.006 * mu
    bc = np.hypot(*(xy("C") - xy("B")).T)
    dc = np.hypot(*(xy("C") - np.array([0.250, 0.0])).T)
    assert np.abs(bc - 0.260).max() < 0.02 * mu and np.abs(dc - 0.180).max() < 0.02 * mu
    assert len(phi) == 360 and np.allclose(np.diff(np.unwrap(phi)), 2 * math.pi / 360, atol=1e-5)


def test_velocity_values_follow_the_slider(four_bar):
    """v_B at every frame is ω·l_AB (closed form); its paper length is v_B / μv."""
    study, _page, doc = four_bar
    mu_v = study.solution.scales[Plan.VELOCITY]
    vb = next(v for v in doc["animation"]["values"] if v["quantity"] == "v_B")
    assert np.allclose(vb["value"], 10.0 * 0.080, atol=1e-9)
    assert np.allclose(vb["mm"], 0.8 / mu_v, atol=0.006)


def test_replay_steps_in_the_order_of_the_protocol(four_bar):
    study, _page, doc = four_bar
    sol = study.solution
    mu = sol.scales
    for r in doc["replays"]:
        if r["plan"] == "centres":          # Kennedy's construction: its own test below
            continue
        plan = Plan(r["plan"])
        groups = {s["group"] for s in r["steps"]}
        expected = [text for _p, _label, text in protocol(sol.construction, sol.ev, r["k"], "en",
                                                          mu, (plan,))]
        said = [s["sentence"]["en"] for s in r["steps"]]
        if plan is Plan.FORCE:               # one polygon per group: its steps, in order
            ids = [s.id for s in sol.construction.of_plan(plan) if s.group in groups
                   and s.id in sol.ev.values and s.op.message is not None]
            assert [s["id"] for s in r["steps"]] == ids
        else:
            assert said == expected
        n = len(r["steps"])
        for lang in LANGUAGES:
            ks = [p["k"] for p in r["prims"][lang]]
            assert all(-1 <= k < n for k in ks)
            assert any(k >= 0 for k in ks), "the replay draws something step by step"
        for row in r["rows"]:
            assert 0 <= row["step"] < n


def test_segment_found_at_its_step(four_bar):
    """In the velocity replay, pb is found at the step that draws b, and its arrow appears
    then: the measured segment and its arrow come with the same sentence."""
    study, _page, doc = four_bar
    r = next(r for r in doc["replays"] if r["plan"] == "velocity")
    row = next(x for x in r["rows"] if x["quantity"] == "v_B")
    step = r["steps"][row["step"]]
    assert "pb" in step["sentence"]["en"]
    drawn = [p for p in r["prims"]["en"] if p["k"] == row["step"]]
    assert any("h" in p for p in drawn), "the arrow pb appears at that step"
    assert float(row["value"]["en"]) == pytest.approx(0.8, abs=5e-4)
    mu_v = study.solution.scales[Plan.VELOCITY]
    assert float(row["mm"]["en"]) == pytest.approx(0.8 / mu_v, abs=0.05)


def test_every_language_is_in_the_page(four_bar):
    _study, _page, doc = four_bar
    assert sorted(doc["languages"]) == sorted(LANGUAGES)
    for lang in LANGUAGES:
        assert all(doc["ui"][lang][k] for k in UI)
        assert doc["ui"][lang]["decimal"] in (".", ",")
    assert doc["ui"]["ru"]["decimal"] == ","
    r = doc["replays"][1]
    texts = {lang: [s["sentence"][lang] for s in r["steps"]] for lang in LANGUAGES}
    assert len({tuple(t) for t in texts.values()}) == len(LANGUAGES)   # each its own words
    assert "," in " ".join(texts["ru"]) and "мм" in " ".join(texts["ru"])


def test_dead_centres_and_sheet_positions_on_the_slider(four_bar):
    _study, _page, doc = four_bar
    a = doc["animation"]
    kinds = {m["kind"] for m in a["marks"]}
    assert {"dead", "chosen"} <= kinds
    # the rocker's two extreme positions: ω3 = 0 there (independently: the velocity of C)
    vc = np.asarray(next(v for v in a["values"] if v["quantity"] == "v_C")["value"])
    for m in a["marks"]:
        if m["kind"] == "dead":
            assert vc[m["k"]] < 0.05 * vc.max()


@pytest.mark.parametrize("path", ALL_TEMPLATES, ids=lambda p: p.stem)
def test_page_weight(path: Path, tmp_path: Path) -> None:
    """Every template's page is one file of at most 3 MB."""
    written = api.draw(path, tmp_path, formats=["html"])
    assert [p.suffix for p in written] == [".html"]
    size = written[0].stat().st_size
    assert 50_000 < size <= 3_000_000


def test_other_kinds_give_their_sheets_in_every_language(tmp_path: Path) -> None:
    """A gears scene's page holds its sheets (the SVG's primitives) in the four languages."""
    path = api.draw(ROOT / "templates" / "planetary_two_row.toml", tmp_path, formats=["html"])[0]
    page = path.read_text(encoding="utf-8")
    doc = _data(page)
    assert [r["id"] for r in doc["replays"]] == ["gears-velocity", "gears-angular"]
    assert sorted(doc["sheets"]) == sorted(LANGUAGES)
    for lang in LANGUAGES:
        sheets = doc["sheets"][lang]
        assert sheets and all(len(s["prims"]) > 50 for s in sheets)
    texts = {lang: {p["t"] for s in doc["sheets"][lang] for p in s["prims"] if "t" in p}
             for lang in LANGUAGES}
    assert texts["en"] != texts["ru"] and texts["en"] != texts["zh"]
    assert len(page.encode()) <= 3_000_000


def test_a_failing_scene_writes_no_page(tmp_path: Path) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text((ROOT / "templates" / "four_bar.toml").read_text(encoding="utf-8")
                   .replace('link = "1"', 'link = "9"'), encoding="utf-8")
    out = tmp_path / "out"
    with pytest.raises(MechplanError) as html_error:
        api.draw(bad, out, formats=["html"])
    with pytest.raises(MechplanError) as svg_error:
        api.draw(bad, out, formats=["svg"])
    assert str(html_error.value) == str(svg_error.value)
    assert not list(out.glob("*.html"))


def test_diagram_cursor_follows_the_slider():
    """The cursor of s(φ) in the slider-crank's animation is the piston's travel at every frame:
    x = r cos φ + √(l² − r² sin² φ) (closed form), drawn on its axes (an affine map to mm)."""
    study = solve_file(str(ROOT / "templates" / "slider_crank.toml"))
    doc = _data(page_text(study, name="slider_crank"))
    a = doc["animation"]
    phi = np.radians(np.asarray(a["phi_deg"]))
    panel = next(p for p in a["panels"] if p["id"] == "diagram-s")
    xy = np.asarray(panel["points"]["diagram-s"]["xy"], dtype=float).reshape(-1, 2)
    r, l = 0.100, 0.400
    s = r * np.cos(phi) + np.sqrt(l**2 - (r * np.sin(phi))**2)
    s -= s.min()
    slope, icpt = np.polyfit(s, -xy[:, 1], 1)            # page y runs down
    assert np.abs(slope * s + icpt + xy[:, 1]).max() < 0.01   # within paper precision
    assert slope > 0
    steps = np.diff(xy[:, 0])
    assert np.allclose(steps, steps[0], atol=0.011) and steps[0] > 0   # φ along the axis
    assert set(panel["static"]) == set(LANGUAGES) and all(panel["static"].values())


def test_machine_dynamics_diagrams_have_a_cursor_at_the_crank_angle():
    """With [dynamics], ω(φ) of the cycle is in the animation; its cursor's x is the cycle angle
    of each frame ((φ − φ0) mod Φ at μφ) and its y the crank's ω there."""
    study = solve_file(str(ROOT / "templates" / "machine_unit.toml"))
    dyn = study.dynamics
    doc = _data(page_text(study, name="machine_unit"))
    a = doc["animation"]
    panel = next(p for p in a["panels"] if p["id"] == "dynamics-omega")
    xy = np.asarray(panel["points"]["dynamics-omega"]["xy"], dtype=float).reshape(-1, 2)
    phi = np.radians(np.asarray(a["phi_deg"]))
    theta = np.mod(phi - dyn.phi0, dyn.spec.cycle)
    slope, _ = np.polyfit(theta, xy[:, 0], 1)
    assert np.abs(np.polyval(np.polyfit(theta, xy[:, 0], 1), theta) - xy[:, 0]).max() < 0.01
    assert slope > 0
    omega = np.interp(theta, dyn.theta, dyn.omega)
    fit = np.polyfit(omega, -xy[:, 1], 1)
    assert np.abs(np.polyval(fit, omega) + xy[:, 1]).max() < 0.01
    assert {p["id"] for p in a["panels"]} >= {"dynamics-moments", "dynamics-energy",
                                              "dynamics-inertia", "dynamics-omega"}


def test_engine_polar_diagram_traced_with_one_scale():
    """The engine's page animates the polar diagram of pin 1: the traced point is (T, Z) at one
    scale on both axes, and Q there is the distance from the pole (0, −K_r)."""
    study = solve_file(str(ROOT / "templates" / "motorcycle_engine.toml"))
    doc = _data(page_text(study, name="engine"))
    a = doc["animation"]
    polar = next(p for p in a["panels"] if p["id"] == "engine-polar")
    xy = np.asarray(polar["points"]["Q"]["xy"], dtype=float).reshape(-1, 2)
    vals = {v["quantity"]: np.asarray(v["value"], dtype=float) for v in a["values"]}
    sx = np.polyfit(vals["T"], xy[:, 0], 1)[0]
    sy = np.polyfit(vals["Z"], -xy[:, 1], 1)[0]
    assert sx == pytest.approx(sy, rel=1e-3) and sx > 0          # one scale: a true polar plot
    k_r = study.dense.pins[1].K_r * 1e-3
    assert np.allclose(vals["Q"], np.hypot(vals["T"], vals["Z"] + k_r), rtol=1e-5, atol=1e-5)
    assert polar["points"]["Q"]["grow"] and len(a["phi_deg"]) == a["frames"] >= 360
    assert doc["sheets"] and not doc["replays"]


@pytest.mark.parametrize("stem", ["cam_cycloidal", "cam_oscillating"])
def test_cam_follower_touches_the_turning_cam(stem):
    """In the cam's animation the roller stays on the turning cam: the roller centre, turned back
    by the frame's angle of the cam, lies one roller radius from the working profile (measured on
    the page's own polyline); the replay lays the rays in order, then the profile."""
    study = solve_file(str(ROOT / "templates" / f"{stem}.toml"))
    g = study.design.geometry
    assert g.roller > 0
    doc = _data(page_text(study, name=stem))
    cam = next(p for p in doc["animation"]["panels"] if p["id"] == "cam")
    rotor = next(it for it in cam["items"] if it["kind"] == "rotor")
    outline = next(p for p in rotor["shape"] if "d" in p and p["d"].endswith("Z"))
    pts = np.array([[float(v) for v in xy.split()] for xy in
                    re.split("[ML]", outline["d"].rstrip("Z")) if xy])
    b = np.asarray(cam["points"]["B"]["xy"], dtype=float).reshape(-1, 2)
    mu = doc["replays"][0]["mu"]["en"]
    mu_m = float(re.search(r"= ([\d.]+)", mu).group(1)) / 1000.0        # m per paper mm
    for k in range(0, len(b), 17):
        a = math.radians(-rotor["angle"][k])
        rot = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
        p = rot @ b[k]
        seg = np.diff(np.vstack([pts, pts[:1]]), axis=0)
        t = np.clip(((p - pts) * seg).sum(1) / (seg * seg).sum(1), 0.0, 1.0)
        dist = np.hypot(*(pts + t[:, None] * seg - p).T).min()
        assert dist == pytest.approx(g.roller / mu_m, abs=0.05)
    steps = doc["replays"][0]["steps"]
    n = study.design.rays.phi.size
    assert [s["id"] for s in steps] == ["base", *(f"ray-{i}" for i in range(n)), "profile"]
    assert all(s["sentence"][lang] for s in steps for lang in LANGUAGES)


#: the planetary templates' tooth sets and input speeds, as their scenes give them (rpm)
TRAINS = {"planetary_single_row": 960.0, "planetary_two_row": 1500.0}


def _willis(stem: str, z: tuple[int, ...], w_in: float) -> dict[str, float]:
    """ω of every link from the tooth numbers (Willis: the train seen from the carrier is an
    ordinary train), the central gear held, the sun the input."""
    if stem == "planetary_single_row":          # sun 1, planet 2, ring 3 held: ω1/ωh = 1 + z3/z1
        z1, z2, z3 = z
        wh = w_in / (1 + z3 / z1)
        return {"1": w_in, "2": wh * (1 - z3 / z2), "3": 0.0, "h": wh}
    z1, z2, z3, z4 = z                          # 1 outside 2; 3 inside ring 4, held
    wh = w_in / (1 + z2 * z4 / (z1 * z3))
    w2 = wh - z1 / z2 * (w_in - wh)             # (ω2 − ωh)/(ω1 − ωh) = −z1/z2
    return {"1": w_in, "2": w2, "3": w2, "4": 0.0, "h": wh}


@pytest.mark.parametrize("stem", sorted(TRAINS))
def test_planetary_train_turns_at_the_willis_ratios(stem):
    """Each wheel and the carrier of the turning train is rotated by ω·t with the ω of the Willis
    ratios of its tooth numbers; every planet's centre stays on the carrier radius
    a_w = m(z1 + z2)/2, at the carrier's angle plus 2πj/k; the slider's φ is the input's ω·t."""
    study = solve_file(str(ROOT / "templates" / f"{stem}.toml"))
    res = study.solution.planetary
    z = tuple(res.chosen.z)
    w_in = TRAINS[stem] * 2 * math.pi / 60
    w = _willis(stem, z, w_in)
    doc = _data(page_text(study, name=stem))
    a = doc["animation"]
    t = np.asarray(a["time"])
    assert a["frames"] == t.size >= 360
    assert np.allclose(np.radians(a["phi_deg"]), w_in * t, rtol=1e-6, atol=1e-6)
    # one turn of the carrier over the cycle
    assert w["h"] * (t[-1] + t[1]) == pytest.approx(2 * math.pi, rel=1e-6)   # 7 digits
    train = next(p for p in a["panels"] if p["id"] == "gears-train")
    rotors = {it["name"]: it for it in train["items"] if it["kind"] == "rotor"}
    for n, omega in w.items():
        planet = n in res.spec.scheme.gear_names[1:-1]
        rot = rotors["2-0"] if planet else rotors[n]      # the planet block turns as one
        # the page turns a body by −angle (y down): counter-clockwise ω·t
        assert np.allclose(-np.radians(rot["angle"]), omega * t, rtol=1e-6, atol=1e-5), n
    m = res.spec.modules[0]
    a_w = m * (z[0] + z[1]) / 2
    mu = train["scale"]
    k = res.spec.planets
    for j in range(k):
        c = np.asarray(rotors[f"2-{j}"]["centre"], dtype=float).reshape(-1, 2)
        assert np.allclose(np.hypot(*c.T) * mu, a_w, atol=0.008 * mu)   # 0.01 mm rounding
        ang = np.arctan2(-c[:, 1], c[:, 0])
        want = w["h"] * t + 2 * math.pi * j / k
        assert np.allclose(np.angle(np.exp(1j * (ang - want))), 0.0, atol=1e-3)
        assert np.allclose(c, np.asarray(train["points"][f"O{j + 1}"]["xy"]).reshape(-1, 2))
    # the velocity plan replayed line by line: the given and held links first, the planet,
    # then the carrier; each line's sentence states its ω (Willis), each step draws its line
    vel = next(r for r in doc["replays"] if r["id"] == "gears-velocity")
    held = res.spec.fixed
    assert [s["id"] for s in vel["steps"]] == ["base", "line-1", f"line-{held}", "line-2", "line-h"]
    for i, s in enumerate(vel["steps"]):
        assert sum(1 for p in vel["prims"]["en"] if p["k"] == i) >= 2      # line and label
        n = s["id"][5:]
        if n and n != held:
            assert number(w[n], 4, "en") in s["sentence"]["en"]
        assert all(s["sentence"][lang] for lang in LANGUAGES)
    if stem == "planetary_two_row":             # the ordinary pair 17/34 on the output shaft h
        w |= {"5": w["h"], "6": -w["h"] * 17 / 34}
    ang = next(r for r in doc["replays"] if r["id"] == "gears-angular")
    rays = [s for s in ang["steps"] if s["id"].startswith("ray-")]
    assert {s["id"][4:] for s in rays} >= {"1", "h"}
    for s in rays:
        assert number(w[s["id"][4:]], 4, "en") in s["sentence"]["en"]


def _meet(p1, p2, q1, q2):
    """Where line p1–p2 meets line q1–q2 (rows of points; NaN where parallel)."""
    d1, d2 = p2 - p1, q2 - q1
    den = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
    w = q1 - p1
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (w[:, 0] * d2[:, 1] - w[:, 1] * d2[:, 0]) / den
    return p1 + t[:, None] * d1


@pytest.mark.parametrize("stem", ["four_bar", "slider_crank", "quick_return", "shaper"])
def test_centres_replayed_in_the_solvers_order_and_moving(stem):
    """The instant centres' replay lists every centre once, in the order Kennedy's search finds
    them, each step drawing its centre and its chord; in the animation each centre is where the
    solver puts it at that crank angle (within the page's 0.01 mm), and for the four-bar where
    the lines of its links meet (I02 on AB × DC, I13 on AD × BC, computed here)."""
    from mechplan.construct.plans.centres import centres_at, circle_diagram

    study = solve_file(str(ROOT / "templates" / f"{stem}.toml"))
    sol = study.solution
    mech = sol.scene.mechanism
    doc = _data(page_text(study, name=stem))
    reps = [r for r in doc["replays"] if r["plan"] == "centres"]
    assert len(reps) == 1
    r = reps[0]
    order = [c.key for c in circle_diagram(mech).centres]
    n = len(mech.moving) + 1
    assert len(order) == n * (n - 1) // 2
    assert [s["id"] for s in r["steps"]] == ["base", *order]
    for i in range(1, len(r["steps"])):
        assert sum(1 for p in r["prims"]["en"] if p["k"] == i) >= 3   # centre, chord, number
        assert all(r["steps"][i]["sentence"][lang] for lang in LANGUAGES)
    assert [x["step"] for x in r["rows"]] == list(range(1, len(order) + 1))

    a = doc["animation"]
    panel = next(p for p in a["panels"] if p["id"] == "centres")
    assert sorted(panel["points"]) == sorted(order)
    mu = sol.scales[Plan.POSITION]
    c = sol.construction
    sense = 1.0 if mech.drive.omega >= 0 else -1.0
    phi = float(sol.phi[0]) + sense * np.arange(a["frames"]) * 2 * math.pi / a["frames"]
    ev = c.evaluate(phi)
    cs = centres_at(c, ev, mech)
    shown = 0
    for key in order:
        page = np.array([np.nan if v is None else v for v in panel["points"][key]["xy"]],
                        dtype=float).reshape(-1, 2) * np.array([1.0, -1.0]) * mu
        ctr = next(x for x in cs.diagram.centres if x.key == key)
        want = cs.point(ctr.i, ctr.j)
        ok = np.isfinite(page).all(axis=1)
        shown += int(ok.sum())
        assert np.allclose(page[ok], want[ok], atol=0.008 * mu)
    assert shown > a["frames"] * 3
    if stem == "four_bar":
        def at(p):
            return np.asarray(ev[c.position(p)], dtype=float)
        A, B, C, D = at("A"), at("B"), at("C"), at("D")
        for key, want in (("02", _meet(A, B, D, C)), ("13", _meet(A, D, B, C))):
            page = np.array([np.nan if v is None else v for v in panel["points"][key]["xy"]],
                            dtype=float).reshape(-1, 2) * np.array([1.0, -1.0]) * mu
            ok = np.isfinite(page).all(axis=1)
            assert ok.sum() > 100
            assert np.allclose(page[ok], want[ok], atol=0.008 * mu)


def test_engine_crank_train_moves_with_the_polar_cursor():
    """The engine's crank train (cylinder 1) at every frame of the polar diagram's cursor: the
    crank pin A on the crank circle at the frame's φ from TDC, the rod |AB| = L, the piston pin
    B on the cylinder's axis at the closed-form travel R(1 − cos φ) + L(1 − √(1 − λ² sin² φ))."""
    study = solve_file(str(ROOT / "templates" / "motorcycle_engine.toml"))
    R, L = study.model.spec.R, study.model.spec.L
    doc = _data(page_text(study, name="engine"))
    a = doc["animation"]
    train = next(p for p in a["panels"] if p["id"] == "engine-train")
    mu = train["scale"]
    pa = np.asarray(train["points"]["A"]["xy"], dtype=float).reshape(-1, 2) * [1, -1] * mu
    pb = np.asarray(train["points"]["B"]["xy"], dtype=float).reshape(-1, 2) * [1, -1] * mu
    assert len(pa) == a["frames"] >= 360
    phi = np.radians(np.asarray(a["phi_deg"]))
    tol = 0.008 * mu                                            # the page's 0.01 mm
    assert np.allclose(np.hypot(*pa.T), R, atol=tol)
    assert np.allclose(np.hypot(*(pb - pa).T), L, atol=2 * tol)
    assert np.allclose(pb[:, 0], 0.0, atol=tol)
    lam = R / L
    travel = R * (1 - np.cos(phi)) + L * (1 - np.sqrt(1 - (lam * np.sin(phi)) ** 2))
    assert np.allclose(R + L - pb[:, 1], travel, atol=tol)
    assert np.allclose(np.angle(np.exp(1j * (np.arctan2(-pa[:, 0], pa[:, 1]) - phi))), 0.0,
                       atol=1e-3)
    frames = train["items"][0]["d"]
    assert len(frames) == a["frames"] and all(frames)


def test_wittenbauer_diagram_has_a_cursor():
    """A machine with [dynamics]: the Wittenbauer diagram's cursor is at (J_red, ΔT) of the
    crank's cycle angle at every frame, at the dynamics sheet's μJ and μT."""
    from mechplan.sheet.dynamics import dynamics_scales

    study = solve_file(str(ROOT / "templates" / "machine_unit.toml"))
    dyn = study.dynamics
    doc = _data(page_text(study, name="machine_unit"))
    a = doc["animation"]
    panel = next(p for p in a["panels"] if p["id"] == "dynamics-wittenbauer")
    xy = np.asarray(panel["points"]["dynamics-wittenbauer"]["xy"], dtype=float).reshape(-1, 2)
    theta = np.mod(np.radians(np.asarray(a["phi_deg"])) - dyn.phi0, dyn.spec.cycle)
    j = np.interp(theta, dyn.theta, dyn.J_red)
    t = np.interp(theta, dyn.theta, dyn.dT)
    sc = dynamics_scales(dyn)
    fx, fy = np.polyfit(j, xy[:, 0], 1), np.polyfit(t, -xy[:, 1], 1)
    assert np.abs(np.polyval(fx, j) - xy[:, 0]).max() < 0.01
    assert np.abs(np.polyval(fy, t) + xy[:, 1]).max() < 0.01
    assert fx[0] == pytest.approx(1 / sc.mu_J, rel=1e-3)
    assert fy[0] == pytest.approx(1 / sc.mu_T, rel=1e-3)
