"""The LMS round trip on a synthetic class: variants by ``mechplan batch``, a Moodle download and
a Canvas download with planted mistakes, graded by the rule, written back in the LMS formats."""

from __future__ import annotations

import csv
import io
import json
import math
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

import ezdxf
import pytest
from check.sheets import PlanSpec, exact_sheet, move, write_dxf
from ezdxf.math import Matrix44

from mechplan.batch import Variant, run_class
from mechplan.check import Options, check
from mechplan.check.report import CARRIED, MISSING, NEW, OK, REFERENCE, SLIP, WRONG
from mechplan.cli import main
from mechplan.lms import round_trip
from mechplan.lms.sheets import MOODLE_COLUMNS
from mechplan.model.plans import Plan
from mechplan.scene import load_scene
from mechplan.solve import solve

TEMPLATES = Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates"
CLASS = [Variant("v1", "", {"links.1.lengths.OA": "90 mm"}),
         Variant("v2", "", {"links.1.lengths.OA": "100 mm"}),
         Variant("v3", "", {"links.1.lengths.OA": "110 mm"})]
V = Plan.VELOCITY
PHI = 30.0
# the instructor's worksheet as Moodle exports it (with a BOM, CRLF line ends, all quoted)
WORKSHEET = ('\ufeff' + ",".join(f'"{c}"' for c in MOODLE_COLUMNS) + "\r\n" + "".join(
    f'"Participant {pid}","{name}","{mail}","Submitted for grading","","100.00","Yes",'
    f'"Monday, 2 March 2026, 10:00 AM","-",""\r\n' for pid, name, mail in (
        ("101", "Иван Петров", "ivan@uni.ru"), ("102", "Nguyễn Văn Bình", "binh@uni.vn"),
        ("103", "Trần Thị Cúc", "cuc@uni.vn"), ("104", "Anna Smith", "anna@uni.edu"),
        ("105", "Bob Jones", "bob@uni.edu"), ("107", "Lê Thị Đào", "dao@uni.vn"))))
ROSTER = ("First name,Last name,ID number,Email address,variant\n"
          "Иван,Петров,s101,ivan@uni.ru,v1\nVăn Bình,Nguyễn,s102,binh@uni.vn,v2\n"
          "Thị Cúc,Trần,s103,cuc@uni.vn,v3\nAnna,Smith,s104,anna@uni.edu,v1\n"
          "Bob,Jones,s105,bob@uni.edu,v2\nCarol,White,s107,carol@uni.edu,v3\n"
          "Thị Đào,Lê,s108,dao@uni.vn,v3\n")


def _velocity_sheet(scene_file: Path, path: Path, mutate=None) -> Path:
    """The velocity plan at φ = 30° drawn by an independent writer (tests/check/sheets.py)."""
    scene = load_scene(scene_file)
    sol = solve(scene, at_deg=[PHI], plans=("position", "velocity", "acceleration"))
    mu = sol.scales[V]
    specs = {V: PlanSpec(mu, (80.0, 80.0), f"μv = {mu:g} m/s/mm")}
    st = exact_sheet(sol, specs)
    if mutate:
        mutate(st)
    return write_dxf(path, sol, specs, st, style="text")


def _moved_rotated(src: Path, dst: Path) -> Path:
    """A copy of a drawing turned by 30°, moved and scaled 1.25× (as a copier would)."""
    doc = ezdxf.readfile(src)
    m = Matrix44.chain(Matrix44.scale(1.25), Matrix44.z_rotate(math.radians(30)),
                       Matrix44.translate(37, -12, 0))
    for e in doc.modelspace():
        e.transform(m)
    doc.saveas(dst)
    return dst


def _zip(files: dict[str, bytes]) -> bytes:
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zf:
        for name, data in files.items():
            zf.writestr(name, data)
    return buf.getvalue()


