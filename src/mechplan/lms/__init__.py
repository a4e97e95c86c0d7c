"""The instructors' round trip with their LMS (Moodle, Canvas): submission archives in, grading
worksheets, feedback files and gradebooks out, variants as quizzes, same-work evidence."""

from __future__ import annotations

from .run import RoundTrip, round_trip

__all__ = ["RoundTrip", "round_trip"]
