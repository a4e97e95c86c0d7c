"""Our own sheets (drawings/*.dxf, made by `mechplan draw`) checked against their scenes.

The velocity, acceleration and force plans of a sheet pass within 0.01 mm (points the sheet labels
as one, "c≡d", excepted); position plans are left out: a sheet draws all positions of the cycle
on one plan.
"""

from __future__ import annotations

import math

import pytest

from mechplan.check import Options, check
from mechplan.check.report import WRONG

from .sheets import ROOT, TEMPLATES

# a template's first sheet; its further sheets (NAME-2, NAME-dynamics) are not checked here
SHEETS = sorted(p for p in (ROOT / "drawings").glob("*.dxf") if (TEMPLATES / f"{p.stem}.toml").exists())


def test_every_template_has_its_sheet() -> None:
    assert {p.stem for p in SHEETS} >= {t.stem for t in TEMPLATES.glob("*.toml")}


@pytest.mark.parametrize("sheet", SHEETS, ids=[p.stem for p in SHEETS])
def test_own_sheet_passes(sheet) -> None:
    scene = TEMPLATES / f"{sheet.stem}.toml"
    report = check(scene, sheet, Options())
    plans = [p for p in report.plans if p.plan in ("velocity", "acceleration", "force")]
    assert {"velocity", "acceleration"} <= {p.plan for p in plans}
    checked = 0
    for p in plans:
        spots = [pt.at_mm for pt in p.points]
        merged = {pt.step for pt in p.points if spots.count(pt.at_mm) > 1}   # "c≡d"
        for s in p.segments:
            assert s.verdict != WRONG, (p.name, s)
            if s.submitted_mm is not None and not {s.start, s.end} & merged:
                checked += 1
                across = (s.exact_mm or 0) * math.sin(math.radians(s.direction_deg or 0))
                assert abs(s.error_mm) < 0.01 and abs(across) < 0.01, (p.name, s)
    assert checked >= 8
    assert not any(v.verdict == WRONG for v in report.values)
