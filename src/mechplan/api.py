"""The public Python API: load a scene, solve it at crank angles, draw it, check a submission.

Examples
--------
>>> import mechplan
>>> m = mechplan.load("templates/slider_crank.toml")
>>> sol = m.solve(phi_deg=[0, 30, 60])
>>> sol.r["B"].shape, sol.omega["2"].shape
((3, 2), (3,))
"""

from __future__ import annotations

import dataclasses
import math
import os
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from .errors import MechplanError, SceneError
from .i18n import Text
from .results import (
    ByName,
    Forces,
    InertiaLoad,
    PairReaction,
    Solution,
    _Columns,
    _frozen,
)
from .scene.writer import to_toml

if TYPE_CHECKING:
    from .check import CheckReport
    from .construct.graph import Construction, Evaluation
    from .model.structure import Structure
    from .scene.spec import Scene
    from .solve import Solution as _Solved
    from .studies import Study

SceneSource = str | os.PathLike[str] | Mapping[str, Any]


_KINEMATIC = ("position", "velocity", "acceleration")
_MAX_ANGLE_DEG = 1e6        # limits.MAX_ANGLE_DEG (checked by tests/api)
_RADIANS = math.pi / 180.0
_TOLERANCE = 1e-6           # construct.estimate.DEFAULT_TOLERANCE (checked by tests/api)


