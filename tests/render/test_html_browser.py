"""The live page in a real browser (Debian's chromium driven by Playwright): stepping through a
plan shows exactly the step's elements and highlights its sentence, the slider moves the
mechanism to the solved position, the language switch re-labels the page, no console error."""

from __future__ import annotations

import json
import os
import re
from pathlib import Path

import numpy as np
import pytest
from scenes import ROOT

from mechplan.i18n import message
from mechplan.live_page import write_page
from mechplan.model.plans import Plan
from mechplan.studies import solve_file

pytestmark = pytest.mark.external

#: where the screenshots go (kept as CI artefacts when MECHPLAN_ARTEFACTS names a folder)
ARTEFACTS = os.environ.get("MECHPLAN_ARTEFACTS")


def _elements(prim: dict) -> int:
    """How many SVG elements the page draws for one primitive (an arrow: shaft and head)."""
    if "t" in prim or "c" in prim:
        return 1
    return int(bool(prim.get("d"))) + int(bool(prim.get("h")))



@pytest.fixture(scope="module")
def four_bar(tmp_path_factory):
    out = tmp_path_factory.mktemp("page")
    study = solve_file(str(ROOT / "templates" / "four_bar.toml"))
    path = write_page(study, out, "four_bar")
    text = path.read_text(encoding="utf-8")
    m = re.search(r'<script type="application/json" id="data">(.*?)</script>', text, re.DOTALL)
    return study, path, json.loads(m.group(1).replace("<\\/", "</"))


def _shot(page, name: str, tmp: Path) -> None:
    folder = Path(ARTEFACTS) if ARTEFACTS else tmp
    folder.mkdir(parents=True, exist_ok=True)
    page.screenshot(path=str(folder / name), full_page=True)


def test_replay_steps_and_slider_in_chromium(browser, four_bar, tmp_path):
    study, path, doc = four_bar
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    errors: list[str] = []
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("request", lambda r: errors.append(f"request {r.url}")
            if not r.url.startswith(("file:", "data:")) else None)
    page.goto(path.as_uri())
    page.wait_for_selector("body[data-ready='1']")

    # the velocity plan of the first chosen position, five presses of "next"
    index = next(i for i, r in enumerate(doc["replays"]) if r["plan"] == "velocity")
    r = doc["replays"][index]
    page.select_option("#plan", str(index))
    page.focus("#next")
    presses = min(5, len(r["steps"]) - 1)
    for _ in range(presses):
        page.click("#next")
    k = presses
    assert page.get_attribute("#counter", "data-step") == str(k + 1)
    current = page.locator("#protocol li.current")
    assert current.count() == 1
    assert current.text_content() == r["steps"][k]["sentence"]["en"]
    assert page.locator("#protocol li").nth(k).get_attribute("aria-current") == "step"
    shown = page.locator("#r-svg > *:not(.off)").count()
    assert shown == sum(_elements(p) for p in r["prims"]["en"] if p["k"] <= k)
    now = page.locator(f"#r-svg > [data-k='{k}']").count()
    assert now == sum(_elements(p) for p in r["prims"]["en"] if p["k"] == k)
    # one more with the keyboard: the step's own elements appear, nothing else
    page.focus("#r-svg")
    page.keyboard.press("ArrowRight")
    assert page.get_attribute("#counter", "data-step") == str(k + 2)
    after = page.locator("#r-svg > *:not(.off)").count()
    assert after - shown == sum(_elements(p) for p in r["prims"]["en"] if p["k"] == k + 1)
    rows = page.locator("#segments tr[data-k]:not(.off)").count()
    assert rows == sum(1 for x in r["rows"] if x["step"] <= k + 1)
    _shot(page, "html-replay.png", tmp_path)

    # the animation: the slider moves B to its solved position at that crank angle
    page.click("#tab-anim")
    page.focus("#phi")
    for _ in range(30):
        page.keyboard.press("ArrowRight")
    assert page.get_attribute("#phi-out", "data-frame") == "30"
    sol = study.solution
    c, mu = sol.construction, sol.scales[Plan.POSITION]
    phi = np.radians(doc["animation"]["phi_deg"][30])
    solved = np.asarray(c.evaluate(np.array([phi]))[c.position("B")])[0] / mu
    dot = page.locator("svg[data-panel='position'] circle[data-point='B']")
    cx, cy = float(dot.get_attribute("cx")), float(dot.get_attribute("cy"))
    assert (cx, -cy) == pytest.approx(tuple(solved), abs=0.006)
    # on screen: the page's own transform (viewBox → pixels) puts the dot's centre there
    screen = dot.evaluate("e => { const m = e.getScreenCTM(); const p = new DOMPoint("
                          "+e.getAttribute('cx'), +e.getAttribute('cy')).matrixTransform(m);"
                          " return [p.x, p.y]; }")
    box = dot.bounding_box()
    assert screen[0] == pytest.approx(box["x"] + box["width"] / 2, abs=1.0)
    assert screen[1] == pytest.approx(box["y"] + box["height"] / 2, abs=1.0)
    before = (cx, cy)
    page.keyboard.press("ArrowRight")
    moved = (float(dot.get_attribute("cx")), float(dot.get_attribute("cy")))
    assert moved != before
    _shot(page, "html-animation.png", tmp_path)

    # the language switch: the page's words and the protocol in Russian
    page.click("#tab-replay")
    page.select_option("#language", "ru")
    assert page.text_content("#tab-replay") == message("html.replay", "ru")
    assert page.locator("#protocol li.current").text_content() == \
        r["steps"][k + 1]["sentence"]["ru"]
    assert page.evaluate("document.documentElement.lang") == "ru"
    assert errors == []
    page.close()


