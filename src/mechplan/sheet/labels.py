"""Moved to :mod:`mechplan.drafting.labels`; this name stays importable (same module object)."""

import importlib
import sys

sys.modules[__name__] = importlib.import_module("mechplan.drafting.labels")