class Mechanism:
    """A linkage read from a scene; solve it at any crank angles.

    The construction (the graph of steps) is built once per set of plans and reused by every
    :meth:`solve` call. Create it with :func:`load` or :func:`loads`.
    """

    def __init__(self, scene: Scene) -> None:
        from .fast import FastPath

        self.scene = scene
        self._built: dict[tuple[str, ...], tuple[Structure, Construction]] = {}
        self._fast = FastPath(scene)
        #: the prepared kernel of the default call at one angle (None: not yet; False: none)
        #: the prepared kernel of a one-angle call per plans asked (None: the scene's), or False
        self._one: dict[Any, Any] = {}
        self._chosen: dict[object, tuple[str, ...]] = {}
        self._asked: dict[tuple[object, object], tuple[tuple[str, ...] | None, ...]] = {}

    def __repr__(self) -> str:
        return f"<mechplan.Mechanism {self.scene.title!r} from {self.scene.path}>"

    @property
    def title(self) -> str:
        """The scene's title."""
        return self.scene.title

    @property
    def points(self) -> tuple[str, ...]:
        """Names of the points of the moving links."""
        from .model.mechanism import GROUND

        return tuple(dict.fromkeys(p for lk in self.scene.mechanism.links.values()
                                   if lk.id != GROUND for p in lk.points))

    @property
    def links(self) -> tuple[str, ...]:
        """Ids of the moving links."""
        return tuple(self.scene.mechanism.moving)

    def construction(self, plans: Sequence[str] | None = None) -> Construction:
        """Return the construction of ``plans`` (built on first use, then reused)."""
        return self._build(self._plans(plans))[1]

    def _plans(self, plans: Sequence[str] | None) -> tuple[str, ...]:
        key = tuple(plans) if plans is not None and not isinstance(plans, str) else plans
        try:
            return self._chosen[key]
        except (KeyError, TypeError):
            pass
        out = self._check_plans(plans)
        try:
            self._chosen[key] = out
        except TypeError:
            pass
        return out

    def _check_plans(self, plans: Sequence[str] | None) -> tuple[str, ...]:
        from .scene.centres import CENTRES
        from .scene.spec import PLANS

        chosen = tuple(plans) if plans is not None else self.scene.plans
        # the instant centres are the study's (mechplan solve): the API's solution leaves them
        unknown = [p for p in chosen if p not in (*PLANS, CENTRES)]
        if unknown or not chosen:
            raise SceneError(Text("errmsg.api.plans_among_plans", {"plans": ', '.join(PLANS),
                                                                   "chosen": repr(list(chosen))}),
                             file=self.scene.path)
        return tuple(p for p in (*_KINEMATIC, "force") if p in chosen or p == "position")

    def _build(self, plans: tuple[str, ...]) -> tuple[Structure, Construction]:
        if plans not in self._built:
            from .solve import build

            self._built[plans] = build(self.scene, plans)
        return self._built[plans]

    def solve(self, phi_deg: float | Sequence[float] | np.ndarray | None = None, *,
              positions: int | None = None, plans: Sequence[str] | None = None,
              points: Sequence[str] | None = None, links: Sequence[str] | None = None,
              fast: bool | None = None) -> Solution:
        """Solve the mechanism at crank angles.

        Parameters
        ----------
        phi_deg : float or array_like, optional
            Crank angles φ in degrees (scene convention); a cylinder or slider driver: its
            length in millimetres. Default: the scene's ``[positions]``.
        positions : int, optional
            Instead of ``phi_deg``: N equal steps from the scene's start position.
        plans : sequence of str, optional
            Any of ``"position"``, ``"velocity"``, ``"acceleration"``, ``"force"`` (default:
            the scene's ``[analysis] plans``, with ``"force"`` when it has masses or loads).
        points, links : sequence of str, optional
            Compute r, v, a of these points only and angle, ω, ε of these moving links only
            (default, neither given: all of them; once one is given, the other defaults to
            none). Only the steps they need are evaluated, and only they are checked and flagged.
        fast : bool, optional
            Use the fused kernel (JIT-compiled with numba, built once per plans and outputs) for
            kinematic plans. Default: when numba is installed. Same values (to 1e-15 of each
            plan's scale), estimates and flags as the numpy path.

        Returns
        -------
        Solution
            Read-only arrays over the N positions.

        Raises
        ------
        MechplanError
            Bad arguments, positions where the mechanism cannot be assembled or is singular, or
            a position count over the memory budget.
        """
        if (type(phi_deg) is float or type(phi_deg) is int) and positions is None \
                and points is None and links is None and fast is not False:
            quick = self._solve_one(float(phi_deg), plans)      # one angle, every output
            if quick is not None:
                return quick
        from .solve import solve

        if phi_deg is not None and positions is not None:
            raise MechplanError(Text("errmsg.api.give_either_phi"))
        if positions is not None and (isinstance(positions, bool)
                                      or not isinstance(positions, (int, np.integer))
                                      or positions < 1):
            raise MechplanError(
                Text("errmsg.api.positions_whole_number", {"positions": repr(positions)})
            )
        at: np.ndarray | None = None
        if phi_deg is not None:
            arr = np.asarray(phi_deg, dtype=float)
            if arr.ndim == 0:
                arr = arr.reshape(1)
            if arr.ndim != 1 or arr.size == 0 or not np.isfinite(arr).all():
                raise MechplanError(Text("errmsg.api.phi_deg_finite", {"phi_deg": repr(phi_deg)}))
            from .limits import check_angles_deg

            check_angles_deg(arr, "phi_deg")
            at = arr
        chosen = self._plans(plans)
        asked = self._outputs(points, links)
        if fast is not False and "force" not in chosen and self.scene.textbook is None:
            quick = self._solve_fast(chosen, at, positions, asked)
            if quick is not None:
                return quick
        elif fast and "force" in chosen:
            raise MechplanError(Text("errmsg.api.fast_true_computes"))
        scene = dataclasses.replace(self.scene, points_of_interest=())
        built = self._build(chosen)
        wanted = None
        if asked != (None, None):
            from .fast import targets

            wanted = list(dict.fromkeys(targets(self.scene, built[1], chosen, *asked).values()))
            if "force" in chosen:
                wanted += built[1].force_results()
        solved = solve(scene, at_deg=at, count=int(positions) if positions else None,
                       plans=chosen, built=built, scales=False, targets=wanted)
        return _solution(solved, *asked)

    def _outputs(self, points: Sequence[str] | None, links: Sequence[str] | None
                 ) -> tuple[tuple[str, ...] | None, tuple[str, ...] | None]:
        """The points and links asked for, checked (None: all of them)."""
        if points is None and links is None:
            return None, None
        points = () if points is None else points
        links = () if links is None else links
        key = (None if points is None else tuple(points), None if links is None else tuple(links))
        if key in self._asked:
            return key                                       # type: ignore[return-value]
        for what, asked, known in (("points", points, self.points),
                                   ("links", links, self.links)):
            if asked is None:
                continue
            if isinstance(asked, str):
                raise MechplanError(Text("errmsg.api.what_sequence_names", {"what": str(what),
                                                                            "asked": repr(asked),
                                                                            "what2": str(what),
                                                                            "asked2": repr(asked)}))
            unknown = [str(x) for x in asked if str(x) not in known]
            if unknown:
                raise MechplanError(
                    Text(
                        "errmsg.api.what_among_known",
                        {
                            "what": str(what),
                            "known": ", ".join(known),
                            "repr": ", ".join(map(repr, unknown)),
                        },
                    )
                )
        key = (None if points is None else tuple(map(str, points)),
               None if links is None else tuple(map(str, links)))
        if key[0] == () and key[1] == ():
            raise MechplanError(Text("errmsg.api.points_links_not"))
        self._asked[key] = key                               # type: ignore[assignment]
        return key


    def _solve_one(self, phi_deg: float, plans: Sequence[str] | None) -> Solution | None:
        """The default call at one crank angle on the fused kernel, with none of the general
        path's argument handling (the same kernel, values, estimates and flags); None when the
        general path must answer (no kernel, a force plan, an angle it refuses, a position the
        kernel cannot build or trust)."""
        if not abs(phi_deg) <= _MAX_ANGLE_DEG:        # nan too: the general path says why
            return None
        key = tuple(plans) if plans is not None and not isinstance(plans, str) else plans
        one = self._one.get(key)
        if one is None:
            try:
                chosen = self._plans(plans)
            except SceneError:
                return None                             # the general path says why
            prepared = None
            if "force" not in chosen and self.scene.textbook is None:
                prepared = self._fast.prepare(self._build(chosen)[1], chosen, None, None)
            one = prepared if prepared is not None else False
            try:
                self._one[key] = one
            except TypeError:                           # unhashable plans: not kept
                pass
        if isinstance(one, bool):                       # False: no kernel for these plans
            return None
        # a linear driver's positions are its length in mm (as ``solve --at``)
        at = np.array([phi_deg / 1000.0 if self.scene.mechanism.drive.linear
                       else phi_deg * _RADIANS])
        block, _rel, _bad, status = one.kernel.run(at, _TOLERANCE, store=False)
        flagged: tuple[tuple[int, str, str, float], ...] = ()
        if status:                  # not buildable, untrusted or flagged: as the fused path says
            result = self._fast.evaluate(one, at)
            if result is None:
                return None
            block, flagged = result.block, result.flagged
        block.flags.writeable = False
        cols = one.columns
        phi = np.array([phi_deg])
        phi.flags.writeable = False
        return Solution(phi, _Columns(block, cols["r"], "position"),
                        _Columns(block, cols["v"], "velocity"),
                        _Columns(block, cols["a"], "acceleration"),
                        _Columns(block, cols["angle"], "angle"),
                        _Columns(block, cols["omega"], "omega"),
                        _Columns(block, cols["epsilon"], "epsilon"), None, flagged)

    def _solve_fast(self, chosen: tuple[str, ...], at: np.ndarray | None,
                    positions: int | None,
                    asked: tuple[tuple[str, ...] | None, tuple[str, ...] | None]
                    ) -> Solution | None:
        c = self._build(chosen)[1]
        prepared = self._fast.prepare(c, chosen, *asked)
        if prepared is None:
            return None
        from .solve import crank_positions, position_count

        count = int(positions) if positions else None
        n = len(at) if at is not None else position_count(self.scene, count)
        if n > 1000:
            from .limits import ensure_within_budget

            # the fused path keeps only the asked results (a point 16 bytes a position, a scalar
            # 8, each counted as a step); should it fall back, the numpy path checks its own need.
            # Checked before the angles are allocated.
            ensure_within_budget(n, len(prepared.keys), file=self.scene.path)
        linear = self.scene.mechanism.drive.linear      # positions in mm, not degrees
        phi = ((at / 1000.0 if linear else np.radians(at)) if at is not None
               else crank_positions(self.scene, c, count))
        result = self._fast.evaluate(prepared, phi)
        if result is None:
            return None
        block, cols = result.block, result.columns
        phi_deg = phi * 1000.0 if linear else np.degrees(phi)
        phi_deg.flags.writeable = False
        return Solution(phi_deg, _Columns(block, cols["r"], "position"),
                        _Columns(block, cols["v"], "velocity"),
                        _Columns(block, cols["a"], "acceleration"),
                        _Columns(block, cols["angle"], "angle"),
                        _Columns(block, cols["omega"], "omega"),
                        _Columns(block, cols["epsilon"], "epsilon"), None, result.flagged)


