"""mechplan's own sheets, at every size, standard and language, pass `mechplan check`.

The invariant of issue 28: for every linkage template, every sheet size A4–A0 and every standard
(ISO, ГОСТ, TCVN), the DXF of every sheet that holds a plan checks with 0 wrong and 0 missing, and
every scale factor the checker reads on the sheet is the one `mechplan solve --json --sheet …
--standard …` prints; on a sheet with the instant-centre panel every centre is graded right (issue
30). Languages rotate with the case (each template sees all four).

Each (template, size, standard) is composed once from one solution per template and every sheet
is checked through the API (DXF bytes written to a temporary file, no subprocess). Measured on one
core: about 80 s of CPU for the 120 compositions (compose ≈ 12 s, check ≈ 68 s).
"""

from __future__ import annotations

import re

import pytest
from scenes import DRIVER_TEMPLATES, TEMPLATES

from mechplan.check import Options, check
from mechplan.check.report import MISSING, OK, WRONG
from mechplan.construct.plans.centres import circle_diagram, label
from mechplan.errors import CheckError
from mechplan.model.plans import Plan
from mechplan.render.dxf import to_bytes
from mechplan.scene import load_scene
from mechplan.sheet.compose import compose
from mechplan.solve import choose_scales, solve

SIZES = ("A4", "A3", "A2", "A1", "A0")
STANDARDS = ("iso", "gost", "tcvn")
LANGUAGES = ("en", "ru", "vi", "zh")
#: a panel that holds a plan the checker reads (not its tables apart, a lever, a diagram)
PLAN_PANEL = re.compile(r"^(position|velocity|acceleration|force)(?!.*(tables|lever|diagram))")


GRID = sorted(TEMPLATES + DRIVER_TEMPLATES)


def test_the_grid_is_every_linkage_template():
    assert sorted(p.stem for p in GRID) == [
        "cam_lever_four_bar", "cylinder_carriage", "excavator_arm", "excavator_boom",
        "five_bar_crank_slider", "five_bar_two_cranks", "four_bar", "machine_unit",
        "offset_slider_crank", "press_friction", "quick_return", "shaper", "shaper_flywheel",
        "six_bar_triad", "slider_coulisse", "slider_crank", "v_engine"]


@pytest.mark.parametrize("path", GRID, ids=[p.stem for p in GRID])
def test_own_sheets_check_clean_at_every_size_standard_and_language(path, tmp_path):
    scene = load_scene(path)
    sol = solve(scene)
    # every instant centre the panel can draw (not those Kennedy's theorem leaves indeterminate)
    centre_names = [label(ctr) for ctr in circle_diagram(scene.mechanism).centres]
    offset = [p.stem for p in GRID].index(path.stem)
    failures: list[str] = []
    case = 0
    for size in SIZES:
        for standard in STANDARDS:
            lang = LANGUAGES[(offset + case) % len(LANGUAGES)]
            case += 1
            comp = compose(sol, size, standard, lang, name=path.stem)
            # the μ of `mechplan solve --json --sheet SIZE --standard STANDARD`
            printed = choose_scales(scene, sol.construction, sol.ev, sol.plans, size, standard)
            assert comp.scales == printed, (size, standard)
            for i, sheet in enumerate(comp.sheets):
                where = f"{size} {standard} {lang} sheet {i + 1}"
                names = [panel.name for panel, _ in comp.placements[i]]
                dxf = tmp_path / f"{path.stem}-{size}-{standard}-{i + 1}.dxf"
                dxf.write_bytes(to_bytes(sheet))
                holds_plan = any(PLAN_PANEL.match(n) for n in names)
                try:
                    report = check(scene, dxf, Options())
                except CheckError:              # "no plan on the sheet": only where none is
                    assert not holds_plan, (where, names)
                    continue
                for p in report.plans:
                    bad = [s.name for s in p.segments if s.verdict in (WRONG, MISSING)]
                    if bad:
                        failures.append(f"{where}: {p.name}: {bad}")
                    if p.mu is None or p.mu != pytest.approx(printed[Plan(p.plan)],
                                                             rel=1e-9):
                        failures.append(f"{where}: {p.name}: μ {p.mu} on the sheet, "
                                        f"{printed[Plan(p.plan)]} printed by solve")
                failures += [f"{where}: {v.name}" for v in report.values if v.verdict == WRONG]
                assert report.plans or not holds_plan, (where, names)
                if "centres" in names:          # the instant-centre panel: every centre graded
                    failures += [f"{where}: centre {c.label}: {c.verdict} {c.error}"
                                 for c in report.centres if c.verdict in (WRONG, MISSING)]
                    # (acceleration poles Q2 of the panel are rows too, graded above)
                    graded = sorted(c.label for c in report.centres if c.verdict == OK
                                    and not c.label.startswith("Q"))
                    if graded != sorted(centre_names):
                        failures.append(f"{where}: centres graded {graded}, "
                                        f"{sorted(centre_names)} drawn")
    assert not failures, "\n".join(failures[:20])
