"""Shared test helpers (keep minimal)."""

from __future__ import annotations

import os
from collections.abc import Callable

import pytest


@pytest.fixture
def require() -> Callable[[bool, str], None]:
    """Return `check(available, what)`: skip with a reason when a tool is missing, fail if
    CI=true."""

    def check(available: bool, what: str) -> None:
        if available:
            return
        if os.environ.get("CI") == "true":
            pytest.fail(f"{what} is missing, and it is required when CI=true")
        pytest.skip(f"{what} is not available")

    return check
