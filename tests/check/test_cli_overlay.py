"""`mechplan check` on the command line: exit codes, JSON, text, overlay sheets."""

from __future__ import annotations

import argparse
import json
import xml.etree.ElementTree as ET
from pathlib import Path

import ezdxf
import pytest

from mechplan.check.report import Tolerance
from mechplan.cli.check import add_parser, parse_tolerances
from mechplan.errors import CheckError, MechplanError
from mechplan.model.plans import Plan

from .sheets import TEMPLATES, PlanSpec, exact_sheet, move, solved, write_dxf

V, A = Plan.VELOCITY, Plan.ACCELERATION
SPECS = {V: PlanSpec(0.01, (50, 50), "μv = 0,01 m/s/mm"),
         A: PlanSpec(0.1, (250, 60), "μa = 0.1 (m/s²)/mm")}
SCENE = str(TEMPLATES / "four_bar.toml")


def main(argv: list[str]) -> int:
    """What `mechplan.cli.main` does with the subcommand: MechplanError → exit 2."""
    parser = argparse.ArgumentParser(prog="mechplan")
    add_parser(parser.add_subparsers(dest="command", required=True))
    args = parser.parse_args(argv)
    try:
        return int(args.func(args))
    except MechplanError as exc:
        print(f"mechplan: error: {exc}")
        return 2


@pytest.fixture
def sheets(tmp_path: Path) -> dict[str, Path]:
    _scene, sol = solved("four_bar", 60)
    good = write_dxf(tmp_path / "good.dxf", sol, SPECS, exact_sheet(sol, SPECS))
    st = exact_sheet(sol, SPECS)
    move(st, V, "c", (3.0, -4.0))
    bad = write_dxf(tmp_path / "bad.dxf", sol, SPECS, st)
    return {"good": good, "bad": bad}


def test_exit_codes_and_text(sheets, capsys) -> None:
    assert main(["check", SCENE, str(sheets["good"]), "--at", "60"]) == 0
    out = capsys.readouterr().out
    assert "PASSED" in out and "Velocity plan" in out and "μ = 0.01 (m/s)/mm" in out
    assert main(["check", SCENE, str(sheets["bad"]), "--at", "60"]) == 1
    out = capsys.readouterr().out
    assert "FAILED" in out and "WRONG (new)" in out and "[wrong point]" in out


def test_json(sheets, capsys) -> None:
    assert main(["check", SCENE, str(sheets["bad"]), "--at", "60", "--json"]) == 1
    doc = json.loads(capsys.readouterr().out)
    assert doc["passed"] is False and doc["phi_deg"] == 60.0
    vel = next(p for p in doc["plans"] if p["plan"] == "velocity")
    pc = next(s for s in vel["segments"] if s["name"] == "pc")
    assert pc["verdict"] == "wrong" and pc["cause"] == "new"
    assert set(pc) >= {"submitted_mm", "exact_mm", "error_mm", "error_pct", "direction_deg",
                       "tolerance_mm", "hint", "depends_on", "carried_from"}
    assert vel["mu_unit"] == "(m/s)/mm" and vel["tolerance"] == {"mm": 1.0, "pct": 2.0,
                                                                  "deg": None}
    assert [f["subject"] for f in doc["findings"]] == ["c"]
    assert "drawn_lines" not in vel


