"""Variants as quizzes: a Moodle XML question bank with one numerical question per value of each
variant's answer key (a category per variant, or per student), the tolerance the drawing's."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from collections.abc import Iterable
from typing import Any

from ..i18n import message, significant, trimmed

#: the answer key's kinds → unit message ids (as the answer key PDF writes them)
UNITS = {"v": "batch.unit.velocity", "a": "batch.unit.acceleration", "omega": "batch.unit.omega",
         "epsilon": "batch.unit.epsilon", "R": "batch.unit.force", "M_b": "batch.unit.moment"}


def _text(parent: ET.Element, tag: str, text: str, **attrs: str) -> ET.Element:
    el = ET.SubElement(parent, tag, attrs)
    ET.SubElement(el, "text").text = text
    return el


def _category(quiz: ET.Element, path: str) -> None:
    q = ET.SubElement(quiz, "question", {"type": "category"})
    _text(q, "category", f"$course$/top/{path}")


def tolerance(value: float, pct: float, floor: float) -> float:
    """The allowed error of a value: ``pct`` % of it, at least ``floor`` (a tiny value's)."""
    return max(abs(value) * pct / 100.0, floor)


def moodle_quiz(keys: Iterable[tuple[str, dict[str, Any]]], pct: float, lang: str = "en",
                positions: int | None = None, figures: int = 6) -> bytes:
    """Moodle XML of numerical questions: ``keys`` are (category, answer key) pairs; each
    non-zero value of a key at each position is one question."""
    quiz = ET.Element("quiz")
    for category, key in keys:
        _category(quiz, f"mechplan/{category}")
        phis = key.get("phi_deg", [])[:positions]
        scale = {row["kind"]: max((abs(x) for x in row["values"] if x is not None), default=0.0)
                 for row in key.get("rows", [])}
        for row in key.get("rows", []):
            unit = message(UNITS[row["kind"]], lang) if row["kind"] in UNITS else ""
            for phi, value in zip(phis, row["values"], strict=False):
                if value is None or not math.isfinite(value):
                    continue
                q = ET.SubElement(quiz, "question", {"type": "numerical"})
                angle = trimmed(phi, 2, lang)
                _text(q, "name", f"{key.get('id', category)} {row['quantity']} φ={angle}°")
                _text(q, "questiontext", message("lms.quiz.question", lang,
                                                 quantity=row["quantity"], phi=angle,
                                                 unit=unit), format="html")
                ET.SubElement(q, "defaultgrade").text = "1"
                answer = _text(q, "answer", significant(value, figures, "en"), fraction="100",
                               format="moodle_auto_format")
                floor = scale.get(row["kind"], 0.0) * pct / 100.0 * 0.05 or 1e-9
                ET.SubElement(answer, "tolerance").text = significant(
                    tolerance(value, pct, floor), 3, "en")
                units = ET.SubElement(q, "units")
                if unit:
                    u = ET.SubElement(units, "unit")
                    ET.SubElement(u, "multiplier").text = "1"
                    ET.SubElement(u, "unit_name").text = unit
                ET.SubElement(q, "unitgradingtype").text = "0"
                ET.SubElement(q, "showunits").text = "3"
                ET.SubElement(q, "unitsleft").text = "0"
    ET.indent(quiz)
    return b'<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(quiz, encoding="utf-8") \
        + b"\n"
