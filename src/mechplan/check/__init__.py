"""Check a submission (a hand-drawn DXF or a table of measured values) against the exact plans.

``check(scene, submission, Options(at_deg=60))`` returns a :class:`CheckReport` with a row per
segment and named value (submitted, exact, error in mm and %, direction error, verdict, cause and
hint) and the root causes found (new errors, swapped labels, arithmetic slips).
``report.text(lang)``, ``report.to_json(lang)`` and the overlay write it in en, ru, vi or zh (one
catalogue of messages: :mod:`mechplan.check.texts`); the report's own fields stay in English.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ..submission.read import Submission, read_submission
    from .grade import Options, check
    from .report import CheckReport, Finding, PlanReport, PointRow, SegmentRow, Tolerance, ValueRow

#: public name → the module that defines it; imported on first use, so that importing a light
#: module of the package (its texts for the command line's help) does not load the checker
_HOME = {"Submission": "..submission.read", "read_submission": "..submission.read",
         "Options": ".grade", "check": ".grade", **{name: ".report" for name in (
             "CheckReport", "Finding", "PlanReport", "PointRow", "SegmentRow", "Tolerance",
             "ValueRow")}}


def __getattr__(name: str) -> Any:
    if name not in _HOME:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(importlib.import_module(_HOME[name], __name__), name)

__all__ = ["CheckReport", "Finding", "Options", "PlanReport", "PointRow", "SegmentRow",
           "Submission", "Tolerance", "ValueRow", "check", "read_submission"]
