"""The label readings of a construction: which step each label people write stands for.

Points on a plan are written in four traditions: ``b`` / ``b′`` / ``b'`` / ``b1`` for the
acceleration image of B, ``π`` / ``π′`` / ``p′`` / ``pi`` / ``P`` for its pole, ``n_CB`` / ``n_cb``
/ ``nCB`` / ``n2`` / ``n1`` for the end of a normal component, ``k`` / ``k_A3A2`` for the Coriolis
component, ``S2`` / ``s2`` for the image of a centre of mass. :func:`label_book` fills a
:class:`~mechplan.submission.labels.LabelBook` from a construction; the reader of a sheet
(:mod:`mechplan.submission.drawn_plans`) looks labels up in it with a weight saying how sure the
reading is, and clusters of labels on a sheet then vote for their plan.
"""

from __future__ import annotations

from ..construct.graph import Construction
from ..construct.ops import Grade
from ..construct.segments import Segment
from ..construct.step import Kind
from ..model.mechanism import GROUND, Mechanism
from ..model.plans import Plan
from ..submission import notation
from ..submission.labels import POLE_ALIASES, LabelBook, PlanKey, plan_key
from ..submission.written import label_key


def label_book(c: Construction, mech: Mechanism) -> LabelBook:
    """Collect the point steps of every plan with the ways people write their labels."""
    book = LabelBook()
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
            book.add(key, label_key(label), sid, 3)
        _add_plan_aliases(book, c, mech, key)
    return book


def _add_plan_aliases(book: LabelBook, c: Construction, mech: Mechanism, key: PlanKey) -> None:
    plan = key[0]
    steps = book.plans[key]
    prime = "'" if plan is Plan.ACCELERATION else ""
    pole = book.poles.get(key)
    if pole is not None and plan in POLE_ALIASES:
        for alias in POLE_ALIASES[plan]:
            book.add(key, alias, pole, 2)
        # the images of frame points are the pole itself ("p ≡ o1 ≡ o3")
        for point in mech.links[GROUND].points:
            book.add(key, label_key(point) + prime, pole, 1)
    if plan is Plan.ACCELERATION:
        for sid, label in steps.items():
            base = label_key(label)
            if base.endswith("'") and not base[:-1][-1:].isdigit():
                book.add(key, base[:-1] + "1", sid, 1)     # Russian "b1" for b′
    if plan in (Plan.VELOCITY, Plan.ACCELERATION):
        by_label = {label_key(lbl): sid for sid, lbl in steps.items()}
        for link_id in mech.moving:
            for point in mech.links[link_id].points:
                own = label_key(point) + prime
                if own not in by_label:
                    continue
                alias = label_key(point + link_id) + prime      # "c2", "c_2", "C2'"
                if alias not in by_label:
                    book.add(key, alias, by_label[own], 2)
    # normals n_XY and Coriolis points k_XY: reversed names, link numbers, ordinals, bare
    by_letter: dict[str, list[str]] = {}    # the operation's letter (``OpSpec.alias``)
    for sid in steps:
        if (letter := c[sid].op.alias) is not None:
            by_letter.setdefault(letter, []).append(sid)
    for letter, found in by_letter.items():
        for i, sid in enumerate(found, start=1):
            other_way = notation.reversed_points(label_key(steps[sid])[1:], mech)
            if other_way is not None:
                book.add(key, letter + label_key(other_way), sid, 2)
            rate = c.quantity_of(c[sid].input("omega"))
            if rate is not None and rate[0] == "omega":   # n2: the normal of link 2
                book.add(key, f"{letter}{rate[1]}", sid, 2, "link")
            book.add(key, f"{letter}{i}", sid, 2, "ordinal")
            if len(found) == 1:
                book.add(key, letter, sid, 2)


def segment_key(seg: Segment) -> PlanKey:
    """The key of the plan a measured segment is drawn on (its force group's polygon)."""
    return plan_key(seg.plan, seg.group)
