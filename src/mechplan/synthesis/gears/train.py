"""Planetary trains: Willis ratios, coaxiality and the assembly, neighbour, undercut and
internal-mesh conditions, all vectorised over arrays of tooth numbers.

Tooth sets are arrays ``z`` of shape (n, g) in the order of ``Scheme.gear_names`` (single row: z1,
z2, z3 = ring; two-row: z1, z2, z3, z4 with the planet block 2–3). Willis: with the carrier h held,
i_ab^h = (ω_a − ω_h)/(ω_b − ω_h) = ∏(∓ z_driven/z_driver), minus for an external mesh.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from ...errors import SceneError
from ...i18n import Text
from ...model.gears import PlanetarySpec, Scheme


def willis_sign(scheme: Scheme) -> int:
    """(−1)^(number of external meshes) of the train with the carrier held."""
    return -1 if sum(not m for m in scheme.internal) % 2 else 1


def willis_i(scheme: Scheme, z: np.ndarray) -> np.ndarray:
    """i_ab^h of each set (a = gear 1, b = the last central gear)."""
    z = np.asarray(z, dtype=float)
    s = willis_sign(scheme)
    if scheme is Scheme.SINGLE_ROW:
        return s * z[..., 2] / z[..., 0]
    return s * (z[..., 1] * z[..., 3]) / (z[..., 0] * z[..., 2])


def willis_exact(scheme: Scheme, z: tuple[int, ...]) -> Fraction:
    """i_ab^h of one set as an exact fraction."""
    s = willis_sign(scheme)
    if scheme is Scheme.SINGLE_ROW:
        return Fraction(s * z[2], z[0])
    return Fraction(s * z[1] * z[3], z[0] * z[2])


def ratio_exact(scheme: Scheme, z: tuple[int, ...], fixed: str, inp: str, out: str
                ) -> float:
    """u_in,out of one set by Willis in exact arithmetic (inf at a pole): no digits lost to
    1 − i when i is close to 1 (the ratio-10⁴ train)."""
    i = willis_exact(scheme, z)
    a, b, h = scheme.links
    if fixed == h:
        u = i if (inp, out) == (a, b) else (1 / i if i else None)
    else:
        i_xy = i if fixed == b else 1 / i
        u = 1 - i_xy if out == h else (1 / (1 - i_xy) if i_xy != 1 else None)
    return math.inf if u is None else float(u)


def ratio_from_i(i: np.ndarray | float, scheme: Scheme, fixed: str, inp: str,
                 out: str) -> np.ndarray:
    """u_in,out = ω_in/ω_out with ``fixed`` held, from Willis' i_ab^h."""
    i = np.asarray(i, dtype=float)
    a, b, h = scheme.links
    with np.errstate(divide="ignore", invalid="ignore"):
        if fixed == h:
            return i if (inp, out) == (a, b) else 1.0 / i
        i_xy = i if fixed == b else 1.0 / i          # x = the moving central gear, y = fixed
        return 1.0 - i_xy if out == h else 1.0 / (1.0 - i_xy)


def i_from_ratio(u: float, scheme: Scheme, fixed: str, inp: str, out: str) -> float:
    """The inverse of :func:`ratio_from_i` (nan at a pole)."""
    a, b, h = scheme.links
    with np.errstate(divide="ignore", invalid="ignore"):
        if fixed == h:
            return float(u if (inp, out) == (a, b) else 1.0 / u)
        i_xy = 1.0 - u if out == h else 1.0 - 1.0 / u
        return float(i_xy if fixed == b else 1.0 / i_xy)


def check_links(spec: PlanetarySpec) -> None:
    """Fixed, input and output must be the three different basic links of the scheme."""
    links = spec.scheme.links
    if spec.speeds is not None:
        return
    for key, name in (("fixed", spec.fixed), ("input", spec.input), ("output", spec.output)):
        if name not in links:
            raise SceneError(
                Text(
                    "errmsg.synthesis_gears_train.one_links_scheme",
                    {
                        "links": ", ".join(links),
                        "value": str(spec.scheme.value),
                        "name": repr(name),
                    },
                ),
                key=f"planetary.{key}",
            )
    if len({spec.fixed, spec.input, spec.output}) != 3:
        raise SceneError(
            Text(
                "errmsg.synthesis_gears_train.fixed_input_output",
                {
                    "links": str(links),
                    "fixed": repr(spec.fixed),
                    "input": repr(spec.input),
                    "output": repr(spec.output),
                },
            ),
            key="planetary.output",
        )


