"""Grow a sheet's drawings into the free room its panels leave: each redrawn, one step at a time,
at larger enlargements while the sheet's panels still fit it (used by the engine, cam and
kinematics sheet sets after :func:`.layout.paginate`)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from shapely.geometry.base import BaseGeometry

from .layout import (
    GOAL,
    Bounds,
    Groups,
    Sheetful,
    _footprint,
    coverage,
    paginate,
    refitted,
    sequence,
)
from .panels import Panel

#: the enlargements a drawing is redrawn at to fill its sheet's free room
#: (:func:`grow_into_room`): finer steps than :data:`.layout.ENLARGEMENTS`, as one drawing
#: grows alone
GROWTH = (0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.25, 1.4, 1.6, 1.8, 2.0)

def _one_sheet(panels: Sequence[Panel], area: BaseGeometry,
               bounds: Bounds) -> list[tuple[float, float]] | None:
    """The offsets of the panels packed on one sheet (rows first, else columns first), or None
    when they do not fit one."""
    for columns in (False, True):
        found = paginate(panels, area, columns=columns, bounds=bounds)
        if not isinstance(found, Panel) and len(found) == 1 \
                and [p.name for p in found[0][0]] == [p.name for p in panels]:
            return found[0][1]
    return None


def _movable(groups: Groups, s: int) -> list[Panel]:
    """The panels of the sheets after sheet ``s`` that could have gone on it: those with no
    earlier part of their sequence (a plan for its tables) on a sheet after ``s``."""
    out: list[Panel] = []
    later: set[str] = set()
    for panels, _ in groups[s + 1:]:
        for p in panels:
            if sequence(p.name) not in later:
                out.append(p)
            later.add(sequence(p.name))
    return out


def _frees_room(panels: Sequence[Panel], later: Sequence[Panel], area: BaseGeometry,
                bounds: Bounds) -> bool:
    """Tell whether a later sheet's panel would fit the free room these panels leave."""
    if not later:
        return False
    room = Sheetful(area, bounds=bounds)
    for p in panels:
        if room.put(p) is None:
            return False            # packed otherwise (columns first): not judged here
    return any(room.spot(*_footprint(q, bounds)[4:]) is not None for q in later)


def _pulled(trial: Sequence[Panel], current: Groups, area: BaseGeometry,
            bounds: Bounds) -> Groups | None:
    """The sheets from this one on when ``trial`` (this sheet's panels, one redrawn larger) leaves
    room a later sheet's panel fits: the later panels, in their order, packed again after these
    (rows first, else columns first; no panel split anew) — the panels that fit pulled onto this
    sheet. ``current``: this sheet and the later ones as they are. None when this sheet would
    not keep all of ``trial``, the set would take more sheets or leave more full sheets under
    :data:`.layout.GOAL`."""
    rest = [p for panels, _ in current[1:] for p in panels]
    names = [p.name for p in trial]
    before = _under(current, area)
    for columns in (False, True):
        found = paginate([*trial, *rest], area, columns=columns, bounds=bounds)
        if isinstance(found, Panel) or len(found) > len(current):
            continue
        if [p.name for p in found[0][0][:len(trial)]] == names \
                and len(found[0][0]) > len(trial) and _under(found, area) <= before:
            return found
    return None


def _box(b: tuple[float, float, float, float]) -> float:
    return (b[2] - b[0]) * (b[3] - b[1])


def _under(groups: Groups, area: BaseGeometry) -> int:
    """The full sheets (all but the last) of ``groups`` covered less than :data:`.layout.GOAL`."""
    return sum(coverage(list(zip(p, o)), area) < GOAL for p, o in groups[:-1])


def grow_into_room(build: Callable[[float], Sequence[Panel]], larger: Sequence[float],
                   groups: Groups, area: BaseGeometry, *,
                   pull: bool = False, onward: bool = False) -> tuple[Groups, dict[str, float]]:
    """Fill each sheet's free room: its drawings redrawn, one step at a time, at the larger
    enlargements ``larger`` (``build(k)``'s panel of the same name) as long as the sheet's panels
    still fit it (repacked in the same order). Tables and texts keep their size; which panels go
    on which sheet does not change (so no later panel fits an earlier sheet's room) — a drawing
    that would leave room a later panel fits stays as it is, or with ``pull`` is redrawn and the
    later sheets packed again after it (:func:`_pulled`: the panels that fit come onto its
    sheet, the set takes no more sheets). Return the sheets and the enlargement of every panel
    redrawn (name → k)."""
    steps = sorted(larger)
    if not steps:
        return groups, {}
    versions: list[dict[str, Panel]] = []
    for k in steps:
        drawn = refitted(build(k), area)
        names = [p.name for p in drawn]
        versions.append({p.name: p for p in drawn if names.count(p.name) == 1})
    bounds = Bounds()
    grown: dict[str, float] = {}
    groups = list(groups)
    out: Groups = []
    s = 0
    while s < len(groups):
        panels, offsets = list(groups[s][0]), groups[s][1]
        movable = _movable(groups, s)
        level = [-1] * len(panels)          # index into ``steps``; -1: as found
        changed = True
        while changed:
            changed = False
            for i, panel in enumerate(panels):
                # the next step that draws it differently (a table or a text: none)
                nxt = next((j for j in range(level[i] + 1, len(steps))
                            if panel.name in versions[j]
                            and bounds(versions[j][panel.name]) != bounds(panel)), None)
                if nxt is None:
                    level[i] = len(steps)
                    continue
                trial = panels[:i] + [versions[nxt][panel.name]] + panels[i + 1:]
                at = _one_sheet(trial, area, bounds)
                if onward and _box(bounds(trial[i])) <= _box(bounds(panel)):
                    at = None               # a shape no larger: not taken
                if at is not None and _frees_room(trial, movable, area, bounds):
                    again = _pulled(trial, [(panels, offsets), *groups[s + 1:]], area,
                                     bounds) if pull else None
                    if again is not None:
                        # later panels pulled onto this sheet: the sheets after it packed anew
                        groups[s + 1:] = again[1:]
                        movable = _movable(groups, s)
                        grown[panel.name] = steps[nxt]
                        level[i] = nxt
                        level += [len(steps)] * (len(again[0][0]) - len(trial))
                        panels, offsets, changed = list(again[0][0]), again[0][1], True
                        break
                    at = None               # redrawn, it would leave room a later panel fits
                if at is None:
                    # no larger drawing fits: it stays as it is (``onward``: the next one tried)
                    level[i] = nxt if onward else len(steps)
                    changed = changed or onward
                    continue
                panels, offsets, level[i], changed = trial, at, nxt, True
                grown[panel.name] = steps[nxt]
        out.append((panels, list(offsets)))
        s += 1
    return out, grown
