"""Check time against the number of DXF entities and CSV rows (issue 38).

A drawn four-bar sheet (``mechplan draw``, read back exactly) grows by random short lines spread
over the sheet (and, in the second series, one random text in ten): what a hatch exploded into
lines or a careless export gives. Each size is checked once in a fresh process (wall time and peak
memory). Writes ``benchmarks/CHECK_SCALE_RESULTS.md``.

Usage: ``python benchmarks/check_scale.py [--sizes 1000,10000,30000,100000] [--label NAME]
[--timeout 600] [--src OTHER/src] [--repeat N]``; ``--label`` names the column (e.g. ``before``
on the old code's ``--src``, ``after``): a run keeps the columns of earlier runs with other
labels. ``--repeat`` keeps the fastest of N runs (the machine may be shared).
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import random
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
RESULTS = HERE / "CHECK_SCALE_RESULTS.md"
DATA = HERE / ".check_scale_results.json"
SCENE = ROOT / "src" / "mechplan" / "templates" / "four_bar.toml"
ENGINE = ROOT / "src" / "mechplan" / "templates" / "motorcycle_engine.toml"
#: address-space limit of each measured process (MB)
MEMORY_MB = 6144

_CHILD = r"""
import json, resource, sys, time
limit = int(sys.argv[4]) * 1024**2          # never let a shared machine swap or kill others
resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
sys.path.insert(0, sys.argv[3])
from mechplan.check import check
from mechplan.errors import MechplanError
t = time.perf_counter()
try:
    r = check(sys.argv[1], sys.argv[2])
    outcome = f"{len(r.rows)} rows"
except MechplanError as exc:
    outcome = "refused: " + str(exc).split(": ", 1)[-1][:80]
except MemoryError:
    outcome = f"MemoryError (limit {sys.argv[4]} MB)"