def test_outputs_and_overlays(sheets, tmp_path: Path, capsys) -> None:
    outs = {s: tmp_path / f"report.{s}" for s in ("json", "txt", "svg", "dxf", "pdf")}
    argv = ["check", SCENE, str(sheets["bad"]), "--at", "60"]
    for p in outs.values():
        argv += ["-o", str(p)]
    assert main(argv) == 1
    capsys.readouterr()
    assert json.loads(outs["json"].read_text(encoding="utf-8"))["summary"]["wrong"] == 2
    assert "FAILED" in outs["txt"].read_text(encoding="utf-8")
    # SVG: three groups of lines, the wrong segments marked with their error
    root = ET.parse(outs["svg"]).getroot()
    ns = {"s": "http://www.w3.org/2000/svg"}
    # the overlay is a Sheet drawn by the render backend: one group per role
    groups = {g.get("class", "").removeprefix("role-"): g
              for g in root.iter("{http://www.w3.org/2000/svg}g")}
    assert {"submission", "exact", "errors", "text"} <= set(groups)
    assert groups["errors"].get("stroke") == "#d62020"
    assert len(groups["submission"].findall("s:line", ns)) == 11
    assert len(groups["exact"].findall("s:line", ns)) == 11
    assert len(groups["errors"].findall("s:line", ns)) == 2
    texts = [t.text for t in groups["errors"].findall("s:text", ns)]
    assert any(t.startswith("pc ") and "mm" in t for t in texts)
    assert root.get("width", "").endswith("mm")
    # DXF: layers by colour, re-read by ezdxf
    doc = ezdxf.readfile(outs["dxf"])
    msp = doc.modelspace()
    assert {"SUBMISSION", "EXACT", "ERRORS"} <= {layer.dxf.name for layer in doc.layers}
    assert len(msp.query('LINE[layer=="ERRORS"]')) == 2
    assert any("bc" in t.dxf.text for t in msp.query('TEXT[layer=="ERRORS"]'))
    assert outs["pdf"].read_bytes().startswith(b"%PDF")
    # the exact plan is placed by the pole: exact and submitted pb coincide
    sub = {(round(e.dxf.start.x, 6), round(e.dxf.start.y, 6), round(e.dxf.end.x, 6),
            round(e.dxf.end.y, 6)) for e in msp.query('LINE[layer=="SUBMISSION"]')}
    exact = {(round(e.dxf.start.x, 6), round(e.dxf.start.y, 6), round(e.dxf.end.x, 6),
              round(e.dxf.end.y, 6)) for e in msp.query('LINE[layer=="EXACT"]')}
    assert len(sub & exact) >= 7


def test_overlay_of_a_table_is_refused(tmp_path: Path, capsys) -> None:
    table = tmp_path / "t.toml"
    table.write_text("[velocity]\npb = 80\n", encoding="utf-8")
    assert main(["check", SCENE, str(table), "--at", "60", "-o",
                 str(tmp_path / "o.svg")]) == 2
    assert "needs a drawn submission" in capsys.readouterr().out
    assert not (tmp_path / "o.svg").exists()


def test_files_are_replaced_atomically(sheets, tmp_path: Path, capsys) -> None:
    out = tmp_path / "o.svg"
    out.write_text("old", encoding="utf-8")
    assert main(["check", SCENE, str(sheets["good"]), "--at", "60", "-o", str(out)]) == 0
    assert out.read_text(encoding="utf-8").startswith("<?xml")
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".o.svg")] == []
    assert main(["check", SCENE, str(sheets["good"]), "--at", "60", "-o",
                 str(tmp_path / "missing" / "o.svg")]) == 2
    assert "output directory must exist" in capsys.readouterr().out


@pytest.mark.parametrize("argv, message", [
    (["--tolerance", "1 furlong"], "cannot read"),
    (["--tolerance", "speed=1mm"], "unknown plan"),
    (["--mu-v", "0.1 N/mm"], "--mu-v"),
    (["--mu-v", "-1"], "must be positive"),
    (["-o", "report.docx"], ".json, .txt"),
    (["--label-distance", "0"], "must be positive"),
])
def test_bad_options(sheets, capsys, argv, message) -> None:
    assert main(["check", SCENE, str(sheets["good"]), "--at", "60", *argv]) == 2
    assert message in capsys.readouterr().out


def test_bad_scene_and_submission(tmp_path: Path, capsys) -> None:
    assert main(["check", str(tmp_path / "none.toml"), str(tmp_path / "x.dxf")]) == 2
    bad = tmp_path / "x.dxf"
    bad.write_text("garbage", encoding="utf-8")
    assert main(["check", SCENE, str(bad), "--at", "60"]) == 2
    out = capsys.readouterr().out
    assert "x.dxf" in out and "Traceback" not in out


def test_scale_and_tolerance_options(sheets, capsys) -> None:
    assert main(["check", SCENE, str(sheets["bad"]), "--at", "60",
                 "--tolerance", "velocity=6mm", "--mu-v", "0,01 m/s/mm"]) == 0
    out = capsys.readouterr().out
    assert "given on the command line" in out and "±6 mm" in out


def test_parse_tolerances() -> None:
    tol = parse_tolerances(["0.5mm,1%", "acceleration=2mm", "velocity: 3deg"])
    assert tol[None] == Tolerance(0.5, 1.0, None)
    assert tol[Plan.ACCELERATION] == Tolerance(2.0, 1.0, None)
    assert tol[Plan.VELOCITY] == Tolerance(0.5, 1.0, 3.0)
    with pytest.raises(CheckError):
        parse_tolerances(["velocity="])
