"""The check report: rows per point, segment and value, root-cause findings, notes; text and
JSON."""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field
from typing import Any

from .. import __version__, i18n
from ..construct.scale import SCALE_KEYS
from ..i18n import Text, num, pad
from ..submission.read import Note
from .texts import T, capitalize, join, tr, word

#: verdicts
OK, WRONG, SLIP, REFERENCE, MISSING, UNCHECKED = ("ok", "wrong", "slip", "reference", "missing",
                                                 "unchecked")
#: causes of a wrong item
NEW, CARRIED, SWAPPED, ACCUMULATED = "new", "carried", "swapped", "accumulated"


@dataclass(frozen=True, slots=True)
class Tolerance:
    """What counts as right on one plan: ±``mm`` on the paper or ±``pct`` %, whichever is larger;
    a direction is right when its end is within that distance across (or within ``deg``)."""

    mm: float = 1.0
    pct: float = 2.0
    deg: float | None = None

    def allowed_mm(self, length_mm: float) -> float:
        """Allowed length error (mm) of a segment ``length_mm`` long."""
        return max(self.mm, self.pct / 100.0 * abs(length_mm))

    def allowed_deg(self, length_mm: float) -> float:
        """Allowed direction error (degrees) of a segment ``length_mm`` long."""
        across = math.degrees(math.atan2(self.allowed_mm(length_mm), max(abs(length_mm), 1e-9)))
        return max(across, self.deg or 0.0)

    def text(self, lang: str = "en") -> str:
        """"±1 mm or ±2 %" (in a language: en, ru, vi, zh)."""
        key = "tolerance_deg" if self.deg else "tolerance"
        return T(key, mm=self.mm, pct=self.pct, deg=self.deg).tr(lang)


@dataclass
class PointRow:
    """A labelled point of a drawn plan and how far it is from the exact one."""

    label: str
    written: str
    step: str
    at_mm: tuple[float, float]
    error_mm: float | None
    tolerance_mm: float | None
    verdict: str
    cause: str = ""
    own_error_mm: float | None = None   # distance from where the student's own points put it
    found: str = ""                     # "line end", "crossing of two lines", "inferred"
    label_distance_mm: float = 0.0
    where: str = ""


@dataclass
class SegmentRow:
    """A measured segment: submitted and exact length on the paper, errors and verdict."""

    name: str
    quantity: str
    kind: str
    step: str
    submitted_mm: float | None
    exact_mm: float | None
    error_mm: float | None = None
    error_pct: float | None = None
    direction_deg: float | None = None
    tolerance_mm: float | None = None
    tolerance_deg: float | None = None
    verdict: str = UNCHECKED
    cause: str = ""
    hint: str = ""
    depends_on: list[str] = field(default_factory=list)
    carried_from: list[str] = field(default_factory=list)
    drawn: bool | None = None          # a line joins the two points on the sheet
    in_construction: bool = True
    submitted_value: float | None = None   # length × μ (SI)
    exact_value: float | None = None
    where: str = ""
    start: str = ""                    # step ids of the two ends
    end: str = ""


@dataclass
class ValueRow:
    """A physical value given by name."""

    name: str
    quantity: str
    unit: str
    submitted: float | None
    exact: float | None
    error_pct: float | None = None
    tolerance: float | None = None       # absolute, SI
    own: float | None = None             # what the student's own drawing/lengths give
    verdict: str = UNCHECKED
    cause: str = ""
    hint: str = ""
    where: str = ""


@dataclass
class CentreRow:
    """An instant centre labelled on a drawing: where it is and where it should be (mm of
    paper); for one marked by an arrow the error is the arrow's angle off it (degrees)."""

    label: str
    written: str
    exact_mm: tuple[float, float] | None
    at_mm: tuple[float, float] | None
    error: float | None
    tolerance: float | None
    verdict: str
    cause: str = ""
    hint: str = ""
    found: str = ""           # "point", "arrow", "infinity"
    where: str = ""


@dataclass
class Finding:
    """A root cause: a new error, swapped labels, an arithmetic slip."""

    kind: str            # "wrong point", "wrong segment", "swapped labels", "arithmetic slip",
    #                      "wrong value"
    plan: str
    subject: str         # label, segment or quantity
    message: str
    step: str = ""
    error: str = ""      # "length", "direction", "length and direction"


