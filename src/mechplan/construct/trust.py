"""Which results can be trusted: flags for poor estimates, failures a sweep survives.

Policy:
- a position the user asked for by its angle must be computable: an unreachable or singular one
  raises (:func:`validity.ensure_valid`, :func:`refuse_unbounded`);
- a sweep (N positions) never dies for one position: those that cannot be built are listed as
  :class:`Failure` and left NaN, the others are returned;
- any result whose estimated relative error exceeds the tolerance is listed as a :class:`Flag`.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..errors import MechplanError, SingularError
from ..i18n import Text, plan_title
from .estimate import UNBOUNDED, ErrorEstimate, estimate_errors
from .graph import Construction, Evaluation
from .ops import Op
from .validity import MAX_CONDITION, ensure_valid


@dataclass(frozen=True, slots=True)
class Flag:
    """A result whose estimated relative error exceeds the tolerance at one position."""

    k: int                  # position index
    phi_deg: float          # crank angle φ (scene convention); a linear driver's length, mm
    quantity: str           # "r", "v", "a", "angle", "omega", "epsilon", "R", "M" …
    subject: str            # point or link ("C", "2", "12")
    label: str              # the step's label on its plan
    group: str
    estimate: float         # relative error estimate (inf: no bound)


@dataclass(frozen=True, slots=True)
class Failure:
    """A position of a sweep that could not be built, with the reason a user reads."""

    k: int
    phi_deg: float
    reason: str


#: results legitimately undefined where their force vanishes (the line of action of a zero force)
_UNDEFINED_AT_ZERO = frozenset({Op.GUIDE_OFFSET, Op.INERTIA_OFFSET, Op.LINE_OF_ACTION})


#: the largest float below UNBOUNDED: "relative ≥ UNBOUNDED somewhere" is "may exceed this"
_BELOW_UNBOUNDED = float(np.nextafter(UNBOUNDED, 0.0))


def _checked(c: Construction, targets: Sequence[str]) -> list[str]:
    return [sid for sid in targets if c[sid].op not in _UNDEFINED_AT_ZERO]


def _subjects(c: Construction, targets: Sequence[str]) -> dict[str, tuple[str, str]]:
    out = {}
    for sid in targets:
        q = c.quantity_of(sid)
        out[sid] = q if q is not None else ("", c[sid].label)
    return out


def unbounded_positions(est: ErrorEstimate, targets: Sequence[str], n: int,
                        undefined: frozenset[str] = frozenset()) -> np.ndarray:
    """Positions where some target's error bound is 100 % of its scale or more (or unbounded)."""
    bad = np.zeros(n, dtype=bool)
    for sid in targets:
        if sid in est and sid not in undefined and est.may_exceed(sid, _BELOW_UNBOUNDED):
            bad |= ~(est.relative(sid) < UNBOUNDED)
    return bad


def refuse_unbounded(c: Construction, ev: Evaluation, est: ErrorEstimate, targets: Sequence[str],
                     file: str | None = None) -> None:
    """Raise :class:`SingularError` for the first target that cannot be bounded at a position."""
    for sid in _checked(c, targets):
        if sid not in est or not est.may_exceed(sid, _BELOW_UNBOUNDED):
            continue
        rel = est.relative(sid)
        bad = ~(rel < UNBOUNDED)
        if np.any(bad):
            step = c[sid]
            k = int(np.argmax(bad))
            phi_deg = _shown(c, ev.phi[k])
            from .plans.force_friction import unsettled
            locked = unsettled(c, ev, k)
            if locked is not None:
                raise SingularError(Text("errmsg2.trust.force_locked",
                                         {"where": _where(c, phi_deg), "reason": locked}),
                                    step=step.label, phi_deg=phi_deg, condition=math.inf,
                                    file=file)
            bound = f"{rel[k]:.1e}" if math.isfinite(rel[k]) else "no bound"
            raise SingularError(
                Text("errmsg2.trust.unbounded",
                     {"plan": plan_title(step.plan.value), "group": step.group or "I",
                      "step": step.label, "where": _where(c, phi_deg), "bound": bound}),
                step=step.label, phi_deg=phi_deg, condition=math.inf, file=file)


