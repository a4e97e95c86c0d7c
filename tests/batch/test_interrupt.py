"""Ctrl-C and SIGKILL of a batch run with local worker processes (issue 38)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

SLIDER = (Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates"
          / "slider_crank.toml")
pytestmark = pytest.mark.skipif(not Path("/proc/self/task").is_dir(), reason="needs Linux /proc")


def start(tmp_path: Path, command: str = "batch") -> tuple[subprocess.Popen[str], Path]:
    """A class of 16 (or a sweep of 800) on two worker processes, in its own process group
    (like a terminal's); return when two variants (chunks) are done."""
    table = tmp_path / "class.toml"
    table.write_text('count = 16\n[rules]\n"links.1.lengths.OA" = { from = "80 mm", to = "100 mm",'
                     ' step = "1 mm" }\n', encoding="utf-8")
    out = tmp_path / "out"
    args = {"batch": ["batch", str(SLIDER), str(table), "--format", "svg"],
            "sweep": ["sweep", str(SLIDER), "--vary", "links.1.lengths.OA=80mm..400mm:40",
                      "--vary", "links.2.lengths.AB=300mm..420mm:400", "--chunk", "7",
                      "--positions", "7200"]}[command]
    # Ctrl-C as in a terminal: a pytest-xdist worker ignores SIGINT and a child would inherit
    # that; a handler of our own is reset to the default when the child starts
    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        proc = subprocess.Popen([sys.executable, "-m", "mechplan.cli", *args, "-o", str(out),
                                 "-j", "2", "--no-progress"], stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True, start_new_session=True)
    finally:
        signal.signal(signal.SIGINT, before)
    deadline = time.monotonic() + 120
    while len(markers(out)) < 2:
        assert proc.poll() is None and time.monotonic() < deadline, proc.communicate()
        time.sleep(0.05)
    return proc, out


def markers(out: Path) -> list[Path]:
    return [*out.glob("*/.complete"), *out.glob("parts-*/part-*.parquet")]


def workers_of(pid: int) -> list[int]:
    children = [int(c) for t in Path(f"/proc/{pid}/task").iterdir()
                for c in (t / "children").read_text().split()]
    return [c for c in children if "popen_loky" in Path(f"/proc/{c}/cmdline").read_text(
        errors="replace")]


def alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except FileNotFoundError:
        return False
    return state != "Z"


@pytest.mark.parametrize("command", ["batch", "sweep"])
def test_ctrl_c_prints_one_line_and_no_worker_traceback(tmp_path, command):
    proc, _ = start(tmp_path, command)
    os.killpg(proc.pid, signal.SIGINT)            # what Ctrl-C in a terminal does
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 130
    assert err == ("mechplan: interrupted; completed outputs are kept, run the same command "
                   "again to resume\n")


def test_sigkill_of_the_main_process_stops_the_workers(tmp_path):
    proc, out = start(tmp_path)
    workers = workers_of(proc.pid)
    assert len(workers) == 2
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    done = len(markers(out))
    deadline = time.monotonic() + 5
    while any(alive(w) for w in workers) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not any(alive(w) for w in workers)
    time.sleep(2)
    assert len(markers(out)) == done                # nobody goes on writing
    proc.communicate()
    # what a kill in the middle of a write leaves; the resume removes it and completes the class
    todo = sorted({f"v{k:02d}" for k in range(1, 17)} - {m.parent.name for m in markers(out)})
    (out / todo[0]).mkdir(exist_ok=True)
    (out / todo[0] / ".answer_key.pdf.x1.tmp").write_bytes(b"half")
    (out / ".summary.csv.x2.tmp").write_bytes(b"half")
    again = subprocess.run([sys.executable, "-m", "mechplan.cli", "batch", str(SLIDER),
                            str(tmp_path / "class.toml"), "-o", str(out), "--format", "svg",
                            "-j", "2", "--no-progress"], capture_output=True, text=True,
                           timeout=300, check=False)
    assert again.returncode == 0, again.stderr
    assert f"{16 - done} solved, {done} complete already" in again.stdout
    assert len(list(out.glob("*/.complete"))) == 16 and not list(out.rglob("*.tmp"))


def test_a_second_run_into_the_same_folder_is_refused(tmp_path):
    proc, out = start(tmp_path, "sweep")
    second = subprocess.run([sys.executable, "-m", "mechplan.cli", "sweep", str(SLIDER),
                             "--vary", "links.1.lengths.OA=80mm..400mm:40", "-o", str(out),
                             "-j", "1", "--no-progress"], capture_output=True, text=True,
                            timeout=120, check=False)
    assert proc.poll() is None                      # the first one is still at work
    os.killpg(proc.pid, signal.SIGINT)
    proc.communicate(timeout=60)
    assert second.returncode == 2
    assert "another mechplan run is writing into this folder" in second.stderr
