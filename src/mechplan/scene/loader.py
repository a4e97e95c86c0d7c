"""Read a TOML scene file into a frozen :class:`Scene`."""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

from ..drafting.fields import SHEETS, STANDARDS, TITLE_BLOCK_FIELDS
from ..errors import SceneError, TopologyError
from ..i18n import LANGUAGES, Text
from ..model.mechanism import GROUND, Drive, DriverKind, Guide, Link, Mechanism, Pair, PairKind
from ..model.plans import Plan
from ..model.structure import analyse
from .centres import CENTRES, centres_of, plan_names
from .crank_law import crank_law_drive, crank_law_positions
from .document import parse_toml
from .drivers import linear_assembly_default, linear_drive, linear_positions
from .geometry import POINT_NAME, extra_point, parse_side, split_pair, triangulate
from .loads import friction_of, gravity_of, loads_of, masses_of
from .reader import Table
from .spec import (
    PLANS,
    DrawingSpec,
    Extreme,
    Positions,
    Scene,
)
from .textbook import parse_textbook

TOP_KEYS = ("kind", "title", "language", "ground", "links", "drive", "assembly", "positions",
            "analysis", "gravity", "loads", "friction", "drawing", "title_block", "description",
            "dynamics", "answers", "centres", "drive2")
LINK_KEYS = ("name", "lengths", "side", "points", "slides", "guides", "guide", "mass", "centre",
             "center", "J", "inertia")
#: scale-factor keys of [drawing.scales] and their dimensions: each plan's, and the moments'
SCALE_KEYS = {plan.scale_key: plan.scale_dimension for plan in Plan} | {"mu_M": "mu_moment"}


def load_scene(path: str | Path) -> Scene:
    """Read and validate a scene file."""
    from .document import read_text

    return parse_scene(read_text(path), str(path))


def parse_scene(text: str, file: str = "<scene>") -> Scene:
    """Parse scene text (TOML)."""
    top = Table(parse_toml(text, file), "", file)
    top.check_keys(TOP_KEYS)
    language = top.string("language", "en", choices=LANGUAGES)
    ground_points, guides = _ground(top)
    links, link_guides = _links(top, ground_points)
    guides.update(link_guides)
    for link in links.values():
        if link.slides_on and link.slides_on not in guides:
            raise top.error(f"links.{link.id}.slides.on", Text(
                "errmsg2.scene_loader.unknown_guide",
                {"guide": repr(link.slides_on),
                 "guides": ", ".join(guides) or Text("errmsg2.scene_loader.none")}))
    _orient_sliders(top, links, guides)
    pairs = _pairs(top, links, guides)
    drive = _drive(top, links, guides, pairs)
    sides, sketch, assembly_phi = _assembly(top, links, drive)
    from .second_driver import second_drive

    mech = Mechanism(links=links, pairs=tuple(pairs), guides=guides, drive=drive, sides=sides,
                     sketch=sketch, drive2=second_drive(top, links, guides, pairs, drive))
    try:
        analyse(mech)
    except TopologyError as exc:
        raise TopologyError(_shared_frame_hint(top, links, exc.detail), file=file,
                            key=exc.key) from None
    all_points = {p for link in links.values() for p in link.points}
    positions = _positions(top, drive, all_points, links)
    if drive.linear and drive.q_range is None:      # the listed lengths span the range
        drive = replace(drive, q_range=(min(positions.angles), max(positions.angles)))
        mech = replace(mech, drive=drive)
    masses = masses_of(top, links)
    plans, interest = _analysis(top, all_points)
    if not top.has("analysis") and (masses or top.raw("loads")):
        plans = (*plans, "force")      # a scene with masses or loads asks for its forces
    centres = centres_of(top, links)
    if centres is not None and CENTRES not in plans:
        plans = (*plans, CENTRES)      # a [centres] table asks for the instant centres
    return Scene(
        path=file, title=top.string("title", Path(file).stem) or "", language=language or "en",
        mechanism=mech, positions=positions, plans=plans, points_of_interest=interest,
        masses=masses, loads=loads_of(top, links, guides, masses), gravity=gravity_of(top),
        drawing=_drawing(top, len(positions.angles) or positions.count),
        assembly_phi=assembly_phi, textbook=parse_textbook(top.data, file, mech),
        friction=friction_of(top), centres=centres)


