"""The one writer of numbers (mechplan.i18n): every value 1e-6 … 1e7 in every language is written
with the language's decimal mark, never in e-notation, and reads back as the value to the digits
shown. The reader here is independent of the writer: its decimal marks are written out by hand."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from mechplan.i18n import (
    LANGUAGES,
    num,
    number,
    scale_factor,
    scientific,
    significant,
    tick,
    trimmed,
)

#: the decimal mark of each language, as its typography manuals give it (not from Babel)
MARK = {"en": ".", "zh": ".", "ru": ",", "vi": ","}
_SUP = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")
#: round scale factors 1, 2, 2.5, 4, 5 × 10ᵏ over 1e-6 … 1e7
ROUND = [m * 10.0 ** k for k in range(-6, 8) for m in (1, 2, 2.5, 4, 5) if m * 10.0 ** k <= 1e7]
#: values with many digits over 1e-6 … 1e7, both signs
RNG = np.random.default_rng(28)
MANY = [float(s * 10 ** e) for s, e in zip(RNG.choice([-1, 1], 300), RNG.uniform(-6, 7, 300))]


def read(text: str, language: str) -> tuple[float, float]:
    """The value a reader takes from ``text``, and the half unit of its last digit."""
    assert "e" not in text.lower(), text
    other = "," if MARK[language] == "." else "."
    assert other not in text, f"{text!r} has a foreign decimal mark in {language}"
    mantissa, _, power = text.partition("×10")
    exponent = int(power.translate(_SUP)) if power else 0
    assert re.fullmatch(r"-?\d+(" + re.escape(MARK[language]) + r"\d+)?", mantissa), text
    decimals = len(mantissa.partition(MARK[language])[2])
    value = float(mantissa.replace(MARK[language], ".")) * 10.0 ** exponent
    return value, 0.5 * 10.0 ** (exponent - decimals)


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("figures", [1, 2, 3, 6])
def test_significant_reads_back_as_the_value_to_the_digits_shown(language, figures):
    for v in ROUND + MANY:
        text = significant(v, figures, language)
        got, half = read(text, language)
        assert abs(got - v) <= half * (1 + 1e-9), (v, text)
        # and it carries the figures asked for (an integer part keeps all its digits)
        assert abs(got - v) <= 0.5 * 10.0 ** (math.floor(math.log10(abs(v))) - figures + 1) * (
            1 + 1e-9), (v, text)


@pytest.mark.parametrize("language", LANGUAGES)
def test_round_scale_factors_print_exactly(language):
    for mu in ROUND:
        text = scale_factor(mu, language)
        assert math.isclose(read(text, language)[0], mu, rel_tol=1e-12), (mu, text)
    mark = MARK[language]
    assert [scale_factor(v, language) for v in (1000, 2500, 40000, 1e7)] == [
        "1000", "2500", "40000", "10000000"]            # not "1", "25", "4" (issue 28, item 1)
    assert scale_factor(0.00025, language) == f"0{mark}00025"
    assert scale_factor(2.5, language) == f"2{mark}5"
    assert scale_factor(6.981317007977318, language) == f"6{mark}98132"   # μA = μM·μφ·H


@pytest.mark.parametrize("language", LANGUAGES)
def test_fixed_decimals_read_back(language):
    for digits in (0, 1, 3, 6):
        for v in MANY:
            if abs(v) * 10 ** digits > 1e15:
                continue
            got, half = read(number(v, digits, language), language)
            assert abs(got - v) <= half * (1 + 1e-9)
            got, half = read(trimmed(v, digits, language), language)
            assert abs(got - v) <= 0.5 * 10.0 ** -digits * (1 + 1e-9)


@pytest.mark.parametrize("language", LANGUAGES)
def test_tick_labels_equal_their_ticks(language):
    for step in ROUND:
        for i in range(-4, 13):
            text = tick(i * step, step, language)
            assert math.isclose(read(text, language)[0], i * step, rel_tol=1e-12,
                                abs_tol=1e-12 * step), (step, i, text)
    mark = MARK[language]
    assert [tick(v, 2.5, language) for v in (2.5, 5.0, 7.5)] == [
        f"2{mark}5", f"5{mark}0", f"7{mark}5"]                # not "2, 5, 8"
    assert tick(0.0475, 0.0025, language) == f"0{mark}0475"     # not "0.048"


@pytest.mark.parametrize("language", LANGUAGES)
def test_tiny_and_huge_values_use_the_power_of_ten_not_e_notation(language):
    text = scientific(1.67e-14, 3, language)
    assert text == f"1{MARK[language]}67×10⁻¹⁴"
    assert significant(1.67e-14, 3, language) == text
    assert read(significant(3.2e9, 2, language), language)[0] == pytest.approx(3.2e9)
    # a catalogue message with an e-format is written the same way ("1.67e-14 %" on a sheet)
    assert num(1.67e-14, ".2e", language) == text
    assert num(2.5, ".1f", language) == f"2{MARK[language]}5"
