"""Sweeps: summaries against closed forms and against a full solve of each variant; resume; plot."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pyarrow.parquet as pq
import pytest

from mechplan.batch.keys import with_values
from mechplan.batch.plan import make_plan, parse_vary
from mechplan.batch.sweep import evaluate_chunk, run_sweep
from mechplan.cli import main
from mechplan.scene import parse_scene
from mechplan.scene.document import parse_toml
from mechplan.solve import solve

TEMPLATES = Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates"
SLIDER = TEMPLATES / "slider_crank.toml"
FOUR_BAR = TEMPLATES / "four_bar.toml"


def test_four_bar_min_transmission_angle_is_the_closed_form(tmp_path):
    axes = [parse_vary("links.1.lengths.AB=60mm..100mm:5"),
            parse_vary("links.2.lengths.BC=200mm..260mm:4")]
    result = run_sweep(FOUR_BAR, axes, tmp_path, workers=1, progress=False)
    table = pq.read_table(result.parquet).to_pylist()
    assert len(table) == 20 and [r["variant"] for r in table] == list(range(20))
    c, d = 180.0, 250.0
    for row in table:
        a, b = row["links.1.lengths.AB"], row["links.2.lengths.BC"]
        # transmission angle at the two crank positions along the frame (law of cosines)
        acute = [math.degrees(math.acos(abs((b * b + c * c - (d + s * a) ** 2) / (2 * b * c))))
                 for s in (-1.0, 1.0)]
        assert row["min_gamma_2_3"] == pytest.approx(min(acute), abs=1e-7)
        assert row["unbuilt"] == 0 and row["error"] == ""
        assert row["max_v_B"] == pytest.approx(a / 1000 * 10.0, rel=1e-12)   # ω1 = 10 rad/s


def test_slider_crank_extremes_are_the_closed_form():
    axes = [parse_vary("links.1.lengths.OA=80mm..120mm:3"),
            parse_vary("drive.speed=1000rpm..2000rpm:2")]
    plan = make_plan(SLIDER.read_text(encoding="utf-8"), str(SLIDER), axes, positions=360)
    _, cols, _ = evaluate_chunk(plan, 0, plan.size)
    theta = np.radians(np.arange(360.0))
    for k in range(plan.size):
        r, omega = cols["links.1.lengths.OA"][k] / 1000, cols["drive.speed"][k] * math.pi / 30
        s, co, l = r * np.sin(theta), r * np.cos(theta), 0.4
        root = np.sqrt(l * l - s * s)
        v = omega * np.abs(-s - s * co / root)
        a = omega ** 2 * np.abs(-co - (co * co - s * s) / root - s * s * co * co / root ** 3)
        assert cols["max_v_B"][k] == pytest.approx(v.max(), rel=1e-12)
        assert cols["max_a_B"][k] == pytest.approx(a.max(), rel=1e-12)
        assert cols["min_gamma_2_3"][k] == pytest.approx(
            90.0 - math.degrees(math.asin(r / l)), abs=1e-9)   # rod ⊥ crank at φ = 90°


def test_prepared_steps_equal_a_full_solve_of_each_variant():
    axes = [parse_vary("links.1.lengths.OA=80mm..120mm:3"),
            parse_vary("links.2.lengths.AB=300mm..420mm:3"),
            parse_vary("links.2.mass=2kg..6kg:2")]
    text = SLIDER.read_text(encoding="utf-8")
    plan = make_plan(text, str(SLIDER), axes, positions=36)
    assert plan.builds < plan.size                     # not one build per variant
    _, cols, _ = evaluate_chunk(plan, 0, plan.size)
    # a chunk sent with only the prepared steps it uses gives the same numbers
    small = plan.restricted(5, 11)
    assert sum(len(t) for t in small.tables.values()) < sum(len(t) for t in plan.tables.values())
    _, part, _ = evaluate_chunk(small, 5, 11)
    for name, column in part.items():
        assert list(column) == list(cols[name][5:11]), name
    doc = parse_toml(text, "t")
    grid = np.unravel_index(np.arange(plan.size), plan.shape)
    for k in range(plan.size):
        values = {ax.key: ax.scene_value(int(g[k])) for ax, g in zip(axes, grid, strict=True)}
        import tomli_w

        sol = solve(parse_scene(tomli_w.dumps(with_values(doc, values)), "v"),
                    at_deg=list(np.arange(36) * 10.0))
        c, ev = sol.construction, sol.ev
        a_s2 = ev[c.acceleration_image("S2")]
        assert cols["max_a_S2"][k] == pytest.approx(np.hypot(*a_s2.T).max(), rel=1e-12)
        assert cols["max_epsilon_2"][k] == pytest.approx(np.abs(ev[c.epsilon("2")]).max(),
                                                         rel=1e-12)
        assert cols["max_M_b"][k] == pytest.approx(np.abs(ev[c.results["M_b"]]).max(), rel=1e-12)


def test_unbuildable_positions_are_counted(tmp_path):
    axes = [parse_vary("links.1.lengths.OA=300mm..500mm:3")]
    result = run_sweep(SLIDER, axes, tmp_path, positions=36, workers=1, progress=False)
    rows = pq.read_table(result.parquet).to_pylist()
    # B is unreachable where |OA sin φ| > AB, singular (rod ⊥ guide) where it equals AB
    for row, r, n in zip(rows, (0.3, 0.4, 0.5), (0, 2, 14), strict=True):
        expected = sum(abs(r * math.sin(math.radians(10 * k))) >= 0.4 - 1e-12 for k in range(36))
        assert row["unbuilt"] == expected == n
        assert math.isfinite(row["max_v_B"])


def test_resume_plot_and_cli(tmp_path, capsys):
    args = ["sweep", str(SLIDER), "--vary", "links.1.lengths.OA=80mm..120mm:4", "--vary",
            "links.2.lengths.AB=300mm..420mm:5", "--positions", "72", "--chunk", "6", "-o",
            str(tmp_path), "-j", "1", "--plot", "max_a_B", "--no-progress"]
    assert main(args) == 0
    first = pq.read_table(tmp_path / "summary.parquet")
    assert "20 variants in 4 chunks (0 complete already)" in capsys.readouterr().out
    assert (tmp_path / "max_a_B.png").read_bytes()[:4] == b"\x89PNG"
    assert main(args) == 0
    assert "(4 complete already)" in capsys.readouterr().out
    assert pq.read_table(tmp_path / "summary.parquet").equals(first)
    csv_lines = (tmp_path / "summary.csv").read_text(encoding="utf-8").splitlines()
    assert len(csv_lines) == 21 and "max_a_B" in csv_lines[0]
    assert main([*args[:-3], "--plot", "max_nothing"]) == 2
    assert "must be one of" in capsys.readouterr().err
