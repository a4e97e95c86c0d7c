"""Read a gear scene (``kind = "gears"``): ``[planetary]``, ``[ordinary]`` and ``[pair]`` tables."""

from __future__ import annotations

from typing import Any

from ..errors import SceneError
from ..i18n import LANGUAGES, Text, join
from ..model.gears import (
    CompoundGear,
    CompoundSpec,
    GearScene,
    OrdinarySpec,
    PairSpec,
    PlanetarySpec,
    Scheme,
    ShiftRule,
)
from .document import parse_toml
from .reader import Table

SCHEMES = tuple(s.value for s in Scheme)
RULES = tuple(r.value for r in ShiftRule)


def _int(t: Table, name: str, default: int | None = None, lo: int | None = None) -> int | None:
    value = t.raw(name, default, required=default is None)
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int):
        raise t.error(name, Text("errmsg.scene_gears.whole_number_value", {"value": repr(value)}))
    if lo is not None and value < lo:
        raise t.error(name, Text("errmsg.scene_gears.least_lo_value", {"lo": str(lo),
                                                                       "value": str(value)}))
    return int(value)


def _ints(t: Table, name: str, count: tuple[int, ...], lo: int = 1) -> tuple[int, ...] | None:
    value = t.raw(name)
    if value is None:
        return None
    if (not isinstance(value, list) or len(value) not in count
            or any(isinstance(v, bool) or not isinstance(v, int) for v in value)):
        raise t.error(
            name,
            Text(
                "errmsg.scene_gears.list_str_whole",
                {"str": join(count, " or "), "value": repr(value)},
            ),
        )
    if any(v < lo for v in value):
        raise t.error(name, Text("errmsg.scene_gears.every_number_least", {"lo": str(lo),
                                                                           "value": repr(value)}))
    return tuple(int(v) for v in value)


def _module(t: Table, name: str = "module") -> float:
    m = t.quantity(name, "length", required=True) or 0.0
    if not m > 0:
        raise t.error(
            name, Text("errmsg.scene_gears.positive_data_module", {"data": repr(t.data[name])})
        )
    return m