def module_ratio(spec: PlanetarySpec) -> float:
    """q = m(1–2)/m(second mesh)."""
    return spec.modules[0] / spec.modules[1]


def centre_distance(spec: PlanetarySpec, z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """a_w of the first mesh and of the second mesh (equal when the set is coaxial), m."""
    z = np.asarray(z, dtype=float)
    m1, m2 = spec.modules
    int1, int2 = spec.scheme.internal
    a12 = m1 * (z[..., 0] - z[..., 1] if int1 else z[..., 0] + z[..., 1]) / 2
    zp, zb = z[..., -2], z[..., -1]
    if spec.scheme is Scheme.SINGLE_ROW:
        zp = z[..., 1]
        m2 = m1
    a34 = m2 * (zb - zp if int2 else zb + zp) / 2
    return a12, a34


def mesh_teeth(spec: PlanetarySpec, z: tuple[int, ...]) -> tuple[tuple[int, int, bool, float],
                                                                 tuple[int, int, bool, float]]:
    """(z of the central gear, z of the planet gear, internal, module) of mesh 1 and mesh 2."""
    m1, m2 = spec.modules
    int1, int2 = spec.scheme.internal
    if spec.scheme is Scheme.SINGLE_ROW:
        return (z[0], z[1], int1, m1), (z[2], z[1], int2, m1)
    return (z[0], z[1], int1, m1), (z[3], z[2], int2, m2)


def shift_sum(z_central: int, z_planet: int, internal: bool, module: float, a_w: float,
              alpha: float) -> float:
    """x_Σ of a mesh working at ``a_w``: x1 + x2 (external) or x_ring − x_planet (internal), from
    cos α_w = a·cos α/a_w and inv α_w = inv α + 2x_Σ·tan α/(z2 ± z1); nan when a_w < a·cos α."""
    z_sum = z_central - z_planet if internal else z_central + z_planet
    a = module * z_sum / 2
    c = a * math.cos(alpha) / a_w if a_w > 0 else math.inf
    if not 0 < c <= 1:
        return math.nan
    alpha_w = math.acos(c)
    inv_a = math.tan(alpha) - alpha
    inv_w = math.tan(alpha_w) - alpha_w
    return z_sum * (inv_w - inv_a) / (2 * math.tan(alpha))


def working_distance(spec: PlanetarySpec, z: tuple[int, ...]) -> float | None:
    """The working centre distance of both meshes: the given one, the larger standard one
    (``centre_auto``), or the common standard one of a coaxial set; None when the set is not
    coaxial and nothing makes it so."""
    a12, a34 = (float(v[0]) for v in centre_distance(spec, np.asarray([z])))
    if spec.centre_distance is not None:
        return spec.centre_distance
    if spec.centre_auto:
        return max(a12, a34)
    return a12 if math.isclose(a12, a34, rel_tol=1e-9, abs_tol=1e-12) else None


def shift_sums(spec: PlanetarySpec, z: tuple[int, ...], a_w: float | None
               ) -> tuple[float, float]:
    """x_Σ of mesh 1 and mesh 2 at the working centre distance (nan without one)."""
    if a_w is None:
        return math.nan, math.nan
    first, second = (shift_sum(*mesh, a_w, spec.alpha) for mesh in mesh_teeth(spec, z))
    return first, second


def shifted(spec: PlanetarySpec) -> bool:
    """True when the train may work at a working centre distance with shifted gears."""
    return spec.centre_distance is not None or spec.centre_auto


def shift_ok(spec: PlanetarySpec, z: np.ndarray) -> np.ndarray:
    """Vectorised: both meshes work at the working centre distance with |x_Σ| ≤ max_shift_sum (or
    the set is coaxial unshifted)."""
    z = np.asarray(z, dtype=np.int64)
    a12, a34 = centre_distance(spec, z)
    if not shifted(spec):
        return np.isclose(a12, a34, rtol=1e-9, atol=1e-12)
    a_w = (np.full_like(a12, spec.centre_distance) if spec.centre_distance is not None
           else np.maximum(a12, a34))
    tan_a = math.tan(spec.alpha)
    inv_a = tan_a - spec.alpha
    ok = np.ones(a12.shape, dtype=bool)
    for a, zsum in ((a12, 2 * a12 / spec.modules[0]),
                    (a34, 2 * a34 / (spec.modules[0] if spec.scheme is Scheme.SINGLE_ROW
                                     else spec.modules[1]))):
        c = a * math.cos(spec.alpha) / a_w
        with np.errstate(invalid="ignore"):
            aw = np.arccos(np.clip(c, -1.0, 1.0))
            x = zsum * ((np.tan(aw) - aw) - inv_a) / (2 * tan_a)
        ok &= (c > 0) & (c <= 1 + 1e-12) & (np.abs(x) <= spec.max_shift_sum + 1e-9)
    return ok


def drawable_distance(spec: PlanetarySpec, z: tuple[int, ...]) -> float | None:
    """The working centre distance when the set is coaxial at it — unshifted, or with each mesh's
    |x_Σ| within ``max_shift_sum`` — else None (the set cannot be built, nor its plan drawn)."""
    working = working_distance(spec, z)
    if working is None:
        return None
    a12, a34 = (float(v[0]) for v in centre_distance(spec, np.asarray([z])))
    if all(math.isclose(working, a, rel_tol=1e-12) for a in (a12, a34)):
        return working                        # unshifted coaxial set
    ok = all(math.isfinite(x) and abs(x) <= spec.max_shift_sum + 1e-12
             for x in shift_sums(spec, z, working))
    return working if ok else None


def assembly_terms(spec: PlanetarySpec, z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """z1·u_1h^(b) = A/B as integers: the sun's turn, in teeth, while the carrier turns once."""
    z = np.asarray(z, dtype=np.int64)
    if spec.scheme is Scheme.SINGLE_ROW:
        return z[..., 0] + z[..., 2], np.ones_like(z[..., 0])
    s = willis_sign(spec.scheme)
    return z[..., 0] * z[..., 2] - s * z[..., 1] * z[..., 3], z[..., 2]


def assembles(spec: PlanetarySpec, z: np.ndarray, k: int | None = None) -> np.ndarray:
    """Assembly with k equally spaced planets: (z1·u_1h/k)(1 + k·p) is an integer for some p.

    With z1·u_1h = A/B and D = kB/gcd(A, kB), an integer p exists iff gcd(k, D) = 1.
    """
    k = spec.planets if k is None else k
    A, B = assembly_terms(spec, z)
    d = k * B
    D = d // np.gcd(np.abs(A), d)
    return np.gcd(k, D) == 1


def assembly_p(spec: PlanetarySpec, z: tuple[int, ...]) -> int | None:
    """The smallest p ≥ 0 that makes (z1·u_1h/k)(1 + k·p) an integer (None: none)."""
    A, B = (int(v) for v in assembly_terms(spec, np.asarray(z)))
    k = spec.planets
    D = k * B // math.gcd(abs(A), k * B)
    if math.gcd(k, D) != 1:
        return None
    return 0 if D == 1 else (-pow(k, -1, D)) % D


def planet_tip_diameter(spec: PlanetarySpec, z: np.ndarray) -> np.ndarray:
    """The larger tip diameter of the planet(s), m (standard teeth)."""
    z = np.asarray(z, dtype=float)
    m1, m2 = spec.modules
    d2 = m1 * (z[..., 1] + 2 * spec.addendum)
    if spec.scheme is Scheme.SINGLE_ROW:
        return d2
    return np.maximum(d2, m2 * (z[..., 2] + 2 * spec.addendum))


def neighbour_gap(spec: PlanetarySpec, z: np.ndarray, k: int | None = None) -> np.ndarray:
    """2·a_w·sin(π/k) − d_a,planet: positive when the tips of adjacent planets do not touch, m."""
    k = spec.planets if k is None else k
    a12, _ = centre_distance(spec, z)
    if spec.centre_distance is not None:
        a12 = np.full_like(a12, spec.centre_distance)
    elif spec.centre_auto:
        a12 = np.maximum(a12, centre_distance(spec, z)[1])
    if k == 1:
        return np.full_like(a12, np.inf)         # a single planet has no neighbour
    return 2 * a12 * math.sin(math.pi / k) - planet_tip_diameter(spec, z)


def ring_differences(spec: PlanetarySpec, z: np.ndarray) -> np.ndarray:
    """z_ring − z_planet of each internal mesh, shape (n, meshes) (inf where the mesh is
    external)."""
    z = np.asarray(z, dtype=np.int64)
    int1, int2 = spec.scheme.internal
    first = z[..., 0] - z[..., 1] if int1 else np.full(z.shape[:-1], np.iinfo(np.int64).max)
    second = z[..., -1] - (z[..., 1] if spec.scheme is Scheme.SINGLE_ROW else z[..., 2])
    if not int2:
        second = np.full(z.shape[:-1], np.iinfo(np.int64).max)
    return np.stack([first, second], axis=-1)


def envelope_diameter(spec: PlanetarySpec, z: np.ndarray) -> np.ndarray:
    """Overall size: the diameter enclosing every pitch circle of the train, m."""
    z = np.asarray(z, dtype=float)
    m1, m2 = spec.modules
    a12, _ = centre_distance(spec, z)
    planet = m1 * z[..., 1] if spec.scheme is Scheme.SINGLE_ROW else np.maximum(
        m1 * z[..., 1], m2 * z[..., 2])
    d_b = (m1 if spec.scheme is Scheme.SINGLE_ROW else m2) * z[..., -1]
    return np.maximum.reduce([m1 * z[..., 0], d_b, 2 * a12 + planet])


@dataclass(frozen=True)
class Conditions:
    """Every condition of a set, with its numbers (SI)."""

    z: tuple[int, ...]
    ratio: float
    ratio_error: float          # (u − u_target)/u_target
    ratio_ok: bool
    a_w: tuple[float, float]    # standard centre distances of mesh 1 and mesh 2, m
    coaxial: bool
    working: float | None       # working centre distance of both meshes (None: not coaxial), m
    shift_sums: tuple[float, float]   # x_Σ of each mesh at the working centre distance
    assembly_value: float       # z1·u_1h/k
    assembly_p: int | None
    z_smallest: int
    undercut_ok: bool
    ring_difference: int | None
    ring_ok: bool
    neighbour_span: float       # 2 a_w sin(π/k), m
    planet_tip: float           # d_a of the larger planet, m
    neighbour_ok: bool
    size: float

    @property
    def valid(self) -> bool:
        """True when every condition holds."""
        return (self.ratio_ok and self.coaxial and self.assembly_p is not None and self.undercut_ok
                and self.ring_ok and self.neighbour_ok)


def conditions(spec: PlanetarySpec, z: tuple[int, ...]) -> Conditions:
    """Evaluate every condition of one set, keeping the numbers for the report."""
    arr = np.asarray([z], dtype=np.int64)
    if spec.speeds is not None:         # a differential: no ratio is asked for
        u, err = math.nan, 0.0
    else:
        u = ratio_exact(spec.scheme, tuple(int(v) for v in z), spec.fixed, spec.input,
                        spec.output)
        err = (u - spec.ratio) / spec.ratio
    a12, a34 = (float(v[0]) for v in centre_distance(spec, arr))
    A, B = (int(v[0]) for v in assembly_terms(spec, arr))
    diffs = [int(d) for d in ring_differences(spec, arr)[0] if d < np.iinfo(np.int64).max]
    tip = float(planet_tip_diameter(spec, arr)[0])
    span = tip + float(neighbour_gap(spec, arr)[0])
    working = working_distance(spec, z)
    sums = shift_sums(spec, z, working)
    coaxial = drawable_distance(spec, z) is not None
    return Conditions(
        z=tuple(int(v) for v in z), ratio=u, ratio_error=err,
        ratio_ok=abs(err) <= spec.deviation + 1e-12, a_w=(a12, a34),
        coaxial=coaxial, working=working if coaxial else None, shift_sums=sums,
        assembly_value=A / B / spec.planets, assembly_p=assembly_p(spec, z),
        z_smallest=min(z), undercut_ok=min(z) >= spec.z_min,
        ring_difference=min(diffs) if diffs else None,
        ring_ok=all(d >= spec.ring_difference for d in diffs),
        neighbour_span=span, planet_tip=tip, neighbour_ok=span > tip,
        size=float(envelope_diameter(spec, arr)[0]))
