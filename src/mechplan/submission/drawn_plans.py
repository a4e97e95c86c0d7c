"""Labelled points of a drawn sheet, grouped into plans.

Line ends that meet (within ``snap`` mm) are one node; each label is given to the node nearest to
its text (within ``label_distance`` mm, reported), arrowhead barbs are not nodes a label can take,
and a label with no line end near it may take a crossing of two lines. Lines joined through nodes
form drawings; each drawing votes for its plan from the look of its labels (primes → acceleration,
capitals → position, lower case → velocity), a scale-factor text near it ("μv = 0,1") and its layer
name. Drawings of one plan whose labels do not clash are one plan.
"""

from __future__ import annotations

import math
import statistics
from collections import Counter
from collections.abc import Collection
from dataclasses import dataclass, field, replace

import numpy as np

from ..errors import CheckError
from ..geom.sketch import box_gap
from ..i18n import Text, join, plan_title, with_case
from ..model.plans import Plan
from .labels import Candidate, LabelBook, PlanKey, feature_votes, layer_plan, mu_plan, written_mu
from .notation import units_ascii
from .read import DrawnLine, Entry, Note, Point, SheetText, Submission
from .sketch import Graph, drawn_graph, place_labels
from .texts import T
from .titles import Box, box_of, names_group, title_above
from .written import label_key, label_names

#: drawings of one plan whose lines do not join are one plan when they are this close (mm)
MERGE_GAP_MM = 30.0


@dataclass(frozen=True, slots=True)
class LabelledPoint:
    """A point of a drawn plan: the step it stands for and where its label was found."""

    step: str
    label: str          # the construction's label
    written: str        # as written on the sheet
    at: Point           # the point (mm of paper)
    where: str          # the text entity of the label
    distance: float     # label → point (mm)
    how: str            # "line end", "point marker", "crossing of two lines", "inferred"


@dataclass
class DrawnPlan:
    """One plan found on a sheet."""

    key: PlanKey
    points: dict[str, LabelledPoint] = field(default_factory=dict)
    lines: list[DrawnLine] = field(default_factory=list)
    number: int = 0                 # 1, 2 … when a sheet holds several plans of one kind
    mu: float | None = None
    mu_source: str = ""
    convention: str = ""            # how numbered normals / Coriolis points were read
    title: str = ""                 # the text that titles the drawing (``titles.title_above``)

    @property
    def name(self) -> Text:
        """"velocity plan", "acceleration plan #2"."""
        return plan_title(self.key[0].value, self.key[1], self.number)

    @property
    def plan(self) -> Plan:
        """The kind of plan."""
        return self.key[0]


@dataclass
class DrawnSheet:
    """What was found on a sheet."""

    plans: list[DrawnPlan]
    notes: list[Note]
    label_distance: float
    other_entries: list[Entry]


# -- labels ----------------------------------------------------------------------------------
@dataclass
class _Label:
    text: SheetText
    written: str
    cands: list[Candidate]
    same: list[tuple[str, list[Candidate]]] = field(default_factory=list)  # "p≡c"
    at: Point | None = None     # None: no point near it
    distance: float = math.inf
    how: str = ""
    component: int = -1         # the drawing it labels