def _planetary(t: Table) -> PlanetarySpec:
    t.check_keys(("scheme", "fixed", "input", "output", "ratio", "deviation", "planets", "module",
                  "modules", "teeth", "z_min", "ring_difference", "addendum", "given",
                  "input_speed", "centre_distance", "pressure_angle", "max_shift_sum",
                  "mesh_efficiency", "output_torque", "speeds"))
    name = t.string("scheme", required=True)
    if name not in SCHEMES:
        raise t.error(
            "scheme",
            Text(
                "errmsg.scene_gears.one_schemes_name",
                {"schemes": ", ".join(SCHEMES), "name": repr(name)},
            ),
        )
    scheme = Scheme(name)
    a, b, h = scheme.links
    speeds = _speeds(t, scheme) if t.has("speeds") else None
    if speeds is not None:
        known = {link for link, _ in speeds}
        free = next(n for n in scheme.links if n not in known)
        t.data = {**t.data, "fixed": "", "input": speeds[0][0], "output": free, "ratio": 1.0}
    fixed, inp, out = (t.string(k, d) for k, d in (("fixed", b), ("input", a), ("output", h)))
    if speeds is not None:
        fixed, inp, out = "", speeds[0][0], free
    for key, value in (("fixed", fixed), ("input", inp), ("output", out)):
        if speeds is None and value not in scheme.links:
            raise t.error(
                key,
                Text(
                    "errmsg.scene_gears.one_scheme_s",
                    {"links": ", ".join(scheme.links), "value": repr(value)},
                ),
            )
    if speeds is None and len({fixed, inp, out}) != 3:
        raise t.error("fixed", Text("errmsg.scene_gears.fixed_input_output", {"fixed": repr(fixed),
                                                                              "inp": repr(inp),
                                                                              "out": repr(out)}))
    ratio = t.quantity("ratio", "dimensionless", required=True)
    if ratio is None or fixed is None or inp is None or out is None:   # required: never None here
        raise t.error("ratio", Text("errors.key.missing"))
    if ratio == 0:
        raise t.error("ratio", Text("errmsg.scene_gears.not_zero"))
    deviation = t.quantity("deviation", "dimensionless", 0.02, nonnegative=True)
    planets = _int(t, "planets", 3, lo=1)
    if t.has("module") and t.has("modules"):
        raise t.error("modules", Text("errmsg.scene_gears.give_either_module"))
    if t.has("modules"):
        raw = t.raw("modules")
        if not isinstance(raw, list) or len(raw) != 2:
            raise t.error("modules", Text("errmsg.scene_gears.two_modules_m", {"raw": repr(raw)}))
        mods = tuple(t.value_quantity(v, f"modules[{j}]", "length") for j, v in enumerate(raw))
        if not all(m > 0 for m in mods):
            raise t.error("modules", Text("errmsg.scene_gears.positive_raw", {"raw": repr(raw)}))
        modules = (mods[0], mods[1])
    else:
        m = _module(t)
        modules = (m, m)
    teeth = _ints(t, "teeth", (2,), lo=1) or (17, 120)
    if teeth[0] > teeth[1]:
        raise t.error(
            "teeth", Text("errmsg.scene_gears.smallest_largest_teeth", {"teeth": str(list(teeth))})
        )
    given = _ints(t, "given", (len(scheme.gear_names),), lo=1)
    speed = t.quantity("input_speed", "angular_velocity", 1.0)
    assert planets is not None and deviation is not None and speed is not None
    if not speed != 0:
        raise t.error("input_speed", Text("errmsg.scene_gears.not_zero2"))
    extra = _shifted_and_loaded(t)
    if speeds is not None:
        if given is None:
            raise t.error("given", Text("errmsg.scene_gears.missing_differential_speeds"))
        extra["speeds"] = speeds
    return PlanetarySpec(**extra, scheme=scheme, fixed=fixed, input=inp, output=out, ratio=ratio,
                         deviation=deviation, planets=planets, modules=modules,
                         z_range=(teeth[0], teeth[1]),
                         z_min=_int(t, "z_min", 17, lo=1) or 17,
                         ring_difference=_int(t, "ring_difference", 8, lo=1) or 8,
                         addendum=t.quantity("addendum", "dimensionless", 1.0,
                                             positive=True) or 1.0,
                         given=given, input_speed=speed)


def _speeds(t: Table, scheme: Scheme) -> tuple[tuple[str, float], tuple[str, float]]:
    """``speeds = {"1" = "1 rad/s", "4" = "-0.5 rad/s"}``: two basic links of a differential."""
    raw = t.raw("speeds")
    if not isinstance(raw, dict) or len(raw) != 2:
        raise t.error(
            "speeds",
            Text(
                "errmsg.scene_gears.give_two_links",
                {"links": ", ".join(scheme.links), "raw": repr(raw)},
            ),
        )
    for key in ("fixed", "input", "output", "ratio"):
        if t.has(key):
            raise t.error(key, Text("errmsg.scene_gears.not_used_differential"))
    out = []
    for link, value in raw.items():
        if link not in scheme.links:
            raise t.error(
                f"speeds.{link}",
                Text("errmsg.scene_gears.one_scheme_s2", {"links": ", ".join(scheme.links)}),
            )
        out.append((str(link), t.value_quantity(value, f"speeds.{link}", "angular_velocity")))
    return out[0], out[1]


def _shifted_and_loaded(t: Table) -> dict[str, Any]:
    """centre_distance (a length or "auto"), pressure_angle, max_shift_sum, mesh_efficiency,
    output_torque."""
    out: dict[str, Any] = {}
    if t.has("centre_distance"):
        raw = t.raw("centre_distance")
        if raw == "auto":
            out["centre_auto"] = True
        else:
            a_w = t.quantity("centre_distance", "length", positive=True)
            out["centre_distance"] = a_w
    alpha = t.quantity("pressure_angle", "angle", 0.3490658503988659, positive=True)
    if alpha is not None and not alpha < 0.7854:
        raise t.error(
            "pressure_angle",
            Text("errmsg.scene_gears.below_deg_data", {"data": repr(t.data["pressure_angle"])}),
        )
    out["alpha"] = alpha
    out["max_shift_sum"] = t.quantity("max_shift_sum", "dimensionless", 2.0, nonnegative=True)
    if t.has("mesh_efficiency"):
        raw = t.raw("mesh_efficiency")
        values = raw if isinstance(raw, list) else [raw, raw]
        if (len(values) != 2 or any(isinstance(v, bool) or not isinstance(v, (int, float))
                                    or not 0 < v <= 1 for v in values)):
            raise t.error(
                "mesh_efficiency", Text("errmsg.scene_gears.number_two_them", {"raw": repr(raw)})
            )
        out["mesh_efficiency"] = (float(values[0]), float(values[1]))
    if t.has("output_torque"):
        out["output_torque"] = t.quantity("output_torque", "moment", nonnegative=True)
    return out


