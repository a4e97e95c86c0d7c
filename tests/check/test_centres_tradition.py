"""The tradition's names of a link's absolute centre (МЦС, tâm vận tốc tức thời, 绝对瞬心, "P2")
are read as I0j and graded; a МЦС without its link is the coupler's where that is unique."""

from __future__ import annotations

import math

import ezdxf
import numpy as np
import pytest

from mechplan.check import Options, check
from mechplan.check.report import OK, WRONG
from mechplan.render.dxf import to_bytes
from mechplan.scene import load_scene
from mechplan.sheet.compose import compose
from mechplan.solve import solve
from mechplan.submission.centre_marks import COUPLER, read_centre

TEMPLATES = "src/mechplan/templates"
FOUR = ("0", "1", "2", "3")


@pytest.mark.parametrize("text, j", [
    ("МЦС", COUPLER), ("МЦС2", "2"), ("МЦС₂", "2"), ("МЦС звена 2", "2"), ("мцс 3", "3"),
    ("tâm vận tốc tức thời khâu 2", "2"), ("TVTTT 2", "2"), ("绝对瞬心2", "2"),
    ("МЦС P03", "3"), ("МЦС (P02)", "2"),
])
def test_absolute_centre_names_are_read(text, j):
    name = read_centre(text, FOUR)
    assert name is not None and (name.i, name.j) == ("0", j)


def test_a_letter_with_one_link_names_it_on_a_drawing_only():
    assert read_centre("P2", FOUR) is None                  # a table's P2 may be a force
    name = read_centre("P₂", FOUR, single=True)
    assert name is not None and (name.i, name.j) == ("0", "2")
    assert read_centre("МЦС5", FOUR) is None and read_centre("P0", FOUR, single=True) is None


def _meet(a, b, c, d):
    m = np.array([[b[0] - a[0], c[0] - d[0]], [b[1] - a[1], c[1] - d[1]]], dtype=float)
    t = np.linalg.solve(m, np.asarray(c, float) - np.asarray(a, float))[0]
    return np.asarray(a, float) + t * (np.asarray(b, float) - np.asarray(a, float))


@pytest.fixture(scope="module")
def ru_panel(tmp_path_factory):
    scene = load_scene(f"{TEMPLATES}/slider_crank.toml")     # its I02 is drawn in the view
    comp = compose(solve(scene), "A3", "iso", "ru", name="slider_crank")
    i = next(n for n, pl in enumerate(comp.placements) if any(p.name == "centres" for p, _ in pl))
    path = tmp_path_factory.mktemp("mcs") / "panel.dxf"
    path.write_bytes(to_bytes(comp.sheets[i]))
    return scene, path


def _renamed(path, tmp_path, old, new, shift=(0.0, 0.0)):
    doc = ezdxf.readfile(path)
    msp = doc.modelspace()
    texts = [t for t in msp.query("TEXT") if t.dxf.text == old]
    circles = [e for e in msp.query("CIRCLE") if e.dxf.radius < 1.5]
    # the drawn label (beside its circle), not the table's row
    label = min(texts, key=lambda t: min(math.dist(tuple(t.dxf.insert)[:2],
                                                   tuple(c.dxf.center)[:2]) for c in circles))
    label.dxf.text = new
    if shift != (0.0, 0.0):
        circle = min(circles, key=lambda c: math.dist(tuple(c.dxf.center)[:2],
                                                      tuple(label.dxf.insert)[:2]))
        cx, cy = tuple(circle.dxf.center)[:2]
        circle.dxf.center = (cx + shift[0], cy + shift[1])
        x, y = tuple(label.dxf.insert)[:2]
        label.dxf.insert = (x + shift[0], y + shift[1])
        if label.dxf.hasattr("align_point"):
            ax, ay = tuple(label.dxf.align_point)[:2]
            label.dxf.align_point = (ax + shift[0], ay + shift[1])
    for t in texts:                                  # the table keeps its own name
        if t is not label:
            t.dxf.text = old
    out = tmp_path / f"{abs(hash((old, new, shift)))}.dxf"
    doc.saveas(out)
    return out


@pytest.mark.parametrize("new", ["МЦС", "МЦС2", "P₂", "МЦС звена 2"])
def test_the_couplers_centre_named_mcs_is_graded_as_i02(ru_panel, tmp_path, new):
    scene, path = ru_panel
    report = check(scene, _renamed(path, tmp_path, "P02", new), Options())
    rows = {c.label: c for c in report.centres}
    assert rows["I02"].verdict == OK and rows["I02"].written == new
    assert all(c.verdict == OK for c in rows.values())
    assert report.summary()["missing"] == 0


def test_a_moved_mcs_is_caught(ru_panel, tmp_path):
    scene, path = ru_panel
    report = check(scene, _renamed(path, tmp_path, "P02", "МЦС", (3.0, 4.0)), Options())
    rows = {c.label: c for c in report.centres}
    assert rows["I02"].verdict == WRONG
    assert rows["I02"].error == pytest.approx(5.0, abs=1e-6)
