"""Read a gear scene (``kind = "gears"``): ``[planetary]``, ``[ordinary]`` and ``[pair]`` tables."""

from __future__ import annotations

from typing import Any

from ..errors import SceneError
from ..i18n import LANGUAGES, Text
from ..model.gears import GearScene, OrdinarySpec, PairSpec, PlanetarySpec, Scheme, ShiftRule
from .document import parse_toml
from .reader import Table

SCHEMES = tuple(s.value for s in Scheme)
RULES = tuple(r.value for r in ShiftRule)


def _int(t: Table, name: str, default: int | None = None, lo: int | None = None) -> int | None:
    value = t.raw(name, default, required=default is None)
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int):
        raise t.error(name, f"must be a whole number (got {value!r})")
    if lo is not None and value < lo:
        raise t.error(name, f"must be at least {lo} (got {value})")
    return int(value)


def _ints(t: Table, name: str, count: tuple[int, ...], lo: int = 1) -> tuple[int, ...] | None:
    value = t.raw(name)
    if value is None:
        return None
    if (not isinstance(value, list) or len(value) not in count
            or any(isinstance(v, bool) or not isinstance(v, int) for v in value)):
        raise t.error(name, f"must be a list of {' or '.join(map(str, count))} whole numbers "
                      f"(got {value!r})")
    if any(v < lo for v in value):
        raise t.error(name, f"every number must be at least {lo} (got {value!r})")
    return tuple(int(v) for v in value)


def _module(t: Table, name: str = "module") -> float:
    m = t.quantity(name, "length", required=True) or 0.0
    if not m > 0:
        raise t.error(name, f"must be positive (got {t.data[name]!r}); a module such as \"2 mm\"")
    return m


def _planetary(t: Table) -> PlanetarySpec:
    t.check_keys(("scheme", "fixed", "input", "output", "ratio", "deviation", "planets", "module",
                  "modules", "teeth", "z_min", "ring_difference", "addendum", "given",
                  "input_speed", "centre_distance", "pressure_angle", "max_shift_sum",
                  "mesh_efficiency", "output_torque", "speeds"))
    name = t.string("scheme", required=True)
    if name not in SCHEMES:
        raise t.error("scheme", f"must be one of {', '.join(SCHEMES)} (got {name!r})")
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
            raise t.error(key, f"must be one of the scheme's links {', '.join(scheme.links)} "
                               f"(got {value!r})")
    if speeds is None and len({fixed, inp, out}) != 3:
        raise t.error("fixed", f"fixed, input and output must be three different links "
                               f"(got {fixed!r}, {inp!r}, {out!r})")
    ratio = t.quantity("ratio", "dimensionless", required=True)
    if ratio is None or fixed is None or inp is None or out is None:   # required: never None here
        raise t.error("ratio", "is missing")
    if ratio == 0:
        raise t.error("ratio", "must not be zero (got 0)")
    deviation = t.quantity("deviation", "dimensionless", 0.02, nonnegative=True)
    planets = _int(t, "planets", 3, lo=1)
    if t.has("module") and t.has("modules"):
        raise t.error("modules", "give either module or modules, not both")
    if t.has("modules"):
        raw = t.raw("modules")
        if not isinstance(raw, list) or len(raw) != 2:
            raise t.error("modules", f"must be two modules [m12, m34] (got {raw!r})")
        mods = tuple(t.value_quantity(v, f"modules[{j}]", "length") for j, v in enumerate(raw))
        if not all(m > 0 for m in mods):
            raise t.error("modules", f"must be positive (got {raw!r})")
        modules = (mods[0], mods[1])
    else:
        m = _module(t)
        modules = (m, m)
    teeth = _ints(t, "teeth", (2,), lo=1) or (17, 120)
    if teeth[0] > teeth[1]:
        raise t.error("teeth", f"must be [smallest, largest] (got {list(teeth)})")
    given = _ints(t, "given", (len(scheme.gear_names),), lo=1)
    speed = t.quantity("input_speed", "angular_velocity", 1.0)
    assert planets is not None and deviation is not None and speed is not None
    if not speed != 0:
        raise t.error("input_speed", "must not be zero")
    extra = _shifted_and_loaded(t)
    if speeds is not None:
        if given is None:
            raise t.error("given", "is missing: a differential (speeds) needs its tooth numbers")
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
        raise t.error("speeds", f"must give two of the links {', '.join(scheme.links)} with their "
                                f"angular velocities, e.g. {{\"1\" = \"1 rad/s\", \"4\" = "
                                f"\"-0.5 rad/s\"}} (got {raw!r})")
    for key in ("fixed", "input", "output", "ratio"):
        if t.has(key):
            raise t.error(key, "is not used by a differential (speeds): remove it")
    out = []
    for link, value in raw.items():
        if link not in scheme.links:
            raise t.error(f"speeds.{link}", f"must be one of the scheme's links "
                                            f"{', '.join(scheme.links)}")
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
        raise t.error("pressure_angle", f"must be below 45 deg (got {t.data['pressure_angle']!r})")
    out["alpha"] = alpha
    out["max_shift_sum"] = t.quantity("max_shift_sum", "dimensionless", 2.0, nonnegative=True)
    if t.has("mesh_efficiency"):
        raw = t.raw("mesh_efficiency")
        values = raw if isinstance(raw, list) else [raw, raw]
        if (len(values) != 2 or any(isinstance(v, bool) or not isinstance(v, (int, float))
                                    or not 0 < v <= 1 for v in values)):
            raise t.error("mesh_efficiency", f"must be a number in (0, 1] or two of them [η12, "
                                             f"η34] (got {raw!r})")
        out["mesh_efficiency"] = (float(values[0]), float(values[1]))
    if t.has("output_torque"):
        out["output_torque"] = t.quantity("output_torque", "moment", nonnegative=True)
    return out


