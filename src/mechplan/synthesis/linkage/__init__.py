"""Linkage synthesis from the time ratio K and the stroke or swing (the K-circle constructions).

Each problem gives a :class:`~.design.LinkageDesign`: the construction (drawn strokes and the
protocol), the chosen dimensions, the conditions (Grashof, transmission angle, dead centres) and
a mechanism scene that ``mechplan solve``/``draw`` analyse as it is.
"""

from __future__ import annotations

from ...errors import SceneError
from ...i18n import Text
from ...model.synthesis import SynthesisSpec
from .coulisse import coulisse
from .crank_rocker import crank_rocker
from .design import LinkageDesign, k_of_theta, theta_of_k
from .function import function_generator
from .guidance import guidance
from .path import path_generation
from .slider_crank import slider_crank


def synthesise(spec: SynthesisSpec) -> LinkageDesign:
    """Synthesise the linkage a synthesis scene asks for."""
    if spec.problem == "crank_rocker":
        return crank_rocker(spec)
    if spec.problem == "slider_crank":
        return slider_crank(spec)
    if spec.problem in ("coulisse", "shaper"):
        return coulisse(spec)
    if spec.problem == "function":
        return function_generator(spec)
    if spec.problem == "guidance":
        return guidance(spec)
    if spec.problem == "path":
        return path_generation(spec)
    raise SceneError(Text(
        "errmsg2.synthesis_linkage.unknown_problem",
        {"problem": repr(spec.problem)}), file=spec.path,
                     key="synthesis.problem")


__all__ = ["LinkageDesign", "k_of_theta", "synthesise", "theta_of_k"]
