"""Scene files (TOML) → frozen :class:`Scene`. The only code that touches raw dicts and strings."""

from .loader import load_scene, parse_scene
from .spec import Scene

__all__ = ["Scene", "load_scene", "parse_scene"]
