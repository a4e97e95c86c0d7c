"""Compound planetary sets of automatic gearboxes — Simpson and Ravigneaux — by Willis in exact
fractions: each gear (shift) is an input member, the members held (braked, or two members locked
together) and an output; every member's speed and the ratio follow from the sets' Willis
equations solved exactly.

Simpson: two single-row sets with a common sun S; front ring R1, front carrier C1 joined to the rear
ring (member "C1R2"), rear carrier C2. Willis of each set with its carrier held:
z_S·(ω_S − ω_C) = −z_R·(ω_R − ω_C).
Ravigneaux: a small sun S1 meshing short pinions, which mesh long pinions; a large sun S2 and the
ring R meshing the long pinions, all on one carrier C. With C held: (ω_S1 − ω_C)/(ω_R − ω_C) =
+z_R/z_S1 (two external meshes and one internal), (ω_S2 − ω_C)/(ω_R − ω_C) = −z_R/z_S2.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

from ...errors import SceneError
from ...i18n import Text
from ...model.gears import CompoundSpec

MEMBERS = {"simpson": ("S", "R1", "C1R2", "C2"), "ravigneaux": ("S1", "S2", "R", "C")}


def willis_rows(spec: CompoundSpec) -> list[dict[str, Fraction]]:
    """The Willis equations as rows {member: coefficient} (Σ coefficient·ω = 0)."""
    z = spec.teeth
    if spec.kind == "simpson":
        zs, zr1, zr2 = z["sun"], z["ring1"], z["ring2"]
        return [{"S": Fraction(zs), "R1": Fraction(zr1), "C1R2": Fraction(-(zs + zr1))},
                {"S": Fraction(zs), "C1R2": Fraction(zr2), "C2": Fraction(-(zs + zr2))}]
    zs1, zs2, zr = z["sun_small"], z["sun_large"], z["ring"]
    # ω_S1 − ω_C = (z_R/z_S1)(ω_R − ω_C);  ω_S2 − ω_C = −(z_R/z_S2)(ω_R − ω_C)
    k1, k2 = Fraction(zr, zs1), Fraction(-zr, zs2)
    return [{"S1": Fraction(1), "R": -k1, "C": k1 - 1},
            {"S2": Fraction(1), "R": -k2, "C": k2 - 1}]


def _solve(rows: list[list[Fraction]], rhs: list[Fraction]) -> list[Fraction] | None:
    """Gauss–Jordan in fractions; None when singular."""
    n = len(rhs)
    a = [row[:] + [b] for row, b in zip(rows, rhs, strict=True)]
    for col in range(n):
        piv = next((r for r in range(col, n) if a[r][col] != 0), None)
        if piv is None:
            return None
        a[col], a[piv] = a[piv], a[col]
        for r in range(n):
            if r != col and a[r][col] != 0:
                f = a[r][col] / a[col][col]
                a[r] = [x - f * y for x, y in zip(a[r], a[col], strict=True)]
    return [a[i][n] / a[i][i] for i in range(n)]


@dataclass(frozen=True)
class Shift:
    """One gear of the set: what drives, what is held or locked, every member's speed (exact,
    per unit input speed) and the ratio u = ω_in/ω_out."""

    name: str
    input: str
    held: tuple[str, ...]
    locked: tuple[str, ...]
    output: str
    speeds: dict[str, Fraction]
    ratio: Fraction


def solve_shift(spec: CompoundSpec, name: str, inp: str, held: tuple[str, ...],
                locked: tuple[str, ...], out: str, key: str) -> Shift:
    """Every member's speed with ω_in = 1, the held members at rest and the locked ones together."""
    names = MEMBERS[spec.kind]
    rows: list[list[Fraction]] = []
    rhs: list[Fraction] = []
    for eq in willis_rows(spec):
        rows.append([eq.get(m, Fraction(0)) for m in names])
        rhs.append(Fraction(0))
    one = {m: Fraction(1 if m == inp else 0) for m in names}
    rows.append([one[m] for m in names])
    rhs.append(Fraction(1))
    for h in held:
        rows.append([Fraction(1 if m == h else 0) for m in names])
        rhs.append(Fraction(0))
    if locked:
        a, b = locked
        rows.append([Fraction((m == a) - (m == b)) for m in names])
        rhs.append(Fraction(0))
    if len(rows) != len(names):
        raise SceneError(Text("compound.error.count", {"name": name, "count": len(rows) - 2}),
                         key=key)
    solved = _solve(rows, rhs)
    if solved is None:
        raise SceneError(Text("compound.error.singular", {"name": name}), key=key)
    speeds = dict(zip(names, solved, strict=True))
    if speeds[out] == 0:
        raise SceneError(Text("compound.error.still", {"name": name, "output": out}), key=key)
    return Shift(name, inp, held, locked, out, speeds, 1 / speeds[out])


def solve_compound(spec: CompoundSpec) -> list[Shift]:
    """Every gear of the scene's set."""
    return [solve_shift(spec, g.name, g.input, g.held, g.locked, g.output,
                        f"compound.gears[{i}]") for i, g in enumerate(spec.gears)]
