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

import importlib
import sys
import types
from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"

_API = ("Forces", "InertiaLoad", "Mechanism", "PairReaction", "Solution", "draw", "load",
        "loads")
_ERRORS = ("MechplanError", "SceneError", "DrawingError", "CheckError", "UnreachableError",
           "SingularError", "TopologyError")

if TYPE_CHECKING:
    from .api import (
        Forces,
        InertiaLoad,
        Mechanism,
        PairReaction,
        Solution,
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


class _Check:
    """``mechplan.check(scene, submission, at_deg=None)``, and the ``mechplan.check`` package.

    The public function and the subpackage share a name: calling runs :func:`mechplan.api.check`,
    attributes are those of the package (``mechplan.check.Options``, ``mechplan.check.grade``).
    """

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        from .api import check

        return check(*args, **kwargs)

    def __getattr__(self, name: str) -> Any:
        return getattr(importlib.import_module(f"{__name__}.check"), name)

    def __setattr__(self, name: str, value: Any) -> None:
        setattr(importlib.import_module(f"{__name__}.check"), name, value)

    def __repr__(self) -> str:
        return "<function mechplan.check>"


class _Package(types.ModuleType):
    """The ``mechplan`` module: ``check`` stays the callable even after
    ``import mechplan.check``."""

    @property
    def check(self) -> _Check:
        return _CHECK

    @check.setter
    def check(self, value: Any) -> None:   # the import system sets the subpackage here
        pass


_CHECK = _Check()
sys.modules[__name__].__class__ = _Package


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
