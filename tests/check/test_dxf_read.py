"""Reading DXF sheets made by a different writer, and sheets that are damaged or incomplete."""

from __future__ import annotations

import ezdxf
import numpy as np
import pytest

from mechplan.check import Options, check, read_submission
from mechplan.check.report import OK, REFERENCE
from mechplan.errors import CheckError
from mechplan.model.plans import Plan
from mechplan.sheet.fonts import text_width_mm

from .sheets import PlanSpec, exact_sheet, solved, write_dxf

V, A, P = Plan.VELOCITY, Plan.ACCELERATION, Plan.POSITION
SPECS = {V: PlanSpec(0.01, (50, 50), "μv = 0,01 m/s/mm"),
         A: PlanSpec(0.1, (250, 60), "μa = 0.1 (m/s²)/mm")}


@pytest.fixture
def four_bar():
    return solved("four_bar", 60)


def _levels(report, level: str) -> list[str]:
    return [n.message for n in report.notes if n.level == level]


def test_texts_are_read_with_their_boxes(tmp_path) -> None:
    doc = ezdxf.new()
    doc.header["$INSUNITS"] = 4
    msp = doc.modelspace()
    msp.add_text("b", dxfattribs={"height": 2.0, "rotation": 90.0}).set_placement((10, 10))
    t = msp.add_text("c′", dxfattribs={"height": 2.0})
    t.set_placement((20, 20), align=ezdxf.enums.TextEntityAlignment.MIDDLE_CENTER)
    msp.add_mtext(r"{\fArial;n\S^CB;}", dxfattribs={"char_height": 2.0, "insert": (30, 30),
                                                     "attachment_point": 5})
    msp.add_line((0, 0), (1, 1))
    path = tmp_path / "t.dxf"
    doc.saveas(path)
    sub = read_submission(path)
    texts = {t.text: t for t in sub.texts}
    assert set(texts) == {"b", "c′", "nCB"}
    # rotated 90°: the box extends up from the insertion point, as wide as the sheet font's "b"
    half = text_width_mm("b", 2.0) / 2
    assert 0.3 < half < 1.0
    assert texts["b"].centre == pytest.approx((10 - 1.0, 10 + half), abs=1e-6)
    assert texts["c′"].centre == pytest.approx((20, 20), abs=1e-6)
    assert texts["nCB"].centre == pytest.approx((30, 30), abs=1e-6)
    assert texts["b"].distance((10 - 0.5, 10 + 0.5)) == 0.0


def test_different_writer_styles_read_alike(tmp_path, four_bar) -> None:
    scene, sol = four_bar
    for style in ("text", "rotated", "mtext", "mixed"):
        st = exact_sheet(sol, SPECS)
        path = write_dxf(tmp_path / f"{style}.dxf", sol, SPECS, st, style=style, arrows=True,
                         polylines=True)
        report = check(scene, path, Options(at_deg=60))
        assert report.passed, (style, report.text())
        assert sum(len(p.segments) for p in report.plans) >= 11


def test_blocks_units_and_markers(tmp_path, four_bar) -> None:
    """Labels inside a block, a drawing in centimetres, points marked with small circles."""
    scene, sol = four_bar
    st = exact_sheet(sol, {V: SPECS[V]})
    doc = ezdxf.new()
    doc.header["$INSUNITS"] = 5          # centimetres
    msp = doc.modelspace()
    blk = doc.blocks.new("LABELS")
    for (plan, label), at in st.points.items():
        blk.add_text(label, dxfattribs={"height": 0.25}).set_placement(
            (at[0] / 10 + 0.09, at[1] / 10 + 0.09))
        msp.add_circle((at[0] / 10, at[1] / 10), 0.05)
    for a, b in (("p", "b"), ("b", "c"), ("p", "c"), ("p", "e")):
        msp.add_line(tuple(st.points[(V, a)] / 10), tuple(st.points[(V, b)] / 10))
    msp.add_blockref("LABELS", (0, 0))
    msp.add_mtext(r"\A1;μv = 0,01 m/s/mm\Pφ = 60°", dxfattribs={"char_height": 0.3,
                                                                 "insert": (0, -5)})
    path = tmp_path / "cm.dxf"
    doc.saveas(path)
    report = check(scene, path, Options())
    assert report.passed, report.text()
    assert report.units.startswith("centimetres")
    assert report.phi_deg == pytest.approx(60.0)
    pc = next(s for s in report.plans[0].segments if s.name == "pc")
    assert pc.submitted_mm == pytest.approx(pc.exact_mm, abs=1e-6)