dt = time.perf_counter() - t
peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
print(json.dumps({"seconds": dt, "peak_mb": peak, "outcome": outcome}))
"""


def base_sheet(folder: Path) -> Path:
    """Draw the four-bar sheet as DXF (once)."""
    out = folder / "four_bar.dxf"
    if not out.exists():
        subprocess.run([sys.executable, "-m", "mechplan.cli", "draw", str(SCENE), "-o",
                        str(folder), "--format", "dxf"], check=True, capture_output=True,
                       env={**os.environ, "PYTHONPATH": str(ROOT / "src")})
    return out


def grown_sheet(base: Path, entities: int, texts: bool, out: Path) -> Path:
    """The sheet ``base`` with random entities added up to ``entities`` in its model space."""
    import ezdxf

    doc = ezdxf.readfile(base)
    msp = doc.modelspace()
    rng = random.Random(entities)
    for i in range(max(0, entities - len(msp))):
        x, y = rng.uniform(20, 820), rng.uniform(20, 570)
        if texts and i % 10 == 0:
            msp.add_text(rng.choice("abcdefkmn") + str(rng.randint(1, 9)),
                         dxfattribs={"insert": (x, y), "height": 2.5})
        else:
            dx, dy = rng.uniform(-10, 10), rng.uniform(-10, 10)
            msp.add_line((x, y), (x + dx, y + dy))
    doc.saveas(out)
    return out


def csv_table(rows: int, out: Path) -> Path:
    """A CSV answer table of ``rows`` rows ``pb, 67.0`` (names cycling over the sheet's)."""
    names = ["pb", "pc", "bc", "pd", "ω2", "ω3", "VC", "VB"]
    with out.open("w", encoding="utf-8") as fh:
        fh.write("φ = 30°\n")
        for i in range(rows):
            fh.write(f"{names[i % len(names)]}, {50 + i % 7}.0\n")
    return out


def answer_table(rows: int, out: Path) -> Path:
    """An engine's answer table of ``rows`` rows of 8 values each (φ; p; Pг; Pj; P; N; T; Z;
    Mкр), angles cycling every 15°: what a student's spreadsheet export may hold."""
    lines = ["φ;p (Па);Pг (Н);Pj (Н);P (Н);N (Н);T (Н);Z (Н);Mкр (Н*м)"]
    lines += [f"{(i * 15) % 720};85000;-37,6;-3830;-3868;-431,4;-2308;-3134;-54,23"
              for i in range(rows)]
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return out


def measure(scene: Path, submission: Path, timeout: float, src: Path) -> dict[str, object]:
    """Check ``submission`` in a fresh process (mechplan from ``src``): seconds, peak MB,
    outcome."""
    try:
        done = subprocess.run([sys.executable, "-c", _CHILD, str(scene), str(submission),
                               str(src), str(MEMORY_MB)], check=False, capture_output=True,
                              text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"seconds": None, "peak_mb": None, "outcome": f"killed after {timeout:.0f} s"}
    if done.returncode:
        return {"seconds": None, "peak_mb": None,
                "outcome": "crashed: " + done.stderr.strip().splitlines()[-1][:80]}
    return dict(json.loads(done.stdout.strip().splitlines()[-1]))


def _cell(m: dict[str, object] | None) -> str:
    if m is None:
        return "—"
    if m["seconds"] is None:
        return str(m["outcome"])
    return f"{m['seconds']:.1f} s, {m['peak_mb']:.0f} MB ({m['outcome']})"


def write(data: dict[str, dict[str, dict[str, object]]], meta: dict[str, str]) -> None:
    """Write the Markdown table of every labelled run."""
    labels = list(data)
    keys = sorted({k for run in data.values() for k in run},
                  key=lambda k: (k.split(":")[0], int(k.split(":")[1])))
    lines = ["# Check time against submission size (issue 38)", "",
             "Generated by `python benchmarks/check_scale.py --label NAME`; do not edit by hand.",
             "Each cell: wall time of `mechplan.check.check(four_bar.toml, submission)` in a fresh",
             "process, its peak resident memory, and what it returned. `lines`: the drawn four-bar",
             "sheet grown by random short lines to N model-space entities; `lines+texts`: one in",
             "ten added entities is a random label text; `csv`: a CSV table of N `name, value`",
             "rows; `answers`: an engine's answer table (motorcycle_engine.toml) of N rows of 8",
             "values. The machine is shared (2 cores, 6 other developers): identical checks of",
             "small sheets vary between 0.7 and 2.2 s, so sizes below 10,000 say little; the large",
             "sizes are what this measures (`--repeat N` keeps the fastest of N runs).",
             "", *(f"- {k}: {v}" for k, v in meta.items()), "",
             "| submission | N | " + " | ".join(labels) + " |",
             "|---|---:|" + "---|" * len(labels)]
    for key in keys:
        kind, n = key.split(":")
        lines.append(f"| {kind} | {int(n):,} | "
                     + " | ".join(_cell(data[label].get(key)) for label in labels) + " |")
    RESULTS.write_text("\n".join(lines) + "\n", encoding="utf-8")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="1000,10000,30000,100000")
    parser.add_argument("--csv-sizes", default="1000,10000,30000")
    parser.add_argument("--answer-sizes", default="500,2000")
    parser.add_argument("--kinds", default="lines,lines+texts,csv,answers")
    parser.add_argument("--label", default="after")
    parser.add_argument("--timeout", type=float, default=600.0)
    parser.add_argument("--repeat", type=int, default=1, help="keep the fastest of N runs")
    parser.add_argument("--report-only", action="store_true",
                        help="rewrite the Markdown from the stored measurements")
    parser.add_argument("--src", type=Path, default=ROOT / "src",
                        help="the mechplan sources to measure (e.g. another checkout's src)")
    args = parser.parse_args()
    data = json.loads(DATA.read_text(encoding="utf-8")) if DATA.exists() else {}
    run = {} if args.report_only else data.setdefault(args.label, {})
    meta = {"machine": f"{platform.machine()}, {os.cpu_count()} logical cores (shared: load "
                       f"{os.getloadavg()[0]:.1f} at start), Python {platform.python_version()}",
            f"run {args.label}, {args.kinds} at {args.sizes} (csv {args.csv_sizes})":
                time.strftime("%Y-%m-%d %H:%M %Z")}
    kinds = [] if args.report_only else args.kinds.split(",")
    if args.report_only:
        meta = {}
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        base = base_sheet(folder) if kinds else folder
        for kind in kinds:
            sizes = {"csv": args.csv_sizes, "answers": args.answer_sizes}.get(kind, args.sizes)
            for n in (int(s) for s in sizes.split(",") if s):
                if kind == "csv":
                    sub = csv_table(n, folder / f"t{n}.csv")
                elif kind == "answers":
                    sub = answer_table(n, folder / f"a{n}.csv")
                else:
                    sub = grown_sheet(base, n, kind == "lines+texts", folder / f"s{n}.dxf")
                scene = ENGINE if kind == "answers" else SCENE
                runs = [measure(scene, sub, args.timeout, args.src)
                        for _ in range(max(1, args.repeat))]
                timed = [r for r in runs if r["seconds"] is not None]
                m = min(timed, key=lambda r: float(r["seconds"])) if timed else runs[0]  # type: ignore[arg-type]
                print(f"{args.label} {kind} {n}: {_cell(m)}", flush=True)
                run[f"{kind}:{n}"] = m
                DATA.write_text(json.dumps(data, indent=1), encoding="utf-8")
    old = {}
    if RESULTS.exists():
        old = {ln[2:].split(": ", 1)[0]: ln[2:].split(": ", 1)[1]
               for ln in RESULTS.read_text(encoding="utf-8").splitlines()
               if ln.startswith("- ") and ": " in ln}
    write(data, {**old, **meta})


if __name__ == "__main__":
    main()
