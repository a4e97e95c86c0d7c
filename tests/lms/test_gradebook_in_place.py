"""Canvas's exported gradebook filled in place: only the assignment's cells of the students
matched change; every other byte (columns, rows, "Points Possible", quoting, BOM, CRLF) stays."""

from __future__ import annotations

import pytest

from mechplan.errors import CheckError
from mechplan.lms import round_trip
from mechplan.lms.gradebook import Graded, assignment_column, fill_gradebook, read_gradebook, scan

# as Canvas exports it (Grades → Export): a BOM, CRLF, names quoted, read-only totals, a test
# student, another assignment before ours and the totals after; {ivan} / {binh} mark our cells
EXPORT = ("\ufeffStudent,ID,SIS User ID,SIS Login ID,Section,Homework 1 (1001),"
          "Course project (777),Current Points,Final Points,Current Score,Final Score\r\n"
          "    Points Possible,,,,,10.00,{possible},(read only),(read only),(read only),"
          "(read only)\r\n"
          "\"Petrov, Ivan\",5001,s101,ivanp,TMM-1,8.00,{ivan},8.00,8.00,80.00,40.00\r\n"
          "\"Nguyen, Binh\",5002,s102,binhn,TMM-1,9,{binh},9.00,9.00,90.00,45.00\r\n"
          "\"White, Carol\",5003,s103,carolw,\"TMM-1, lab \"\"B\"\"\",7.5,5.00,12.5,12.5,"
          "62.50,62.50\r\n"
          "\"Student, Test\",9999,,,TMM-1,,,0.00,0.00,,\r\n")
ROSTER = ("Student,ID,SIS User ID,SIS Login ID,Section,variant\n"
          "\"Petrov, Ivan\",5001,s101,ivanp,TMM-1,v1\n\"Nguyen, Binh\",5002,s102,binhn,TMM-1,v1\n"
          "\"White, Carol\",5003,s103,carolw,TMM-1,v2\n")


def _download(tmp_path, small_class):
    _, variants, v = small_class
    sub = tmp_path / "submissions"
    sub.mkdir()
    (sub / "ivanp_5001_90001_sheet.dxf").write_bytes(
        (variants / "v1" / "slider_crank.dxf").read_bytes())
    # 5 values, v_B 30 % off: one new mistake of five
    rows = [("VA", v["v_A"], "m/s"), ("VB", v["v_B"] * 1.3, "m/s"), ("VS2", v["v_S2"], "m/s"),
            ("w2", v["ω2"], "rad/s"), ("aB", v["a_B"], "m/s²")]
    (sub / "late_binhn_5002_90002_answers.csv").write_text(
        "φ,30°\n" + "".join(f"{n},{x!r} {u}\n" for n, x, u in rows), encoding="utf-8")
    (sub / "zed_5009_90009_sheet.dxf").write_bytes(
        (variants / "v1" / "slider_crank.dxf").read_bytes())
    roster = tmp_path / "roster.csv"
    roster.write_text(ROSTER + "zed,5009,s109,zed,TMM-2,v1\n", encoding="utf-8")
    return variants, sub, roster


@pytest.mark.parametrize("possible, max_grade, ivan, binh", [
    ("10.00", 10, "10", "8"),                # the rule's scale is the assignment's
    ("10.00", 100, "10", "8"),               # scaled to Points Possible, and said so
])
def test_only_the_assignment_cells_change(small_class, tmp_path, possible, max_grade, ivan,
                                          binh):
    variants, sub, roster = _download(tmp_path, small_class)
    before = EXPORT.format(possible=possible, ivan="", binh="7.00")
    book = tmp_path / "Grades-TMM.csv"
    book.write_bytes(before.encode("utf-8"))
    rule = tmp_path / "rule.toml"
    rule.write_text(f'max_grade = {max_grade}\n[canvas]\nassignment = "Course project"\n'
                    'assignment_id = "777"\n', encoding="utf-8")
    done = round_trip(variants, sub, tmp_path / "out", roster=roster, rule=rule, gradebook=book)
    after = (tmp_path / "out" / "canvas_gradebook.csv").read_bytes()
    # the expected file is the export itself with the two cells written — byte for byte
    assert after == EXPORT.format(possible=possible, ivan=ivan, binh=binh).encode("utf-8")
    problems = [(p.who, p.problem) for p in done.problems]
    assert any(w.startswith("zed") and "not in the Canvas gradebook" in p for w, p in problems)
    assert any("scaled" in p for _, p in problems) == (max_grade != 10)