def find_plans(sub: Submission, book: LabelBook, label_distance: float | None = None,
               snap: float = 0.2, mu_elsewhere: Collection[Plan] = ()) -> DrawnSheet:
    """Find the labelled points of a sheet and group them into plans, each with the scale factor
    written beside it (not for the plans in ``mu_elsewhere``, whose μ is given otherwise)."""
    notes: list[Note] = []
    graph = drawn_graph(sub.lines, sub.markers, snap, sub.heads)
    # scale-factor texts and other "name = value" texts
    scale_entries = [(plan, e) for e in sub.entries if (plan := mu_plan(e.name)) is not None]
    other = [e for e in sub.entries if mu_plan(e.name) is None]
    labels: list[_Label] = []
    for t in sub.texts:
        if axis_title(t.text):             # "a, m/s²": a diagram's axis, not a point
            continue
        names = label_names(t.text)
        readings = [(n, book.candidates(n)) for n in names]
        readings = [(n, cands) for n, cands in readings if cands]
        if readings:
            labels.append(_Label(t, *readings[0], same=readings[1:]))
        elif len(names) == 1 and len(label_key(names[0])) <= 3 and names[0].isalpha():
            notes.append(Note("info", T("note.not_label", text=t.text.strip()), t.where))
    if not labels:
        if sub.lines:
            raise _no_labels(sub, book)
        return DrawnSheet([], notes, label_distance or 0.0, other)
    if label_distance is None:
        heights = [lb.text.height for lb in labels if lb.text.height > 0]
        label_distance = min(10.0, max(3.0, 2.0 * statistics.median(heights))) if heights else 5.0
    _attach(labels, graph, sub.lines, label_distance, notes)
    for lb in list(labels):        # "p≡c": one point, several names
        for written, cands in lb.same:
            labels.append(replace(lb, written=written, cands=cands, same=[]))
    attached = [lb for lb in labels if lb.at is not None]
    if not attached:
        raise _far_labels(sub, labels, label_distance)
    plans = _group(attached, graph, sub, book, scale_entries, notes)
    for dp in plans:
        if dp.plan not in mu_elsewhere:
            _scale_of(dp, scale_entries, notes)
    return DrawnSheet(plans, notes, label_distance, other)


#: unit symbols an axis title writes after its quantity ("s, m", "φ, °", "F, N")
_UNIT_WORDS = frozenset({"m", "mm", "N", "kN", "J", "kJ", "°", "rad", "deg", "W", "kW", "Pa",
                         "kPa", "MPa", "kg", "s"})


def axis_title(text: str) -> bool:
    """True for the title of a diagram's axis: a quantity and its unit after a comma ("a, m/s²",
    "ψ, °", "M_b, N·m"), which is no label of a point ("p, o1" names one point twice)."""
    if "=" in text or ":" in text:
        return False
    parts = [x.strip() for x in text.split(",")]
    if len(parts) != 2 or not parts[0] or not parts[1]:
        return False
    unit = units_ascii(parts[1])
    return unit in _UNIT_WORDS or any(ch in unit for ch in "/²³·*^")


def _no_labels(sub: Submission, book: LabelBook) -> Exception:
    known = sorted({lbl for steps in book.plans.values() for lbl in steps.values()})
    sample = ", ".join(known[:14]) + (" …" if len(known) > 14 else "")
    texts = [t.text for t in sub.texts][:6]
    found = T("error.texts_not_labels", texts=", ".join(repr(t) for t in texts)) if texts else ""
    return CheckError(T("error.no_labels", n=len(sub.lines), found=found, sample=sample),
                      file=sub.path)


def _far_labels(sub: Submission, labels: list[_Label], tol: float) -> Exception:
    worst = ", ".join(f"'{lb.written}' ({lb.text.where}, {lb.distance:.1f} mm)"
                      for lb in labels[:5])
    return CheckError(T("error.labels_far", tol=tol, worst=worst), file=sub.path)


def _attach(labels: list[_Label], graph: Graph, lines: list[DrawnLine], tol: float,
            notes: list[Note]) -> None:
    """Give each label its point on the sheet (:func:`place_labels`) and the drawing it labels."""
    for lb, spot in zip(labels, place_labels([lb.text for lb in labels], graph, lines, tol)):
        lb.at, lb.distance = spot.at, spot.distance
        if spot.node >= 0:
            lb.how = T("how.marker") if spot.node in graph.markers else T("how.line_end")
            lb.component = graph.component[spot.node]
        elif spot.at is not None:
            lb.how = T("how.crossing")
            lb.component = graph.nearest_component(spot.at)
        else:
            notes.append(Note("warning", T("note.label_far", written=lb.written, d=lb.distance,
                                           tol=tol), lb.text.where))


