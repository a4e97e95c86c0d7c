"""The ``mechplan synth`` subcommand: a synthesis scene in, a mechanism scene file out."""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import Any

from ..errors import SceneError
from ..i18n import LANGUAGES, Text


def _synth(args: argparse.Namespace) -> int:
    from ..outputs import prepare_dir
    from ..studies import solve_file
    from ..studies.synthesis import SynthesisStudy

    study = solve_file(args.scene)
    if not isinstance(study, SynthesisStudy):
        raise SceneError(Text("synth.error.not_synthesis"), file=args.scene, key="kind")
    out = prepare_dir(args.output)
    written = study.write_files(out, Path(args.scene).stem)
    if args.json:
        doc = study.to_json()
        doc["written"] = [str(p) for p in written]
        print(json.dumps(doc, ensure_ascii=False, indent=1))
    else:
        print(study.report(args.lang), end="")
        for p in written:
            print(p)
    return 0


def add_parser(subparsers: Any) -> None:
    """Register ``mechplan synth``."""
    s = subparsers.add_parser(
        "synth", help="synthesise a linkage from K and its stroke or swing; write its scene",
        description="Solve a synthesis scene (kind = \"synthesis\"), print its construction "
        "protocol and conditions, and write the mechanism scene <SCENE>-mechanism.toml that "
        "`mechplan solve` and `mechplan draw` take as it is.")
    s.add_argument("scene")
    s.add_argument("-o", "--output", default=".", help="output folder (default: .)")
    s.add_argument("--lang", choices=LANGUAGES)
    s.add_argument("--json", action="store_true", help="one JSON document, SI units")
    s.set_defaults(func=_synth)
