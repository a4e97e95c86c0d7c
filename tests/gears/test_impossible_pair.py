"""A gear pair that cannot exist is an error, a pair that fails a check is flagged (issue 38)."""

from __future__ import annotations

from pathlib import Path

import pytest

from mechplan.cli import FLAGGED, main
from mechplan.errors import SceneError
from mechplan.model.gears import PairSpec, ShiftRule
from mechplan.synthesis.gears.involute import pair_layout

ROOT = Path(__file__).resolve().parents[2]
TWO_ROW = (ROOT / "templates" / "planetary_two_row.toml").read_text(encoding="utf-8")


def test_addendum_10_is_an_error_naming_the_key(tmp_path, capsys) -> None:
    scene = tmp_path / "g.toml"
    scene.write_text(TWO_ROW.replace("addendum = 1.0 ", "addendum = 10.0 "), encoding="utf-8")
    assert main(["solve", str(scene), "--lang", "en"]) == 2
    err = capsys.readouterr().err
    assert "g.toml" in err and "key 'pair.addendum'" in err and "cannot be cut" in err
    assert main(["solve", str(scene)]) == 2          # the template's own language: Russian
    err = capsys.readouterr().err
    assert "ключ 'pair.addendum'" in err and "нельзя нарезать" in err and "cannot" not in err


def test_tooth_crossing_below_its_tip() -> None:
    with pytest.raises(SceneError, match="cannot be cut") as info:
        pair_layout(PairSpec(0.004, 12, 20, shifts=(3.0, 0.0)))
    assert info.value.key == "pair.shifts"
    with pytest.raises(SceneError, match="cannot be cut"):
        pair_layout(PairSpec(0.004, 17, 34, addendum=10.0, rule=ShiftRule.BALANCED))


def test_interference_is_flagged_not_clean(tmp_path, capsys) -> None:
    scene = tmp_path / "g.toml"
    scene.write_text(TWO_ROW.replace('shift_rule = "balanced_sliding"', 'shift_rule = "given"')
                     .replace("teeth = [17, 34]", "teeth = [10, 60]"), encoding="utf-8")
    assert main(["solve", str(scene), "--lang", "en"]) == FLAGGED
    captured = capsys.readouterr()
    assert "warning: Gear 1: lowest contact point" in captured.err
    assert "fails" in captured.err and "Largest specific sliding" in captured.out


def test_template_pair_is_clean(capsys) -> None:
    assert main(["solve", str(ROOT / "templates" / "planetary_two_row.toml")]) == 0
    assert capsys.readouterr().err == ""
