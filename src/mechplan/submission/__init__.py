"""What a student handed in, read from its file before it means anything.

A hand-drawn DXF becomes lines, arrowheads, point markers and texts with their boxes (``dxf``); a
TOML/CSV table becomes ``name = value`` entries (``read``); a study's answer table becomes named
answers with their angles (``answer_table``); the lines of a drawing become a graph of points,
and its label texts the points they stand for (``sketch``), grouped into the plans drawn on the
sheet (``drawn_plans``) by the readings a :class:`~.labels.LabelBook` offers; labels, names,
numbers and units are read as students write them in four traditions (``written``, ``labels``,
``notation`` with its catalogue ``notation.toml``). Each item keeps where it came from (file,
entity handle, line). Nothing here knows a construction (the checker fills the label book from
one; step ids are opaque strings here): :mod:`mechplan.check` gives what was read its meaning and
grades it. Like :mod:`mechplan.scene`, this is where strings from a user's files stop.
"""

from .read import DrawnLine, Entry, Note, SheetText, Submission, read_submission

__all__ = ["DrawnLine", "Entry", "Note", "SheetText", "Submission", "read_submission"]
