"""SVG sheets embed their fonts, subset to exactly the characters they use."""

from __future__ import annotations

import base64
import io
import re

from fontTools.ttLib import TTFont
from scenes import ROOT

from mechplan.drafting.primitives import Text
from mechplan.render.svg import to_svg
from mechplan.studies import solve_file

FACE = re.compile(r"font-family: '([^']+)'; "
                  r"src: url\(data:font/(ttf|otf);base64,([A-Za-z0-9+/=]+)\)")


def _faces(svg: str) -> dict[str, TTFont]:
    return {m.group(1): TTFont(io.BytesIO(base64.b64decode(m.group(3))))
            for m in FACE.finditer(svg)}


def test_latin_cyrillic_and_chinese_sheets_embed_the_glyphs_they_use():
    for template, lang, family in (("four_bar", "en", "osifont"), ("offset_slider_crank", "ru",
                                                                     "osifont"),
                                   ("shaper", "zh", "Noto Sans CJK SC")):
        sheet = solve_file(ROOT / "templates" / f"{template}.toml").sheets(None, None, lang,
                                                                             template)[0]
        svg = to_svg(sheet)
        faces = _faces(svg)
        assert family in faces, (template, sorted(faces))
        used = {c for p in sheet.flat() if isinstance(p, Text) for c in p.string} - {" "}
        covered = set()
        for font in faces.values():
            covered |= {chr(cp) for cp in font.getBestCmap()}
        missing = {c for c in used if c not in covered}
        assert not missing, (template, sorted(missing)[:20])
        # subset, not the whole font: only a little more than the characters used
        assert len(faces[family].getBestCmap()) <= len(used) + 5
        assert to_svg(sheet) == svg                  # deterministic (no timestamps)