def _ground(top: Table) -> tuple[dict[str, tuple[float, float]], dict[str, Guide]]:
    ground = top.table("ground", required=True)
    assert ground is not None
    points: dict[str, tuple[float, float]] = {}
    guide_tables = []
    for name, value in ground.data.items():
        if name in ("guide", "guides"):
            guide_tables.append(ground.table(name))
            continue
        if not POINT_NAME.match(name):
            raise ground.error(name, Text("errmsg2.scene_loader.frame_point_capital"))
        if not isinstance(value, list) or len(value) != 2:
            raise ground.error(name, Text(
                "errmsg2.scene_loader.frame_coordinates",
                {"value": repr(value)}))
        points[name] = (ground.value_quantity(value[0], name, "length"),
                        ground.value_quantity(value[1], name, "length"))
    if not points:
        raise ground.error(None, Text("errmsg2.scene_loader.no_frame_point"))
    guides: dict[str, Guide] = {}
    for gt in guide_tables:
        assert gt is not None
        for gname in gt.data:
            g = gt.table(gname)
            assert g is not None
            guides[gname] = _guide(g, gname, GROUND, points)
    return points, guides


def _guide(g: Table, name: str, link: str, local: dict[str, tuple[float, float]]) -> Guide:
    g.check_keys(("through", "angle", "toward", "towards"))
    through = g.string("through", required=True)
    assert through is not None
    if through not in local:
        raise g.error("through", Text(
            "errmsg2.scene_loader.unknown_through",
            {"point": repr(through), "points": ', '.join(local)}))
    origin = local[through]
    toward = g.string("toward") or g.string("towards")
    if toward is not None:
        if toward not in local:
            raise g.error("toward", Text(
                "errmsg2.scene_loader.unknown_toward",
                {"point": repr(toward), "points": ', '.join(local)}))
        dx, dy = local[toward][0] - origin[0], local[toward][1] - origin[1]
        if dx == 0 and dy == 0:
            raise g.error("toward", Text(
                "errmsg2.scene_loader.toward_coincides",
                {"toward": toward, "through": through}))
        angle = math.atan2(dy, dx)
    else:
        angle_v = g.quantity("angle", "angle")
        if angle_v is None:
            raise g.error(None, Text(
                "errmsg2.scene_loader.guide_needs_angle",
                {"name": name}))
        angle = angle_v
    return Guide(name=name, link=link, origin=origin, angle=angle, through=through)


def _links(top: Table, ground: dict[str, tuple[float, float]]
           ) -> tuple[dict[str, Link], dict[str, Guide]]:
    lt = top.table("links", required=True)
    assert lt is not None
    links: dict[str, Link] = {GROUND: Link(GROUND, "frame", dict(ground))}
    guides: dict[str, Guide] = {}
    if not lt.data:
        raise lt.error(None, Text("errmsg2.scene_loader.no_links"))
    for link_id in lt.data:
        if link_id == GROUND:
            raise lt.error(link_id, Text("errmsg2.scene_loader.link_zero_frame"))
        t = lt.table(link_id)
        assert t is not None
        t.check_keys(LINK_KEYS)
        local, slides_on = _link_points(t, link_id)
        link = Link(id=link_id, name=t.string("name", "") or "", points=local, slides_on=slides_on)
        links[link_id] = link
        for gkey in ("guides", "guide"):
            gt = t.table(gkey)
            if gt is not None:
                for gname in gt.data:
                    if gname in guides:
                        raise gt.error(gname, Text("errmsg2.scene_loader.guide_exists"))
                    sub = gt.table(gname)
                    assert sub is not None
                    guides[gname] = _guide(sub, gname, link_id, local)
    return links, guides


