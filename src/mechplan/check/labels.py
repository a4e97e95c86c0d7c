"""Labels and quantity names as people write them, normalised to the construction's own.

Points on a plan are written in four traditions: ``b`` / ``b′`` / ``b'`` / ``b1`` for the
acceleration image of B, ``π`` / ``π′`` / ``p′`` / ``pi`` / ``P`` for its pole, ``n_CB`` / ``n_cb``
/ ``nCB`` / ``n2`` / ``n1`` for the end of a normal component, ``k`` / ``k_A3A2`` for the Coriolis
component, ``S2`` / ``s2`` for the image of a centre of mass. A :class:`LabelBook` built from a
construction answers "which step is this label on which plan" with a weight saying how sure the
reading is; clusters of labels on a sheet then vote for their plan.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

from ..construct.graph import Construction
from ..construct.ops import Grade
from ..construct.segments import Segment
from ..construct.step import Kind, Plan
from ..errors import SceneError
from ..model.mechanism import GROUND, Mechanism
from ..scene.loader import SCALE_KEYS
from ..submission import notation
from ..submission.read import Entry, Note
from ..submission.written import label_key
from ..units import parse_quantity
from .texts import T

#: a plan drawn on its own: force polygons are one per group, the other plans one each
PlanKey = tuple[Plan, str]
#: how textbooks also write the pole of the velocity and the acceleration plan (usual readings)
POLE_ALIASES = {Plan.VELOCITY: ("p", "pv"),
                Plan.ACCELERATION: ("π", "π'", "p'", "pi", "pi'", "p1", "π1")}


@dataclass(frozen=True, slots=True)
class Candidate:
    """One reading of a written label: a point step of a plan, and how sure the reading is."""

    plan: PlanKey
    step: str
    label: str          # the construction's label of the step
    weight: int         # 3 exact, 2 usual alias, 1 weak alias
    convention: str = ""  # "link" / "ordinal" for numbered normals and Coriolis points


@dataclass
class LabelBook:
    """Label readings of every point of every plan of a construction."""

    plans: dict[PlanKey, dict[str, str]] = field(default_factory=dict)   # plan → step → label
    aliases: dict[PlanKey, dict[str, list[Candidate]]] = field(default_factory=dict)
    poles: dict[PlanKey, str] = field(default_factory=dict)

    @classmethod
    def build(cls, c: Construction, mech: Mechanism) -> LabelBook:
        """Collect the point steps of every plan with the ways people write their labels."""
        book = cls()
        # points of a plan are the ends of its segments and its pole (a force's own vector, a
        # value of Kind.POINT, is not a point of the polygon)
        ends = {sid for seg in c.segments for sid in (seg.start, seg.end)}
        for step in c:
            if step.kind is not Kind.POINT:
                continue
            origin = step.op.grade is Grade.ORIGIN
            if step.plan is not Plan.POSITION and not origin and step.id not in ends:
                continue
            key = plan_key(step.plan, step.group)
            steps = book.plans.setdefault(key, {})
            if step.label in steps.values():
                continue        # an earlier step already carries this label on this plan
            steps[step.id] = step.label
            if origin:
                book.poles[key] = step.id
        for key, steps in book.plans.items():
            book.aliases[key] = {}
            for sid, label in steps.items():
                book._add(key, label_key(label), sid, 3)
            book._add_plan_aliases(c, mech, key)
        return book

    def _add(self, key: PlanKey, alias: str, sid: str, weight: int, convention: str = "") -> None:
        entries = self.aliases[key].setdefault(alias, [])
        if not any(e.step == sid and e.convention == convention for e in entries):
            entries.append(Candidate(key, sid, self.plans[key][sid], weight, convention))

    def _add_plan_aliases(self, c: Construction, mech: Mechanism, key: PlanKey) -> None:
        plan = key[0]
        steps = self.plans[key]
        prime = "'" if plan is Plan.ACCELERATION else ""
        pole = self.poles.get(key)
        if pole is not None and plan in POLE_ALIASES:
            for alias in POLE_ALIASES[plan]:
                self._add(key, alias, pole, 2)
            # the images of frame points are the pole itself ("p ≡ o1 ≡ o3")
            for point in mech.links[GROUND].points:
                self._add(key, label_key(point) + prime, pole, 1)
        if plan is Plan.ACCELERATION:
            for sid, label in steps.items():
                base = label_key(label)
                if base.endswith("'") and not base[:-1][-1:].isdigit():
                    self._add(key, base[:-1] + "1", sid, 1)     # Russian "b1" for b′
        if plan in (Plan.VELOCITY, Plan.ACCELERATION):
            by_label = {label_key(lbl): sid for sid, lbl in steps.items()}
            for link_id in mech.moving:
                for point in mech.links[link_id].points:
                    own = label_key(point) + prime
                    if own not in by_label:
                        continue
                    alias = label_key(point + link_id) + prime      # "c2", "c_2", "C2'"
                    if alias not in by_label:
                        self._add(key, alias, by_label[own], 2)
        # normals n_XY and Coriolis points k_XY: reversed names, link numbers, ordinals, bare
        by_letter: dict[str, list[str]] = {}    # the operation's letter (``OpSpec.alias``)
        for sid in steps:
            if (letter := c[sid].op.alias) is not None:
                by_letter.setdefault(letter, []).append(sid)
        for letter, found in by_letter.items():
            for i, sid in enumerate(found, start=1):
                other_way = notation.reversed_points(label_key(steps[sid])[1:], mech)
                if other_way is not None:
                    self._add(key, letter + label_key(other_way), sid, 2)
                rate = c.quantity_of(c[sid].input("omega"))
                if rate is not None and rate[0] == "omega":   # n2: the normal of link 2
                    self._add(key, f"{letter}{rate[1]}", sid, 2, "link")
                self._add(key, f"{letter}{i}", sid, 2, "ordinal")
                if len(found) == 1:
                    self._add(key, letter, sid, 2)

    def candidates(self, text: str) -> list[Candidate]:
        """All readings of a written label, best first (exact label, usual alias, weak alias)."""
        raw = text.strip()
        alias = label_key(raw)
        out: list[Candidate] = []
        for table in self.aliases.values():
            out.extend(table.get(alias, []))
        if raw == "P":       # an upper-case P is the acceleration pole in several textbooks
            for key, pole in self.poles.items():
                if key[0] is Plan.ACCELERATION:
                    out.append(Candidate(key, pole, self.plans[key][pole], 2))
        out.sort(key=lambda cnd: -cnd.weight)
        return out


def plan_key(plan: Plan, group: str = "") -> PlanKey:
    """The key of a plan drawn on its own (force polygons per group)."""
    return (plan, group if plan is Plan.FORCE else "")


def segment_key(seg: Segment) -> PlanKey:
    """The key of the plan a measured segment is drawn on (its force group's polygon)."""
    return plan_key(seg.plan, seg.group)


def feature_votes(text: str) -> dict[Plan, int]:
    """What the look of a label says about its plan: primes and π → acceleration, capitals →
    position, lower case → velocity."""
    raw = text.strip()
    key = label_key(raw)
    if not key:
        return {}
    if key.startswith(("π", "pi")) or key.endswith("'"):
        return {Plan.ACCELERATION: 2}
    if key[0] in "nk" and len(key) > 1 and raw[0].islower():
        return {Plan.ACCELERATION: 1}
    if raw == "P":
        return {Plan.ACCELERATION: 1, Plan.POSITION: 1}
    if raw[0].isupper():
        return {Plan.POSITION: 2}
    return {Plan.VELOCITY: 1}


MU_NAMES: dict[str, Plan] = {
    "l": Plan.POSITION, "s": Plan.POSITION, "v": Plan.VELOCITY, "a": Plan.ACCELERATION,
    "f": Plan.FORCE, "p": Plan.FORCE, "r": Plan.FORCE,
}
_MU_NAME = re.compile(r"^(?:μ|µ|mu|u|k)[_\s{]*([lsvafprLSVAFPR])[}]?$", re.IGNORECASE)


def parse_mu(text: str, plan: Plan) -> float:
    """A written scale factor of a plan in SI ("0,1 м/с/мм"); a :class:`SceneError` if it is not
    one."""
    return parse_quantity(notation.units_ascii(text), SCALE_KEYS[plan.scale_key])


def written_mu(e: Entry, text: str, plan: Plan, notes: list[Note], level: str,
               unusable: str) -> float | None:
    """The scale factor ``text`` written as ``e`` in SI, or None with a note at ``level`` (the
    message ``unusable`` when the text is no scale factor of the plan)."""
    try:
        mu = parse_mu(text, plan)
    except SceneError as exc:
        notes.append(Note(level, T(unusable, name=e.name, text=text, detail=exc.detail), e.where))
        return None
    if not (mu > 0 and math.isfinite(mu)):
        notes.append(Note(level, T("note.mu_positive", name=e.name, text=text), e.where))
        return None
    return mu


def mu_plan(name: str) -> Plan | None:
    """The plan of a scale-factor name: "μv", "mu_v", "μ_a", "mu_F", "μl" (None otherwise)."""
    m = _MU_NAME.match(name.strip())
    if not m:
        return None
    return MU_NAMES[m.group(1).lower()]


