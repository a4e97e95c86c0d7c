"""The ordinary pair 5–6 on the train's velocity plan: gear 5 turns with the planetary output,
gear 6 about its own axis at a56 = m(z5 + z6)/2, and the plan's ω6 equals ω5·z5/(−z6)."""

from __future__ import annotations

from pathlib import Path

import pytest

from mechplan.studies import solve_file

TEMPLATE = Path(__file__).resolve().parents[2] / "templates" / "planetary_two_row.toml"


def test_pair_56_on_the_plan():
    st = solve_file(TEMPLATE)
    sol = st.solution
    o = sol.ordinary_plan
    z5, z6, m = sol.ordinary.z5, sol.ordinary.z6, sol.ordinary.spec.module
    assert o.a56 == pytest.approx(m * (z5 + z6) / 2)
    w5 = sol.planetary.plan.omega[sol.planetary.spec.output]
    assert o.omega6 == pytest.approx(w5 * z5 / -z6, rel=1e-14)
    (y0, v0), (y1, v1) = o.lines["6"]
    v_axis = v0 + (v1 - v0) * (o.a56 - y0) / (y1 - y0)          # gear 6 at rest on its axis
    assert v_axis == pytest.approx(0.0, abs=1e-12)
    assert (v1 - v0) / (y1 - y0) == pytest.approx(o.omega6, rel=1e-12)
    (_, _), (y5, v5) = o.lines["5"]
    assert v5 / y5 == pytest.approx(w5, rel=1e-14) and y5 == pytest.approx(y0)
    sheets = st.sheets(None, None, "en", "t")
    texts = [p.string for s in sheets for p in s.flat() if hasattr(p, "string")]
    assert "6" in texts and "C" in texts
