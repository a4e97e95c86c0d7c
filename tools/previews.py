"""Write PNG previews of the templates' sheets to drawings/previews/ (60 dpi, for the README).

Every template's own sheets go to drawings/previews/; one template per capability is also drawn on
A4 and A3 (drawings/previews/a4/, a3/) for docs/sheets.md.

Run: PYTHONPATH=src python tools/previews.py
"""

from __future__ import annotations

from pathlib import Path

from PIL import Image

from mechplan.render import write
from mechplan.studies import solve_file

ROOT = Path(__file__).resolve().parents[1]

#: the sizes students print their reports on, and one page per capability on them:
#: (template, the name of the sheet previewed)
SMALL_SIZES = ("A4", "A3")
CAPABILITIES = (("v_engine", "v_engine"), ("machine_unit", "machine_unit-dynamics"),
                ("motorcycle_engine", "motorcycle_engine"), ("cam_cycloidal", "cam_cycloidal"),
                ("planetary_two_row", "planetary_two_row"))


def _preview(path: Path, out: Path, size: str | None, only: str | None = None) -> None:
    out.mkdir(parents=True, exist_ok=True)
    for sheet in solve_file(str(path)).sheets(size, None, None, path.stem):
        if only is not None and sheet.name != only:
            continue
        (png,) = write(sheet, out, ["png"], png_dpi=60)
        # line art: 16 grey levels keep the previews small
        Image.open(png).convert("L").quantize(16).save(png, optimize=True)
        print(png)


def main() -> None:
    out = ROOT / "drawings" / "previews"
    for path in sorted((ROOT / "templates").glob("*.toml")):
        _preview(path, out, None)
    for size in SMALL_SIZES:
        for name, sheet in CAPABILITIES:
            _preview(ROOT / "templates" / f"{name}.toml", out / size.lower(), size, sheet)


if __name__ == "__main__":
    main()
