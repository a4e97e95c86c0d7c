"""Files a user gives mechplan (issue 38): only regular files under a size limit are read, without
blocking on a FIFO; data files a scene names stay inside its folder; errors name the file and the
key and never echo what a file holds."""

from __future__ import annotations

import concurrent.futures
import csv
import io
import os
import subprocess
import sys
from pathlib import Path

import pytest

from mechplan import limits
from mechplan.batch import Variant, run_class
from mechplan.batch.variants import read_variants
from mechplan.errors import CheckError, SceneError
from mechplan.scene import load_scene
from mechplan.scene.engine import parse_engine_scene
from mechplan.studies import solve_file
from mechplan.submission.read import read_submission
from mechplan.userfiles import DATA, SCENE, data_file, read_bytes

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "engine"))
from helpers import moto

FOUR_BAR = Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates" / "four_bar.toml"
SECRET = "root:x:0:0:SECRET-FIRST-LINE:/root:/bin/bash"


def _within(seconds: float, fifo: Path, call):
    """Run ``call`` in a thread; if it blocks, a writer opening ``fifo`` frees it and the test
    fails."""
    pool = concurrent.futures.ThreadPoolExecutor(1)
    future = pool.submit(call)
    try:
        return future.result(timeout=seconds)
    except concurrent.futures.TimeoutError:
        fd = os.open(fifo, os.O_WRONLY | os.O_NONBLOCK)
        os.close(fd)
        pytest.fail(f"reading the FIFO {fifo} blocked for {seconds} s")
    finally:
        pool.shutdown(wait=False)


def _raises(call, error):
    try:
        call()
    except error as exc:
        return exc
    pytest.fail(f"{call} raised no {error.__name__}")


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs on this system")
@pytest.mark.parametrize(("name", "reader", "error"), [
    ("scene.toml", load_scene, SceneError),
    ("scene.toml", solve_file, SceneError),
    ("class.csv", read_variants, SceneError),
    ("ivanov.dxf", read_submission, CheckError),
    ("ivanov.csv", read_submission, CheckError),
    ("ivanov.toml", read_submission, CheckError),
    ("ivanov", read_submission, CheckError),
])
def test_a_fifo_is_refused_without_blocking(tmp_path, name, reader, error):
    fifo = tmp_path / name
    os.mkfifo(fifo)
    exc = _within(10.0, fifo, lambda: _raises(lambda: reader(fifo), error))
    assert "FIFO" in str(exc) and str(fifo) in str(exc)


@pytest.mark.parametrize("device", ["/dev/zero", "/dev/urandom"])
@pytest.mark.parametrize(("reader", "error"), [(load_scene, SceneError),
                                               (read_variants, SceneError),
                                               (read_submission, CheckError)])
def test_a_device_is_refused_before_reading(tmp_path, device, reader, error):
    if not os.path.exists(device):
        pytest.skip(f"no {device} here")
    suffix = {read_variants: ".csv", read_submission: ".dxf"}.get(reader, ".toml")
    link = tmp_path / f"input{suffix}"
    link.symlink_to(device)
    exc = _raises(lambda: reader(link), error)
    assert "device" in str(exc) and str(link) in str(exc)


def test_a_file_over_its_limit_is_refused_before_reading(tmp_path):
    big = tmp_path / "huge.dxf"
    with big.open("wb") as fh:                      # sparse: no disk used, nothing to read
        fh.truncate(limits.DXF_MAX_BYTES + 1)
    exc = _raises(lambda: read_submission(big), CheckError)
    assert "at most 128.0 MB" in str(exc) and str(big) in str(exc)
    scene = tmp_path / "huge.toml"
    with scene.open("wb") as fh:
        fh.truncate(limits.SCENE_MAX_BYTES + 1)
    exc = _raises(lambda: load_scene(scene), SceneError)
    assert "scene file must be at most 4.0 MB" in str(exc)


def test_a_folder_and_a_missing_file(tmp_path):
    assert "not a folder" in str(_raises(lambda: read_bytes(tmp_path, SCENE, error=SceneError),
                                         SceneError))
    exc = _raises(lambda: load_scene(tmp_path / "nothing.toml"), SceneError)
    assert "does not exist" in str(exc) and "nothing.toml" in str(exc)


def test_a_scene_that_is_not_utf8_names_the_byte_not_the_text(tmp_path):
    scene = tmp_path / "latin.toml"
    scene.write_bytes(b'title = "caf\xe9 SECRET"\n')
    exc = _raises(lambda: load_scene(scene), SceneError)
    assert "UTF-8" in str(exc) and "SECRET" not in str(exc)


def test_a_regular_file_is_read_whole(tmp_path):
    f = tmp_path / "ok.csv"
    f.write_bytes(b"a,b\n" * 1000)
    assert read_bytes(f, DATA) == b"a,b\n" * 1000


# -- data files a scene names ------------------------------------------------------------------
def _engine(tmp_path: Path, name: str) -> Path:
    scene = tmp_path / "engine.toml"
    scene.write_text(moto().split("[indicator]")[0] + (
        f'[indicator]\nsource = "volume"\nunits = ["cm^3", "MPa"]\nfile = "{name}"\n'),
        encoding="utf-8")
    return scene


@pytest.mark.parametrize(("name", "why"), [("/etc/passwd", "absolute path"),
                                           ("../secret.csv", "leaves it"),
                                           ("sub/../../secret.csv", "leaves it")])
