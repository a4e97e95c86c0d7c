"""Class tables: CSV rows, TOML students and rules, seeds stable across processes."""

from __future__ import annotations

import hashlib
import os
import subprocess
import sys
from pathlib import Path

import pytest

from mechplan.batch.keys import with_values
from mechplan.batch.plan import parse_vary
from mechplan.batch.variants import read_variants, seed_of
from mechplan.errors import SceneError

SRC = str(Path(__file__).resolve().parents[2] / "src")

RULES = """
count = 40
prefix = "s"
[rules]
"links.1.lengths.OA" = { from = "90 mm", to = "110 mm", step = "2.5 mm" }
"links.2.lengths.AB" = { from = "380 mm", to = "420 mm", digits = 1 }
"drive.speed" = { choices = ["1400 rpm", "1500 rpm", "1600 rpm"] }
[[students]]
id = "ann"
name = "Анна"
values = { "links.1.lengths.OA" = "95 mm" }
"""


def test_seed_is_sha256_of_id_and_key():
    digest = hashlib.sha256(b"s07\0links.1.lengths.OA").digest()
    assert seed_of("s07", "links.1.lengths.OA") == int.from_bytes(digest[:8], "little")


def test_rules_draw_on_the_grid_and_explicit_values_win(tmp_path):
    path = tmp_path / "class.toml"
    path.write_text(RULES, encoding="utf-8")
    rows = read_variants(path)
    assert [r.id for r in rows][:3] == ["ann", "s01", "s02"] and len(rows) == 41
    assert rows[0].name == "Анна" and rows[0].values["links.1.lengths.OA"] == "95 mm"
    oa = {float(r.values["links.1.lengths.OA"].split()[0]) for r in rows[1:]}
    assert oa <= {90.0 + 2.5 * k for k in range(9)} and len(oa) > 3
    for r in rows[1:]:
        ab = float(r.values["links.2.lengths.AB"].split()[0])
        assert 380.0 <= ab <= 420.0 and round(ab, 1) == ab
        assert r.values["drive.speed"] in ("1400 rpm", "1500 rpm", "1600 rpm")
    # the same values on a second read, and a rule's value does not depend on the other rules
    assert read_variants(path) == rows
    path.write_text(RULES.replace('"drive.speed" = { choices = ["1400 rpm", "1500 rpm", '
                                  '"1600 rpm"] }', ""), encoding="utf-8")
    again = read_variants(path)
    assert [r.values["links.2.lengths.AB"] for r in again] == \
        [r.values["links.2.lengths.AB"] for r in rows]


def test_values_regenerate_in_another_process(tmp_path):
    path = tmp_path / "class.toml"
    path.write_text(RULES, encoding="utf-8")
    code = ("import sys; from mechplan.batch.variants import read_variants; "
            "print(repr([(r.id, sorted(r.values.items())) for r in read_variants(sys.argv[1])]))")
    out = subprocess.run([sys.executable, "-c", code, str(path)], capture_output=True, text=True,
                         env={**os.environ, "PYTHONPATH": SRC, "PYTHONHASHSEED": "12345"},
                         check=True).stdout.strip()
    here = repr([(r.id, sorted(r.values.items())) for r in read_variants(path)])
    assert out == here


def test_csv_rows(tmp_path):
    path = tmp_path / "class.csv"
    path.write_text("id,name,links.1.lengths.OA,drive.speed\n"
                    "a1,Nguyễn Văn A,90 mm,1500 rpm\na2,Li Wei,,1200 rpm\n", encoding="utf-8")
    rows = read_variants(path)
    assert rows[0].values == {"links.1.lengths.OA": "90 mm", "drive.speed": "1500 rpm"}
    assert rows[1].name == "Li Wei" and rows[1].values == {"drive.speed": "1200 rpm"}


@pytest.mark.parametrize("text, words", [
    ("id,name\na,x\na,y\n", "unique"),
    ("name\nx\n", "'id'"),
    ("id\n../evil\n", "names a folder"),
])
def test_csv_errors(tmp_path, text, words):
    path = tmp_path / "class.csv"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(SceneError, match=words):
        read_variants(path)


@pytest.mark.parametrize("rule, words", [
    ('{ from = "9 mm", to = "1 mm" }', "not be below"),
    ('{ from = "1 mm" }', "both from and to"),
    ('{ choices = [] }', "non-empty"),
    ('{ from = "1 mm", to = "2 mm", step = "-1 mm" }', "positive"),
])
def test_rule_errors(tmp_path, rule, words):
    path = tmp_path / "class.toml"
    path.write_text(f'count = 2\n[rules]\n"links.1.lengths.OA" = {rule}\n', encoding="utf-8")
    with pytest.raises(SceneError, match=words):
        read_variants(path)


def test_key_paths_set_existing_tables_only():
    doc = {"links": {"1": {"lengths": {"OA": "100 mm"}}}}
    out = with_values(doc, {"links.1.lengths.OA": "90 mm"})
    assert (out["links"]["1"]["lengths"]["OA"] == "90 mm"
            and doc["links"]["1"]["lengths"]["OA"] == "100 mm")
    with pytest.raises(SceneError, match="no value at links.7.lengths.OA"):
        with_values(doc, {"links.7.lengths.OA": "90 mm"})


def test_parse_vary():
    ax = parse_vary("links.1.lengths.AB=60mm..100mm:5")
    assert ax.key == "links.1.lengths.AB" and ax.unit == "mm"
    assert ax.values == (60.0, 70.0, 80.0, 90.0, 100.0) and ax.scene_value(1) == "70 mm"
    assert parse_vary("links.2.points.S2=0,2..0,4:3").values == pytest.approx((0.2, 0.3, 0.4))
    for bad in ("AB=1..2", "AB=1mm..2cm:3", "=1..2:3"):
        with pytest.raises(SceneError):
            parse_vary(bad)
