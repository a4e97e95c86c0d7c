"""A course project: the studies of one student's project, their sheets and the note.

A project file (TOML) names its studies by role — ``linkage`` (a mechanism scene, with its
``[dynamics]`` when it has one), ``engine``, ``gears``, ``cam`` — with paths relative to the
project file, and the title-page data: student, group, variant, instructor, school, tradition and
language. See docs/note.md.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import MechplanError, SceneError
from ..i18n import LANGUAGES, Text

#: the roles a project may fill, in the note's order, and the scene kind each one takes
ROLES: dict[str, str] = {"linkage": "mechanism", "engine": "engine", "gears": "gears",
                         "cam": "cam"}
TRADITIONS: tuple[str, ...] = ("gost", "tcvn", "gb", "plain")
DEFAULT_TRADITION = {"ru": "gost", "vi": "tcvn", "zh": "gb", "en": "plain"}
_STANDARD = {"gost": "gost", "tcvn": "tcvn", "gb": "iso", "plain": "iso"}
_PEOPLE = ("student", "group", "variant", "instructor", "school", "year", "code")


@dataclass(frozen=True)
class Project:
    """A parsed project file: its studies by role and the title page."""

    file: str
    title: str
    language: str
    tradition: str
    studies: dict[str, Path]
    people: dict[str, str] = field(default_factory=dict)
    sheet: str | None = None

    @property
    def standard(self) -> str:
        """The drafting standard of the sheets (gost, tcvn, iso; a GB sheet is drawn as ISO)."""
        return _STANDARD[self.tradition]


def _text(table: dict[str, Any], key: str, file: str, where: str) -> str:
    value = table.get(key, "")
    if not isinstance(value, (str, int)) or isinstance(value, bool):
        raise SceneError(Text("errmsg3.project.must_be_text", {
            "where": where, "key": key, "type": type(value).__name__}), file=file,
                         key=f"{where}.{key}")
    return str(value)


def read_project(path: str | os.PathLike[str]) -> Project:
    """Read and check a project file; every study file must exist and be of its role's kind."""
    from ..scene.document import parse_toml, read_text, scene_kind

    file = str(path)
    data = parse_toml(read_text(Path(path)), file)
    head = data.get("project", {})
    if not isinstance(head, dict):
        raise SceneError(Text("errmsg3.project.not_table"), file=file, key="project")
    unknown = sorted(set(head) - {"title", "language", "tradition", "sheet", *_PEOPLE})
    if unknown:
        raise SceneError(Text("errmsg3.project.unknown_keys", {"keys": unknown}), file=file,
                         key=f"project.{unknown[0]}")
    language = _text(head, "language", file, "project") or "en"
    if language not in LANGUAGES:
        raise SceneError(Text("errmsg3.project.language", {
            "languages": list(LANGUAGES), "value": repr(language)}),
            file=file, key="project.language")
    tradition = _text(head, "tradition", file, "project") or DEFAULT_TRADITION[language]
    if tradition not in TRADITIONS:
        raise SceneError(Text("errmsg3.project.tradition", {
            "traditions": list(TRADITIONS), "value": repr(tradition)}),
            file=file, key="project.tradition")
    raw = data.get("studies")
    if not isinstance(raw, dict) or not raw:
        raise SceneError(Text("errmsg3.project.no_studies"),
                         file=file, key="studies")
    base = Path(path).parent
    studies: dict[str, Path] = {}
    for role, rel in raw.items():
        if role not in ROLES:
            raise SceneError(Text("errmsg3.project.not_role", {"role": role, "roles": list(ROLES)}),
                             file=file, key=f"studies.{role}")
        if not isinstance(rel, str) or not rel:
            raise SceneError(Text("errmsg3.project.path", {"role": role}), file=file,
                             key=f"studies.{role}")
        p = (base / rel)
        if not p.is_file():
            raise SceneError(Text("errmsg3.project.missing_file", {"role": role, "path": rel}),
                             file=file, key=f"studies.{role}")
        kind = scene_kind(parse_toml(read_text(p), str(p)), str(p))
        if kind != ROLES[role]:
            raise SceneError(Text("errmsg3.project.wrong_kind", {
                "role": role, "wanted": repr(ROLES[role]), "kind": repr(kind), "path": rel}),
                file=file, key=f"studies.{role}")
        studies[role] = p
    sheet = head.get("sheet")
    order = list(ROLES)
    return Project(file=file, title=_text(head, "title", file, "project"), language=language,
                   tradition=tradition,
                   studies=dict(sorted(studies.items(), key=lambda kv: order.index(kv[0]))),
                   people={k: _text(head, k, file, "project") for k in _PEOPLE},
                   sheet=str(sheet) if sheet else None)


def solve_project(project: Project) -> dict[str, Any]:
    """Solve every study; a failing one raises an error naming its file."""
    from ..studies import solve_file

    solved: dict[str, Any] = {}
    for role, path in project.studies.items():
        try:
            solved[role] = solve_file(path)
        except MechplanError as exc:
            if exc.file:
                raise
            raise type(exc)(str(exc), file=str(path)) from None
    return solved


def run_project(path: str | os.PathLike[str], out_dir: str | os.PathLike[str],
                formats: tuple[str, ...] = ("docx", "pdf", "svg", "dxf"),
                figures: bool = True) -> list[Path]:
    """Solve a project and write its sheets and its note into ``out_dir``; return the files.

    Everything is computed and rendered in memory first: a study that fails leaves no file
    behind, and each file is replaced atomically.
    """
    from ..outputs import prepare_dir
    from ..render.atomic import write_atomic
    from .build import build_note
    from .write import note_files

    project = read_project(path)
    solved = solve_project(project)
    stem = Path(path).stem
    sheets = []
    for role, study in solved.items():
        sheets += study.sheets(project.sheet, project.standard, project.language,
                               f"{stem}-{role}")
    note = build_note(project, solved, sheets if figures else [])
    files: dict[str, bytes] = note_files(note, stem, tuple(f for f in formats
                                                           if f in ("docx", "pdf")))
    sheet_formats = [f for f in formats if f in ("svg", "dxf", "pdf", "png")]
    if sheet_formats:
        from ..render import _renderer

        for sheet in sheets:
            for fmt in sheet_formats:
                files[f"{sheet.name}.{fmt}"] = _renderer(fmt, 150.0)(sheet)
    out = prepare_dir(out_dir)
    written = []
    for name, data in files.items():
        target = out / name
        if target.resolve().parent != out.resolve():
            raise MechplanError(Text("errmsg3.project.leaves_output", {"name": repr(name)}))
        written.append(write_atomic(target, data))
    return written
