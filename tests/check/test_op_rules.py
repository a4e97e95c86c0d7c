"""The checker knows operations only through their specs, and plans only through `Plan`."""

from __future__ import annotations

import argparse
import re
from pathlib import Path

import pytest

import mechplan.check
from mechplan.cli.check import PLAN_NAMES, add_parser, parse_scales
from mechplan.construct.ops import SPECS, Grade
from mechplan.errors import CheckError
from mechplan.model.plans import Plan

CHECK = Path(mechplan.check.__file__).parent


def test_check_names_no_operation() -> None:
    """Grading and hint rules are read from `OpSpec` (grade, hint, hint_rule, alias), never by
    naming an operation."""
    named = {f"{p.name}:{n}": m.group(0) for p in sorted(CHECK.glob("*.py"))
             for n, line in enumerate(p.read_text(encoding="utf-8").splitlines(), start=1)
             if (m := re.search(r"\bOp\.[A-Z_]+|ops import .*\bOp\b|ops\.catalog", line))}
    assert named == {}


def test_spec_rules_the_checker_reads() -> None:
    origins = {s.value for s in SPECS.values() if s.grade is Grade.ORIGIN}
    given = {s.value for s in SPECS.values() if s.grade is Grade.GIVEN}
    rates = {s.value for s in SPECS.values() if s.grade is Grade.RATE}
    letters = {s.value: s.alias for s in SPECS.values() if s.alias}
    assert origins == {"pole"} and given == {"fixed_point"}
    assert rates == {"omega", "epsilon", "copy"}
    assert letters == {"normal": "n", "coriolis": "k"}


def _args(*argv: str) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="mechplan")
    add_parser(parser.add_subparsers(dest="command", required=True))
    return parser.parse_args(["check", "scene.toml", "sheet.dxf", *argv])


@pytest.mark.parametrize("option, text, plan, si", [
    ("--mu-l", "0.002 m/mm", Plan.POSITION, 0.002),
    ("--mu-v", "0.1 m/s/mm", Plan.VELOCITY, 0.1),
    ("--mu-a", "2 (m/s^2)/mm", Plan.ACCELERATION, 2.0),
    ("--mu-F", "0.1 kN/mm", Plan.FORCE, 100.0),
])
def test_scale_options_follow_plan_scale_keys(option: str, text: str, plan: Plan,
                                              si: float) -> None:
    assert option == "--" + plan.scale_key.replace("_", "-")
    assert parse_scales(_args(option, text)) == pytest.approx({plan: si})
    with pytest.raises(CheckError, match=re.escape(option) + " must be positive"):
        parse_scales(_args(option, "-1"))


def test_plan_names_of_the_tolerance_option() -> None:
    assert PLAN_NAMES == {"position": Plan.POSITION, "l": Plan.POSITION,
                          "velocity": Plan.VELOCITY, "v": Plan.VELOCITY,
                          "acceleration": Plan.ACCELERATION, "a": Plan.ACCELERATION,
                          "force": Plan.FORCE, "f": Plan.FORCE}
