"""Run one fuzz case of the command line in a forked child with limits, and judge it.

The child is forked from the test process (mechplan already imported: a case costs milliseconds,
not an interpreter start), gets an address-space limit (``resource.setrlimit``), runs
``mechplan.cli.main`` in-process with its working directory inside the case's output folder, and
is killed past a time limit. A case passes when the exit code is one its command may give, stderr
holds no traceback, and nothing was created, changed or removed outside the output folder: the
folder above the case's own, the test process's working directory and the case's inputs are
listed before and after.
"""

from __future__ import annotations

import os
import resource
import signal
import sys
import tempfile
import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path

#: what each command may exit with (solve: 3 = flagged; check and batch: 1 = something wrong)
CODES = {"solve": {0, 2, 3}, "draw": {0, 2}, "check": {0, 1, 2}, "batch": {0, 1, 2}}


@dataclass
class Case:
    """Input files (name → bytes, written to ``in/``) and the arguments of ``mechplan``;
    ``{in}`` and ``{out}`` in an argument stand for the input and output folders."""

    kind: str
    files: dict[str, bytes]
    argv: list[str]
    note: str = ""


@dataclass
class Outcome:
    """What a case did."""

    case: Case
    code: int | None
    stderr: str
    seconds: float
    problems: list[str] = field(default_factory=list)


#: caches other tests and tools running beside the campaign (pytest-xdist) write in the working
#: directory
_TOOL_CACHES = {".hypothesis", ".pytest_cache", ".ruff_cache", ".mypy_cache", "__pycache__",
                ".import_linter_cache"}


def _listing(folder: Path, recursive: bool = False) -> dict[str, tuple[int, int]]:
    """Names (relative) → (size, mtime in ns) of a folder's entries; a folder's own size and time
    are left out (a tool writing inside one is not the case writing beside it)."""
    out: dict[str, tuple[int, int]] = {}
    try:
        entries = folder.rglob("*") if recursive else folder.iterdir()
        for p in entries:
            if not recursive and (p.name in _TOOL_CACHES or p.name.startswith(".coverage")):
                continue
            try:
                st = p.lstat()
            except OSError:
                continue
            is_dir = p.is_dir() and not p.is_symlink()
            out[str(p.relative_to(folder))] = (0, 0) if is_dir else (st.st_size, st.st_mtime_ns)
    except OSError:
        pass
    return out


def _child(argv: list[str], out: Path, log: Path, memory: int) -> None:
    """Run the command in the forked child; never returns."""
    code = 97
    try:
        resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        os.chdir(out)
        tempfile.tempdir = str(out)               # temporary files count as the output's
        os.environ["TMPDIR"] = str(out)
        os.environ["MECHPLAN_MEMORY_BUDGET"] = f"{memory // 4}"
        for fd, name in ((1, "stdout"), (2, "stderr")):
            handle = os.open(log / name, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
            os.dup2(handle, fd)
            os.close(handle)
        sys.stdout = open(1, "w", encoding="utf-8", errors="replace", closefd=False)  # noqa: SIM115
        sys.stderr = open(2, "w", encoding="utf-8", errors="replace", closefd=False)  # noqa: SIM115
        sys.stdin = open(os.devnull, encoding="utf-8")                                # noqa: SIM115
        from mechplan.cli import main

        try:
            code = main(argv)
        except SystemExit as exc:                 # argparse: 2
            code = exc.code if isinstance(exc.code, int) else 2
    except BaseException:                         # noqa: BLE001 - this is what the case looks for
        traceback.print_exc()
        code = 99
    finally:
        try:
            sys.stdout.flush()
            sys.stderr.flush()
        finally:
            os._exit(code if isinstance(code, int) and 0 <= code < 256 else 98)


def run_case(case: Case, root: Path, *, seconds: float, memory: int) -> Outcome:
    """Write the case's inputs under ``root`` and run it in a forked child."""
    src, out, log = root / "in", root / "out", root / "log"
    for folder in (src, out, log):
        folder.mkdir(parents=True)
    for name, data in case.files.items():
        (src / name).parent.mkdir(parents=True, exist_ok=True)
        (src / name).write_bytes(data)
    argv = [a.replace("{in}", str(src)).replace("{out}", str(out)) for a in case.argv]
    watched = {"the case's folder": (root, False),
               "the folder around the case": (root.parent, False),
               "the working directory": (Path.cwd(), False), "the inputs": (src, True)}
    before = {name: _listing(folder, rec) for name, (folder, rec) in watched.items()}
    sys.stdout.flush()
    sys.stderr.flush()
    start = time.perf_counter()
    pid = os.fork()
    if pid == 0:
        _child(argv, out, log, memory)
    status, hung = None, False
    while True:
        done, status = os.waitpid(pid, os.WNOHANG)
        if done:
            break
        if time.perf_counter() - start > seconds:
            os.kill(pid, signal.SIGKILL)
            os.waitpid(pid, 0)
            hung = True
            break
        time.sleep(0.005)
    elapsed = time.perf_counter() - start
    stderr = (log / "stderr").read_text(encoding="utf-8", errors="replace")
    code = None if hung or status is None else (
        os.WEXITSTATUS(status) if os.WIFEXITED(status) else -os.WTERMSIG(status))
    outcome = Outcome(case, code, stderr, elapsed)
    allowed = CODES[case.argv[0]]
    if hung:
        outcome.problems.append(f"still running after {seconds:g} s")
    elif code not in allowed:
        outcome.problems.append(f"exit code {code} (expected one of {sorted(allowed)})")
    if "Traceback" in stderr:
        outcome.problems.append("a traceback in stderr")
    for name, (folder, rec) in watched.items():
        after = _listing(folder, rec)
        if name == "the folder around the case":
            after = {k: v for k, v in after.items() if k != root.name}
            before[name] = {k: v for k, v in before[name].items() if k != root.name}
        if after != before[name]:
            changed = sorted(set(after) ^ set(before[name]) | {
                k for k in after if k in before[name] and after[k] != before[name][k]})
            outcome.problems.append(f"{name} changed: {changed[:5]}")
    return outcome
