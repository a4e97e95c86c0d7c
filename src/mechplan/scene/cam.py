"""Parse a cam scene (``kind = "cam"``) into a :class:`~mechplan.model.cam.CamSpec`."""

from __future__ import annotations

import math
from pathlib import Path

from ..drafting.fields import SHEETS, STANDARDS, TITLE_BLOCK_FIELDS
from ..errors import SceneError
from ..i18n import LANGUAGES, Text
from ..model.cam import (
    CamDrawing,
    CamSpec,
    Contact,
    Follower,
    FollowerDynamics,
    Law,
    Limits,
    Motion,
    Phase,
    PhaseKind,
)
from .document import parse_toml
from .reader import Table

TOP_KEYS = ("kind", "title", "language", "description", "follower", "motion", "limits", "drawing",
            "title_block", "dynamics")
LAWS = tuple(law.value for law in Law if law not in (Law.TABLE_S, Law.TABLE_A)) + ("table",)
KINDS = tuple(k.value for k in PhaseKind)
FULL_TURN_TOL = math.radians(1e-6)


def parse_cam(text: str, file: str = "<scene>") -> CamSpec:
    """Parse the text of a cam scene; every error names the file and the key."""
    top = Table(parse_toml(text, file), "", file)
    top.check_keys(TOP_KEYS)
    follower = _follower(top)
    stroke, omega, sense, phases = _motion(top, follower)
    limits = _limits(top, follower)
    dyn = _dynamics(top, follower, omega)
    return CamSpec(dynamics=dyn, title=top.string("title", Path(file).stem) or "",
                   language=top.string("language", "en", choices=LANGUAGES) or "en",
                   follower=follower, phases=phases, stroke=stroke, omega=omega, sense=sense,
                   limits=limits, drawing=_drawing(top), path=file)


def _required(top: Table, name: str) -> Table:
    t = top.table(name)
    if t is None:
        raise top.error(name, Text("errors.key.table_missing"))
    return t


def _follower(top: Table) -> Follower:
    f = _required(top, "follower")
    f.check_keys(("motion", "contact", "offset", "roller_radius", "arm", "pivot_distance",
                  "face_margin"))
    motion = Motion(f.string("motion", "translating", choices=tuple(m.value for m in Motion)))
    contact = Contact(f.string("contact", "roller", choices=tuple(c.value for c in Contact)))
    roller = 0.0
    if contact is Contact.ROLLER:
        roller = f.quantity("roller_radius", "length", required=True, positive=True) or 0.0
    elif f.has("roller_radius"):
        raise f.error(
            "roller_radius",
            Text("errmsg.scene_cam.only_roller_follower", {"value": repr(contact.value)}),
        )
    arm = pivot = 0.0
    offset: float | None = 0.0
    if motion is Motion.OSCILLATING:
        if contact is Contact.FLAT:           # the face passes through the pivot: no arm
            if f.has("arm"):
                raise f.error("arm", Text("errmsg.scene_cam.not_used_flat"))
        else:
            arm = f.quantity("arm", "length", required=True, positive=True) or 0.0
        pivot = f.quantity("pivot_distance", "length", required=True, positive=True) or 0.0
        if f.has("offset"):
            raise f.error("offset", Text("errmsg.scene_cam.only_translating_follower"))
    else:
        for k in ("arm", "pivot_distance"):
            if f.has(k):
                raise f.error(k, Text("errmsg.scene_cam.only_oscillating_follower"))
        raw = f.raw("offset", "0 mm")
        if raw == "best":
            offset = None
        else:
            offset = f.value_quantity(raw, "offset", "length")
        if contact is Contact.FLAT and offset is None:
            raise f.error("offset", Text("errmsg.scene_cam.length_flat_faced"))
    margin = f.quantity("face_margin", "length", 0.005, nonnegative=True) or 0.0
    return Follower(motion, contact, offset, roller, arm, pivot, margin)


