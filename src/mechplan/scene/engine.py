"""Parse an engine scene (``kind = "engine"``) into an :class:`EngineScene`.

For a master/articulated V pair the linkage (crank, master rod with its lug, articulated rod,
two pistons) is written as a mechanism scene and parsed here, so the exact mechanism solver
computes the articulated cylinder.
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..errors import SceneError
from ..i18n import LANGUAGES, Text
from ..model.engine import (
    ArticulatedRod,
    ArticulatedSpec,
    CylinderSpec,
    EngineSpec,
    IndicatorKind,
    IndicatorSpec,
    Layout,
    MassSpec,
    RodMasses,
    ThermalSpec,
)
from ..model.engine_balance import BalanceSpec
from ..model.engine_thermal import Cycle
from ..units import registry
from .document import parse_toml
from .engine_balance import parse_balance
from .engine_layout import articulated_layout, group_linkage, radial_firing_order, rod_side
from .engine_thermal import parse_thermal
from .reader import Table
from .spec import DrawingSpec, Scene

TOP_KEYS = ("kind", "title", "language", "engine", "masses", "indicator", "articulated", "drawing",
            "title_block", "output", "balance", "thermal", "rod_side")


@dataclass(frozen=True)
class EngineScene:
    """An engine scene: the engine, its sheets and (master/articulated V) the linkage."""

    engine: EngineSpec
    drawing: DrawingSpec
    path: str
    linkage: Scene | None = None
    balance: BalanceSpec | None = None
    cycle: Cycle | None = None


def parse_engine_scene(text: str, file: str = "<scene>", *,
                       data_dir: str | Path | None = None) -> EngineScene:
    """Parse the text of an engine scene; a data file it names (``[indicator] file``) is read
    inside the scene's folder, or inside ``data_dir`` when given."""
    from .loader import _drawing

    top = Table(parse_toml(text, file), "", file)
    top.check_keys(TOP_KEYS)
    language = top.string("language", "en", choices=LANGUAGES) or "en"
    title = top.string("title", "") or ""
    e = top.table("engine", required=True)
    assert e is not None
    e.check_keys(("strokes", "speed", "bore", "crank_radius", "rod_length", "lambda", "p0",
                  "layout", "cylinders", "firing_order", "throws", "banks", "grid", "table_step"))
    strokes = e.raw("strokes", 4)
    if strokes not in (2, 4):
        raise e.error("strokes", Text("errmsg3.engine.strokes", {"value": repr(strokes)}))
    omega = e.quantity("speed", "angular_velocity", required=True, positive=True)
    bore = e.quantity("bore", "length", required=True, positive=True)
    R = e.quantity("crank_radius", "length", required=True, positive=True)
    assert omega is not None and bore is not None and R is not None
    L = _rod_length(e, R)
    p0 = e.quantity("p0", "pressure", 101325.0, nonnegative=True)
    assert p0 is not None
    layout = Layout(e.string("layout", "inline", choices=tuple(x.value for x in Layout)))
    masses = _masses(top.table("masses", required=True), L)  # type: ignore[arg-type]
    articulated = None
    rods: tuple[ArticulatedRod, ...] = ()
    if layout in (Layout.ARTICULATED, Layout.RADIAL):
        a = top.table("articulated", required=True)
        assert a is not None
        if layout is Layout.ARTICULATED:
            articulated, _ = _articulated(a)
        n_cyl, throws, banks, rods = articulated_layout(e, a, layout, L)
        default_order = (radial_firing_order(n_cyl, int(strokes)) if layout is Layout.RADIAL
                         else None)
    else:
        if top.has("articulated"):
            raise top.error("articulated", Text("errmsg3.engine.articulated_only"))
        n_cyl = e.raw("cylinders", 1)
        if not isinstance(n_cyl, int) or isinstance(n_cyl, bool) or not 1 <= n_cyl <= 24:
            raise e.error("cylinders", Text("errmsg3.engine.cylinders", {"value": repr(n_cyl)}))
        throws, banks = [], []
        default_order = None
    order = _firing_order(e, n_cyl, default_order)
    cycle = 180.0 * strokes
    if not throws:
        throws = _angles(e, "throws", n_cyl)
        banks = _angles(e, "banks", n_cyl) if e.has("banks") else [0.0] * n_cyl
        if not e.has("throws"):
            if layout is Layout.V:
                raise e.error("throws", Text("errmsg3.engine.v_throws"))
            interval = cycle / n_cyl
            throws = [0.0] * n_cyl
            for k, number in enumerate(order):
                throws[number - 1] = math.radians((k * interval) % 360.0)
    articulated_numbers = {r.number for r in rods}
    cylinders = tuple(CylinderSpec(i + 1, throws[i], banks[i], i + 1 in articulated_numbers)
                      for i in range(n_cyl))
    _check_firing(e, cylinders, order, strokes)
    grid = e.raw("grid", 720 if strokes == 4 else 360)
    if not isinstance(grid, int) or isinstance(grid, bool) or grid < 36:
        raise e.error("grid", Text("errmsg3.engine.grid", {"value": repr(grid)}))
    step = e.quantity("table_step", "angle", math.radians(15.0), positive=True)
    assert step is not None
    if abs(math.radians(cycle) / step - round(math.radians(cycle) / step)) > 1e-6:
        raise e.error("table_step", Text("errmsg3.engine.table_step", {
            "cycle": f"{cycle:g}", "step": f"{math.degrees(step):g}"}))
    cycle = None
    th = top.table("thermal")
    if th is not None:
        if top.has("indicator"):
            raise top.error("indicator", Text("cycle.error.exclusive"))
        cycle, ind = parse_thermal(th, strokes=int(strokes), cylinders=n_cyl, speed=omega,
                                   p0=p0, stroke_bore=2.0 * R / bore, lam=R / L)
    else:
        ind = _indicator(top.table("indicator", required=True),  # type: ignore[arg-type]
                         strokes, file, data_dir)
    rs = top.table("rod_side")
    double = rod_side(rs, bore, int(strokes), file, data_dir) if rs is not None else None
    out = top.table("output")
    csv_path = None
    if out is not None:
        out.check_keys(("csv",))
        name = out.string("csv")
        if name:
            csv_path = str(Path(file).parent / name) if not Path(name).is_absolute() else name
    spec = EngineSpec(title=title, strokes=int(strokes), speed=omega, bore=bore, R=R, L=L, p0=p0,
                      layout=layout, cylinders=cylinders, firing_order=order, masses=masses,
                      indicator=ind, articulated=articulated, rods=rods, rod_side=double,
                      grid=grid, table_step=step, language=language, csv=csv_path)
    linkage = group_linkage(spec, file) if rods else None
    bal = top.table("balance")
    n_pins = (1 if layout is Layout.RADIAL else
              (n_cyl + 1) // 2 if layout in (Layout.V, Layout.ARTICULATED) else n_cyl)
    balance = parse_balance(bal, n_pins) if bal is not None else None
    if balance is not None and balance.rod_offset and layout is not Layout.V:
        assert bal is not None
        raise bal.error("rod_offset", Text("layouts.error.rod_offset_layout"))
    return EngineScene(spec, _drawing(top, 1), file, linkage, balance, cycle)


def _rod_length(e: Table, R: float) -> float:
    if e.has("rod_length") and e.has("lambda"):
        raise e.error("lambda", Text("errmsg3.engine.rod_or_lambda"))
    if e.has("lambda"):
        lam = e.quantity("lambda", "dimensionless", required=True)
        assert lam is not None
        if not 0.0 < lam < 1.0:
            raise e.error("lambda", Text("errmsg3.engine.lambda_range", {"lam": f"{lam:g}"}))
        return R / lam
    L = e.quantity("rod_length", "length", required=True, positive=True)
    assert L is not None
    if not R / L < 1.0:
        raise e.error("rod_length", Text("errmsg3.engine.rod_short", {"lam": f"{R / L:g}"}))
    return L


def _rod(t: Table, L: float, prefix: str = "rod") -> RodMasses:
    m = t.quantity(prefix, "mass", required=True, nonnegative=True)
    assert m is not None
    small = f"{prefix}_small_end"
    centre = f"{prefix}_centre"
    J = t.quantity(f"{prefix}_J", "inertia", nonnegative=True)
    if t.has(small) and t.has(centre):
        raise t.error(centre, Text("errmsg3.engine.rod_both", {"small": small, "centre": centre}))
    if t.has(small):
        m1 = t.quantity(small, "mass", required=True, nonnegative=True)
        assert m1 is not None
        if m1 > m:
            raise t.error(small, Text("errmsg3.engine.small_end_exceeds",
                                          {"mass": f"{m:g}", "given": f"{m1:g}"}))
        return RodMasses(m1, m - m1, J)
    if t.has(centre):
        l2 = t.quantity(centre, "length", required=True, nonnegative=True)
        assert l2 is not None
        if l2 > L:
            raise t.error(centre, Text("errmsg3.engine.centre_outside",
                                           {"length": f"{L * 1e3:g}", "given": f"{l2 * 1e3:g}"}))
        return RodMasses(m * l2 / L, m * (L - l2) / L, J, L - l2, l2)
    raise t.error(small, Text("errmsg3.engine.rod_split_missing",
                                  {"small": small, "centre": centre}))


def _masses(t: Table, L: float) -> MassSpec:
    t.check_keys(("piston", "rod", "rod_small_end", "rod_centre", "rod_J", "rotating_extra",
                  "crank", "counterweight"))
    piston = t.quantity("piston", "mass", required=True, nonnegative=True)
    assert piston is not None
    return MassSpec(piston, _rod(t, L), t.quantity("rotating_extra", "mass", 0.0, nonnegative=True)
                    or 0.0, t.quantity("crank", "mass", 0.0, nonnegative=True) or 0.0,
                    t.quantity("counterweight", "mass", 0.0, nonnegative=True) or 0.0)


def _articulated(a: Table) -> tuple[ArticulatedSpec, float]:
    a.check_keys(("bank_angle", "lug_radius", "lug_angle", "rod_length", "piston", "rod",
                  "rod_small_end", "rod_centre", "rod_J"))
    bank = a.quantity("bank_angle", "angle", required=True)
    r = a.quantity("lug_radius", "length", required=True, positive=True)
    ang = a.quantity("lug_angle", "angle", required=True)
    L = a.quantity("rod_length", "length", required=True, positive=True)
    piston = a.quantity("piston", "mass", required=True, nonnegative=True)
    assert bank is not None and r is not None and ang is not None and L is not None
    assert piston is not None
    b = math.remainder(bank, 2 * math.pi)
    if abs(b) < math.radians(10.0) or abs(b) > math.radians(170.0):
        raise a.error("bank_angle", Text("errmsg3.engine.bank_angle",
                                         {"angle": f"{math.degrees(bank):g}"}))
    if not 0.0 < ang < math.pi:
        raise a.error("lug_angle", Text("errmsg3.engine.lug_angle",
                                        {"angle": f"{math.degrees(ang):g}"}))
    return ArticulatedSpec(r, ang, L, piston, _rod(a, L)), b % (2 * math.pi)


def _angles(e: Table, name: str, n: int) -> list[float]:
    raw = e.raw(name)
    if raw is None:
        return [0.0] * n
    if not isinstance(raw, list) or len(raw) != n:
        raise e.error(name, Text("errmsg3.engine.angles_per_cylinder",
                                 {"n": str(n), "value": repr(raw)}))
    return [e.value_quantity(v, f"{name}[{i}]", "angle") % (2 * math.pi) for i, v in enumerate(raw)]


def _firing_order(e: Table, n: int, default: list[int] | None = None) -> tuple[int, ...]:
    raw = e.raw("firing_order", default or (list(range(1, n + 1)) if n <= 2 else None))
    if raw is None:
        raise e.error("firing_order", Text("errmsg3.engine.firing_missing", {"n": str(n)}))
    if (not isinstance(raw, list)
            or not all(isinstance(v, int) and not isinstance(v, bool) for v in raw)
            or sorted(raw) != list(range(1, n + 1))):
        raise e.error("firing_order", Text("errmsg3.engine.firing_every",
                                                 {"n": str(n), "value": repr(raw)}))
    return tuple(raw)


def _check_firing(e: Table, cylinders: tuple[CylinderSpec, ...], order: tuple[int, ...],
                  strokes: int) -> None:
    from ..model.engine import firing_phases

    try:
        firing_phases(cylinders, order, strokes)
    except ValueError as exc:
        raise e.error("firing_order", str(exc)) from None


def _rows(t: Table, units: tuple[str, str], dims: tuple[str, str],
          file: str, data_dir: str | Path | None = None) -> list[tuple[float, float]]:
    ureg = registry()

    from_file = t.has("file")

    def conv(value: object, unit: str, target: str, where: str) -> float:
        q: Any
        try:
            if isinstance(value, str):
                q = ureg.Quantity(value.replace(",", "."))
                q = q * ureg(unit) if q.dimensionless and unit else q
            else:
                q = float(value) * ureg(unit)  # type: ignore[arg-type]
            return float(q.to(target).magnitude)
        except Exception:  # noqa: BLE001 - pint raises many kinds
            # a data file's content is never echoed: it may be any file the scene names
            if from_file:
                raise t.error(where, Text("errmsg3.engine.number_in", {"unit": unit})) from None
            raise t.error(where, Text("errmsg3.engine.number_in_got",
                                      {"unit": unit, "value": repr(value)})) from None

    targets = tuple("m**3" if d == "volume" else ("rad" if d == "angle" else "Pa") for d in dims)
    if from_file:
        raw = _data_rows(t, file, data_dir)
        if raw and not _numeric(raw[0][0]):
            raw = raw[1:]                                # a header row
        where = "file"
    else:
        raw = t.raw("table", required=True)
        where = "table"
        if not isinstance(raw, list):
            raise t.error("table", Text("errmsg3.engine.rows_expected"))
    rows = []
    for j, row in enumerate(raw):
        if not isinstance(row, list) or len(row) < 2:
            raise t.error(f"{where}[{j}]", Text("errmsg3.engine.row_expected") if from_file
                          else Text("errmsg3.engine.row_expected_got", {"value": repr(row)}))
        rows.append((conv(row[0], units[0], targets[0], f"{where}[{j}]"),
                     conv(row[1], units[1], targets[1], f"{where}[{j}]")))
    if len(rows) < 5:
        raise t.error(where, Text("errmsg3.engine.few_rows", {"count": str(len(rows))}))
    bad = [r for r in rows if r[1] < 0.0]
    if bad:
        raise t.error(where, Text("errmsg3.engine.below_vacuum", {"pressure": f"{bad[0][1]:g}"}))
    return rows


def _data_rows(t: Table, file: str, data_dir: str | Path | None) -> list[list[str]]:
    """The rows of the CSV data file ``t.file``: inside the scene's folder (or ``data_dir``), a
    regular file under :data:`~mechplan.limits.DATA_MAX_BYTES`; errors name the key, never a
    line of the file."""
    from ..userfiles import DATA, data_file, read_text

    name = t.string("file")
    assert name is not None
    key = t.key("file")
    path = data_file(name, file, key=key, data_dir=data_dir, error=SceneError)
    text = read_text(path, DATA, error=SceneError, key=key, shown=file)   # the key names it
    try:
        return [r for r in csv.reader(io.StringIO(text, newline=""))
                if r and not r[0].lstrip().startswith("#")]
    except csv.Error as exc:
        raise t.error("file", Text("errmsg3.engine.csv_unreadable", {"reason": str(exc)})) from None


def _numeric(s: str) -> bool:
    try:
        float(s.replace(",", "."))
        return True
    except ValueError:
        return False


def _indicator(t: Table, strokes: int, file: str,
               data_dir: str | Path | None = None) -> IndicatorSpec:
    source = t.string("source", "thermal", choices=tuple(k.value for k in IndicatorKind))
    kind = IndicatorKind(source)
    if kind is not IndicatorKind.THERMAL:
        t.check_keys(("source", "units", "table", "file", "epsilon"))
        units = t.raw("units", ["cm^3" if kind is IndicatorKind.VOLUME else "deg", "MPa"])
        if (not isinstance(units, list) or len(units) != 2
                or not all(isinstance(u, str) for u in units)):
            raise t.error("units", Text("errmsg3.engine.units_two"))
        dims = ("volume" if kind is IndicatorKind.VOLUME else "angle", "pressure")
        rows = _rows(t, (units[0], units[1]), dims, file, data_dir)
        eps = t.quantity("epsilon", "dimensionless")
        if eps is not None and not eps > 1.0:
            raise t.error("epsilon", Text("errmsg3.engine.epsilon_range", {"eps": f"{eps:g}"}))
        return IndicatorSpec(kind, rows=tuple(rows), epsilon=eps)
    t.check_keys(("source", "epsilon", "p_a", "p_r", "n1", "n2", "p_z", "rho", "ignition_advance",
                  "peak_angle", "peak_fraction", "tdc_fraction", "exhaust_opening", "rounding"))
    eps = t.quantity("epsilon", "dimensionless", required=True)
    assert eps is not None
    if not eps > 1.0:
        raise t.error("epsilon", Text("errmsg3.engine.epsilon_range", {"eps": f"{eps:g}"}))
    vals = {}
    for name in ("p_a", "p_r", "p_z"):
        v = t.quantity(name, "pressure", required=True)
        assert v is not None
        if not v > 0.0:
            raise t.error(name, Text("errmsg3.engine.pressure_vacuum",
                                     {"value": repr(t.raw(name))}))
        vals[name] = v
    n1 = t.quantity("n1", "dimensionless", required=True, positive=True)
    n2 = t.quantity("n2", "dimensionless", required=True, positive=True)
    rho = t.quantity("rho", "dimensionless", 1.0)
    assert n1 is not None and n2 is not None and rho is not None
    if not 1.0 <= rho < eps:
        raise t.error("rho", Text("errmsg3.engine.rho_range", {"rho": f"{rho:g}"}))
    p_c = vals["p_a"] * eps ** n1
    if vals["p_z"] < p_c:
        raise t.error("p_z", Text("errmsg3.engine.p_z_low", {
            "p_c": f"{p_c / 1e6:.3f}", "p_z": f"{vals['p_z'] / 1e6:g}"}))
    rounding = t.raw("rounding", True)
    if not isinstance(rounding, bool):
        raise t.error("rounding", Text("errmsg3.engine.rounding_bool", {"value": repr(rounding)}))

    def angle(name: str, default: float, hi: float) -> float:
        v = t.quantity(name, "angle", math.radians(default))
        assert v is not None
        if not 0.0 < v < math.radians(hi):
            raise t.error(name, Text("errmsg3.engine.angle_range", {
                "hi": f"{hi:g}", "angle": f"{math.degrees(v):g}"}))
        return v

    frac = t.quantity("peak_fraction", "dimensionless", 0.85, positive=True)
    tdc = t.quantity("tdc_fraction", "dimensionless", 1.2, positive=True)
    assert frac is not None and tdc is not None
    if frac > 1.0:
        raise t.error("peak_fraction", Text("errmsg3.engine.peak_fraction", {"value": f"{frac:g}"}))
    peak = angle("peak_angle", 12.0, 40.0)
    thermal = ThermalSpec(eps, vals["p_a"], vals["p_r"], n1, n2, vals["p_z"], rho,
                          angle("ignition_advance", 15.0, 60.0), peak, frac, tdc,
                          angle("exhaust_opening", 50.0, 90.0), rounding)
    if rounding and tdc * p_c > frac * vals["p_z"]:
        raise t.error("tdc_fraction", Text("errmsg3.engine.tdc_fraction", {
            "tdc": f"{tdc * p_c / 1e6:.3f}", "peak": f"{frac * vals['p_z'] / 1e6:.3f}"}))
    return IndicatorSpec(IndicatorKind.THERMAL, thermal=thermal, epsilon=eps)
