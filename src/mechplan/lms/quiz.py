"""Variants as quizzes: a Moodle XML question bank with one numerical question per value of each
variant's answer key (a category per variant, or per student), the tolerance the drawing's."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from typing import Any

from ..i18n import message, trimmed

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


def lms_number(value: float, figures: int) -> str:
    """A number as an LMS reads it (a machine format, not text for a reader): ``figures``
    significant figures, a point, an exponent ``e-15`` for very small or large values — never
    the "×10⁻¹⁵" a sheet writes, which Moodle and Canvas cannot read."""
    return f"{value:.{figures}g}"


def tolerance(value: float, pct: float, floor: float) -> float:
    """The allowed error of a value: ``pct`` % of it, at least ``floor`` (a tiny value's)."""
    return max(abs(value) * pct / 100.0, floor)


@dataclass(frozen=True)
class Question:
    """One numerical question: a value of a variant's answer key at one position."""

    name: str
    text: str
    answer: str          # written as the LMS reads it (lms_number: 6 significant figures)
    tolerance: float
    value: float
    unit: str


def questions(key: dict[str, Any], pct: float, lang: str = "en",
              figures: int = 6) -> Iterator[Question]:
    """The questions of an answer key: each finite value of each row at each position."""
    phis = key.get("phi_deg", [])
    scale = {row["kind"]: max((abs(x) for x in row["values"] if x is not None), default=0.0)
             for row in key.get("rows", [])}
    for row in key.get("rows", []):
        unit = message(UNITS[row["kind"]], lang) if row["kind"] in UNITS else ""
        floor = scale.get(row["kind"], 0.0) * pct / 100.0 * 0.05 or 1e-9
        for phi, value in zip(phis, row["values"], strict=False):
            if value is None or not math.isfinite(value):
                continue
            angle = trimmed(phi, 2, lang)
            yield Question(f"{key.get('id', '')} {row['quantity']} φ={angle}°",
                           message("lms.quiz.question", lang, quantity=row["quantity"],
                                   phi=angle, unit=unit),
                           lms_number(value, figures), tolerance(value, pct, floor),
                           value, unit)


def moodle_quiz(keys: Iterable[tuple[str, dict[str, Any]]], pct: float,
                lang: str = "en") -> bytes:
    """Moodle XML of numerical questions: ``keys`` are (category, answer key) pairs; each
    value of a key at each position is one question."""
    quiz = ET.Element("quiz")
    for category, key in keys:
        _category(quiz, f"mechplan/{category}")
        for question in questions(key, pct, lang):
            q = ET.SubElement(quiz, "question", {"type": "numerical"})
            _text(q, "name", question.name)
            _text(q, "questiontext", question.text, format="html")
            ET.SubElement(q, "defaultgrade").text = "1"
            answer = _text(q, "answer", question.answer, fraction="100",
                           format="moodle_auto_format")
            ET.SubElement(answer, "tolerance").text = lms_number(question.tolerance, 3)
            unit = question.unit
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


QTI = "http://www.imsglobal.org/xsd/ims_qtiasiv1p2"
MANIFEST = "http://www.imsglobal.org/xsd/imsccv1p1/imscp_v1p1"


def _field(parent: ET.Element, label: str, entry: str) -> None:
    f = ET.SubElement(parent, "qtimetadatafield")
    ET.SubElement(f, "fieldlabel").text = label
    ET.SubElement(f, "fieldentry").text = entry


def _qti_assessment(ident: str, title: str, key: dict[str, Any], pct: float, lang: str) -> bytes:
    """One quiz in QTI 1.2 as Canvas imports it: numerical questions answered within a range."""
    root = ET.Element("questestinterop", {"xmlns": QTI})
    test = ET.SubElement(root, "assessment", {"ident": ident, "title": title})
    section = ET.SubElement(test, "section", {"ident": "root_section"})
    for n, q in enumerate(questions(key, pct, lang), 1):
        item = ET.SubElement(section, "item", {"ident": f"{ident}_q{n}", "title": q.name})
        meta = ET.SubElement(ET.SubElement(item, "itemmetadata"), "qtimetadata")
        _field(meta, "question_type", "numerical_question")
        _field(meta, "points_possible", "1.0")
        pres = ET.SubElement(item, "presentation")
        ET.SubElement(ET.SubElement(pres, "material"), "mattext",
                      {"texttype": "text/html"}).text = q.text
        resp = ET.SubElement(pres, "response_str", {"ident": "response1",
                                                    "rcardinality": "Single"})
        ET.SubElement(ET.SubElement(resp, "render_fib", {"fibtype": "Decimal"}),
                      "response_label", {"ident": "answer1"})
        proc = ET.SubElement(item, "resprocessing")
        ET.SubElement(ET.SubElement(proc, "outcomes"), "decvar",
                      {"maxvalue": "100", "minvalue": "0", "varname": "SCORE",
                       "vartype": "Decimal"})
        cond = ET.SubElement(proc, "respcondition", {"continue": "No"})
        either = ET.SubElement(ET.SubElement(cond, "conditionvar"), "or")
        ET.SubElement(either, "varequal", {"respident": "response1"}).text = q.answer
        within = ET.SubElement(either, "and")
        ET.SubElement(within, "vargte", {"respident": "response1"}).text = lms_number(
            q.value - q.tolerance, 6)
        ET.SubElement(within, "varlte", {"respident": "response1"}).text = lms_number(
            q.value + q.tolerance, 6)
        ET.SubElement(cond, "setvar", {"action": "Set", "varname": "SCORE"}).text = "100"
    ET.indent(root)
    return b'<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, encoding="utf-8")


def canvas_qti(keys: Iterable[tuple[str, dict[str, Any]]], pct: float, lang: str = "en") -> bytes:
    """A Canvas QTI 1.2 package (zip): one quiz per (title, answer key), with its manifest."""
    import hashlib
    import io
    import zipfile

    manifest = ET.Element("manifest", {"identifier": "mechplan_quizzes", "xmlns": MANIFEST})
    meta = ET.SubElement(manifest, "metadata")
    ET.SubElement(meta, "schema").text = "IMS Content"
    ET.SubElement(meta, "schemaversion").text = "1.1.3"
    ET.SubElement(manifest, "organizations")
    resources = ET.SubElement(manifest, "resources")
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zf:
        for title, key in keys:
            ident = "g" + hashlib.sha256(title.encode()).hexdigest()[:24]
            zf.writestr(f"{ident}/{ident}.xml", _qti_assessment(ident, title, key, pct, lang))
            res = ET.SubElement(resources, "resource", {"identifier": ident,
                                                         "type": "imsqti_xmlv1p2"})
            ET.SubElement(res, "file", {"href": f"{ident}/{ident}.xml"})
        ET.indent(manifest)
        zf.writestr("imsmanifest.xml", b'<?xml version="1.0" encoding="UTF-8"?>\n'
                    + ET.tostring(manifest, encoding="utf-8"))
    return buf.getvalue()