def test_a_data_file_outside_the_scene_folder_is_refused_naming_the_key(tmp_path, name, why):
    folder = tmp_path / "scenes"
    folder.mkdir()
    (tmp_path / "secret.csv").write_text(SECRET + "\n", encoding="utf-8")
    scene = _engine(folder, name)
    exc = _raises(lambda: solve_file(scene), SceneError)
    assert exc.key == "indicator.file" and why in str(exc) and str(scene) in str(exc)
    assert "SECRET" not in str(exc) and "root:" not in str(exc)


def test_a_symlink_out_of_the_scene_folder_is_refused(tmp_path):
    folder = tmp_path / "scenes"
    folder.mkdir()
    (tmp_path / "secret.csv").write_text(SECRET + "\n", encoding="utf-8")
    (folder / "pv.csv").symlink_to(tmp_path / "secret.csv")
    exc = _raises(lambda: solve_file(_engine(folder, "pv.csv")), SceneError)
    assert exc.key == "indicator.file" and "leaves it" in str(exc)


def test_a_data_file_never_echoes_its_content(tmp_path):
    (tmp_path / "pv.csv").write_text("\n".join([SECRET] * 8) + "\n", encoding="utf-8")
    exc = _raises(lambda: solve_file(_engine(tmp_path, "pv.csv")), SceneError)
    assert exc.key.startswith("indicator.file") and "SECRET" not in str(exc)


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs on this system")
def test_a_data_file_that_is_a_fifo_or_device(tmp_path):
    os.mkfifo(tmp_path / "pv.csv")
    scene = _engine(tmp_path, "pv.csv")
    exc = _within(10.0, tmp_path / "pv.csv", lambda: _raises(lambda: solve_file(scene),
                                                             SceneError))
    assert exc.key == "indicator.file" and "FIFO" in str(exc)
    (tmp_path / "z.csv").symlink_to("/dev/zero")
    exc = _raises(lambda: solve_file(_engine(tmp_path, "z.csv")), SceneError)
    assert "leaves it" in str(exc)                   # /dev/zero is outside the folder anyway


def test_a_data_dir_named_by_the_user(tmp_path):
    data = tmp_path / "data"
    data.mkdir()
    (data / "pv.csv").write_text(SECRET + "\n", encoding="utf-8")
    scene = _engine(tmp_path, "pv.csv")
    # the file is looked up in data/, found, and its content is not echoed
    exc = _raises(lambda: parse_engine_scene(scene.read_text(encoding="utf-8"), str(scene),
                                             data_dir=data), SceneError)
    assert exc.key.startswith("indicator.file") and "SECRET" not in str(exc)
    assert data_file("pv.csv", scene, key="k", data_dir=data) == (data / "pv.csv").resolve()
    with pytest.raises(SceneError, match="inside the folder"):
        data_file("../engine.toml", scene, key="k", data_dir=data, error=SceneError)


def test_a_variant_pointing_the_indicator_table_at_etc_passwd_leaks_nothing(tmp_path):
    template = _engine(tmp_path, "pv.csv")
    out = tmp_path / "class"
    try:        # the class refuses the value up front, or the scene refuses the path
        run_class(template, [Variant("s1", "Ivanov", {"indicator.file": "/etc/passwd"})], out,
                  formats=("svg",), workers=1, progress=False)
    except SceneError as exc:
        assert exc.key == "indicator.file" and "root:" not in str(exc)
    else:
        rows = list(csv.DictReader(io.StringIO((out / "summary.csv").read_text(
            encoding="utf-8"))))
        assert rows and rows[0]["error"] and "root:" not in rows[0]["error"]
    written = "".join(p.read_text(encoding="utf-8", errors="replace")
                      for p in out.rglob("*") if p.is_file() and p.suffix != ".toml")
    assert "root:" not in written


def _pv_table(folder: Path) -> Path:
    """A sound p–V table (the §3 engine's own diagram sampled every 5°)."""
    from mechplan.studies import solve_text

    base = solve_text(moto(), "m.toml")
    kin, dia = base.model.kin, base.model.diagram
    F_P = 3.141592653589793 * 0.0565 ** 2 / 4
    import numpy as np

    phi = np.radians(np.arange(0, 725, 5.0))
    V = dia.V_c + F_P * kin.x(phi)
    p = dia.at_phi(phi, kin.x(phi) / (2 * 0.0235))
    p[-1] = p[0]
    path = folder / "pv.csv"
    path.write_text("V_cm3,p_MPa\n" + "\n".join(f"{float(a) * 1e6!r},{float(b) * 1e-6!r}"
                                                  for a, b in zip(V, p)),
                    encoding="utf-8")
    return path


def test_the_command_line_names_the_data_folder(tmp_path):
    data = tmp_path / "data"
    data.mkdir()
    _pv_table(data)
    scene = _engine(tmp_path, "pv.csv")
    cmd = [sys.executable, "-m", "mechplan.cli", "solve", str(scene)]
    missing = subprocess.run(cmd, check=False, capture_output=True, text=True, timeout=300)
    assert missing.returncode == 2 and "indicator.file" in missing.stderr
    assert "does not exist" in missing.stderr and "Traceback" not in missing.stderr
    found = subprocess.run(cmd + ["--data-dir", str(data)], check=False, capture_output=True,
                           text=True, timeout=300)
    assert found.returncode == 0, found.stderr


def test_a_class_reads_the_templates_data_files(tmp_path):
    """A variant's scene is written in its own folder; its data files stay the template's."""
    _pv_table(tmp_path)
    template = _engine(tmp_path, "pv.csv")
    out = tmp_path / "class"
    run_class(template, [Variant("s1", "Ivanov", {"engine.speed": "8000 rpm"})], out,
              formats=("svg",), workers=1, progress=False)
    rows = list(csv.DictReader(io.StringIO((out / "summary.csv").read_text(encoding="utf-8"))))
    assert rows[0]["error"] == "", rows[0]["error"]
