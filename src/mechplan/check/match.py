"""Give a submission's names meaning: segments and quantities of the construction, scale factors,
the crank angle. Everything here is about names; numbers are compared in :mod:`.grade`."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

from ..construct.graph import Construction
from ..construct.segments import Segment
from ..construct.step import Kind
from ..errors import SceneError
from ..model.mechanism import Mechanism
from ..model.plans import Plan
from ..submission import notation
from ..submission.labels import (
    LabelBook,
    PlanKey,
    feature_votes,
    mu_plan,
    plan_key,
    section_plan,
    written_mu,
)
from ..submission.read import Entry, Note, Point
from ..submission.written import (
    case_key,
    is_angle_name,
    is_length_text,
    label_key,
    number_and_half,
    parse_angle,
    parse_value,
)
from .labels import segment_key
from .texts import T, join, plan_title


@dataclass(frozen=True, slots=True)
class Quantity:
    """A quantity of the construction a submission may name."""

    name: str                 # "v_S2", "omega_2", "a^n_CB", "J_red"
    dimension: str            # a key of units.DIMENSIONS
    plan: Plan | None
    step: str | None = None   # a result step (vector → magnitude, scalar → signed value)
    segment: Segment | None = None
    extra: str | None = None  # "J_red", "M_red": computed by the dynamics module

    @property
    def display(self) -> str:
        """"ω2", "ε3", "v_S2"."""
        m = re.fullmatch(r"(omega|epsilon)_(\w+)", self.name)
        if m:
            return ("ω" if m.group(1) == "omega" else "ε") + m.group(2)
        return self.name


@dataclass
class TableSegment:
    """A drawn length given in a table (or written on the sheet), matched to a segment."""

    segment: Segment
    key: PlanKey
    written: str
    where: str
    length_mm: float
    length_half_unit: float          # half a unit of the last written digit (mm)
    mu: float | None = None          # μ written on the same row


@dataclass
class GivenValue:
    """A physical value given by name: "v_S2 = 2.95 m/s", "ω2 = 27 rad/s"."""

    written: str
    quantity: Quantity
    value: float                     # SI
    text: str
    where: str
    half_unit: float                 # half a unit of the last written digit, SI
    length_mm: float | None = None   # a length written with it ("pb = 67 mm → v_B = 6.7 m/s")
    length_half_unit: float = 0.0
    mu: float | None = None
    at: Point | None = None          # where it is written on a sheet (mm)


@dataclass
class Interpretation:
    """What the names of a submission mean."""

    segments: list[TableSegment] = field(default_factory=list)
    values: list[GivenValue] = field(default_factory=list)
    scales: dict[Plan, tuple[float, str]] = field(default_factory=dict)
    notes: list[Note] = field(default_factory=list)


# -- quantities --------------------------------------------------------------------------------
class QuantityIndex:
    """Quantities of a construction, found by the names students write (``notation.toml``)."""

    def __init__(self, c: Construction, mech: Mechanism, with_dynamics: bool) -> None:
        self.mech = mech
        self.by_key: dict[str, Quantity] = {}
        for name, sid in c.results.items():
            step = c[sid]
            if step.plan is Plan.POSITION and step.kind is Kind.POINT:
                continue
            if name.startswith("K_"):
                continue                  # a point of a line of action, not a value
            dim: str | None
            if name.startswith("load_"):           # a given force or couple
                dim = "moment" if step.kind is Kind.SCALAR else "force"
            elif step.plan is Plan.FORCE and step.kind is Kind.POINT:
                dim = "force"
            else:
                dim = notation.dimension(name)
            if dim is not None:
                self._put(name, Quantity(name, dim, step.plan, step=sid))
        for seg in c.segments:
            dim = ("force" if seg.plan is Plan.FORCE else notation.dimension(seg.quantity)
                   or seg.plan.dimension)
            q = Quantity(seg.quantity, dim, seg.plan, segment=seg)
            self._put(seg.quantity, q)
            rev = _reversed_quantity(seg, mech)
            if rev:
                self._put(rev, q)
        self.has_force = bool(c.of_plan(Plan.FORCE))
        if with_dynamics:
            self._put("J_red", Quantity("J_red", "inertia", None, extra="J_red"))
            self._put("M_red", Quantity("M_red", "moment", None, extra="M_red"))

    def _put(self, name: str, q: Quantity) -> None:
        self.by_key.setdefault(notation.key(name), q)

    def find(self, name: str) -> Quantity | None:
        """The quantity a written name stands for, or None."""
        reading = notation.read(name, self.mech)
        if reading is None:
            return None
        if reading.canonical.startswith("F@"):
            link = self.mech.links[reading.canonical[2:]]
            return next((self.by_key[k] for p in link.points
                         if (k := notation.key(f"F_{p}")) in self.by_key), None)
        return self.by_key.get(notation.key(reading.canonical))

    def names(self) -> list[str]:
        """Display names of all quantities, for messages."""
        return sorted({q.display for q in self.by_key.values()})


def _reversed_quantity(seg: Segment, mech: Mechanism) -> str | None:
    """v_CB ≡ v_BC, a^n_CB ≡ a^n_BC: the same magnitude named from the other end."""
    m = re.fullmatch(r"(v|a\^n|a\^t|a\^k|a\^r|a)_(\w+)", seg.quantity)
    other_way = notation.reversed_points(m.group(2).lower(), mech) if m else None
    return f"{m.group(1)}_{other_way}" if m and other_way else None


class SegmentIndex:
    """Segments of a construction by the ways their names are written ("pb", "πb'", "b1n2")."""

    def __init__(self, c: Construction, book: LabelBook) -> None:
        self.by_key: dict[str, list[tuple[Segment, PlanKey, int]]] = {}
        self.exact_case: dict[str, Segment] = {}
        for seg in c.segments:
            key = segment_key(seg)
            if key not in book.aliases:
                key = plan_key(seg.plan, c[seg.end].group)
            table = book.aliases.get(key, {})
            starts = [(a, cand.weight) for a, cs in table.items() for cand in cs
                      if cand.step == seg.start]
            ends = [(a, cand.weight) for a, cs in table.items() for cand in cs
                    if cand.step == seg.end]
            self._put(label_key(seg.name), seg, key, 4)
            self.exact_case.setdefault(case_key(seg.name), seg)
            for a, wa in starts:
                for b, wb in ends:
                    self._put(a + b, seg, key, min(wa, wb))
                    self._put(b + a, seg, key, min(wa, wb) - 1)

    def names(self) -> list[str]:
        """The construction's segment names, for messages."""
        return sorted({seg.name for seg in self.exact_case.values()})

    def _put(self, k: str, seg: Segment, key: PlanKey, weight: int) -> None:
        entries = self.by_key.setdefault(k, [])
        if not any(e[0] is seg for e in entries):
            entries.append((seg, key, weight))

    def find(self, name: str, plan: Plan | None = None,
             prefer: Plan | None = None) -> tuple[Segment, PlanKey] | None:
        """The segment a written name stands for (best reading), or None.

        ``plan`` restricts the reading to one plan; ``prefer`` breaks ties (the plan of the
        quantity written with it); a name written exactly as on the plan ("BC" on the position
        plan, "bc" on the velocity plan) wins over other readings.
        """
        entries = self.by_key.get(label_key(name), [])
        if plan is not None:
            entries = [e for e in entries if e[1][0] is plan]
        if not entries:
            return None
        exact = self.exact_case.get(case_key(name))
        votes = feature_votes(name.strip())

        def rank(e: tuple[Segment, PlanKey, int]) -> tuple[int, int, int, int]:
            return (int(e[0] is exact), int(e[1][0] is prefer), e[2], votes.get(e[1][0], 0))

        best = max(entries, key=rank)
        return best[0], best[1]


