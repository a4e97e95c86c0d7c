"""The checker grades a student's instant centres (issue 30): names in every tradition, the
centres on a drawing (own panel, a position plan, planted mistakes) and the rows of a table.

Golden places come from plain line intersections of the mechanism's points (A, B, C, D of the
four-bar), not from the Kennedy construction under test."""

from __future__ import annotations

import math

import ezdxf
import numpy as np
import pytest

from mechplan.check import Options, check
from mechplan.check.overlay import marks
from mechplan.check.report import MISSING, NEW, OK, SWAPPED, WRONG
from mechplan.render.dxf import to_bytes
from mechplan.scene import load_scene
from mechplan.sheet.compose import compose
from mechplan.solve import solve
from mechplan.submission.centre_marks import read_centre

TEMPLATES = "src/mechplan/templates"
FOUR = ("0", "1", "2", "3")


@pytest.mark.parametrize("text, links, want", [
    ("I13", FOUR, ("1", "3", "")), ("I₁₃", FOUR, ("1", "3", "")), ("P13", FOUR, ("1", "3", "")),
    ("П13", FOUR, ("1", "3", "")), ("Р13", FOUR, ("1", "3", "")), ("P 1 3", FOUR, ("1", "3", "")),
    ("I_{13}", FOUR, ("1", "3", "")), ("P1-3", FOUR, ("1", "3", "")),
    ("I13x", FOUR, ("1", "3", "x")), ("P₀₂B", FOUR, ("0", "2", "B")),
    ("I1,13", ("0", "1", "13"), ("1", "13", "")), ("I113", ("0", "1", "13"), ("1", "13", "")),
])
def test_centre_names_of_every_tradition_are_read(text, links, want):
    name = read_centre(text, links)
    assert name is not None and (name.i, name.j, name.rest) == want


@pytest.mark.parametrize("text", ["P3", "I14", "Pc5", "I1", "pb", "I13 is here", "I(0,1)",
                                  "III(2,3,4,5)"])
def test_other_names_are_no_centres(text):
    assert read_centre(text, FOUR) is None


def _meet(a, b, c, d):
    """The meet of line a–b and line c–d (2-D)."""
    m = np.array([[b[0] - a[0], c[0] - d[0]], [b[1] - a[1], c[1] - d[1]]], dtype=float)
    t = np.linalg.solve(m, np.asarray(c, float) - np.asarray(a, float))[0]
    return np.asarray(a, float) + t * (np.asarray(b, float) - np.asarray(a, float))


@pytest.fixture(scope="module")
def four_bar_panel(tmp_path_factory):
    """The own four-bar sheet with the instant-centre panel (en, A3, ISO)."""
    scene = load_scene(f"{TEMPLATES}/four_bar.toml")
    comp = compose(solve(scene), "A3", "iso", "en", name="four_bar")
    i = next(n for n, pl in enumerate(comp.placements) if any(p.name == "centres" for p, _ in pl))
    path = tmp_path_factory.mktemp("cc") / "panel.dxf"
    path.write_bytes(to_bytes(comp.sheets[i]))
    return scene, path


def _xy(v):
    return np.array([v.x, v.y])


def _panel_marks(doc):
    """The texts of the panel's centres and the small circle each stands beside."""
    msp = doc.modelspace()
    circles = [e for e in msp.query("CIRCLE") if e.dxf.radius < 1.5]
    out = {}
    for t in msp.query("TEXT"):
        at = _xy(t.dxf.insert)
        near = min(circles, key=lambda c: math.dist(_xy(c.dxf.center), at), default=None)
        if near is not None and math.dist(_xy(near.dxf.center), at) < 8.0 and \
                read_centre(t.dxf.text, FOUR) is not None:
            out.setdefault(t.dxf.text, (t, near))
    return out


