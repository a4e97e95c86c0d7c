"""Render one page of the note in each tradition's layout to docs/note/page-<tradition>.png,
and, where LibreOffice is installed, the ГОСТ page of the DOCX as LibreOffice lays it out
(docs/note/docx-page-gost.png).

Run: .venv/bin/python tools/note_pages.py  (needs pdfplumber, from the test extra)
"""

from __future__ import annotations

import shutil
import subprocess
import tempfile
from pathlib import Path

import pdfplumber

from mechplan.note.project import run_project

ROOT = Path(__file__).resolve().parents[1]
TEMPLATES = ROOT / "src" / "mechplan" / "templates"
CASES = {"gost": ("ru", "Курсовой проект по ТММ", "ТММ.01.00.00 ПЗ"),
         "tcvn": ("vi", "Đồ án nguyên lý máy", ""),
         "gb": ("zh", "机械原理课程设计", ""),
         "plain": ("en", "Term project: theory of machines", "")}


def main() -> None:
    out = ROOT / "docs" / "note"
    out.mkdir(parents=True, exist_ok=True)
    for tradition, (lang, title, code) in CASES.items():
        with tempfile.TemporaryDirectory() as tmp:
            project = Path(tmp) / f"{tradition}.toml"
            project.write_text(
                f'[project]\ntitle = "{title}"\nlanguage = "{lang}"\ntradition = "{tradition}"\n'
                f'code = "{code}"\nstudent = "A. Student"\n[studies]\n'
                f'linkage = "{(TEMPLATES / "v_engine.toml").as_posix()}"\n', encoding="utf-8")
            run_project(project, Path(tmp) / "out", ("pdf", "docx"))
            with pdfplumber.open(Path(tmp) / "out" / f"{tradition}-note.pdf") as pdf:
                pdf.pages[2].to_image(resolution=60).save(out / f"page-{tradition}.png")
            print(out / f"page-{tradition}.png")
            soffice = shutil.which("soffice")
            if tradition == "gost" and soffice:
                subprocess.run([soffice, "--headless", f"-env:UserInstallation=file://{tmp}/lo",
                                "--convert-to", "pdf", "--outdir", f"{tmp}/lo",
                                f"{tmp}/out/gost-note.docx"], check=True, capture_output=True)
                with pdfplumber.open(Path(tmp) / "lo" / "gost-note.pdf") as pdf:
                    pdf.pages[2].to_image(resolution=60).save(out / "docx-page-gost.png")
                print(out / "docx-page-gost.png")


if __name__ == "__main__":
    main()