def _group(labels: list[_Label], graph: Graph, sub: Submission, book: LabelBook,
           scale_entries: list[tuple[Plan, Entry]], notes: list[Note]) -> list[DrawnPlan]:
    comps: dict[int, list[_Label]] = {}
    for lb in labels:
        comps.setdefault(lb.component, []).append(lb)
    lines_of: dict[int, list[DrawnLine]] = {}
    for i, (a, _) in enumerate(graph.line_nodes):
        lines_of.setdefault(graph.component[a], []).append(sub.lines[i])
    figures = _figures(lines_of, comps)
    kinds_in_book = {k[0] for k in book.plans}
    force_groups = [k[1] for k in book.plans if k[0] is Plan.FORCE and k[1]]
    decided: list[tuple[PlanKey, int, list[_Label]]] = []
    for comp, members in comps.items():
        votes: Counter[Plan] = Counter()
        for lb in members:
            plans_here = {c.plan[0]: c.weight for c in reversed(lb.cands)}
            votes.update(plans_here)
            votes.update({p: w for p, w in feature_votes(lb.written).items() if p in plans_here})
        hint = _hint_of(comp, members, graph, lines_of.get(comp, []), scale_entries, set(comps))
        # a title naming a force group ("Force plan I(0,1) — …") says the drawing is its polygon
        # (its μF may stand nearer another drawing)
        title = title_above(_points_of(members), sub.texts, force_groups,
                            _boxes(comps, [comp]), figures) if force_groups else None
        titled_force = title is not None and any(names_group(title.text, g)
                                                 for g in force_groups)
        if titled_force:
            hint.add(Plan.FORCE)
        votes.update(dict.fromkeys(hint, 3.0 * len(members) ** 0.5 + 3.0))
        if Plan.FORCE not in hint:
            votes.pop(Plan.FORCE, None)
        votes = Counter({p: v for p, v in votes.items() if p in kinds_in_book})
        if not votes:
            continue
        plan = Plan.FORCE if titled_force else max(
            votes, key=lambda p: (votes[p], -list(Plan).index(p)))
        keys = [k for k in book.plans if k[0] is plan]
        decided.append((_key_of(book, keys, members, sub, _boxes(comps, [comp]), figures),
                        comp, members))
    # merge drawings of one plan unless their labels clash
    plans: list[DrawnPlan] = []
    groups: list[tuple[PlanKey, list[int], list[_Label]]] = []
    for key, comp, members in decided:
        steps = _steps(members, key)
        for g in groups:
            if g[0] == key and not steps & _steps(g[2], key) \
                    and box_gap(_points_of(members), _points_of(g[2])) <= MERGE_GAP_MM:
                g[1].append(comp)
                g[2].extend(members)
                break
        else:
            groups.append((key, [comp], list(members)))
    found: list[DrawnPlan] = []
    for key, comps_, members in groups:
        dp = DrawnPlan(key)
        title = title_above(_points_of(members), sub.texts, [k[1] for k in book.plans],
                            _boxes(comps, comps_), figures)
        dp.title = title.text.strip() if title is not None else ""
        for comp in comps_:
            dp.lines.extend(lines_of.get(comp, []))
        _resolve(dp, members, book, notes)
        _pole(dp, book, graph, sub, notes)
        if dp.points:
            found.append(dp)
    # one labelled point measures nothing: beside real plans it is a stray label (a letter of a
    # note), and a pole alone is no plan anywhere (Zhukovsky's lever labels its pole p) — not
    # plans whose every segment would be "missing"
    others = any(len(dp.points) >= 2 for dp in found)
    lone = [dp for dp in found if len(dp.points) == 1
            and (others or set(dp.points) == {book.poles.get(dp.key)})]
    for dp in lone:
        for lp in dp.points.values():
            notes.append(Note("info", T("note.lone_label", written=lp.written), lp.where))
    found = [dp for dp in found if all(dp is not x for x in lone)]
    counts = Counter(dp.key for dp in found)
    seen: Counter[PlanKey] = Counter()
    for dp in found:
        if counts[dp.key] > 1:
            seen[dp.key] += 1
            dp.number = seen[dp.key]
        plans.append(dp)
    for key, n in counts.items():
        if n > 1:
            notes.append(Note("warning", T("note.repeated_plans", n=n,
                                           plan=plan_title(key[0].value, key[1], case="gen")),
                              sub.path))
    return plans


def _boxes(comps: dict[int, list[_Label]], but: list[int]) -> list[Box]:
    """The boxes of the labelled drawings other than ``but``."""
    return [b for c, members in comps.items() if c not in but
            and (b := box_of(_points_of(members))) is not None]


