"""The tradition's names of a link's absolute centre (МЦС, tâm vận tốc tức thời, 绝对瞬心, "P2")
are read as I0j and graded; a МЦС without its link is the coupler's where that is unique. The
acceleration pole labelled on the centres' drawing (Q2) is graded against its definition."""

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


@pytest.fixture(scope="module")
def four_bar_ru(tmp_path_factory):
    scene = load_scene(f"{TEMPLATES}/four_bar.toml")          # [centres] links = ["2"]
    comp = compose(solve(scene), "A3", "iso", "ru", name="four_bar")
    i = next(n for n, pl in enumerate(comp.placements) if any(p.name == "centres" for p, _ in pl))
    path = tmp_path_factory.mktemp("q") / "panel.dxf"
    path.write_bytes(to_bytes(comp.sheets[i]))
    return scene, path


def _pole_exact(scene, deg):
    """Q of the coupler by the definition: the point whose acceleration a_B + ε×r − ω²r is 0,
    solved as a 2 × 2 linear system (not the closed form under test)."""
    sol = solve(scene, at_deg=[deg])
    c, ev = sol.construction, sol.ev
    a_b, r_b = ev[c.acceleration_image("B")][0], ev[c.position("B")][0]
    w, e = float(ev[c.omega("2")][0]), float(ev[c.epsilon("2")][0])
    m = np.array([[-w * w, -e], [e, -w * w]])
    return r_b + np.linalg.solve(m, -a_b)


def test_the_acceleration_pole_is_graded_and_a_moved_one_caught(four_bar_ru, tmp_path):
    scene, path = four_bar_ru
    report = check(scene, path, Options())
    rows = {c.label: c for c in report.centres}
    assert rows["Q2"].verdict == OK and rows["Q2"].error == pytest.approx(0.0, abs=1e-6)
    # the drawn pole against the definition, through the drawing's own pins (I01, I03)
    phi = report.centres_phi if report.centres_phi is not None else report.phi_deg
    q = _pole_exact(scene, phi)
    sol = solve(scene, at_deg=[phi])
    a, d = (sol.ev[sol.construction.position(p)][0] for p in "AD")
    pa, pd = np.array(rows["I01"].at_mm), np.array(rows["I03"].at_mm)
    mu = float(np.hypot(*(d - a))) / float(np.hypot(*(pd - pa)))
    assert np.allclose(pa + (q - a) / mu, rows["Q2"].at_mm, atol=1e-6)
    doc = ezdxf.readfile(path)
    msp = doc.modelspace()
    (text,) = [t for t in msp.query("TEXT") if t.dxf.text == "Q2"]
    circle = min((e for e in msp.query("CIRCLE") if e.dxf.radius < 1.5),
                 key=lambda e: math.dist(tuple(e.dxf.center)[:2], rows["Q2"].at_mm))
    for ent, key in ((circle, "center"), (text, "insert"), (text, "align_point")):
        if ent.dxf.hasattr(key):
            x, y = tuple(ent.dxf.get(key))[:2]
            ent.dxf.set(key, (x + 3.0, y + 4.0))
    doc.saveas(tmp_path / "moved_q.dxf")
    moved = check(scene, tmp_path / "moved_q.dxf", Options())
    rows = {c.label: c for c in moved.centres}
    assert rows["Q2"].verdict == WRONG and rows["Q2"].error == pytest.approx(5.0, abs=1e-6)
    assert all(c.verdict == OK for n, c in rows.items() if n != "Q2")
    for lang in ("en", "ru", "vi", "zh"):
        assert "Q = A +" in moved.text(lang)
