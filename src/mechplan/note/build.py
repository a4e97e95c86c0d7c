"""Assemble a note from a solved project: title data, one chapter per study, the figures."""

from __future__ import annotations

import datetime
from typing import Any

from ..i18n import message
from .chapters import cam_blocks, dynamics_blocks, engine_blocks, gears_blocks
from .model import Block, Figure, Heading, Meta, Note, Paragraph

#: the words of the title page and the frames, said in the note's language
_LABELS = ("note", "student", "group", "variant", "instructor", "school", "year", "sheet",
           "sheets", "changed", "signature", "date", "developed", "checked", "contents",
           "letter")


def _m(key: str, lang: str, **values: Any) -> str:
    return message(f"note.{key}", lang, **values)


def build_note(project: Any, solved: dict[str, Any], sheets: list[Any],
               png_dpi: float = 110.0) -> Note:
    """The note of a solved project (``solved``: role → study; ``sheets``: their sheets, shown
    as figures in the chapter of their study)."""
    lang = project.language
    people = dict(project.people)
    people["year"] = people.get("year") or str(datetime.date.today().year)
    meta = Meta(title=project.title or next(iter(solved.values())).to_json().get("title", ""),
                language=lang, tradition=project.tradition,
                labels={k: _m(f"label.{k}", lang) for k in _LABELS},
                **{k: people.get(k, "") for k in ("student", "group", "variant", "instructor",
                                                  "school", "year", "code")})
    blocks: list[Block] = [Heading(_m("h.task", lang), 1, "task"),
                           Paragraph(_m("p.task", lang, title=meta.title))]
    for role, study in solved.items():
        doc = study.to_json()
        blocks.append(Paragraph(_m(f"p.task.{role}", lang, title=doc.get("title", ""))))
    for role, study in solved.items():
        doc = study.to_json()
        if role == "linkage":
            from .linkage import linkage_blocks

            blocks += linkage_blocks(study, doc, lang)
            if "dynamics" in doc:
                blocks += dynamics_blocks(doc["dynamics"], lang)
        elif role == "engine":
            blocks += engine_blocks(doc, lang)
        elif role == "gears":
            blocks += gears_blocks(doc, lang)
        elif role == "cam":
            blocks += cam_blocks(doc, lang)
        blocks += _figures(sheets, f"-{role}", lang, png_dpi)
    blocks += [Heading(_m("h.conclusion", lang), 1, "conclusion"),
               Paragraph(_m("p.conclusion", lang)),
               Heading(_m("h.references", lang), 1, "references")]
    blocks += [Paragraph(f"{i}. {_m(f'ref.{i}', lang)}") for i in (1, 2, 3)]
    return Note(meta, tuple(blocks))


def _figures(sheets: list[Any], tag: str, lang: str, dpi: float) -> list[Block]:
    from ..render import mpl, svg

    out: list[Block] = []
    for sheet in sheets:
        if tag not in sheet.name:
            continue
        title = sheet.attributes.get("title", "") or sheet.name
        out.append(Figure(_m("figure.sheet", lang, name=sheet.name, title=title),
                          svg.to_svg(sheet).encode("utf-8"),
                          mpl.to_bytes(sheet, "png", dpi=dpi), sheet.width_mm, sheet.height_mm))
    return out
