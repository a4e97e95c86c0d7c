"""Units are written in the sheet's language: a Russian sheet says "Н·м", "(м/с)/мм", "Дж"."""

from __future__ import annotations

import re

import pytest
from scenes import ALL_TEMPLATES

from mechplan.i18n import LANGUAGES, catalogue, unit
from mechplan.sheet.primitives import Text
from mechplan.studies import solve_file

RUSSIAN = [p for p in ALL_TEMPLATES
           if re.search(r'^language\s*=\s*"ru"', p.read_text(encoding="utf-8"), re.MULTILINE)]
# a Latin SI symbol standing as a unit: after a number, a comma or "(", before "/", ")" or the end
LATIN_UNIT = re.compile(r"(?:[\d,(]\s?|, )(mm|m|s|N|kN|J|kg|rad|MPa|cm)(?:[/·²³)]|$|\s)")


def test_compound_units_symbol_by_symbol():
    assert unit("(m/s²)/mm", "ru") == "(м/с²)/мм"
    assert unit("kg·m²/mm", "ru") == "кг·м²/мм"
    assert unit("N·m", "ru") == "Н·м" and unit("J", "ru") == "Дж" and unit("1/s", "ru") == "1/с"
    for lang in ("en", "vi", "zh"):
        assert unit("(m/s²)/mm", lang) == "(m/s²)/mm" and unit("kg·m²", lang) == "kg·m²"
    assert unit("furlong", "ru") == "furlong"                 # no entry: kept as written


def test_every_language_has_every_unit():
    ids = {k for k in catalogue("en") if k.startswith("unit.")}
    assert len(ids) >= 20
    for lang in LANGUAGES:
        assert ids <= set(catalogue(lang)), lang
    assert all(not re.search("[A-Za-z]", catalogue("ru")[k]) for k in ids)


def test_templates_in_russian_exist():
    assert {p.stem for p in RUSSIAN} >= {"machine_unit", "offset_slider_crank", "cam_cycloidal",
                                          "planetary_two_row"}


@pytest.mark.parametrize("path", RUSSIAN, ids=lambda p: p.stem)
def test_russian_sheets_write_no_latin_units(path):
    study = solve_file(path)
    texts = [p.string for s in study.sheets(None, None, None, path.stem) for p in s.flat()
             if isinstance(p, Text)]
    assert any("мм" in t for t in texts)
    latin = [t for t in texts if LATIN_UNIT.search(t)]
    assert not latin, latin[:10]