def _graded_by_hand(report, max_grade=100.0, carried=0.25, slip=0.5) -> float:
    """The default rule computed here: each checked or missing row 1 point; new −1, carried
    −0.25, swapped −0.5, accumulated −0.25, slip −0.5, missing −1."""
    rows = [r for r in report.rows if r.verdict in (OK, REFERENCE, WRONG, SLIP, MISSING)]
    cost = {NEW: 1.0, CARRIED: carried, "swapped": 0.5, "accumulated": 0.25}
    lost = sum(cost.get(r.cause or NEW, 1.0) if r.verdict == WRONG else
               slip if r.verdict == SLIP else 1.0 if r.verdict == MISSING else 0.0 for r in rows)
    return round(max_grade * (len(rows) - lost) / len(rows), 1)


@pytest.fixture(scope="module")
def klass(tmp_path_factory):
    root = tmp_path_factory.mktemp("lms")
    variants = root / "class"
    run_class(TEMPLATES / "slider_crank.toml", CLASS, variants, formats=("dxf",), workers=1,
              progress=False)
    own = variants / "v1" / "slider_crank.dxf"          # mechplan's own sheet of variant 1
    wrong = _velocity_sheet(variants / "v2" / "scene.toml", root / "binh.dxf",
                            lambda st: move(st, V, "b", (6.0, 0.0)))
    copied = _moved_rotated(own, root / "cuc.dxf")
    key = json.loads((variants / "v1" / "answer_key.json").read_text(encoding="utf-8"))
    k = key["phi_deg"].index(PHI)
    vals = {r["quantity"]: r["values"][k] for r in key["rows"]}
    table = (f'"φ" = "30°"\n[values]\nVA = "{vals["v_A"]:.6g} m/s"\n'
             f'VB = "{vals["v_B"] * 1.3:.6g} m/s"\n"ω2" = "{vals["ω2"]:.6g} rad/s"\n')
    key3 = json.loads((variants / "v3" / "answer_key.json").read_text(encoding="utf-8"))
    v3 = {r["quantity"]: r["values"][k] for r in key3["rows"]}
    # a CSV table of "name, value" rows in another notation, all right for variant 3
    dao = "φ,30°\n" + "".join(f"{n},{v3[q]:.6g} {u}\n" for n, q, u in (
        ("VA", "v_A", "m/s"), ("VB", "v_B", "m/s"), ("VS2", "v_S2", "m/s"),
        ("w2", "ω2", "rad/s"), ("aB", "a_B", "m/s^2")))
    moodle = {
        "Иван Петров_101_assignsubmission_file_/sheet.dxf": own.read_bytes(),
        "Nguyễn Văn Bình_102_assignsubmission_file_/plan.dxf": wrong.read_bytes(),
        "Nguyễn Văn Bình_102_assignsubmission_file_/note.pdf": b"%PDF-1.4 not a drawing",
        "Trần Thị Cúc_103_assignsubmission_file_/extra.zip": _zip({"in/cuc.dxf":
                                                                    copied.read_bytes()}),
        "Anna Smith_104_assignsubmission_file_/answers.toml": table.encode(),
        "Bob Jones_105_assignsubmission_file_/broken.dxf": b"0\nSECTION\n2\nENTITIES\ngarbage",
        "Dave Stranger_106_assignsubmission_file_/dave.dxf": own.read_bytes(),
        # Moodle without "Download submissions in folders": flat names
        "Lê Thị Đào_107_assignsubmission_file_bảng.csv": dao.encode(),
    }
    download = root / "moodle.zip"
    download.write_bytes(_zip(moodle))
    (root / "worksheet.csv").write_bytes(WORKSHEET.encode("utf-8"))
    (root / "roster.csv").write_text(ROSTER, encoding="utf-8")
    out = root / "graded"
    done = round_trip(variants, download, out, roster=root / "roster.csv",
                      worksheet=root / "worksheet.csv")
    return root, variants, done, {"own": own, "wrong": wrong, "table": table}


def _worksheet(out: Path) -> list[list[str]]:
    return list(csv.reader(io.StringIO(out.joinpath("grading_worksheet.csv").read_bytes()
                                       .decode("utf-8-sig"), newline="")))


