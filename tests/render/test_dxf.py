"""DXF output re-read by ezdxf, GDAL and LibreCAD."""

from __future__ import annotations

import importlib.util
import math
import os
import shutil
import subprocess
from pathlib import Path

import ezdxf
import pytest

from mechplan import render
from mechplan.render import dxf as dxf_backend
from mechplan.sheet import Arrow, Role, Text
from mechplan.sheet.fonts import SheetFont

from .samples import FIELDS, LINE_END, LINE_START, TEXTS, sample_sheet

ALLOWED_LINEWEIGHTS = {0, 5, 9, 13, 15, 18, 20, 25, 30, 35, 40, 50, 53, 60, 70, 80, 90, 100, 106,
                       120, 140, 158, 200, 211}


def _write(tmp_path: Path, standard: str = "iso", language: str = "vi") -> tuple[Path, object]:
    sheet = sample_sheet(standard, language)
    path = render.write(sheet, tmp_path / f"{standard}_{language}.dxf", ("dxf",))[0]
    return path, sheet


@pytest.mark.parametrize(("standard", "language"),
                         [("iso", "en"), ("iso", "ru"), ("iso", "vi"), ("iso", "zh"),
                          ("gost", "ru"), ("tcvn", "vi")])
def test_dxf_reads_back_clean(tmp_path: Path, standard: str, language: str) -> None:
    path, _ = _write(tmp_path, standard, language)
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    assert not auditor.has_errors and len(auditor.fixes) == 0
    assert doc.dxfversion == "AC1027"
    h = doc.header
    assert (h["$INSUNITS"], h["$MEASUREMENT"], h["$LWDISPLAY"]) == (4, 1, 1)
    assert h["$DWGCODEPAGE"] == {"en": "ANSI_1252", "ru": "ANSI_1251", "vi": "ANSI_1258",
                                 "zh": "ANSI_936"}[language]
    # every text survives the round trip, whatever the code page says
    texts = {e.dxf.text for e in doc.modelspace().query("TEXT")}
    assert {TEXTS["vi"], TEXTS["ru"], TEXTS["zh"], TEXTS["el"]} <= texts
    block_name = f"TITLE_BLOCK_{standard.upper()}"
    assert block_name in doc.blocks
    insert = doc.modelspace().query(f"INSERT[name=='{block_name}']").first
    values = {a.dxf.tag: a.dxf.text for a in insert.attribs}
    fields = FIELDS[language]
    assert values["TITLE"] == fields["title"] or values["TITLE"] + " " + values.get(
        "TITLE_2", "") == fields["title"]
    assert values["AUTHOR"] == fields["author"]
    assert values["INSTRUCTOR"] == fields["instructor"]
    attdefs = {a.dxf.tag for a in doc.blocks[block_name].query("ATTDEF")}
    assert attdefs == set(values)


def test_layers_lineweights_linetypes(tmp_path: Path) -> None:
    path, _ = _write(tmp_path)
    doc = ezdxf.readfile(path)
    for role in Role:
        layer = doc.layers.get(role.layer)
        assert layer.dxf.lineweight == round(role.style.lineweight_mm * 100)
        assert layer.dxf.lineweight in ALLOWED_LINEWEIGHTS
    assert doc.layers.get("FRAME").dxf.lineweight == 70
    assert doc.layers.get("OUTLINE").dxf.lineweight == 50
    assert doc.layers.get("THIN").dxf.lineweight == 25
    assert doc.layers.get("DASHED").dxf.linetype == "DASHED"
    assert doc.layers.get("CHAIN").dxf.linetype == "DASHDOT"
    assert doc.linetypes.get("DASHED").simplified_line_pattern() == pytest.approx((6.0, 1.5))
    assert doc.linetypes.get("DASHDOT").simplified_line_pattern() == pytest.approx(
        (12.0, 1.5, 0.25, 1.5))
    used = {e.dxf.linetype for e in doc.entitydb.values() if e.dxf.hasattr("linetype")}
    used |= {layer.dxf.linetype for layer in doc.layers}
    for name in used:  # AutoCAD refuses undefined line types
        assert name.upper() in {"BYLAYER", "BYBLOCK"} or name in doc.linetypes
    # entities take their look from the layer
    assert all(e.dxf.get("lineweight", -1) == -1 for e in doc.modelspace())
    assert all(e.dxf.get("color", 256) == 256 for e in doc.modelspace())


