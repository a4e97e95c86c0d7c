"""The instant-centre panel: every centre named (a point, or an arrow to a far one), the lines of
Kennedy's constructions, the circle diagram and the table of centres."""

from __future__ import annotations

import pytest
from scenes import ROOT

from mechplan.drafting.primitives import Line, Polyline, Role, Table, Text
from mechplan.scene import load_scene
from mechplan.sheet.centres import centres_panels
from mechplan.sheet.compose import compose
from mechplan.sheet.scales import room
from mechplan.solve import solve


@pytest.mark.parametrize("name, lang", [("four_bar", "en"), ("quick_return", "ru"),
                                        ("shaper", "zh"), ("slider_crank", "vi")])
def test_every_centre_is_named_in_the_view_and_the_table(name, lang):
    sol = solve(load_scene(ROOT / "templates" / f"{name}.toml"))
    view, diagram, table, *_ = centres_panels(sol, 1, sol.scales[next(iter(sol.scales))], lang,
                                          room("A1", "iso"))
    n = len(sol.scene.mechanism.links)
    count = n * (n - 1) // 2
    sym = "I" if lang == "en" else "P"
    texts = " ".join(t.string for t in view.primitives if isinstance(t, Text))
    names = [f"{sym}{i}{j}" for i in range(n) for j in range(i + 1, n)]
    assert all(nm in texts for nm in names), (names, texts)
    # the Kennedy lines: two per centre found by the theorem (where they cross the view)
    dashed = [p for p in view.primitives if isinstance(p, Line) and p.role is Role.DASHED]
    assert len(dashed) >= 2
    # the centrodes the scene asks for ([centres] links) are drawn dash-dot
    assert any(isinstance(p, Polyline) and p.role is Role.CHAIN for p in view.primitives)
    chords = [p for p in diagram.primitives if isinstance(p, Line)]
    assert len(chords) == count
    assert sum(p.role is Role.OUTLINE for p in chords) == len(sol.scene.mechanism.pairs)
    (tab,) = [p for p in table.primitives if isinstance(p, Table)]
    assert len(tab.cells) == count + 1
    assert {row[0] for row in tab.cells[1:]} == set(names)
    infinite = [row for row in tab.cells[1:] if row[1] == "∞"]
    assert (len(infinite) > 0) == any(
        p.kind.value == "P" for p in sol.scene.mechanism.pairs)


def test_the_panel_is_drawn_only_when_asked():
    text = (ROOT / "templates" / "four_bar.toml").read_text(encoding="utf-8")
    from mechplan.scene import parse_scene

    plain = parse_scene(text[:text.index("[centres]")])
    names = [p.name for placed in compose(solve(plain)).placements for p, _ in placed]
    assert not any(n.startswith("centres") for n in names)
    asked = load_scene(ROOT / "templates" / "four_bar.toml")
    names = [p.name for placed in compose(solve(asked)).placements for p, _ in placed]
    assert {"centres", "centres-diagram", "centres-table"} <= set(names)