def _link_points(t: Table, link_id: str) -> tuple[dict[str, tuple[float, float]], str | None]:
    lengths: dict[str, float] = {}
    keys: dict[str, str] = {}
    lengths_t = t.table("lengths")
    if lengths_t is not None:
        for key in lengths_t.data:
            pair = split_pair(key)
            if pair is None or pair[0] == pair[1]:
                raise lengths_t.error(key, Text("errmsg2.scene_loader.length_key"))
            value = lengths_t.quantity(key, "length", positive=True)
            assert value is not None
            k = "|".join(pair)
            if k in lengths or "|".join(pair[::-1]) in lengths:
                raise lengths_t.error(key, Text("errmsg2.scene_loader.length_twice"))
            lengths[k] = value
            keys[k] = key
    sides: dict[str, tuple[str, str, int]] = {}
    side_t = t.table("side")
    if side_t is not None:
        for name in side_t.data:
            text = side_t.string(name)
            parsed = parse_side(text or "")
            if parsed is None:
                raise side_t.error(name, Text(
                    "errmsg2.scene_loader.side_text",
                    {"text": repr(text)}))
            sides[name] = parsed
    slides_on = None
    local: dict[str, tuple[float, float]] = {}
    slides_t = t.table("slides")
    if slides_t is not None:
        slides_t.check_keys(("point", "on"))
        point = slides_t.string("point", required=True)
        slides_on = slides_t.string("on", required=True)
        if lengths:
            raise t.error("lengths", Text("errmsg2.scene_loader.slider_lengths"))
        assert point is not None
        if not POINT_NAME.match(point):
            raise slides_t.error("point", Text(
                "errmsg2.scene_loader.not_point_name",
                {"point": repr(point)}))
        local[point] = (0.0, 0.0)
    elif lengths:
        local = triangulate(t, lengths, keys, sides)
    points_t = t.table("points")
    if points_t is not None:
        for name, spec in points_t.data.items():
            if not POINT_NAME.match(name):
                raise points_t.error(name, Text("errmsg2.scene_loader.point_capital"))
            if name in local:
                raise points_t.error(name, Text(
                    "errmsg2.scene_loader.point_twice",
                    {"name": name, "link": link_id}))
            local[name] = extra_point(t, name, spec, local)
    centre = t.raw("centre", t.raw("center"))
    if isinstance(centre, dict):
        ct = t.table("centre" if t.has("centre") else "center")
        assert ct is not None
        for name, spec in ct.data.items():
            if name not in local:
                local[name] = extra_point(t, name, spec, local)
    if not local:
        raise t.error(None, Text("errmsg2.scene_loader.link_no_points", {"link": link_id}))
    if slides_on is None and len(local) < 2:
        raise t.error("lengths", Text(
            "errmsg2.scene_loader.link_one_length",
            {"link": link_id}))
    return local, slides_on


def _shared_frame_hint(top: Table, links: dict[str, Link], detail: str) -> str:
    """``detail`` and the extra points (``points = {...}``) that join a link to the frame by their
    name."""
    frame = set(links[GROUND].points)
    found = []
    lt = top.table("links")
    for lid in links:
        t = lt.table(lid) if lt is not None and lid != GROUND and lid in lt.data else None
        extra = t.raw("points", {}) if t is not None else {}
        for name in extra if isinstance(extra, dict) else ():
            if name in frame:
                found.append(f"links.{lid}.points.{name}")
    if not found:
        return detail
    return Text("errmsg2.scene_loader.frame_hint", {"detail": detail, "found": ", ".join(found)})


def _orient_sliders(top: Table, links: dict[str, Link], guides: dict[str, Guide]) -> None:
    """Check sliders do not slide on their own guide."""
    for link in links.values():
        if link.slides_on and guides[link.slides_on].link == link.id:
            raise top.error(f"links.{link.id}.slides.on", Text(
                "errmsg2.scene_loader.slides_own_guide"))


def _pairs(top: Table, links: dict[str, Link], guides: dict[str, Guide]) -> list[Pair]:
    pairs: list[Pair] = []
    seen: dict[str, list[str]] = {}
    for lid, link in links.items():
        for p in link.points:
            seen.setdefault(p, []).append(lid)
    for point, on in seen.items():
        for other in on[1:]:
            pairs.append(Pair(PairKind.REVOLUTE, on[0], other, point))
    for lid, link in links.items():
        if link.slides_on:
            g = guides[link.slides_on]
            point = next(iter(link.points))
            pairs.append(Pair(PairKind.PRISMATIC, lid, g.link, point, g.name))
    for lid, link in links.items():
        carries = any(g.link == lid and any(o.slides_on == g.name for o in links.values())
                      for g in guides.values())
        if link.slides_on and not carries and not any(len(seen[p]) > 1 for p in link.points):
            point = next(iter(link.points))
            joints = sorted(p for p, on in seen.items() if lid not in on)
            raise top.error(f"links.{lid}.slides.point", Text(
                "errmsg2.scene_loader.slide_point_joint",
                {"point": repr(point),
                 "points": ", ".join(joints) or Text("errmsg2.scene_loader.none")}))
    for lid, link in links.items():
        if lid != GROUND and not any(p.joins(lid) for p in pairs):
            raise top.error(f"links.{lid}", Text(
                "errmsg2.scene_loader.link_unconnected",
                {"link": lid}))
    return pairs


