"""Lines of the gear report for shifted trains (working centre distance, shift sums) and for
the train's torques and efficiency."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ..i18n import message, number, significant, unit

if TYPE_CHECKING:
    from ..synthesis.gears.solve import PlanetaryResult


def shifted_lines(res: PlanetaryResult, lang: str) -> list[str]:
    """The working centre distance and x_Σ of each mesh, when the train works with shifts."""
    c = res.chosen
    if c.working is None or all(abs(x) < 1e-12 for x in c.shift_sums if math.isfinite(x)):
        return []
    return [message("gearcam.shifted", lang, aw=number(c.working * 1000, 3, lang),
                    x1=number(c.shift_sums[0], 4, lang), x2=number(c.shift_sums[1], 4, lang))]


def torque_lines(res: PlanetaryResult, lang: str) -> list[str]:
    """Torques on the basic links, efficiency, forces on one planet."""
    from ..synthesis.gears.forces import train_forces

    f = train_forces(res)
    if f is None:
        return []
    out = [message("gearcam.torques", lang, eta_h=number(f.relative_efficiency, 4, lang),
                   driver=f.driver_in_relative, eta=number(f.efficiency, 4, lang))]
    nm = unit("N·m", lang)
    out += [f"  M_{link} = {number(m, 3, lang)} {nm}" for link, m in f.torque.items()]
    out.append(message("gearcam.planet_forces", lang, A=number(f.planet_forces["A"], 2, lang),
                       B=number(f.planet_forces["B"], 2, lang),
                       O=number(f.planet_forces["O"], 2, lang)))
    return out


def differential_head(res: PlanetaryResult, lang: str) -> list[str]:
    """The scheme and the two given speeds of a differential."""
    s = res.spec
    assert s.speeds is not None
    (l1, w1), (l2, w2) = s.speeds
    return [message("gearcam.differential", lang,
                    scheme=message(f"gears.scheme.{s.scheme.value}", lang), a=l1,
                    wa=significant(w1, 6, lang), b=l2, wb=significant(w2, 6, lang), c=s.output,
                    k=s.planets)]


def superposition_lines(res: PlanetaryResult, lang: str) -> list[str]:
    """ω of the free link: each input alone (the other held) and their sum."""
    s, plan = res.spec, res.plan
    if plan is None or res.partials is None or s.speeds is None:
        return []
    (l1, _), (l2, _) = s.speeds
    p1, p2 = res.partials
    c = s.output
    return [message("gearcam.superposed", lang, c=c, a=l1, b=l2,
                    w1=significant(p1.omega[c], 6, lang),
                    w2=(f"({significant(p2.omega[c], 6, lang)})" if p2.omega[c] < 0
                        else significant(p2.omega[c], 6, lang)),
                    w=significant(plan.omega[c], 6, lang))]