def test_worksheet_grades_by_the_rule(klass):
    _root, variants, done, files = klass
    rows = {r[0]: r for r in _worksheet(done.out)[1:]}
    g = MOODLE_COLUMNS.index("Grade")
    c = MOODLE_COLUMNS.index("Feedback comments")
    assert rows["Participant 101"][g] == "100"                 # own sheet, everything right
    assert rows["Participant 107"][g] == "100"                 # a right table, flat layout
    assert "bảng.csv: 5 of 5 right" in rows["Participant 107"][c]
    # the wrong point b: graded as the rule says from the rows mechplan check finds
    report = check(variants / "v2" / "scene.toml", files["wrong"], Options())
    assert any(r.verdict == WRONG and r.cause == NEW for r in report.rows)
    expected = _graded_by_hand(report)
    assert expected < 100
    assert float(rows["Participant 102"][g]) == pytest.approx(expected)
    assert "new" in rows["Participant 102"][c] and "plan.dxf" in rows["Participant 102"][c]
    # the table: 3 values, v_B 30 % off → one new mistake of three
    assert float(rows["Participant 104"][g]) == pytest.approx(round(100 * 2 / 3, 1))
    # the unreadable file: no grade, the reason in the comment and in problems.csv
    assert rows["Participant 105"][g] == ""
    assert "broken.dxf" in rows["Participant 105"][c]
    # Dave is not in the worksheet (nor on the roster): never written in, listed
    assert "Participant 106" not in rows
    problems = (done.out / "problems.csv").read_text(encoding="utf-8")
    assert ".submissions" not in problems and "00_" not in problems   # the student's names
    assert "Maximum Grade" not in problems                    # the rule's 100 is the worksheet's
    for who, what in (("Dave Stranger", "not on the roster"), ("Dave Stranger", ("not in the "
                      "grading worksheet")), ("Carol White", "handed in nothing"),
                      ("Bob Jones", "broken.dxf"), ("Nguyễn Văn Bình", "note.pdf")):
        assert any(who in line and what in line for line in problems.splitlines()), (who, what)


def test_worksheet_imports_back_as_moodle_wrote_it(klass):
    _root, _, done, _ = klass
    raw = done.out.joinpath("grading_worksheet.csv").read_bytes()
    assert raw.startswith(b"\xef\xbb\xbf")                      # same encoding (BOM kept)
    assert raw.count(b"\r\n") == 7 and raw.replace(b"\r\n", b"").count(b"\n") == 0
    before = list(csv.reader(io.StringIO(WORKSHEET.lstrip("\ufeff"), newline="")))
    after = _worksheet(done.out)
    assert after[0] == list(MOODLE_COLUMNS) == before[0]
    assert [r[0] for r in after] == [r[0] for r in before]    # same identifiers, same order
    changed = {MOODLE_COLUMNS[i] for b, a in zip(before[1:], after[1:], strict=True)
               for i in range(len(b)) if a[i] != b[i]}
    assert changed <= {"Grade", "Feedback comments"}


def test_feedback_zip_layout(klass):
    _, _, done, _ = klass
    with zipfile.ZipFile(done.out / "feedback_files.zip") as zf:
        names = set(zf.namelist())
        report = zf.read("Иван Петров_101_assignsubmission_file_/sheet_report.txt").decode()
        pdf = zf.read("Nguyễn Văn Bình_102_assignsubmission_file_/plan_overlay.pdf")
    assert pdf.startswith(b"%PDF")
    assert "Иван Петров_101_assignsubmission_file_/sheet_overlay.dxf" in names
    assert "Nguyễn Văn Bình_102_assignsubmission_file_/plan_overlay.dxf" in names
    assert "Anna Smith_104_assignsubmission_file_/answers_report.txt" in names
    assert all(n.count("/") == 1 and n.split("/")[0].endswith("_assignsubmission_file_")
               for n in names)
    assert "PASSED" in report


def test_same_work_names_the_copied_pair(klass):
    _, _, done, _ = klass
    pairs = {(frozenset((s.first, s.second)), s.evidence) for s in done.same}
    assert (frozenset(("Иван Петров (101)", "Trần Thị Cúc (103)")), "same geometry") in pairs
    assert (frozenset(("Иван Петров (101)", "Dave Stranger (106)")), "identical file") in pairs
    assert not any("Nguyễn" in s.first + s.second for s in done.same)
    # the copy of variant 1 handed in for variant 3 fits variant 1 better than its own
    fits = [s for s in done.same if s.evidence == "fits another variant"]
    assert any(s.first == "Trần Thị Cúc (103)" and s.second == "v1" for s in fits), fits
    text = (done.out / "same_work.csv").read_text(encoding="utf-8")
    assert "Trần Thị Cúc (103)" in text


