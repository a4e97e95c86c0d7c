"""Variants files and outputs from people mechplan does not trust (issue 38): variant keys set
only the template's values, names are data, CSV cells are never formulas, nothing is written
outside the output folder or through a link, absurd sizes are refused up front."""

from __future__ import annotations

import csv
import io
import os
import time
import tomllib
from pathlib import Path

import pyarrow as pa
import pytest

from mechplan.batch import Variant, read_variants, run_class
from mechplan.batch.check_class import check_class
from mechplan.batch.csvsafe import csv_safe, csv_safe_table
from mechplan.batch.keys import with_values
from mechplan.batch.klass import ClassJob, variant_scene, write_summary
from mechplan.check.grade import Options
from mechplan.cli import main
from mechplan.errors import MechplanError, SceneError

TEMPLATES = Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates"
SLIDER = TEMPLATES / "slider_crank.toml"
ENGINE = TEMPLATES / "motorcycle_engine.toml"


def listing(root: Path) -> set[str]:
    return {str(p.relative_to(root)) for p in root.rglob("*")}


def batch(tmp_path: Path, variants: str, *extra: str, template: Path = SLIDER,
          suffix: str = ".toml") -> tuple[int, str, str]:
    table = tmp_path / f"class{suffix}"
    table.write_text(variants, encoding="utf-8")
    code = main(["batch", str(template), str(table), "-o", str(tmp_path / "out"), "--format",
                 "svg", "-j", "1", "--no-progress", *extra])
    return code, str(table), str(tmp_path / "out")


# -- a variants file writes nothing outside -o ----------------------------------------------------
@pytest.mark.parametrize("values, words", [
    ('{ output = { csv = "/tmp/mechplan-evil.csv" } }', "got a table"),
    ('{ engine = "x" }', "has a table at engine"),
    ('{ "engine.speed" = { csv = "x" } }', "got a table"),
    ('{ "engine.nonsense" = "1" }', "no value at engine.nonsense"),
])
def test_a_variant_sets_only_values_the_template_has(tmp_path, capsys, values, words):
    code, _, out = batch(tmp_path, f'[[students]]\nid = "s1"\nvalues = {values}\n',
                             template=ENGINE)
    err = capsys.readouterr().err
    assert code == 2 and words in err and "class.toml" in err and "Traceback" not in err
    assert not Path(out).exists() and not Path("/tmp/mechplan-evil.csv").exists()


@pytest.mark.parametrize("name", ["/abs/evil.csv", "../../evil.csv", "..", "a/b.csv", "C:x.csv"])
def test_a_variant_names_no_file_outside_its_folder(name):
    doc = {"output": {"csv": "engine.csv"}, "indicator": {"file": "p.csv"}}
    with pytest.raises(SceneError, match="only name a file inside the student's folder"):
        with_values(doc, {"output.csv": name})
    with pytest.raises(SceneError, match="only name a file inside"):
        with_values(doc, {"indicator.file": name})
    assert with_values(doc, {"output.csv": "v07.csv"})["output"]["csv"] == "v07.csv"


def test_a_rule_choice_cannot_name_a_path_or_a_table(tmp_path):
    path = tmp_path / "class.toml"
    path.write_text('count = 2\n[rules]\n"output.csv" = { choices = ["../../x.csv"] }\n',
                    encoding="utf-8")
    with pytest.raises(SceneError, match="inside the student's folder"):
        read_variants(path)
    path.write_text('count = 2\n[rules]\n"output" = { choices = [{ csv = "/x" }] }\n',
                    encoding="utf-8")
    with pytest.raises(SceneError, match="got a table"):
        read_variants(path)


NAMES = ['Ann\n[output]\ncsv = "/tmp/mechplan-evil.csv"\n[x]', "A\r\nB", "tab\there",
         "nul\x00del\x7fls\u2028end", "back\\slash \"quoted\"", "Nguyễn Văn A"]


@pytest.mark.parametrize("name", NAMES)
def test_a_name_is_data_never_toml_source(name):
    job = ClassJob(ENGINE.read_text(encoding="utf-8"), str(ENGINE), "engine", "/nowhere")
    text = variant_scene(job, Variant("s1", name, {"engine.speed": "8000 rpm"}))
    doc = tomllib.loads(text)
    expected = with_values(tomllib.loads(ENGINE.read_text(encoding="utf-8")),
                           {"engine.speed": "8000 rpm"})
    assert doc == expected                          # no key was injected
    first, rest = text.split("\n", 1)
    assert first.startswith("# s1 — ") and "[output]" not in rest


