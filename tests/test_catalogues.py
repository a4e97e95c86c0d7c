"""Every message id and every placeholder exists in all four catalogues."""

from __future__ import annotations

import pytest

from mechplan.i18n import LANGUAGES, catalogue, message, number, placeholders


def test_every_id_in_every_language():
    ids = {lang: set(catalogue(lang)) for lang in LANGUAGES}
    reference = ids["en"]
    assert reference, "the English catalogue is empty"
    for lang in LANGUAGES:
        assert ids[lang] == reference, (lang, sorted(ids[lang] ^ reference)[:20])


def test_every_placeholder_in_every_language():
    en = catalogue("en")
    for lang in LANGUAGES:
        other = catalogue(lang)
        bad = [k for k, text in en.items() if placeholders(other.get(k, "")) != placeholders(text)]
        assert not bad, (lang, bad[:20])


def test_no_empty_translation():
    for lang in LANGUAGES:
        empty = [k for k, v in catalogue(lang).items() if not v.strip()]
        assert not empty, (lang, empty[:20])


@pytest.mark.parametrize(("lang", "expected"), [("en", "-1.50"), ("ru", "-1,50"), ("vi", "-1,50"),
                                                 ("zh", "-1.50")])
def test_decimal_mark(lang, expected):
    assert number(-1.4999, 2, lang) == expected
    assert number(-0.001, 2, lang) in ("0.00", "0,00")


def test_message_fills_placeholders():
    assert message("core.language.ru", "ru") == "русский"
