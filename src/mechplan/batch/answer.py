"""Answer keys: the values a student must find, as JSON and as a printable table (PDF)."""

from __future__ import annotations

import io
import math
from typing import Any

from ..i18n import message, number

#: rows per page and position columns per page of the printed key (A4 landscape)
ROWS_PER_PAGE = 32
COLUMNS_PER_PAGE = 8

# (symbol, unit message id) of the quantities of a linkage's key
_UNIT = {"v": "batch.unit.velocity", "a": "batch.unit.acceleration", "omega": "batch.unit.omega",
         "epsilon": "batch.unit.epsilon", "R": "batch.unit.force", "M_b": "batch.unit.moment"}


def _mag(v: list[float]) -> float:
    return math.hypot(v[0], v[1])


def _mechanism_rows(doc: dict[str, Any]) -> tuple[list[float], list[dict[str, Any]]]:
    positions = doc["positions"]
    phi = [float(p["phi_deg"]) for p in positions]
    rows: list[dict[str, Any]] = []

    def add(quantity: str, kind: str, values: list[float | None]) -> None:
        if any(v is not None and abs(v) > 1e-9 for v in values):
            rows.append({"quantity": quantity, "kind": kind, "values": values})

    points = list(positions[0]["points"]) if positions else []
    for sym in ("v", "a"):
        for p in points:
            add(f"{sym}_{p}", sym, [_mag(pos["points"][p][sym]) if sym in pos["points"][p] else None
                                    for pos in positions])
    links = list(positions[0]["links"]) if positions else []
    for sym, name in (("omega", "ω"), ("epsilon", "ε")):
        for lid in links:
            add(f"{name}{lid}", sym, [pos["links"][lid].get(sym) for pos in positions])
    if positions and "forces" in positions[0]:
        for pair in positions[0]["forces"].get("reactions", {}):
            add(f"R{pair}", "R", [_mag(pos["forces"]["reactions"][pair]) for pos in positions])
        for guide in positions[0]["forces"].get("guide_reactions", {}):
            add(f"R{guide}", "R", [_mag(pos["forces"]["guide_reactions"][guide]["force"])
                                   for pos in positions])
        add("M_b", "M_b", [pos["forces"].get("balancing_moment") for pos in positions])
    if positions and positions[0].get("textbook"):        # the scene's [answers] (textbook.md)
        tb = positions[0]["textbook"]
        for key in tb.get("sliding", {}):
            add(f"v_rel {key}", "v", [pos["textbook"]["sliding"][key]["v_slide"]
                                      for pos in positions])
            add(f"a^k {key}", "a", [pos["textbook"]["sliding"][key].get("a_cor_magnitude")
                                    for pos in positions])
        for key in tb.get("rubbing", {}):
            add(f"v_rub {key}", "v", [pos["textbook"]["rubbing"][key]["v_rub"]
                                      for pos in positions])
    return phi, rows


def _flatten(doc: Any, path: str = "") -> list[tuple[str, float]]:
    """Numeric leaves of a JSON document with their paths (any scene kind)."""
    if isinstance(doc, bool):
        return []
    if isinstance(doc, int | float):
        return [(path, float(doc))]
    if isinstance(doc, dict):
        return [x for k, v in doc.items() for x in _flatten(v, f"{path}.{k}" if path else str(k))]
    if isinstance(doc, list):
        return [x for i, v in enumerate(doc) for x in _flatten(v, f"{path}[{i}]")]
    return []