def _ordinary(t: Table) -> OrdinarySpec:
    t.check_keys(("module", "teeth", "ratio"))
    teeth = _ints(t, "teeth", (2,))
    ratio = t.quantity("ratio", "dimensionless", positive=True)
    if (teeth is None) == (ratio is None):
        raise t.error("teeth", Text("errmsg.scene_gears.give_either_teeth"))
    return OrdinarySpec(module=_module(t), teeth=(teeth[0], teeth[1]) if teeth else None,
                        ratio=ratio)


def _pair(t: Table, ordinary: OrdinarySpec | None, z_from_ordinary: tuple[int, int] | None
          ) -> PairSpec:
    t.check_keys(("module", "teeth", "pressure_angle", "addendum", "clearance", "shifts",
                  "shift_rule", "z_min", "contour", "tip_land", "min_contact_ratio",
                  "internal"))
    teeth = _ints(t, "teeth", (2,)) or z_from_ordinary
    if teeth is None and ordinary is None:
        raise t.error("teeth", Text("errmsg.scene_gears.missing_z_z"))
    teeth = teeth or (0, 0)            # 0, 0: the ordinary stage's gears once they are chosen
    if t.has("module"):
        module = _module(t)
    elif ordinary is not None:
        module = ordinary.module
    else:
        raise t.error("module", Text("errmsg.scene_gears.missing_length_such"))
    alpha = t.quantity("pressure_angle", "angle", 0.3490658503988659, positive=True)
    assert alpha is not None
    if not alpha < 0.7854:
        raise t.error(
            "pressure_angle",
            Text("errmsg.scene_gears.below_deg_data2", {"data": repr(t.data["pressure_angle"])}),
        )
    rule = ShiftRule(t.string("shift_rule", "given", choices=RULES))
    shifts_raw = t.raw("shifts", [0.0, 0.0])
    if (not isinstance(shifts_raw, list) or len(shifts_raw) != 2
            or any(isinstance(v, bool) or not isinstance(v, (int, float)) for v in shifts_raw)):
        raise t.error(
            "shifts", Text("errmsg.scene_gears.two_numbers_x", {"shifts_raw": repr(shifts_raw)})
        )
    if t.has("shifts") and rule is not ShiftRule.GIVEN:
        raise t.error(
            "shifts", Text("errmsg.scene_gears.are_chosen_shift", {"value": repr(rule.value)})
        )
    internal = _flag(t, "internal")
    if internal and rule not in (ShiftRule.GIVEN, ShiftRule.CONTOUR):
        raise t.error("shift_rule", Text("machine.error.internal_rule",
                                         {"value": repr(rule.value)}))
    if internal and not teeth[1] > teeth[0] > 0:
        raise t.error("teeth", Text("machine.error.internal_teeth",
                                    {"z1": teeth[0], "z2": teeth[1]}))
    return PairSpec(internal=internal, module=module, z1=teeth[0], z2=teeth[1], alpha=alpha,
                    addendum=t.quantity("addendum", "dimensionless", 1.0, positive=True) or 1.0,
                    clearance=t.quantity("clearance", "dimensionless", 0.25,
                                         nonnegative=True) or 0.0,
                    shifts=(float(shifts_raw[0]), float(shifts_raw[1])), rule=rule,
                    z_min=_int(t, "z_min", 17, lo=1) or 17,
                    contour=rule is ShiftRule.CONTOUR or _flag(t, "contour"),
                    tip_land=_fraction(t, "tip_land", 0.25),
                    eps_min=_fraction(t, "min_contact_ratio", 1.2))


