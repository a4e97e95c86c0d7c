"""Sheets composed from solved templates: layout, scales, texts, files, true scale."""

from __future__ import annotations

import base64
import io
import math
import re
from pathlib import Path

import ezdxf
import pytest
from scenes import ROOT, TEMPLATES
from shapely import box

from mechplan.cli import main
from mechplan.model.plans import Plan
from mechplan.render import dxf as dxf_backend
from mechplan.render import mpl as mpl_backend
from mechplan.render import svg as svg_backend
from mechplan.scene import load_scene
from mechplan.sheet.compose import compose, packing_area
from mechplan.sheet.frame import make_frame
from mechplan.sheet.panels import _points_of
from mechplan.sheet.primitives import Text
from mechplan.solve import solve


def composed(path: Path, **kw):
    return compose(solve(load_scene(path)), name=path.stem, **kw)


def _box(points):
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    return box(min(xs), min(ys), max(xs), max(ys))


@pytest.mark.parametrize("path", TEMPLATES, ids=lambda p: p.stem)
def test_panels_never_overlap_each_other_or_the_frame(path):
    comp = composed(path)
    scene = load_scene(path)
    for sheet, placed in zip(comp.sheets, comp.placements):
        frame = make_frame(scene.drawing.sheet, scene.drawing.standard, {"title": "x"},
                           language=scene.language)
        area = packing_area(frame)
        boxes = []
        for panel, (dx, dy) in placed:
            x0, y0, x1, y1 = panel.bounds()
            b = box(x0 + dx, y0 + dy, x1 + dx, y1 + dy)
            assert area.contains(b), panel.name
            boxes.append(b)
        for i, a in enumerate(boxes):
            for b in boxes[i + 1:]:
                assert a.intersection(b).area < 1e-6
        # every primitive of a panel stays inside its box (nothing sticks out of a panel)
        for (panel, (dx, dy)), b in zip(placed, boxes):
            for p in panel.primitives:
                pts = [(x + dx, y + dy) for x, y in _points_of(p)]
                if pts:
                    assert b.buffer(1e-6).contains(_box(pts)), (panel.name, p)


@pytest.mark.parametrize("path", TEMPLATES, ids=lambda p: p.stem)
def test_point_labels_do_not_overlap_each_other(path):
    comp = composed(path)
    for placed in comp.placements:
        for panel, _ in placed:
            labels = [p for p in panel.primitives if isinstance(p, Text) and p.height_mm == 3.5
                      and not p.string.startswith("μ")]
            rects = [_box(_points_of(t)) for t in labels]
            for i, a in enumerate(rects):
                for b in rects[i + 1:]:
                    assert a.intersection(b).area < 0.25 * min(a.area, b.area), (panel.name,)


def _round_mantissa(mu: float) -> bool:
    m = mu / 10 ** math.floor(math.log10(mu) + 1e-12)
    return any(math.isclose(m, r, rel_tol=1e-9) for r in (1, 2, 2.5, 4, 5))


@pytest.mark.parametrize("path", TEMPLATES, ids=lambda p: p.stem)
def test_scale_factors_are_round_or_the_scenes_own(path):
    comp = composed(path)
    fixed = load_scene(path).drawing.scales
    keys = {Plan.POSITION: "mu_l", Plan.VELOCITY: "mu_v", Plan.ACCELERATION: "mu_a",
            Plan.FORCE: "mu_F"}
    for plan, mu in comp.scales.items():
        if keys[plan] in fixed:
            assert mu == fixed[keys[plan]]
        else:
            assert _round_mantissa(mu), (plan, mu)


def test_v_engine_sheet_uses_the_projects_scale_factors_and_decimal_comma():
    comp = composed(ROOT / "templates" / "v_engine.toml")
    assert comp.scales[Plan.VELOCITY] == pytest.approx(0.1)
    strings = {p.string for s in comp.sheets for p in s.flat() if isinstance(p, Text)}
    assert "μv = 0,1 (m/s)/mm" in strings and "μa = 2 (m/s²)/mm" in strings
    assert "67,0" in strings and "6,702" in strings          # pb 67.0 mm → v_B 6.702 m/s
    en = compose(solve(load_scene(ROOT / "templates" / "v_engine.toml")), lang="en")
    strings_en = {p.string for s in en.sheets for p in s.flat() if isinstance(p, Text)}
    assert "67.0" in strings_en and "Velocity plan — position 0, φ = 180.0°" in strings_en


