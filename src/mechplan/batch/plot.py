"""A summary of a sweep plotted against two varied keys (matplotlib PNG)."""

from __future__ import annotations

import io
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from ..errors import MechplanError
from ..i18n import Text, message
from ..render.atomic import write_atomic
from .plan import SweepPlan


def plot_summary(parquet: Path, plan: SweepPlan, column: str, keys: Sequence[str] | None,
                 path: Path, language: str = "en") -> Path:
    """Plot ``column`` over two varied keys (the other keys at their first value); write a PNG."""
    import pyarrow.parquet as pq
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    names = [a.key for a in plan.axes]
    if keys:
        chosen = list(keys)
    else:
        chosen = [a.key for a in plan.axes if len(a.values) > 1][:2]
    if len(chosen) != 2 or any(k not in names for k in chosen) or chosen[0] == chosen[1]:
        raise MechplanError(Text("batchvars.plot_keys", {"names": ", ".join(names),
                                                         "chosen": ", ".join(chosen) or "—"}))
    schema = pq.read_schema(parquet)
    if column not in schema.names:
        summaries = [c for c in schema.names if c.startswith(("max_", "min_"))]
        raise MechplanError(Text("batchvars.plot_summary", {"summaries": ", ".join(summaries),
                                                            "value": repr(column)}))
    table = pq.read_table(parquet, columns=["variant", column])
    variant = table.column("variant").to_numpy()
    value = table.column(column).to_numpy(zero_copy_only=False).astype(float)
    grid = np.unravel_index(variant, plan.shape)
    ix, iy = names.index(chosen[0]), names.index(chosen[1])
    keep = np.ones(variant.shape, dtype=bool)
    for i in range(len(names)):
        if i not in (ix, iy):
            keep &= grid[i] == 0
    ax_x, ax_y = plan.axes[ix], plan.axes[iy]
    z = np.full((len(ax_y.values), len(ax_x.values)), np.nan)
    z[grid[iy][keep], grid[ix][keep]] = value[keep]
    fig = Figure(figsize=(7.0, 5.5))
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    mesh = ax.pcolormesh(ax_x.values, ax_y.values, z, shading="nearest", cmap="viridis")
    if min(z.shape) > 1 and np.isfinite(z).sum() > 3:
        ax.contour(ax_x.values, ax_y.values, z, colors="white", linewidths=0.6)
    from .sweep import unit_of

    unit = unit_of(column)
    fig.colorbar(mesh, ax=ax, label=f"{column} [{unit}]" if unit else column)
    ax.set_xlabel(f"{ax_x.key} [{ax_x.unit}]" if ax_x.unit else ax_x.key)
    ax.set_ylabel(f"{ax_y.key} [{ax_y.unit}]" if ax_y.unit else ax_y.key)
    ax.set_title(message("batch.plot.title", language, summary=column, x=ax_x.key, y=ax_y.key))
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=120, metadata={"Software": "mechplan"})
    return write_atomic(path, buf.getvalue())