def _motion(top: Table, follower: Follower) -> tuple[float, float, int, tuple[Phase, ...]]:
    m = _required(top, "motion")
    m.check_keys(("stroke", "swing", "speed", "sense", "phases"))
    if follower.motion is Motion.OSCILLATING:
        if m.has("stroke"):
            raise m.error("stroke", Text("errmsg.scene_cam.translating_follower_give"))
        stroke = m.quantity("swing", "angle", required=True) or 0.0
        if not 0 < stroke < math.pi / 2:
            raise m.error(
                "swing", Text("errmsg.scene_cam.between_value", {"value": repr(m.raw("swing"))})
            )
        unit = "angle"
    else:
        if m.has("swing"):
            raise m.error("swing", Text("errmsg.scene_cam.oscillating_follower_give"))
        stroke = m.quantity("stroke", "length", required=True) or 0.0
        if not stroke > 0:
            raise m.error(
                "stroke", Text("errmsg.scene_cam.positive_value2", {"value": repr(m.raw("stroke"))})
            )
        unit = "length"
    omega = m.quantity("speed", "angular_velocity", required=True) or 0.0
    if not omega > 0:
        raise m.error(
            "speed", Text("errmsg.scene_cam.positive_give_sense", {"value": repr(m.raw("speed"))})
        )
    sense = 1 if m.string("sense", "ccw", choices=("ccw", "cw")) == "ccw" else -1
    raw = m.raw("phases", required=True)
    if not isinstance(raw, list) or not raw:
        raise m.error("phases", Text("errmsg.scene_cam.expected_list_phase"))
    phases = tuple(_phase(Table(p, f"{m.key('phases')}[{i}]", m.file), stroke, unit)
                   for i, p in enumerate(raw))
    total = sum(p.angle for p in phases)
    if abs(total - 2 * math.pi) > FULL_TURN_TOL:
        raise m.error(
            "phases",
            Text("errmsg.scene_cam.angles_sum_total", {"total": f"{math.degrees(total):.6g}"}),
        )
    level = 0
    needs = {PhaseKind.RISE: 0, PhaseKind.FAR_DWELL: 1, PhaseKind.RETURN: 1,
             PhaseKind.NEAR_DWELL: 0}
    for p in phases:
        if needs[p.kind] != level:
            where = Text("errmsg.scene_cam.far_position") if needs[p.kind] else \
                Text("errmsg.scene_cam.near_position")
            raise SceneError(Text("errmsg.scene_cam.value_start_from", {"value": str(p.kind.value),
                                                                        "where": where}),
                             file=m.file, key=p.key + ".kind")
        level = {PhaseKind.RISE: 1, PhaseKind.RETURN: 0}.get(p.kind, level)
    if level != 0:
        raise m.error("phases", Text("errmsg.scene_cam.end_near_position"))
    return stroke, omega, sense, phases


def _phase(t: Table, stroke: float, unit: str) -> Phase:
    t.check_keys(("kind", "angle", "law", "blend", "s", "a"))
    kind = PhaseKind(t.string("kind", required=True, choices=KINDS))
    angle = t.quantity("angle", "angle", required=True) or 0.0
    if not angle > 0:
        raise t.error(
            "angle", Text("errmsg.scene_cam.positive_value", {"value": repr(t.raw("angle"))})
        )
    moving = kind in (PhaseKind.RISE, PhaseKind.RETURN)
    if not moving:
        for k in ("law", "blend", "s", "a"):
            if t.has(k):
                raise t.error(
                    k, Text("errmsg.scene_cam.not_used_value", {"value": str(kind.value)})
                )
        return Phase(kind, angle, key=t.path)
    name = t.string("law", required=True, choices=LAWS)
    blend = 0.1
    if name == "uniform":
        blend = t.quantity("blend", "dimensionless", 0.1) or 0.0
        if not 0 < blend < 0.5:
            raise t.error(
                "blend", Text("errmsg.scene_cam.between_value2", {"value": repr(t.raw("blend"))})
            )
    elif t.has("blend"):
        raise t.error("blend", Text("errmsg.scene_cam.only_uniform_law"))
    if name != "table":
        for k in ("s", "a"):
            if t.has(k):
                raise t.error(k, Text("errmsg.scene_cam.only_law_table"))
        return Phase(kind, angle, Law(name), blend, key=t.path)
    if t.has("s") == t.has("a"):
        raise t.error("law", Text("errmsg.scene_cam.table_law_needs"))
    if t.has("s"):
        values = _values(t, "s", unit, 4)
        start, end = (0.0, stroke) if kind is PhaseKind.RISE else (stroke, 0.0)
        if abs(values[0] - start) > 1e-9 * stroke or abs(values[-1] - end) > 1e-9 * stroke:
            raise t.error(
                "s",
                Text(
                    "errmsg.scene_cam.run_from_start",
                    {
                        "start": f"{start:g}",
                        "end": f"{end:g}",
                        "value": str(kind.value),
                        "values": f"{values[0]:g}",
                        "values2": f"{values[-1]:g}",
                    },
                ),
            )
        return Phase(kind, angle, Law.TABLE_S, table=tuple(values), key=t.path)
    values = _values(t, "a", "dimensionless", 3)
    return Phase(kind, angle, Law.TABLE_A, table=tuple(values), key=t.path + ".a")


def _values(t: Table, name: str, dimension: str, least: int) -> list[float]:
    raw = t.raw(name)
    if not isinstance(raw, list) or len(raw) < least:
        raise t.error(name, Text("errmsg.scene_cam.expected_list_least", {"least": str(least),
                                                                          "raw": repr(raw)}))
    return [t.value_quantity(v, f"{name}[{i}]", dimension) for i, v in enumerate(raw)]


