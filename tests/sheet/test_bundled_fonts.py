"""Fonts installed with the package: a machine without any system font draws with them, silently."""

from __future__ import annotations

import json
import logging
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from fontTools.ttLib import TTFont

from mechplan.i18n import catalogue
from mechplan.render import write
from mechplan.sheet.fonts import (
    BUNDLED_DIR,
    SheetFont,
    _is_cjk,
    bundled_path,
    covers,
    font_for,
    font_path,
    has_cjk,
    missing_glyphs,
)
from mechplan.sheet.primitives import Sheet, Text
from mechplan.studies import solve_file

ROOT = Path(__file__).resolve().parents[2]

#: a machine with no system fonts: matplotlib's list is emptied, mechplan looks in no system folder
FRESH = r"""
import json, sys
import matplotlib.font_manager as fm
fm.findSystemFonts = lambda *a, **k: []
fm.fontManager = fm.FontManager()
fm.findfont = fm.fontManager.findfont
import mechplan.sheet.fonts as F
from mechplan.render import write
from mechplan.sheet.primitives import Sheet, Text
import pdfplumber
samples = json.loads(sys.argv[2])
out = {}
for lang, string in samples.items():
    sheet = Sheet(120, 40, (Text((10, 20), string, 5.0),), language=lang, name=f"s_{lang}")
    [pdf] = write(sheet, sys.argv[1], ["pdf"])
    with pdfplumber.open(pdf) as doc:
        out[lang] = sorted({c["fontname"].split("+")[-1] for c in doc.pages[0].chars})
    out[lang + "_paths"] = {f.name: str(F.font_path(f)) for f in F.SheetFont}
print(json.dumps(out))
"""

SAMPLES = {"en": "Velocity plan", "ru": "План скоростей", "vi": "Họa đồ vận tốc",
           "zh": "速度图与加速度图"}


def test_a_fresh_machine_embeds_the_bundled_fonts_without_warnings(tmp_path: Path) -> None:
    env = dict(os.environ, MPLCONFIGDIR=str(tmp_path / "mpl"),
               PYTHONPATH=os.pathsep.join([str(ROOT / "src"), os.environ.get("PYTHONPATH", "")]))
    proc = subprocess.run([sys.executable, "-c", FRESH, str(tmp_path), json.dumps(SAMPLES)],
                          capture_output=True, text=True, env=env, timeout=120, check=False)
    assert proc.returncode == 0, proc.stderr
    assert "findfont" not in proc.stderr and "not found" not in proc.stderr, proc.stderr
    got = json.loads(proc.stdout)
    assert got["en"] == ["osifont"] and got["ru"] == ["osifont"] and got["vi"] == ["osifont"]
    assert got["zh"] == ["NotoSansCJKsc-Regular"]
    paths = got["zh_paths"]
    assert Path(paths["ISO"]).parent == BUNDLED_DIR and Path(paths["CJK"]).parent == BUNDLED_DIR


def test_the_bundled_cjk_font_covers_the_chinese_catalogues() -> None:
    cmap = TTFont(BUNDLED_DIR / "NotoSansCJKsc-Regular.ttf", lazy=True).getBestCmap()
    used = set()
    package = ROOT / "src" / "mechplan"
    for path in [*package.glob("locale/zh/*.po"), *package.rglob("*.py"),
                 *package.glob("templates/*.toml"), *ROOT.glob("templates/*.toml")]:
        used |= {c for c in path.read_text(encoding="utf-8") if _is_cjk(ord(c))}
    # a string with Chinese in it is drawn in the CJK font as a whole: every character of a
    # Chinese message (Greek, ⊥ ∥ → ′ ², digits, punctuation) must be in that font too
    messages = catalogue("zh")
    for text in messages.values():
        if has_cjk(text):
            used |= {c for c in text if not c.isspace()}
    missing = sorted(c for c in used if ord(c) not in cmap)
    assert not missing, f"run tools/subset_cjk_font.py: the bundled font lacks {''.join(missing)}"
    assert {"速", "度", "图", "⊥", "φ", "μ", "′"} <= used


@pytest.mark.parametrize("path", sorted((ROOT / "templates").glob("*.toml")), ids=lambda p: p.stem)
def test_every_chinese_sheet_has_every_glyph_in_its_font(path: Path) -> None:
    """What a zh sheet can put on paper: the templates drawn in Chinese, every string covered."""
    study = solve_file(path)
    for sheet in study.sheets(None, None, "zh", path.stem):
        strings = [p.string for p in sheet.flat() if isinstance(p, Text)]
        assert any(has_cjk(s) for s in strings)
        assert missing_glyphs(strings) == "", sheet.name
        for s in strings:
            font = font_for(s)
            assert covers(font, s), (sheet.name, s, font)
            assert font_path(font) == bundled_path(font)


def test_chinese_outside_the_subset_is_warned_once_and_drawn_the_same_everywhere(
        tmp_path: Path, caplog: pytest.LogCaptureFixture) -> None:
    rare = "𠀀龘"                                # CJK Extension B and a rare character
    assert missing_glyphs(["速度", rare]) == "".join(sorted(rare))
    sheet = Sheet(120, 40, (Text((10, 20), "速度" + rare, 5.0),), language="zh", name="rare")
    with caplog.at_level(logging.WARNING, logger="mechplan.render"):
        write(sheet, tmp_path, ["svg", "pdf"])
    warned = [r.getMessage() for r in caplog.records if r.name == "mechplan.render"]
    assert len(warned) == 1 and "𠀀" in warned[0] and "--system-fonts" in warned[0]


