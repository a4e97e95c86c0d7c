"""The instant centres through the scene, the CLI's JSON and report, and their documentation."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

from mechplan.errors import SceneError
from mechplan.i18n import LANGUAGES
from mechplan.scene import parse_scene
from mechplan.studies import solve_text

ROOT = Path(__file__).resolve().parents[2]
DOC = (ROOT / "docs" / "centres.md").read_text(encoding="utf-8")


def _example() -> str:
    m = re.search(r"<!-- example: scene centres -->\s*```\w*\n(.*?)```", DOC, re.DOTALL)
    assert m
    return m.group(1)


def _four_bar() -> str:
    """The four-bar template without its own [centres] table."""
    text = (ROOT / "templates" / "four_bar.toml").read_text(encoding="utf-8")
    return text[:text.index("[centres]")] if "[centres]" in text else text


def _table_keys(heading_row: str, after: str) -> set[str]:
    """The first column of the table that follows ``after`` in docs/centres.md."""
    part = DOC[DOC.index(after):]
    rows = part[part.index(heading_row):].split("\n\n")[0].splitlines()[2:]
    return {re.match(r"\| `([^`]+)`", r).group(1) for r in rows}


@pytest.fixture(scope="module")
def doc() -> dict:
    study = solve_text(_example(), "centres.toml")
    return study.to_json()["centres"]


def test_the_documented_keys_are_the_keys_of_the_json(doc):
    top = _table_keys("| key | value |", '## JSON: the `"centres"` object')
    assert set(doc) == top
    per = _table_keys("| key | value |", "Each object of `positions`:")
    assert set(doc["positions"][0]) == per
    centre_keys = {"at_infinity", "r", "direction", "indeterminate", "lines", "sine",
                   "conditioning", "error_estimate"}
    for entry in doc["positions"][0]["centres"].values():
        assert set(entry) <= centre_keys
        assert ("r" in entry) != ("direction" in entry)
    assert set(doc["centrodes"]["2"]) == {"phi_deg", "fixed", "moving"}


def test_the_example_gives_the_printed_answer(doc):
    # Khurmi & Gupta Example 6.1: ω_BC ≈ 6.3 rad/s; the centres agree with the velocity plan
    pos = doc["positions"][0]
    assert abs(pos["omega"]["2"]) == pytest.approx(6.3, rel=0.02)
    assert doc["agreement_max"] < 1e-12
    assert doc["order"] == ["I01", "I03", "I12", "I23", "I02", "I13"]
    assert pos["centres"]["I02"]["lines"] == [["I01", "I12"], ["I03", "I23"]]
    assert pos["acceleration_pole"]["2"] is not None
    assert pos["inflection_circle"]["2"]["radius"] > 0
    assert len(doc["centrodes"]["2"]["fixed"]) == 360


def test_centres_at_infinity_are_directions_in_the_json():
    text = (ROOT / "templates" / "quick_return.toml").read_text(encoding="utf-8")
    study = solve_text(text + '\n[analysis]\nplans = ["position", "velocity", "centres"]\n',
                       "qr.toml")
    doc = study.to_json()["centres"]
    for pos in doc["positions"]:
        i23 = pos["centres"]["I23"]
        assert i23["at_infinity"] is True and "r" not in i23
        assert sum(x * x for x in i23["direction"]) == pytest.approx(1.0)


@pytest.mark.parametrize("lang", LANGUAGES)
def test_the_report_says_the_centres_in_every_language(lang):
    study = solve_text(_example(), "centres.toml")
    text = study.report(lang)
    sym = "I" if lang == "en" else "P"
    assert f"{sym}13" in text and f"{sym}02" in text
    assert "ω2 = ω1 · " in text
    assert "{" not in text.split("Instant centres")[-1]


def test_the_cli_prints_the_centres(tmp_path):
    scene = tmp_path / "k.toml"
    scene.write_text(_example(), encoding="utf-8")
    out = subprocess.run([sys.executable, "-m", "mechplan.cli", "solve", str(scene), "--json"],
                         capture_output=True, text=True, check=True).stdout
    assert json.loads(out)["centres"]["count"] == 6


def test_no_centres_unless_asked():
    text = _four_bar()
    study = solve_text(text, "four_bar.toml")
    assert "centres" not in study.to_json()
    assert "centres" not in study.solution.extras


@pytest.mark.parametrize("table, key", [
    ('[centres]\nlinks = ["7"]\n', "centres.links"),
    ('[centres]\nlinks = ["0"]\n', "centres.links"),
    ('[centres]\npositions = 2\n', "centres.positions"),
    ('[centres]\ninflection = "yes"\n', "centres.inflection"),
    ('[centres]\ncentrodes = true\n', "centres.centrodes"),
    ('[analysis]\nplans = ["centers", "velocity", "centroids"]\n', "analysis.plans"),
])
def test_scene_errors_name_the_key(table, key):
    text = _four_bar() + "\n" + table
    with pytest.raises(SceneError) as err:
        parse_scene(text, "four_bar.toml")
    assert err.value.key == key
    assert "four_bar.toml" in str(err.value)


def test_the_aliases_spell_centres():
    text = _four_bar()
    scene = parse_scene(text + '\n[analysis]\nplans = ["position", "instant_centres"]\n')
    assert scene.plans == ("position", "centres")
    scene = parse_scene(text + '\n[centres]\nlinks = [2]\n')
    assert "centres" in scene.plans and scene.centres.links == ("2",)
