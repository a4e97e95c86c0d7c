"""mechplan: the graphical method of planar mechanism analysis, constructed step by step."""

__version__ = "0.1.0"
