"""A small class of two variants (``mechplan batch``) shared by the LMS tests of other forms,
the gradebook and the schemas."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from mechplan.batch import Variant, run_class

TEMPLATES = Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates"
PHI = 30.0


@pytest.fixture(scope="session")
def small_class(tmp_path_factory):
    root = tmp_path_factory.mktemp("small_class")
    variants = root / "class"
    run_class(TEMPLATES / "slider_crank.toml",
              [Variant("v1", "", {"links.1.lengths.OA": "90 mm"}),
               Variant("v2", "", {"links.1.lengths.OA": "100 mm"})],
              variants, formats=("dxf",), workers=1, progress=False)
    key = json.loads((variants / "v1" / "answer_key.json").read_text(encoding="utf-8"))
    k = key["phi_deg"].index(PHI)
    values = {r["quantity"]: r["values"][k] for r in key["rows"]}
    return root, variants, values
