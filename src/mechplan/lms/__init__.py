"""The instructors' round trip with their LMS (Moodle, Canvas): submission archives in, grading
worksheets, feedback files and gradebooks out, variants as quizzes, same-work evidence."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from .run import RoundTrip, round_trip

__all__ = ["RoundTrip", "round_trip"]


def __getattr__(name: str) -> Any:
    # imported on first use: `mechplan --help` builds the check options from lms.cli alone
    if name in __all__:
        from . import run

        return getattr(run, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
