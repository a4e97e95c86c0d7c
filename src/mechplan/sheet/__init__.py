"""Sheets presenting a solution (:mod:`.compose`, :mod:`.panels`, :mod:`.lever`).

The drafting names (primitives with layer roles, frames and title blocks) live in
:mod:`mechplan.drafting` and are re-exported here as before.
"""

from mechplan.drafting.frame import (
    PAPER_SIZES_MM,
    TITLE_FIELDS,
    FrameLayout,
    Orientation,
    Rect,
    Standard,
    make_frame,
    paper_size,
)
from mechplan.drafting.primitives import (
    DASH_PATTERNS_MM,
    ISO_3098_HEIGHTS_MM,
    LANGUAGES,
    ROLE_STYLES,
    Arc,
    Arrow,
    Block,
    Circle,
    HAlign,
    Line,
    LineType,
    Point,
    Polyline,
    Primitive,
    Role,
    RoleStyle,
    Sheet,
    Table,
    Text,
    VAlign,
)

__all__ = [
    "DASH_PATTERNS_MM", "ISO_3098_HEIGHTS_MM", "LANGUAGES", "PAPER_SIZES_MM", "ROLE_STYLES",
    "TITLE_FIELDS", "Arc", "Arrow", "Block", "Circle", "FrameLayout", "HAlign", "Line", "LineType",
    "Orientation", "Point", "Polyline", "Primitive", "Rect", "Role", "RoleStyle", "Sheet",
    "Standard", "Table", "Text", "VAlign", "make_frame", "paper_size",
]