def test_own_panel_is_graded_right_and_its_kennedy_centre_is_where_lines_meet(four_bar_panel):
    scene, path = four_bar_panel
    report = check(scene, path, Options())
    rows = {c.label: c for c in report.centres}
    # (the panel also names the coupler's acceleration pole Q2: test_centres_tradition.py)
    assert sorted(rows) == ["I01", "I02", "I03", "I12", "I13", "I23", "Q2"]
    assert all(c.verdict == OK for c in rows.values())
    assert report.passed and report.summary()["missing"] == 0
    # I13 of a four-bar: where the frame line A–D meets the coupler line B–C (drawn pins)
    doc = ezdxf.readfile(path)
    pins = {n: _xy(c.dxf.center) for n, (_, c) in _panel_marks(doc).items()}
    want = _meet(pins["I01"], pins["I03"], pins["I12"], pins["I23"])
    assert np.allclose(rows["I13"].exact_mm, want, atol=1e-6)
    assert np.allclose(rows["I13"].at_mm, want, atol=1e-6)
    js = report.to_json("ru")
    assert [c["label"] for c in js["centres"]] == [c.label for c in report.centres]
    assert js["centres_mu_l"] > 0


def test_a_centre_moved_5_mm_is_wrong_by_5_mm_with_its_kennedy_lines(four_bar_panel, tmp_path):
    scene, path = four_bar_panel
    doc = ezdxf.readfile(path)
    text, circle = _panel_marks(doc)["I13"]
    cx, cy = _xy(circle.dxf.center)
    circle.dxf.center = (cx + 3.0, cy + 4.0)          # 5 mm away
    x, y = _xy(text.dxf.insert)
    text.dxf.insert = (x + 3.0, y + 4.0)
    if text.dxf.hasattr("align_point"):
        ax, ay = _xy(text.dxf.align_point)
        text.dxf.align_point = (ax + 3.0, ay + 4.0)
    doc.saveas(tmp_path / "moved.dxf")
    report = check(scene, tmp_path / "moved.dxf", Options())
    rows = {c.label: c for c in report.centres}
    assert rows["I13"].verdict == WRONG and rows["I13"].cause == NEW
    assert rows["I13"].error == pytest.approx(5.0, abs=1e-6)
    assert "I01–I03" in rows["I13"].hint and "I12–I23" in rows["I13"].hint
    assert all(c.verdict == OK for n, c in rows.items() if n != "I13")
    assert not report.passed
    assert any(f.subject == "I13" for f in report.findings)
    for lang in ("en", "ru", "vi", "zh"):
        assert "I12–I23" in report.text(lang)
    # the overlay draws the error from the drawn centre to the exact one
    errors = [m for m in marks(report) if m.layer == "ERRORS" and m.end is not None]
    assert any(m.start == rows["I13"].at_mm and m.end == rows["I13"].exact_mm for m in errors)


def test_two_exchanged_centre_labels_are_found_as_swapped(four_bar_panel, tmp_path):
    scene, path = four_bar_panel
    doc = ezdxf.readfile(path)
    marks = _panel_marks(doc)
    marks["I13"][0].dxf.text, marks["I03"][0].dxf.text = "I03", "I13"
    doc.saveas(tmp_path / "swapped.dxf")
    report = check(scene, tmp_path / "swapped.dxf", Options())
    rows = {c.label: c for c in report.centres}
    assert (rows["I13"].verdict, rows["I13"].cause) == (WRONG, SWAPPED)
    assert (rows["I03"].verdict, rows["I03"].cause) == (WRONG, SWAPPED)
    assert all(c.verdict == OK for n, c in rows.items() if n not in ("I13", "I03"))


def test_an_unlabelled_centre_is_missing(four_bar_panel, tmp_path):
    scene, path = four_bar_panel
    doc = ezdxf.readfile(path)
    marks = _panel_marks(doc)
    doc.modelspace().delete_entity(marks["I13"][0])
    for t in doc.modelspace().query("TEXT"):       # the table's I13 is no drawn centre either
        if t.dxf.text == "I13":
            doc.modelspace().delete_entity(t)
    doc.saveas(tmp_path / "missing.dxf")
    rows = {c.label: c for c in check(scene, tmp_path / "missing.dxf", Options()).centres}
    assert rows["I13"].verdict == MISSING
    assert all(c.verdict == OK for n, c in rows.items() if n != "I13")