def test_the_column_is_found_or_the_columns_are_named(tmp_path):
    path = tmp_path / "g.csv"
    path.write_text(EXPORT.format(possible="10", ivan="", binh=""), encoding="utf-8")
    book = read_gradebook(path)
    assert assignment_column(book, "Course project", "777") == 6
    assert assignment_column(book, "Course project", "") == 6        # by name alone
    assert assignment_column(book, "Homework 1", "") == 5
    with pytest.raises(CheckError, match=r"Lab 3 \(42\).*Homework 1 \(1001\)"):
        assignment_column(book, "Lab 3", "42")
    bad = tmp_path / "bad.csv"
    bad.write_text("name,grade\nx,1\n", encoding="utf-8")
    with pytest.raises(CheckError, match="not a Canvas gradebook"):
        read_gradebook(bad)


def test_scan_keeps_every_field_where_it_stands():
    text = 'a,"b,1","c ""q""",\r\n"multi\nline",x,,"",\n'
    records = scan(text)
    assert [r.cells for r in records] == [["a", "b,1", 'c "q"', ""],
                                          ["multi\nline", "x", "", "", ""]]
    assert all(text[s:e] in (c, f'"{c}"', '"' + c.replace('"', '""') + '"')
               for r in records for c, (s, e) in zip(r.cells, r.spans, strict=True))


def test_a_grade_without_a_row_or_a_value_leaves_the_file_alone(tmp_path):
    path = tmp_path / "g.csv"
    raw = EXPORT.format(possible="10", ivan="3", binh="4").replace("\r\n", "\n").lstrip("\ufeff")
    path.write_bytes(raw.encode("cp1251", errors="replace"))
    book = read_gradebook(path)
    data, missing, _ = fill_gradebook(
        book, [Graded("nobody", 5.0, ids=("1",)), Graded("Ivan", None, ids=("5001",)),
               Graded("Binh by name", 6.0, names=("Binh Nguyen",))], 6, 10, 1)
    assert missing == ["nobody"]
    assert data == raw.replace(",4,9.00", ",6,9.00").encode("cp1251", errors="replace")


def test_a_worksheet_without_a_bom_comes_back_without_one(tmp_path):
    from mechplan.lms.sheets import MOODLE_COLUMNS, Filled, fill_worksheet, read_worksheet

    text = (",".join(f'"{c}"' for c in MOODLE_COLUMNS) + "\n"
            '"Participant 7","Ann Lee","ann@x.org","","","100.00","Yes","","-",""\n')
    path = tmp_path / "ws.csv"
    path.write_bytes(text.encode("utf-8"))
    data, missing = fill_worksheet(read_worksheet(path), [Filled("7", "Ann Lee", "", 90.0, "ok")],
                                   100, 1)
    assert not missing and data == text.replace('"Yes","","-",""', '"Yes","","-","ok"').replace(
        '"100.00","Yes"', '"100.00","Yes"').replace('"","100.00"', '"90","100.00"').encode()


def test_the_command_line_fills_the_gradebook(small_class, tmp_path, capsys):
    from mechplan.cli import main

    variants, sub, roster = _download(tmp_path, small_class)
    book = tmp_path / "export.csv"
    book.write_bytes(EXPORT.format(possible="10.00", ivan="", binh="").encode("utf-8"))
    rule = tmp_path / "rule.toml"
    rule.write_text('max_grade = 10\n[canvas]\nassignment_id = "777"\n', encoding="utf-8")
    out = tmp_path / "graded"
    main(["check", str(variants), str(sub), "-o", str(out), "--roster", str(roster),
          "--gradebook", str(book), "--rule", str(rule)])
    assert (out / "canvas_gradebook.csv").read_bytes() == EXPORT.format(
        possible="10.00", ivan="10", binh="8").encode("utf-8")
    assert "not in the Canvas gradebook" in capsys.readouterr().out