def test_geometry_and_text_styles(tmp_path: Path) -> None:
    path, sheet = _write(tmp_path)
    doc = ezdxf.readfile(path)
    msp = doc.modelspace()
    known = [ln for ln in msp.query("LINE[layer=='OUTLINE']")
             if tuple(ln.dxf.start)[:2] == LINE_START and tuple(ln.dxf.end)[:2] == LINE_END]
    assert len(known) == 1
    arrows = [p for p in sheet.primitives if isinstance(p, Arrow)]
    solids = msp.query("SOLID")
    assert len(solids) == len(arrows)
    tips = {tuple(round(c, 6) for c in s.dxf.vtx0)[:2] for s in solids}
    assert tips == {a.end for a in arrows}
    assert len(msp.query("HATCH[layer=='FILL']")) == 1
    styles = {e.dxf.text: e.dxf.style for e in msp.query("TEXT")}
    # styles are named after the LibreCAD stroke font with their glyphs; AutoCAD uses the file
    assert styles[TEXTS["zh"]] == "unicode"
    assert styles[TEXTS["vi"]] == "mechplan-vi"
    assert doc.styles.get("kst32b").dxf.font == SheetFont.ISO.file_name
    assert doc.styles.get("mechplan-vi").dxf.font == SheetFont.ISO.file_name
    assert doc.styles.get("unicode").dxf.font == SheetFont.CJK.file_name
    heights = {e.dxf.height for e in msp.query("TEXT")}
    assert heights <= {2.5, 3.5, 5.0}
    rotated = [e for e in msp.query("TEXT") if e.dxf.text == "b"]
    assert rotated[0].dxf.rotation == pytest.approx(90.0)


def test_condensed_attribute_keeps_width_factor(tmp_path: Path) -> None:
    path, sheet = _write(tmp_path, "gost", "ru")
    block = next(p for p in sheet.primitives if hasattr(p, "attributes"))
    date = next(p for p in block.primitives if isinstance(p, Text) and p.tag == "DATE")
    assert date.width_factor < 1.0  # "12.05.25" does not fit 10 mm at 2.5 mm
    doc = ezdxf.readfile(path)
    insert = doc.modelspace().query("INSERT").first
    attrib = insert.get_attrib("DATE")
    # condensed as the sheet asked, and more where LibreCAD's stroke font is wider than osifont
    fitted = dxf_backend.fitted_width_factor(date, attrib.dxf.style)
    assert attrib.dxf.width == pytest.approx(fitted, abs=1e-4) and fitted <= date.width_factor
    assert attrib.dxf.height == pytest.approx(date.height_mm)
    # the attribute sits where the sheet put the text (middle-centre aligned)
    assert tuple(attrib.dxf.align_point)[:2] == pytest.approx(date.position)
    assert (attrib.dxf.halign, attrib.dxf.valign) == (1, 2)


@pytest.mark.external
def test_gdal_reads_text(tmp_path: Path, require) -> None:
    require(shutil.which("ogrinfo") is not None, "GDAL ogrinfo (apt-get install gdal-bin)")
    path, _ = _write(tmp_path, "tcvn", "vi")
    summary = subprocess.run(["ogrinfo", "-ro", "-so", str(path), "entities"],
                             capture_output=True, text=True, timeout=60, check=True).stdout
    count = int(summary.split("Feature Count:")[1].split()[0])
    doc = ezdxf.readfile(path)
    msp = doc.modelspace()
    inserts = msp.query("INSERT")
    attribs = sum(len(e.attribs) for e in inserts)
    block_texts = sum(len(doc.blocks[e.dxf.name].query("TEXT")) for e in inserts)
    # GDAL merges a block's geometry into one feature and keeps its texts and attributes apart
    assert count == len(msp) + block_texts + attribs
    assert "Extent: (0.000000, 0.000000) - (210.000000, 297.000000)" in summary
    out = subprocess.run(["ogrinfo", "-ro", "--config", "DXF_ENCODING", "UTF-8", str(path),
                          "entities"], capture_output=True, text=True, timeout=60,
                         check=True).stdout
    read = {line.split(" = ", 1)[1] for line in out.splitlines()
            if line.strip().startswith("Text (String) = ")}
    assert {TEXTS["vi"], TEXTS["ru"], TEXTS["zh"], "ĐỒ ÁN NGUYÊN LÝ MÁY", "Nguyễn Văn An"} <= read