def answer_key(study_json: dict[str, Any], variant_id: str, name: str,
               values: dict[str, Any]) -> dict[str, Any]:
    """Return the answer key document of one variant (SI units; signs as in ``solve --json``).

    A linkage's key has one column per solved position and one row per quantity (|v|, |a| of every
    point, ω and ε of every link, reaction magnitudes and M_b when loaded); any other scene kind's
    key lists every number of its JSON document.
    """
    key: dict[str, Any] = {"id": variant_id, "name": name, "values": values,
                           "title": study_json.get("title", "")}
    if "positions" in study_json and "dof" in study_json:
        phi, rows = _mechanism_rows(study_json)
        key.update(kind="mechanism", phi_deg=phi, rows=rows)
    else:
        key.update(kind="other", phi_deg=[], rows=[
            {"quantity": path, "kind": "", "values": [value]}
            for path, value in _flatten(study_json) if path != "mechplan"])
    key["solution"] = study_json
    return key


def headline(key: dict[str, Any]) -> dict[str, float]:
    """Key numbers of a variant for the class summary: the largest magnitude of every row."""
    out: dict[str, float] = {}
    for row in key["rows"]:
        vals = [abs(v) for v in row["values"] if v is not None]
        if vals and key["kind"] == "mechanism":
            out[f"max|{row['quantity']}|"] = max(vals)
    return out


def _fmt(value: float | None, language: str) -> str:
    if value is None or not math.isfinite(value):
        return "—"
    mag = abs(value)
    digits = 4 if mag < 1 else 3 if mag < 10 else 2 if mag < 100 else 1 if mag < 1000 else 0
    return number(value, digits, language)


def answer_pdf(key: dict[str, Any], language: str) -> bytes:
    """Return the printable answer key: A4 landscape pages of the key's table."""
    from matplotlib.backends.backend_pdf import PdfPages

    from ..drafting.primitives import HAlign, Sheet, Table, Text
    from ..render.mpl import figure, render_context

    rows = key["rows"]
    phi = key["phi_deg"] or [None]
    head_q = message("batch.key.quantity", language)
    head_u = message("batch.key.unit", language)
    title = message("batch.key.title", language, title=one_line(str(key["title"])))
    who = (message("batch.key.variant", language, id=key["id"], name=one_line(key["name"]))
           if key["name"]
           else message("batch.key.variant_id", language, id=key["id"]))
    pages: list[Sheet] = []
    col_chunks = [list(range(i, min(i + COLUMNS_PER_PAGE, len(phi))))
                  for i in range(0, len(phi), COLUMNS_PER_PAGE)]
    row_chunks = [rows[i:i + ROWS_PER_PAGE] for i in range(0, len(rows), ROWS_PER_PAGE)] or [[]]
    for cols in col_chunks:
        for chunk in row_chunks:
            heads = [message("batch.key.position", language, phi=number(phi[c], 1, language))
                     if phi[c] is not None else message("batch.key.value", language) for c in cols]
            cells = [(head_q, head_u, *heads)]
            for row in chunk:
                unit = message(_UNIT[row["kind"]], language) if row["kind"] in _UNIT else ""
                cells.append((row["quantity"], unit,
                              *(_fmt(row["values"][c], language) for c in cols)))
            q_width = 60.0 if key["kind"] != "mechanism" else 22.0
            widths = (q_width, 16.0, *([24.0] * len(cols)))
            table = Table((12.0, 182.0), widths, tuple([5.5] * len(cells)), tuple(cells),
                          text_height_mm=2.5)
            prims = [Text((12.0, 198.0), title, 5.0), Text((12.0, 190.0), who, 3.5),
                     *table.expand()]
            page = len(pages) + 1
            prims.append(Text((285.0, 8.0), message("batch.key.page", language, page=page), 2.5,
                              halign=HAlign.RIGHT))
            pages.append(Sheet(297.0, 210.0, tuple(prims), {"title": title}, language,
                               f"answer_key_{page}"))
    buf = io.BytesIO()
    with render_context(), PdfPages(buf, metadata={"Title": title, "Creator": "mechplan",
                                                   "CreationDate": None}) as pdf:
        for sheet in pages:
            pdf.savefig(figure(sheet))
    return buf.getvalue()


def one_line(text: str) -> str:
    """A name as one printed line: every character that is not printable is a space."""
    return " ".join("".join(c if c.isprintable() else " " for c in text).split())
