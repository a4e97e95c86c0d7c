"""The quizzes against their schemas: mechplan's Moodle XML bank and Canvas QTI package validate;
a quiz broken the ways an import fails (no answer, a bad tolerance, no 100 % answer, a number
Moodle cannot read, an empty range) does not."""

from __future__ import annotations

import io
import json
import re
import zipfile

import pytest

from mechplan.lms.quiz import canvas_qti, moodle_quiz
from mechplan.lms.validate import canvas_package_errors, moodle_quiz_errors, qti_errors


@pytest.fixture(scope="module")
def keys(small_class):
    _, variants, _ = small_class
    out = {v: json.loads((variants / v / "answer_key.json").read_text(encoding="utf-8"))
           for v in ("v1", "v2")}
    short = out["v2"]                     # two positions of v2 are enough for a second category
    short["phi_deg"] = short["phi_deg"][:2]
    for row in short["rows"]:
        row["values"] = row["values"][:2]
    return out


@pytest.fixture(scope="module")
def bank(keys):
    return moodle_quiz([(f"Ann Lee 201 — {v}", k) for v, k in keys.items()], 2.0).decode()


def test_our_moodle_bank_validates(bank):
    assert moodle_quiz_errors(bank.encode()) == []
    assert bank.count('type="numerical"') > 100


def test_numbers_near_zero_are_written_as_moodle_reads_them(bank):
    answers = re.findall(r"<answer[^>]*>\s*<text>([^<]*)</text>", bank)
    tolerances = re.findall(r"<tolerance>([^<]*)</tolerance>", bank)
    assert answers and len(answers) == len(tolerances)
    for text in answers + tolerances:
        float(text)                    # "1.34e-15", never "1.34×10⁻¹⁵"
    assert any("e-" in a for a in answers)    # the key has values that are zero to rounding


def _first_numerical(bank: str) -> tuple[int, int]:
    start = bank.index('<question type="numerical">')
    return start, bank.index("</question>", start) + len("</question>")


@pytest.mark.parametrize("break_it, why", [
    (lambda q: re.sub(r"<answer .*?</answer>", "", q, flags=re.DOTALL), "missing answer"),
    (lambda q: re.sub(r"<tolerance>[^<]*<", "<tolerance>abc<", q), "tolerance not a number"),
    (lambda q: re.sub(r"<tolerance>[^<]*<", "<tolerance>-0.5<", q), "negative tolerance"),
    (lambda q: q.replace('fraction="100"', 'fraction="50"'), "no answer worth 100 %"),
    (lambda q: q.replace('fraction="100" ', ""), "answer without a grade"),
    (lambda q: re.sub(r"(<answer [^>]*>\s*<text>)[^<]*", r"\g<1>1.3×10⁻⁵", q), "×10 notation"),
    (lambda q: q.replace('type="numerical"', 'type="numeric"'), "unknown question type"),
    (lambda q: re.sub(r"<name>\s*<text>[^<]*</text>", "<name><text> </text>", q), "no name"),
    (lambda q: q.replace("<showunits>3</showunits>", "<showunits>7</showunits>"), "showunits"),
])
def test_a_broken_moodle_question_does_not_validate(bank, break_it, why):
    start, end = _first_numerical(bank)
    broken = bank[:start] + break_it(bank[start:end]) + bank[end:]
    assert broken != bank, why
    errors = moodle_quiz_errors(broken.encode())
    assert errors, why
    assert all("question[" in e for e in errors), errors


def test_a_category_must_name_a_context(bank):
    broken = bank.replace("$course$/top/", "top/", 1)
    assert moodle_quiz_errors(broken.encode())


def test_other_question_types_are_accepted_by_name(bank):
    extra = ('<question type="multichoice"><name><text>x</text></name><answer fraction="100">'
             "<text>a</text></answer></question>\n</quiz>")
    assert moodle_quiz_errors(bank.replace("</quiz>", extra).encode()) == []


@pytest.fixture(scope="module")
def package(keys):
    return canvas_qti([(f"mechplan {v}", k) for v, k in keys.items()], 2.0)


def test_our_canvas_package_validates(package):
    assert canvas_package_errors(package) == []


def _assessment(package) -> str:
    with zipfile.ZipFile(io.BytesIO(package)) as zf:
        name = next(n for n in zf.namelist() if n != "imsmanifest.xml")
        return zf.read(name).decode()


@pytest.mark.parametrize("break_it, why", [
    (lambda t: re.sub(r"(<vargte [^>]*>)([^<]*)(</vargte>\s*<varlte [^>]*>)([^<]*)",
                      r"\g<1>\g<4>\g<3>\g<2>", t, count=1), "an empty range (bounds swapped)"),
    (lambda t: re.sub(r"(<varlte [^>]*>)[^<]*", r"\g<1>abc", t, count=1), "bound not a number"),
    (lambda t: t.replace(' ident="response1"', "", 1), "response without ident"),
    (lambda t: t.replace("<resprocessing>", "<resprocessing><itemfeedback/>", 1),
     "element outside QTI's content model"),
    (lambda t: t.replace('fibtype="Decimal"', 'fibtype="Float"', 1), "fibtype"),
])
def test_a_broken_qti_item_does_not_validate(package, break_it, why):
    text = _assessment(package)
    assert qti_errors(text.encode()) == []
    broken = break_it(text)
    assert broken != text, why
    assert qti_errors(broken.encode()), why


def test_a_manifest_naming_a_missing_file_is_refused(package):
    buf = io.BytesIO()
    with zipfile.ZipFile(io.BytesIO(package)) as zin, zipfile.ZipFile(buf, "w") as zout:
        for name in zin.namelist():
            if name == "imsmanifest.xml":      # every assessment left out
                zout.writestr(name, zin.read(name))
    errors = canvas_package_errors(buf.getvalue())
    assert errors and all("listed, not in the package" in e for e in errors)
