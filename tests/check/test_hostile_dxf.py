"""DXF sheets built to hurt (issue 38): INSERT bombs and blocks inside themselves are refused at
once, a damaged file whose recovery raises AttributeError is a clean error, a binary DXF is
read like its ASCII twin."""

from __future__ import annotations

import io
import subprocess
import sys
import time
from pathlib import Path

import ezdxf
import pytest

from mechplan import limits
from mechplan.errors import CheckError
from mechplan.submission.read import read_submission

FOUR_BAR = Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates" / "four_bar.toml"


def _sheet() -> ezdxf.document.Drawing:
    doc = ezdxf.new("R2000")
    msp = doc.modelspace()
    msp.add_line((0, 0), (40, 0))
    msp.add_line((40, 0), (40, 30))
    msp.add_text("pb = 40", dxfattribs={"insert": (10, 5), "height": 2.5})
    return doc


def _bomb(path: Path, copies: int = 10, levels: int = 8) -> Path:
    """A block of ``copies`` lines, inserted ``copies`` times by a block, … ``levels`` deep."""
    doc = _sheet()
    prev = None
    for level in range(levels):
        block = doc.blocks.new(f"L{level}")
        for i in range(copies):
            if prev is None:
                block.add_line((i, 0), (i, 1))
            else:
                block.add_blockref(prev, (i * 0.1, 0))
        prev = f"L{level}"
    doc.modelspace().add_blockref(prev, (0, 0))
    doc.saveas(path)
    return path


def test_an_insert_bomb_is_refused_in_a_second(tmp_path):
    bomb = _bomb(tmp_path / "bomb.dxf")
    assert bomb.stat().st_size < 40_000            # 10^8 lines from a 25 kB file
    start = time.perf_counter()
    with pytest.raises(CheckError, match="more than 200000 entities") as info:
        read_submission(bomb)
    assert time.perf_counter() - start < 15   # refused, not expanded (minutes)
    assert info.value.file == str(bomb)


def test_a_block_inserting_itself_is_refused(tmp_path):
    doc = _sheet()
    block = doc.blocks.new("SELF")
    block.add_line((0, 0), (1, 1))
    block.add_blockref("SELF", (1, 0))
    doc.modelspace().add_blockref("SELF", (0, 0))
    doc.saveas(tmp_path / "self.dxf")
    with pytest.raises(CheckError, match="block 'SELF' inserts itself"):
        read_submission(tmp_path / "self.dxf")
    doc = _sheet()                                  # A → B → A
    doc.blocks.new("A").add_blockref("B", (0, 0))
    doc.blocks.new("B").add_blockref("A", (0, 0))
    doc.modelspace().add_blockref("A", (0, 0))
    doc.saveas(tmp_path / "cycle.dxf")
    with pytest.raises(CheckError, match="inserts itself"):
        read_submission(tmp_path / "cycle.dxf")


def test_nesting_deeper_than_the_limit_is_refused_and_within_it_read(tmp_path):
    deep = _bomb(tmp_path / "deep.dxf", copies=1, levels=limits.DXF_MAX_INSERT_DEPTH + 1)
    with pytest.raises(CheckError, match=f"more than {limits.DXF_MAX_INSERT_DEPTH} levels"):
        read_submission(deep)
    ok = read_submission(_bomb(tmp_path / "ok.dxf", copies=2, levels=limits.DXF_MAX_INSERT_DEPTH))
    # 2^8 lines of the innermost block, plus the sheet's own two
    assert len(ok.lines) == 2 ** limits.DXF_MAX_INSERT_DEPTH + 2


