"""A table of instant centres graded (``I13 = (x, y) mm``, ``I13x``, ``I13y``, the distance
``I13A``, ``P03 = ∞`` or ``∞ 90°``), and what the drawn and written centres share: the exact
centre at a position and the rule that places it (its pair, or the two lines of Kennedy's
theorem)."""

from __future__ import annotations

import math
import re
from collections.abc import Sequence

import numpy as np

from ..construct.ops import centres as H
from ..construct.plans.centres import Centre, Centres, label, ordered
from ..model.mechanism import PairKind
from ..model.plans import Plan
from ..submission.centre_marks import CentreName, says_infinity
from ..submission.read import Entry, Note
from .context import Ctx
from .report import NEW, OK, WRONG, CheckReport, ValueRow
from .texts import T, Text

#: how far an arrow toward a far centre, or a written direction, may be off (degrees)
ARROW_DEG = 3.0


def exact_centre(cs: Centres, ctr: Centre, k: int) -> tuple[np.ndarray | None, np.ndarray | None]:
    """(point m, None) for a finite centre, (None, direction) at infinity, (None, None) if
    indeterminate."""
    h = cs.values[(ctr.i, ctr.j)].h[k:k + 1]
    if not np.all(np.isfinite(h)):
        return None, None
    if H.is_infinite(h)[0]:
        return None, H.direction(h)[0]
    return H.point(h, cs.length)[0], None


def find_centre(cs: Centres, key: tuple[str, str]) -> Centre | None:
    try:
        return cs.diagram.centre(*key)
    except KeyError:
        return None


def rule_of(cs: Centres, ctr: Centre, k: int) -> Text:
    """Where a centre is by its rule: a pair's pin or direction, or the two lines of Kennedy's
    theorem it lies on."""
    name = label(ctr)
    if ctr.pair is not None:
        if ctr.pair.kind is PairKind.PRISMATIC:
            return T("centres.hint_prismatic", centre=name, a=ctr.pair.a, b=ctr.pair.b)
        return T("centres.hint_pin", centre=name, point=ctr.pair.point)
    lines = []
    for t in cs.values[(ctr.i, ctr.j)].triangles[k]:
        kk = ctr.via[int(t)]
        a, b = ordered(cs.diagram.links, ctr.i, kk), ordered(cs.diagram.links, ctr.j, kk)
        lines.append(T("centres.line", a=label(a), b=label(b)))
    return T("centres.hint_lines", centre=name, l1=lines[0], l2=lines[-1])


def grade_table(ctx: Ctx, cs: Centres, k: int, report: CheckReport,
                 entries: Sequence[tuple[CentreName, Entry]]) -> None:
    tol = ctx.options.tol(Plan.POSITION)
    mu_l = ctx.scales.get(Plan.POSITION) or cs.length / 100.0
    links = cs.diagram.links
    pins = [r for ctr in cs.diagram.centres if ctr.primary
            and (r := exact_centre(cs, ctr, k)[0]) is not None]
    middle = np.mean(pins, axis=0) if pins else np.zeros(2)
    mech_pts = {p for lk in ctx.scene.mechanism.links.values() for p in lk.points}
    for name, e in entries:
        ctr = find_centre(cs, ordered(links, name.i, name.j)) if name.i in links and \
            name.j in links and name.i != name.j else None
        text = e.value or e.text or e.length or ""
        if ctr is None:
            report.notes.append(Note("warning", T("centres.unknown", name=e.name)))
            continue
        r, _u = exact_centre(cs, ctr, k)
        parts = _numbers(text) if not _inf_text(text) else []
        rest = name.rest
        wanted: list[tuple[str, float | None, float | None]] = []
        if rest == "" and len(parts) == 2:
            wanted = [("x", parts[0], None if r is None else r[0]),
                      ("y", parts[1], None if r is None else r[1])]
        elif rest.lower() in ("x", "y") and len(parts) == 1:
            i = 0 if rest.lower() == "x" else 1
            wanted = [(rest.lower(), parts[0], None if r is None else r[i])]
        elif rest in mech_pts and len(parts) == 1 and ctx.c.has_position(rest):
            at = np.asarray(ctx.ev[ctx.c.position(rest)][k], dtype=float)
            wanted = [(rest, parts[0], None if r is None else float(np.hypot(*(r - at))))]
        elif rest == "" and _inf_text(text) and len(parts) <= 1:
            report.values.append(_infinite_row(e, ctr, r, _u, text))
            continue
        else:
            report.notes.append(Note("warning", T("centres.unread", name=e.name, text=text)))
            continue
        for what, got, exact in wanted:
            row = ValueRow(e.name if len(wanted) == 1 else f"{e.name}.{what}", label(ctr), "m",
                           got, exact, where=e.where)
            if got is None:
                continue
            if exact is None:
                row.verdict, row.cause = WRONG, NEW
                row.hint = T("centres.hint_infinite", centre=label(ctr))
            else:
                # ±1 mm of paper at the scene's μl or 2 % of the centre's distance from the
                # mechanism (a far centre is drawn with long lines), as on a drawing
                far = float(np.hypot(*(r - middle))) if r is not None else 0.0
                row.tolerance = max(tol.pct / 100.0 * far, tol.mm * mu_l)
                row.error_pct = 100.0 * (got - exact) / abs(exact) if exact else None
                row.verdict = OK if abs(got - exact) <= row.tolerance else WRONG
                if row.verdict == WRONG:
                    row.cause = NEW
                    row.hint = rule_of(cs, ctr, k)
            report.values.append(row)


