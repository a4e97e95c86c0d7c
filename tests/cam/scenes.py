"""Cam scene texts for the tests."""

from __future__ import annotations


def cam_text(*, law="cycloidal", rise="120 deg", far="30 deg", ret="120 deg", near="90 deg",
             stroke="20 mm", contact="roller", offset="0 mm", roller="8 mm", sense="ccw",
             alpha_rise="30 deg", alpha_return="30 deg", base=None, return_law=None,
             extra_follower="", extra_limits="") -> str:
    """A translating-follower cam scene."""
    roller_line = f'roller_radius = "{roller}"' if contact == "roller" else ""
    offset_line = f'offset = "{offset}"' if offset is not None else ""
    base_line = f'base_radius = "{base}"' if base else ""
    return f"""
kind = "cam"
title = "test cam"
[follower]
motion = "translating"
contact = "{contact}"
{offset_line}
{roller_line}
{extra_follower}
[motion]
stroke = "{stroke}"
speed = "100 rad/s"
sense = "{sense}"
phases = [
  {{ kind = "rise", angle = "{rise}", law = "{law}" }},
  {{ kind = "far_dwell", angle = "{far}" }},
  {{ kind = "return", angle = "{ret}", law = "{return_law or law}" }},
  {{ kind = "near_dwell", angle = "{near}" }},
]
[limits]
pressure_angle_rise = "{alpha_rise}"
pressure_angle_return = "{alpha_return}"
{base_line}
{extra_limits}
"""


def oscillating_text(*, arm="100 mm", pivot="120 mm", roller="8 mm", sense="ccw", base=None) -> str:
    """An oscillating roller follower cam scene."""
    base_line = f'base_radius = "{base}"' if base else ""
    return f"""
kind = "cam"
[follower]
motion = "oscillating"
contact = "roller"
arm = "{arm}"
pivot_distance = "{pivot}"
roller_radius = "{roller}"
[motion]
swing = "20 deg"
speed = "30 rad/s"
sense = "{sense}"
phases = [
  {{ kind = "rise", angle = "120 deg", law = "poly345" }},
  {{ kind = "far_dwell", angle = "40 deg" }},
  {{ kind = "return", angle = "100 deg", law = "cycloidal" }},
  {{ kind = "near_dwell", angle = "100 deg" }},
]
[limits]
pressure_angle_rise = "45 deg"
pressure_angle_return = "60 deg"
{base_line}
"""