def _solution(s: _Solved, only_points: tuple[str, ...] | None = None,
              only_links: tuple[str, ...] | None = None) -> Solution:
    c, ev = s.construction, s.ev
    r: dict[str, np.ndarray] = {}
    v: dict[str, np.ndarray] = {}
    a: dict[str, np.ndarray] = {}
    from .fast import all_points

    points = all_points(s.scene) if only_points is None else only_points
    links = s.scene.mechanism.moving if only_links is None else only_links
    for p in points:
        _take(r, p, ev, c.position)
        if "velocity" in s.plans and c.has_result("v", p):
            _take(v, p, ev, c.velocity_image)
        if "acceleration" in s.plans and c.has_result("a", p):
            _take(a, p, ev, c.acceleration_image)
    angle: dict[str, np.ndarray] = {}
    omega: dict[str, np.ndarray] = {}
    epsilon: dict[str, np.ndarray] = {}
    for link in links:
        for quantity, out, plan, accessor in (("angle", angle, "position", c.link_angle),
                                              ("omega", omega, "velocity", c.omega),
                                              ("epsilon", epsilon, "acceleration", c.epsilon)):
            if plan in s.plans and c.has_result(quantity, link):
                out[link] = _frozen(ev.get(accessor(link)))
    forces = _forces(s.extras["forces"]) if "forces" in s.extras else None
    flags = tuple((f.k, f.quantity, f.subject, f.estimate) for f in s.flags)
    shown = s.phi * 1000.0 if s.scene.mechanism.drive.linear else np.degrees(s.phi)   # mm / °
    return Solution(_frozen(shown), ByName(r, "position"), ByName(v, "velocity"),
                    ByName(a, "acceleration"), ByName(angle, "angle"), ByName(omega, "omega"),
                    ByName(epsilon, "epsilon"), forces, flags, s.extras.get("textbook"))


