"""What written labels, scale-factor names, layer names and table sections say about plans.

A :class:`LabelBook` holds the readings of every point of every plan: the label the construction
gives it, the usual and weak aliases people write (``b1`` for b′, ``p``/``π`` for a pole, ``n2``
for the normal of link 2). It is filled by whoever knows the construction
(:func:`mechplan.check.labels.label_book`); the reader only looks labels up in it, so this package
knows no construction. Step ids here are opaque strings.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

from ..errors import SceneError
from ..model.plans import Plan
from ..units import parse_quantity
from . import notation
from .read import Entry, Note, Submission
from .texts import T
from .written import is_angle_name, label_key

#: a plan drawn on its own: force polygons are one per group, the other plans one each
PlanKey = tuple[Plan, str]
#: how textbooks also write the pole of the velocity and the acceleration plan (usual readings)
POLE_ALIASES = {Plan.VELOCITY: ("p", "pv"),
                Plan.ACCELERATION: ("π", "π'", "p'", "pi", "pi'", "p1", "π1")}


def plan_key(plan: Plan, group: str = "") -> PlanKey:
    """The key of a plan drawn on its own (force polygons per group)."""
    return (plan, group if plan is Plan.FORCE else "")


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
    """Label readings of every point of every plan."""

    plans: dict[PlanKey, dict[str, str]] = field(default_factory=dict)   # plan → step → label
    aliases: dict[PlanKey, dict[str, list[Candidate]]] = field(default_factory=dict)
    poles: dict[PlanKey, str] = field(default_factory=dict)

    def add(self, key: PlanKey, alias: str, sid: str, weight: int, convention: str = "") -> None:
        """Read ``alias`` (a :func:`label_key`) as step ``sid`` of plan ``key`` too."""
        entries = self.aliases.setdefault(key, {}).setdefault(alias, [])
        if not any(e.step == sid and e.convention == convention for e in entries):
            entries.append(Candidate(key, sid, self.plans[key][sid], weight, convention))

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


# -- scale factors -----------------------------------------------------------------------------
MU_NAMES: dict[str, Plan] = {
    "l": Plan.POSITION, "s": Plan.POSITION, "v": Plan.VELOCITY, "a": Plan.ACCELERATION,
    "f": Plan.FORCE, "p": Plan.FORCE, "r": Plan.FORCE,
}
_MU_NAME = re.compile(r"^(?:μ|µ|mu|u|k)[_\s{]*([lsvafprLSVAFPR])[}]?$", re.IGNORECASE)


def mu_plan(name: str) -> Plan | None:
    """The plan of a scale-factor name: "μv", "mu_v", "μ_a", "mu_F", "μl" (None otherwise)."""
    m = _MU_NAME.match(name.strip())
    if not m:
        return None
    return MU_NAMES[m.group(1).lower()]


def parse_mu(text: str, plan: Plan) -> float:
    """A written scale factor of a plan in SI ("0,1 м/с/мм"); a :class:`SceneError` if it is not
    one."""
    return parse_quantity(notation.units_ascii(text), plan.scale_dimension)


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


# -- layers and sections -----------------------------------------------------------------------
#: words in layer names that say which plan a drawing is (acceleration before velocity: 加速度)
LAYER_HINTS: tuple[tuple[Plan, tuple[str, ...]], ...] = (
    (Plan.ACCELERATION, ("acc", "ускор", "gia tốc", "gia toc", "加速度")),
    (Plan.VELOCITY, ("vel", "скор", "vận tốc", "van toc", "速度")),
    (Plan.FORCE, ("force", "сил", "lực", "luc", "力")),
    (Plan.POSITION, ("pos", "mech", "полож", "vị trí", "vi tri", "位置", "机构")),
)


def layer_plan(layer: str) -> Plan | None:
    """The plan a layer's name says a drawing is (None: it says none)."""
    low = layer.lower()
    for plan, words in LAYER_HINTS:
        if any(w in low for w in words):
            return plan
    return None


def section_plan(section: str | None) -> PlanKey | None:
    """The plan named by a table section or a CSV plan column ("velocity", "план ускорений")."""
    if not section:
        return None
    low = section.lower().strip()
    for word, plan in (("position", Plan.POSITION), ("velocit", Plan.VELOCITY),
                       ("acceleration", Plan.ACCELERATION), ("force", Plan.FORCE)):
        if low.startswith(word):
            group = section.strip()[len(word):].strip() if plan is Plan.FORCE else ""
            group = group.lstrip("s").strip() if group.startswith("s ") else group
            return plan_key(plan, group)
    layer = layer_plan(section)
    return None if layer is None else plan_key(layer)


def asks_for_forces(sub: Submission) -> bool:
    """Whether a submission holds a force plan or force values (its names, sections, layers)."""
    for e in sub.entries:
        plan = mu_plan(e.name)
        if plan is not None or is_angle_name(e.name):
            if plan is Plan.FORCE:
                return True
            continue
        if notation.dimension(e.name) in ("force", "moment") or (
                e.section and "force" in e.section.lower()):
            return True
    return any(layer_plan(t.layer) is Plan.FORCE for t in sub.texts) or any(
        layer_plan(ln.layer) is Plan.FORCE for ln in sub.lines)
