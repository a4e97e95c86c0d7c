"""The crank–coulisse quick-return mechanism and the six-link shaper from the time ratio K.

At the extreme positions the coulisse O3B touches the crank circle, so the coulisse swings by
ψ = θ = 180°·(K − 1)/(K + 1) and the crank is r = O1O3·sin(ψ/2). The tip B of a coulisse of
length L moves along a chord H = 2L·sin(ψ/2). In the shaper the ram line is drawn halfway
between the arc's top and the chord B1B2 (at L·(1 + cos(ψ/2))/2 from O3): the rod BC then
deviates from it by the same, smallest, largest angle at the ends and in the middle of the
stroke, sin α = L·(1 − cos(ψ/2))/(2·BC). The ram's extremes come with the coulisse's (the ram
moves with the coulisse angle only, monotonically over the swing), so the ram's stroke is H and
its time ratio K exactly.
"""

from __future__ import annotations

import math

from ...errors import SceneError
from ...i18n import Text
from ...model.synthesis import SynthesisSpec
from . import geometry as g
from .design import LinkageDesign, Step, Stroke, theta_of_k
from .scene_out import base, deg, link_name, mm

#: the rod BC of a shaper when the scene gives none, as a part of the coulisse O3B
DEFAULT_ROD_PART = 0.3


def _error(spec: SynthesisSpec, key: str, msgid: str, **values: str) -> SceneError:
    return SceneError(Text(f"synth.error.{msgid}", values), file=spec.path,
                      key=f"synthesis.{key}")


def _frame_and_crank(spec: SynthesisSpec, psi: float) -> tuple[float, float]:
    half = math.sin(psi / 2)
    if spec.frame is not None and spec.crank is not None:
        raise _error(spec, "crank", "frame_or_crank")
    if spec.frame is not None:
        return spec.frame, spec.frame * half
    if spec.crank is not None:
        return spec.crank / half, spec.crank
    raise _error(spec, "frame", "needs", problem=spec.problem)


