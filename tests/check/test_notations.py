"""Answer sets in the four course traditions' own notations, each with planted mistakes.

Every answer set is the V-engine (worked example §1) at φ = 60°, written as a student of one
tradition writes it: Russian (VC2, aC2, as2, Фи2, Mур), Vietnamese (VC2B2, Fqt2, Mcb, Jtt, P3),
Chinese (v_C, a_S2, ω_2, F_I2, J_e) and English (omega2, alpha2, a^t_CB, Q2, R21). Every planted
mistake must be flagged with its kind — new (wrong), carried (follows from the student's own
wrong number), slip (does not follow from the student's own numbers) — and nothing else may be.
The exact numbers come from the engine's evaluation, the mistakes are planted on them by hand.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from mechplan.check import Options, check
from mechplan.check.report import CARRIED, NEW, OK, REFERENCE, SLIP, WRONG
from mechplan.dynamics import Loading
from mechplan.dynamics.reduced import reduced_of
from mechplan.scene import load_scene
from mechplan.solve import solve

from .sheets import TEMPLATES

MU_V, MU_A, L_BC, M_2 = 0.1, 2.0, 0.248, 3.1     # the template's μv, μa, l_BC (m), m_2 (kg)


@pytest.fixture(scope="module")
def engine():
    scene = load_scene(TEMPLATES / "v_engine.toml")
    loading = Loading.from_scene(scene)
    sol = solve(scene, at_deg=[60], plans=("position", "velocity", "acceleration", "force"),
                loading=loading)
    c, ev = sol.construction, sol.ev

    def mag(sid: str) -> float:
        v = np.asarray(ev[sid][0])
        return float(np.hypot(*v)) if v.ndim else abs(float(v))

    x = {k: mag(sid) for k, sid in c.results.items()}
    for s in c.segments:
        if s.plan.value == "velocity":
            x[f"mm_{s.name}"] = float(np.hypot(*(ev[s.end][0] - ev[s.start][0]))) / MU_V
    m_red, j_red = reduced_of(c, ev, scene.mechanism, loading)
    x["M_red"], x["J_red"] = abs(float(m_red[0])), float(j_red[0])
    f_c = next(s for s in c.segments if s.quantity == "F_C")
    x["F_C"] = float(np.hypot(*(ev[f_c.end][0] - ev[f_c.start][0])))
    return scene, x


def _rows(report) -> dict[str, tuple[str, str]]:
    out = {s.name: (s.verdict, s.cause) for p in report.plans for s in p.segments}
    out.update({v.name: (v.verdict, v.cause) for v in report.values})
    return out


def _grade(report, planted: dict[str, tuple[str, str]], written: list[str]) -> tuple[int, int]:
    """Assert every planted mistake is flagged with its kind and every other row is right;
    return (planted mistakes flagged, right values checked)."""
    rows = _rows(report)
    missing = [n for n in written if n not in rows]
    assert not missing, (missing, [n.message for n in report.notes])
    for name, (verdict, cause) in rows.items():
        if name in planted:
            assert (verdict, cause) == planted[name], (name, verdict, cause, report.text())
        else:
            assert verdict in (OK, REFERENCE), (name, verdict, cause, report.text())
    return len(planted), len(rows) - len(planted)


def test_russian_toml(tmp_path: Path, engine) -> None:
    scene, x = engine
    pc_bad = x["mm_pc"] + 5.0
    text = f'''"φ" = "60°"
["масштабы"]
"μv" = "0,1 m/s/mm"
"μa" = "2 (m/s^2)/mm"
["план скоростей"]
pb = {x["mm_pb"]:.1f}
pc = {pc_bad:.1f}
pd = {x["mm_pd"] + 5:.1f}
ps2 = {x["mm_ps2"]:.1f}
bc = {x["mm_bc"]:.1f}
["величины"]
VC2 = "{pc_bad * MU_V:.3f} m/s"
V_S2 = "{x["v_S2"]:.3f} m/s"
aC2 = "{x["a_C"]:.1f} m/s^2"
as2 = "{x["a_S2"] * 1.2:.1f} m/s^2"
"ω2" = "{x["omega_2"]:.2f} rad/s"
"aτC2B2" = "{x["epsilon_2"] * L_BC:.1f} m/s^2"
"ε2" = "{x["epsilon_2"] * 1.1:.0f} rad/s^2"
"Фи2" = "{M_2 * x["a_S2"] * 1.2:.0f} N"
R12 = "{x["R_12"]:.0f} N"
R_03 = "{x["R_03"]:.0f} N"
"Mур" = "{x["M_b"]:.1f} N*m"
"Мпр" = "{x["M_red"]:.2f} N*m"
"Jпр" = "{x["J_red"]:.4f} kg*m^2"
'''
    path = tmp_path / "ivanov.toml"
    path.write_text(text, encoding="utf-8")
    report = check(scene, path, Options(at_deg=60))
    planted = {"pc": (WRONG, NEW), "pd": (WRONG, CARRIED), "VC2": (WRONG, CARRIED),
               "as2": (WRONG, NEW), "ε2": (SLIP, NEW), "Фи2": (WRONG, CARRIED)}
    written = ["pb", "pc", "pd", "ps2", "bc", "VC2", "V_S2", "aC2", "as2", "ω2", "aτC2B2", "ε2",
               "Фи2", "R12", "R_03", "Mур", "Мпр", "Jпр"]
    assert _grade(report, planted, written) == (6, 12)
    # an acceleration name is an acceleration: aC2 is compared with a_C, never with pc
    assert next(v for v in report.values if v.name == "aC2").quantity == "a_C"
    assert "арифметическая ошибка" in report.text("ru")


def test_vietnamese_csv(tmp_path: Path, engine) -> None:
    scene, x = engine
    pb_mm = x["mm_pb"] + 0.9         # within ±1 mm: a good segment ...
    rows = [
        "đoạn,độ dài,tỉ lệ,đại lượng,giá trị",
        # ... but its value is the exact one copied, not pb × μv: a slip although near exact
        f"pb,{pb_mm:.1f},0.1 m/s/mm,VB1,{x['v_B']:.2f} m/s",
        f"bc,{x['mm_bc']:.1f},0.1 m/s/mm,VC2B2,{x['mm_bc'] * MU_V * 1.08:.3f} m/s",
        f"pc,{x['mm_pc']:.1f},0.1 m/s/mm,VC3,{x['mm_pc'] * MU_V:.3f} m/s",
        f"de,{x['mm_de']:.1f},0.1 m/s/mm,VE4D4,{x['mm_de'] * MU_V:.3f} m/s",
        f"Fqt2,,,,{M_2 * x['a_S2'] * 0.85:.0f} N",
        f"as2,,,,{x['a_S2']:.1f} m/s^2",
        f"Mcb,,,,{x['M_b']:.1f} N*m",
        f"Mtt,,,,{x['M_red']:.2f} N*m",
        f"Jtt,,,,{x['J_red']:.4f} kg*m^2",
        f"G5,,,,{x['G_5']:.2f} N",
        f"P3,,,,{x['F_C']:.0f} N",
    ]
    path = tmp_path / "nguyen_van_a.csv"
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")
    report = check(scene, path, Options(at_deg=60))
    planted = {"VB1": (SLIP, NEW), "VC2B2": (SLIP, NEW), "Fqt2": (SLIP, NEW)}
    written = ["pb", "bc", "pc", "de", "VB1", "VC2B2", "VC3", "VE4D4", "Fqt2", "as2", "Mcb",
               "Mtt", "Jtt", "G5", "P3"]
    assert _grade(report, planted, written) == (3, 12)
    assert "lỗi tính toán" in report.text("vi")


def test_chinese_toml(tmp_path: Path, engine) -> None:
    scene, x = engine
    text = f'''"φ1" = "60 deg"
["速度多边形"]
pb = {x["mm_pb"]:.1f}
pc = {x["mm_pc"]:.1f}
bc = {x["mm_bc"] - 4:.1f}
["数值"]
"μ_v" = "0.1 m/s/mm"
v_C = "{x["v_C"]:.3f} m/s"
v_CB = "{(x["mm_bc"] - 4) * MU_V:.3f} m/s"
"ω_2" = "{(x["mm_bc"] - 4) * MU_V / L_BC:.2f} rad/s"
a_S2 = "{x["a_S2"]:.1f} m/s^2"
F_I2 = "{M_2 * x["a_S2"]:.0f} N"
M_b = "{x["M_b"] * 1.5:.0f} N*m"
J_e = "{x["J_red"]:.4f} kg*m^2"
'''
    path = tmp_path / "wang.toml"
    path.write_text(text, encoding="utf-8")
    report = check(scene, path, Options(at_deg=60))
    planted = {"bc": (WRONG, NEW), "v_CB": (WRONG, CARRIED), "ω_2": (WRONG, CARRIED),
               "M_b": (WRONG, NEW)}
    written = ["pb", "pc", "bc", "v_C", "v_CB", "ω_2", "a_S2", "F_I2", "M_b", "J_e"]
    assert _grade(report, planted, written) == (4, 6)
    assert "计算错误" in report.text("zh") or "传递" in report.text("zh")


def test_english_csv_and_names_not_understood(tmp_path: Path, engine) -> None:
    scene, x = engine
    rows = [
        "name,value",
        "mu_v,0.1 m/s/mm",
        f"v_CB,{x['mm_bc'] * MU_V:.3f} m/s",
        f"omega2,{x['omega_2'] * 1.3:.2f} rad/s",
        f"a^t_CB,{x['epsilon_2'] * L_BC:.1f} m/s^2",
        f"alpha2,{x['epsilon_2']:.0f} rad/s^2",
        f"Q2,{M_2 * x['a_S2']:.0f} N",
        f"R21,{x['R_21']:.0f} N",
        f"G5,{x['G_5'] * 2:.2f} N",
        f"a_Z9,{x['a_S2']:.1f} m/s^2",
    ]
    path = tmp_path / "smith.csv"
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")
    report = check(scene, path, Options(at_deg=60))
    planted = {"omega2": (SLIP, NEW), "G5": (WRONG, NEW)}
    written = ["v_CB", "omega2", "a^t_CB", "alpha2", "Q2", "R21", "G5"]
    assert _grade(report, planted, written) == (2, 5)
    # a name that is no quantity of this mechanism is reported with the closest candidates,
    # never graded as another quantity
    notes = " | ".join(n.message for n in report.notes)
    assert "'a_Z9' is not understood" in notes and "closest: a_" in notes


def test_fair_tolerances_on_short_segments(tmp_path: Path, engine) -> None:
    """A 0.3 mm error on a 3.5 mm segment (9 %) is a good drawing, and so are the values that
    follow from it; an error is carried only from an upstream item that is itself wrong."""
    scene, x = engine
    bc = x["mm_bc"] * MU_V              # bc at μv = 1 (m/s)/mm: about 3.5 mm long
    pc, pd = x["mm_pc"] * MU_V, x["mm_pd"] * MU_V
    text = f'''at = "60 deg"
[velocity]
mu_v = "1 m/s/mm"
bc = {bc + 0.3:.2f}
pc = {pc + 0.8:.2f}
pd = {pd + 1.6:.2f}
[values]
v_CB = "{bc + 0.3:.2f} m/s"
"ω2" = "{(bc + 0.3) / L_BC:.2f} rad/s"
'''
    path = tmp_path / "short.toml"
    path.write_text(text, encoding="utf-8")
    report = check(scene, path, Options(at_deg=60))
    rows = _rows(report)
    assert 0.05 < 0.3 / bc < 0.1                      # the short segment is 5–10 % off ...
    assert rows["bc"] == (OK, "") and rows["v_CB"] == (OK, "") and rows["ω2"] == (OK, "")
    assert rows["pc"] == (OK, "")                     # 0.8 mm: within ±1 mm
    assert rows["pd"] == (WRONG, NEW)                 # not carried from a right pc
