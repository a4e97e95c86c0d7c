"""Write the live page of a solved scene: ``draw --format html`` (see docs/html.md)."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from .errors import DrawingError
from .i18n import message


def page_text(study: Any, size: str | None = None, standard: str | None = None,
              language: str | None = None, name: str = "scene", frames: int | None = None) -> str:
    """The HTML text of the live page of a solved study (a linkage: ``MechanismStudy``).

    The scale factors are the sheet's (``size``, ``standard``: the scene's own by default), so
    the paper millimetres on the page are those of the drawing.
    """
    from .render.html import to_html
    from .sheet.live import FRAMES, live_document
    from .studies.mechanism import MechanismStudy

    if not isinstance(study, MechanismStudy):
        kind = getattr(study, "kind", None) or type(study).__name__.removesuffix("Study").lower()
        raise DrawingError(message("html.kind_unsupported", language or "en", scene=name,
                                   kind=kind))
    sol = study.solution
    scene = sol.scene
    own = (size in (None, scene.drawing.sheet) and standard in (None, scene.drawing.standard))
    if own and sol.scales:
        mu = dict(sol.scales)
    else:
        from .sheet.scales import decide_scales

        mu = decide_scales(scene, sol.construction, sol.ev, sol.plans, size, standard)
    doc = live_document(sol, mu, language or scene.language, name, frames or FRAMES)
    return to_html(doc)


def write_page(study: Any, out: str | os.PathLike[str], name: str, *, size: str | None = None,
               standard: str | None = None, language: str | None = None,
               frames: int | None = None) -> Path:
    """Write ``<out>/<name>.html`` (whole or not at all) and return its path."""
    from .outputs import prepare_dir
    from .render.atomic import write_atomic

    text = page_text(study, size, standard, language, name, frames)   # before any file
    return write_atomic(prepare_dir(out) / f"{name}.html", text.encode("utf-8"))