# -- entries -----------------------------------------------------------------------------------
def interpret(entries: list[Entry], qi: QuantityIndex, si: SegmentIndex,
              from_sheet: bool) -> Interpretation:
    """Sort entries into scale factors, the crank angle, drawn lengths and physical values."""
    out = Interpretation()
    for e in entries:
        _interpret_one(e, out, qi, si, from_sheet)
    return out


def _interpret_one(e: Entry, out: Interpretation, qi: QuantityIndex, si: SegmentIndex,
                   from_sheet: bool) -> None:
    notes = out.notes
    text = e.text if e.text is not None else (e.length if e.length is not None else e.value)
    plan = mu_plan(e.name)
    if plan is not None:
        mu = None if text is None else written_mu(e, text, plan, notes, "error", "note.mu_error")
        if mu is None or from_sheet:
            return
        prev = out.scales.get(plan)
        if prev and abs(prev[0] - mu) > 1e-12 * mu:
            notes.append(Note("warning", T("note.mu_second",
                                           plan=plan_title(plan.value, case="gen"),
                                           name=e.name, text=text), e.where))
        else:
            out.scales[plan] = (mu, T("read_from", name=e.name, text=text, where=e.where))
        return
    if is_angle_name(e.name):
        try:                    # the angle itself is read by grade._angles
            if text is not None:
                parse_angle(text)
        except SceneError as exc:
            notes.append(Note("error", T("note.crank_angle", name=e.name, text=text,
                                         detail=exc.detail), e.where))
        return
    sec = section_plan(e.section)
    length_text = e.length if e.length is not None else (
        e.text if e.text is not None and is_length_text(e.text) else None)
    given = qi.find(e.quantity) if e.quantity else None     # the quantity written with it
    # a name of plan points ("pb", "ab", "πc'") is a segment; a quantity's name ("aC2", "as2",
    # "VC2B2") is never read as a segment (its length in mm is reported below)
    if length_text is not None and (notation.read(e.name, qi.mech) is None or _plain(e.name)):
        found = si.find(e.name, sec[0] if sec else None, given.plan if given else None)
        if found is not None:
            _table_segment(e, found[0], found[1], length_text, out, qi)
            return
    q = qi.find(e.name)
    if q is None:
        q = given
    if q is not None:
        vtext = e.value if e.value is not None else text
        if vtext is None:
            return
        if is_length_text(vtext) and "mm" in vtext.lower() and q.dimension != "length":
            notes.append(Note("error", T("note.length_not_value", name=e.name, text=vtext,
                                         display=q.display, dim=T(f"dim.{q.dimension}")),
                              e.where))
            return
        parsed = parse_value(vtext, q.dimension, e.where, notes, e.name)
        if parsed is None:
            return
        gv = GivenValue(e.name, q, parsed[0], vtext, e.where, parsed[1], at=e.at)
        if e.length is not None and e.value is not None:
            number, half = number_and_half(e.length)
            gv.length_mm, gv.length_half_unit = number, half
        out.values.append(gv)
        return
    level = "info" if from_sheet else "error"
    if from_sheet and not re.match(r"^[A-Za-zα-ωΑ-Ω]", e.name):
        return
    dim = notation.dimension(e.name)
    if dim in ("force", "moment") and not qi.has_force:
        notes.append(Note(level, T("note.force_without_plan", name=e.name), e.where))
        return
    near = notation.closest(e.name, [*qi.names(), *si.names()])
    notes.append(Note(level, T("note.unknown_name", name=e.name) if from_sheet else
                      T("note.unknown_name_known", name=e.name, known=join(near)), e.where))