def coulisse(spec: SynthesisSpec) -> LinkageDesign:
    """Synthesise the quick-return (``coulisse``) or the shaper (``shaper``) a scene asks for."""
    shaper = spec.problem == "shaper"
    if not spec.k > 1.0:
        raise _error(spec, "K", "k_above_one", value=repr(spec.k))
    psi = theta_of_k(spec.k)
    a, r = _frame_and_crank(spec, psi)
    half, cos_half = math.sin(psi / 2), math.cos(psi / 2)
    if spec.coulisse is not None and spec.stroke is not None:
        raise _error(spec, "stroke", "stroke_or_coulisse")
    if spec.coulisse is not None:
        big_l = spec.coulisse
    elif spec.stroke is not None:
        big_l = spec.stroke / (2 * half)
    else:
        raise _error(spec, "stroke", "needs", problem=spec.problem)
    if not big_l > a + r:
        raise _error(spec, "stroke" if spec.coulisse is None else "coulisse", "coulisse_short",
                     L=repr(round(big_l * 1e3, 3)), need=repr(round((a + r) * 1e3, 3)))
    h_tip = 2 * big_l * half
    O1: g.Vec = (0.0, 0.0)
    O3: g.Vec = (0.0, -a)
    A2 = g.polar(r, -psi / 2)                 # the right extreme: crank square to the coulisse
    A1 = g.polar(r, math.pi + psi / 2)
    B2 = g.add(O3, (big_l * half, big_l * cos_half))
    B1 = g.add(O3, (-big_l * half, big_l * cos_half))
    # crank angles as the analysis counts them: from +x in the sense of rotation
    phi2 = (-spec.sense * psi / 2) % (2 * math.pi)
    phi1 = (spec.sense * (math.pi + psi / 2)) % (2 * math.pi)
    sweep = (phi1 - phi2) % (2 * math.pi)
    ground: dict[str, object] = {"O1": ["0 mm", "0 mm"], "O3": ["0 mm", mm(-a)]}
    links: dict[str, object] = {
        "1": {"name": link_name("crank", spec), "lengths": {"O1A": mm(r)}},
        "2": {"name": link_name("block", spec), "slides": {"point": "A", "on": "slot"}},
        "3": {"name": link_name("coulisse", spec), "lengths": {"O3B": mm(big_l)},
              "guides": {"slot": {"through": "O3", "toward": "B"}}},
    }
    strokes = [Stroke("point", O1, role="given", label="O1"),
               Stroke("point", O3, role="given", label="O3"),
               Stroke("line", O3, B1, role="given", label="B1"),
               Stroke("line", O3, B2, role="given", label="B2"),
               Stroke("line", O3, (0.0, big_l - a)),
               Stroke("circle", O1, r=r, role="result"),
               Stroke("line", O1, A1, role="mechanism", label="A1"),
               Stroke("line", O1, A2, role="mechanism", label="A2"),
               Stroke("line", B1, B2, role="result")]
    protocol = [Step("synth.theta", {"k": spec.k, "theta": psi}),
                Step("synth.cq.swing", {"psi": psi, "a": a}),
                Step("synth.cq.crank", {"r": r}),
                Step("synth.cq.tip", {"L": big_l, "H": h_tip})]
    lengths = {"r": r, "a": a, "L": big_l}
    conditions: dict[str, object] = {"turns_fully": "1", "rocks": "3", "coulisse_swing": psi,
                                     "dead_centres_phi": [phi2, phi1],
                                     "working_stroke_phi": max(sweep, 2 * math.pi - sweep),
                                     "working_from": "B2" if sweep > math.pi else "B1"}
    output, kind, asked, start = "3", "angle", psi, {"extreme": "3", "which": "min"}
    assembly: dict[str, object] | None = None
    if shaper:
        rod = spec.rod if spec.rod is not None else DEFAULT_ROD_PART * big_l
        y_ram = big_l * (1 + cos_half) / 2
        dev = big_l * (1 - cos_half) / 2
        if not rod > dev:
            raise _error(spec, "rod", "rod_short", rod=repr(round(rod * 1e3, 3)),
                         need=repr(round(dev * 1e3, 3)))
        alpha = math.asin(dev / rod)
        if spec.gamma_limit is not None and not math.pi / 2 - alpha >= spec.gamma_limit:
            raise _error(spec, "gamma_min", "gamma_below",
                         got=repr(round(math.degrees(math.pi / 2 - alpha), 4)),
                         limit=repr(round(math.degrees(spec.gamma_limit), 4)))
        ram_y = -a + y_ram
        dx = math.sqrt(rod * rod - dev * dev)
        C2 = (B2[0] + dx, ram_y)
        C1 = (B1[0] + dx, ram_y)
        ground["R"] = ["0 mm", mm(ram_y)]
        ground["guides"] = {"ram": {"through": "R", "angle": "0 deg"}}
        links["4"] = {"name": link_name("rod", spec), "lengths": {"BC": mm(rod)}}
        links["5"] = {"name": link_name("ram", spec), "slides": {"point": "C", "on": "ram"}}
        assembly = {"at": deg(phi2), "C": [mm(C2[0]), mm(C2[1])]}
        start = {"extreme": "C", "which": "max"}
        output, kind, asked = "C", "length", h_tip
        strokes += [Stroke("line", (B1[0] - 0.2 * h_tip, ram_y), (C2[0] + 0.2 * h_tip, ram_y),
                           role="result", label="R"),
                    Stroke("line", B1, C1, role="mechanism", label="C1"),
                    Stroke("line", B2, C2, role="mechanism", label="C2")]
        protocol += [Step("synth.sh.ram", {"y": y_ram, "dev": dev}),
                     Step("synth.sh.rod", {"rod": rod, "alpha": alpha})]
        lengths.update({"rod": rod, "ram_height": y_ram})
        conditions.update({"pressure_max": alpha, "gamma_min": math.pi / 2 - alpha,
                           "ram_stroke": h_tip})
    choice = protocol[1]
    scene = base(spec, ground, links, start, assembly)
    return LinkageDesign(spec.problem, spec.k, psi, lengths, strokes, protocol, conditions, [],
                         choice, scene, output, kind, asked)
