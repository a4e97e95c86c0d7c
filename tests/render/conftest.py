"""Fixtures of the render tests: a real browser for the live page."""

from __future__ import annotations

import shutil

import pytest


@pytest.fixture
def browser(require):
    """Debian's Chromium driven by Playwright (skipped with its reason where either is missing;
    CI installs both)."""
    exe = shutil.which("chromium") or shutil.which("chromium-browser")
    require(exe is not None, "Chromium (apt-get install --no-install-recommends chromium)")
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        require(False, "Playwright for Python (pip install playwright)")
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=exe, args=["--no-sandbox", "--disable-gpu"])
        yield b
        b.close()
