"""docs/textbook.md as printed: its example scene is solved, its JSON obeys the documented schema
(docs/textbook.schema.json, no undocumented key), and its example answer table is graded ok."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path
from typing import Any

import pytest

from mechplan.check import check
from mechplan.scene import load_scene, parse_scene
from mechplan.solve import solve, to_json
from mechplan.textbook_report import attach, spec_from_flags

ROOT = Path(__file__).resolve().parents[2]
DOC = (ROOT / "docs" / "textbook.md").read_text(encoding="utf-8")
SCHEMA = json.loads((ROOT / "docs" / "textbook.schema.json").read_text(encoding="utf-8"))
TYPES = {"object": dict, "array": list, "string": str, "null": type(None)}


def example(name: str) -> str:
    m = re.search(r"<!-- example: " + re.escape(name) + r" -->\s*```\w*\n(.*?)```", DOC, re.DOTALL)
    assert m, f"example {name!r} is missing"
    return m.group(1)


def _is(value: Any, kind: str) -> bool:
    if kind == "number":
        return isinstance(value, (int, float)) and not isinstance(value, bool)
    return isinstance(value, TYPES[kind])


def validate(value: Any, schema: dict[str, Any], where: str = "$") -> None:
    """The subset of JSON Schema the documented schema uses."""
    if "$ref" in schema:
        schema = SCHEMA["$defs"][schema["$ref"].rsplit("/", 1)[1]]
    if "type" in schema:
        kinds = schema["type"] if isinstance(schema["type"], list) else [schema["type"]]
        assert any(_is(value, k) for k in kinds), f"{where}: {value!r} is not {kinds}"
    if "enum" in schema:
        assert value in schema["enum"], f"{where}: {value!r} not in {schema['enum']}"
    if isinstance(value, dict):
        for key in schema.get("required", []):
            assert key in value, f"{where}: {key} is missing"
        props = schema.get("properties", {})
        extra = schema.get("additionalProperties", True)
        for key, item in value.items():
            if key in props:
                validate(item, props[key], f"{where}.{key}")
            elif isinstance(extra, dict):
                validate(item, extra, f"{where}.{key}")
            else:
                assert extra is not False, f"{where}: undocumented key {key!r}"
    if isinstance(value, list) and "items" in schema:
        assert len(value) >= schema.get("minItems", 0)
        assert len(value) <= schema.get("maxItems", len(value))
        for i, item in enumerate(value):
            validate(item, schema["items"], f"{where}[{i}]")


def _keys(schema: Any) -> set[str]:
    out: set[str] = set()
    if isinstance(schema, dict):
        out |= set(schema.get("properties", {}))
        for v in schema.values():
            out |= _keys(v)
    return out


def test_every_schema_key_is_documented():
    missing = [k for k in _keys(SCHEMA) if f'"{k}"' not in DOC and k not in ("positions",)]
    assert not missing, missing


def test_the_documented_scene_gives_the_documented_json():
    sol = solve(parse_scene(example("scene textbook"), "textbook.toml"))
    doc = to_json(sol)
    validate(doc, SCHEMA)
    st = doc["textbook"]["strokes"]["B"]
    r, l, e = 0.1, 0.35, 0.05
    assert st["H"] == pytest.approx(math.sqrt((l + r) ** 2 - e ** 2)
                                    - math.sqrt((l - r) ** 2 - e ** 2), rel=1e-12)
    assert set(doc["positions"][0]["textbook"]) == {
        "sliding", "relative", "turning", "rubbing", "transmission", "least_velocity"}
    assert doc["positions"][0]["textbook"]["rubbing"]["O"]["radius"] == pytest.approx(0.025)


@pytest.mark.parametrize("template", ["shaper", "four_bar", "quick_return", "slider_crank"])
def test_templates_with_every_answer_obey_the_schema(template):
    scene = load_scene(ROOT / "templates" / f"{template}.toml")
    sol = solve(scene, at_deg=[0.0, 47.0, 180.0])
    attach(sol, spec_from_flags("all", 10.0, None))
    validate(to_json(sol), SCHEMA)


def test_the_documented_table_is_graded_ok(tmp_path):
    s, t = tmp_path / "scene.toml", tmp_path / "answers.toml"
    s.write_text(example("scene textbook"), encoding="utf-8")
    t.write_text(example("table textbook"), encoding="utf-8")
    rows = check(str(s), str(t)).values
    assert len(rows) == 4
    assert all(v.verdict == "ok" for v in rows), [(v.name, v.submitted, v.exact) for v in rows]


def test_the_public_api_carries_the_answers():
    import mechplan
    mech = mechplan.loads(example("scene textbook"), "textbook.toml")
    sol = mech.solve([30.0, 120.0])
    assert sol.textbook is not None
    assert sol.textbook.strokes[0].K == pytest.approx(
        (math.pi + math.asin(0.2) - math.asin(0.05 / 0.45))
        / (math.pi - math.asin(0.2) + math.asin(0.05 / 0.45)), rel=1e-10)
    assert sol.textbook.sliding[0].v_slide.shape == (2,)