def _take(out: dict[str, np.ndarray], point: str, ev: Evaluation, accessor: Any) -> None:
    try:
        sid = accessor(point)
    except KeyError:        # a point with no step on this plan (e.g. a frame point of a guide)
        return
    out[point] = _frozen(ev.get(sid))


def _forces(fa: Any) -> Forces:
    def reaction(rx: Any) -> PairReaction:
        return PairReaction(rx.key, rx.i, rx.j, rx.point, _frozen(rx.force), rx.guide,
                            None if rx.offset is None else _frozen(rx.offset))

    inertia = {k: InertiaLoad(k, _frozen(q), _frozen(m)) for k, (q, m) in fa.inertia.items()}
    return Forces(
        inertia=ByName(inertia, "inertia"),
        reactions=ByName({k: reaction(x) for k, x in fa.reactions.items()}, "reaction"),
        guide_reactions=ByName({k: reaction(x) for k, x in fa.guide_reactions.items()},
                              "guide reaction"),
        M_b=_frozen(fa.balancing_moment), M_b_zhukovsky=_frozen(fa.zhukovsky_moment),
        M_red=_frozen(fa.reduced_moment), J_red=_frozen(fa.reduced_inertia),
        friction=fa.friction)


# -- reading scenes ---------------------------------------------------------------------------

def loads(text: str | Mapping[str, Any], name: str = "<scene>") -> Mechanism | Study:
    """Read a scene from TOML text or a dict.

    Parameters
    ----------
    text : str or Mapping
        The scene as TOML text, or as the dict a TOML reader returns for it.
    name : str
        The name errors give for the scene (default ``"<scene>"``, ``"<dict>"`` for a dict).

    Returns
    -------
    Mechanism or Study
        A :class:`Mechanism` for a linkage (``kind = "mechanism"``, the default); for the other
        kinds (``"cam"``, ``"gears"``, ``"engine"``) the solved study, with ``report(language)``,
        ``to_json()`` and ``sheets(...)``.
    """
    if isinstance(text, Mapping):
        if name == "<scene>":
            name = "<dict>"
        text = to_toml(text)
    elif not isinstance(text, str):
        raise SceneError(Text("errmsg.api.scene_toml_text", {"name": str(type(text).__name__)}),
                         file=name)
    from .scene.document import parse_toml, scene_kind

    if scene_kind(parse_toml(text, name), name) == "mechanism":
        from .scene import parse_scene

        return Mechanism(parse_scene(text, name))
    from .studies import solve_text

    return solve_text(text, name)


