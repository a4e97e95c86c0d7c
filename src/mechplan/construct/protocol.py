"""The construction protocol: one sentence per step in the reader's language, with measured lengths.

Sentences are the catalogue messages ``protocol.op.<operation>`` (``locale/<lang>/protocol.po``);
their fields are the step's subject ``{s0}``, ``{s1}``, ``{s2}``, its label ``{label}``, the
measured segments ``{m}``, its value ``{v}``, the plan's pole ``{pole}`` and, for a similarity
image, the labels ``{a}``, ``{b}`` of the two known images.
"""

from __future__ import annotations

import math

import numpy as np

from ..i18n import message, number, unit
from ..model.plans import Plan
from .graph import Construction, Evaluation
from .ops import SPECS, Drawn, OpSpec, Written
from .segments import Segment
from .step import Step
from .terms import pole_label

#: operation → message id of its sentence (kept for ``check/``, which asks whether one exists)
TEXT: dict[OpSpec, str] = {s: s.message for s in SPECS.values() if s.message}


def plan_title(plan: Plan, lang: str) -> str:
    """"Velocity plan", "План скоростей", …"""
    return message(f"protocol.plan.{plan.value}", lang)


def sense_text(value: float, lang: str) -> str:
    """"counter-clockwise" for a positive value, "clockwise" otherwise."""
    return message("protocol.sense.ccw" if value > 0 else "protocol.sense.cw", lang)


def mm(lang: str) -> str:
    """The millimetre symbol of a language (мм in Russian)."""
    return unit("mm", lang)


def vector_text(value: np.ndarray, lang: str, digits: int = 1, si_unit: str = "N") -> str:
    """"1459,8 N ∠ -120,0°": magnitude and direction (no angle for a zero vector)."""
    mag = float(np.hypot(*value))
    text = f"{number(mag, digits, lang)} {unit(si_unit, lang)}"
    if float(f"{mag:.{digits}f}") != 0:
        text += f" ∠ {number(math.degrees(math.atan2(value[1], value[0])), digits, lang)}°"
    return text


def _scalar_text(step: Step, value: float, lang: str) -> str:
    written = step.op.written
    if step.plan is Plan.FORCE:
        if written is Written.LINEAR or step.label.startswith("F_d"):   # F_d, F_d⁰ (friction)
            return f"{number(value, 2, lang)} {unit('N', lang)}"
        if written is Written.OFFSET:
            return f"{number(value * 1000, 1, lang)} {mm(lang)}"
        return f"{number(value, 2, lang)} {unit('N·m', lang)}"
    if written is Written.LINEAR:        # a linear driver: l (mm), l̇ (m/s), l̈ (m/s²)
        if step.plan is Plan.POSITION:
            return f"{number(value * 1000, 1, lang)} {mm(lang)}"
        rate = "m/s" if step.plan is Plan.VELOCITY else "m/s²"
        return f"{number(value, 3, lang)} {unit(rate, lang)}"
    if written is Written.ANGLE or step.label.startswith("θ"):
        return f"{number(math.degrees(value), 2, lang)}°"
    rate = "rad/s" if step.plan is Plan.VELOCITY else "rad/s²"
    text = f"{number(value, 3, lang)} {unit(rate, lang)}"
    if float(number(value, 3, "en")) != 0 and written is Written.RATE:
        text += f" ({sense_text(value, lang)})"
    return text


def measured(seg: Segment, ev: Evaluation, k: int, mu: float, lang: str) -> str:
    """"pb = 67.0 mm → v_B = 6.70 m/s" for one segment at position k."""
    a, b = ev[seg.start][k], ev[seg.end][k]
    length = float(np.hypot(*(b - a)))
    if seg.plan is Plan.POSITION:
        return f"{seg.name} = {number(length / mu, 1, lang)} {mm(lang)}"
    return (f"{pole_label(seg.name, lang)} = {number(length / mu, 1, lang)} {mm(lang)} → "
            f"{seg.quantity} = {number(length, 3, lang)} {unit(seg.plan.unit, lang)}")


def sentence(c: Construction, step: Step, ev: Evaluation, k: int, lang: str,
             mu: dict[Plan, float]) -> str:
    """The protocol sentence of one step at position k."""
    subject = [pole_label(s, lang) for s in step.subject] + ["", "", ""]
    segs = [s for s in c.segments if s.end == step.id and s.plan is step.plan]
    m = "; ".join(measured(s, ev, k, mu.get(s.plan, 1.0), lang) for s in segs)
    value = ev[step.id]
    if value.ndim == 1:
        v = _scalar_text(step, float(value[k]), lang)
    elif step.plan is Plan.FORCE and value.ndim == 2:
        v = vector_text(value[k], lang)
    else:
        v = ""
    label = pole_label(step.label, lang)
    msgid = step.op.message
    if msgid is None:
        return f"{label} = {v or m}"
    fields = {
        "label": label,
        "m": (": " + m) if m and step.op.written is Written.MEET else m,
        "v": v,
        "pole": "p" if step.plan is Plan.VELOCITY else pole_label("π", lang),
        "a": "",
        "b": "",
        "s0": subject[0],
        "s1": subject[1],
        "s2": subject[2],
    }
    if step.op.draw is Drawn.IMAGE_TRIANGLE:     # the two images it is similar to
        fields.update(a=pole_label(c[step.input("a")].label, lang),
                      b=pole_label(c[step.input("b")].label, lang))
    return message(msgid, lang, **fields)


def protocol(c: Construction, ev: Evaluation, k: int, lang: str, mu: dict[Plan, float],
             plans: tuple[Plan, ...]) -> list[tuple[Plan, str, str]]:
    """(plan, label, sentence) for every evaluated step of the given plans at position k."""
    out = []
    for step in c:
        if step.plan in plans and step.id in ev.values and step.op.message is not None:
            out.append(
                (step.plan, pole_label(step.label, lang), sentence(c, step, ev, k, lang, mu))
            )
    return out
