"""Write PNG previews of every template's sheets to drawings/previews/ (60 dpi, for the README).

Run: PYTHONPATH=src python tools/previews.py
"""

from __future__ import annotations

from pathlib import Path

from PIL import Image

from mechplan.render import write
from mechplan.studies import solve_file

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    out = ROOT / "drawings" / "previews"
    out.mkdir(parents=True, exist_ok=True)
    for path in sorted((ROOT / "templates").glob("*.toml")):
        for sheet in solve_file(str(path)).sheets(None, None, None, path.stem):
            (png,) = write(sheet, out, ["png"], png_dpi=60)
            # line art: 16 grey levels keep the previews small
            Image.open(png).convert("L").quantize(16).save(png, optimize=True)
            print(png)


if __name__ == "__main__":
    main()
