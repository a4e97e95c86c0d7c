"""Tables of measured lengths and values (TOML, CSV): injected errors, slips, units, bad input."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from mechplan.check import Options, check
from mechplan.check.report import CARRIED, NEW, OK, REFERENCE, SLIP, WRONG
from mechplan.errors import CheckError
from mechplan.scene import load_scene
from mechplan.solve import solve

from .sheets import TEMPLATES, solved


def _exact(sol, name: str) -> float:
    c, ev = sol.construction, sol.ev
    seg = next(s for s in c.segments if s.name == name)
    return float(np.hypot(*(ev[seg.end][0] - ev[seg.start][0])))


def _verdicts(report) -> dict[str, str]:
    out = {s.name: s.verdict for p in report.plans for s in p.segments}
    out.update({v.name: v.verdict for v in report.values})
    return out


def _notes(report, level: str) -> str:
    return " | ".join(n.message for n in report.notes if n.level == level)


@pytest.fixture
def four_bar():
    return solved("four_bar", 60)


def test_toml_lengths_values_and_injected_errors(tmp_path: Path, four_bar) -> None:
    scene, sol = four_bar
    mm = {n: _exact(sol, n) / mu for n, mu in (("pb", 0.01), ("bc", 0.01), ("pc", 0.01),
                                                ("pe", 0.01), ("πb′", 0.1), ("b′n_CB", 0.1),
                                                ("n_CB c′", 0.1))}
    w2 = abs(float(sol.ev["vel.omega.2"][0]))
    bc_comma = f"{mm['bc']:.1f}".replace(".", ",")
    text = f"""
at = "60 deg"
[scales]
mu_v = "0,01 m/s/mm"
mu_a = "0.1 (m/s^2)/mm"
[velocity]
pb = {mm['pb']:.1f}
bc = "{bc_comma} mm"
pc = "{mm['pc'] + 3:.1f} mm → {(mm['pc'] + 3) * 0.01:.3f} m/s"
pe = {{ mm = {mm['pe']:.1f}, value = "{mm['pe'] * 0.01 * 1.2:.3f} m/s" }}
[acceleration]
"πb'" = {mm['πb′']:.1f}
"b1n2" = {mm['b′n_CB']:.1f}
"n_CB c'" = {mm['n_CB c′']:.1f}
[values]
"ω2" = "{w2:.3f} rad/s"
"""
    path = tmp_path / "t.toml"
    path.write_text(text, encoding="utf-8")
    report = check(scene, path, Options())
    assert report.phi_deg == pytest.approx(60.0)
    v = _verdicts(report)
    assert v["pb"] == v["bc"] == v["pe"] == v["πb′"] == v["b′n_CB"] == v["n_CB c′"] == OK
    assert v["pc"] == WRONG and v["ω2"] == OK
    assert v["v_C"] == WRONG        # follows the wrong pc: carried, not a slip
    assert v["v_E"] == SLIP         # pe × μ ≠ the value written
    kinds = {(f.kind, f.subject) for f in report.findings}
    assert kinds == {("wrong segment", "pc"), ("arithmetic slip", "v_E")}
    vc = next(r for r in report.values if r.name == "v_C")
    assert vc.cause == CARRIED and "follows from your own" in vc.hint


def test_toml_scale_inferred_and_carried_segments(tmp_path: Path, four_bar) -> None:
    scene, sol = four_bar
    pb, bc, pe = (_exact(sol, n) / 0.01 for n in ("pb", "bc", "pe"))
    path = tmp_path / "t.toml"
    path.write_text(f"[velocity]\npb = {pb:.2f}\nbc = {bc * 1.2:.2f}\npe = {pe * 1.1:.2f}\n",
                    encoding="utf-8")
    report = check(scene, path, Options(at_deg=60))
    plan = report.plans[0]
    assert plan.mu == pytest.approx(0.01, rel=1e-3)
    assert "inferred from pb" in plan.mu_source
    rows = {s.name: s for s in plan.segments}
    assert rows["pb"].verdict == REFERENCE
    assert rows["bc"].verdict == WRONG and rows["bc"].cause == NEW
    assert rows["pe"].verdict == WRONG and rows["pe"].cause == CARRIED
    assert rows["pe"].carried_from == ["bc"]
    assert [f.subject for f in report.findings] == ["bc"]


def test_csv_with_header_decimal_comma_and_semicolons(tmp_path: Path, four_bar) -> None:
    scene, sol = four_bar
    pb, bc, pc = (_exact(sol, n) / 0.01 for n in ("pb", "bc", "pc"))
    rows = [("pb", pb, pb * 0.01), ("bc", bc, bc * 0.01), ("pc", pc, pc * 0.01 * 1.25)]
    text = "segment;mm;mu;quantity;value\n" + "".join(
        f"{n};{mm:.1f};0,01;{'v_' + {'pb': 'B', 'bc': 'CB', 'pc': 'C'}[n]};{val:.3f}\n".replace(
            ".", ",") for n, mm, val in rows)
    path = tmp_path / "t.csv"
    path.write_text(text, encoding="utf-8")
    report = check(scene, path, Options(at_deg=60))
    v = _verdicts(report)
    assert v["pb"] == v["bc"] == v["pc"] == OK       # "bc" is the velocity segment, not BC
    assert v["v_B"] == v["v_CB"] == OK and v["v_C"] == SLIP
    assert [f.kind for f in report.findings] == ["arithmetic slip"]
    assert "no unit; read in SI" in _notes(report, "info")


def test_a_rows_scale_factor_must_be_positive(tmp_path: Path, four_bar) -> None:
    """A row's own μ of zero or below is no scale factor: a note says so and the row is graded
    at the table's μ (here inferred from the other row), as a μ written on a sheet would be."""
    scene, sol = four_bar
    pb, bc = (_exact(sol, n) / 0.01 for n in ("pb", "bc"))
    path = tmp_path / "t.csv"
    path.write_text(f"segment;mm;mu\npb;{pb:.1f};-0,01\nbc;{bc:.1f};0\n", encoding="utf-8")
    report = check(scene, path, Options(at_deg=60))
    errors = _notes(report, "error")
    assert "'pb = -0,01' must be positive" in errors and "'bc = 0' must be positive" in errors
    rows = {s.name: s for p in report.plans for s in p.segments}
    assert rows["pb"].verdict == REFERENCE and rows["bc"].verdict == OK
    assert rows["bc"].exact_mm == pytest.approx(bc, rel=2e-3)     # at μ = 0.01 from pb's row


