"""Synthesis: cams (laws, base radius, inversion profile) and gears."""
