"""Grow a sheet's drawings into the free room its panels leave: each redrawn, one step at a time,
at larger enlargements while the sheet's panels still fit it (used by the engine, cam and
kinematics sheet sets after :func:`.layout.paginate`)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from shapely.geometry.base import BaseGeometry

from .layout import Bounds, Groups, Sheetful, _footprint, paginate, refitted, sequence
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


def grow_into_room(build: Callable[[float], Sequence[Panel]], larger: Sequence[float],
                   groups: Groups, area: BaseGeometry) -> tuple[Groups, dict[str, float]]:
    """Fill each sheet's free room: its drawings redrawn, one step at a time, at the larger
    enlargements ``larger`` (``build(k)``'s panel of the same name) as long as the sheet's panels
    still fit it (repacked in the same order). Tables and texts keep their size; which panels go
    on which sheet does not change (so no later panel fits an earlier sheet's room). Return the
    sheets and the enlargement of every panel redrawn (name → k)."""
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
    out: Groups = []
    for s, (panels, offsets) in enumerate(groups):
        panels = list(panels)
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
                if at is not None and _frees_room(trial, movable, area, bounds):
                    at = None               # redrawn, it would leave room a later panel fits
                if at is None:
                    level[i] = len(steps)   # no larger drawing fits: it stays as it is
                    continue
                panels, offsets, level[i], changed = trial, at, nxt, True
                grown[panel.name] = steps[nxt]
        out.append((panels, list(offsets)))
    return out, grown
