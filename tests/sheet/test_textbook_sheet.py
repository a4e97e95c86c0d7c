"""The textbook answers' tables on the sheet: present when asked, absent otherwise, and their
numbers are the solution's (the JSON's) as written by the number writers."""

from __future__ import annotations

import math
from pathlib import Path

from mechplan.drafting.primitives import Table, Text
from mechplan.i18n import number
from mechplan.scene import parse_scene
from mechplan.sheet.compose import compose_sheets
from mechplan.solve import solve, to_json

DOC = (Path(__file__).resolve().parents[2] / "docs" / "textbook.md").read_text(encoding="utf-8")
SCENE = DOC.split("<!-- example: scene textbook -->")[1].split("```toml\n")[1].split("```")[0]


def _texts(sheets) -> list[str]:
    out = []
    for sh in sheets:
        for p in sh.primitives:
            if isinstance(p, Table):
                out += [c for row in p.cells for c in row]
            elif isinstance(p, Text):
                out.append(p.string)
    return out


def test_the_tables_carry_the_solutions_numbers():
    sol = solve(parse_scene(SCENE, "textbook.toml"))
    doc = to_json(sol)
    texts = _texts(compose_sheets(sol, lang="ru"))
    st = doc["textbook"]["strokes"]["B"]
    assert any(f"K = {number(st['K'], 4, 'ru')}" in t for t in texts)
    assert any(f"H = {number(st['H'] * 1000, 2, 'ru')}" in t for t in texts)
    for k, pos in enumerate(doc["positions"]):
        v = pos["textbook"]["sliding"]["B/x"]["v_slide"]
        assert number(v, 4, "ru") in texts, (k, v)
        g = pos["textbook"]["transmission"]["II(2,3)"]["gamma_deg"]
        assert number(g, 2, "ru") in texts
    gmin = doc["textbook"]["transmission_min"]["II(2,3)"]["gamma_min_deg"]
    assert math.isclose(gmin, 90 - math.degrees(math.asin(0.15 / 0.35)), abs_tol=1e-9)
    assert any(f"γ_min = {number(gmin, 2, 'ru')}°" in t for t in texts)


def test_no_tables_when_not_asked():
    scene = SCENE.split("[answers]")[0]
    texts = _texts(compose_sheets(solve(parse_scene(scene, "plain.toml")), lang="en"))
    assert not any("K = " in t or t.startswith("v_rel") for t in texts)


def test_an_own_sheet_with_the_tables_still_checks_clean(tmp_path):
    """The tables add no warning to the check of mechplan's own sheet (the own-sheets
    invariant): the same warnings as the sheet of the scene without [answers]."""
    from mechplan.check import check
    from mechplan.cli import main

    def warnings(text: str, name: str) -> tuple[bool, list[str]]:
        scene = tmp_path / f"{name}.toml"
        scene.write_text(text, encoding="utf-8")
        assert main(["draw", str(scene), "-o", str(tmp_path), "--format", "dxf"]) == 0
        report = check(str(scene), str(tmp_path / f"{name}.dxf"))
        return report.passed, sorted(n.message.replace(name, "X") for n in report.notes
                                     if n.level in ("warning", "error"))

    with_tables = warnings(SCENE, "asked")
    without = warnings(SCENE.split("[answers]")[0], "plain")
    assert with_tables[0] and without[0]
    assert with_tables[1] == without[1]