def test_centres_on_a_students_position_plan_are_placed_by_its_mu(tmp_path):
    """Centres labelled on the position plan of sheet 1 (I02 right, P₁₃ 5 mm off): placed by
    the plan's μl and points, graded against line meets of the drawn A, B, C, D."""
    scene = load_scene(f"{TEMPLATES}/four_bar.toml")
    comp = compose(solve(scene), "A3", "iso", "ru", name="four_bar")
    path = tmp_path / "sheet1.dxf"
    path.write_bytes(to_bytes(comp.sheets[0]))
    plain = check(scene, path, Options())
    pos = next(p for p in plain.plans if p.plan == "position")
    a, b, c, d = (np.array(pos.exact_mm[x]) for x in "ABCD")
    i13 = _meet(a, d, b, c)
    i02 = _meet(a, b, d, c)
    off = i13 + np.array([0.0, 5.0])
    doc = ezdxf.readfile(path)
    msp = doc.modelspace()
    for name, p in (("P₁₃", off), ("I02", i02)):
        msp.add_point((float(p[0]), float(p[1])))
        msp.add_text(name, dxfattribs={"height": 2.5}).set_placement(
            (float(p[0]) + 1.0, float(p[1]) + 1.0))
    doc.saveas(tmp_path / "with_centres.dxf")
    report = check(scene, tmp_path / "with_centres.dxf", Options())
    rows = {r.label: r for r in report.centres}
    assert rows["I02"].verdict == OK and rows["I02"].error == pytest.approx(0.0, abs=1e-6)
    assert rows["I13"].verdict == WRONG and rows["I13"].written == "P₁₃"
    assert rows["I13"].error == pytest.approx(5.0, abs=1e-6)
    assert "I01–I03" in rows["I13"].hint and "I12–I23" in rows["I13"].hint
    assert {r.label for r in report.centres if r.verdict == MISSING} == {
        "I01", "I03", "I12", "I23"}
    assert report.centres_mu == pytest.approx(pos.mu)


def _four_bar_at_60():
    scene = load_scene(f"{TEMPLATES}/four_bar.toml")
    sol = solve(scene, at_deg=[60.0])
    c, ev = sol.construction, sol.ev
    return scene, {p: np.asarray(ev[c.position(p)][0]) for p in "ABCD"}


def test_a_table_of_centres_is_graded(tmp_path):
    scene, p = _four_bar_at_60()
    i13 = _meet(p["A"], p["D"], p["B"], p["C"])     # metres, the frame of the scene
    i02 = _meet(p["A"], p["B"], p["D"], p["C"])
    dist = float(np.hypot(*(i02 - p["B"])))
    table = tmp_path / "t.toml"
    table.write_text(
        '"φ" = "60°"\n'
        f'I13 = "({i13[0] * 1000:.2f}, {i13[1] * 1000:.2f}) mm"\n'
        f'"P₀₂x" = "{i02[0] * 1000:.2f} mm"\n'
        f'P02y = "{i02[1] * 1000 + 40:.2f} mm"\n'
        f'I02B = "{dist:.5f} m"\n'
        'I23 = "(1, 2) mm"\n'
        'I14 = "(1, 2) mm"\n', encoding="utf-8")
    report = check(scene, table, Options(at_deg=60))
    rows = {v.name: v for v in report.values}
    assert rows["I13.x"].verdict == OK and rows["I13.y"].verdict == OK
    assert rows["I13.x"].exact == pytest.approx(i13[0], abs=1e-9)
    assert rows["P₀₂x"].verdict == OK and rows["I02B"].verdict == OK
    assert rows["I02B"].exact == pytest.approx(dist, rel=1e-9)
    assert rows["P02y"].verdict == WRONG and "I01–I12" in rows["P02y"].hint
    assert rows["I23.x"].verdict == WRONG and "C" in rows["I23.x"].hint
    assert any("I14" in n.message for n in report.notes)
    assert not report.passed


def test_a_centre_at_infinity_in_a_table_is_accepted_and_a_number_is_not(tmp_path):
    scene = load_scene(f"{TEMPLATES}/slider_crank.toml")
    table = tmp_path / "t.toml"
    table.write_text('"φ" = "60°"\nP03 = "∞"\nI23x = "1 mm"\n', encoding="utf-8")
    report = check(scene, table, Options(at_deg=60))
    rows = {v.name: v for v in report.values}
    assert rows["P03"].verdict == OK
    assert rows["I23x"].verdict == WRONG