def test_injected_name_in_a_real_run_writes_only_into_out(tmp_path):
    name = NAMES[0].replace('"', "'")
    code, _, out = batch(tmp_path, f'[[students]]\nid = "s1"\nname = """{name}"""\n'
                                   'values = { "links.1.lengths.OA" = "90 mm" }\n')
    assert code == 0 and not Path("/tmp/mechplan-evil.csv").exists()
    scene = (Path(out) / "s1" / "scene.toml").read_text(encoding="utf-8")
    assert "output" not in tomllib.loads(scene)
    assert listing(tmp_path) <= {"class.toml", "out", *(f"out/{p}" for p in listing(Path(out)))}


@pytest.mark.parametrize("sid", ["s01\n", "s01\ncsv = 1", "../x", ".hidden", "x" * 101])
def test_an_id_is_a_plain_folder_name(tmp_path, sid):
    path = tmp_path / "class.toml"
    path.write_text(f"[[students]]\nid = {sid!r}\n".replace("'", '"').replace("\n\"", '\\n"')
                    if "\n" not in sid else
                    "[[students]]\nid = \"" + sid.replace("\n", "\\n") + "\"\n",
                    encoding="utf-8")
    with pytest.raises(SceneError, match="student id must be"):
        read_variants(path)


# -- CSV cells are never formulas -----------------------------------------------------------------
@pytest.mark.parametrize("cell, written", [
    ("=HYPERLINK(\"http://x\")", "'=HYPERLINK(\"http://x\")"), ("+1+cmd|' /C calc'!A0", None),
    ("-2+3", None), ("@SUM(A1:A2)", None), ("\t=1", None), ("\r=1", None),
    ("-30 mm", None), ("Иван", "Иван"), ("-1.5", "-1.5"), ("+2e-3", "+2e-3"), (-7, -7),
    (-2.5, -2.5), ("", ""), (None, None)])
def test_csv_safe(cell, written):
    expected = written if written is not None or cell is None else "'" + cell
    assert csv_safe(cell) == expected


def test_class_summary_escapes_formulas_and_keeps_numbers(tmp_path):
    rows = [{"id": "s1", "name": "=1+2", "status": "ok", "error": "", "links.1.lengths.OA": -5,
             "max|v_B|": -0.25},
            {"id": "s2", "name": "@cmd", "status": "failed", "error": "-bad", "x": "+1"}]
    path = write_summary(tmp_path / "summary.csv", rows)
    got = list(csv.DictReader(io.StringIO(path.read_text(encoding="utf-8"))))
    assert got[0]["name"] == "'=1+2" and got[0]["links.1.lengths.OA"] == "-5"
    assert got[0]["max|v_B|"] == "-0.25"
    assert got[1]["name"] == "'@cmd" and got[1]["error"] == "'-bad" and got[1]["x"] == "+1"


def test_class_run_escapes_a_name(tmp_path):
    _, _, out = batch(tmp_path, "id,name,links.1.lengths.OA\ns1,=cmd|'/C calc'!A0,-90 mm\n",
                         suffix=".csv")
    rows = list(csv.DictReader((Path(out) / "summary.csv").open(encoding="utf-8")))
    assert rows[0]["name"] == "'=cmd|'/C calc'!A0"
    assert rows[0]["links.1.lengths.OA"] == "'-90 mm"      # text, not a number


def test_sweep_text_columns_are_escaped_numbers_kept():
    table = pa.table({"variant": [0, 1], "x": [-1.5, 2.0], "error": ["=1+1", ""]})
    safe = csv_safe_table(table)
    assert safe.column("error").to_pylist() == ["'=1+1", ""]
    assert safe.column("x").to_pylist() == [-1.5, 2.0]


def test_class_check_report_escapes_file_names(tmp_path):
    scenes = tmp_path / "variants"
    scenes.mkdir()
    for n in ("v1", "v2"):
        (scenes / f"{n}.toml").write_text(SLIDER.read_text(encoding="utf-8"), encoding="utf-8")
    subs = tmp_path / "class"
    subs.mkdir()
    (subs / "=HYPERLINK(1).csv").write_text("x\n", encoding="utf-8")   # no variant in its name
    rows = check_class(scenes, subs, tmp_path / "reports", Options())
    assert rows[0]["student"] == "=HYPERLINK(1)"
    text = (tmp_path / "reports" / "summary.csv").read_text(encoding="utf-8")
    assert "\n'=HYPERLINK(1),'=HYPERLINK(1).csv," in text