def _shown(c: Construction, q: float) -> float:
    """A position's coordinate as reported: φ in degrees, a linear driver's length in mm."""
    return float(q) * 1000.0 if c.drive.linear else math.degrees(float(q))


def _where(c: Construction, shown: float) -> str:
    if c.drive.linear:
        return Text("errmsg2.trust.where_linear", {"value": f"{shown:g}"})
    return Text("errmsg2.trust.where_phi", {"value": f"{shown:g}"})


def failures(c: Construction, ev: Evaluation, est: ErrorEstimate, targets: Sequence[str],
             file: str | None = None, max_condition: float = MAX_CONDITION) -> list[Failure]:
    """Positions of a sweep that cannot be built, each with the message a single solve would
    give."""
    undefined = frozenset(targets) - frozenset(_checked(c, targets))
    bad = unbounded_positions(est, targets, ev.n, undefined)
    for gap in ev.gaps.values():
        bad |= gap > 0
    for sine in ev.sines.values():
        with np.errstate(divide="ignore"):
            bad |= 1.0 / sine > max_condition
    out: list[Failure] = []
    first_of: dict[str, Failure] = {}
    for k in np.flatnonzero(bad):
        phi_deg = _shown(c, ev.phi[k])
        cause = _cause(c, ev, est, targets, int(k), max_condition)
        if cause in first_of and len(out) >= FULL_REASONS:
            # the same cause as an earlier position: say so instead of searching again
            out.append(Failure(int(k), phi_deg, f"as at {_where(c, first_of[cause].phi_deg)}: "
                                                f"{first_of[cause].reason}"))
            continue
        one = c.evaluate(ev.phi[k:k + 1])
        one.evaluate_all(targets)
        try:
            ensure_valid(c, one, file, max_condition)
            refuse_unbounded(c, one, estimate_errors(c, one, targets), targets, file)
            reason = "not computable"
        except MechplanError as exc:
            reason = exc.detail
        failure = Failure(int(k), phi_deg, reason)
        first_of.setdefault(cause, failure)
        out.append(failure)
    return out


#: failures explained in full (each needs its own search of the unreachable interval); the rest
#: refer to the first position with the same cause
FULL_REASONS = 12


def _cause(c: Construction, ev: Evaluation, est: ErrorEstimate, targets: Sequence[str], k: int,
           max_condition: float) -> str:
    """The first step that fails at position k (a meet with no solution or an ill-conditioned
    one)."""
    for sid, gap in ev.gaps.items():
        if gap[k] > 0:
            return sid
    for sid, sine in ev.sines.items():
        if not sine[k] * max_condition >= 1.0:
            return sid
    return "unbounded"


def flags(c: Construction, ev: Evaluation, est: ErrorEstimate, targets: Sequence[str],
          tolerance: float, skip: Sequence[int] = ()) -> list[Flag]:
    """Every (position, result) whose estimated relative error exceeds ``tolerance``."""
    names = _subjects(c, targets)
    skip_mask = np.zeros(ev.n, dtype=bool)
    skip_mask[list(skip)] = True
    out: list[Flag] = []
    for sid in targets:
        if sid not in est:
            continue
        undefined_at_zero = c[sid].op in _UNDEFINED_AT_ZERO
        if not undefined_at_zero and not est.may_exceed(sid, tolerance):
            continue
        rel = est.relative(sid)
        if undefined_at_zero:
            rel = np.where(np.isfinite(ev[sid]), rel, 0.0)
        for k in np.flatnonzero((rel > tolerance) & ~skip_mask):
            quantity, subject = names[sid]
            step = c[sid]
            out.append(Flag(int(k), _shown(c, ev.phi[k]), quantity, subject, step.label,
                            step.group, float(rel[k])))
    out.sort(key=lambda f: (f.k, f.quantity, f.subject))
    return out
