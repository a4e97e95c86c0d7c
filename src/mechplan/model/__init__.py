"""Mechanism topology and dimensions: links, pairs, guides, drive; structure analysis."""