@pytest.mark.external
def test_librecad_draws_true_scale(tmp_path: Path, require) -> None:
    require(shutil.which("librecad") is not None, "LibreCAD (apt-get install librecad)")
    require(importlib.util.find_spec("pdfplumber") is not None, "pdfplumber (pip)")
    import pdfplumber

    path, _ = _write(tmp_path, "iso", "en")
    out = tmp_path / "lc"
    out.mkdir()
    env = {**os.environ, "QT_QPA_PLATFORM": "offscreen"}
    subprocess.run(["librecad", "dxf2pdf", "-s", "1", "-f", "0,0,0,0", "-t", str(out), str(path)],
                   env=env, capture_output=True, timeout=120, check=True)
    pdf_path = out / f"{path.stem}.pdf"
    assert pdf_path.exists()
    with pdfplumber.open(pdf_path) as pdf:
        page = pdf.pages[0]
        mm = 25.4 / 72.0
        assert page.width * mm == pytest.approx(210.0, abs=0.5)
        lengths = [math.dist(ln["pts"][0], ln["pts"][-1]) * mm for ln in page.lines
                   if abs(ln["pts"][0][1] - ln["pts"][-1][1]) < 0.01]
        near = [v for v in lengths if abs(v - 100.0) < 2.0]
    assert len(near) == 1
    assert near[0] == pytest.approx(100.0, abs=0.2)


def test_librecad_draws_every_text_within_the_width_the_sheet_measured() -> None:
    """Each TEXT's style names a LibreCAD font with all its glyphs, and in that font, at the
    written width factor, it is no wider than the sheet measured it in osifont (kst32b draws
    "направление" 40 % wider). Checked against LibreCAD itself in test_librecad.py."""
    from mechplan.drafting.fonts import text_width_mm
    from mechplan.render.librecad import stroke_fonts
    from mechplan.studies import solve_file

    root = Path(__file__).resolve().parents[2]
    sheet = solve_file(root / "templates" / "slider_crank.toml").sheets(None, "gost", "ru",
                                                                        "s")[0]
    # one string may be written at two heights (a centre's name on the drawing and in a table)
    texts = {(t.string, round(t.height_mm, 6)): t for t in sheet.flat() if isinstance(t, Text)}
    fonts = stroke_fonts()
    doc = dxf_backend.to_document(sheet)
    condensed = 0
    for e in doc.modelspace().query("TEXT"):
        t = texts.get((e.dxf.text, round(e.dxf.height, 6)))
        if t is None or e.dxf.layer == dxf_backend.TITLE_VALUES_LAYER:
            continue
        font = fonts[e.dxf.style]
        assert font.has(e.dxf.text), (e.dxf.style, e.dxf.text)
        drawn = font.width_mm(e.dxf.text, e.dxf.height, e.dxf.width)
        assert drawn <= text_width_mm(t.string, t.height_mm) * t.width_factor + 1e-6, t.string
        condensed += e.dxf.width < t.width_factor
    assert condensed > 10
    assert fonts["kst32b"].width_mm("направление", 5.0) > 1.3 * text_width_mm("направление", 5.0)
    # "∥" is in LibreCAD's unicode font only: its strings use that style, not azomix (◊)
    assert dxf_backend.text_style("∥ x") == "unicode" and dxf_backend.text_style("⊥ AB") == "azomix"