def _drive(top: Table, links: dict[str, Link], guides: dict[str, Guide],
           pairs: list[Pair]) -> Drive:
    d = top.table("drive", required=True)
    assert d is not None
    kind = d.string("kind", "crank", choices=tuple(k.value for k in DriverKind))
    if kind != "crank":
        return linear_drive(d, DriverKind(kind), links, guides, pairs)
    d.check_keys(("kind", "link", "speed", "omega", "sense", "from", "angle", "epsilon", "law"))
    return crank_drive(d, links, guides, pairs)


def crank_drive(d: Table, links: dict[str, Link], guides: dict[str, Guide],
                pairs: list[Pair]) -> Drive:
    """A crank named by a drive table (``[drive]``, ``[drive2]``) with its speed and sense."""
    link = d.string("link", required=True)
    assert link is not None
    if link not in links or link == GROUND:
        known = ", ".join(k for k in links if k != GROUND)
        raise d.error("link", Text("errmsg2.scene_loader.unknown_drive_link",
                                   {"link": repr(link), "links": known}))
    sense = d.string("sense", "ccw", choices=("cw", "ccw"))
    pivots = [p.point for p in pairs
              if p.kind is PairKind.REVOLUTE and {p.a, p.b} == {GROUND, link}]
    if len(pivots) != 1:
        raise d.error("link", Text("errmsg2.scene_loader.drive_one_pivot",
                                   {"link": link, "count": str(len(pivots))}))
    ref_name = d.string("from", "+x") or "+x"
    ref = _reference_angle(d, ref_name, guides)
    sign = 1.0 if sense == "ccw" else -1.0
    if d.has("law"):        # φ(t) by a table (scene/crank_law.py)
        return crank_law_drive(d, link, pivots[0], ref, ref_name, sign, first=d.path == "drive")
    if not d.has("speed") and not d.has("omega"):
        raise d.error("speed", Text("errmsg2.scene_loader.speed_missing"))
    speed_key = "speed" if d.has("speed") else "omega"
    speed = d.quantity(speed_key, "angular_velocity", required=True, positive=True)
    assert speed is not None
    eps = d.quantity("epsilon", "angular_acceleration", 0.0) or 0.0
    return Drive(link=link, pivot=pivots[0], omega=sign * speed, epsilon=sign * eps,
                 ref_angle=ref, ref_name=ref_name)


def _reference_angle(d: Table, name: str, guides: dict[str, Guide]) -> float:
    axes = {"+x": 0.0, "x": 0.0, "+y": math.pi / 2, "y": math.pi / 2, "-x": math.pi,
            "-y": -math.pi / 2}
    if name in axes:
        return axes[name]
    if name in guides:
        if guides[name].link != GROUND:
            raise d.error("from", Text("errmsg2.scene_loader.guide_moves", {"name": name}))
        return guides[name].angle
    try:
        return d.value_quantity(name, "from", "angle")
    except SceneError:
        raise d.error("from", Text(
            "errmsg2.scene_loader.phi_from",
            {"guides": ", ".join(guides) or Text("errmsg2.scene_loader.none_defined"),
             "value": repr(name)})) from None


def _assembly(top: Table, links: dict[str, Link], drive: Drive
              ) -> tuple[dict[str, tuple[str, str, int]], dict[str, tuple[float, float]], float]:
    sides: dict[str, tuple[str, str, int]] = {}
    sketch: dict[str, tuple[float, float]] = {}
    a = top.table("assembly")
    phi = linear_assembly_default(top, drive) if drive.linear or drive.law else 0.0
    if a is None:
        return sides, sketch, phi
    names = {p for link in links.values() for p in link.points}
    for key, value in a.data.items():
        if key == "at":
            phi = a.quantity("at", "length" if drive.linear else "angle") or 0.0
            continue
        if key not in names:
            raise a.error(key, Text(
                "errmsg2.scene_loader.assembly_unknown_point",
                {"point": repr(key)}))
        if isinstance(value, list):
            if len(value) != 2:
                raise a.error(key, Text("errmsg2.scene_loader.sketch_coordinates"))
            sketch[key] = (a.value_quantity(value[0], key, "length"),
                           a.value_quantity(value[1], key, "length"))
        elif isinstance(value, str) and value.strip() in ("+", "-"):
            sides[key] = ("", "", 1 if value.strip() == "+" else -1)
        else:
            parsed = parse_side(value) if isinstance(value, str) else None
            if parsed is None:
                raise a.error(key, Text(
                    "errmsg2.scene_loader.assembly_value",
                    {"value": repr(value)}))
            for p in parsed[:2]:
                if p not in names:
                    raise a.error(key, Text(
                        "errmsg2.scene_loader.assembly_unknown_in",
                        {"point": repr(p), "value": repr(value)}))
            sides[key] = parsed
    return sides, sketch, phi