def test_sheets_page_of_gears_in_chromium(browser, tmp_path):
    """A gear scene's page shows its sheets too; switching the language redraws them."""
    path = write_page(solve_file(str(ROOT / "templates" / "planetary_two_row.toml")), tmp_path,
                      "gears")
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    errors: list[str] = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.goto(path.as_uri())
    page.wait_for_selector("body[data-ready='1']")
    page.click("#tab-sheets")
    assert page.is_visible("#s-svg") and page.is_visible("#tab-replay")
    first = page.locator("#s-svg text").all_text_contents()
    assert len(first) > 50
    other = "zh" if page.evaluate("document.documentElement.lang") != "zh" else "ru"
    page.select_option("#language", other)
    second = page.locator("#s-svg text").all_text_contents()
    assert second != first
    assert any(("\u4e00" <= c <= "\u9fff") if other == "zh" else ("а" <= c <= "я")
               for t in second for c in t)
    assert errors == []
    _shot(page, "html-gears-sheets.png", tmp_path)
    page.close()


def _open(browser, path):
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    errors: list[str] = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.on("request", lambda r: errors.append(f"request {r.url}")
            if not r.url.startswith(("file:", "data:")) else None)
    page.goto(path.as_uri())
    page.wait_for_selector("body[data-ready='1']")
    return page, errors


def _step_through(page, doc, rid: str, presses: int) -> None:
    """Select a replay, press "next" and check that exactly the steps' elements are shown."""
    index = next(i for i, r in enumerate(doc["replays"]) if r["id"] == rid)
    r = doc["replays"][index]
    page.select_option("#plan", str(index))
    for _ in range(presses):
        page.click("#next")
    assert page.get_attribute("#counter", "data-step") == str(presses + 1)
    assert page.locator("#protocol li.current").text_content() == \
        r["steps"][presses]["sentence"][doc["lang"]]
    lang = doc["lang"]
    shown = page.locator("#r-svg > *:not(.off)").count()
    assert shown == sum(_elements(p) for p in r["prims"][lang] if p["k"] <= presses)
    now = page.locator(f"#r-svg > [data-k='{presses}']").count()
    assert now == sum(_elements(p) for p in r["prims"][lang] if p["k"] == presses) > 0


def test_planetary_train_turns_in_chromium(browser, tmp_path):
    """The velocity plan of the train line by line; the slider turns the planets: each planet's
    group is translated to its centre on the carrier radius and turned by its ω·t."""
    study = solve_file(str(ROOT / "templates" / "planetary_single_row.toml"))
    path = write_page(study, tmp_path, "train")
    text = path.read_text(encoding="utf-8")
    m = re.search(r'<script type="application/json" id="data">(.*?)</script>', text, re.DOTALL)
    doc = json.loads(m.group(1).replace("<\\/", "</"))
    page, errors = _open(browser, path)
    _step_through(page, doc, "gears-velocity", 3)
    _shot(page, "html-gears-replay.png", tmp_path)
    page.click("#tab-anim")
    page.focus("#phi")
    for _ in range(40):
        page.keyboard.press("ArrowRight")
    assert page.get_attribute("#phi-out", "data-frame") == "40"
    res = study.solution.planetary
    a = doc["animation"]
    t = a["time"][40]
    a_w, mu = res.plan.a_w, a["panels"][0]["scale"]
    for j in range(res.spec.planets):
        g = page.locator(f"svg[data-panel='gears-train'] g[data-item='2-{j}']")
        mat = g.evaluate("e => { const m = e.transform.baseVal.consolidate().matrix;"
                         " return [m.a, m.b, m.e, m.f]; }")
        carrier = res.plan.omega["h"] * t + 2 * np.pi * j / res.spec.planets
        assert mat[2] == pytest.approx(a_w / mu * np.cos(carrier), abs=0.01)
        assert -mat[3] == pytest.approx(a_w / mu * np.sin(carrier), abs=0.01)
        spin = -np.arctan2(mat[1], mat[0])          # y down: counter-clockwise is negative
        want = res.plan.omega["2"] * t
        assert np.angle(np.exp(1j * (spin - want))) == pytest.approx(0.0, abs=1e-4)
    _shot(page, "html-gears-train.png", tmp_path)
    assert errors == []
    page.close()


def test_instant_centres_in_chromium(browser, four_bar, tmp_path):
    """Kennedy's construction replayed (each centre's lines, circle and chord appear with its
    sentence); the centres' panel follows the slider to the solver's centres."""
    from mechplan.construct.plans.centres import centres_at

    study, path, doc = four_bar
    page, errors = _open(browser, path)
    rid = next(r["id"] for r in doc["replays"] if r["plan"] == "centres")
    _step_through(page, doc, rid, 5)
    _shot(page, "html-centres-replay.png", tmp_path)
    page.click("#tab-anim")
    page.focus("#phi")
    for _ in range(25):
        page.keyboard.press("ArrowRight")
    sol = study.solution
    c, mech = sol.construction, sol.scene.mechanism
    phi = np.radians(doc["animation"]["phi_deg"][25])
    cs = centres_at(c, c.evaluate(np.array([phi])), mech)
    mu = sol.scales[Plan.POSITION]
    for key in ("01", "12", "13"):
        dot = page.locator(f"svg[data-panel='centres'] circle[data-point='{key}']")
        cx, cy = float(dot.get_attribute("cx")), float(dot.get_attribute("cy"))
        want = cs.point(key[0], key[1])[0] / mu
        assert (cx, -cy) == pytest.approx(tuple(want), abs=0.006)
    _shot(page, "html-centres-moving.png", tmp_path)
    assert errors == []
    page.close()
