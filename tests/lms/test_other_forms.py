"""Submissions in the other forms an LMS download holds: answer tables as Excel workbooks and
drawings as a PDF with the DXF attached — graded exactly like the same CSV and DXF, within the
limits of every file read inside another."""

from __future__ import annotations

import io
import zipfile
import zlib
from pathlib import Path

import openpyxl
import pytest
from pypdf import PdfWriter

from mechplan.check import Options, check
from mechplan.errors import CheckError
from mechplan.lms import round_trip
from mechplan.submission.read import read_submission


def _rows(v, wrong=1.0):
    """One table in the notations of the CSV tables: an angle row, "name, value, unit" rows
    (numbers as numbers), a "name = value unit" cell, a decimal comma in a text cell."""
    return [["φ", "30°"], ["VA", v["v_A"], "m/s"], [f"VB = {v['v_B'] * wrong!r} m/s"],
            ["w2", v["ω2"], "rad/s"], ["VS2", f"{v['v_S2']!r}".replace(".", ",") + " m/s"],
            ["aB", v["a_B"], "m/s²"]]


def _xlsx(path: Path, rows, sheet_first_empty=False) -> Path:
    book = openpyxl.Workbook()
    sheet = book.active
    if sheet_first_empty:              # an empty active sheet: the first sheet with data is read
        sheet = book.create_sheet("answers")
    for r in rows:
        sheet.append(r)
    book.save(path)
    return path


def _csv(path: Path, rows) -> Path:
    path.write_text("".join(",".join(f'"{c}"' for c in r) + "\n" for r in rows),
                    encoding="utf-8")
    return path


def _verdicts(report):
    return [(r.name if hasattr(r, "name") else "", r.verdict, r.cause) for r in report.rows]


@pytest.mark.parametrize("wrong", [1.0, 1.3])
def test_a_workbook_is_graded_like_the_same_csv(small_class, tmp_path, wrong):
    _, variants, v = small_class
    scene = variants / "v1" / "scene.toml"
    rows = _rows(v, wrong)
    book = check(scene, _xlsx(tmp_path / "t.xlsx", rows), Options())
    table = check(scene, _csv(tmp_path / "t.csv", rows), Options())
    assert book.summary() == table.summary()
    assert _verdicts(book) == _verdicts(table)
    assert book.summary()["checked"] == 5
    assert book.summary()["wrong"] == (0 if wrong == 1.0 else 1)


def test_the_first_sheet_with_data_when_the_active_one_is_empty(small_class, tmp_path):
    _, _variants, v = small_class
    sub = read_submission(_xlsx(tmp_path / "t.xlsx", _rows(v), sheet_first_empty=True))
    assert [e.name for e in sub.entries][:2] == ["φ", "VA"]


def _pdf_with_attachment(dxf: bytes, name="sheet.dxf", extra=()) -> bytes:
    w = PdfWriter()
    w.add_blank_page(595, 842)
    for n, data in extra:
        w.add_attachment(n, data)
    w.add_attachment(name, dxf)
    buf = io.BytesIO()
    w.write(buf)
    return buf.getvalue()