def _infinite_row(e: Entry, ctr: Centre, r: np.ndarray | None, u: np.ndarray | None,
                  text: str) -> ValueRow:
    """A centre written "∞" (with its direction "∞ 90°" or not): right when it is at infinity
    (and the direction is right either way, within 3°)."""
    m = re.search(r"([+\-−]?\d+(?:[.,]\d+)?)\s*°", text)
    angle = float(m.group(1).replace(",", ".").replace("−", "-")) if m else None
    row = ValueRow(e.name, label(ctr), "deg" if angle is not None else "", angle, None,
                   where=e.where)
    if r is not None or u is None:
        row.verdict, row.cause = WRONG, NEW
        row.hint = T("centres.hint_finite", centre=label(ctr))
        return row
    exact = math.degrees(math.atan2(u[1], u[0])) % 180.0
    if angle is None:
        row.verdict = OK
        return row
    row.exact = exact if abs(exact - angle % 180.0) <= 90.0 else exact + 180.0
    off = abs(math.remainder(angle - exact, 180.0))
    row.tolerance = ARROW_DEG
    row.verdict = OK if off <= ARROW_DEG else WRONG
    if row.verdict == WRONG:
        row.cause = NEW
        row.hint = T("centres.hint_infinite_dir", centre=label(ctr), angle=exact)
    return row


def _inf_text(text: str) -> bool:

    return says_infinity(text)


def _numbers(text: str) -> list[float]:
    """The values of ``"(120.5, 80.2) mm"``, ``"120,5; 80,2 mm"``, ``"0.12 m"`` in metres (a bare
    number is millimetres, as the sheet's table writes them)."""
    t = text.strip().strip("()[]")
    unit = "mm"
    for u in ("mm", "cm", "m", "мм", "см", "м"):
        if t.endswith(u):
            unit, t = u, t[: -len(u)].strip().strip("()[]")
            break
    scale = {"mm": 1e-3, "мм": 1e-3, "cm": 1e-2, "см": 1e-2, "m": 1.0, "м": 1.0}[unit]
    pieces = [p for p in (t.split(";") if ";" in t else _comma_split(t)) if p.strip()]
    out = []
    for p in pieces:
        try:
            out.append(float(p.strip().replace(",", ".").replace("−", "-")) * scale)
        except ValueError:          # not a number: the row is reported unread
            return []
    return out


def _comma_split(t: str) -> list[str]:
    """"120.5, 80.2" → two numbers; "120,5" (a decimal comma) → one."""
    if ", " in t or t.count(",") > 1:
        return t.split(", ") if ", " in t else t.split(",")
    return t.split()
