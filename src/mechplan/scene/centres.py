"""The ``[centres]`` table: which links' centrodes, acceleration poles and inflection circles."""

from __future__ import annotations

from dataclasses import dataclass

from ..i18n import Text
from ..model.mechanism import GROUND, Link
from .reader import Table

#: the plan name a scene asks for the instant centres by (and the spelling it also takes)
CENTRES = "centres"
ALIASES = ("instant_centres", "instant_centers", "centers")
#: positions over the cycle the centrodes are traced at, by default
CENTRODE_POSITIONS = 360


@dataclass(frozen=True, slots=True)
class CentresSpec:
    """What the instant centres of a scene show beyond the centres and velocities by them.

    ``links``: the links whose fixed and moving centrodes (over ``positions`` positions of the
    cycle), acceleration pole and (``inflection``) inflection circle are given."""

    links: tuple[str, ...] = ()
    positions: int = CENTRODE_POSITIONS
    inflection: bool = False


def centres_of(top: Table, links: dict[str, Link]) -> CentresSpec | None:
    """Read ``[centres]`` (None when the scene has none)."""
    t = top.table(CENTRES)
    if t is None:
        return None
    t.check_keys(("links", "positions", "inflection"))
    chosen = t.raw("links", [])
    if not isinstance(chosen, list) or not all(isinstance(x, (str, int)) for x in chosen):
        raise t.error("links", Text(
            "errmsg2.scene_centres.links_list",
            {"value": repr(chosen)}))
    out = tuple(str(x) for x in chosen)
    for lid in out:
        if lid not in links or lid == GROUND:
            moving = ", ".join(k for k in links if k != GROUND)
            raise t.error("links", Text(
                "errmsg2.scene_centres.unknown_moving",
                {"link": repr(lid), "links": moving}))
    count = t.raw("positions", CENTRODE_POSITIONS)
    if not isinstance(count, int) or isinstance(count, bool) or not 4 <= count <= 100_000:
        raise t.error("positions", Text(
            "errmsg2.scene_centres.count_range",
            {"value": repr(count)}))
    inflection = t.raw("inflection", False)
    if not isinstance(inflection, bool):
        raise t.error("inflection", Text(
            "errmsg2.scene_centres.true_false",
            {"value": repr(inflection)}))
    return CentresSpec(out, count, inflection)


def plan_names(plans: list[str]) -> list[str]:
    """The plan names with the aliases of ``centres`` spelt ``centres``."""
    return [CENTRES if p in ALIASES else p for p in plans]