def _figures(lines_of: dict[int, list[DrawnLine]], labelled: Collection[int]) -> list[Box]:
    """The boxes of the unlabelled figures of lines (a table's rules, a frame): a text standing
    over one of them heads it, not the drawing below."""
    out = []
    for comp, lines in lines_of.items():
        if comp in labelled:
            continue
        xs = [c for ln in lines for c in (ln.start[0], ln.end[0])]
        ys = [c for ln in lines for c in (ln.start[1], ln.end[1])]
        out.append((min(xs), max(xs), min(ys), max(ys)))
    return out


def _key_of(book: LabelBook, keys: list[PlanKey], members: list[_Label],
            sub: Submission, others: list[Box], figures: list[Box]) -> PlanKey:
    """Which plan of a kind a drawing is: the group its title names (two cranks' force polygons
    carry the same letters), else the plan its labels fit best."""
    if len(keys) > 1:
        groups = [k[1] for k in keys if k[1]]
        title = title_above(_points_of(members), sub.texts, groups, others, figures)
        named = [k for k in keys if title is not None and names_group(title.text, k[1])]
        if len(named) == 1:
            return named[0]
    return max(keys, key=lambda k: _fit(book, k, members))


def _fit(book: LabelBook, key: PlanKey, members: list[_Label]) -> float:
    """How well labels fit one plan: force polygons share letters (a, b, c …), so the group
    whose points the labels cover best, and fill best."""
    found = {c.step for lb in members for c in lb.cands if c.plan == key}
    return len(found) / (len(book.plans[key]) + len(members) - len(found))


def _points_of(labels: list[_Label]) -> list[Point]:
    return [lb.at for lb in labels if lb.at is not None]


def _hint_of(comp: int, members: list[_Label], graph: Graph, lines: list[DrawnLine],
             scale_entries: list[tuple[Plan, Entry]], labelled: set[int]) -> set[Plan]:
    hints: set[Plan] = set()
    layers = [layer_plan(ln.layer) for ln in lines] + [layer_plan(lb.text.layer)
                                                         for lb in members]
    named = Counter(p for p in layers if p is not None)
    for plan, n in named.most_common(1):    # the plan most layers name, if more than half do
        if n > named.total() / 2:
            hints.add(plan)
    # a scale-factor text belongs to the labelled drawing nearest to it
    for plan, entry in scale_entries:
        if entry.at is not None and _mu_owner(entry.at, graph, labelled) == comp:
            hints.add(plan)
    return hints


def _mu_owner(at: Point, graph: Graph, labelled: set[int]) -> int:
    """The labelled drawing a scale-factor text at ``at`` belongs to: the one whose box is
    nearest (a text stands above or beside its plan; a long vector's far end is no measure of
    where its drawing is); among drawings whose boxes hold the text, the one with the nearest
    line end."""
    comp = np.asarray(graph.component)
    best: list[tuple[float, float, int]] = []
    for c in labelled:
        pts = graph.nodes[comp == c]
        if not len(pts):
            continue
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        gap = np.maximum(np.maximum(lo - at, np.asarray(at) - hi), 0.0)
        node = float(np.hypot(*(pts - at).T).min())
        best.append((float(np.hypot(*gap)), node, c))
    return min(best)[2] if best else -1


def _reading(lb: _Label, key: PlanKey, convention: str = "") -> Candidate | None:
    """The best reading of a label as a point of one plan, under a numbering convention of normals
    and Coriolis points ("link", "ordinal"; "" for a reading without one)."""
    return next((c for c in lb.cands if c.plan == key and c.convention == convention), None)


def _steps(labels: list[_Label], key: PlanKey) -> set[str]:
    """The steps of one plan labels are read as without a numbering convention."""
    return {c.step for lb in labels if (c := _reading(lb, key)) is not None}