def test_several_plans_grouped_by_their_labels(tmp_path, four_bar) -> None:
    """Velocity, acceleration and position plans on one sheet, no layers, no scale texts near:
    the labels alone say which is which."""
    scene, sol = four_bar
    specs = {V: PlanSpec(0.01, (50, 50), None), A: PlanSpec(0.1, (250, 60), None),
             P: PlanSpec(0.002, (100, 250), None)}
    st = exact_sheet(sol, specs)
    path = write_dxf(tmp_path / "three.dxf", sol, specs, st)
    doc = ezdxf.readfile(path)
    for e in doc.modelspace().query("LINE"):
        e.dxf.layer = "0"
    doc.saveas(path)
    report = check(scene, path, Options(at_deg=60))
    assert sorted(p.plan for p in report.plans) == ["acceleration", "position", "velocity"]
    assert report.passed


def test_no_labels_is_unusable(tmp_path) -> None:
    scene, _ = solved("four_bar", 60)
    doc = ezdxf.new()
    doc.modelspace().add_line((0, 0), (10, 10))
    doc.modelspace().add_text("Velocity plan").set_placement((0, -10))
    path = tmp_path / "nolabels.dxf"
    doc.saveas(path)
    with pytest.raises(CheckError, match="no point labels") as exc:
        check(scene, path, Options(at_deg=60))
    assert "nolabels.dxf" in str(exc.value) and "TEXT or MTEXT" in str(exc.value)


def test_empty_dxf_is_unusable(tmp_path) -> None:
    scene, _ = solved("four_bar", 60)
    path = tmp_path / "empty.dxf"
    ezdxf.new().saveas(path)
    with pytest.raises(CheckError, match="no lines and no texts"):
        check(scene, path, Options(at_deg=60))


@pytest.mark.parametrize("content", [b"", b"this is not a drawing\n", b"\x00\x01\x02" * 50,
                                     b"0\nSECTION\n2\nENTITIES\n0\nLINE\n10\nabc\n"])
def test_garbage_is_unusable(tmp_path, content: bytes) -> None:
    scene, _ = solved("four_bar", 60)
    path = tmp_path / "bad.dxf"
    path.write_bytes(content)
    with pytest.raises(CheckError) as exc:
        check(scene, path, Options(at_deg=60))
    assert "bad.dxf" in str(exc.value)


def test_truncated_dxf_gives_a_partial_report_or_a_clear_error(tmp_path, four_bar) -> None:
    scene, sol = four_bar
    st = exact_sheet(sol, SPECS)
    full = write_dxf(tmp_path / "full.dxf", sol, SPECS, st).read_bytes()
    for fraction in (0.3, 0.6, 0.8, 0.95):
        path = tmp_path / f"cut{fraction}.dxf"
        path.write_bytes(full[: int(len(full) * fraction)])
        try:
            report = check(scene, path, Options(at_deg=60))
        except CheckError as exc:
            assert "cut" in str(exc)
            continue
        # what could be read is checked, and nothing read is reported wrong
        assert report.passed, report.text()


