"""mechplan: the graphical method of planar mechanism analysis, constructed step by step.

The public API (see ``docs/api.md``)::

    import mechplan
    m = mechplan.load("slider_crank.toml")      # or mechplan.loads(text_or_dict)
    sol = m.solve(phi_deg=[0, 30, 60])           # sol.r["B"], sol.v["B"], sol.omega["2"] …
    mechplan.draw("slider_crank.toml", "out", formats=["pdf"])
    mechplan.check("slider_crank.toml", "my_plan.dxf")

Names are imported on first use, so ``import mechplan`` stays light.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"

_API = ("Forces", "InertiaLoad", "Mechanism", "PairReaction", "Solution", "check", "draw",
        "load", "loads")
_ERRORS = ("MechplanError", "SceneError", "DrawingError", "CheckError", "UnreachableError",
           "SingularError", "TopologyError")

if TYPE_CHECKING:
    from .api import (
        Forces,
        InertiaLoad,
        Mechanism,
        PairReaction,
        Solution,
        check,
        draw,
        load,
        loads,
    )
    from .errors import (
        CheckError,
        DrawingError,
        MechplanError,
        SceneError,
        SingularError,
        TopologyError,
        UnreachableError,
    )


def __getattr__(name: str) -> Any:
    if name in _API:
        from . import api

        return getattr(api, name)
    if name in _ERRORS:
        from . import errors

        return getattr(errors, name)
    raise AttributeError(f"module 'mechplan' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted({*globals(), *_API, *_ERRORS})


__all__ = [
    "CheckError", "DrawingError", "Forces", "InertiaLoad", "Mechanism", "MechplanError",
    "PairReaction", "SceneError", "SingularError", "Solution", "TopologyError",
    "UnreachableError", "__version__", "check", "draw", "load", "loads",
]
