"""Report, JSON, sheet and the profile DXF of a cam scene."""

from __future__ import annotations

import json
import math
from pathlib import Path

import ezdxf
import numpy as np
import pytest

from mechplan.cli import main
from mechplan.i18n import LANGUAGES
from mechplan.sheet.primitives import Circle, Polyline, Text
from mechplan.studies import solve_file, solve_text

from .scenes import cam_text

TEMPLATES = Path(__file__).resolve().parents[2] / "templates"


@pytest.fixture(scope="module")
def study():
    return solve_file(TEMPLATES / "cam_cycloidal.toml")


def test_report_in_every_language(study):
    for lang in LANGUAGES:
        text = study.report(lang)
        assert "r0" in text and "28" in text
    assert "28,385 мм" in study.report("ru")          # decimal comma and Russian unit
    assert "28.385 mm" in study.report("en")


def test_json_tables(study):
    doc = json.loads(json.dumps(study.to_json()))
    assert doc["kind"] == "cam"
    rows = doc["table"]
    assert len(rows) == 36 and rows[1]["phi"] == pytest.approx(math.radians(10))
    for r in rows:                                        # polar and Cartesian agree
        assert r["rho"] == pytest.approx(math.hypot(r["x"], r["y"]))
        assert math.atan2(r["y"], r["x"]) % (2 * math.pi) == pytest.approx(r["theta"])
    # the roller centre is one roller radius out from the working profile, along the radius at 0°
    assert rows[0]["y_pitch"] - rows[0]["y"] == pytest.approx(0.006)
    assert doc["profile"]["chord_error"] <= 1e-6
    assert doc["s_prime_s_zone"]["r0"] == pytest.approx(doc["base_radius"]["minimum"])


def test_sheet_draws_the_construction(study):
    sheets = study.sheets(None, None, "en", "cam")
    assert len(sheets) == 1
    prims = list(sheets[0].flat())
    circles = [p for p in prims if isinstance(p, Circle)]
    # the scale the sheet says it draws the cam at (m per paper mm)
    said = [p.string for p in prims if isinstance(p, Text) and p.string.startswith("μl = ")]
    mu = float(said[0].split()[2])
    assert 1e-3 / mu in (1.0, 2.0, 2.5, 4.0, 5.0, 10.0)   # a standard drawing scale n:1
    rollers = [c for c in circles if c.radius == pytest.approx(0.006 / mu)]   # rr = 6 mm
    assert len(rollers) == 24                             # one per 15° ray
    base = [c for c in circles if c.radius == pytest.approx(study.design.geometry.r0 / mu)]
    assert base                                           # the base circle at the same scale
    closed = [p for p in prims if isinstance(p, Polyline) and p.closed and len(p.points) > 400]
    assert closed                                          # the working profile


def test_draw_writes_the_profile_dxf(tmp_path):
    assert main(["draw", str(TEMPLATES / "cam_cycloidal.toml"), "-o", str(tmp_path),
                 "--format", "dxf"]) == 0
    doc = ezdxf.readfile(tmp_path / "cam_cycloidal-profile.dxf")
    entities = list(doc.modelspace())
    assert len(entities) == 1 and entities[0].dxftype() == "LWPOLYLINE" and entities[0].closed
    assert doc.units == 4
    pts = np.array([(p[0], p[1]) for p in entities[0].get_points()])
    st = solve_file(TEMPLATES / "cam_cycloidal.toml")
    assert np.allclose(pts, st.design.profile_points * 1e3, atol=1e-9)
    assert np.min(np.hypot(*pts.T)) == pytest.approx(28.385087 - 6.0, abs=1e-5)   # r0 − rr
    assert (tmp_path / "cam_cycloidal.dxf").exists()


def test_clockwise_cam_is_the_mirror_image():
    ccw = solve_text(cam_text(offset="4 mm"), "a.toml").design
    cw = solve_text(cam_text(offset="4 mm", sense="cw"), "b.toml").design
    assert cw.geometry.r0 == pytest.approx(ccw.geometry.r0)
    assert np.allclose(cw.table.profile * [-1, 1], ccw.table.profile)


def test_table_laws_in_a_scene_follow_the_law_they_tabulate():
    xs = np.linspace(0, 1, 61)
    s_mm = 20 * (xs - np.sin(2 * np.pi * xs) / (2 * np.pi))
    table = ", ".join(f'"{float(v)!r} mm"' for v in s_mm)
    shape = ", ".join(repr(float(v)) for v in np.sin(2 * np.pi * np.linspace(0, 1, 121)))
    text = cam_text().replace('law = "cycloidal" }', f'law = "table", s = [{table}] }}', 1)
    text = text.replace('law = "cycloidal" }', f'law = "table", a = [{shape}] }}', 1)
    exact = solve_text(cam_text(), "a.toml").design
    tab = solve_text(text, "t.toml").design
    assert tab.r0_min == pytest.approx(exact.r0_min, rel=2e-4)
    assert np.max(np.abs(tab.dense.s - exact.dense.s)) < 2e-6          # m
