"""A closed profile as its own DXF: one closed LWPOLYLINE in millimetres, for CAM/CNC.

The points are given (computed upstream); this module only writes them: R2013, $INSUNITS = 4 (mm),
the origin of the drawing at the origin of the points (the cam centre), full double precision.
"""

from __future__ import annotations

import io
import os
from collections.abc import Sequence
from pathlib import Path

import ezdxf

from mechplan.errors import DrawingError
from mechplan.render.atomic import write_atomic

LAYER = "PROFILE"


def profile_bytes(points_mm: Sequence[tuple[float, float]], layer: str = LAYER) -> bytes:
    """Return the DXF file of one closed polyline through ``points_mm`` (first point not
    repeated)."""
    pts = [(float(x), float(y)) for x, y in points_mm]
    if len(pts) < 3:
        raise DrawingError(f"a closed profile must have at least 3 points (got {len(pts)})")
    doc = ezdxf.new("R2013", setup=False)
    doc.units = 4
    doc.header["$MEASUREMENT"] = 1
    doc.header["$LUNITS"] = 2
    doc.layers.add(layer, color=7, lineweight=50)
    msp = doc.modelspace()
    msp.add_lwpolyline(pts, format="xy", close=True, dxfattribs={"layer": layer})
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    doc.header["$EXTMIN"] = (min(xs), min(ys), 0.0)
    doc.header["$EXTMAX"] = (max(xs), max(ys), 0.0)
    auditor = doc.audit()
    if auditor.has_errors:
        raise DrawingError(f"DXF audit must report no errors (got {len(auditor.errors)})")
    stream = io.StringIO()
    doc.write(stream)
    return doc.encode(stream.getvalue())


def write_profile_dxf(points_mm: Sequence[tuple[float, float]], path: str | os.PathLike[str],
                      layer: str = LAYER) -> Path:
    """Write the closed profile to ``path`` atomically."""
    return write_atomic(path, profile_bytes(points_mm, layer))
