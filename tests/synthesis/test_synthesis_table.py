"""The conditions table of the synthesis sheet (issue 31): its cells against values computed
here from the synthesised lengths, drawn as a table on the sheet in four languages."""

from __future__ import annotations

import math

import pytest
from scenes import ROOT

from mechplan.drafting.primitives import Table, Text
from mechplan.i18n import message
from mechplan.studies import solve_file
from mechplan.studies.synthesis_table import condition_rows


def study(name: str):
    return solve_file(ROOT / "templates" / f"{name}.toml")


def test_crank_rocker_table_values_are_the_closed_forms():
    s = study("synth_crank_rocker")
    n = s.design.lengths
    r, l, c, d = (n[k] * 1e3 for k in ("r", "l", "c", "d"))
    v = sorted((r, l, c, d))
    margin = v[1] + v[2] - v[0] - v[3]
    mu = [math.acos((l * l + c * c - bd * bd) / (2 * l * c)) for bd in (d - r, d + r)]
    gamma = math.degrees(min(min(m, math.pi - m) for m in mu))
    rows = {r[0]: r[1:] for r in condition_rows(s, "en")}
    assert rows["Grashof (margin, mm)"] == ["yes", f"{margin:.3f}"]
    assert float(rows["γmin, °"][0]) == pytest.approx(gamma, abs=1e-3)
    assert rows["Time ratio K"] == ["1.200000", "1.200000"]
    assert rows["Swing ψ, °"] == ["45.0000", "45.0000"]
    assert rows["γmin, °"][1].endswith("[γ] = 40.0°")


@pytest.mark.parametrize("name", ["synth_crank_rocker", "synth_path", "synth_guidance",
                                  "synth_central_rocker"])
@pytest.mark.parametrize("lang", ["en", "ru", "vi", "zh"])
def test_the_table_is_drawn_on_the_sheet(name, lang):
    s = study(name)
    rows = condition_rows(s, lang)
    assert len(rows) >= 4 and all(len(r) == 3 for r in rows)
    sheets = s.sheets("A3", None, lang, name)
    texts = [p.string for sh in sheets for p in sh.primitives if isinstance(p, Text)]
    texts += [cell for sh in sheets for p in sh.primitives if isinstance(p, Table)
              for row in p.cells for cell in row]
    assert message("synth.table.title", lang) in texts
    assert all(r[0] in texts and r[1] in texts for r in rows)