def test_a_centre_at_infinity_is_graded_by_its_arrow_or_accepted_as_written(tmp_path):
    """The slider-crank's I03 (the slider's guide, ⊥ at infinity): right with the panel's arrow,
    wrong with an arrow turned 45°, and accepted written "I03 ∞" with no arrow."""
    scene = load_scene(f"{TEMPLATES}/slider_crank.toml")
    comp = compose(solve(scene), "A3", "iso", "en", name="slider_crank")
    i = next(n for n, pl in enumerate(comp.placements) if any(p.name == "centres" for p, _ in pl))
    path = tmp_path / "panel.dxf"
    path.write_bytes(to_bytes(comp.sheets[i]))
    rows = {c.label: c for c in check(scene, path, Options()).centres}
    assert rows["I03"].verdict == OK and rows["I03"].found == "infinity"

    doc = ezdxf.readfile(path)
    msp = doc.modelspace()
    text = next(e for e in msp.query("TEXT") if "∞" in e.dxf.text and "I03" in e.dxf.text)
    at = _xy(text.dxf.insert)
    heads = [e for e in msp.query("SOLID") if math.dist(_xy(e.dxf.vtx0), at) < 12.0]
    assert heads
    tip = _xy(heads[0].dxf.vtx0)
    for h in heads:                      # turn the head 45° about its tip
        for v in ("vtx0", "vtx1", "vtx2", "vtx3"):
            if h.dxf.hasattr(v):
                d = _xy(h.dxf.get(v)) - tip
                c, s = math.cos(math.pi / 4), math.sin(math.pi / 4)
                h.dxf.set(v, (tip[0] + c * d[0] - s * d[1], tip[1] + s * d[0] + c * d[1]))
    doc.saveas(tmp_path / "turned.dxf")
    rows = {c.label: c for c in check(scene, tmp_path / "turned.dxf", Options()).centres}
    assert rows["I03"].verdict == WRONG and rows["I03"].error == pytest.approx(45.0, abs=1.0)

    for h in heads:
        msp.delete_entity(h)
    text.dxf.text = "I03 ∞"
    doc.saveas(tmp_path / "no_arrow.dxf")
    rows = {c.label: c for c in check(scene, tmp_path / "no_arrow.dxf", Options()).centres}
    assert rows["I03"].verdict == OK


def test_the_table_of_centres_drawn_on_a_sheet_is_read_and_graded(tmp_path):
    """mechplan's table of centres (name, x, y mm; or ∞ and the direction) is read back: every
    row right on the own sheet, a number changed by 20 mm wrong."""
    scene = load_scene(f"{TEMPLATES}/four_bar.toml")
    comp = compose(solve(scene), "A3", "iso", "ru", name="four_bar")
    i = next(n for n, pl in enumerate(comp.placements)
             if any(x.name == "centres-table" for x, _ in pl))
    path = tmp_path / "table.dxf"
    path.write_bytes(to_bytes(comp.sheets[i]))
    rows = [v for v in check(scene, path, Options()).values if v.quantity.startswith("I")]
    assert len(rows) == 12 and all(v.verdict == OK for v in rows)
    doc = ezdxf.readfile(path)
    msp = doc.modelspace()
    name = next(t for t in msp.query("TEXT") if t.dxf.text == "P13"
                and any(abs(_xy(c.dxf.insert)[1] - _xy(t.dxf.insert)[1]) < 1.0
                        and _xy(c.dxf.insert)[0] > _xy(t.dxf.insert)[0] for c in msp.query("TEXT")
                        if c.dxf.text.replace(",", "").replace("-", "").isdigit()))
    y = _xy(name.dxf.insert)[1]
    x_cell = min((c for c in msp.query("TEXT") if abs(_xy(c.dxf.insert)[1] - y) < 1.0
                  and _xy(c.dxf.insert)[0] > _xy(name.dxf.insert)[0]),
                 key=lambda c: _xy(c.dxf.insert)[0])
    x_mm = float(x_cell.dxf.text.replace(",", ".").replace("−", "-"))
    x_cell.dxf.text = f"{x_mm + 20.0:.1f}".replace(".", ",")
    doc.saveas(tmp_path / "table_wrong.dxf")
    report = check(scene, tmp_path / "table_wrong.dxf", Options())
    rows = {v.name: v for v in report.values if v.quantity.startswith("I")}
    assert rows["P13.x"].verdict == WRONG and rows["P13.y"].verdict == OK
    assert rows["P13.x"].submitted - rows["P13.x"].exact == pytest.approx(0.020, abs=1e-4)
    assert "I01–I03" in rows["P13.x"].hint