def test_csv_without_header(tmp_path: Path, four_bar) -> None:
    scene, sol = four_bar
    w3 = abs(float(sol.ev["vel.omega.3"][0]))
    path = tmp_path / "t.csv"
    path.write_text(f"# name, value\nmu_v, 0.01 m/s/mm\npb, {_exact(sol, 'pb') / 0.01:.1f}\n"
                    f"omega3, {w3 * 60 / (2 * np.pi):.1f}, rpm\n\"v_B\",\"0,80 m/s\"\n",
                    encoding="utf-8")
    report = check(scene, path, Options(at_deg=60))
    v = _verdicts(report)
    assert v == {"pb": OK, "omega3": OK, "v_B": OK}


def test_force_values_and_reduced_inertia(tmp_path: Path) -> None:
    scene = load_scene(TEMPLATES / "slider_crank.toml")
    from mechplan.dynamics import Loading
    from mechplan.dynamics.reduced import reduced_of

    loading = Loading.from_scene(scene)
    sol = solve(scene, at_deg=[60], plans=("position", "velocity", "acceleration", "force"),
                loading=loading)
    c, ev = sol.construction, sol.ev
    r12 = float(np.hypot(*ev[c.results["R_12"]][0]))
    r03 = float(np.hypot(*ev[c.results["R_03"]][0]))
    mb = float(ev[c.results["M_b"]][0])
    _, j_red = reduced_of(c, ev, scene.mechanism, loading)
    path = tmp_path / "forces.toml"
    path.write_text(f"""
[values]
R12 = "{r12 / 1000:.3f} kN"
"R_{{03}}" = "{r03 * 1.1:.0f} N"
M_b = "{mb:.1f} N·m"
J_red = "{float(j_red[0]):.4f} kg·m²"
M_q2 = "5 N"
Q_9 = "1 N"
""", encoding="utf-8")
    report = check(scene, path, Options(at_deg=60))
    v = _verdicts(report)
    assert v == {"R12": OK, "R_{03}": WRONG, "M_b": OK, "J_red": OK}
    errors = _notes(report, "error")
    assert "'5 N' is not a moment" in errors
    assert "'Q_9' is not understood" in errors and "closest: Q_3, Q_2" in errors