def test_class_check_does_not_read_a_submission_that_is_a_link(tmp_path):
    secret = tmp_path / "private.csv"
    secret.write_text("phi,60\nv_B,SECRET-CONTENT\n", encoding="utf-8")
    subs = tmp_path / "class"
    subs.mkdir()
    (subs / "ivanov.csv").symlink_to(secret)
    (subs / "petrov.csv").write_text("x\n", encoding="utf-8")
    rows = check_class(SLIDER, subs, tmp_path / "reports", Options())
    by_name = {r["student"]: r for r in rows}
    assert set(by_name) == {"ivanov", "petrov"}
    assert "symbolic link" in by_name["ivanov"]["error"]
    assert "passed" not in by_name["ivanov"] or by_name["ivanov"]["passed"] in ("", None)
    reports = tmp_path / "reports"
    assert not (reports / "ivanov.txt").exists()
    assert all("SECRET" not in p.read_text(encoding="utf-8") for p in reports.iterdir())


# -- folders: never through a link; not a folder, read-only ---------------------------------------
def test_a_student_folder_that_is_a_link_is_not_written_through(tmp_path):
    out, elsewhere = tmp_path / "out", tmp_path / "elsewhere"
    out.mkdir()
    elsewhere.mkdir()
    (out / "s1").symlink_to(elsewhere, target_is_directory=True)
    result = run_class(SLIDER, [Variant("s1", "", {}), Variant("s2", "", {})], out,
                       formats=("svg",), workers=1, progress=False)
    assert list(elsewhere.iterdir()) == []
    rows = {r["id"]: r for r in result.rows}
    assert rows["s1"]["status"] == "failed" and "symbolic link" in rows["s1"]["error"]
    assert rows["s2"]["status"] == "ok"


def test_a_parts_folder_that_is_a_link_is_refused(tmp_path, capsys):
    args = ["sweep", str(SLIDER), "--vary", "links.1.lengths.OA=80mm..120mm:3", "--positions",
            "8", "-j", "1", "--no-progress", "-o", str(tmp_path / "out")]
    assert main(args) == 0
    parts = next((tmp_path / "out").glob("parts-*"))
    elsewhere = tmp_path / "elsewhere"
    parts.rename(elsewhere)
    parts.symlink_to(elsewhere, target_is_directory=True)
    before = sorted(p.name for p in elsewhere.iterdir())
    assert main(args) == 2
    err = capsys.readouterr().err
    assert "symbolic link" in err and "Traceback" not in err
    assert sorted(p.name for p in elsewhere.iterdir()) == before


def read_only_folder(tmp_path: Path) -> Path:
    if os.geteuid() == 0:         # root writes anywhere but in sysfs
        return Path("/sys")
    folder = tmp_path / "ro"
    folder.mkdir()
    folder.chmod(0o500)
    return folder