@dataclass
class PlanReport:
    """One plan of the submission."""

    name: str
    plan: str
    group: str
    mu: float | None
    mu_source: str
    tolerance: Tolerance
    anchor: str = ""
    convention: str = ""
    points: list[PointRow] = field(default_factory=list)
    segments: list[SegmentRow] = field(default_factory=list)
    #: exact points of the plan on the sheet, placed by the anchor (mm): label → (x, y)
    exact_mm: dict[str, tuple[float, float]] = field(default_factory=dict)
    #: the submission's lines of this plan (mm), for the overlay
    drawn_lines: list[tuple[tuple[float, float], tuple[float, float]]] = field(
        default_factory=list)
    #: exact segments on the sheet (mm): (name, start, end)
    exact_segments: list[tuple[str, tuple[float, float], tuple[float, float]]] = field(
        default_factory=list)
    #: the plan's own crank angle (°) when the sheet's plans are of several positions
    phi_deg: float | None = None

    @property
    def mu_unit(self) -> str:
        """"(m/s)/mm"."""
        return SCALE_KEYS.get(self.plan, ("", ""))[1]


@dataclass
class CheckReport:
    """Everything a check found."""

    scene: str
    submission: str
    kind: str
    phi_deg: float
    phi_source: str
    plans: list[PlanReport] = field(default_factory=list)
    values: list[ValueRow] = field(default_factory=list)
    findings: list[Finding] = field(default_factory=list)
    notes: list[Note] = field(default_factory=list)
    label_distance_mm: float | None = None
    units: str = ""
    #: instant centres labelled on a drawing (check/centres.py), their scale and its source
    centres: list[CentreRow] = field(default_factory=list)
    centres_mu: float | None = None
    centres_frame: Text | str = ""
    centres_phi: float | None = None      # their own crank angle when not the sheet's
    #: a linear driver's coordinate ("l4"): ``phi_deg`` is then its value in mm, not an angle
    coordinate: str = ""

    @property
    def rows(self) -> list[SegmentRow | ValueRow]:
        """All segment and value rows."""
        return [s for p in self.plans for s in p.segments] + list(self.values)

    def summary(self) -> dict[str, int]:
        """Counts of rows by verdict and of wrong rows by cause."""
        out = {"checked": 0, "ok": 0, "wrong": 0, "slip": 0, "missing": 0, "unchecked": 0,
               NEW: 0, CARRIED: 0, SWAPPED: 0, ACCUMULATED: 0, "findings": len(self.findings)}
        for r in self.rows:
            if r.verdict in (OK, WRONG, SLIP, REFERENCE):
                out["checked"] += 1
            out[OK if r.verdict == REFERENCE else r.verdict] += 1
            if r.verdict == WRONG:
                out[r.cause if r.cause in out else NEW] += 1
        for c in self.centres:
            out["checked"] += c.verdict in (OK, WRONG)
            out[c.verdict] += 1
            if c.verdict == WRONG:
                out[c.cause if c.cause in out else NEW] += 1
        return out

    @property
    def nothing_found(self) -> bool:
        """True when nothing on the submission could be checked against the exact construction
        (a reference segment only fixes the scale factor): such a submission does not pass."""
        return not any(r.verdict in (OK, WRONG, SLIP) for r in [*self.rows, *self.centres])

    @property
    def passed(self) -> bool:
        """True when something was checked and nothing checked is wrong."""
        return not self.nothing_found and not any(r.verdict in (WRONG, SLIP)
                                                  for r in [*self.rows, *self.centres])

    def verdict(self) -> Text:
        """PASSED, FAILED, or FAILED because nothing gradeable was found."""
        if self.nothing_found:
            return Text("readers.report.nothing_found")
        return T("report.passed" if self.passed else "report.failed")

    # -- output ------------------------------------------------------------------------------
    def to_json(self, lang: str = "en") -> dict[str, Any]:
        """One JSON document (lengths in mm of paper, values in SI, angles in degrees).

        Keys and codes (verdict, cause, kind, level, plan …) are the same in every language;
        the sentences (hints, messages, sources, where) are written in ``lang``, and each code
        has its words alongside (``verdict_text``, ``kind_text`` …)."""
        def verdict_words(item: Any) -> dict[str, str]:
            return {"verdict_text": verdict_text(item.verdict, item.cause, lang),
                    "cause_text": word("cause", item.cause, lang) if item.cause else ""}

        plans = []
        for p in self.plans:
            d = asdict(p)
            del d["drawn_lines"], d["exact_segments"]
            d.update(mu_unit=p.mu_unit, title=capitalize(tr(p.name, lang)),
                     tolerance_text=p.tolerance.text(lang))
            for pt, rd in zip(p.points, d["points"]):
                rd.update(verdict_words(pt), found_text=tr(pt.found, lang))
            for seg, rd in zip(p.segments, d["segments"]):
                rd.update(verdict_words(seg))
            plans.append(d)
        findings = [asdict(f) | {"kind_text": word("kind", f.kind, lang),
                                 "plan_text": tr(f.plan, lang),
                                 "error_text": word("error", f.error, lang) if f.error else ""}
                    for f in self.findings]
        return _json({
            "mechplan": __version__, "scene": self.scene, "submission": self.submission,
            "kind": self.kind, "phi_deg": self.phi_deg, "phi_source": self.phi_source,
            "coordinate": self.coordinate or None,
            "units": self.units, "label_distance_mm": self.label_distance_mm,
            "passed": self.passed, "summary": self.summary(), "plans": plans,
            "values": [asdict(v) | verdict_words(v) for v in self.values], "findings": findings,
            "centres": [asdict(c) | verdict_words(c) for c in self.centres],
            "centres_mu_l": self.centres_mu, "centres_frame": self.centres_frame,
            "centres_phi_deg": self.centres_phi,
            "notes": [asdict(n) | {"level_text": word("level", n.level, lang)} for n in self.notes],
            "lang": lang,
            "nothing_found": self.nothing_found, "result_text": self.verdict().tr(lang),
        }, lang)

    def text(self, lang: str = "en") -> str:
        """The report for a terminal, in a language (en, ru, vi, zh): per plan a table of
        segments, then values, findings, notes."""
        def say(key: str, **args: Any) -> str:
            return T(key, **args).tr(lang)

        out = [say("report.title", submission=self.submission),
               say("report.scene", scene=self.scene),
               (say("report.q", name=self.coordinate, q=self.phi_deg, source=self.phi_source)
                if self.coordinate else
                say("report.phi", phi=self.phi_deg, source=self.phi_source))
               if math.isfinite(self.phi_deg) else tr(self.phi_source, lang)]
        if self.units:
            out.append(say("report.units", units=self.units))
        if self.label_distance_mm is not None:
            out.append(say("report.label_distance", d=self.label_distance_mm))
        # the summary's counts fill the sentence's fields; counts it does not name are left out
        out.append(say("report.result",
                       verdict=self.verdict(), **self.summary()))
        for p in self.plans:
            out.append("")
            mu = T("report.mu", mu=p.mu, unit=p.mu_unit) if p.mu else T("report.mu_unknown")
            title = capitalize(tr(p.name, lang))
            if p.phi_deg is not None:
                title = (say("report.plan_at_q", title=title, name=self.coordinate, q=p.phi_deg)
                         if self.coordinate else
                         say("report.plan_at", title=title, phi=p.phi_deg))
            out.append(say("report.plan_source" if p.mu_source else "report.plan", title=title,
                           mu=mu, source=p.mu_source))
            out.append("   " + say("report.tolerance_anchor" if p.anchor else "report.tolerance",
                                   tol=p.tolerance.text(lang), anchor=p.anchor))
            if p.convention:
                out.append(f"   {tr(p.convention, lang)}")
            wrong_pts = [pt for pt in p.points if pt.verdict == WRONG]
            if wrong_pts:
                out.append("   " + say("report.points_off", points=join(
                    T("report.point_off", label=pt.label, err=pt.error_mm,
                      cause=word("cause", pt.cause, lang)) for pt in wrong_pts
                    if pt.error_mm is not None)))
            out.extend(_table(lang, _SEGMENT_COLUMNS, p.segments))
            if any(not row.in_construction for row in p.segments):
                out.append("   " + say("report.not_in_construction"))
        if self.values:
            out += ["", say("report.values"), *_table(lang, _VALUE_COLUMNS, self.values)]
        if self.centres:
            from .centres import centres_text

            out += ["", *centres_text(self, lang)]
        if self.findings:
            out += ["", say("report.findings")]
            for i, f in enumerate(self.findings, start=1):
                out.append("   " + say("report.finding", i=i, kind=word("kind", f.kind, lang),
                                       plan=f.plan, subject=f.subject, message=f.message))
        if self.notes:
            out += ["", say("report.notes")]
            for n in self.notes:
                note = (say("report.note_where", where=n.where, message=n.message) if n.where
                        else tr(n.message, lang))
                out.append("   " + say("report.note", level=word("level", n.level, lang),
                                       note=note))
        return "\n".join(out)


