"""Exact references (60 digits, mpmath) for the singular hard cases; independent of mechplan.

Positions in closed form; velocities and accelerations from the loop-closure equations solved as
linear systems in mpmath (the analytic method), or from the inscribed-angle theorem.
"""

from __future__ import annotations

from mpmath import mp, mpf

DPS = 60


def _f(x) -> float:
    return float(x)


def slider_crank(r: float, l: float, e: float, theta: float, omega: float) -> dict[str, float]:
    """Offset slider-crank: crank OA = r about O = (0, 0), rod AB = l, B on the guide y = e, far
    branch.

    Returns B's x, v, a (along the guide) and the rod's angle, ω, ε.
    """
    with mp.workdps(DPS):
        r, l, e, th, w = mpf(r), mpf(l), mpf(e), mpf(theta), mpf(omega)
        ax, ay = r * mp.cos(th), r * mp.sin(th)
        g = e - ay                                  # vertical rise of the rod from A to B
        s = mp.sqrt(l * l - g * g)
        bx = ax + s
        # velocities: A + ω2 × (B − A) = B, with v_B along x: unknowns v_B, ω2
        vax, vay = -w * ay, w * ax
        dx, dy = bx - ax, e - ay
        # vay + ω2·dx = 0 ; vax − ω2·dy = v_B
        w2 = -vay / dx
        vb = vax - w2 * dy
        # accelerations: a_A + ε2 × d − ω2² d = a_B (along x)
        aax, aay = -w * w * ax, -w * w * ay
        eps2 = -(aay - w2 * w2 * dy) / dx
        ab = aax - eps2 * dy - w2 * w2 * dx
        return {"B_x": _f(bx), "v_B": _f(vb), "a_B": _f(ab), "omega_2": _f(w2),
                "epsilon_2": _f(eps2)}


def four_bar(a: float, b: float, c: float, d: float, theta: float,
             omega: float) -> dict[str, float]:
    """Four-bar A = (0, 0), D = (d, 0), AB = a, BC = b, DC = c, C left of B→D."""
    with mp.workdps(DPS):
        a, b, c, d, th, w = (mpf(x) for x in (a, b, c, d, theta, omega))
        bx, by = a * mp.cos(th), a * mp.sin(th)
        ux, uy = d - bx, -by
        L = mp.sqrt(ux * ux + uy * uy)
        along = (b * b - c * c + L * L) / (2 * L)
        h2 = b * b - along * along
        h = mp.sqrt(h2) if h2 > 0 else mpf(0)
        ex, ey = ux / L, uy / L
        cx, cy = bx + along * ex - h * ey, by + along * ey + h * ex
        # velocities: v_B + ω2 × (C − B) = ω3 × (C − D)
        vbx, vby = -w * by, w * bx
        r2x, r2y = cx - bx, cy - by
        r3x, r3y = cx - d, cy
        # −ω2 r2y + ω3 r3y = −vbx ; ω2 r2x − ω3 r3x = −vby
        det = -r2y * (-r3x) - r3y * r2x
        w2 = ((-vbx) * (-r3x) - r3y * (-vby)) / det
        w3 = (-r2y * (-vby) - (-vbx) * r2x) / det
        # accelerations: a_B + ε2 × r2 − ω2² r2 = ε3 × r3 − ω3² r3
        abx, aby = -w * w * bx, -w * w * by
        kx = -abx + w2 * w2 * r2x - w3 * w3 * r3x
        ky = -aby + w2 * w2 * r2y - w3 * w3 * r3y
        e2 = (kx * (-r3x) - r3y * ky) / det
        e3 = (-r2y * ky - kx * r2x) / det
        vcx, vcy = -w3 * r3y, w3 * r3x
        acx, acy = -e3 * r3y - w3 * w3 * r3x, e3 * r3x - w3 * w3 * r3y
        return {"C_x": _f(cx), "C_y": _f(cy), "v_C_x": _f(vcx), "v_C_y": _f(vcy),
                "a_C_x": _f(acx), "a_C_y": _f(acy), "omega_2": _f(w2), "omega_3": _f(w3),
                "epsilon_2": _f(e2), "epsilon_3": _f(e3)}


def slotted_through_pivot(omega: float) -> dict[str, float]:
    """Coulisse pivoting on the crank circle: ω3 = ω1/2 and ε3 = 0 at every angle (inscribed
    angle)."""
    return {"omega_3": omega / 2.0, "epsilon_3": 0.0}
