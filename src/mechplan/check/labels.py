"""Labels and quantity names as people write them, normalised to the construction's own.

Points on a plan are written in four traditions: ``b`` / ``b′`` / ``b'`` / ``b1`` for the
acceleration image of B, ``π`` / ``π′`` / ``p′`` / ``pi`` / ``P`` for its pole, ``n_CB`` / ``n_cb``
/ ``nCB`` / ``n2`` / ``n1`` for the end of a normal component, ``k`` / ``k_A3A2`` for the Coriolis
component, ``S2`` / ``s2`` for the image of a centre of mass. A :class:`LabelBook` built from a
construction answers "which step is this label on which plan" with a weight saying how sure the
reading is; clusters of labels on a sheet then vote for their plan.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from ..construct.graph import Construction
from ..construct.ops import Grade
from ..construct.segments import Segment
from ..construct.step import Kind, Plan
from ..model.mechanism import GROUND, Mechanism
from ..scene.loader import SCALE_KEYS
from ..submission import notation
from ..submission.written import label_key
from ..units import parse_quantity

#: a plan drawn on its own: force polygons are one per group, the other plans one each
PlanKey = tuple[Plan, str]


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
    def build(cls, c: Construction, mech: Mechanism | None = None) -> LabelBook:
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
            book.plans.setdefault(key, {})
            if step.label in book.plans[key].values():
                continue        # an earlier step already carries this label on this plan
            book.plans[key][step.id] = step.label
            if origin:
                book.poles[key] = step.id
        for key, steps in book.plans.items():
            table: dict[str, list[Candidate]] = {}
            book.aliases[key] = table
            for sid, label in steps.items():
                book._add(key, label_key(label), sid, label, 3)
            book._add_plan_aliases(c, mech, key)
        return book

    def _add(self, key: PlanKey, alias: str, sid: str, label: str, weight: int,
             convention: str = "") -> None:
        table = self.aliases[key]
        entries = table.setdefault(alias, [])
        if any(e.step == sid and e.convention == convention for e in entries):
            return
        entries.append(Candidate(key, sid, label, weight, convention))

    def _add_plan_aliases(self, c: Construction, mech: Mechanism | None, key: PlanKey) -> None:
        plan = key[0]
        steps = self.plans[key]
        pole = self.poles.get(key)
        if pole is not None:
            label = steps[pole]
            if plan is Plan.VELOCITY:
                for alias in ("p", "pv"):
                    self._add(key, alias, pole, label, 2)
            elif plan is Plan.ACCELERATION:
                for alias in ("π", "π'", "p'", "pi", "pi'", "p1", "π1"):
                    self._add(key, alias, pole, label, 2 if alias[0] in "πp" else 1)
            if mech is not None and plan in (Plan.VELOCITY, Plan.ACCELERATION):
                # the images of frame points are the pole itself ("p ≡ o1 ≡ o3")
                prime = "'" if plan is Plan.ACCELERATION else ""
                for point in mech.links[GROUND].points:
                    self._add(key, label_key(point) + prime, pole, label, 1)
        if plan is Plan.ACCELERATION:
            for sid, label in steps.items():
                base = label_key(label)
                if base.endswith("'") and not base[:-1][-1:].isdigit():
                    self._add(key, base[:-1] + "1", sid, label, 1)  # Russian "b1" for b′
        if mech is not None and plan in (Plan.VELOCITY, Plan.ACCELERATION):
            prime = "'" if plan is Plan.ACCELERATION else ""
            by_label = {label_key(lbl): sid for sid, lbl in steps.items()}
            for link_id, link in mech.links.items():
                if link_id == GROUND:
                    continue
                for point in link.points:
                    own = label_key(point) + prime
                    if own not in by_label:
                        continue
                    alias = label_key(point + link_id) + prime      # "c2", "c_2", "C2'"
                    if alias not in by_label:
                        self._add(key, alias, by_label[own], steps[by_label[own]], 2)
        # normals n_XY and Coriolis points k_XY: reversed names, link numbers, ordinals, bare
        by_letter: dict[str, list[str]] = {}    # the operation's letter (``OpSpec.alias``)
        for sid in steps:
            if (letter := c[sid].op.alias) is not None:
                by_letter.setdefault(letter, []).append(sid)
        for letter, found in by_letter.items():
            for i, sid in enumerate(found, start=1):
                step = c[sid]
                label = steps[sid]
                sub = label_key(label)[1:]
                names = notation.points(sub, mech) if mech is not None else None
                if names and len(names) == 2:
                    self._add(key, letter + label_key(names[1] + names[0]), sid, label, 2)
                rate = c.quantity_of(step.inputs[1]) if len(step.inputs) > 1 else None
                if rate is not None and rate[0] == "omega":   # n2: the normal of link 2
                    link_no = rate[1]
                    self._add(key, f"{letter}{link_no}", sid, label, 2, "link")
                self._add(key, f"{letter}{i}", sid, label, 2, "ordinal")
                if len(found) == 1:
                    self._add(key, letter, sid, label, 2)

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

    def label_of(self, key: PlanKey, sid: str) -> str:
        """The construction's label of a step."""
        return self.plans[key][sid]


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


def mu_plan(name: str) -> Plan | None:
    """The plan of a scale-factor name: "μv", "mu_v", "μ_a", "mu_F", "μl" (None otherwise)."""
    m = _MU_NAME.match(name.strip())
    if not m:
        return None
    return MU_NAMES[m.group(1).lower()]