#: JSON keys whose values are sentences, written in the report's language; every other string
#: (codes, names, labels) stays as it is
PROSE_KEYS = frozenset({"hint", "message", "mu_source", "phi_source", "convention", "units",
                        "where", "centres_frame"})


def _json(x: Any, lang: str, key: str = "") -> Any:
    """A JSON document: floats rounded (not finite: null), sentences in a language, every other
    Text as its plain English."""
    if isinstance(x, float):
        return None if not math.isfinite(x) else round(x, 6)
    if isinstance(x, dict):
        return {k: _json(v, lang, k) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_json(v, lang, key) for v in x]
    if isinstance(x, i18n.Text):
        return x.tr(lang) if key in PROSE_KEYS else str(x)
    return x


def verdict_text(v: str, cause: str, lang: str = "en") -> str:
    """"ok", "WRONG (new)", "SLIP" in a language."""
    w = word("verdict", v, lang)
    if v == WRONG and cause:
        return T("report.verdict_cause", word=w, cause=word("cause", cause, lang)).tr(lang)
    return w


def _num(x: float | None, fmt: str, lang: str = "en") -> str:
    if x is None or not math.isfinite(x):
        return "—"
    if lang != "en":
        return num(x, fmt, lang)        # format_number: "0,0", never "-0,0"
    text = format(x, fmt)
    return text.replace("-", "+") if text.strip().lstrip("-+").strip("0.") == "" else text


