"""Hostile submission archives: names that climb out, zip bombs, deep nesting — refused with a
message naming the entry, nothing written anywhere; odd names kept inside the output."""

from __future__ import annotations

import io
import os
import zipfile
from pathlib import Path

import pytest

from mechplan.cli import main
from mechplan.errors import CheckError
from mechplan.lms import archive, round_trip
from mechplan.lms.archive import ArchiveError, read_zip

TEMPLATES = Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates"
SCENE = TEMPLATES / "slider_crank.toml"
TABLE = b'"\xcf\x86" = "30\xc2\xb0"\n[values]\nVA = "14.1 m/s"\n'


def _zip(files: dict[str, bytes], level: int = zipfile.ZIP_DEFLATED) -> bytes:
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", level) as zf:
        for name, data in files.items():
            zf.writestr(zipfile.ZipInfo(name), data, compress_type=level)
    return buf.getvalue()


def _files(root: Path) -> set[str]:
    return {str(p.relative_to(root)) for p in root.rglob("*")}


@pytest.mark.parametrize("name", ["../evil.dxf", "Ann_1_assignsubmission_file_/../../evil.dxf",
                                  "/tmp/evil.dxf", "C:/evil.dxf", "..\\..\\evil.dxf",
                                  "Ann_1_assignsubmission_file_\\..\\..\\evil.dxf"])
def test_names_out_of_the_folder_are_refused(tmp_path, name, capsys):
    box = tmp_path / "box"
    box.mkdir()
    download = box / "all.zip"
    download.write_bytes(_zip({"Ann_1_assignsubmission_file_/a.toml": TABLE, name: b"x"}))
    before = _files(tmp_path)
    with pytest.raises(ArchiveError) as err:
        round_trip(SCENE, download, box / "out")
    assert repr(name) in str(err.value) and "outside the output folder" in str(err.value)
    assert _files(tmp_path) == before                  # nothing written at all
    assert not Path("/tmp/evil.dxf").exists() or name != "/tmp/evil.dxf"
    code = main(["check", str(SCENE), str(download), "-o", str(box / "out")])
    assert code == 2 and "outside the output folder" in capsys.readouterr().err
    assert _files(tmp_path) == before


def test_a_zip_bomb_is_refused_by_its_ratio(tmp_path):
    bomb = _zip({"Ann_1_assignsubmission_file_/bomb.dxf": bytes(8 * 1024**2)})
    assert len(bomb) < 100_000                         # 8 MB of zeros in a few kB
    with pytest.raises(ArchiveError, match=r"bomb\.dxf.*compressed \d+ to 1"):
        read_zip(bomb, "all.zip")


def test_a_lying_size_header_is_caught(tmp_path):
    data = bytearray(_zip({"Ann_1_assignsubmission_file_/a.dxf": b"0" * 5000},
                          zipfile.ZIP_STORED))
    # the central directory and the local header say 50 bytes, the data are 5000
    for sig, off in ((b"PK\x03\x04", 22), (b"PK\x01\x02", 24)):
        at = data.index(sig) + off
        data[at:at + 4] = (50).to_bytes(4, "little")
    with pytest.raises(ArchiveError, match=r"a\.dxf"):
        read_zip(bytes(data), "all.zip")


def test_total_size_and_entry_count_limits(monkeypatch):
    monkeypatch.setattr(archive, "MAX_TOTAL", 10_000)
    with pytest.raises(ArchiveError, match=r"f3\.dxf.*beyond the limits"):
        read_zip(_zip({f"f{i}.dxf": os.urandom(3000) for i in range(5)}), "all.zip")
    monkeypatch.setattr(archive, "MAX_ENTRIES", 4)
    with pytest.raises(ArchiveError, match=r"more than 4 entries.*f4\.dxf"):
        read_zip(_zip({f"f{i}.dxf": b"x" for i in range(6)}), "all.zip")


def test_nesting_deeper_than_the_limit_is_refused():
    inner = _zip({"Ann_1_assignsubmission_file_/a.toml": TABLE})
    ok = inner
    for k in range(archive.MAX_DEPTH):
        ok = _zip({f"level{k}.zip": ok})
    assert [m.parts[-1] for m in read_zip(ok, "all.zip")] == ["a.toml"]
    with pytest.raises(ArchiveError, match=r"nested more than 3 deep"):
        read_zip(_zip({"deeper.zip": ok}), "all.zip")


def test_odd_names_stay_inside_the_output(tmp_path):
    odd = "Ann\u202e:*?<>|\t_7_assignsubmission_file_/..a\\b:c*.toml"
    download = tmp_path / "all.zip"
    download.write_bytes(_zip({odd: TABLE,
                               "Ann_8_assignsubmission_file_/sub/./x.toml": TABLE,
                               "Eve ..\u2215.._9_assignsubmission_file_/...toml": TABLE}))
    out = tmp_path / "out"
    done = round_trip(SCENE, download, out)
    for p in tmp_path.rglob("*"):
        assert p in (download, out) or out in p.parents, p
    assert len(done.results) == 3 and all(len(r.files) == 1 for r in done.results)
    with zipfile.ZipFile(out / "feedback_files.zip") as zf:
        assert all(".." not in n.split("/") for n in zf.namelist())


def test_an_empty_download_is_refused(tmp_path):
    download = tmp_path / "all.zip"
    download.write_bytes(_zip({"Ann_1_assignsubmission_file_/": b""}))
    with pytest.raises(CheckError, match="no"):
        round_trip(SCENE, download, tmp_path / "out")
    assert not (tmp_path / "out").exists()