def test_a_damaged_dxf_whose_recovery_raises_attribute_error_is_a_clean_error(tmp_path):
    text = io.StringIO()
    _sheet().write(text)
    damaged = text.getvalue().replace("AcDbLayout\n  1\nLayout1\n", "AcDbLayout\n  1\nINSERT\n")
    assert damaged != text.getvalue()
    path = tmp_path / "damaged.dxf"
    path.write_text(damaged, encoding="utf-8")
    with pytest.raises(CheckError, match="looks damaged .AttributeError"):
        read_submission(path)
    done = subprocess.run([sys.executable, "-m", "mechplan.cli", "check", str(FOUR_BAR),
                           str(path)], check=False, capture_output=True, text=True, timeout=120)
    assert done.returncode == 2 and "Traceback" not in done.stderr
    assert "damaged" in done.stderr and str(path) in done.stderr


def test_a_binary_dxf_is_read_like_its_ascii_twin(tmp_path):
    doc = _sheet()
    doc.saveas(tmp_path / "ascii.dxf")
    doc.saveas(tmp_path / "binary.dxf", fmt="bin")
    assert (tmp_path / "binary.dxf").read_bytes().startswith(b"AutoCAD Binary DXF")
    a, b = read_submission(tmp_path / "ascii.dxf"), read_submission(tmp_path / "binary.dxf")
    assert [(ln.start, ln.end) for ln in b.lines] == [(ln.start, ln.end) for ln in a.lines]
    assert [t.text for t in b.texts] == ["pb = 40"]
    (tmp_path / "binary.dxf").rename(tmp_path / "sheet")          # no suffix: sniffed
    assert len(read_submission(tmp_path / "sheet").lines) == 2


@pytest.mark.parametrize("error", [AssertionError, AttributeError, KeyError, RecursionError])
def test_whatever_the_recovery_raises_on_damage_is_a_clean_error(tmp_path, monkeypatch, error):
    import ezdxf.recover

    def broken(stream, errors="surrogateescape"):
        raise error("half-built object")

    monkeypatch.setattr(ezdxf.recover, "read", broken)
    path = tmp_path / "truncated.dxf"               # no EOF: only the recovery reads it
    path.write_bytes(b"0\nSECTION\n2\nENTITIES\n0\nLINE\n8\n0\n10\n0.0\n")
    with pytest.raises(CheckError, match=f"looks damaged .{error.__name__}"):
        read_submission(path)


def test_too_many_entities_are_refused_before_ezdxf_builds_them(tmp_path, monkeypatch):
    import ezdxf.recover

    from mechplan.submission import dxf_open

    doc = _sheet()
    for i in range(150):
        doc.modelspace().add_line((i, 0), (i, 5))
    doc.saveas(tmp_path / "many.dxf")
    monkeypatch.setattr(dxf_open, "DXF_MAX_ENTITIES", 100)

    def never(*args, **kwargs):
        raise AssertionError("ezdxf was asked to build the document")

    monkeypatch.setattr(ezdxf, "read", never)
    monkeypatch.setattr(ezdxf.recover, "read", never)
    with pytest.raises(CheckError, match="more than 100 entities"):
        read_submission(tmp_path / "many.dxf")


def test_points_and_arrowheads_at_non_finite_coordinates_are_skipped(tmp_path):
    """A POINT, a small CIRCLE or an arrowhead (SOLID) at inf/nan is skipped with a note; the
    sheet is still read and checked (the checker's KD-trees take finite points only)."""
    doc = _sheet()
    msp = doc.modelspace()
    nan, inf = float("nan"), float("inf")
    msp.add_point((nan, 3.0))
    msp.add_circle((inf, 1.0), radius=0.5)
    msp.add_solid([(nan, 0.0), (1.0, 0.0), (0.5, 1.0)])
    msp.add_point((40.0, 30.0))
    path = tmp_path / "ivanov.dxf"
    doc.saveas(path)
    sub = read_submission(path)
    assert sub.markers == [((40.0, 30.0), sub.markers[0][1])]
    assert sub.heads == []
    assert sum("non-finite" in str(n.message) for n in sub.notes) == 3
    from mechplan.check import Options, check

    with pytest.raises(CheckError, match="no point labels"):   # read through: a user error,
        check(FOUR_BAR, path, Options(at_deg=60))              # not scipy's ValueError
