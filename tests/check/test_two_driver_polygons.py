"""Two drivers' force polygons carry the same vertex letters (each closes its driver's loads, the
reaction on its pin and its carrier's force): the checker tells them apart by the title drawn
above each ("Force plan I(0,1) — position 1"), so a loaded five-bar's and a loaded excavator
arm's own sheets grade every force polygon clean."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from mechplan.check import Options, check
from mechplan.check.report import MISSING, WRONG
from mechplan.errors import CheckError
from mechplan.render.dxf import to_bytes
from mechplan.scene import parse_scene
from mechplan.sheet.compose import compose
from mechplan.solve import solve

sys.path.insert(0, str(Path(__file__).parents[1] / "dynamics"))
TEMPLATES = Path(__file__).parents[2] / "src" / "mechplan" / "templates"


def _five_bar() -> str:
    text = (TEMPLATES / "five_bar_two_cranks.toml").read_text(encoding="utf-8")
    text = text.replace('lengths = { BC = "200 mm" }',
                        'lengths = { BC = "200 mm" }\npoints = { S2 = "0.5 of B C" }\n'
                        'mass = "2 kg"\ncentre = "S2"\nJ = "0.01 kg*m^2"')
    text = text.replace('lengths = { DC = "180 mm" }',
                        'lengths = { DC = "180 mm" }\npoints = { S3 = "0.5 of D C" }\n'
                        'mass = "1.5 kg"\ncentre = "S3"\nJ = "0.006 kg*m^2"')
    return text.replace("[assembly]", '[gravity]\ng = "9.81 m/s^2"\n\n[assembly]')


def _arm() -> str:
    from test_two_cylinders_forces import _loaded

    return _loaded((TEMPLATES / "excavator_arm.toml").read_text(encoding="utf-8"))


@pytest.mark.parametrize(("name", "text_of"), [("five_bar", _five_bar), ("arm", _arm)])
def test_each_drivers_polygon_is_graded_as_its_own(name, text_of, tmp_path):
    (tmp_path / f"{name}.toml").write_text(text_of(), encoding="utf-8")
    scene = parse_scene(text_of(), str(tmp_path / f"{name}.toml"))
    sol = solve(scene)
    comp = compose(sol, "A3", "iso", "en", name=name)
    graded = set()
    for i, sheet in enumerate(comp.sheets):
        dxf = tmp_path / f"{name}-{i}.dxf"
        dxf.write_bytes(to_bytes(sheet))
        try:
            report = check(scene, dxf, Options())
        except CheckError:
            continue
        for p in report.plans:
            if p.plan != "force":
                continue
            bad = [s.name for s in p.segments if s.verdict in (WRONG, MISSING)]
            assert not bad, (name, i, str(p.name), bad)
            graded.add(str(p.name))
    drivers = {"five_bar": ("I(0,1)", "I(0,4)"), "arm": ("I(3,4)", "I(6,7)")}[name]
    for group in drivers:
        assert any(group in g for g in graded), (group, graded)
