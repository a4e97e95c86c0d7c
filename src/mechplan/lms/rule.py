"""The grading rule an instructor states in TOML: points per checked item (per plan), what a
mistake costs (new, carried, swapped, small errors adding up, arithmetic slips, missing items),
the tolerances, the grade scale. ``DEFAULT_RULE`` is the documented default (docs/classes.md)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import CheckError
from ..userfiles import SCENE, read_text
from .texts import say

DEFAULT_RULE = """\
# mechplan grading rule (docs/classes.md). Every key may be left out: the default is shown.
max_grade = 100        # the grade of a submission with everything right (Moodle's Maximum Grade)
decimals = 1           # digits after the point in the grade
nothing_found = 0      # grade when nothing gradeable was found ("" leaves the cell empty)
unreadable = ""        # grade when the file could not be read or matched ("" leaves it empty)

[points]               # points of one checked segment / value, by plan ("values": table values)
default = 1.0
position = 1.0
velocity = 1.0
acceleration = 1.0
force = 1.0
values = 1.0

[penalty]              # share of an item's points lost, by what went wrong
new = 1.0              # a new mistake
carried = 0.25         # right from the student's own wrong earlier point
swapped = 0.5          # labels swapped
accumulated = 0.25     # small errors adding up
slip = 0.5             # arithmetic slip (length × μ written wrong)
missing = 1.0          # asked for, not on the submission

[tolerance]            # as mechplan check --tolerance: mm on paper, % of the length
mm = 1.0
pct = 2.0

[canvas]
assignment = "Course project"   # the gradebook column is "assignment (assignment_id)"
assignment_id = ""
"""

PENALTIES = ("new", "carried", "swapped", "accumulated", "slip", "missing")


@dataclass
class Rule:
    """A grading rule."""

    max_grade: float = 100.0
    decimals: int = 1
    nothing_found: float | None = 0.0
    unreadable: float | None = None
    points: dict[str, float] = field(default_factory=dict)
    penalty: dict[str, float] = field(default_factory=dict)
    tolerance_mm: float = 1.0
    tolerance_pct: float = 2.0
    assignment: str = "Course project"
    assignment_id: str = ""

    def points_of(self, plan: str) -> float:
        """Points of one item of a plan."""
        return self.points.get(plan, self.points.get("default", 1.0))


def _number(doc: dict[str, Any], key: str, file: str, low: float = 0.0,
            high: float = 1e9) -> float:
    value = doc[key]
    if isinstance(value, bool) or not isinstance(value, int | float) or not (
            math.isfinite(value) and low <= value <= high):
        raise CheckError(say("rule_number", low=low, high=high, value=repr(value)), file=file,
                         key=key)
    return float(value)


def _optional(doc: dict[str, Any], key: str, file: str) -> float | None:
    return None if doc.get(key) == "" else _number(doc, key, file)


def parse_rule(text: str, file: str = "<rule>") -> Rule:
    """A rule from TOML text (keys left out keep the default)."""
    from ..scene.document import parse_toml

    given = parse_toml(text, file)
    doc = parse_toml(DEFAULT_RULE, "<default rule>")
    for k, v in given.items():
        if k not in doc:
            raise CheckError(say("rule_key", keys=", ".join(doc)), file=file, key=k)
        if isinstance(doc[k], dict):
            if not isinstance(v, dict):
                raise CheckError(say("rule_key", keys=", ".join(doc)), file=file, key=k)
            doc[k] = {**doc[k], **v}
        else:
            doc[k] = v
    points = {k: _number(doc["points"], k, file, 0, 1e6) for k in doc["points"]}
    penalty = {k: _number(doc["penalty"], k, file, 0, 1) for k in doc["penalty"]}
    unknown = set(penalty) - set(PENALTIES)
    if unknown:
        raise CheckError(say("rule_key", keys=", ".join(PENALTIES)), file=file,
                         key="penalty." + min(unknown))
    canvas = doc["canvas"]
    return Rule(_number(doc, "max_grade", file, 0, 1e6),
                int(_number(doc, "decimals", file, 0, 6)),
                _optional(doc, "nothing_found", file), _optional(doc, "unreadable", file),
                points, penalty, _number(doc["tolerance"], "mm", file, 0, 1e4),
                _number(doc["tolerance"], "pct", file, 0, 100),
                str(canvas.get("assignment", "")), str(canvas.get("assignment_id", "")))


def load_rule(path: Path | None) -> Rule:
    """The rule of a TOML file, or the default."""
    if path is None:
        return parse_rule(DEFAULT_RULE, "<default rule>")
    return parse_rule(read_text(path, SCENE, error=CheckError), str(path))


@dataclass
class Grade:
    """A submission's grade and how it was reached."""

    grade: float | None
    earned: float
    possible: float
    lost: dict[str, float]           # points lost by cause


def grade_report(report: Any, rule: Rule) -> Grade:
    """Grade a check report by the rule: every checked or missing row is worth its plan's
    points; a wrong row loses its cause's share, a slip or a missing row theirs."""
    from ..check.report import CARRIED, MISSING, NEW, OK, REFERENCE, SLIP, WRONG

    if report.nothing_found:
        return Grade(rule.nothing_found, 0.0, 0.0, {})
    possible, lost = 0.0, dict.fromkeys(PENALTIES, 0.0)
    items = [(p.plan, s) for p in report.plans for s in p.segments] + \
            [("values", v) for v in report.values]
    for plan, row in items:
        if row.verdict not in (OK, REFERENCE, WRONG, SLIP, MISSING):
            continue
        pts = rule.points_of(plan)
        possible += pts
        cause = {WRONG: row.cause if row.cause in PENALTIES else NEW, SLIP: "slip",
                 MISSING: "missing"}.get(row.verdict)
        if cause is not None:
            lost[cause] += pts * rule.penalty.get(cause, 1.0 if cause != CARRIED else 0.25)
    earned = max(possible - sum(lost.values()), 0.0)
    grade = round(rule.max_grade * earned / possible, rule.decimals) if possible else \
        rule.nothing_found
    return Grade(grade, earned, possible, {k: v for k, v in lost.items() if v})
