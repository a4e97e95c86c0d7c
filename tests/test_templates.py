"""Every bundled template, of every kind, is loaded, solved, reported and drawn."""

from __future__ import annotations

import json

import pytest
from scenes import ALL_TEMPLATES

from mechplan.i18n import LANGUAGES
from mechplan.studies import solve_file


@pytest.mark.parametrize("path", ALL_TEMPLATES, ids=lambda p: p.stem)
def test_template_solves_reports_and_draws(path):
    study = solve_file(path)
    doc = study.to_json()
    json.dumps(doc)                                  # serialisable as it is
    for lang in LANGUAGES:
        assert study.report(lang).strip()
    sheets = study.sheets(None, None, None, path.stem)
    assert sheets and all(s.name.startswith(path.stem) for s in sheets)
