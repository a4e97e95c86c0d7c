"""Sheets as AutoCAD and LibreCAD save them: MTEXT formatting codes and \\U+ escapes, labels as
block attributes, DIMENSION entities, any layers, R12 and R2018, a TCVN3 label; a class at once.

The four-bar's velocity plan at φ = 60° is written with plain ezdxf entities (not our renderer)
with planted mistakes: point c moved 3, −4 mm (a new error: pc and bc wrong), e built right from
that wrong c (carried: pe wrong) and a value written as the exact one although the student's own
pc × μv says otherwise (a slip).
"""

from __future__ import annotations

import csv
from pathlib import Path

import ezdxf
import numpy as np
import pytest

from mechplan.batch.check_class import check_class, variant_of
from mechplan.check import Options, check, read_submission
from mechplan.check.report import CARRIED, NEW, OK, REFERENCE, SLIP, WRONG
from mechplan.errors import CheckError
from mechplan.model.plans import Plan

from .sheets import TEMPLATES, PlanSpec, exact_sheet, move, segments, solved, write_dxf

V = Plan.VELOCITY
MU = 0.01
SPEC = {V: PlanSpec(MU, (50, 50))}


@pytest.fixture(scope="module")
def four_bar():
    return solved("four_bar", 60)


def _student(sol, carry: bool = False):
    st = exact_sheet(sol, SPEC)
    move(st, V, "c", (3.0, -4.0))
    if carry:
        # e built right from the student's own wrong c: bce similar to BCE (complex ratio)
        c, ev = sol.construction, sol.ev
        B, C, E = (complex(*ev[c.position(n)][0]) for n in "BCE")
        b, cc = (complex(*st.points[(V, n)]) for n in "bc")
        e = b + (cc - b) * (E - B) / (C - B)
        st.points[(V, "e")] = np.array([e.real, e.imag])
    return st


def _write(path: Path, sol, version: str) -> tuple[Path, float]:
    """The student's velocity plan as AutoCAD writes it; returns the path and the drawn pc."""
    st = _student(sol, carry=True)
    doc = ezdxf.new(version)
    doc.header["$INSUNITS"] = 4
    doc.layers.add("Vantoc")                 # any layer name
    doc.styles.add("VN", font=".VnTime.ttf")
    blk = doc.blocks.new("NHAN")             # a label block with an attribute
    blk.add_attdef("TEN", (0, 0), dxfattribs={"height": 2.5})
    msp = doc.modelspace()
    for a, b in segments(sol, V):
        msp.add_line(tuple(st.points[(V, a)]), tuple(st.points[(V, b)]),
                     dxfattribs={"layer": "Vantoc"})
    for i, ((_plan, label), at) in enumerate(st.points.items()):
        x, y = float(at[0]) + 0.9, float(at[1]) + 0.9
        if i % 2 == 0:
            ref = msp.add_blockref("NHAN", (x, y))
            ref.add_auto_attribs({"TEN": label})
        elif version == "R12":
            msp.add_text(label, dxfattribs={"height": 2.5}).set_placement((x, y))
        else:
            code = "".join(f"\\U+{ord(ch):04X}" if ord(ch) > 127 else ch for ch in label)
            m = msp.add_mtext(r"{\fArial|b0|i1|c0|p34;\H1.0x;" + code + "}",
                              dxfattribs={"char_height": 2.5})
            m.set_location((x, y), attachment_point=7)
    msp.add_text("H\xe4a \xae\xe5 v\xcbn t\xe8c", dxfattribs={"height": 5, "style": "VN"}
                 ).set_placement((40, 110))          # "Họa đồ vận tốc" typed in TCVN3
    pc = st.points[(V, "c")] - st.points[(V, "p")]
    v_c = float(np.hypot(*(sol.ev[sol.construction.velocity_image("C")][0])))
    if version == "R12":
        msp.add_text("mu_v = 0.01 m/s/mm", dxfattribs={"height": 3.5}).set_placement((20, 20))
        msp.add_text(f"v_C = {v_c:.3f} m/s", dxfattribs={"height": 3.5}).set_placement((20, 12))
    else:
        msp.add_mtext(r"{\fArial;\U+03BC\H0.7x;\S^v;\H1.43x; = 0,01 m/s/mm}",
                      dxfattribs={"char_height": 3.5, "insert": (20, 20)})
        msp.add_mtext(f"v\\H0.7x;\\S^C;\\H1.43x; = {v_c:.3f} m/s",
                      dxfattribs={"char_height": 3.5, "insert": (20, 12)})
        p0 = tuple(st.points[(V, "p")])
        p1 = tuple(st.points[(V, "c")])
        dim = msp.add_aligned_dim(p1=p0, p2=p1, distance=12, text="pc = <>",
                                  dxfattribs={"layer": "DIM"})
        dim.render()
    path = path.with_name(f"{path.stem}_{version}.dxf")
    doc.saveas(path)
    return path, float(np.hypot(*pc))


