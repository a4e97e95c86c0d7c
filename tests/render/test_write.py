"""`render.write` dispatch and atomic output."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from mechplan import render
from mechplan.errors import DrawingError
from mechplan.render import atomic, mpl
from mechplan.render.atomic import write_atomic

from .samples import sample_sheet


def test_write_all_formats_to_directory(tmp_path: Path) -> None:
    sheet = sample_sheet("iso", "en")
    paths = render.write(sheet, tmp_path, png_dpi=50)
    assert [p.name for p in paths] == [f"iso_en.{f}" for f in ("dxf", "svg", "pdf", "png")]
    heads = {p.suffix: p.read_bytes()[:8] for p in paths}
    assert heads[".pdf"].startswith(b"%PDF")
    assert heads[".png"].startswith(b"\x89PNG")
    assert heads[".svg"].startswith(b"<?xml")
    assert b"SECTION" in paths[0].read_bytes()[:64]
    assert sorted(os.listdir(tmp_path)) == sorted(p.name for p in paths)


def test_write_by_suffix_and_formats(tmp_path: Path) -> None:
    sheet = sample_sheet("tcvn", "vi")
    assert render.write(sheet, tmp_path / "plan.svg") == [tmp_path / "plan.svg"]
    written = render.write(sheet, tmp_path / "plan.svg", formats=("dxf", "svg"))
    assert written == [tmp_path / "plan.dxf", tmp_path / "plan.svg"]
    new_dir = str(tmp_path / "out") + os.sep
    assert render.write(sheet, new_dir, formats=["DXF"]) == [tmp_path / "out" / "tcvn_vi.dxf"]


def test_write_rejects_unknown_format(tmp_path: Path) -> None:
    with pytest.raises(DrawingError, match="formats must be among"):
        render.write(sample_sheet(), tmp_path, formats=("dwg",))
    assert os.listdir(tmp_path) == []


def test_failed_render_leaves_existing_files(tmp_path: Path, monkeypatch) -> None:
    sheet = sample_sheet("iso", "ru")
    target = tmp_path / "sheet.dxf"
    target.write_bytes(b"old drawing")
    (tmp_path / "sheet.svg").write_bytes(b"old svg")

    def broken(*_args, **_kwargs):
        raise DrawingError("renderer failed")

    monkeypatch.setattr(mpl, "to_bytes", broken)
    with pytest.raises(DrawingError, match="renderer failed"):
        render.write(sheet, target, formats=("dxf", "svg", "pdf"))
    assert target.read_bytes() == b"old drawing"  # nothing replaced before all rendered
    assert (tmp_path / "sheet.svg").read_bytes() == b"old svg"
    assert sorted(os.listdir(tmp_path)) == ["sheet.dxf", "sheet.svg"]


def test_atomic_write_failure_midway(tmp_path: Path) -> None:
    target = tmp_path / "drawing.pdf"
    target.write_bytes(b"previous")

    def half(fh) -> None:
        fh.write(b"partial content")
        raise OSError("disk full")

    with pytest.raises(OSError, match="disk full"):
        write_atomic(target, half)
    assert target.read_bytes() == b"previous"
    assert os.listdir(tmp_path) == ["drawing.pdf"]


def test_atomic_write_replaces_and_keeps_mode(tmp_path: Path) -> None:
    target = tmp_path / "a.dxf"
    target.write_bytes(b"x")
    target.chmod(0o640)
    write_atomic(target, b"new")
    assert target.read_bytes() == b"new"
    assert target.stat().st_mode & 0o777 == 0o640
    assert os.listdir(tmp_path) == ["a.dxf"]


def test_atomic_write_needs_directory(tmp_path: Path) -> None:
    with pytest.raises(DrawingError, match="output directory must exist"):
        atomic.write_atomic(tmp_path / "missing" / "a.svg", b"x")
