"""The examples of docs/reference.md and docs/api.md, run as printed, checked independently."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

import mechplan

ROOT = Path(__file__).resolve().parents[2]
REFERENCE = (ROOT / "docs" / "reference.md").read_text(encoding="utf-8")
API = (ROOT / "docs" / "api.md").read_text(encoding="utf-8")
W1 = 1500 * 2 * math.pi / 60


def example(text: str, name: str) -> str:
    m = re.search(r"<!-- example: " + re.escape(name) + r" -->\s*```\w*\n(.*?)```", text, re.DOTALL)
    assert m, f"example {name!r} is missing"
    return m.group(1)


def rot90(u: np.ndarray) -> np.ndarray:
    return np.stack([-u[:, 1], u[:, 0]], axis=1)


def test_every_load_type_as_documented_obeys_virtual_power() -> None:
    m = mechplan.loads(example(REFERENCE, "scene loads"), "loads.toml")
    sol = m.solve()
    assert sol.forces is not None
    v, r, w = sol.v, sol.r, sol.omega
    power = np.zeros(sol.positions)
    dot = lambda f, vel: np.sum(f * vel, axis=1)
    power += dot(np.array([0.0, -200.0]), v["S2"])                  # vector
    power += dot(np.array([0.0, 150.0]), v["A"])                     # magnitude, angle 90°
    to_o = -r["S2"] / np.linalg.norm(r["S2"], axis=1)[:, None]
    power += dot(50.0 * to_o, v["S2"])                               # towards O
    gas = 0.5e6 * math.pi * 0.08**2 / 4
    power += dot(np.array([-gas, 0.0]), v["B"])                      # pressure towards O (−x)
    power += 15.0 * w["2"]                                           # moment, ccw +
    s = r["B"][:, 0]                                                 # displacement from O along x
    table = np.interp(s, [0.3, 0.4, 0.5], [0.0, 500.0, 1000.0])
    power += -table * v["B"][:, 0]                                   # towards O
    power += -4.0 * dot(sol.a["S2"], v["S2"]) - 0.06 * sol.epsilon["2"] * w["2"]
    power += -3.0 * dot(sol.a["B"], v["B"])
    np.testing.assert_allclose(sol.forces.M_b, -power / W1, rtol=1e-9, atol=1e-9)


def test_the_link_frame_as_documented() -> None:
    m = mechplan.loads(example(REFERENCE, "scene link-frame"), "frame.toml")
    sol = m.solve()
    a, b = sol.r["A"], sol.r["B"]
    u = (b - a) / np.linalg.norm(b - a, axis=1)[:, None]
    np.testing.assert_allclose(sol.r["E"], a + 0.060 * u + 0.025 * rot90(u), atol=1e-12)
    np.testing.assert_allclose(sol.r["K"], b + np.array([0.0, -0.030]), atol=1e-12)


@pytest.mark.parametrize("name, suffix, at", [("submission toml", ".toml", None),
                                              ("submission csv", ".csv", 30.0)])
def test_the_submission_examples_pass(tmp_path: Path, name: str, suffix: str, at) -> None:
    path = tmp_path / f"submission{suffix}"
    path.write_text(example(REFERENCE, name), encoding="utf-8")
    report = mechplan.check(ROOT / "templates" / "slider_crank.toml", path, at_deg=at)
    assert report.passed
    assert report.phi_deg == pytest.approx(30.0)
    checked = [s.name for p in report.plans for s in p.segments]
    assert {"pa", "pb", "ab"} <= set(checked)


def test_the_api_example_runs_as_printed(tmp_path: Path, monkeypatch, capsys) -> None:
    from mechplan.cli import main

    monkeypatch.chdir(tmp_path)
    assert main(["new", "slider_crank"]) == 0
    capsys.readouterr()
    exec(compile(example(API, "python"), "docs/api.md", "exec"), {})   # noqa: S102
    out = capsys.readouterr().out
    assert out.split() == example(API, "output").split()