@pytest.mark.parametrize("version", ["R12", "R2018"])
def test_autocad_sheet_with_planted_mistakes(tmp_path: Path, four_bar, version: str) -> None:
    scene, sol = four_bar
    path, pc_mm = _write(tmp_path / "sv", sol, version)
    sub = read_submission(path)
    texts = {t.text for t in sub.texts}
    assert "Họa đồ vận tốc" in texts                        # TCVN3 decoded
    if version == "R2018":
        assert "μv = 0,01 m/s/mm" in texts                  # \U+03BC, \H, \S^v;
        dims = [e for e in sub.entries if e.name == "pc"]   # the dimension's measured value
        assert dims and float(dims[0].text or "nan") == pytest.approx(pc_mm, abs=1e-3)
    report = check(scene, sub, Options(at_deg=60))
    rows = {s.name: (s.verdict, s.cause) for p in report.plans for s in p.segments}
    rows |= {v.name: (v.verdict, v.cause) for v in report.values}
    v_c = "v_C" if version == "R12" else "vC"          # the MTEXT's stacked C reads "vC"
    planted = {"pc": (WRONG, NEW), "bc": (WRONG, NEW), "pe": (WRONG, CARRIED),
               v_c: (SLIP, NEW)}
    for name, got in rows.items():
        if name in planted:
            assert got == planted[name], (name, got, report.text())
        else:
            assert got[0] in (OK, REFERENCE), (name, got, report.text())
    assert set(planted) <= set(rows)
    assert [f.subject for f in report.findings if f.kind == "wrong point"] == ["c"]
    points = {p.label: (p.verdict, p.cause) for pl in report.plans for p in pl.points}
    assert points == {"p": (OK, ""), "b": (OK, ""), "c": (WRONG, NEW), "e": (WRONG, CARRIED)}
    assert any("TCVN3" in n.message for n in report.notes)


def test_vni_text_is_reported_not_guessed(tmp_path: Path) -> None:
    doc = ezdxf.new("R2010")
    doc.styles.add("VNI", font="VNI-Times.ttf")
    msp = doc.modelspace()
    msp.add_line((0, 0), (10, 0))
    msp.add_text("Hoïa ñoà vaän toác", dxfattribs={"style": "VNI"}).set_placement((0, 5))
    doc.saveas(tmp_path / "vni.dxf")
    sub = read_submission(tmp_path / "vni.dxf")
    assert any(n.level == "warning" and "VNI" in n.message for n in sub.notes)


@pytest.mark.parametrize("content, message", [
    (b"hello, this is not a drawing\n", "cannot tell what kind"),
    (b"0\nSECTION\n2\nENTITIES\n0\nLINE\n8\n0\n10\n0.0\n", "truncated"),
])
def test_not_a_dxf_or_truncated(tmp_path: Path, content: bytes, message: str, four_bar) -> None:
    path = tmp_path / "broken.dxf"
    path.write_bytes(content)
    scene, _ = four_bar
    with pytest.raises(CheckError) as err:
        check(scene, path, Options(at_deg=60))
    assert "DXF" in str(err.value) or message in str(err.value)


def test_a_class_at_once(tmp_path: Path, four_bar) -> None:
    _scene, sol = four_bar
    folder = tmp_path / "class"
    folder.mkdir()
    good = exact_sheet(sol, SPEC)
    write_dxf(folder / "an_four_bar.dxf", sol, {V: PlanSpec(MU, (50, 50), "μv = 0,01 m/s/mm")},
              good)
    bad = _student(sol)
    write_dxf(folder / "binh_four_bar.dxf", sol, {V: PlanSpec(MU, (50, 50), "μv = 0,01 m/s/mm")},
              bad)
    (folder / "chi_four_bar.dxf").write_bytes(b"not a drawing")
    (folder / "dung.csv").write_text("pb, 80\n", encoding="utf-8")
    variants = tmp_path / "variants"
    variants.mkdir()
    (variants / "four_bar.toml").write_bytes((TEMPLATES / "four_bar.toml").read_bytes())
    (variants / "slider_crank.toml").write_bytes((TEMPLATES / "slider_crank.toml").read_bytes())
    assert variant_of(folder / "an_four_bar.dxf", sorted(variants.glob("*.toml"))).name == \
        "four_bar.toml"
    out = tmp_path / "out"
    rows = check_class(variants, folder, out, Options(at_deg=60), "vi", jobs=1)
    by = {r["student"]: r for r in rows}
    assert by["an_four_bar"]["passed"] is True and by["an_four_bar"]["wrong"] == 0
    assert by["binh_four_bar"]["passed"] is False and by["binh_four_bar"]["new"] == 2
    assert "DXF" in by["chi_four_bar"]["error"]
    assert "ivanov_v07" in by["dung"]["error"]          # no variant named in "dung.csv"
    table = list(csv.DictReader((out / "summary.csv").open(encoding="utf-8")))
    assert [r["student"] for r in table] == ["an_four_bar", "binh_four_bar", "chi_four_bar",
                                             "dung"]
    assert (out / "binh_four_bar.txt").read_text(encoding="utf-8").count("SAI") >= 2


def test_class_on_the_command_line(tmp_path: Path, four_bar, capsys) -> None:
    from .test_cli_overlay import main

    _scene, sol = four_bar
    folder = tmp_path / "class"
    folder.mkdir()
    spec = {V: PlanSpec(MU, (50, 50), "μv = 0,01 m/s/mm")}
    write_dxf(folder / "an.dxf", sol, spec, exact_sheet(sol, spec))
    write_dxf(folder / "binh.dxf", sol, spec, _student(sol))
    out = tmp_path / "reports"
    assert main(["check", str(TEMPLATES / "four_bar.toml"), str(folder), "--at", "60", "-o",
                 str(out), "--lang", "ru"]) == 1
    said = capsys.readouterr().out
    assert "an (four_bar.toml): ЗАЧТЕНО" in said and "binh (four_bar.toml): НЕ ЗАЧТЕНО" in said
    assert (out / "summary.csv").exists() and (out / "an.json").exists()


def test_errors_are_said_in_the_report_language(tmp_path: Path, capsys) -> None:
    from .test_cli_overlay import main

    path = tmp_path / "empty.dxf"
    path.write_bytes(b"")
    assert main(["check", str(TEMPLATES / "four_bar.toml"), str(path), "--lang", "ru"]) == 2
    assert "файл пуст; ожидается чертёж DXF" in capsys.readouterr().out
