"""Answer tables of the dynamics, engine, cam and gear studies: planted mistakes are found with
the right kind (wrong / slip / swapped / carried), right values are never flagged.

Expected values come from closed forms computed here (cycloidal law, slider-crank kinematics,
Willis, involute geometry); the flywheel's J is the study's own (its value is tested in
tests/dynamics) — here only the grading of it is under test."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from mechplan.check import check
from mechplan.check.answers import maybe_check_answers
from mechplan.errors import CheckError
from mechplan.studies import solve_file

TEMPLATES = Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates"
FOUND: dict[str, list[int]] = {}


def _rows(report):
    return {v.name: v for v in report.values}


def _grade(report, planted: dict[str, tuple[str, str]]):
    """Every planted mistake flagged with its verdict and cause; every other row ok."""
    rows = _rows(report)
    for name, row in rows.items():
        if name in planted:
            verdict, cause = planted[name]
            assert (row.verdict, row.cause) == (verdict, cause), (name, row)
        else:
            assert row.verdict == "ok", (name, row)
    assert set(planted) <= set(rows), set(planted) - set(rows)
    return len(planted), len(rows) - len(planted)


def _write(tmp_path: Path, name: str, text: str) -> Path:
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


# -- cam: cycloidal rise of h = 10 mm over 60°, dwell 20°, return 60°, central roller ----------
H, BETA = 0.010, math.radians(60)


def _cyc(phi_deg: float) -> tuple[float, float, float]:
    x = math.radians(phi_deg) / BETA
    return (H * (x - math.sin(2 * math.pi * x) / (2 * math.pi)),
            H / BETA * (1 - math.cos(2 * math.pi * x)),
            2 * math.pi * H / BETA ** 2 * math.sin(2 * math.pi * x))


def _r0_min() -> float:
    """Central translating follower, α ≤ 30° on rise and return: r0 ≥ |s′|/tg 30° − s."""
    phi = np.linspace(0, 60, 60001)
    x = np.radians(phi) / BETA
    s = H * (x - np.sin(2 * np.pi * x) / (2 * np.pi))
    s1 = H / BETA * (1 - np.cos(2 * np.pi * x))
    return float(np.max(s1 / math.tan(math.radians(30)) - s))


def test_cam_table_russian_toml(tmp_path):
    r0 = _r0_min()
    s20, s1_20, s2_20 = _cyc(20)
    s45, s1_45, _ = _cyc(45)
    a20 = math.degrees(math.atan(s1_20 / (r0 + s20)))
    a45 = math.degrees(math.atan(s1_45 / (r0 + s45)))
    lines = [
        f'"R0" = "{r0 * 1000:.2f} мм"'.replace(".", ","),
        '"e" = "0 мм"',
        '"αmax" = "36°"',                                       # planted: wrong (exact 30°)
        '["φ = 20°"]',
        f'"S" = "{s20 * 1000:.3f} мм"'.replace(".", ","),
        f'"s′" = "{s1_20 * 1000:.2f} мм"'.replace(".", ","),
        f'"s″" = "{s2_20 * 1000:.1f} мм"'.replace(".", ","),
        f'"α" = "{a20 + 3:.2f}°"'.replace(".", ","),           # planted: slip (own s, s′ give a20)
        '["φ = 45°"]',
        f'"S" = "{s45 * 1000:.3f} мм"'.replace(".", ","),
        f'"s′" = "{s1_45 * 1000:.2f} мм"'.replace(".", ","),
        f'"α" = "{a45:.2f}°"'.replace(".", ","),
    ]
    report = check(TEMPLATES / "cam_cycloidal.toml", _write(tmp_path, "ivanov.toml",
                                                            "\n".join(lines)))
    FOUND["cam"] = list(_grade(report, {"αmax": ("wrong", "new"),
                                        "α (20°)": ("slip", "new")}))
    assert "arithmetic slip" in {f.kind for f in report.findings}


def test_cam_table_vietnamese_csv_swapped(tmp_path):
    r0 = _r0_min()
    s30, s1_30, _ = _cyc(30)
    s10, s1_10, _ = _cyc(10)
    csv = "\n".join([
        "tên;giá trị;đơn vị",
        f"r0;{r0 * 1000:.2f};mm".replace(".", ","),
        f"s;{s1_30 * 1000:.2f};mm;30".replace(".", ","),          # planted: s and s′ swapped
        f"s';{s30 * 1000:.3f};mm;30".replace(".", ","),
        f"s;{s10 * 1000:.4f};mm;10".replace(".", ","),
        f"s';{s1_10 * 1000:.3f};mm;10".replace(".", ","),
        "αmaxđi;30;°",
        "ρmin;9,49;mm",
        "Pq;3;mm",                                                  # not an answer of a cam
    ])
    report = check(TEMPLATES / "cam_cycloidal.toml", _write(tmp_path, "nguyen.csv", csv))
    FOUND["cam_vi"] = list(_grade(report, {"s (30°)": ("wrong", "swapped"),
                                           "s' (30°)": ("wrong", "swapped")}))
    assert any("Pq" in n.message and "closest" in n.message for n in report.notes)
    assert any(f.kind == "swapped labels" for f in report.findings)


# -- engine: slider-crank closed forms at the table angles --------------------------------------
def _engine_rows(phis):
    study = solve_file(TEMPLATES / "motorcycle_engine.toml")
    doc = study.to_json()
    e = doc["engine"]
    R, L, w, p0 = e["R"], e["L"], e["omega"], e["p0"]
    Fp = math.pi * e["bore"] ** 2 / 4
    mj = doc["cylinders"][0]["m_j"]
    lam = R / L
    out = {}
    for phi in phis:
        a = math.radians(phi)
        p = next(r for r in doc["angles"] if r["phi_deg"] == phi)["cylinders"]["1"]["p"]

        def xb(t):
            return R * math.cos(t) + math.sqrt(L * L - (R * math.sin(t)) ** 2)

        h = 1e-4
        acc = -(xb(a + h) - 2 * xb(a) + xb(a - h)) / h ** 2 * w ** 2    # toward the crank: +
        beta = math.asin(lam * math.sin(a))
        Pk = (p - p0) * Fp
        Pj = -mj * acc
        P = Pk + Pj
        T = P * math.sin(a + beta) / math.cos(beta)
        Z = P * math.cos(a + beta) / math.cos(beta)
        out[phi] = {"p": p, "Pk": Pk, "Pj": Pj, "P": P, "N": P * math.tan(beta), "T": T, "Z": Z,
                    "M": T * R}
    return out


def test_engine_wide_csv_russian(tmp_path):
    rows = _engine_rows([30, 90, 375, 420])
    head = "φ;p (Па);Pг (Н);Pj (Н);P (Н);N (Н);T (Н);Z (Н);Mкр (Н*м)"
    lines = [head]
    for phi, r in rows.items():
        vals = dict(r)
        if phi == 90:
            vals["T"] = r["T"] * 1.3                # planted: M follows from this wrong T
            vals["M"] = vals["T"] * 0.0235
        if phi == 375:
            vals["M"] = r["M"] * 1.1                # planted: slip (their T·R differs)
        if phi == 420:
            vals["Pj"] = r["Pj"] * 1.5              # planted: Pj wrong, P = Pг + Pj slip
        cells = [str(phi)] + [f"{vals[k]:.5g}".replace(".", ",")
                              for k in ("p", "Pk", "Pj", "P", "N", "T", "Z", "M")]
        lines.append(";".join(cells))
    report = check(TEMPLATES / "motorcycle_engine.toml", _write(tmp_path, "petrov.csv",
                                                                "\n".join(lines)))
    planted = {"T (90°)": ("slip", "new"), "Mкр (90°)": ("wrong", "carried"),
               "Mкр (375°)": ("slip", "new"), "Pj (420°)": ("wrong", "new"),
               "P (420°)": ("slip", "new")}
    FOUND["engine"] = list(_grade(report, planted))


def test_engine_toml_vietnamese_swapped_and_sign(tmp_path):
    rows = _engine_rows([60, 390])
    r60, r390 = rows[60], rows[390]
    text = "\n".join([
        '["φ = 60°"]',
        f'Pkt = "{r60["Pk"]:.1f} N"', f'Pj = "{r60["Pj"]:.1f} N"', f'P1 = "{r60["P"]:.1f} N"',
        f'T = "{r60["Z"]:.1f} N"', f'Z = "{r60["T"]:.1f} N"',         # planted: swapped
        '["φ = 390°"]',
        f'P = "{r390["P"] / 1000:.4f} kN"', f'T = "{r390["T"]:.1f} N"',
        f'Mkq = "{-r390["M"]:.2f} N*m"',                             # planted: sign
    ])
    report = check(TEMPLATES / "motorcycle_engine.toml", _write(tmp_path, "tran.toml", text))
    planted = {"T (60°)": ("wrong", "swapped"), "Z (60°)": ("wrong", "swapped"),
               "Mkq (390°)": ("slip", "new")}
    FOUND["engine_vi"] = list(_grade(report, planted))


# -- gears: Willis and involute closed forms ---------------------------------------------------
def _pair_closed_form():
    m, z1, z2, alpha = 0.003, 12, 30, math.radians(20)
    x1 = (17 - z1) / 17

    def inv(a):
        return math.tan(a) - a

    target = inv(alpha) + 2 * x1 * math.tan(alpha) / (z1 + z2)
    aw = brentq(lambda a: inv(a) - target, 0.1, 1.0)
    return {"x1": x1, "alpha_w": math.degrees(aw),
                "a_w": m * (z1 + z2) / 2 * math.cos(alpha) / math.cos(aw),
                "rb1": m * z1 * math.cos(alpha) / 2, "rb2": m * z2 * math.cos(alpha) / 2}


def test_gears_english_toml(tmp_path):
    z1, z2, z3, m = 18, 27, 72, 0.003
    u = 1 + z3 / z1                                          # Willis, ring fixed, carrier out
    pc = _pair_closed_form()
    text = "\n".join([
        "z1 = 18", "z2 = 27", "z3 = 72", "k = 3",
        f'u = "{u + 0.3:.2f}"',                              # planted: slip (their z give 5)
        f'a_w = "{m * (z1 + z2) / 2 * 1000:.1f} mm"',
        '"(z1+z3)/k" = 30',
        "[pair]",
        f'x1 = {pc["x1"]:.3f}', "x2 = 0",
        f'"αw" = "{pc["alpha_w"]:.2f} deg"',
        f'a_w = "{pc["a_w"] * 1000 + 1.5:.2f} mm"',          # planted: slip (their x give a_w)
        f'rb1 = "{pc["rb1"] * 1000:.3f} mm"', f'rb2 = "{pc["rb2"] * 1000:.3f} mm"',
    ])
    report = check(TEMPLATES / "planetary_single_row.toml", _write(tmp_path, "smith.toml", text))
    FOUND["gears"] = list(_grade(report, {"u": ("slip", "new"), "a_w": ("slip", "new")}))


def test_gears_other_valid_set_and_wrong_set_chinese_csv(tmp_path):
    # a valid set other than the program's (24, 36, 96): its own values are the exact ones
    csv = "名称,数值\nz1,24\nz2,36\nz3,96\n传动比,5\n中心距,90 mm"
    report = check(TEMPLATES / "planetary_single_row.toml", _write(tmp_path, "li.csv", csv))
    FOUND["gears_zh_valid"] = list(_grade(report, {}))
    assert any("meet every condition" in n.message for n in report.notes)
    # a set that breaks the conditions: z3 wrong; u follows from the student's z → carried
    z1, z2, z3 = 18, 27, 70
    csv = "\n".join(["名称,数值", f"z1,{z1}", f"z2,{z2}", f"z3,{z3}",
                     f"传动比,{1 + z3 / z1:.4f}"])
    report = check(TEMPLATES / "planetary_single_row.toml", _write(tmp_path, "wang.csv", csv))
    FOUND["gears_zh_wrong"] = list(_grade(report, {"z3": ("wrong", "new"),
                                                   "传动比": ("wrong", "carried")}))


# -- machine dynamics: flywheel answers ----------------------------------------------------------
def test_flywheel_table_russian_and_english(tmp_path):
    doc = solve_file(TEMPLATES / "machine_unit.toml").to_json()["dynamics"]
    J, delta, wm = doc["flywheel"]["exact"]["J"], 0.0125, math.pi * 300 / 30
    w_max, w_min = wm * (1 + delta / 2), wm * (1 - delta / 2)     # closed form
    text = "\n".join([
        f'"Jм" = "{J * 1.004:.2f} кг*м^2"'.replace(".", ","),
        f'"ωmax" = "{w_max:.3f} рад/с"'.replace(".", ","),
        f'"ωmin" = "{w_min:.3f} рад/с"'.replace(".", ","),
        f'"δ" = "{delta * 1.3:.5f}"'.replace(".", ","),        # planted: slip (own ω give δ)
        f'"ΔTmax" = "{J * delta * wm ** 2:.1f} Дж"'.replace(".", ","),
        f'"JW" = "{J * 1.2:.1f} kg*m^2"',                      # planted: slip (ΔT/(δω²))
    ])
    assert abs(wm - doc["omega_m"]) < 1e-9
    report = check(TEMPLATES / "machine_unit.toml", _write(tmp_path, "sidorov.toml", text))
    FOUND["dynamics"] = list(_grade(report, {"δ": ("slip", "new"), "JW": ("slip", "new")}))
    text = "\n".join([f'J_fly = "{J * 1.08:.1f} kg*m^2"',            # planted: wrong
                      f'omega_m = "{wm:.2f} rad/s"', f'"J_flywheel_x" = "{J:.1f} kg*m^2"'])
    report = check(TEMPLATES / "machine_unit.toml", _write(tmp_path, "smith.toml", text))
    FOUND["dynamics_en"] = list(_grade(report, {"J_fly": ("wrong", "new")}))
    assert any("J_flywheel_x" in n.message for n in report.notes)


def test_linkage_table_of_a_dynamics_scene_is_not_an_answer_table(tmp_path):
    p = _write(tmp_path, "t.toml", '"φ" = "30°"\n[velocity]\npb = 67.0\n')
    assert maybe_check_answers(TEMPLATES / "machine_unit.toml", p) is None


@pytest.mark.parametrize("name", ["cam_cycloidal", "planetary_single_row"])
def test_a_study_is_not_checked_from_a_drawing(tmp_path, name):
    """A cam or gear study has no plans to draw: a DXF is refused with what to hand in instead
    (the CLI exits 2 with the message), never read as a linkage scene."""
    from mechplan.cli import main

    drawing = tmp_path / "sheet.dxf"
    drawing.write_text("0\nEOF\n", encoding="utf-8")
    with pytest.raises(CheckError, match=r"answers are checked from a table \(\.toml, \.csv"):
        check(TEMPLATES / f"{name}.toml", drawing)
    assert main(["check", str(TEMPLATES / f"{name}.toml"), str(drawing)]) == 2
    # a linkage scene with [dynamics] still has its plans checked from a drawing
    assert maybe_check_answers(TEMPLATES / "machine_unit.toml", drawing) is None


@pytest.mark.parametrize("lang", ["en", "ru", "vi", "zh"])
def test_report_in_four_languages(tmp_path, lang):
    p = _write(tmp_path, "g.toml", 'z1 = 18\nz2 = 27\nz3 = 70\nu = "4,9"\nzz = 3\n')
    text = check(TEMPLATES / "planetary_single_row.toml", p).text(lang)
    assert "z3" in text and "zz" in text


def test_cli_exit_codes(tmp_path, capsys):
    from mechplan.cli import main

    ok = _write(tmp_path, "ok.toml", "z1 = 18\nz2 = 27\nz3 = 72\nu = 5\n")
    bad = _write(tmp_path, "bad.toml", "z1 = 18\nz2 = 27\nz3 = 72\nu = 6\n")
    assert main(["check", str(TEMPLATES / "planetary_single_row.toml"), str(ok)]) == 0
    assert main(["check", str(TEMPLATES / "planetary_single_row.toml"), str(bad),
                 "--lang", "vi"]) == 1
    assert "bộ truyền bánh răng" in capsys.readouterr().out


# -- no false alarm on any template: a table of the study's values at 4 significant digits ----
def _g(x: float, unit: str = "") -> str:
    return f"{x:.4g} {unit}".strip()


def _generated(name: str) -> str:
    doc = solve_file(TEMPLATES / name).to_json()
    out: list[str] = []
    if doc.get("kind") == "engine":
        for a in doc["angles"][1::7]:
            c = a["cylinders"]["1"]
            out.append(f'["φ = {a["phi_deg"]:g}°"]')
            out += [f'{k} = "{_g(c[k], u)}"' for k, u in (("p", "Pa"), ("Pk", "N"), ("Pj", "N"),
                                                          ("P", "N"), ("N", "N"), ("T", "N"),
                                                          ("Z", "N"), ("M", "N*m"))]
            out.append(f'"ΣM" = "{_g(a["M_total"], "N*m")}"')
        return f'"Mср" = "{_g(doc["torque"]["mean"], "N*m")}"\n' + "\n".join(out)
    if doc.get("kind") == "cam":
        osc = doc["follower"]["motion"] != "translating"
        alpha = not osc and doc["follower"]["contact"] != "flat"
        b, pa = doc["base_radius"], doc["pressure_angle_max"]
        rho = doc["radius_of_curvature_min"]["profile"][0]
        out += [f'r0 = "{_g(b["used"], "m")}"', f'"ρmin" = "{_g(rho, "m")}"']
        if not osc:
            out.append(f'"αmaxп" = "{math.degrees(pa["rise"][0]):.3f}°"')
        for r in doc["table"][1::5]:
            out.append(f'["φ = {math.degrees(r["phi"]):.4g}°"]')
            out += [f's = "{_g(r["s"], "rad" if osc else "m")}"', f"s1 = {r['s1']:.4g}" if osc
                    else f's1 = "{_g(r["s1"], "m")}"']
            if alpha:
                out.append(f'"α" = "{math.degrees(r["alpha"]):.3f}°"')
        return "\n".join(out)
    if doc.get("kind") == "gears":
        c = doc["planetary"]["chosen"]
        out += [f"z{i} = {z}" for i, z in enumerate(c["z"], start=1)]
        out += [f"k = {doc['planetary']['planets']}", f"u = {c['ratio']:.4g}",
                f'a_w = "{_g(c["a_w_m"][0], "m")}"']
        p = doc.get("pair")
        if p:
            out += ["[pair]", f"x1 = {p['x'][0]:.4g}", f"x2 = {p['x'][1]:.4g}",
                    f'"αw" = "{p["alpha_w_deg"]:.4g}°"', f'a_w = "{_g(p["a_w_m"], "m")}"',
                    f'"εα" = {p["contact_ratio"]:.4g}', f'rb1 = "{_g(p["gears"][0]["r_b"], "m")}"']
        return "\n".join(out)
    d = doc["dynamics"]
    fly = d["flywheel"]
    out += [f'"Jм" = "{_g(fly["exact"]["J"], "kg*m^2")}"',
            f'JW = "{_g(fly["wittenbauer"]["J"], "kg*m^2")}"',
            f'"δ" = {d["delta"]}', f'"ωmax" = "{d["motion"]["omega_max"]:.5g} rad/s"',
            f'"ωmin" = "{d["motion"]["omega_min"]:.5g} rad/s"',
            f'Mc = "{_g(d["constant_moment"], "N*m")}"']
    for pos in d["positions"][1::4]:
        out.append(f'["φ = {pos["phi_deg"]:g}°"]')
        out += [f'"Jпр" = "{_g(pos["J_red"], "kg*m^2")}"', f'"ω" = "{pos["omega"]:.5g} rad/s"']
    return "\n".join(out)


@pytest.mark.parametrize("name", ["cam_cycloidal.toml", "cam_flat.toml", "cam_oscillating.toml",
                                  "motorcycle_engine.toml", "v_engine_dynamics.toml",
                                  "planetary_single_row.toml", "planetary_two_row.toml",
                                  "machine_unit.toml", "shaper_flywheel.toml"])
def test_right_tables_of_every_template_pass(tmp_path, name):
    report = check(TEMPLATES / name, _write(tmp_path, "right.toml", _generated(name)))
    bad = [(v.name, v.verdict, v.hint) for v in report.values if v.verdict != "ok"]
    assert not bad and len(report.values) >= 5, bad
    assert not [n for n in report.notes if n.level == "error"], report.notes


def test_answer_table_toml_forms(tmp_path: Path) -> None:
    """Every TOML form of an answer table (module docstring of submission/answer_table.py) is
    read with its angle and section; the table's own angle is not an answer; a value of no use is
    a note."""
    from mechplan.submission.answer_table import read_answers
    from mechplan.submission.notation import is_angle_column as is_angle_name

    path = _write(tmp_path, "forms.toml", """"φ" = "60 deg"
M_mean = { value = 12.5, unit = "N*m" }
ok = true

["φ = 30°"]
P = "1200 N"

["60°"]
T = 300

[pair]
z1 = 17

[[rows]]
"φ" = "90°"
p = "2 MPa"
N = "-150 N"
""")
    table = read_answers(path, is_angle_name)
    got = [(e.name, e.text or e.value, e.phi_deg, e.section) for e in table.entries]
    assert got == [("M_mean", "12.5 N*m", None, None), ("P", "1200 N", 30.0, None),
                   ("T", "300", 60.0, None), ("z1", "17", None, "pair"),
                   ("p", "2 MPa", 90.0, None), ("N", "-150 N", 90.0, None)]
    assert [n.level for n in table.notes] == ["error"] and "True" in table.notes[0].message