def _pdf_by_hand(stream: bytes, name: str = "sheet.dxf", size: int | None = None,
                 more=()) -> bytes:
    """A PDF written here object by object: one page whose paper-clip annotations
    (``/FileAttachment``) carry the files, deflated, in their file specifications: first
    ``more`` (name, deflated stream, declared size), then ``name``."""
    files = [*more, (name, stream, size)]
    annots = " ".join(f"{4 + 3 * k} 0 R" for k in range(len(files)))
    objects = [
        b"<< /Type /Catalog /Pages 2 0 R >>",
        b"<< /Type /Pages /Kids [3 0 R] /Count 1 >>",
        f"<< /Type /Page /Parent 2 0 R /MediaBox [0 0 595 842] /Annots [{annots}] >>".encode(),
    ]
    for k, (fname, body, declared) in enumerate(files):
        params = f" /Params << /Size {declared} >>" if declared is not None else ""
        objects += [
            f"<< /Type /Annot /Subtype /FileAttachment /Rect [20 20 40 40] /FS {5 + 3 * k} 0 R >>"
            .encode(),
            f"<< /Type /Filespec /F ({fname}) /UF ({fname}) /EF << /F {6 + 3 * k} 0 R >> >>"
            .encode(),
            f"<< /Type /EmbeddedFile /Filter /FlateDecode /Length {len(body)}{params} >>\n"
            .encode() + b"stream\n" + body + b"\nendstream",
        ]
    out = bytearray(b"%PDF-1.7\n")
    offsets = []
    for i, body in enumerate(objects, start=1):
        offsets.append(len(out))
        out += f"{i} 0 obj\n".encode() + body + b"\nendobj\n"
    xref = len(out)
    out += f"xref\n0 {len(objects) + 1}\n0000000000 65535 f \n".encode()
    out += b"".join(f"{o:010d} 00000 n \n".encode() for o in offsets)
    out += (f"trailer\n<< /Size {len(objects) + 1} /Root 1 0 R >>\nstartxref\n{xref}\n%%EOF\n"
            .encode())
    return bytes(out)


def test_a_pdf_with_the_dxf_attached_is_graded_like_the_dxf(small_class, tmp_path):
    _, variants, _ = small_class
    scene = variants / "v1" / "scene.toml"
    dxf = variants / "v1" / "slider_crank.dxf"
    pdf = tmp_path / "sheet.pdf"
    pdf.write_bytes(_pdf_with_attachment(dxf.read_bytes(), "plan.dxf",
                                         extra=[("readme.txt", b"my project")]))
    hand = tmp_path / "hand.pdf"
    hand.write_bytes(_pdf_by_hand(zlib.compress(dxf.read_bytes())))
    direct = check(scene, dxf, Options())
    assert direct.summary()["checked"] > 50
    for got in (check(scene, pdf, Options()), check(scene, hand, Options())):
        assert got.summary() == direct.summary()
        assert _verdicts(got) == _verdicts(direct)
    notes = " ".join(str(n) for n in read_submission(pdf).notes)
    assert "plan.dxf" in notes and "readme.txt" in notes


def test_a_pdf_without_a_dxf_says_what_it_holds(tmp_path):
    pdf = tmp_path / "note.pdf"
    pdf.write_bytes(_pdf_with_attachment(b"just words", "notes.txt"))
    with pytest.raises(CheckError, match="no DXF attached.*notes.txt"):
        read_submission(pdf)
    fake = tmp_path / "fake.pdf"
    fake.write_bytes(b"%PDF-1.4 not a drawing")
    with pytest.raises(CheckError, match="cannot be read"):
        read_submission(fake)


def test_an_attachment_bomb_is_refused_naming_it(tmp_path):
    bomb = zlib.compress(b"0\n" * (36 * 1024**2), 9)        # 72 MB of DXF-ish text, ~70 kB
    for size in (None, 72 * 1024**2):                        # undeclared, declared
        pdf = tmp_path / "bomb.pdf"
        pdf.write_bytes(_pdf_by_hand(bomb, "big.dxf", size))
        with pytest.raises(CheckError, match="big.dxf.*more than 64 MB"):
            read_submission(pdf)


def test_only_the_named_drawing_is_inflated(small_class, tmp_path):
    _, variants, _ = small_class
    dxf = (variants / "v1" / "slider_crank.dxf").read_bytes()
    bomb = zlib.compress(b" " * (72 * 1024**2), 9)              # a 72 MB "notes.txt"
    pdf = tmp_path / "both.pdf"
    pdf.write_bytes(_pdf_by_hand(zlib.compress(dxf), "plan.dxf", more=[("notes.txt", bomb,
                                                                          None)]))
    sub = read_submission(pdf)                  # the notes are listed, never inflated
    assert len(sub.lines) == len(read_submission(variants / "v1" / "slider_crank.dxf").lines)
    assert "notes.txt" in str(sub.notes[0])
    unnamed = tmp_path / "unnamed.pdf"          # no name says DXF: sniffed one by one
    unnamed.write_bytes(_pdf_by_hand(zlib.compress(dxf), "drawing", more=[
        ("readme", zlib.compress(b"hello"), None)]))
    assert read_submission(unnamed).lines


