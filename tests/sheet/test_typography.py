"""Real sub- and superscripts in DXF, SVG and PDF; decimal marks and angles per language."""

from __future__ import annotations

import io
import re

import ezdxf
import pytest
from scenes import ROOT

from mechplan.drafting.typography import glyph_runs, mtext, plain, runs
from mechplan.render import dxf as dxf_backend
from mechplan.render import mpl as mpl_backend
from mechplan.render import svg as svg_backend
from mechplan.scene import load_scene
from mechplan.sheet.compose import compose, scale_field
from mechplan.sheet.primitives import Sheet, Text
from mechplan.solve import solve
from mechplan.submission.dxf import clean_text


def test_runs_raise_and_lower_the_marked_parts():
    assert runs("a^n_CB") == [("a", 0), ("n", 1), ("CB", -1)]
    assert runs("v_B = ω1·l_AB") == [("v", 0), ("B", -1), (" = ω1·l", 0), ("AB", -1)]
    assert runs("pb") == [("pb", 0)] and runs("x ^ y") == [("x ^ y", 0)]
    assert plain("R^t_24") == "Rt24"
    assert mtext("a^n_CB") == "a\\Sn^CB;" and mtext("ω^2") == "ω\\S2^;"
    assert mtext("v_B") == "v\\S^B;" and mtext("a{b}") == "a\\{b\\}"


def _one(text: str) -> Sheet:
    return Sheet(60.0, 30.0, (Text((10.0, 10.0), text, 5.0),), language="en", name="t")


def test_dxf_writes_a_stacked_mtext_that_readers_take_apart():
    doc = ezdxf.read(io.StringIO(dxf_backend.to_bytes(_one("a^n_CB")).decode("utf-8")))
    (m,) = [e for e in doc.modelspace() if e.dxftype() == "MTEXT"]
    assert m.text == "a\\Sn^CB;" and m.dxf.char_height == 5.0
    assert clean_text(m.text, mtext=True) == "anCB"         # the checker's reader
    assert not [e for e in doc.modelspace() if e.dxftype() == "TEXT"]


def test_dxf_stacks_the_unicode_exponents_librecad_fonts_lack():
    """"1,1×10⁻¹⁶" (the number writers' ×10ⁿ form): no LibreCAD font has ⁻¹⁶, so the DXF writes
    the exponent as a raised stack, in a style whose font has every other glyph."""
    from mechplan.render.librecad import stroke_fonts

    assert glyph_runs("1,1×10⁻¹⁶") == [("1,1×10", 0), ("-16", 1)]
    assert glyph_runs("M_b⁰ S₄") == [("M", 0), ("b", -1), ("0", 1), (" S", 0), ("4", -1)]
    assert mtext("1,1×10⁻¹⁶") == "1,1×10\\S-16^;"
    doc = ezdxf.read(io.StringIO(dxf_backend.to_bytes(_one("δ = 1,1×10⁻¹⁶")).decode("utf-8")))
    (m,) = [e for e in doc.modelspace() if e.dxftype() == "MTEXT"]
    assert m.text == "δ = 1,1×10\\S-16^;"
    assert stroke_fonts()[m.dxf.style].has("δ = 1,1×10-16")
    assert not [e for e in doc.modelspace() if e.dxftype() == "TEXT"]


def test_svg_shifts_smaller_tspans_off_the_baseline_and_back():
    svg = svg_backend.to_svg(_one("a^n_CB x"))
    spans = re.findall(r"<tspan([^>]*)>([^<]*)</tspan>", svg)
    assert [s[1] for s in spans] == ["a", "n", "CB", " x"]
    dy = [float(re.search(r'dy="([-0-9.]+)"', a).group(1)) if "dy=" in a else 0.0 for a, _ in spans]
    # up 0.45 h (SVG y runs down), then down to 0.25 h below, then back to the baseline
    assert dy == pytest.approx([0.0, -2.25, 3.5, -1.25])
    sizes = [a for a, t in spans if t in ("n", "CB")]
    assert all("font-size" in a for a in sizes)


def test_pdf_draws_the_superscript_small_and_raised():
    pdfplumber = pytest.importorskip("pdfplumber")
    with pdfplumber.open(io.BytesIO(mpl_backend.to_bytes(_one("a^n_CB"), "pdf"))) as pdf:
        chars = {c["text"]: c for c in pdf.pages[0].chars}
    a, n, c = chars["a"], chars["n"], chars["C"]
    assert n["size"] == pytest.approx(0.7 * a["size"], rel=0.02)
    assert n["bottom"] < a["bottom"] - 1.0            # pdfplumber's y runs down: n is higher
    assert c["bottom"] > a["bottom"] + 0.5            # CB is lower
    assert a["x1"] <= n["x0"] + 0.1 and n["x1"] <= c["x0"] + 0.1


def test_decimal_marks_and_angles_follow_the_language():
    assert scale_field(0.0025, "ru") == "1:2,5" and scale_field(0.0025, "en") == "1:2.5"
    sol = solve(load_scene(ROOT / "templates" / "slider_crank.toml"))
    comp = compose(sol, lang="ru")
    texts = [p.string for s in comp.sheets for p in s.flat() if isinstance(p, Text)]
    assert not [t for t in texts if re.search(r"\d\.\d", t)]
    angles = [float(m.replace(",", ".")) for t in texts for m in re.findall(r"φ = (-?[0-9,]+)°", t)]
    assert angles and all(0.0 <= a < 360.0 for a in angles)
