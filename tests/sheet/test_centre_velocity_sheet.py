"""The velocities by instant centres on the sheet: each arrow measured back from the drawn
primitives (its foot at its point, at right angles to the radius, its length |v| / μv) and the
table of the construction against the velocity plan."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from scenes import ROOT

from mechplan.drafting.primitives import Arc, Circle, Line, Table, Text
from mechplan.scene import load_scene
from mechplan.sheet.centres import centres_panels
from mechplan.sheet.scales import room
from mechplan.solve import solve


def _number(s: str) -> float:
    return float(s.replace(",", ".").replace("−", "-"))


@pytest.mark.parametrize("name, lang", [("four_bar", "en"), ("slider_crank", "ru"),
                                        ("quick_return", "vi"), ("shaper", "zh")])
def test_arrows_measured_back_from_the_drawing(name, lang):
    sol = solve(load_scene(ROOT / "templates" / f"{name}.toml"))
    k = 1
    view, _diagram, _table, vtable = centres_panels(sol, k, sol.scales[next(iter(sol.scales))],
                                                    lang, room("A1", "iso"))
    c, ev, mech = sol.construction, sol.ev, sol.scene.mechanism
    # the view's scale from two pins drawn as circles (the frame's pivots)
    circles = [p.center for p in view.primitives if isinstance(p, Circle)]
    crank = mech.drive.link
    crank_pin = next(pr.point for pr in mech.pairs
                     if crank in (pr.a, pr.b) and "0" not in (pr.a, pr.b))
    a, b = ev[c.position(mech.drive.pivot)][k], ev[c.position(crank_pin)][k]
    ca = min(circles, key=lambda q: math.dist(q, circles[0]))
    # μ: the circle nearest each pivot under the trial scale from the title's "1:…"
    title = next(t.string for t in view.primitives if isinstance(t, Text) and ":" in t.string
                 and re.search(r"1:\s*[\d.,]+", t.string))
    mu = _number(re.search(r"1:\s*([\d.,]+)", title).group(1)) / 1000.0
    ca = min(circles, key=lambda q: math.dist(q, np.asarray(a) / mu))
    cb = min(circles, key=lambda q: math.dist(q, np.asarray(b) / mu))
    assert math.dist(ca, np.asarray(a) / mu) < 0.05 and math.dist(cb, np.asarray(b) / mu) < 0.05
    mu = float(np.hypot(*(np.asarray(a) - b))) / math.dist(ca, cb)     # exact, from the pins
    from mechplan.i18n import message

    head = message("icdraw.panel.arrows", lang, value="@").split("@")[0]
    arrows = next(t.string for t in view.primitives if isinstance(t, Text)
                  and t.string.startswith(head))
    mu_v = _number(re.match(re.escape(head) + r"\s*([\d.,]+)", arrows).group(1))
    lines = [p for p in view.primitives if isinstance(p, Line)]
    assert any(isinstance(p, Arc) for p in view.primitives) or name == "shaper"
    # the driving crank's pin: v = ω1·r at right angles to the crank, drawn from the pin
    drv = mech.drive.link
    pin = next(pr.point for pr in mech.pairs if drv in (pr.a, pr.b) and "0" not in (pr.a, pr.b))
    foot = np.asarray(ev[c.position(pin)][k]) / mu
    v = ev[c.velocity_image(pin)][k]
    tip = foot + v / mu_v
    assert any(math.dist(p.start, foot) < 1e-6 * (1 + math.hypot(*foot))
               and math.dist(p.end, tip) < 1e-6 * (1 + math.hypot(*tip)) for p in lines)
    radius = ev[c.position(pin)][k] - ev[c.position(mech.drive.pivot)][k]
    assert abs(float(np.dot(v, radius))) < 1e-9 * float(np.hypot(*v) * np.hypot(*radius))
    # the table: each v's arrow (mm) is |v|/μv to 0.1 mm and the difference from the plan tiny
    (tab,) = [p for p in vtable.primitives if isinstance(p, Table)]
    rows = {row[0]: row for row in tab.cells[1:]}
    for p in (pin,):
        speed = float(np.hypot(*ev[c.velocity_image(p)][k]))
        assert _number(rows[f"v_{p}"][1]) == pytest.approx(speed / mu_v, abs=0.051)
    for row in tab.cells[1:]:
        diff = row[5].replace("×10", "e").translate(str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789"))
        assert _number(diff) < 1e-12, row
