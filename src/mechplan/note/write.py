"""Write a note's files in memory: DOCX and PDF (see docs/note.md for the choice of tools)."""

from __future__ import annotations

from .model import Note


def note_files(note: Note, stem: str, formats: tuple[str, ...]) -> dict[str, bytes]:
    """``{file name: bytes}`` of the note in each format (``docx``, ``pdf``)."""
    files: dict[str, bytes] = {}
    if "docx" in formats:
        from .docx_writer import to_docx

        files[f"{stem}-note.docx"] = to_docx(note)
    if "pdf" in formats:
        from .typst_writer import to_pdf

        files[f"{stem}-note.pdf"] = to_pdf(note)
    return files
