"""Same geometry by registration: one similarity (turn, scale, mirror, move) found between two
segment sets, with the lines it matches and the residual as the evidence."""

from __future__ import annotations

import math

import ezdxf
import numpy as np
import pytest
from ezdxf.math import Matrix44
from hypothesis import given, settings
from hypothesis import strategies as st

from mechplan.geom.registration import fit_similarity, register
from mechplan.lms.samework import fingerprint, same_work
from mechplan.submission.read import read_submission


def _carry(seg, angle_deg, scale, mirrored, shift):
    """Segments carried by a similarity written out here: mirror y, turn, scale, move."""
    pts = seg.reshape(-1, 2).copy()
    if mirrored:
        pts[:, 1] = -pts[:, 1]
    c, s = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    pts = scale * np.stack([c * pts[:, 0] - s * pts[:, 1], s * pts[:, 0] + c * pts[:, 1]], 1)
    return (pts + np.asarray(shift)).reshape(seg.shape)


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 10_000), angle=st.floats(-179.0, 179.0), scale=st.floats(0.2, 5.0),
       mirrored=st.booleans(), dx=st.floats(-500, 500), dy=st.floats(-500, 500))
def test_a_carried_copy_is_registered_with_its_transform(seed, angle, scale, mirrored, dx, dy):
    rng = np.random.default_rng(seed)
    seg = rng.uniform(0, 200, size=(30, 2, 2))
    copy = _carry(seg, angle, scale, mirrored, (dx, dy))
    order = rng.permutation(len(copy))               # another order, some drawn backwards
    copy = copy[order]
    copy[::3] = copy[::3, ::-1]
    found = register(seg, copy)
    assert found is not None and found.matched == 30
    t = found.transform
    assert t.mirrored == mirrored
    assert t.scale == pytest.approx(scale, rel=1e-9)
    assert math.remainder(t.angle_deg - angle, 360.0) == pytest.approx(0.0, abs=1e-7)
    assert t.shift == pytest.approx((dx, dy), abs=1e-6 * (1 + abs(dx) + abs(dy)))
    assert found.relative < 1e-10


def test_least_squares_fit_against_a_closed_form():
    # three points and their image under a known similarity plus a known symmetric error: the
    # Umeyama fit of a pure turn+scale recovers it exactly when the error is zero
    x = np.array([[0.0, 0.0], [2.0, 0.0], [0.0, 1.0]])
    y = _carry(x, 30.0, 2.0, False, (5.0, -1.0))
    t = fit_similarity(x, y, False)
    assert (t.scale, t.angle_deg) == pytest.approx((2.0, 30.0))
    assert t.apply(x) == pytest.approx(y)


def test_extra_and_missing_lines_still_match_noise_does_not():
    rng = np.random.default_rng(7)
    seg = rng.uniform(0, 200, size=(60, 2, 2))
    copy = _carry(seg, 41.0, 0.8, True, (10.0, 3.0))
    edited = np.concatenate([copy[3:], rng.uniform(0, 200, size=(5, 2, 2))])   # −3, +5 lines
    found = register(seg, edited)
    assert found is not None and found.matched == 57 and found.relative < 1e-10
    redrawn = copy + rng.normal(0, 0.3, size=copy.shape)      # drawn again by hand, ±0.3 mm
    again = register(seg, redrawn)
    assert again is None or again.relative > 1e-4


@pytest.fixture(scope="module")
def sheets(small_class, tmp_path_factory):
    _, variants, _ = small_class
    root = tmp_path_factory.mktemp("geometry")
    own = variants / "v1" / "slider_crank.dxf"
    doc = ezdxf.readfile(own)
    m = Matrix44.chain(Matrix44.scale(1.25, -1.25, 1), Matrix44.z_rotate(math.radians(73)),
                       Matrix44.translate(37, -12, 0))
    for e in doc.modelspace():
        e.transform(m)
    doc.saveas(root / "copy.dxf")
    return {"own": own, "copy": root / "copy.dxf", "other": variants / "v2" / "slider_crank.dxf"}


def test_a_turned_scaled_mirrored_sheet_is_found_another_variant_is_not(sheets):
    prints = [fingerprint(name, path.read_bytes(), read_submission(path))
              for name, path in sheets.items()]
    same = same_work(prints)
    assert [(s.first, s.second, s.evidence) for s in same] == [("own", "copy", "same geometry")]
    detail = same[0].detail
    lines = len(read_submission(sheets["own"]).lines)
    assert f"{lines} of {lines} lines" in detail
    assert "turned 73°" in detail and "scaled 1.25" in detail and "mirrored" in detail
    assert "moved (37, -12) mm" in detail


def test_the_evidence_is_said_in_the_instructors_language(sheets):
    prints = [fingerprint(name, sheets[name].read_bytes(), read_submission(sheets[name]))
              for name in ("own", "copy")]
    detail = same_work(prints, "ru")[0].detail
    assert "поворот 73°" in detail and "зеркально" in detail
