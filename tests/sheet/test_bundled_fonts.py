"""Fonts installed with the package: a machine without any system font draws with them, silently."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

from fontTools.ttLib import TTFont

from mechplan.sheet.fonts import BUNDLED_DIR, _is_cjk

ROOT = Path(__file__).resolve().parents[2]

#: a machine with no system fonts: matplotlib's list is emptied, mechplan looks in no system folder
FRESH = r"""
import json, sys
import matplotlib.font_manager as fm
fm.findSystemFonts = lambda *a, **k: []
fm.fontManager = fm.FontManager()
fm.findfont = fm.fontManager.findfont
import mechplan.sheet.fonts as F
F._FONT_DIRS = ()
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
    cmap = TTFont(BUNDLED_DIR / "NotoSansCJKsc-Regular.otf", lazy=True).getBestCmap()
    used = set()
    package = ROOT / "src" / "mechplan"
    for path in [*package.glob("locale/zh/*.po"), *package.rglob("*.py"),
                 *package.glob("templates/*.toml")]:
        used |= {c for c in path.read_text(encoding="utf-8") if _is_cjk(ord(c))}
    missing = sorted(c for c in used if ord(c) not in cmap)
    assert not missing, f"run tools/subset_cjk_font.py: the bundled font lacks {''.join(missing)}"
    assert {"速", "度", "图"} <= used


def test_the_bundled_fonts_carry_their_licences() -> None:
    assert "Open Font License" in (BUNDLED_DIR / "OFL-NotoSansCJK.txt").read_text(encoding="utf-8")
    assert "special exception" in (BUNDLED_DIR / "LICENSE-osifont.txt").read_text(encoding="utf-8")