def load(source: SceneSource) -> Mechanism | Study:
    """Read a scene file (or a dict) and return a :class:`Mechanism` or, for other kinds, a Study.

    Parameters
    ----------
    source : str, os.PathLike or Mapping
        Path of a ``.toml`` scene file, or the scene as a dict.

    Returns
    -------
    Mechanism or Study
        See :func:`loads`.

    Raises
    ------
    SceneError
        The file cannot be read, or the scene is malformed (the message names file and key).
    """
    if isinstance(source, Mapping):
        return loads(source)
    from .scene.document import read_text

    return loads(read_text(os.fspath(source)), str(source))


def _study(scene: SceneSource | Mechanism | Study) -> tuple[Study, str]:
    from .studies.mechanism import MechanismStudy

    if isinstance(scene, Mechanism):
        from .solve import solve

        return MechanismStudy(solve(scene.scene)), Path(scene.scene.path).stem or "scene"
    if isinstance(scene, Mapping):
        loaded = loads(scene)
        return _study(loaded)[0] if isinstance(loaded, Mechanism) else loaded, "scene"
    if isinstance(scene, (str, os.PathLike)):
        from .studies import solve_file

        return solve_file(os.fspath(scene)), Path(scene).stem
    return scene, "scene"


def draw(scene: SceneSource | Mechanism | Study, out_dir: str | os.PathLike[str] = ".", *,
         formats: Sequence[str] = ("dxf", "svg", "pdf"), sheet: str | None = None,
         standard: str | None = None, language: str | None = None,
         name: str | None = None) -> list[Path]:
    """Draw the sheets of a scene and return the files written.

    Parameters
    ----------
    scene : path, dict, Mechanism or Study
        What to draw; a path or dict is solved at the scene's own positions.
    out_dir : path
        Output folder, created if missing.
    formats : sequence of str
        Any of ``"dxf"``, ``"svg"``, ``"pdf"``, ``"png"``, and ``"html"``: the live page of a
        linkage, one self-contained file (docs/html.md).
    sheet, standard, language : str, optional
        ``"A0"`` … ``"A4"``; ``"iso"``, ``"gost"``, ``"tcvn"``; ``"en"``, ``"ru"``, ``"vi"``,
        ``"zh"`` (default: the scene's ``[drawing]`` and ``language``).
    name : str, optional
        Base name of the files (default: the scene file's stem).

    Raises
    ------
    MechplanError
        A bad scene, or an output folder that cannot be written (the message names it).
    """
    from .outputs import prepare_dir
    from .render import write

    study, stem = _study(scene)
    out = prepare_dir(out_dir)
    written: list[Path] = []
    fmts = [str(f).lower().lstrip(".") for f in formats]
    if "html" in fmts:
        from .live_page import write_page

        written.append(write_page(study, out, name or stem, size=sheet, standard=standard,
                                  language=language))
        fmts = [f for f in fmts if f != "html"]
    for s in study.sheets(sheet, standard, language, name or stem) if fmts else ():
        written += write(s, out, fmts)
    return written


def check(scene: SceneSource | Mechanism, submission: str | os.PathLike[str], *,
          at_deg: float | None = None) -> CheckReport:
    """Check a submission (a hand-drawn DXF, or a TOML/CSV table of values) against the scene.

    Parameters
    ----------
    scene : path, dict or Mechanism
        The scene the submission solves.
    submission : path
        A ``.dxf`` drawing, or a ``.toml`` / ``.csv`` table of measured values.
    at_deg : float, optional
        Crank angle φ of the submission (default: written on it, or the best fit).

    Returns
    -------
    mechplan.check.CheckReport
        ``passed``, ``text(language)``, ``to_json(language)`` and the rows per segment.
    """
    from .check import Options
    from .check import check as run_check

    if isinstance(scene, Mechanism):
        spec = scene.scene
    else:
        loaded = load(scene)
        if not isinstance(loaded, Mechanism):
            raise SceneError(Text("errmsg.api.only_mechanism_scenes"), key="kind")
        spec = loaded.scene
    return run_check(spec, str(submission), Options(at_deg=at_deg))


__all__ = ["ByName", "Forces", "InertiaLoad", "Mechanism", "PairReaction", "Solution", "check",
           "draw", "load", "loads", "to_toml"]