def _workbook_with(part: str, body: bytes, src: Path, dst: Path) -> Path:
    """A copy of a workbook with one part replaced."""
    with zipfile.ZipFile(src) as zin, zipfile.ZipFile(dst, "w", zipfile.ZIP_DEFLATED) as zout:
        for info in zin.infolist():
            zout.writestr(info.filename, body if info.filename == part else zin.read(info))
    return dst


def test_hostile_workbooks_are_refused(small_class, tmp_path):
    _, _, v = small_class
    good = _xlsx(tmp_path / "good.xlsx", _rows(v))
    sheet = "xl/worksheets/sheet1.xml"
    laughs = (b'<?xml version="1.0"?><!DOCTYPE lolz [<!ENTITY lol "lol">'
              b'<!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">]><worksheet>&lol2;'
              b'</worksheet>')
    with pytest.raises(CheckError, match="DTD"):
        read_submission(_workbook_with(sheet, laughs, good, tmp_path / "laughs.xlsx"))
    spaces = b'<?xml version="1.0"?>' + b" " * (8 * 1024**2)      # 8 MB deflating ~1000:1
    with pytest.raises(CheckError, match="compressed .* to 1"):
        read_submission(_workbook_with(sheet, spaces, good, tmp_path / "ratio.xlsx"))
    junk = tmp_path / "junk.xlsx"
    junk.write_bytes(b"PK\x03\x04 not really")
    with pytest.raises(CheckError, match="not a readable zip"):
        read_submission(junk)


def test_round_trip_grades_workbooks_and_pdfs_like_csv_and_dxf(small_class, tmp_path):
    _, variants, v = small_class
    dxf = (variants / "v1" / "slider_crank.dxf").read_bytes()
    rows = _rows(v, 1.3)
    book = _xlsx(tmp_path / "b.xlsx", rows).read_bytes()
    table = _csv(tmp_path / "b.csv", rows).read_bytes()
    moodle = {
        "Ann Lee_201_assignsubmission_file_/sheet.dxf": dxf,
        "Bo Chen_202_assignsubmission_file_/sheet.pdf": _pdf_with_attachment(dxf),
        "Cat Ray_203_assignsubmission_file_/answers.csv": table,
        "Dan Orr_204_assignsubmission_file_/answers.xlsx": book,
    }
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w") as zf:
        for name, data in moodle.items():
            zf.writestr(name, data)
    (tmp_path / "d.zip").write_bytes(buf.getvalue())
    roster = tmp_path / "roster.csv"
    roster.write_text("First name,Last name,variant\nAnn,Lee,v1\nBo,Chen,v1\nCat,Ray,v1\n"
                      "Dan,Orr,v1\n", encoding="utf-8")
    done = round_trip(variants, tmp_path / "d.zip", tmp_path / "out", roster=roster)
    grades = {r.p.id: r.grade for r in done.results}
    assert grades["201"] == grades["202"] == 100
    assert grades["203"] == grades["204"] == pytest.approx(round(100 * 4 / 5, 1))
    assert not done.problems


def test_a_wide_answer_table_reads_the_same_from_a_workbook(tmp_path):
    from mechplan.submission.answer_table import read_answers

    rows = [["φ", "p [MPa]", "T (N)", "Mкр"], [0, 1.25, -340.5, "12,5 N*m"],
            [30, 2.5, 120, "-3,75 N*m"]]
    book = read_answers(_xlsx(tmp_path / "w.xlsx", rows), lambda n: n.strip() in ("φ", "phi"))
    table = read_answers(_csv(tmp_path / "w.csv", rows), lambda n: n.strip() in ("φ", "phi"))
    got = [(e.name, e.text, e.phi_deg) for e in book.entries]
    assert got == [(e.name, e.text, e.phi_deg) for e in table.entries]
    assert ("T", "-340.5 N", 0.0) in got and ("Mкр", "-3,75 N*m", 30.0) in got