def _ordinary(t: Table) -> OrdinarySpec:
    t.check_keys(("module", "teeth", "ratio"))
    teeth = _ints(t, "teeth", (2,))
    ratio = t.quantity("ratio", "dimensionless", positive=True)
    if (teeth is None) == (ratio is None):
        raise t.error("teeth", "give either teeth = [z5, z6] or ratio (the |u| wanted)")
    return OrdinarySpec(module=_module(t), teeth=(teeth[0], teeth[1]) if teeth else None,
                        ratio=ratio)


def _pair(t: Table, ordinary: OrdinarySpec | None, z_from_ordinary: tuple[int, int] | None
          ) -> PairSpec:
    t.check_keys(("module", "teeth", "pressure_angle", "addendum", "clearance", "shifts",
                  "shift_rule", "z_min", "contour", "tip_land", "min_contact_ratio"))
    teeth = _ints(t, "teeth", (2,)) or z_from_ordinary
    if teeth is None and ordinary is None:
        raise t.error("teeth", "is missing (z1, z2 of the pair)")
    teeth = teeth or (0, 0)            # 0, 0: the ordinary stage's gears once they are chosen
    if t.has("module"):
        module = _module(t)
    elif ordinary is not None:
        module = ordinary.module
    else:
        raise t.error("module", "is missing (a length such as \"4 mm\")")
    alpha = t.quantity("pressure_angle", "angle", 0.3490658503988659, positive=True)
    assert alpha is not None
    if not alpha < 0.7854:
        raise t.error("pressure_angle", f"must be below 45 deg (got {t.data['pressure_angle']!r})")
    rule = ShiftRule(t.string("shift_rule", "given", choices=RULES))
    shifts_raw = t.raw("shifts", [0.0, 0.0])
    if (not isinstance(shifts_raw, list) or len(shifts_raw) != 2
            or any(isinstance(v, bool) or not isinstance(v, (int, float)) for v in shifts_raw)):
        raise t.error("shifts", f"must be two numbers [x1, x2] (got {shifts_raw!r})")
    if t.has("shifts") and rule is not ShiftRule.GIVEN:
        raise t.error("shifts", f"are chosen by shift_rule = {rule.value!r}; remove one of them")
    return PairSpec(module=module, z1=teeth[0], z2=teeth[1], alpha=alpha,
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
    top.check_keys(("kind", "title", "language", "planetary", "ordinary", "pair"))
    language = top.string("language", "en", choices=LANGUAGES) or "en"
    p = top.table("planetary")
    o = top.table("ordinary")
    q = top.table("pair")
    if p is None and q is None:
        raise SceneError("a gear scene needs a [planetary] or a [pair] table", file=file)
    planetary = _planetary(p) if p else None
    ordinary = _ordinary(o) if o else None
    pair = None
    if q is not None:
        pair = _pair(q, ordinary, ordinary.teeth if ordinary else None)
    return GearScene(title=top.string("title", "") or "", language=language, planetary=planetary,
                     ordinary=ordinary, pair=pair, file=file)