@pytest.mark.parametrize("command", ["batch", "sweep", "check"])
@pytest.mark.parametrize("kind", ["file", "read-only", "under a file"])
def test_unusable_output_is_a_clean_error(tmp_path, capsys, command, kind):
    a_file = tmp_path / "a_file"
    a_file.write_text("x", encoding="utf-8")
    out = {"file": a_file, "read-only": read_only_folder(tmp_path),
           "under a file": a_file / "sub"}[kind]
    table = tmp_path / "class.csv"
    table.write_text("id\ns1\n", encoding="utf-8")
    subs = tmp_path / "subs"
    subs.mkdir()
    (subs / "a.csv").write_text("x\n", encoding="utf-8")
    argv = {"batch": ["batch", str(SLIDER), str(table), "-j", "1", "--no-progress"],
            "sweep": ["sweep", str(SLIDER), "--vary", "links.1.lengths.OA=80mm..90mm:2", "-j",
                      "1", "--no-progress"],
            "check": ["check", str(SLIDER), str(subs)]}[command]
    assert main([*argv, "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("mechplan: error: ") and err.count("\n") == 1, err
    assert "Traceback" not in err and str(out) in err


# -- options --------------------------------------------------------------------------------------
@pytest.mark.parametrize("extra, words", [
    (["--chunk", "-3"], "--chunk must be a whole number of variants ≥ 1 (got -3)"),
    (["--chunk", "0"], "(got 0)"),
    (["--scheduler", "nonsense"], "--scheduler must be a Dask scheduler address"),
    (["--scheduler", "tcp://host:99999"], "--scheduler must be"),
    (["--scheduler", "tcp://[::1"], "--scheduler must be"),
])
def test_bad_sweep_options(tmp_path, capsys, extra, words):
    t0 = time.monotonic()
    code = main(["sweep", str(SLIDER), "--vary", "links.1.lengths.OA=80mm..90mm:2", "-o",
                 str(tmp_path / "o"), "--no-progress", *extra])
    err = capsys.readouterr().err
    assert code == 2 and words in err and "Traceback" not in err and "Exception" not in err
    assert err.count("\n") == 1 and time.monotonic() - t0 < 15
    assert not (tmp_path / "o").exists()


# -- budgets: refused at once, with the estimate --------------------------------------------------
@pytest.mark.parametrize("count, words", [
    ("1000000000", "at most 10000 students (got 1000000000)"),
    ("1e6", "(got 1e+06)"), ("1e9", "(got 1e+09)"),
    ("100000000000000000000000000000", "(got a number of 30 digits)"),
    ("inf", "(got inf)"),
])
def test_class_budget(tmp_path, capsys, count, words):
    t0 = time.monotonic()
    code, _, _ = batch(tmp_path, f"count = {count}\n")
    err = capsys.readouterr().err
    assert code == 2 and words in err and "class.toml: key 'count'" in err, err
    assert time.monotonic() - t0 < 15   # refused, not allocated


@pytest.mark.parametrize("rule, words", [
    ('{ from = "1 mm", to = "1e400 mm" }', "must be finite numbers (got inf)"),
    ('{ from = "-1e400 mm", to = "1 mm", step = "1 mm" }', "(got -inf)"),
    ('{ from = "0 mm", to = "1e300 mm", step = "1e-300 mm" }',
     "at most 1000000000000 steps (got inf)"),
    ('{ from = "0 mm", to = "1 mm", step = "1e-320 mm" }',
     "at most 1000000000000 steps (got inf)"),
    ('{ from = "0 mm", to = "1e200 mm", step = "1 mm" }', "(got 1e+200)"),
    ('{ from = "0 mm", to = "1 mm", digits = 100000 }', "digits must be at most 12"),
])
def test_rule_budget(tmp_path, capsys, rule, words):
    t0 = time.monotonic()
    code, _, _ = batch(tmp_path, f'count = 2\n[rules]\n"links.1.lengths.OA" = {rule}\n')
    err = capsys.readouterr().err
    assert code == 2 and words in err and "rules.links.1.lengths.OA" in err, err
    assert time.monotonic() - t0 < 15   # refused, not allocated


@pytest.mark.parametrize("vary, extra, words", [
    (["links.1.lengths.OA=80mm..120mm:100000", "links.2.lengths.AB=300mm..400mm:100000"], [],
     ("10000000000 variants × 360 positions = 3600000000000 variant-positions, about "
      "1400 CPU-hours")),
    (["links.1.lengths.OA=80mm..120mm:" + "9" * 400], [], "STEPS must be at most 1000000"),
    (["links.1.lengths.OA=80mm..120mm:10"], ["--positions", "100000000000"],
     "at most 100000 positions per variant"),
    (["links.1.lengths.OA=80mm..1e400mm:10"], [], "FROM and TO must be finite"),
])
def test_sweep_budget(tmp_path, capsys, vary, extra, words):
    t0 = time.monotonic()
    code = main(["sweep", str(SLIDER), *(x for v in vary for x in ("--vary", v)), "-o",
                 str(tmp_path / "o"), "--no-progress", *extra])
    err = capsys.readouterr().err
    assert code == 2 and words in err and "Traceback" not in err, err
    assert time.monotonic() - t0 < 15   # refused, not allocated
    assert not (tmp_path / "o").exists()


def test_a_key_error_names_the_variants_file(tmp_path):
    with pytest.raises(MechplanError) as exc:
        run_class(SLIDER, [Variant("s1", "", {"links.9.mass": "1 kg"})], tmp_path,
                  variants_file="class.csv")
    assert str(exc.value).startswith("class.csv: key 'links.9.mass': the template has no value")