@pytest.mark.parametrize("path", TEMPLATES, ids=lambda p: p.stem)
def test_drawings_folder_is_up_to_date(path):
    """`mechplan draw templates/*.toml -o drawings --format dxf,svg` regenerates drawings/.

    Compared: every element and attribute of the SVG, each embedded font by its family and the
    characters it maps (not its bytes, which another fontTools may write otherwise), and the
    DXF's lines, texts and text styles.
    """
    for sheet in composed(path).sheets:
        svg = svg_backend.to_svg(sheet)
        stored = (ROOT / "drawings" / f"{sheet.name}.svg").read_bytes()
        assert svg_essence(stored) == svg_essence(svg.encode("utf-8")), sheet.name
        doc = ezdxf.readfile(ROOT / "drawings" / f"{sheet.name}.dxf")
        # R2013 is UTF-8
        fresh = ezdxf.read(io.StringIO(dxf_backend.to_bytes(sheet).decode("utf-8")))
        assert _signature(doc) == _signature(fresh)
        assert _styles(doc) == _styles(fresh)


_FACE = re.compile(r"@font-face \{ font-family: '([^']+)'; "
                   r"src: url\(data:font/(?:ttf|otf);base64,([A-Za-z0-9+/=]+)\) "
                   r"format\('(?:truetype|opentype)'\); \}")


def svg_essence(svg: bytes) -> tuple[list[tuple[str, str]], bytes]:
    """Return (the embedded fonts as (family, characters mapped), the rest of the SVG)."""
    from xml.etree import ElementTree

    from fontTools.ttLib import TTFont

    root = ElementTree.fromstring(svg)
    faces = []
    for style in root.iter("{http://www.w3.org/2000/svg}style"):
        text = style.text or ""
        for m in _FACE.finditer(text):
            font = TTFont(io.BytesIO(base64.b64decode(m.group(2))))
            faces.append((m.group(1), "".join(sorted(map(chr, font.getBestCmap())))))
        style.text = _FACE.sub("@font-face", text)
    return sorted(faces), ElementTree.tostring(root)


def _styles(doc) -> list[tuple[str, str]]:
    return sorted((s.dxf.name, s.dxf.font) for s in doc.styles)


def _signature(doc) -> list[tuple]:
    out = []
    for e in doc.modelspace():
        kind = e.dxftype()
        if kind == "LINE":
            out.append((kind, e.dxf.layer, *(round(v, 6) for v in (*e.dxf.start, *e.dxf.end))))
        elif kind in ("TEXT", "ATTRIB"):
            out.append((kind, e.dxf.text, round(e.dxf.height, 6)))
        else:
            out.append((kind, e.dxf.layer))
    return sorted(out, key=repr)


def test_dxf_of_a_full_sheet_audits_clean():
    sheet = composed(ROOT / "templates" / "v_engine.toml").sheets[0]
    doc = ezdxf.read(io.StringIO(dxf_backend.to_bytes(sheet).decode("utf-8")))
    auditor = doc.audit()
    assert not auditor.has_errors and not auditor.has_fixes
    assert doc.dxfversion == "AC1027" and doc.header["$INSUNITS"] == 4


def test_pdf_of_a_full_sheet_is_true_scale():
    pdfplumber = pytest.importorskip("pdfplumber")
    sheet = composed(ROOT / "templates" / "four_bar.toml").sheets[0]
    with pdfplumber.open(io.BytesIO(mpl_backend.to_bytes(sheet, "pdf"))) as pdf:
        page = pdf.pages[0]
        mm = 25.4 / 72
        assert page.width * mm == pytest.approx(841.0, abs=0.05)
        widths = [abs(ln["x1"] - ln["x0"]) * mm for ln in page.lines]
        widths += [r["width"] * mm for r in page.rects]
        assert any(abs(w - 811.0) < 0.1 for w in widths)      # the ISO frame: 841 − 20 − 10


def test_draw_writes_nothing_when_the_scenes_own_scale_does_not_fit(tmp_path, capsys):
    text = (ROOT / "templates" / "four_bar.toml").read_text(encoding="utf-8")
    scene = tmp_path / "fb.toml"
    scene.write_text(text + '\n[drawing]\nsheet = "A4"\nscales = { mu_l = "0.0002 m/mm" }\n',
                     encoding="utf-8")
    out = tmp_path / "out"
    code = main(["draw", str(scene), "-o", str(out)])
    assert code == 2
    assert "does not fit" in capsys.readouterr().err
    assert not out.exists() or list(out.iterdir()) == []


def test_draw_cli_writes_every_format(tmp_path, capsys):
    code = main(["draw", str(ROOT / "templates" / "slider_crank.toml"), "-o", str(tmp_path),
                 "--format", "dxf,svg,pdf,png", "--lang", "ru", "--standard", "gost"])
    assert code == 0
    names = sorted(p.name for p in tmp_path.iterdir())
    # kinematics and kinetostatics share the A1 sheet
    assert names == sorted(f"slider_crank.{ext}" for ext in ("dxf", "svg", "pdf", "png"))
    svg = (tmp_path / "slider_crank.svg").read_text(encoding="utf-8")
    assert re.search(r'width="841(\.0*)?mm"', svg) and "План скоростей" in svg


