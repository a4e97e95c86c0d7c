"""Measure how much of each sheet its panels cover, for every template at every size A4–A0.

Coverage of a sheet = the sum of the areas of its panels' bounding boxes (each panel's drawing,
titles and tables; the 8 mm gaps between panels not counted) / the area of its drawing area
(inside the frame, clear of the centring marks and the title block — ``layout.drawing_area``).
A set of sheets is what one layout frames together (a linkage's kinematics and kinetostatics,
a dynamics or engine set, …); its last sheet holds what is left over and may be partial, every
other sheet is *full* and should be covered ≥ 55 %.

Run: PYTHONPATH=src python tools/coverage.py [--write]   (--write: the table into docs/sheets.md)
"""

from __future__ import annotations

import argparse
import re
import sys
import textwrap
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from mechplan.sheet import compose as compose_module
from mechplan.sheet import layout
from mechplan.sheet.frame import make_frame
from mechplan.studies import solve_file

ROOT = Path(__file__).resolve().parents[1]
SIZES = ("A4", "A3", "A2", "A1", "A0")
GOAL = 0.55
BEGIN, END = "<!-- coverage:begin -->", "<!-- coverage:end -->"


def covered(placed, area_mm2: float) -> float:
    """The share of the drawing area covered by the boxes of the panels placed on a sheet."""
    total = 0.0
    for panel, _offset in placed:
        x0, y0, x1, y1 = panel.bounds()
        total += (x1 - x0) * (y1 - y0)
    return total / area_mm2


@contextmanager
def recorded() -> Iterator[list[list[float]]]:
    """Collect the coverage of every set of sheets framed while inside (one list per set)."""
    sets: list[list[float]] = []
    original = layout.framed

    def framed(placements, *, size, standard, language, name, fields):
        area = layout.drawing_area(make_frame(size, standard, dict(fields), language=language))
        sets.append([covered(placed, area.area) for placed in placements])
        return original(placements, size=size, standard=standard, language=language, name=name,
                        fields=fields)

    layout.framed = framed                       # type: ignore[assignment]
    compose_module.framed = framed               # type: ignore[attr-defined]
    try:
        yield sets
    finally:
        layout.framed = original
        compose_module.framed = original         # type: ignore[attr-defined]


def measure(path: Path) -> dict[str, list[list[float]]]:
    """Per size, the coverage of each sheet of each set of the template's sheets."""
    study = solve_file(str(path))
    out = {}
    for size in SIZES:
        with recorded() as sets:
            study.sheets(size, None, None, path.stem)
        out[size] = sets
    return out


def cell(sets: list[list[float]]) -> str:
    """ "62 58 · 31 %": the sets' sheets; a full sheet under the goal in bold."""
    parts = []
    for covered in sets:
        texts = [f"**{c * 100:.0f}**" if i < len(covered) - 1 and c < GOAL else f"{c * 100:.0f}"
                 for i, c in enumerate(covered)]
        parts.append(" ".join(texts))
    return " · ".join(parts) + " %"


def table(results: dict[str, dict[str, list[list[float]]]]) -> str:
    """The markdown table and its summary lines."""
    lines = ["| template | " + " | ".join(SIZES) + " |", "|---" * (len(SIZES) + 1) + "|"]
    full: list[float] = []
    sheets = 0
    for name, by_size in results.items():
        lines.append(f"| {name} | " + " | ".join(cell(by_size[s]) for s in SIZES) + " |")
        for sets in by_size.values():
            for covered in sets:
                full += covered[:-1]
                sheets += len(covered)
    under = sum(c < GOAL for c in full)
    summary = (f"{sheets} sheets; {len(full)} full sheets (not the last of their set), "
               f"{under} of them under {GOAL:.0%}; the lowest full sheet "
               f"{min(full) * 100:.0f} %, the mean of the full sheets "
               f"{sum(full) / len(full) * 100:.0f} %.")
    lines += ["", *textwrap.wrap(summary, 100)]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--write", action="store_true", help="write the table into docs/sheets.md")
    parser.add_argument("templates", nargs="*", help="template stems (default: all)")
    args = parser.parse_args(argv)
    paths = sorted((ROOT / "templates").glob("*.toml"))
    if args.templates:
        paths = [p for p in paths if p.stem in args.templates]
    results = {}
    for path in paths:
        results[path.stem] = measure(path)
        print(path.stem, {s: cell(v) for s, v in results[path.stem].items()}, file=sys.stderr)
    text = table(results)
    print(text)
    if args.write:
        doc = ROOT / "docs" / "sheets.md"
        old = doc.read_text(encoding="utf-8")
        new, n = re.subn(re.escape(BEGIN) + ".*?" + re.escape(END),
                         lambda _m: f"{BEGIN}\n{text}\n{END}", old, flags=re.DOTALL)
        if n != 1:
            raise SystemExit(f"docs/sheets.md must hold one {BEGIN} … {END} block")
        doc.write_text(new, encoding="utf-8")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
