"""The check report: rows per point, segment and value, root-cause findings, notes; text and JSON."""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field
from typing import Any

from .. import __version__
from ..construct.scale import SCALE_KEYS
from .submission import Note

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

    def text(self) -> str:
        """"±1 mm or ±2 %"."""
        out = f"±{self.mm:g} mm or ±{self.pct:g} %"
        return out + (f" (directions ±{self.deg:g}°)" if self.deg else "")


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
        return out

    @property
    def passed(self) -> bool:
        """True when nothing checked is wrong."""
        return not any(r.verdict in (WRONG, SLIP) for r in self.rows)

    # -- output ------------------------------------------------------------------------------
    def to_json(self) -> dict[str, Any]:
        """One JSON document (lengths in mm of paper, values in SI, angles in degrees)."""
        def clean(x: Any) -> Any:
            if isinstance(x, float):
                return None if not math.isfinite(x) else round(x, 6)
            if isinstance(x, dict):
                return {k: clean(v) for k, v in x.items()}
            if isinstance(x, (list, tuple)):
                return [clean(v) for v in x]
            return x

        plans = []
        for p in self.plans:
            d = asdict(p)
            d.pop("drawn_lines")
            d.pop("exact_segments")
            d["mu_unit"] = p.mu_unit
            d["tolerance"] = asdict(p.tolerance)
            plans.append(d)
        return clean({
            "mechplan": __version__, "scene": self.scene, "submission": self.submission,
            "kind": self.kind, "phi_deg": self.phi_deg, "phi_source": self.phi_source,
            "units": self.units, "label_distance_mm": self.label_distance_mm,
            "passed": self.passed, "summary": self.summary(), "plans": plans,
            "values": [asdict(v) for v in self.values],
            "findings": [asdict(f) for f in self.findings],
            "notes": [{"level": n.level, "message": n.message, "where": n.where}
                      for n in self.notes],
        })

    def text(self) -> str:
        """The report for a terminal."""
        return render_text(self)


def _num(x: float | None, fmt: str) -> str:
    if x is None or not math.isfinite(x):
        return "—"
    text = format(x, fmt)
    return text.replace("-", "+") if text.strip().lstrip("-+").strip("0.") == "" else text


def _verdict(v: str, cause: str) -> str:
    if v in (WRONG, SLIP):
        word = "WRONG" if v == WRONG else "SLIP"
        return f"{word} ({cause})" if cause and v == WRONG else word
    return v


def render_text(r: CheckReport) -> str:
    """The report as plain text: per plan a table of segments, then values, findings, notes."""
    s = r.summary()
    out = [f"mechplan check: {r.submission}",
           f"scene: {r.scene}",
           f"crank angle φ = {r.phi_deg:.2f}° ({r.phi_source})"]
    if r.units:
        out.append(f"drawing units: {r.units}")
    if r.label_distance_mm is not None:
        out.append(f"labels taken within {r.label_distance_mm:.1f} mm of a line end")
    out.append(f"result: {'PASSED' if r.passed else 'FAILED'} — {s['checked']} checked, "
               f"{s['ok']} ok, {s['wrong']} wrong ({s['new']} new, {s['carried']} carried, "
               f"{s['swapped']} by swapped labels, {s['accumulated']} by small errors adding up), "
               f"{s['slip']} arithmetic slip(s), {s['missing']} not on the submission")
    for p in r.plans:
        out.append("")
        mu = (f"μ = {p.mu:.6g} {p.mu_unit}" if p.mu else "μ unknown")
        out.append(f"## {p.name[0].upper() + p.name[1:]}: {mu}" + (f" ({p.mu_source})"
                                                                   if p.mu_source else ""))
        out.append(f"   tolerance {p.tolerance.text()}" + (f"; placed by {p.anchor}"
                                                           if p.anchor else ""))
        if p.convention:
            out.append(f"   {p.convention}")
        wrong_pts = [pt for pt in p.points if pt.verdict == WRONG]
        if wrong_pts:
            out.append("   points off their exact place: " + ", ".join(
                f"{pt.label} {pt.error_mm:.1f} mm ({pt.cause})" for pt in wrong_pts
                if pt.error_mm is not None))
        out.append(f"   {'segment':<14}{'quantity':<12}{'drawn mm':>9}{'exact mm':>9}"
                   f"{'err mm':>8}{'err %':>8}{'dir °':>7}  verdict")
        for row in p.segments:
            name = row.name if row.in_construction else f"{row.name}*"
            out.append(f"   {name:<14}{row.quantity:<12}{_num(row.submitted_mm, '9.1f'):>9}"
                       f"{_num(row.exact_mm, '9.1f'):>9}{_num(row.error_mm, '+8.1f'):>8}"
                       f"{_num(row.error_pct, '+8.1f'):>8}{_num(row.direction_deg, '+7.1f'):>7}"
                       f"  {_verdict(row.verdict, row.cause)}")
            if row.verdict in (WRONG, SLIP) and row.hint:
                out.append(f"        → {row.hint}")
        if any(not row.in_construction for row in p.segments):
            out.append("   * drawn between labelled points, not a segment of the construction")
    if r.values:
        out.append("")
        out.append("## Values")
        out.append(f"   {'name':<12}{'submitted':>12}{'exact':>12}{'unit':>8}{'err %':>8}  verdict")
        for v in r.values:
            out.append(f"   {v.name:<12}{_num(v.submitted, '12.4g'):>12}{_num(v.exact, '12.4g'):>12}"
                       f"{v.unit:>8}{_num(v.error_pct, '+8.1f'):>8}  {_verdict(v.verdict, v.cause)}")
            if v.verdict in (WRONG, SLIP) and v.hint:
                out.append(f"        → {v.hint}")
    if r.findings:
        out.append("")
        out.append("## Findings (root causes)")
        for i, f in enumerate(r.findings, start=1):
            out.append(f"   {i}. [{f.kind}] {f.plan}: {f.subject}: {f.message}")
    if r.notes:
        out.append("")
        out.append("## Notes")
        for n in r.notes:
            out.append(f"   {n.level}: {n}")
    return "\n".join(out)
