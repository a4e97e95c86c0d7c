"""The page of each tradition (sizes in mm), shared by the DOCX and the PDF writers.

- ``gost``: ГОСТ 2.105 / 2.104 text document: A4, a frame 20 mm from the left edge and 5 mm from
  the others, the main inscription of a text document at the foot (form 2a, 185 × 15 mm; form 2,
  185 × 40 mm, on the first page after the title page in the PDF).
- ``tcvn``: the Vietnamese university layout (left 30, right 20, top and bottom 20 mm), no frame.
- ``gb``: GB/T 7713 style report (top 25, bottom 20, left 25, right 20 mm), a rule under the
  running head.
- ``plain``: an English report, 25 mm all round.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True, slots=True)
class Page:
    """Margins of the text area (mm) and the frame, if the tradition draws one."""

    left: float
    right: float
    top: float
    bottom: float
    frame: bool = False
    frame_left: float = 20.0
    frame_other: float = 5.0
    stamp_height: float = 15.0          # form 2a
    first_stamp_height: float = 40.0    # form 2
    running_head: bool = False
    font_pt: float = 12.0
    line_spacing: float = 1.15


PAGE_W, PAGE_H = 210.0, 297.0

PAGES: dict[str, Page] = {
    "gost": Page(left=30, right=10, top=15, bottom=25, frame=True, font_pt=14,
                 line_spacing=1.5),
    "tcvn": Page(left=30, right=20, top=20, bottom=20, font_pt=13, line_spacing=1.3),
    "gb": Page(left=25, right=20, top=25, bottom=20, running_head=True, font_pt=12),
    "plain": Page(left=25, right=25, top=25, bottom=25, font_pt=11),
}
