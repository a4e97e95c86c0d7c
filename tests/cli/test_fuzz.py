"""Malformed scenes never end in a traceback: only MechplanError (exit code 2).

Hypothesis mutates the templates (replaces, deletes or adds values at random key paths) and reads,
solves and reports each result. ``MECHPLAN_FUZZ_EXAMPLES=5000`` runs thousands; the default keeps
the suite fast.
"""

from __future__ import annotations

import copy
import json
import os
import tomllib
from pathlib import Path
from typing import Any

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import mechplan

ROOT = Path(__file__).resolve().parents[2]
SCENES = {p.stem: tomllib.loads(p.read_text(encoding="utf-8"))
          for p in sorted((ROOT / "templates").glob("*.toml"))}
EXAMPLES = int(os.environ.get("MECHPLAN_FUZZ_EXAMPLES", "200"))

junk = st.one_of(
    st.sampled_from(["", "0 mm", "-5 mm", "1e300 mm", "1,0,0 mm", "80", "abc", "800 rpm",
                     "60 deg", "nan mm", "inf N", "left of A->B", "+", "midpoint A B", "Q",
                     "0.5 of A Z", "1 MPa", "cw", "+x", "x", "-y", "3.1 kg", "0 rad/s",
                     "1e-300 mm", "1 m/s", "ω", "[", "max"]),
    st.integers(-10**6, 10**6), st.floats(allow_nan=True, allow_infinity=True),
    st.booleans(), st.just([]), st.just({}), st.lists(st.sampled_from(["0 mm", "1 mm", 3]),
                                                      max_size=3),
)


def _paths(node: Any, prefix: tuple = ()) -> list[tuple]:
    out = [prefix] if prefix else []
    if isinstance(node, dict):
        for k, v in node.items():
            out += _paths(v, (*prefix, k))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            out += _paths(v, (*prefix, i))
    return out


def _mutate(data: dict, draw: st.DrawFn) -> dict:
    data = copy.deepcopy(data)
    for _ in range(draw(st.integers(1, 3))):
        paths = _paths(data)
        if not paths:
            break
        path = draw(st.sampled_from(paths))
        parent = data
        for k in path[:-1]:
            parent = parent[k]
        action = draw(st.sampled_from(["replace", "delete", "add"]))
        if action == "replace":
            parent[path[-1]] = draw(junk)
        elif action == "delete":
            del parent[path[-1]]
        elif isinstance(parent, dict):
            parent[draw(st.sampled_from(["force", "speed", "Z", "count", "points", "at"]))] = \
                draw(junk)
    return data


@st.composite
def scenes(draw: st.DrawFn) -> dict:
    return _mutate(SCENES[draw(st.sampled_from(sorted(SCENES)))], draw)


@settings(max_examples=EXAMPLES, deadline=None, derandomize=True,
          suppress_health_check=list(HealthCheck))
@given(scenes())
def test_malformed_scenes_raise_only_user_errors(data: dict) -> None:
    try:
        m = mechplan.load(data)
        if not isinstance(m, mechplan.Mechanism):      # a cam, gear train or engine: solved
            assert m.report("en").strip()
            json.dumps(m.to_json())
            return
        sol = m.solve(phi_deg=[17.0, 200.0])
        for arr in sol.r.values():
            assert arr.shape == (2, 2)
        assert np.isfinite(sol.phi_deg).all()
    except mechplan.MechplanError as exc:
        text = str(exc)
        assert text and "Traceback" not in text