def test_units_that_do_not_fit_and_unknown_names(tmp_path: Path, four_bar) -> None:
    scene, _ = four_bar
    path = tmp_path / "t.toml"
    path.write_text('[values]\nv_B = "0.8 rad/s"\nomega_2 = "1.35 m/s"\nv_Z = "1 m/s"\n'
                    'pc = "55 mm"\nv_C = "55 mm"\n', encoding="utf-8")
    report = check(scene, path, Options(at_deg=60))
    errors = _notes(report, "error")
    assert "'0.8 rad/s' is not a velocity" in errors
    assert "'1.35 m/s' is not an angular velocity" in errors
    assert "'v_Z' is not understood" in errors and "closest: v_" in errors
    assert "'v_C = 55 mm' is a length on the paper" in errors
    assert [r.name for r in report.values] == []
    assert [s.name for p in report.plans for s in p.segments] == ["pc"]


@pytest.mark.parametrize("name, content, message", [
    ("bad.toml", "pb = [1, \n", "not a valid TOML"),
    ("empty.toml", "# nothing\n", "holds no values"),
    ("nothing.toml", '[values]\nfoo = "1 m/s"\n', "nothing in the table can be checked"),
    ("empty.csv", "", "holds no rows"),
    ("bin.csv", "pb\x00,1\n", "binary"),
    ("nohead.csv", "mm,mu\n1,2\n", "no name column"),
    ("x.json", "{}", "cannot tell what kind of submission"),
])
def test_unusable_tables(tmp_path: Path, four_bar, name: str, content: str, message: str) -> None:
    scene, _ = four_bar
    path = tmp_path / name
    path.write_text(content, encoding="utf-8")
    with pytest.raises(CheckError, match=message) as exc:
        check(scene, path, Options(at_deg=60))
    assert name in str(exc.value)


def test_missing_file(tmp_path: Path, four_bar) -> None:
    with pytest.raises(CheckError, match="does not exist"):
        check(four_bar[0], tmp_path / "nope.dxf", Options(at_deg=60))


def test_csv_rows_that_cannot_be_read_are_reported(tmp_path: Path, four_bar) -> None:
    scene, sol = four_bar
    path = tmp_path / "t.csv"
    path.write_text(f"pb, {_exact(sol, 'pb') / 0.01:.1f}\nlonely\nbc, abc\nmu_v, 0.01\n",
                    encoding="utf-8")
    report = check(scene, path, Options(at_deg=60))
    errors = _notes(report, "error")
    assert "t.csv line 2" in " ".join(n.where for n in report.notes)
    assert "expected 'name, value'" in errors
    assert _verdicts(report) == {"pb": OK}


def test_linkage_table_toml_forms(tmp_path: Path) -> None:
    """The TOML forms of a table of lengths and values (docs/check.md) are read as entries with
    their section; rows of an array name their segment; a value of no use is a note."""
    from mechplan.submission.read import read_submission

    path = tmp_path / "forms.toml"
    path.write_text(""""φ" = 60
[velocity]
pb = 67.0
ab = { mm = 31.5, mu = "0.01 m/s/mm" }

[values]
v_S2 = "2.95 m/s"
bad = [1, 2]

[[rows]]
segment = "pc"
name = "v_C"
mm = 12
value = 0.12
unit = "m/s"
""", encoding="utf-8")
    sub = read_submission(path)
    got = [(e.name, e.text, e.length, e.mu, e.quantity, e.value, e.section) for e in sub.entries]
    assert got == [("φ", "60", None, None, None, None, None),
                   ("pb", "67.0", None, None, None, None, "velocity"),
                   ("ab", None, "31.5", "0.01 m/s/mm", None, None, "velocity"),
                   ("v_S2", "2.95 m/s", None, None, None, None, "values"),
                   ("pc", None, "12", None, "v_C", "0.12 m/s", None)]
    assert [n.level for n in sub.notes] == ["error"] and "[1, 2]" in sub.notes[0].message
