"""A plan's title decides which group's force polygon it is and at which position it was drawn.

Two cranks' force polygons carry the same vertex letters (a, b, …), and a slider-driven coulisse's
driver and group polygons too: by fit alone the checker read a loaded five-bar's polygon of
I(0,1) as I(0,4) at another position (2 segments "wrong") and a loaded coulisse's polygon at the
wrong position (5 "wrong"). The titles mechplan writes ("Force plan I(0,1) — position 1,
φ = 30.0°", "… position 1, s1 = -200.0 mm") name both; the loaded variants of the two templates
must check clean at several sizes, standards and languages.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from mechplan.check import Options, check
from mechplan.check.report import MISSING, WRONG
from mechplan.errors import CheckError
from mechplan.render.dxf import to_bytes
from mechplan.scene import load_scene
from mechplan.sheet.compose import compose
from mechplan.solve import solve
from mechplan.submission.read import SheetText
from mechplan.submission.titles import names_group, position_written, title_above, written_step

TEMPLATES = Path(__file__).parents[2] / "src/mechplan/templates"


def _loaded_five_bar() -> str:
    text = (TEMPLATES / "five_bar_two_cranks.toml").read_text(encoding="utf-8")
    text = text.replace('[links.2]\nname = "coupler"\n',
                        '[links.2]\nname = "coupler"\nmass = "2 kg"\n'
                        'centre = { S2 = "midpoint B C" }\n', 1)
    text = text.replace('[links.3]\nname = "coupler"\n',
                        '[links.3]\nname = "coupler"\nmass = "1.5 kg"\n'
                        'centre = { S3 = "midpoint D C" }\n', 1)
    return text + '\n[gravity]\ng = "9.81 m/s^2"\n'


def _loaded_coulisse() -> str:
    text = (TEMPLATES / "slider_coulisse.toml").read_text(encoding="utf-8")
    text = text.replace('lengths = { O3E = "500 mm" }\n',
                        'lengths = { O3E = "500 mm" }\nmass = "12 kg"\n'
                        'centre = { S3 = "midpoint O3 E" }\n', 1)
    text = text.replace('[links.1]\nname = "slider block"\n',
                        '[links.1]\nname = "slider block"\nmass = "3 kg"\ncentre = "B"\n', 1)
    return text + '\n[gravity]\ng = "9.81 m/s^2"\n'


CASES = {"five_bar_loaded": _loaded_five_bar, "coulisse_loaded": _loaded_coulisse}


@pytest.mark.parametrize("name", sorted(CASES))
def test_loaded_sheets_with_same_letter_polygons_check_clean(name, tmp_path):
    scene_path = tmp_path / f"{name}.toml"
    scene_path.write_text(CASES[name](), encoding="utf-8")
    scene = load_scene(scene_path)
    sol = solve(scene)
    failures: list[str] = []
    force_plans = 0
    for size, standard, lang in (("A1", "iso", "en"), ("A3", "gost", "ru"), ("A2", "tcvn", "vi")):
        comp = compose(sol, size, standard, lang, name=name)
        for i, sheet in enumerate(comp.sheets):
            dxf = tmp_path / f"{name}-{size}-{i + 1}.dxf"
            dxf.write_bytes(to_bytes(sheet))
            try:
                report = check(scene, dxf, Options())
            except CheckError:
                continue
            for p in report.plans:
                force_plans += p.plan == "force"
                bad = [s.name for s in p.segments if s.verdict in (WRONG, MISSING)]
                if bad:
                    failures.append(f"{size} {standard} sheet {i + 1}: {p.name}: {bad}")
    assert force_plans >= 3 * 2, force_plans      # the group's and the drivers' polygons, graded
    assert not failures, "\n".join(failures)


def _text(text: str, x: float, y: float, width: float = 60.0) -> SheetText:
    return SheetText(text, (x + width / 2, y), 3.5, "TEXT", half=(width / 2, 1.75))


def test_the_title_is_the_nearest_above_and_names_the_group():
    texts = [_text("Force plan I(0,1) — position 1, φ = 30.0°", 0, 100),
             _text("μF = 0.2 N/mm", 0, 95, 20),
             _text("Force plan II(0,1) — position 3, φ = 90.0°", 200, 100),
             _text("Velocity plan — position 2, φ = 60.0°", 0, 40)]
    drawing = [(10.0, 60.0), (50.0, 90.0)]
    title = title_above(drawing, texts, ["I(0,1)", "II(0,1)"])
    assert title is texts[0]                     # not the scale under it, not the one below
    assert names_group(title.text, "I(0,1)") and not names_group(title.text, "II(0,1)")
    assert not names_group(texts[2].text, "I(0,1)")
    assert title_above([(210.0, 60.0)], texts, ["I(0,1)"]) is texts[2]
    # a drawing with no title above it, nor ending within 200 mm left of it, has none
    assert title_above([(500.0, 60.0)], texts) is None


@pytest.mark.parametrize(("title", "expected"), [
    ("Force plan I(0,1) — position 1, φ = 30.0°", ("φ", 30.0, "°")),
    ("План сил II(2,3) — положение 4, φ = 120,5°", ("φ", 120.5, "°")),
    ("Velocity plan — position 2, s1 = -150.0 mm", ("s1", -150.0, "mm")),
    ("phi1 = 45 deg", ("phi1", 45.0, "deg")),
    ("Рычаг Жуковского — s1 = -100,0 мм", ("s1", -100.0, "мм")),
    ("Force plan II(2,3)", None),
    ("μF = 0.2 N/mm", None),
])
def test_position_written_at_the_end_of_a_title(title, expected):
    assert position_written(title) == expected


def test_written_step_is_half_the_last_digit():
    assert written_step("… s1 = -100,0 мм") == pytest.approx(0.05)
    assert written_step("φ = 30°") == pytest.approx(0.5)
    assert written_step("l4 = 1562.25 mm") == pytest.approx(0.005)


def test_a_title_over_another_drawing_titles_that_one():
    """A grid cell's title above a column of drawings titles the drawing under it, not the one
    under that (a lever drawn far right of its own title, below a grid of velocity plans)."""
    texts = [_text("Position 10, φ = 303.8°", 430, 287, 40),
             _text("Zhukovsky's lever — φ = 33.8°", 181, 190, 96)]
    cell = (435.0, 510.0, 243.0, 285.0)
    lever = [(408.0, 95.0), (470.0, 140.0)]
    assert title_above(lever, texts, others=[cell]) is texts[1]
    assert title_above(lever, texts) is texts[0]           # without the drawing between them


def test_linear_driver_sheet_with_plans_of_two_positions(tmp_path):
    """The excavator's A3 ГОСТ sheet in Russian draws the plans of position 1 (l4 = 1562,5 мм)
    and velocity plans of other positions (l4 = 1450,0 мм …) in a grid; graded all at the sheet's
    best position, a plan of position 0 had 4 segments "wrong". The report names the driver's
    coordinate, not a crank angle."""
    scene = load_scene(TEMPLATES / "excavator_boom.toml")
    comp = compose(solve(scene), "A3", "gost", "ru", name="excavator_boom")
    dxf = tmp_path / "excavator_boom.dxf"
    dxf.write_bytes(to_bytes(comp.sheets[0]))
    report = check(scene, dxf, Options())
    at = {p.name if isinstance(p.name, str) else p.name.tr("en"): p.phi_deg for p in report.plans}
    assert report.passed, report.text()
    positions = {round(1450.0 + 112.5 * k, 6) for k in range(5)}       # the scene's l4, mm
    assert {round(v, 6) for v in at.values()} <= positions and len(set(at.values())) >= 2, at
    assert at["position plan"] == pytest.approx(1562.5)                  # the titled position 1
    assert report.coordinate == "l4"
    text = report.text("ru")
    assert "l4 = 1562,50 мм" in text and "φ = 1562" not in text


def test_a_text_over_a_table_heads_the_table_not_the_drawing_below():
    """A force group's equation heading its table ("I(0,1): R21 + R01 = 0", the table's rules
    under it) names the group but titles no drawing: the lever below the table keeps its own
    title, further off but with nothing between (read as the group's second force plan before)."""
    texts = [_text("I(0,1):  R21 + R01 = 0", 165, 253, 48),
             _text("Zhukovsky's lever — φ = 33.8°", 31, 222.5, 70)]
    table = (164.8, 212.4, 235.5, 250.5)                 # the rules of the table under the heading
    lever = [(144.5, 195.9), (179.4, 167.2)]
    assert title_above(lever, texts, ["I(0,1)"]) is texts[0]     # nearer, without the table
    assert title_above(lever, texts, ["I(0,1)"], figures=[table]) is texts[1]
    # a figure beside the gap (not across the span between them) leaves the title
    assert title_above(lever, texts, ["I(0,1)"], figures=[(300.0, 340.0, 235.0, 250.0)]) \
        is texts[0]
    # an underline (no height) is not a figure that parts a title from its drawing
    assert title_above(lever, texts, ["I(0,1)"], figures=[(165.0, 213.0, 251.0, 251.0)]) \
        is texts[0]


@pytest.mark.parametrize(("stem", "size", "standard", "lang"), [
    ("press_friction", "A3", "gost", "ru"), ("press_friction", "A4", "iso", "en"),
    ("machine_unit", "A3", "gost", "ru")])
def test_the_lever_under_a_table_is_no_force_plan(stem, size, standard, lang, tmp_path):
    """The sheets with the lever and a force group's tables: every drawn plan read once (no
    "force … plan #2" made of the lever's letters), all segments right."""
    scene = load_scene(TEMPLATES / f"{stem}.toml")
    comp = compose(solve(scene), size, standard, lang, name=stem)
    levers = 0
    for i, sheet in enumerate(comp.sheets):
        names = [panel.name for panel, _ in comp.placements[i]]
        if not any(n.endswith("lever") for n in names):
            continue
        levers += 1
        dxf = tmp_path / f"{stem}-{i + 1}.dxf"
        dxf.write_bytes(to_bytes(sheet))
        report = check(scene, dxf, Options())
        forces = [p for p in report.plans if p.plan == "force"]
        groups = [n.split("-")[2] for n in names if re.fullmatch(r"force-\d+-[^-]+", n)
                  and not n.endswith("lever")]
        assert len(forces) == len(groups), ([p.name for p in report.plans], names)
        assert all(s.verdict not in (WRONG, MISSING) for p in report.plans for s in p.segments)
    assert levers >= 1
