"""Dynamics: loads on the mechanism, kinetostatics results, reduced moments and inertia."""

from .loading import Loading
from .reduced import reduced_inertia, reduced_moment

__all__ = ["Loading", "reduced_inertia", "reduced_moment"]