def test_duplicate_and_far_labels(tmp_path, four_bar) -> None:
    scene, sol = four_bar
    st = exact_sheet(sol, SPECS)
    path = write_dxf(tmp_path / "dup.dxf", sol, SPECS, st)
    doc = ezdxf.readfile(path)
    msp = doc.modelspace()
    b = st.points[(V, "b")]
    e = st.points[(V, "e")]
    msp.add_text("c", dxfattribs={"height": 2.5}).set_placement((b[0] + 0.8, b[1] - 3.0))
    msp.add_text("e′", dxfattribs={"height": 2.5}).set_placement((400, 400))   # far from lines
    msp.add_text("q", dxfattribs={"height": 2.5}).set_placement((e[0] + 0.5, e[1] + 0.5))
    doc.saveas(path)
    report = check(scene, path, Options(at_deg=60))
    errors = " ".join(_levels(report, "error"))
    warnings = " ".join(_levels(report, "warning"))
    assert "label 'c' appears 2 times" in errors
    assert "'e′' is" in warnings and "--label-distance" in warnings
    assert any("'q' is not a label" in m for m in _levels(report, "info"))
    vel = next(p for p in report.plans if p.plan == "velocity")
    rows = {s.name: s.verdict for s in vel.segments}
    assert rows["pb"] == OK and rows["pe"] == OK
    assert rows["pc"] == "missing" and rows["bc"] == "missing"
    assert report.passed        # what is left is right


def test_missing_scale_and_no_driving_vector(tmp_path, four_bar) -> None:
    """Without μ and without a labelled segment, lengths cannot be checked: a clear note."""
    scene, sol = four_bar
    specs = {V: PlanSpec(0.01, (50, 50), None)}
    st = exact_sheet(sol, specs)
    path = write_dxf(tmp_path / "nomu.dxf", sol, specs, st,
                     skip_labels={(V, "b"), (V, "p"), (V, "c")})
    report = check(scene, path, Options(at_deg=60))
    assert any("no scale factor for the velocity plan" in m for m in _levels(report, "error"))
    assert all(s.verdict != "wrong" for s in report.plans[0].segments)


def test_metres_in_the_header_but_millimetres_on_the_sheet(tmp_path, four_bar) -> None:
    scene, sol = four_bar
    st = exact_sheet(sol, SPECS)
    path = write_dxf(tmp_path / "m.dxf", sol, SPECS, st, units=6)
    report = check(scene, path, Options(at_deg=60))
    assert report.passed
    assert any("read in millimetres" in m for m in _levels(report, "warning"))


def test_unreadable_scale_text_falls_back(tmp_path, four_bar) -> None:
    scene, sol = four_bar
    specs = {V: PlanSpec(0.01, (50, 50), "μv = 0,01 N/mm")}      # a force unit
    st = exact_sheet(sol, specs)
    path = write_dxf(tmp_path / "badmu.dxf", sol, specs, st)
    report = check(scene, path, Options(at_deg=60))
    assert report.passed
    assert any("μv = 0,01 N/mm" in m and "cannot be used" in m
               for m in _levels(report, "warning"))
    assert "inferred from pb" in report.plans[0].mu_source


def test_label_distance_is_reported_and_settable(tmp_path, four_bar) -> None:
    scene, sol = four_bar
    st = exact_sheet(sol, {V: SPECS[V]})
    path = write_dxf(tmp_path / "off.dxf", sol, {V: SPECS[V]}, st, label_offset=(3.0, 3.0))
    with pytest.raises(CheckError, match="within 1.0 mm") as exc:
        check(scene, path, Options(at_deg=60, label_distance=1.0))
    assert "--label-distance" in str(exc.value) and "'b'" in str(exc.value)
    far = check(scene, path, Options(at_deg=60))
    assert far.passed and far.label_distance_mm == pytest.approx(5.0)
    mixed = write_dxf(tmp_path / "mixed.dxf", sol, {V: SPECS[V]}, st, label_offset=(0.5, 0.5))
    doc = ezdxf.readfile(mixed)
    e = st.points[(V, "e")]
    for t in doc.modelspace().query("TEXT"):
        if t.dxf.text == "e":
            t.set_placement((e[0] + 4.0, e[1] + 4.0))
    doc.saveas(mixed)
    near = check(scene, mixed, Options(at_deg=60, label_distance=2.0))
    assert any("'e' is" in m and "more than the 2.0 mm allowed" in m
               for m in _levels(near, "warning"))
    assert next(s for s in near.plans[0].segments if s.name == "pe").verdict == "missing"


