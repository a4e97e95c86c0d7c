"""Labels and quantity names in the four notations read as the construction's own."""

from __future__ import annotations

import pytest

from mechplan.check.labels import label_book
from mechplan.model.plans import Plan
from mechplan.scene import load_scene
from mechplan.submission import notation
from mechplan.submission.dxf import clean_text
from mechplan.submission.labels import LabelBook, mu_plan
from mechplan.submission.written import is_angle_name, label_key

from .sheets import TEMPLATES, solved

V_ENGINE = TEMPLATES / "v_engine.toml"


@pytest.mark.parametrize("written, key", [
    ("b′", "b'"), ("b'", "b'"), ("B’", "b'"), ("n_{CB}", "ncb"), ("nCB", "ncb"), ("n_cb", "ncb"),
    ("s₂", "s2"), ("π′", "π'"), ("Π", "π"), (" k ", "k"),
])
def test_label_key(written: str, key: str) -> None:
    assert label_key(written) == key


@pytest.mark.parametrize("raw, mtext, plain", [
    (r"{\fArial|b1|i0;b\H0.7x;\S^1;}", True, "b1"),
    (r"n\S^CB;", True, "nCB"),
    (r"\A1;μv = 0,1\Pμa = 2", True, "μv = 0,1\nμa = 2"),
    (r"{\C1;c}\~", True, "c"),
    ("%%c 40", False, "Ø 40"),
    ("φ = 60%%d", False, "φ = 60°"),
])
def test_clean_text(raw: str, mtext: bool, plain: str) -> None:
    assert clean_text(raw, mtext=mtext) == plain


@pytest.mark.parametrize("name, key", [
    ("ω2", "omega2"), ("omega_2", "omega2"), ("w2", "omega2"), ("ε3", "epsilon3"),
    ("eps3", "epsilon3"), ("a^n_CB", "ancb"), ("aⁿ_CB", "ancb"), ("a_CB^n", "ancb"),
    ("a^τ_CB", "atcb"), ("v_{S2}", "vs2"), ("V_s2", "vs2"), ("R12", "r12"), ("R_12", "r12"),
    ("J_red", "jred"), ("J_пр", "jred"), ("M_ур", "mb"), ("ω₂", "omega2"),
])
def test_quantity_key(name: str, key: str) -> None:
    # quantity names are read through the notation catalogue (check/notation.toml)
    mech = load_scene(V_ENGINE).mechanism
    reading = notation.read(name, mech)
    assert reading is not None and notation.key(reading.canonical) == key


@pytest.mark.parametrize("name, plan", [
    ("μv", Plan.VELOCITY), ("mu_v", Plan.VELOCITY), ("μ_a", Plan.ACCELERATION),
    ("mu_a", Plan.ACCELERATION), ("μl", Plan.POSITION), ("μF", Plan.FORCE), ("μ_F", Plan.FORCE),
    ("kv", Plan.VELOCITY), ("v_B", None), ("mu", None),
])
def test_mu_names(name: str, plan: Plan | None) -> None:
    assert mu_plan(name) is plan


def test_angle_names() -> None:
    assert all(is_angle_name(n) for n in ("φ", "φ1", "phi", "at"))
    assert not any(is_angle_name(n) for n in ("ω1", "pb", "a"))


def _reads(book: LabelBook, text: str, plan: Plan) -> set[str]:
    return {c.label for c in book.candidates(text) if c.plan[0] is plan}


def test_book_reads_the_four_notations() -> None:
    scene, sol = solved("four_bar", 60)
    book = label_book(sol.construction, scene.mechanism)
    A, V = Plan.ACCELERATION, Plan.VELOCITY
    for pole in ("π", "π′", "p′", "p'", "pi", "P"):
        assert _reads(book, pole, A) == {"π"}, pole
    assert _reads(book, "p", V) == {"p"}
    assert _reads(book, "a", V) == {"p"}          # the image of the frame point A is the pole
    for written in ("b′", "b'", "b1", "B'"):
        assert "b′" in _reads(book, written, A), written
    for written in ("n_CB", "n_cb", "nCB", "n_BC", "n2"):
        assert "n_CB" in _reads(book, written, A), written
    assert "n_CD" in _reads(book, "n3", A)
    assert _reads(book, "S2", Plan.POSITION) == set()     # the four-bar has no S2
    assert _reads(book, "E", Plan.POSITION) == {"E"}


def test_book_coriolis_and_coincident_points() -> None:
    scene, sol = solved("shaper", 60)
    book = label_book(sol.construction, scene.mechanism)
    A, V = Plan.ACCELERATION, Plan.VELOCITY
    assert _reads(book, "k", A) == {"k_A3A2"}          # the only Coriolis point
    assert _reads(book, "kA3A2", A) == {"k_A3A2"}
    assert _reads(book, "a3", V) == {"a3"}
    assert _reads(book, "a2", V) == {"a"}              # A of the slider 2 is the crank pin
    assert _reads(book, "a3'", A) == {"a3′"}
    assert "p" in _reads(book, "o3", V)