def test_moodle_quiz_one_question_per_value(klass):
    _, variants, done, _ = klass
    root = ET.parse(done.out / "quiz_moodle.xml").getroot()
    assert root.tag == "quiz"
    cats = [q for q in root if q.get("type") == "category"]
    nums = [q for q in root if q.get("type") == "numerical"]
    keys = {r.p.id: r.variant for r in done.results if r.variant}
    assert len(cats) == len(keys)
    expected = 0
    for vid in keys.values():
        key = json.loads((variants / vid / "answer_key.json").read_text(encoding="utf-8"))
        expected += sum(1 for r in key["rows"] for x in r["values"] if x is not None)
    assert len(nums) == expected
    key = json.loads((variants / "v1" / "answer_key.json").read_text(encoding="utf-8"))
    vb = next(r for r in key["rows"] if r["quantity"] == "v_B")["values"][1]
    q = next(q for q in nums if q.findtext("name/text") == "v1 v_B φ=30°")
    assert float(q.findtext("answer/text")) == pytest.approx(vb, rel=1e-5)
    assert float(q.findtext("answer/tolerance")) == pytest.approx(0.02 * vb, rel=1e-2)
    assert q.find("answer").get("fraction") == "100"


def test_canvas_download_and_gradebook(klass, tmp_path):
    _root, variants, _, files = klass
    download = tmp_path / "submissions"
    download.mkdir()
    (download / "ivanp_5001_90001_sheet.dxf").write_bytes(files["own"].read_bytes())
    (download / "late_binhn_5002_90002_plan.dxf").write_bytes(files["wrong"].read_bytes())
    (download / "stray.txt").write_text("whose?", encoding="utf-8")
    roster = tmp_path / "canvas.csv"
    roster.write_text("Student,ID,SIS User ID,SIS Login ID,Section,variant\n"
                      "\"Petrov, Ivan\",5001,s101,ivanp,TMM-1,v1\n"
                      "\"Nguyen, Binh\",5002,s102,binhn,TMM-1,v2\n", encoding="utf-8")
    rule = tmp_path / "rule.toml"
    rule.write_text('max_grade = 10\n[penalty]\ncarried = 0\n[canvas]\nassignment = '
                    '"Course project"\nassignment_id = "777"\n', encoding="utf-8")
    out = download / "graded"              # inside the download: never read as submissions
    round_trip(variants, download, out, roster=roster, rule=rule)
    done = round_trip(variants, download, out, roster=roster, rule=rule)
    assert len(done.results) == 2 and not any("graded" in p.file for p in done.problems)
    table = list(csv.reader((out / "canvas_gradebook.csv").open(encoding="utf-8")))
    assert table[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section",
                        "Course project (777)"]
    assert table[1][0].strip() == "Points Possible" and table[1][5] == "10"
    rows = {r[1]: r for r in table[2:]}
    assert rows["5001"][:5] == ["Petrov, Ivan", "5001", "s101", "ivanp", "TMM-1"]
    assert rows["5001"][5] == "10"
    report = check(variants / "v2" / "scene.toml", files["wrong"], Options())
    assert float(rows["5002"][5]) == pytest.approx(_graded_by_hand(report, 10.0, carried=0.0))
    assert next(r for r in done.results if r.p.id == "5002").p.late
    assert any("stray.txt" in p.file for p in done.problems)


def test_cli_round_trip_and_resume(klass, capsys):
    root, variants, done, _ = klass
    out = done.out
    stamp = {p: p.stat().st_mtime_ns for p in (out / "reports").rglob("*.txt")}
    code = main(["check", str(variants), str(root / "moodle.zip"), "-o", str(out),
                 "--roster", str(root / "roster.csv"), "--worksheet", str(root / "worksheet.csv")])
    said = capsys.readouterr().out
    assert code == 1                       # some students have problems
    assert "Иван Петров (101): variant v1, grade 100" in said
    assert "same work" in said
    # nothing checked again: the reports are the first run's
    assert {p: p.stat().st_mtime_ns for p in (out / "reports").rglob("*.txt")} == stamp