#: columns of the text tables: (title, width, alignment, field, number format)
_SEGMENT_COLUMNS = (("col.segment", 14, "<", "name", ""), ("col.quantity", 12, "<", "quantity", ""),
                    ("col.drawn_mm", 9, ">", "submitted_mm", "9.1f"),
                    ("col.exact_mm", 9, ">", "exact_mm", "9.1f"),
                    ("col.err_mm", 8, ">", "error_mm", "+8.1f"),
                    ("col.err_pct", 8, ">", "error_pct", "+8.1f"),
                    ("col.dir", 7, ">", "direction_deg", "+7.1f"))
_VALUE_COLUMNS = (("col.name", 12, "<", "name", ""),
                  ("col.submitted", 12, ">", "submitted", "12.4g"),
                  ("col.exact", 12, ">", "exact", "12.4g"), ("col.unit", 8, ">", "unit", ""),
                  ("col.err_pct", 8, ">", "error_pct", "+8.1f"))


def _table(lang: str, columns: tuple[tuple[str, int, str, str, str], ...],
           rows: list[Any]) -> list[str]:
    """A table of rows with a verdict column, and the hint under each wrong row."""
    out = ["   " + "".join(pad(T(key).tr(lang), w, a) for key, w, a, _, _ in columns) + "  "
           + T("col.verdict").tr(lang)]
    for row in rows:
        cells = []
        for _, w, a, name, fmt in columns:
            x = getattr(row, name)
            if name == "name" and not getattr(row, "in_construction", True):
                x = f"{x}*"
            elif name == "unit":
                x = i18n.unit(x, lang)          # "м/с" on a Russian report
            cells.append(pad(_num(x, fmt, lang) if fmt else x, w, a))
        out.append("   " + "".join(cells) + f"  {verdict_text(row.verdict, row.cause, lang)}")
        if row.verdict in (WRONG, SLIP) and row.hint:
            out.append(f"        → {tr(row.hint, lang)}")
    return out
