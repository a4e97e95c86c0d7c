"""Check a submission (a hand-drawn DXF or a table of measured values) against the exact plans.

``check(scene, submission, Options(at_deg=60))`` returns a :class:`CheckReport` with a row per
segment and named value (submitted, exact, error in mm and %, direction error, verdict, cause and
hint) and the root causes found (new errors, swapped labels, arithmetic slips).
``report.text(lang)``, ``report.to_json(lang)`` and the overlay write it in en, ru, vi or zh (one
catalogue of messages: :mod:`mechplan.check.texts`); the report's own fields stay in English.
"""

from ..submission.read import Submission, read_submission
from .grade import Options, check
from .report import CheckReport, Finding, PlanReport, PointRow, SegmentRow, Tolerance, ValueRow

__all__ = ["CheckReport", "Finding", "Options", "PlanReport", "PointRow", "SegmentRow",
           "Submission", "Tolerance", "ValueRow", "check", "read_submission"]