@pytest.mark.external
def test_librecad_reads_a_full_sheet_at_true_scale(tmp_path, require):
    import os
    import shutil
    import subprocess

    require(shutil.which("librecad") is not None, "LibreCAD (apt-get install librecad)")
    pdfplumber = pytest.importorskip("pdfplumber")
    src = ROOT / "drawings" / "four_bar.dxf"
    env = {**os.environ, "QT_QPA_PLATFORM": "offscreen"}
    subprocess.run(["librecad", "dxf2pdf", "-s", "1", "-f", "0,0,0,0", "-t", str(tmp_path),
                    str(src)],
                   env=env, capture_output=True, timeout=120, check=True)
    with pdfplumber.open(tmp_path / "four_bar.pdf") as pdf:
        page = pdf.pages[0]
        mm = 25.4 / 72
        lengths = [math.dist(ln["pts"][0], ln["pts"][-1]) * mm for ln in page.lines]
        lengths += [r["width"] * mm for r in page.rects]
    assert any(abs(v - 811.0) < 0.3 for v in lengths)       # the frame, 841 − 20 − 10 mm


@pytest.mark.external
def test_chromium_renders_a_full_sheet(tmp_path, require):
    import shutil
    import subprocess

    import numpy as np

    exe = shutil.which("chromium") or shutil.which("chromium-browser")
    require(exe is not None, "Chromium (apt-get install --no-install-recommends chromium)")
    from matplotlib import image

    w, h = round(841 / 25.4 * 96), round(594 / 25.4 * 96)
    shot = tmp_path / "sheet.png"
    subprocess.run([exe, "--headless=new", "--no-sandbox", "--disable-gpu",
                    "--disable-background-networking", "--disable-component-update",
                    "--disable-sync", "--no-first-run", f"--user-data-dir={tmp_path / 'profile'}",
                    "--hide-scrollbars", f"--window-size={w},{h}", f"--screenshot={shot}",
                    (ROOT / "drawings" / "four_bar.svg").as_uri()],
                   capture_output=True, timeout=120, check=True)
    img = image.imread(shot)[..., :3].mean(axis=2)
    dark = img < 0.5
    assert 0.002 < dark.mean() < 0.2                             # drawn, not blank
    row = dark[h // 4]                                           # a row crossing the frame
    cols = np.nonzero(row)[0]
    frame_px = cols.max() - cols.min()
    assert frame_px * 25.4 / 96 == pytest.approx(811.0, abs=1.0)


def test_plans_at_chooses_the_positions_drawn(tmp_path):
    text = (ROOT / "templates" / "four_bar.toml").read_text(encoding="utf-8")
    scene_path = tmp_path / "fb.toml"
    scene_path.write_text(text + "\n[drawing]\nplans_at = [3, 7]\n", encoding="utf-8")
    comp = composed(scene_path)
    names = [panel.name for placed in comp.placements for panel, _ in placed]
    assert "acceleration-3" in names and "acceleration-7" in names
    assert "acceleration-1" not in names and "velocity-1-tables" not in names
    assert names.index("acceleration-3") < names.index("acceleration-7")


def test_drawings_are_compared_by_font_family_and_glyphs_not_font_bytes():
    from fontTools import subset
    from fontTools.ttLib import TTFont

    sheet = composed(ROOT / "templates" / "four_bar.toml").sheets[0]
    svg = svg_backend.to_svg(sheet)
    m = _FACE.search(svg)
    assert m is not None and m.group(1) == "osifont"
    # the same glyphs written by "another fontTools": other bytes (no hinting, no names)
    font = TTFont(io.BytesIO(base64.b64decode(m.group(2))))
    options = subset.Options()
    options.hinting = False
    options.name_IDs = [1, 2]
    sub = subset.Subsetter(options)
    sub.populate(unicodes=font.getBestCmap())
    sub.subset(font)
    buf = io.BytesIO()
    font.save(buf)
    other = svg.replace(m.group(2), base64.b64encode(buf.getvalue()).decode("ascii"))
    assert other != svg
    assert svg_essence(other.encode()) == svg_essence(svg.encode())
    # a glyph less, or a text moved by 0.1 mm, is a different drawing
    font = TTFont(io.BytesIO(base64.b64decode(m.group(2))))
    assert ord("A") in font.getBestCmap()
    sub = subset.Subsetter(options)
    sub.populate(unicodes=set(font.getBestCmap()) - {ord("A")})
    sub.subset(font)
    buf = io.BytesIO()
    font.save(buf)
    fewer = svg.replace(m.group(2), base64.b64encode(buf.getvalue()).decode("ascii"))
    assert svg_essence(fewer.encode()) != svg_essence(svg.encode())
    moved = re.sub(r'translate\(([\d.]+) ', lambda t: f"translate({float(t.group(1)) + 0.1:.4f} ",
                   svg, count=1)
    assert svg_essence(moved.encode()) != svg_essence(svg.encode())
