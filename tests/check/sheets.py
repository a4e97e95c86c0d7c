"""Synthetic submissions: exact plans written as a student would, with known injected errors.

Written with plain ezdxf entities (LINE, LWPOLYLINE, TEXT, MTEXT), never with our sheet renderer,
so the reader is tested against a different writer.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field
from pathlib import Path

import ezdxf
import numpy as np

from mechplan.construct.step import Kind
from mechplan.model.plans import Plan
from mechplan.scene import load_scene
from mechplan.solve import solve

ROOT = Path(__file__).resolve().parents[2]
TEMPLATES = ROOT / "templates"


def solved(name: str, at_deg: float):
    """A template solved at one crank angle (position, velocity and acceleration plans)."""
    scene = load_scene(TEMPLATES / f"{name}.toml")
    return scene, solve(scene, at_deg=[at_deg], plans=("position", "velocity", "acceleration"))


@dataclass
class PlanSpec:
    """How one plan is drawn: its scale factor, where its pole (or first point) goes on the
    sheet."""

    mu: float
    origin: tuple[float, float]
    mu_text: str | None = None         # e.g. "μv = 0,02 m/s/mm"; None: no scale factor written
    group: str = ""                    # the group of a force polygon


@dataclass
class Student:
    """What the student does differently from the exact plan (labels as the construction's)."""

    points: dict[tuple[Plan, str], np.ndarray] = field(default_factory=dict)  # label → mm on sheet
    written: dict[tuple[Plan, str], str] = field(default_factory=dict)        # label as written
    texts: list[tuple[str, tuple[float, float]]] = field(default_factory=list)


def exact_sheet(sol, specs: dict[Plan, PlanSpec], k: int = 0) -> Student:
    """Exact plans on a sheet: every point of every segment, in mm, by label."""
    c, ev = sol.construction, sol.ev
    st = Student()
    for plan, spec in specs.items():
        anchor = None
        if plan is Plan.POSITION:
            anchor = next(s.start for s in c.segments if s.plan is plan)
        base = np.zeros(2) if anchor is None else ev[anchor][k]
        for s in c.segments:
            if s.plan is not plan or (spec.group and s.group != spec.group):
                continue
            for sid in (s.start, s.end):
                st.points[(plan, c[sid].label)] = (np.asarray(spec.origin)
                                                   + (ev[sid][k] - base) / spec.mu)
    return st


def segments(sol, plan: Plan, group: str = "") -> list[tuple[str, str]]:
    """(start label, end label) of the plan's segments (of one force polygon)."""
    c = sol.construction
    return [(c[s.start].label, c[s.end].label) for s in c.segments
            if s.plan is plan and (not group or s.group == group)]


def write_dxf(path: Path, sol, specs: dict[Plan, PlanSpec], st: Student, *, style: str = "text",
              polylines: bool = False, arrows: bool = False, units: int = 4,
              label_offset: tuple[float, float] = (0.9, 0.9), skip_labels: set = frozenset(),
              height: float = 2.5) -> Path:
    """Write the student's plans: segments as LINEs (or polylines through the pole), labels as
    TEXT ("text"), rotated TEXT ("rotated"), MTEXT with formatting codes ("mtext") or mixed."""
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = units
    msp = doc.modelspace()
    for plan, spec in specs.items():
        layer = {Plan.POSITION: "POSITION", Plan.VELOCITY: "PLAN_V",
                 Plan.ACCELERATION: "PLAN_A", Plan.FORCE: "FORCE"}[plan]
        segs = segments(sol, plan, spec.group)
        drawn = set()
        if polylines:
            # chains of segments as one LWPOLYLINE where they join end to start
            chains: list[list[str]] = []
            for a, b in segs:
                for ch in chains:
                    if ch[-1] == a:
                        ch.append(b)
                        break
                else:
                    chains.append([a, b])
            for ch in chains:
                msp.add_lwpolyline([tuple(st.points[(plan, x)]) for x in ch],
                                   dxfattribs={"layer": layer})
                drawn |= {(a, b) for a, b in itertools.pairwise(ch)}
        for a, b in segs:
            if (a, b) in drawn:
                continue
            pa, pb = st.points[(plan, a)], st.points[(plan, b)]
            msp.add_line(tuple(pa), tuple(pb), dxfattribs={"layer": layer})
            if arrows and plan is not Plan.POSITION:
                _arrow(msp, pa, pb, layer)
        done = set()
        for (p, label), at in st.points.items():
            if p is not plan or label in done or (p, label) in skip_labels:
                continue
            done.add(label)
            text = st.written.get((p, label), label)
            _label(msp, text, at, style, label_offset, height, len(done))
        if spec.mu_text:
            msp.add_text(spec.mu_text, dxfattribs={"height": 3.5}).set_placement(
                (spec.origin[0] - 10, spec.origin[1] - 25))
    for text, at in st.texts:
        msp.add_text(text, dxfattribs={"height": 3.0}).set_placement(at)
    doc.saveas(path)
    return path


def _arrow(msp, a, b, layer) -> None:
    d = np.asarray(b) - np.asarray(a)
    n = float(np.hypot(*d))
    if n < 8:
        return
    u = d / n
    for s in (1, -1):
        ang = math.radians(15) * s
        r = np.array([[math.cos(ang), -math.sin(ang)], [math.sin(ang), math.cos(ang)]])
        tail = np.asarray(b) - 4.0 * (r @ u)
        msp.add_line(tuple(b), tuple(tail), dxfattribs={"layer": layer})


def _label(msp, text, at, style, offset, height, i) -> None:
    x, y = float(at[0]) + offset[0], float(at[1]) + offset[1]
    mode = style if style != "mixed" else ("text", "rotated", "mtext")[i % 3]
    if mode == "text":
        msp.add_text(text, dxfattribs={"height": height}).set_placement((x, y))
    elif mode == "rotated":
        # rotated 30°, middle-centre aligned at a point just beside the label's point
        t = msp.add_text(text, dxfattribs={"height": height, "rotation": 30.0})
        t.set_placement((x + 1.0, y + 1.0),
                        align=ezdxf.enums.TextEntityAlignment.MIDDLE_CENTER)
    else:
        m = msp.add_mtext(_mtext_code(text), dxfattribs={"char_height": height})
        m.set_location((x, y), rotation=0.0, attachment_point=7)


def _mtext_code(text: str) -> str:
    """A label with MTEXT formatting: font, height, and n_CB as a stacked subscript."""
    if text.startswith(("n_", "k_")):
        return r"{\fArial|b0|i1;" + text[0] + r"\H0.7x;\S^" + text[2:] + ";}"
    return r"{\fArial|b0|i1;" + text + "}"


def move(st: Student, plan: Plan, label: str, delta) -> None:
    """Move one point of the student's plan by ``delta`` mm."""
    st.points[(plan, label)] = st.points[(plan, label)] + np.asarray(delta, dtype=float)


def rotate_about(st: Student, plan: Plan, label: str, centre: str, deg: float) -> None:
    """Turn one point about another by ``deg``."""
    c = st.points[(plan, centre)]
    v = st.points[(plan, label)] - c
    a = math.radians(deg)
    st.points[(plan, label)] = c + np.array([v[0] * math.cos(a) - v[1] * math.sin(a),
                                             v[0] * math.sin(a) + v[1] * math.cos(a)])


def swap(st: Student, plan: Plan, a: str, b: str) -> None:
    """Exchange the labels of two points."""
    st.points[(plan, a)], st.points[(plan, b)] = st.points[(plan, b)], st.points[(plan, a)]


def point_labels(sol, plan: Plan) -> list[str]:
    """Labels of the plan's point steps."""
    return [s.label for s in sol.construction.of_plan(plan) if s.kind is Kind.POINT]
