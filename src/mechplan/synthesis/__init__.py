"""Synthesis: cams and gears."""