def _positions(top: Table, drive: Drive, points: set[str], links: dict[str, Link]) -> Positions:
    t = top.table("positions")
    drive_t = top.table("drive")
    if drive.linear or drive.law is not None:   # a crank by a table: within its angles
        return (linear_positions if drive.linear else crank_law_positions)(t, drive)
    if t is None:
        if drive_t is not None and drive_t.has("angle"):
            return Positions(angles=(drive_t.quantity("angle", "angle") or 0.0,))
        return Positions(count=12)
    t.check_keys(("at", "count", "start"))
    if t.has("at"):
        values = t.raw("at")
        if not isinstance(values, list) or not values:
            raise t.error("at", Text("errmsg2.scene_loader.angles_list"))
        return Positions(angles=tuple(t.value_quantity(v, f"at[{i}]", "angle")
                                      for i, v in enumerate(values)))
    count = t.raw("count", 12)
    if not isinstance(count, int) or isinstance(count, bool) or count < 1:
        raise t.error("count", Text(
            "errmsg2.scene_loader.count_whole",
            {"value": repr(count)}))
    start = t.raw("start", "0 deg")
    if isinstance(start, dict):
        st = t.table("start")
        assert st is not None
        st.check_keys(("extreme", "which"))
        subject = st.string("extreme", required=True)
        which = st.string("which", "max", choices=("max", "min"))
        if subject not in points and subject not in links:
            raise st.error("extreme", Text(
                "errmsg2.scene_loader.extreme_subject",
                {"subject": repr(subject)}))
        return Positions(count=count, start_extreme=Extreme(subject or "", which or "max"))
    return Positions(count=count, start_angle=t.value_quantity(start, "start", "angle"))


def _analysis(top: Table, points: set[str]) -> tuple[tuple[str, ...], tuple[str, ...]]:
    t = top.table("analysis")
    if t is None:
        return ("position", "velocity", "acceleration"), ()
    t.check_keys(("plans", "points"))
    plans = t.raw("plans", ["position", "velocity", "acceleration"])
    if isinstance(plans, list):
        plans = plan_names(plans)
    if not isinstance(plans, list) or any(p not in (*PLANS, CENTRES) for p in plans):
        raise t.error("plans", Text(
            "errmsg2.scene_loader.plans_list",
            {"choices": ', '.join((*PLANS, CENTRES)), "value": repr(plans)}))
    interest = t.raw("points", [])
    if not isinstance(interest, list):
        raise t.error("points", Text("errmsg2.scene_loader.points_list"))
    for p in interest:
        if p not in points:
            raise t.error("points", Text(
                "errmsg2.scene_loader.points_unknown",
                {"point": repr(p)}))
    return tuple(plans), tuple(interest)


def _drawing(top: Table, positions: int) -> DrawingSpec:
    t = top.table("drawing")
    tb = top.table("title_block")
    fields: dict[str, str] = {}
    if tb is not None:
        tb.check_keys(TITLE_BLOCK_FIELDS)
        for k, v in tb.data.items():
            if isinstance(v, (dict, list)) or "\n" in str(v):
                raise tb.error(k, Text("errmsg2.scene_loader.one_line", {"value": repr(v)}))
            fields[k] = str(v)
    if t is None:
        return DrawingSpec(title_block=fields)
    t.check_keys(("sheet", "standard", "scales", "plans_at"))
    scales: dict[str, float] = {}
    st = t.table("scales")
    if st is not None:
        st.check_keys(tuple(SCALE_KEYS))
        for k, dim in SCALE_KEYS.items():
            v = st.quantity(k, dim, positive=True)
            if v is not None:
                scales[k] = v
    plans_at = t.raw("plans_at", [])
    if not isinstance(plans_at, list) or not all(
            isinstance(n, int) and not isinstance(n, bool) and 0 <= n < positions
            for n in plans_at):
        raise t.error("plans_at", Text(
            "errmsg2.scene_loader.plans_at",
            {"last": str(positions - 1), "value": repr(plans_at)}))
    return DrawingSpec(sheet=t.string("sheet", "A1", choices=SHEETS) or "A1",
                       standard=t.string("standard", "iso", choices=STANDARDS) or "iso",
                       scales=scales, title_block=fields, plan_positions=tuple(plans_at))