def test_unlabelled_pole_is_inferred(tmp_path, four_bar) -> None:
    scene, sol = four_bar
    st = exact_sheet(sol, {V: SPECS[V]})
    path = write_dxf(tmp_path / "nopole.dxf", sol, {V: SPECS[V]}, st, skip_labels={(V, "p")})
    report = check(scene, path, Options(at_deg=60))
    assert report.passed
    assert any("pole p" in m and "not labelled" in m for m in _levels(report, "info"))
    assert all(s.verdict in (OK, REFERENCE) for s in report.plans[0].segments)


def test_label_at_a_crossing_of_two_lines(tmp_path, four_bar) -> None:
    """A student who draws the two construction lines through c past their crossing."""
    scene, sol = four_bar
    st = exact_sheet(sol, {V: SPECS[V]})
    doc = ezdxf.new()
    msp = doc.modelspace()
    pts = {k[1]: v for k, v in st.points.items()}
    c = pts["c"]
    for a, b in (("p", "b"), ("p", "e"), ("b", "e")):
        msp.add_line(tuple(pts[a]), tuple(pts[b]))
    for a in ("b", "p"):      # through b ⊥ BC and through p ⊥ DC, both past c
        d = c - pts[a]
        msp.add_line(tuple(pts[a]), tuple(c + 0.3 * d))
    for label, at in pts.items():
        msp.add_text(label, dxfattribs={"height": 2.5}).set_placement(
            (at[0] + 0.8, at[1] + 0.8))
    msp.add_text("μv = 0.01").set_placement((0, 0))
    doc.header["$INSUNITS"] = 4
    path = tmp_path / "cross.dxf"
    doc.saveas(path)
    report = check(scene, path, Options(at_deg=60))
    assert report.passed, report.text()
    c_row = next(p for p in report.plans[0].points if p.label == "c")
    assert c_row.found == "crossing of two lines"
    assert np.allclose(c_row.at_mm, c, atol=1e-6)


def test_a_leader_takes_the_label_it_points_into(tmp_path) -> None:
    """Two labels near a short leader's end: the one the leader runs toward is tied to its start
    (the other is nearer the end, beside the leader's line)."""
    doc = ezdxf.new()
    doc.header["$INSUNITS"] = 4
    doc.layers.add("DIMENSION")
    msp = doc.modelspace()
    msp.add_line((0, 0), (0, 3.5), dxfattribs={"layer": "DIMENSION"})
    mid = ezdxf.enums.TextEntityAlignment.MIDDLE_CENTER
    msp.add_text("b", dxfattribs={"height": 3.5}).set_placement((-2.0, 4.2), align=mid)
    msp.add_text("s4", dxfattribs={"height": 3.5}).set_placement((1.6, 6.3), align=mid)
    msp.add_line((0, 0), (30, 0))
    doc.saveas(tmp_path / "x.dxf")
    sub = read_submission(tmp_path / "x.dxf")
    at = {t.text: t.centre for t in sub.texts}
    assert at["s4"] == pytest.approx((0.0, 0.0))
    assert at["b"] == pytest.approx((-2.0, 4.2))


@pytest.mark.parametrize(("text", "angles"), [
    ("位置 11，φ = 1.0°", {1.0}), ("Position 1, φ = 61.0°", {61.0}), ("phi1 = 30 deg", {30.0}),
    ("Vị trí 2, φ = 30,5°", {30.5}), ("μφ = 4 °/mm", set()), ("ψ(φ)", set()),
    ("φ = 360°", {0.0})])
def test_crank_angles_written_in_titles(text, angles) -> None:
    from mechplan.check.positions import written_angles
    from mechplan.submission.read import SheetText

    assert written_angles([SheetText(text, (0.0, 0.0), 3.5, "")]) == angles
