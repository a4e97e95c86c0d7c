"""The same class and sweep on a real Dask cluster (2 local worker processes) as embedded."""

from __future__ import annotations

import json
from pathlib import Path

import pyarrow.parquet as pq

from mechplan.batch import Variant, run_class
from mechplan.batch.plan import parse_vary
from mechplan.batch.sweep import run_sweep

SLIDER = (Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates"
          / "slider_crank.toml")
CLASS = [Variant("a", "A", {"links.1.lengths.OA": "90 mm"}),
         Variant("b", "B", {"links.1.lengths.OA": "110 mm"}),
         Variant("x", "X", {"links.1.lengths.OA": "600 mm"})]
AXES = [parse_vary("links.1.lengths.OA=80mm..120mm:5"),
        parse_vary("links.2.lengths.AB=300mm..400mm:4")]


def test_class_and_sweep_on_a_local_cluster_equal_the_embedded_run(tmp_path, require):
    try:
        import distributed
    except ImportError:
        distributed = None
    require(distributed is not None, "dask.distributed (pip install 'mechplan[cluster]')")
    assert distributed is not None
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  host="127.0.0.1", dashboard_address=None) as cluster:
        address = cluster.scheduler_address
        on_cluster = run_class(SLIDER, CLASS, tmp_path / "c", formats=("svg",), scheduler=address,
                               progress=False)
        sweep_cluster = run_sweep(SLIDER, AXES, tmp_path / "sc", positions=90, chunk=5,
                                  scheduler=address, progress=False)
        # the tasks ran in the cluster's worker processes
        logs = cluster.get_logs()
        assert len([k for k in logs if k != "Scheduler"]) >= 2
    embedded = run_class(SLIDER, CLASS, tmp_path / "e", formats=("svg",), workers=1,
                         progress=False)
    sweep_embedded = run_sweep(SLIDER, AXES, tmp_path / "se", positions=90, chunk=5, workers=1,
                               progress=False)
    def rows(result, folder):
        return [{k: str(v).replace(str(tmp_path / folder), "DIR") for k, v in r.items()}
                for r in result.rows]

    assert rows(on_cluster, "c") == rows(embedded, "e") and on_cluster.failed == 1
    for sid in ("a", "b"):
        keys = [json.loads((tmp_path / d / sid / "answer_key.json").read_text(encoding="utf-8"))
                for d in ("c", "e")]
        assert keys[0] == keys[1]
    assert sweep_cluster.chunks == 4
    assert pq.read_table(sweep_cluster.parquet).equals(pq.read_table(sweep_embedded.parquet))

