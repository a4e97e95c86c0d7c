"""Write the live page of a solved scene: ``draw --format html`` (see docs/html.md)."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from .i18n import DEFAULT_LANGUAGE


def page_text(study: Any, size: str | None = None, standard: str | None = None,
              language: str | None = None, name: str = "scene", frames: int | None = None) -> str:
    """The HTML text of the live page of a solved study (a linkage: ``MechanismStudy``).

    The scale factors are the sheet's (``size``, ``standard``: the scene's own by default), so
    the paper millimetres on the page are those of the drawing.
    """
    from .i18n import LANGUAGES
    from .render.html import to_html
    from .sheet.live import FRAMES, live_document, sheets_document
    from .studies.mechanism import MechanismStudy

    if not isinstance(study, MechanismStudy):        # cams, gears, engines: their sheets
        first = study.sheets(size, standard, language, name)
        lang = first[0].language if first else language or DEFAULT_LANGUAGE
        sheets = {lg: first if lg == lang else study.sheets(size, standard, lg, name)
                  for lg in LANGUAGES}
        doc = sheets_document(sheets, lang, name, name)
        from .studies.cam import CamStudy
        from .studies.engine import EngineStudy

        if isinstance(study, EngineStudy):          # the polar diagram traced as φ runs
            from .sheet.live_engine import engine_animation

            doc["animation"] = engine_animation(study)
        elif isinstance(study, CamStudy):           # inversion ray by ray; the cam turning
            from .sheet.live_cam import cam_animation, cam_replay

            replay, mu_cam = cam_replay(study.design)
            doc["replays"] = [replay]
            doc["animation"] = cam_animation(study.design, mu_cam)
        else:
            from .studies.gears import GearStudy

            res = study.solution.planetary if isinstance(study, GearStudy) else None
            if res is not None and res.plan is not None:   # the plans replayed; the train turning
                from .sheet.live_gears import gear_animation, gear_replays

                doc["replays"] = gear_replays(res, study.solution.ordinary_plan)
                doc["animation"] = gear_animation(res)
        return to_html(doc)
    sol = study.solution
    scene = sol.scene
    own = (size in (None, scene.drawing.sheet) and standard in (None, scene.drawing.standard))
    if own and sol.scales:
        mu = dict(sol.scales)
    else:
        from .sheet.scales import decide_scales

        mu = decide_scales(scene, sol.construction, sol.ev, sol.plans, size, standard)
    doc = live_document(sol, mu, language or scene.language, name, frames or FRAMES,
                        study.dynamics)
    return to_html(doc)


def write_page(study: Any, out: str | os.PathLike[str], name: str, *, size: str | None = None,
               standard: str | None = None, language: str | None = None,
               frames: int | None = None) -> Path:
    """Write ``<out>/<name>.html`` (whole or not at all) and return its path."""
    from .outputs import prepare_dir
    from .render.atomic import write_atomic

    text = page_text(study, size, standard, language, name, frames)   # before any file
    return write_atomic(prepare_dir(out) / f"{name}.html", text.encode("utf-8"))