def test_canvas_qti_package(klass):
    _, variants, done, _ = klass
    qti = "{http://www.imsglobal.org/xsd/ims_qtiasiv1p2}"
    with zipfile.ZipFile(done.out / "quiz_canvas_qti.zip") as zf:
        manifest = ET.fromstring(zf.read("imsmanifest.xml"))
        hrefs = [f.get("href") for f in manifest.iter() if f.tag.endswith("}file")]
        tests = {}
        for href in hrefs:
            test = ET.fromstring(zf.read(href)).find(f"{qti}assessment")
            tests[test.get("title")] = test
    assert set(tests) == {"mechplan v1", "mechplan v2", "mechplan v3"}
    for vid, test in tests.items():
        key = json.loads((variants / vid.split()[1] / "answer_key.json").read_text("utf-8"))
        items = list(test.iter(f"{qti}item"))
        assert len(items) == sum(1 for r in key["rows"] for x in r["values"] if x is not None)
    key = json.loads((variants / "v1" / "answer_key.json").read_text(encoding="utf-8"))
    vb = next(r for r in key["rows"] if r["quantity"] == "v_B")["values"][1]
    item = next(i for i in tests["mechplan v1"].iter(f"{qti}item")
                if i.get("title") == "v1 v_B φ=30°")
    kinds = [f.findtext(f"{qti}fieldentry") for f in item.iter(f"{qti}qtimetadatafield")]
    assert "numerical_question" in kinds
    low = float(item.find(f".//{qti}vargte").text)
    high = float(item.find(f".//{qti}varlte").text)
    assert low == pytest.approx(0.98 * vb, rel=1e-5) and high == pytest.approx(1.02 * vb, rel=1e-5)


def test_the_documented_default_rule_is_the_default():
    from mechplan.lms.rule import DEFAULT_RULE

    doc = (Path(__file__).resolve().parents[2] / "docs" / "classes.md").read_text(encoding="utf-8")
    assert DEFAULT_RULE.strip() in doc


def test_a_worksheet_with_another_maximum_is_flagged(klass, tmp_path):
    root, variants, _, _ = klass
    sheet = tmp_path / "ws.csv"
    sheet.write_text(WORKSHEET.replace('"100.00"', '"10.00"'), encoding="utf-8")
    done = round_trip(variants, root / "moodle.zip", tmp_path / "out",
                      roster=root / "roster.csv", worksheet=sheet)
    assert any("Maximum Grade is 10.00" in p.problem for p in done.problems)


def test_same_table_in_another_order(tmp_path):
    from mechplan.lms.samework import fingerprint, same_work
    from mechplan.submission.read import read_submission

    rows = ["φ,30°", "VA,17.3 m/s", "VB,10.7 m/s", "VS2,14 m/s", "w2,-37.8 rad/s", "aB,2738 m/s^2"]
    a, b, c = tmp_path / "a.csv", tmp_path / "b.csv", tmp_path / "c.csv"
    a.write_text("\n".join(rows) + "\n", encoding="utf-8")
    b.write_text("\n".join([rows[0], *reversed(rows[1:])]) + "\n", encoding="utf-8")
    c.write_text("\n".join([*rows[:-1], "aB,2700 m/s^2"]) + "\n", encoding="utf-8")
    prints = [fingerprint(p.stem, p.read_bytes(), read_submission(p)) for p in (a, b, c)]
    assert [(s.first, s.second, s.evidence) for s in same_work(prints)] == [("a", "b",
                                                                            "same table")]


def test_the_round_trips_quizzes_validate_against_their_schemas(klass):
    from mechplan.lms.validate import canvas_package_errors, moodle_quiz_errors

    _, _, done, _ = klass
    assert moodle_quiz_errors((done.out / "quiz_moodle.xml").read_bytes()) == []
    assert canvas_package_errors((done.out / "quiz_canvas_qti.zip").read_bytes()) == []