def test_the_bundled_fonts_carry_their_licences() -> None:
    assert "Open Font License" in (BUNDLED_DIR / "OFL-NotoSansCJK.txt").read_text(encoding="utf-8")
    assert "special exception" in (BUNDLED_DIR / "LICENSE-osifont.txt").read_text(encoding="utf-8")


#: what a drawing measures and embeds, printed by a fresh process
MACHINE = r"""
import hashlib, json, sys
import mechplan.sheet.fonts as F
from mechplan.render import mpl, svg
from mechplan.sheet.primitives import Sheet, Text
strings = json.loads(sys.argv[1])
sheet = Sheet(160, 60, tuple(Text((10, 10 + 12 * i), s, 5.0) for i, s in enumerate(strings)),
              language="zh", name="machine")
print(json.dumps({
    "paths": {f.name: str(F.font_path(f)) for f in F.SheetFont},
    "widths": [F.text_width_mm(s, 5.0) for s in strings],
    "svg": hashlib.sha256(svg.to_svg(sheet).encode()).hexdigest(),
    "pdf": hashlib.sha256(mpl.to_bytes(sheet, "pdf")).hexdigest(),
}))
"""


def _machine(tmp_path: Path, home: Path, **env: str) -> dict:
    strings = ["速度多边形 p", "План скоростей", "v ∥ AB ⊥ ✓", "Họa đồ vận tốc"]
    full = dict(os.environ, HOME=str(home), MPLCONFIGDIR=str(home / "mpl"),
                XDG_DATA_HOME=str(home / ".local" / "share"),
                PYTHONPATH=os.pathsep.join([str(ROOT / "src"), os.environ.get("PYTHONPATH", "")]),
                **env)
    for key in ("MECHPLAN_FONT_DIRS", "MECHPLAN_SYSTEM_FONTS"):
        if key not in env:
            full.pop(key, None)
    proc = subprocess.run([sys.executable, "-c", MACHINE, json.dumps(strings)], env=full,
                          capture_output=True, text=True, timeout=120, check=False)
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout)


def test_a_drawing_is_the_same_whatever_fonts_the_machine_has(tmp_path: Path) -> None:
    """A machine with other files of the sheet fonts installed (another osifont, a full Noto,
    another DejaVu) measures and embeds exactly what a machine without them does, unless the
    user opts in to the system's fonts."""
    import matplotlib

    plain = tmp_path / "plain"
    other = tmp_path / "other"
    fonts = other / ".fonts"
    fonts.mkdir(parents=True)
    mpl_fonts = Path(matplotlib.get_data_path()) / "fonts" / "ttf"
    # real fonts with other metrics, under the sheet fonts' file names (as a Debian package would)
    shutil.copy(mpl_fonts / "DejaVuSerif.ttf", fonts / "osifont.ttf")
    shutil.copy(mpl_fonts / "DejaVuSans-Bold.ttf", fonts / "DejaVuSans.ttf")
    shutil.copy(mpl_fonts / "DejaVuSansMono.ttf", fonts / "NotoSansSC-Regular.otf")
    a = _machine(tmp_path, plain)
    b = _machine(tmp_path, other)
    assert a == b
    assert {Path(p).name for p in a["paths"].values()} == {
        "osifont.ttf", "DejaVuSans.ttf", "NotoSansCJKsc-Regular.ttf"}
    assert all(Path(p).parent in (BUNDLED_DIR, mpl_fonts) for p in a["paths"].values())
    # the opt-in: the system's fonts are searched first, and the drawing changes with them
    c = _machine(tmp_path, other, MECHPLAN_SYSTEM_FONTS="1")
    assert all(not Path(p).is_relative_to(BUNDLED_DIR) for p in c["paths"].values())
    assert (c["svg"], c["pdf"]) != (a["svg"], a["pdf"])
    d = _machine(tmp_path, plain, MECHPLAN_FONT_DIRS=str(fonts))
    assert d["paths"]["ISO"] == str(fonts / "osifont.ttf") and d["widths"] != a["widths"]


def test_doctor_names_each_font_file_and_where_it_comes_from(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from mechplan.doctor import report

    monkeypatch.delenv("MECHPLAN_FONT_DIRS", raising=False)
    monkeypatch.delenv("MECHPLAN_SYSTEM_FONTS", raising=False)
    text = report()
    assert "fonts: the bundled fonts" in text
    for font in SheetFont:
        assert f"  {font.family}: bundled {bundled_path(font)}" in text
    shutil.copy(bundled_path(SheetFont.ISO), tmp_path / "osifont-lgpl3fe.ttf")
    monkeypatch.setenv("MECHPLAN_FONT_DIRS", str(tmp_path))
    text = report()
    assert f"  osifont: MECHPLAN_FONT_DIRS {tmp_path / 'osifont-lgpl3fe.ttf'}" in text
    assert f"  Noto Sans CJK SC: bundled {bundled_path(SheetFont.CJK)}" in text


def test_draw_system_fonts_flag_opts_in_for_the_run(tmp_path: Path,
                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    from mechplan.cli import main

    monkeypatch.setenv("MECHPLAN_SYSTEM_FONTS", "0")          # restored after the test
    assert main(["draw", str(ROOT / "templates" / "four_bar.toml"), "-o", str(tmp_path),
                 "--format", "svg"]) == 0
    assert os.environ["MECHPLAN_SYSTEM_FONTS"] == "0"
    assert main(["draw", str(ROOT / "templates" / "four_bar.toml"), "-o", str(tmp_path),
                 "--format", "svg", "--system-fonts"]) == 0
    assert os.environ["MECHPLAN_SYSTEM_FONTS"] == "1"
