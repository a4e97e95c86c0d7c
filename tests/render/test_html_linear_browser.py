"""The live page of a cylinder-driven machine in a real browser (Chromium by Playwright): the
slider writes the driver's length ("l4 = 2200.0 mm" … "3000.0 mm" over the range), in Russian
with its decimal comma and "мм"; no console error."""

from __future__ import annotations

import pytest
from scenes import ROOT

from mechplan.live_page import write_page
from mechplan.studies import solve_file

pytestmark = pytest.mark.external



def test_the_slider_writes_the_cylinders_length(browser, tmp_path):
    study = solve_file(str(ROOT / "templates" / "excavator_arm.toml"))
    path = write_page(study, tmp_path, "excavator_arm", frames=41)
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    errors: list[str] = []
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(path.as_uri())
    page.click("#tab-anim")
    assert page.text_content("#phi-out") == "l4 = 2200.0 mm"
    page.focus("#phi")
    for _ in range(20):                                 # 20 of 40 steps of 20 mm
        page.keyboard.press("ArrowRight")
    assert page.get_attribute("#phi-out", "data-frame") == "20"
    assert page.text_content("#phi-out") == "l4 = 2600.0 mm"
    page.keyboard.press("End")
    assert page.text_content("#phi-out") == "l4 = 3000.0 mm"
    page.select_option("#language", "ru")
    assert page.text_content("#phi-out") == "l4 = 3000,0 мм"
    assert errors == []
    page.close()