def _table_segment(e: Entry, seg: Segment, key: PlanKey, length_text: str, out: Interpretation,
                   qi: QuantityIndex) -> None:
    """A drawn length written for a segment, with the value and μ written on its row."""
    notes = out.notes
    number, half = number_and_half(length_text)
    if number is None or not math.isfinite(number) or number < 0:
        notes.append(Note("error", T("note.length_expected", name=e.name, text=length_text),
                          e.where))
        return
    # a μ written on the row that is no scale factor is not used (as one written on a sheet)
    row_mu = written_mu(e, e.mu, seg.plan, notes, "error", "note.row_mu_error") if e.mu else None
    if e.value is not None:
        qname = e.quantity or seg.quantity
        q = qi.find(qname) or qi.find(seg.quantity)
        if q is not None:
            parsed = parse_value(e.value, q.dimension, e.where, notes, qname)
            if parsed is not None:
                out.values.append(GivenValue(qname, q, parsed[0], e.value, e.where,
                                             parsed[1], number, half, row_mu, e.at))
        else:
            notes.append(Note("warning", T("note.unknown_quantity", name=qname), e.where))
    out.segments.append(TableSegment(seg, key, e.name, e.where, number, half, row_mu))


def _plain(name: str) -> bool:
    """A name of plan points only: lower-case labels and primes ("ab", "pb", "πc'")."""
    return bool(re.fullmatch(r"[a-zπ'′’]+", name.strip()))
