"""Large and empty submissions (issue 38): absurd tables are refused up front naming the line, a
sheet with nothing gradeable does not pass, and the fast paths for large sheets (KD-trees, an
STRtree, the label assignment split into groups) give what the brute force gives."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import ezdxf
import numpy as np
import pytest
from scipy.optimize import linear_sum_assignment

from mechplan import limits
from mechplan.batch.variants import read_variants
from mechplan.check import check
from mechplan.errors import CheckError, SceneError
from mechplan.submission.read import DrawnLine, SheetText, read_submission
from mechplan.submission.sketch import _overshoots, drawn_graph, place_labels

FOUR_BAR = Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates" / "four_bar.toml"


# -- tables --------------------------------------------------------------------------------------
def test_a_csv_cell_over_128_kb_is_refused_naming_its_line(tmp_path):
    table = tmp_path / "ivanov.csv"
    table.write_text("name,value\npb,67\npc," + "9" * (limits.CSV_CELL_MAX_CHARS + 1) + "\n",
                     encoding="utf-8")
    with pytest.raises(CheckError) as info:
        read_submission(table)
    assert info.value.key == "line 3" and "longer than 131072 characters" in str(info.value)
    assert "999" not in str(info.value)


def test_a_table_with_absurdly_many_rows_is_refused(tmp_path):
    table = tmp_path / "ivanov.csv"
    table.write_text("pb, 67\n" * (limits.TABLE_MAX_ROWS + 1), encoding="utf-8")
    with pytest.raises(CheckError, match=f"more than {limits.TABLE_MAX_ROWS} rows"):
        read_submission(table)
    toml = tmp_path / "petrov.toml"
    toml.write_text("".join(f"p{i} = {i}\n" for i in range(limits.TABLE_MAX_ROWS + 1)),
                    encoding="utf-8")
    with pytest.raises(CheckError, match="rows or values"):
        read_submission(toml)


def test_a_variants_file_names_the_id_column_and_the_line_of_a_newline(tmp_path):
    csv_file = tmp_path / "class.csv"
    csv_file.write_text('id,name\ns0,Petrov\n"s\n1",Ivanov\n', encoding="utf-8")
    with pytest.raises(SceneError) as info:
        read_variants(csv_file)
    assert info.value.key == "line 4, column id" and "'s\\n1'" in str(info.value)
    toml = tmp_path / "class.toml"
    toml.write_text('[[students]]\nid = "s\\n1"\n', encoding="utf-8")
    with pytest.raises(SceneError) as info:
        read_variants(toml)
    assert info.value.key == "students[0].id"


def test_a_variants_cell_over_128_kb_is_a_clean_error(tmp_path):
    csv_file = tmp_path / "class.csv"
    csv_file.write_text("id,name\ns1," + "x" * 200_000 + "\n", encoding="utf-8")
    with pytest.raises(SceneError) as info:
        read_variants(csv_file)
    assert info.value.key == "line 2" and "field limit" in str(info.value)


# -- nothing gradeable ---------------------------------------------------------------------------
def _reference_only(path: Path) -> Path:
    """Two lines, the pole and one point: a velocity plan whose only segment, pb, is the
    reference that fixes its unknown scale factor — nothing on it can be graded."""
    doc = ezdxf.new("R2000")
    doc.header["$INSUNITS"] = 4
    msp = doc.modelspace()
    msp.add_line((0, 0), (40, 0))
    msp.add_line((40, 0), (40, 30))
    msp.add_text("p", dxfattribs={"insert": (-3, -3), "height": 2.5})
    msp.add_text("b", dxfattribs={"insert": (41, -3), "height": 2.5})
    doc.saveas(path)
    return path


def test_a_sheet_with_nothing_gradeable_does_not_pass(tmp_path):
    sheet = _reference_only(tmp_path / "empty.dxf")
    report = check(FOUR_BAR, sheet)
    assert [r.verdict for r in report.rows if r.verdict not in ("missing", "unchecked")] == [
        "reference"]
    assert report.nothing_found and not report.passed
    assert "nothing could be graded" in report.text()
    assert report.to_json()["passed"] is False and report.to_json()["nothing_found"] is True
    assert "НЕ ЗАЧТЕНО" in report.text("ru")
    done = subprocess.run([sys.executable, "-m", "mechplan.cli", "check", str(FOUR_BAR),
                           str(sheet), "-o", str(tmp_path / "r.json")], check=False,
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 1 and "nothing could be graded" in done.stdout
    assert json.loads((tmp_path / "r.json").read_text(encoding="utf-8"))["passed"] is False


# -- the fast paths give what the brute force gives ------------------------------------------------
def _random_sheet(rng: np.random.Generator, n: int) -> list[DrawnLine]:
    starts = rng.uniform(0, 120, (n, 2))
    ends = starts + rng.uniform(-20, 20, (n, 2))
    # some lines end exactly on others' ends, so points where several lines meet exist
    ends[: n // 3] = starts[rng.integers(0, n, n // 3)]
    return [DrawnLine(tuple(a), tuple(b), f"L{i}") for i, (a, b) in enumerate(zip(starts, ends))
            if np.hypot(*(b - a)) > 1e-6]


def _overshoot_brute(nodes, end, other, degree, snap, reach=15.0):
    """The rule as it was written before (each loose end against every node)."""
    e, o = nodes[end], nodes[other]
    d = o - e
    length = float(np.hypot(*d))
    if length < 1e-9:
        return False
    u = d / length
    rel = nodes - e
    along = rel @ u
    across = np.abs(rel[:, 0] * u[1] - rel[:, 1] * u[0])
    hits = np.nonzero((along > snap) & (along < min(reach, length - snap)) & (across <= snap))[0]
    return any(degree[k] >= 2 for k in hits)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_overshoots_from_the_strtree_equal_the_brute_force(seed):
    rng = np.random.default_rng(seed)
    graph = drawn_graph(_random_sheet(rng, 400), [], 0.5)
    degree = np.asarray(graph.degree)
    assert len(graph.loose) > 100
    fast = _overshoots(graph.nodes, graph.loose, degree, 0.5)
    brute = {int(e) for e, o in graph.loose if _overshoot_brute(graph.nodes, e, o, degree, 0.5)}
    assert fast == brute and brute


def _place_brute(texts, graph, tol):
    """The label assignment as one dense problem over all labels and points (as before)."""
    nodes, n, big, k = graph.nodes, len(graph.nodes), 1e6, len(texts)
    d = np.stack([t.distance(nodes) for t in texts])
    marker = np.isin(np.arange(n), list(graph.markers))
    deco = np.where(graph.decorated(np.arange(n)), tol, 0.0)
    loose = np.array([{0: 0.45, 1: 0.45, 2: 0.15}.get(g, 0.0) for g in graph.degree]) * tol
    score = np.where(d <= tol, np.where(marker, d - 0.2 * tol, d + deco + loose), np.inf)
    best = np.argsort(score, axis=1, kind="stable")[:, :8]
    keep = np.zeros(score.shape, dtype=bool)
    np.put_along_axis(keep, best, True, axis=1)
    keep &= np.isfinite(score)
    columns = np.flatnonzero(keep.any(axis=0))
    cost = np.full((k, len(columns) + k), big)
    cost[:, :len(columns)] = np.where(keep[:, columns], score[:, columns], big)
    first = score[np.arange(k), best[:, 0]]
    cost[np.arange(k), len(columns) + np.arange(k)] = np.where(np.isfinite(first),
                                                               first + 0.5 * tol, big)
    cost += tol
    node = [-1] * k
    rows, cols = linear_sum_assignment(cost)
    for r, j in zip(rows, cols):
        if cost[r, j] < big:
            node[r] = int(columns[j] if j < len(columns) else best[r, 0])
    return node


@pytest.mark.parametrize("seed", [4, 5, 6])
def test_labels_placed_group_by_group_as_one_dense_assignment_places_them(seed):
    rng = np.random.default_rng(seed)
    lines = _random_sheet(rng, 300)
    graph = drawn_graph(lines, [], 0.5)
    texts = [SheetText(chr(97 + i % 26), tuple(rng.uniform(0, 120, 2)), 2.5, f"T{i}",
                       half=(1.0, 1.25)) for i in range(120)]
    tol = 4.0
    spots = place_labels(texts, graph, lines, tol)
    brute = _place_brute(texts, graph, tol)
    # random positions leave no ties: the same optimum is the same assignment
    assert [s.node for s in spots] == brute
    assert sum(i >= 0 for i in brute) > 30


def test_nearest_component_keeps_the_first_of_equals():
    lines = [DrawnLine((0, 0), (10, 0), "a"), DrawnLine((20, 0), (30, 0), "b")]
    graph = drawn_graph(lines, [], 0.5)
    assert graph.nearest_component((15, 0)) == graph.component[1]   # node (10, 0) comes first
    assert graph.nearest_component((15, 0), {graph.component[2]}) == graph.component[2]
    assert graph.nearest_component((15, 0), set()) == -1


@pytest.mark.parametrize("text", ["a = " + "[" * 1000 + "]" * 1000,
                                  "x = " + "{a = " * 600 + "1" + "}" * 600,
                                  "x = " + "[" * 20 + "1" + "]" * 20])
def test_a_table_nested_absurdly_deep_is_refused(tmp_path, text):
    table = tmp_path / "deep.toml"
    table.write_text(text + "\n", encoding="utf-8")
    with pytest.raises(CheckError, match=r"more than (16|32) levels"):
        read_submission(table)
    machine = FOUR_BAR.with_name("machine_unit.toml")         # an answer table of a study
    with pytest.raises(CheckError, match="levels"):
        check(machine, table)


@pytest.mark.parametrize("seed", [7, 8, 9])
def test_swaps_tried_within_groups_pair_as_all_pairs_do(seed):
    """Swapped answers are looked for among values of one angle and dimension only: the pairs
    (and their order) are those of trying every pair."""
    from mechplan.check.context import swaps

    rng = np.random.default_rng(seed)
    items = [(int(rng.integers(0, 4)), int(rng.integers(0, 3)), int(rng.integers(0, 5)))
             for _ in range(300)]        # (angle, dimension, value)

    def fits(a, b):
        return a[:2] == b[:2] and abs(a[2] - b[2]) <= 1

    everything = swaps(items, fits)
    assert len(everything) > 50
    assert swaps(items, fits, group=lambda r: r[:2]) == everything