def _resolve(dp: DrawnPlan, members: list[_Label], book: LabelBook, notes: list[Note]) -> None:
    key = dp.key
    chosen: dict[int, Candidate] = {}
    numbered: list[int] = []
    for i, lb in enumerate(members):
        plain = _reading(lb, key)
        if plain is not None:
            chosen[i] = plain
        elif any(c.plan == key for c in lb.cands):
            numbered.append(i)
        else:
            known = ", ".join(sorted(book.plans[key].values()))
            notes.append(Note("warning", T("note.not_point_of_plan", written=lb.written,
                                           plan=plan_title(key[0].value, key[1], case="gen"),
                                           known=known), lb.text.where))
    if numbered:
        for convention in ("link", "ordinal"):
            picks = {i: c for i in numbered
                     if (c := _reading(members[i], key, convention)) is not None}
            if len(picks) == len(numbered) and len({c.step for c in picks.values()}) == len(picks):
                chosen.update(picks)
                how = T("convention.link" if convention == "link" else "convention.ordinal")
                written = join(members[i].written for i in numbered)
                dp.convention = T("convention.numbered", written=written, how=how)
                break
        else:
            for i in numbered:
                notes.append(Note("warning", T("note.ambiguous_numbered",
                                               written=members[i].written),
                                  members[i].text.where))
    by_step: dict[str, list[int]] = {}
    for i, c in chosen.items():
        by_step.setdefault(c.step, []).append(i)
    for sid, idx in by_step.items():
        idx = _surest(sid, idx, members, chosen, book, key, notes)
        spots = {members[i].at for i in idx}
        if len(spots) > 1:
            where = join((T("note.where_at", where=members[i].text.where, xy=_xy(members[i].at))
                          for i in idx), "; ")
            notes.append(Note("error", T("note.label_repeated", label=book.plans[key][sid],
                                         n=len(idx), where=where,
                                         plan=plan_title(key[0].value, key[1], case="loc")),
                              members[idx[0]].text.where))
            continue
        lb = min((members[i] for i in idx), key=lambda m: m.distance)
        assert lb.at is not None
        dp.points[sid] = LabelledPoint(sid, book.plans[key][sid], lb.written, lb.at,
                                       lb.text.where, lb.distance, lb.how)


def _surest(sid: str, idx: list[int], members: list[_Label], chosen: dict[int, Candidate],
            book: LabelBook, key: PlanKey, notes: list[Note]) -> list[int]:
    """The labels of one point to keep: where they stand at different points, those read most
    surely (the exact label over an alias, e.g. ``g`` over a weight's ``G5`` read as g₅) when
    they agree on one point; the others are noted and left out. All of them otherwise."""
    if len({members[i].at for i in idx}) < 2:
        return idx
    top = max(chosen[i].weight for i in idx)
    surest = [i for i in idx if chosen[i].weight == top]
    if len({members[i].at for i in surest}) > 1:
        return idx
    for i in idx:
        if i not in surest:
            notes.append(Note("warning", T("note.label_weaker", written=members[i].written,
                                           label=book.plans[key][sid],
                                           plan=plan_title(key[0].value, key[1], case="gen")),
                              members[i].text.where))
    return surest


def _xy(p: Point | None) -> str:
    return "(?)" if p is None else T("xy", x=p[0], y=p[1])


def _pole(dp: DrawnPlan, book: LabelBook, graph: Graph, sub: Submission,
          notes: list[Note]) -> None:
    pole = book.poles.get(dp.key)
    if pole is None or pole in dp.points or len(dp.points) < 2:
        return
    # the pole is where most vectors to labelled points start
    count = graph.ends_from(p.at for p in dp.points.values())
    if not count:
        return
    (n, best), *rest = count.most_common(2)
    if best < 2 or (rest and rest[0][1] == best):
        notes.append(Note("warning", T("note.pole_unknown", plan=with_case(dp.name, "gen")),
                          sub.path))
        return
    at = (float(graph.nodes[n][0]), float(graph.nodes[n][1]))
    label = book.plans[dp.key][pole]
    dp.points[pole] = LabelledPoint(pole, label, "", at, sub.path, 0.0, T("how.inferred"))
    notes.append(Note("info", T("note.pole_inferred", label=label, plan=with_case(dp.name, "gen"),
                                xy=_xy(at), n=best), sub.path))


def _scale_of(dp: DrawnPlan, scale_entries: list[tuple[Plan, Entry]], notes: list[Note]) -> None:
    plan = dp.plan
    mine = [e for p, e in scale_entries if p is plan]
    if len(mine) > 1 and dp.points:
        centre = np.mean([p.at for p in dp.points.values()], axis=0)
        mine.sort(key=lambda e: math.inf if e.at is None else math.dist(e.at, centre))
    for e in mine:
        text = e.text or e.value or e.length or ""
        dp.mu = written_mu(e, text, plan, notes, "warning", "note.mu_unusable")
        if dp.mu is not None:
            dp.mu_source = T("mu.text", name=e.name, text=text, where=e.where)
            return
