"""Assembly mode is explicit and fixed: by side of a directed line, by sign, or by a sketch."""

import numpy as np
import pytest
from scenes import build_text, four_bar_text, slider_crank_text

from mechplan.errors import SceneError

PHI = np.linspace(0, 2 * np.pi, 721)


def _cross(a, b, c):
    return (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])


@pytest.mark.parametrize("side", ["left", "right"])
def test_side_of_a_directed_line_holds_over_the_whole_cycle(side):
    _, c = build_text(four_bar_text(side_c=side))
    ev = c.evaluate(PHI)
    s = _cross(ev["pos.B"], ev["pos.D"], ev["pos.C"])
    assert np.all(s > 0) if side == "left" else np.all(s < 0)


def test_sketch_picks_the_nearest_branch_once():
    text = four_bar_text().replace('C = "left of B->D"', 'C = ["250 mm", "-170 mm"]')
    _, c = build_text(text)
    ev = c.evaluate(PHI)
    assert ev["pos.C"][0, 1] < 0                          # the sketched (lower) branch at φ = 0
    assert np.all(_cross(ev["pos.B"], ev["pos.D"], ev["pos.C"]) < 0)   # and it stays there
    _, right = build_text(four_bar_text(side_c="right"))
    assert np.allclose(ev["pos.C"], right.evaluate(PHI)["pos.C"], rtol=0, atol=1e-15)


def test_arc_across_a_guide_takes_the_signed_intersection():
    _, plus = build_text(slider_crank_text(side="+"))
    _, minus = build_text(slider_crank_text(side="-"))
    b_plus, b_minus = plus.evaluate(PHI)["pos.B"], minus.evaluate(PHI)["pos.B"]
    a = plus.evaluate(PHI)["pos.A"]
    assert np.all(b_plus[:, 0] > a[:, 0]) and np.all(b_minus[:, 0] < a[:, 0])
    # mirror images about the foot of the crank pin on the guide
    assert np.allclose(b_plus[:, 0] + b_minus[:, 0], 2 * a[:, 0], atol=1e-15)


def test_side_relative_to_points_found_later_is_refused():
    text = four_bar_text().replace('C = "left of B->D"', 'C = "left of B->E"')
    with pytest.raises(SceneError) as info:
        build_text(text)
    assert "assembly.C" in str(info.value) and "before E" in str(info.value)
