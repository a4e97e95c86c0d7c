"""SVG output parsed as XML and rendered by headless Chromium."""

from __future__ import annotations

import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from mechplan import render
from mechplan.render import svg
from mechplan.sheet import Role

from .samples import LINE_END, LINE_START, TEXTS, sample_sheet

NS = {"s": "http://www.w3.org/2000/svg"}


def _parse(text: str) -> ET.Element:
    return ET.fromstring(text.encode("utf-8"))


def _group(root: ET.Element, role: Role) -> list[ET.Element]:
    return root.findall(f".//s:g[@class='role-{role.value.lower()}']", NS)


def test_svg_size_viewbox_and_flip(tmp_path: Path) -> None:
    sheet = sample_sheet("iso", "vi")
    path = render.write(sheet, tmp_path / "a4.svg", ("svg",))[0]
    root = ET.parse(path).getroot()
    assert root.get("width") == "210.0mm" and root.get("height") == "297.0mm"
    assert [float(v) for v in root.get("viewBox").split()] == [0.0, 0.0, 210.0, 297.0]
    lines = [ln for g in _group(root, Role.OUTLINE) for ln in g.findall("s:line", NS)]
    coords = {tuple(float(ln.get(k)) for k in ("x1", "y1", "x2", "y2")) for ln in lines}
    x0, y0 = LINE_START
    x1, y1 = LINE_END
    assert (x0, 297.0 - y0, x1, 297.0 - y1) in coords  # y flipped: origin at the bottom left


def test_svg_styles_per_role() -> None:
    root = _parse(svg.to_svg(sample_sheet("gost", "ru")))
    for role in (Role.FRAME, Role.OUTLINE, Role.THIN, Role.DASHED, Role.CHAIN, Role.TABLE):
        groups = _group(root, role)
        assert groups, role
        for g in groups:
            assert float(g.get("stroke-width")) == pytest.approx(role.style.lineweight_mm)
            assert g.get("stroke-linecap") == "butt"
    assert _group(root, Role.DASHED)[0].get("stroke-dasharray") == "6.0 1.5"
    assert _group(root, Role.CHAIN)[0].get("stroke-dasharray") == "12.0 1.5 0.25 1.5"
    assert _group(root, Role.OUTLINE)[0].get("stroke-dasharray") is None
    assert root.find(".//s:g[@id='TITLE_BLOCK_GOST']", NS) is not None


def test_svg_text_fonts_and_arrowheads() -> None:
    sheet = sample_sheet("tcvn", "vi")
    root = _parse(svg.to_svg(sheet))
    texts = {t.text: t for t in root.iter("{http://www.w3.org/2000/svg}text")}
    for s in (TEXTS["vi"], TEXTS["ru"], TEXTS["zh"], TEXTS["el"], "ĐỒ ÁN NGUYÊN LÝ MÁY"):
        assert s in texts
    zh = texts[TEXTS["zh"]].get("font-family")
    vi = texts[TEXTS["vi"]].get("font-family")
    assert zh.startswith("'Noto Sans CJK SC'") and zh.endswith("sans-serif")
    assert vi.startswith("osifont,") and "'Noto Sans CJK SC'" in vi
    assert texts["Nguyễn Văn An"].get("data-tag") == "AUTHOR"
    # 3.5 mm capital height needs a larger em size
    assert float(texts[TEXTS["vi"]].get("font-size")) > 3.5
    heads = [p for p in root.iter("{http://www.w3.org/2000/svg}polygon")
             if p.get("fill") == "black"]
    assert len(heads) == 3  # two arrowheads and one filled polygon


def _longest_dark_run(row: np.ndarray) -> int:
    best = run = 0
    for dark in row:
        run = run + 1 if dark else 0
        best = max(best, run)
    return best


@pytest.mark.external
def test_chromium_renders_true_scale(tmp_path: Path, require) -> None:
    exe = shutil.which("chromium") or shutil.which("chromium-browser")
    require(exe is not None, "Chromium (apt-get install --no-install-recommends chromium)")
    sheet = sample_sheet("iso", "zh")
    path = render.write(sheet, tmp_path / "sheet.svg", ("svg",))[0]
    shot = tmp_path / "shot.png"
    px_per_mm = 96.0 / 25.4
    w, h = round(210 * px_per_mm), round(297 * px_per_mm)
    subprocess.run(
        [exe, "--headless=new", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run", "--hide-scrollbars",
         "--force-device-scale-factor=1", f"--user-data-dir={tmp_path / 'profile'}",
         f"--window-size={w},{h}", f"--screenshot={shot}", path.as_uri()],
        capture_output=True, timeout=120, check=True)
    image = np.asarray(Image.open(shot).convert("L"))
    assert image.shape == (h, w)
    dark = image < 128
    assert 0.005 < dark.mean() < 0.2  # a drawing, neither blank nor black
    row = round((297.0 - LINE_START[1]) * px_per_mm)
    run = max(_longest_dark_run(dark[r]) for r in range(row - 2, row + 3))
    assert run == pytest.approx(100.0 * px_per_mm, abs=1.5)  # 377.95 px
    # the frame: 0.7 mm line at 10 mm from the top edge
    frame_rows = np.flatnonzero(dark[: round(15 * px_per_mm), w // 3])
    assert frame_rows.size and abs(frame_rows.mean() - 10 * px_per_mm) < 2