def _limits(top: Table, follower: Follower) -> Limits:
    t = top.table("limits") or Table({}, "limits", top.file)
    t.check_keys(("pressure_angle_rise", "pressure_angle_return", "base_radius",
                  "min_curvature_radius"))
    default = math.radians(45.0 if follower.motion is Motion.OSCILLATING else 30.0)
    rise = t.quantity("pressure_angle_rise", "angle", default)
    ret = t.quantity("pressure_angle_return", "angle", math.radians(70.0))
    for k, v in (("pressure_angle_rise", rise), ("pressure_angle_return", ret)):
        if v is None or not 0 < v < math.pi / 2:
            raise t.error(k, Text("errmsg.scene_cam.between_k", {"k": repr(t.raw(k))}))
    base = t.quantity("base_radius", "length", positive=True)
    rho = t.quantity("min_curvature_radius", "length", 0.0, nonnegative=True) or 0.0
    return Limits(rise or 0.0, ret or 0.0, base, rho)


def _drawing(top: Table) -> CamDrawing:
    fields: dict[str, str] = {}
    tb = top.table("title_block")
    if tb is not None:
        tb.check_keys(TITLE_BLOCK_FIELDS)
        for k, v in tb.data.items():
            if isinstance(v, (dict, list)) or "\n" in str(v):
                raise tb.error(k, Text("errmsg.scene_cam.expected_one_line", {"v": repr(v)}))
            fields[k] = str(v)
    t = top.table("drawing")
    if t is None:
        return CamDrawing(title_block=fields)
    t.check_keys(("sheet", "standard", "ray_step", "table_step", "chord_error"))
    d = CamDrawing()
    steps = {}
    for k, default in (("ray_step", d.ray_step), ("table_step", d.table_step)):
        v = t.quantity(k, "angle", default) or default
        if not math.radians(0.5) <= v <= math.radians(90):
            raise t.error(k, Text("errmsg.scene_cam.between_k2", {"k": repr(t.raw(k))}))
        steps[k] = v
    chord = t.quantity("chord_error", "length", d.chord_error, positive=True) or d.chord_error
    if not 1e-8 <= chord <= 1e-3:
        raise t.error("chord_error",
                      Text("errmsg.scene_cam.between_m_mm", {"value": repr(t.raw('chord_error'))}))
    return CamDrawing(sheet=t.string("sheet", "A1", choices=SHEETS) or "A1",
                      standard=t.string("standard", "iso", choices=STANDARDS) or "iso",
                      ray_step=steps["ray_step"], table_step=steps["table_step"],
                      chord_error=chord, title_block=fields)


def _dynamics(top: Table, follower: Follower, omega: float) -> FollowerDynamics | None:
    """``[dynamics]``: the follower's mass (inertia), spring, damper, load and the top speed."""
    t = top.table("dynamics")
    if t is None:
        return None
    swinging = follower.motion is Motion.OSCILLATING
    inertia = "inertia" if swinging else "mass"
    other = "mass" if swinging else "inertia"
    t.check_keys((inertia, "stiffness", "preload", "damping", "load", "speed_max", "margin",
                  "follower_stiffness", "damping_ratio", other))
    if t.has(other):
        example = '"0.002 kg*m^2"' if swinging else '"0.5 kg"'
        raise t.error(
            other,
            Text(
                "errmsg.scene_cam.value_follower_give",
                {
                    "value": Text("errmsg.scene_cam.a_translating" if swinging
                                  else "errmsg.scene_cam.an_oscillating"),
                    "inertia": str(inertia),
                    "example": str(example),
                },
            ),
        )
    mass = t.quantity(inertia, "inertia" if swinging else "mass", required=True, positive=True)
    force = "moment" if swinging else "force"
    stiffness = t.quantity("stiffness", "moment" if swinging else "stiffness", nonnegative=True)
    preload = t.quantity("preload", force, nonnegative=True)
    damping = t.quantity("damping", "torsional_damping" if swinging else "damping", 0.0,
                         nonnegative=True)
    load = t.quantity("load", force, 0.0)
    speed_max = t.quantity("speed_max", "angular_velocity", positive=True)
    if speed_max is not None and speed_max < omega:
        raise t.error(
            "speed_max",
            Text(
                "errmsg.scene_cam.least_cam_speed",
                {"omega": f"{omega:.6g}", "value": repr(t.raw("speed_max"))},
            ),
        )
    margin = t.quantity("margin", force, 0.0, nonnegative=True)
    k_f = t.quantity("follower_stiffness", "moment" if swinging else "stiffness", positive=True)
    zeta = t.quantity("damping_ratio", "dimensionless", 0.0, nonnegative=True) or 0.0
    if not zeta < 1:
        raise t.error(
            "damping_ratio",
            Text("errmsg.scene_cam.below_value", {"value": repr(t.raw("damping_ratio"))}),
        )
    if t.has("damping_ratio") and k_f is None:
        raise t.error("damping_ratio", Text("errmsg.scene_cam.elastic_follower_give"))
    return FollowerDynamics(mass=mass or 0.0, stiffness=stiffness, preload=preload,
                            damping=damping or 0.0, load=load or 0.0, speed_max=speed_max,
                            margin=margin or 0.0, follower_stiffness=k_f, damping_ratio=zeta)
