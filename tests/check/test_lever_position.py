"""A value written on Zhukovsky's lever is graded at the lever's own position.

On a small sheet the lever (titled "Zhukovsky's lever — φ = 30.0°", its M_q and M_b beneath) can
share the sheet with velocity plans of other positions; its values are graded at the φ of the
title they stand under, not at the position the sheet's other plans fit best.
"""

from __future__ import annotations

import ezdxf
import pytest
from scenes import DRIVER_TEMPLATES, TEMPLATES

from mechplan.check import Options, check
from mechplan.check.report import OK, WRONG
from mechplan.render.dxf import to_bytes
from mechplan.scene import load_scene
from mechplan.sheet.compose import compose
from mechplan.solve import solve


@pytest.fixture(scope="module")
def lever_sheet(tmp_path_factory):
    """machine_unit on a small sheet in Russian: the first sheet whose lever shares it with
    velocity plans of other positions (the grid of every position; which sheet that is follows
    the layout: A3 ГОСТ sheet 2 since the tables flow by rows, A4 ISO before)."""
    path = next(p for p in TEMPLATES if p.stem == "machine_unit")
    scene = load_scene(path)
    sol = solve(scene)
    for size, standard in (("A4", "iso"), ("A3", "gost"), ("A4", "gost"), ("A3", "iso")):
        comp = compose(sol, size, standard, "ru", name=path.stem)
        for i, sheet in enumerate(comp.sheets):
            names = [panel.name for panel, _ in comp.placements[i]]
            if any(n.endswith("lever") for n in names) and any(
                    n.startswith("velocity-all") for n in names):
                dxf = tmp_path_factory.mktemp("lever") / f"sheet-{i + 1}.dxf"
                dxf.write_bytes(to_bytes(sheet))
                return scene, dxf
    pytest.fail("no A4 or A3 sheet holds the lever with velocity plans of other positions")


def _retitle(src, dst, old: str, new: str) -> None:
    doc = ezdxf.readfile(src)
    hits = [e for e in doc.modelspace().query("TEXT") if old in e.dxf.text]
    assert len(hits) == 1, [e.dxf.text for e in hits]
    hits[0].dxf.text = hits[0].dxf.text.replace(old, new)
    doc.saveas(dst)


def test_lever_values_graded_at_the_lever_position(lever_sheet) -> None:
    scene, dxf = lever_sheet
    report = check(scene, dxf, Options())
    values = {v.name: v for v in report.values}
    assert {"Mq2", "Mb"} <= values.keys()
    assert all(v.verdict == OK for v in report.values), report.text()
    # the plans of the sheet fit another position best: the values follow the lever's title
    assert report.phi_deg != pytest.approx(30.0)
    assert values["Mq2"].exact == pytest.approx(values["Mq2"].submitted, abs=0.01)


def test_the_title_decides_the_position(lever_sheet, tmp_path) -> None:
    """The same M_q2 under a lever titled with another angle is graded at that angle (and is
    wrong there): the title decides, not the position the drawn lever fits best."""
    scene, dxf = lever_sheet
    moved = tmp_path / "moved.dxf"
    _retitle(dxf, moved, "Жуковского — φ = 30,0°", "Жуковского — φ = 300,0°")
    values = {v.name: v for v in check(scene, moved, Options()).values}
    assert values["Mq2"].verdict == WRONG


def test_values_under_a_title_naming_a_linear_driver_coordinate(tmp_path) -> None:
    """The excavator arm (two cylinders) on A3 TCVN in Chinese: its lever, titled
    "… — l4 = 2400.0 mm" with M_q2, M_q5, F_d beneath, shares a sheet with velocity plans of
    l4 = 2800 and 3000 mm; the values are graded at l4 = 2400 mm, the position the title names
    (graded at the sheet's best-fitting position they were wrong by 85 %, 97 %, 14 %)."""
    path = next(p for p in DRIVER_TEMPLATES if p.stem == "excavator_arm")
    scene = load_scene(path)
    comp = compose(solve(scene), "A3", "tcvn", "zh", name=path.stem)
    graded = 0
    for i, sheet in enumerate(comp.sheets):
        names = [panel.name for panel, _ in comp.placements[i]]
        if not any(n.endswith("lever") for n in names):
            continue
        dxf = tmp_path / f"sheet-{i + 1}.dxf"
        dxf.write_bytes(to_bytes(sheet))
        report = check(scene, dxf, Options())
        values = {v.name: v for v in report.values}
        assert {"Mq2", "Fd"} <= values.keys(), sorted(values)
        assert all(v.verdict == OK for v in report.values), report.text()
        graded += len(values)
    assert graded >= 3