def _flag(t: Table, key: str) -> bool:
    v = t.raw(key, False)
    if not isinstance(v, bool):
        raise t.error(key, Text("contour.error.flag", {"value": repr(v)}))
    return v


def _fraction(t: Table, key: str, default: float) -> float:
    """A plain positive number (the contour's limits: s_a/m, ε_α)."""
    v = t.raw(key, default)
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not 0 < v < 10:
        raise t.error(key, Text("contour.error.fraction", {"value": repr(v)}))
    return float(v)


def parse_gears(text: str, file: str = "<scene>") -> GearScene:
    """Parse the text of a gear scene."""
    data: dict[str, Any] = parse_toml(text, file)
    top = Table(data, "", file)
    top.check_keys(("kind", "title", "language", "planetary", "ordinary", "pair", "compound"))
    language = top.string("language", "en", choices=LANGUAGES) or "en"
    p = top.table("planetary")
    o = top.table("ordinary")
    q = top.table("pair")
    cp = top.table("compound")
    if p is None and q is None and cp is None:
        raise SceneError(Text("errmsg.scene_gears.gear_scene_needs"), file=file)
    planetary = _planetary(p) if p else None
    ordinary = _ordinary(o) if o else None
    pair = None
    if q is not None:
        pair = _pair(q, ordinary, ordinary.teeth if ordinary else None)
    return GearScene(title=top.string("title", "") or "", language=language, planetary=planetary,
                     ordinary=ordinary, pair=pair, file=file,
                     compound=_compound(cp) if cp is not None else None)


COMPOUND_TEETH = {"simpson": ("sun", "ring1", "ring2"),
                  "ravigneaux": ("sun_small", "sun_large", "ring")}
COMPOUND_MEMBERS = {"simpson": ("S", "R1", "C1R2", "C2"), "ravigneaux": ("S1", "S2", "R", "C")}


def _compound(t: Table) -> CompoundSpec:
    """``[compound]``: a Simpson or Ravigneaux set, its teeth and its gears."""
    t.check_keys(("type", "teeth", "input_speed", "gears"))
    kind = t.string("type", required=True, choices=tuple(COMPOUND_TEETH)) or "simpson"
    tt = t.table("teeth", required=True)
    assert tt is not None
    tt.check_keys(COMPOUND_TEETH[kind])
    teeth = {k: _int(tt, k, lo=1) or 0 for k in COMPOUND_TEETH[kind]}
    for k in COMPOUND_TEETH[kind]:
        if not tt.has(k):
            raise tt.error(k, Text("compound.error.teeth", {"names": ", ".join(
                COMPOUND_TEETH[kind])}))
    ring = teeth["ring"] if kind == "ravigneaux" else min(teeth["ring1"], teeth["ring2"])
    suns = [teeth[k] for k in COMPOUND_TEETH[kind] if k.startswith("sun")]
    if not ring > max(suns):
        raise tt.error(COMPOUND_TEETH[kind][-1], Text("compound.error.ring", {"ring": ring}))
    speed = t.quantity("input_speed", "angular_velocity", 1.0) or 1.0
    raw = t.raw("gears", required=True)
    if not isinstance(raw, list) or not raw or not all(isinstance(g, dict) for g in raw):
        raise t.error("gears", Text("compound.error.gears"))
    members = COMPOUND_MEMBERS[kind]
    gears = []
    for i, g in enumerate(raw):
        gt = Table(g, f"{t.key('gears')}[{i}]", t.file)
        gt.check_keys(("name", "input", "output", "held", "locked"))
        lists = {}
        for k in ("held", "locked"):
            v = gt.raw(k, [])
            if isinstance(v, str):
                v = [v]
            if not isinstance(v, list) or any(m not in members for m in v) or \
                    (k == "locked" and len(v) not in (0, 2)):
                raise gt.error(k, Text("compound.error.members", {
                    "members": ", ".join(members), "value": repr(v)}))
            lists[k] = tuple(v)
        gears.append(CompoundGear(
            name=gt.string("name", str(i + 1)) or str(i + 1),
            input=gt.string("input", required=True, choices=members) or "",
            output=gt.string("output", required=True, choices=members) or "",
            held=lists["held"], locked=lists["locked"]))
    return CompoundSpec(kind, teeth, tuple(gears), speed)
