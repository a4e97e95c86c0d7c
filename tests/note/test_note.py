"""The explanatory note of a course project: DOCX and PDF read back, numbers checked against
independent computations and the studies' JSON, sections present exactly when their study is."""

from __future__ import annotations

import math
import re
import shutil
import subprocess
import tomllib
from pathlib import Path

import docx
import pytest

from mechplan.errors import MechplanError
from mechplan.i18n import message
from mechplan.note.project import run_project
from mechplan.studies import solve_file

TEMPLATES = Path(__file__).resolve().parents[2] / "src" / "mechplan" / "templates"
PROJECT = TEMPLATES / "projects" / "v_engine_project.toml"
ROLES = {"linkage": "v_engine.toml", "engine": "v_engine_dynamics.toml",
         "gears": "planetary_two_row.toml", "cam": "cam_cycloidal.toml"}


def _project(folder: Path, lang: str, roles: dict[str, str], tradition: str = "") -> Path:
    lines = ["[project]", 'title = "Course project"', f'language = "{lang}"',
             'student = "Ivanov I. I."', 'group = "M-21"']
    if tradition:
        lines.append(f'tradition = "{tradition}"')
    lines.append("[studies]")
    lines += [f'{role} = "{(TEMPLATES / name).as_posix()}"' for role, name in roles.items()]
    path = folder / "project.toml"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def _texts(document: docx.document.Document) -> list[str]:
    return [p.text for p in document.paragraphs]


def _headings(document: docx.document.Document) -> list[str]:
    """The headings without their section numbers ("2.1 Structural analysis" → the text)."""
    heads = [p.text for p in document.paragraphs if p.style.name.startswith("Heading")]
    numbered = [h for h in heads[1:]]                          # "Contents" is not numbered
    assert all(re.match(r"\d+(\.\d+)* ", h) for h in numbered), numbered
    return [re.sub(r"^\d+(\.\d+)* ", "", h) for h in heads]


def _tables(document: docx.document.Document) -> list[list[list[str]]]:
    return [[[c.text for c in row.cells] for row in t.rows] for t in document.tables]


def _dec(text: str) -> float:
    return float(text.replace(",", ".").replace("−", "-"))


@pytest.fixture(scope="module")
def full(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The bundled V-engine project (Vietnamese, TCVN page): note and sheets."""
    out = tmp_path_factory.mktemp("full")
    run_project(PROJECT, out, ("docx", "pdf"))
    return out


def test_files_are_written_only_inside_the_folder(full: Path) -> None:
    names = sorted(p.name for p in full.iterdir())
    # the note (DOCX, PDF) and the sheet of every study (PDF, the format asked for)
    assert names == sorted(["v_engine_project-note.docx", "v_engine_project-note.pdf"]
                           + [f"v_engine_project-{role}.pdf" for role in ROLES])
    assert not list(full.parent.glob(".*.tmp"))


def test_docx_holds_every_section_with_its_heading(full: Path) -> None:
    d = docx.Document(str(full / "v_engine_project-note.docx"))
    heads = _headings(d)
    for key in ("h.task", "h.structure", "h.kinematics", "h.forces", "h.conclusion",
                "h.references"):
        assert message(f"note.{key}", "vi") in heads, key
    for key, role in (("h.engine", "engine"), ("h.gears", "gears"), ("h.cam", "cam")):
        title = solve_file(TEMPLATES / ROLES[role]).to_json()["title"]
        assert message(f"note.{key}", "vi", title=title) in heads
    # a TOC field and page numbers are fields Word and LibreOffice fill in
    xml = d.element.xml
    assert 'TOC \\o "1-3"' in xml
    footers = "".join(s.footer._element.xml for s in d.sections)
    assert " PAGE " in footers
    assert len(d.inline_shapes) == 4          # the four studies' sheets as figures


def test_crank_speed_formula_is_substituted(full: Path) -> None:
    scene = tomllib.loads((TEMPLATES / "v_engine.toml").read_text(encoding="utf-8"))
    n = float(scene["drive"]["speed"].split()[0])            # "800 rpm"
    omega = math.pi * n / 30
    lines = [t for t in _texts(docx.Document(str(full / "v_engine_project-note.docx")))
             if t.startswith("ω1 = π·n/30")]
    assert len(lines) == 1
    m = re.match(r"ω1 = π·n/30 = ([\d,]+)·([\d,]+)/30 = ([\d,]+) rad/s\t\((\d+)\)$", lines[0])
    assert m, lines[0]
    assert _dec(m[1]) == pytest.approx(math.pi, abs=5e-5)
    assert _dec(m[2]) == n
    assert _dec(m[3]) == pytest.approx(omega, abs=0.005)
    assert "," in m[3]                                         # Vietnamese decimal comma


def test_angular_velocities_and_segment_tables(full: Path) -> None:
    d = docx.Document(str(full / "v_engine_project-note.docx"))
    texts = _texts(d)
    # §1: v_B = ω1·l_AB with l_AB = 80 mm; the velocity plan's pb measures it
    v_b = math.pi * 800 / 30 * 0.080
    rows = [r for t in _tables(d) for r in t]
    pb = [r for r in rows if r[0] == "pb"]
    assert pb and _dec(pb[0][4]) == pytest.approx(v_b, rel=1e-4)
    assert _dec(pb[0][1]) == pytest.approx(v_b / 0.1, abs=0.05)        # μv = 0.1 (m/s)/mm
    # ω2 = v_CB / l_CB: at the dead centre v_C = 0, so v_CB = v_B and ω2 = v_B/0.248
    w2 = [t for t in texts if t.startswith("ω2 = v_CB/l_CB")]
    assert w2, [t for t in texts if t.startswith("ω")]
    value = re.search(r"= ([\d,]+) rad/s", w2[0])
    assert value and _dec(value[1]) == pytest.approx(v_b / 0.248, abs=0.001)
    assert message("protocol.sense.cw", "vi") in w2[0]
    # the crank's end: v_B = ω1·l_AB and a_B = ω1²·l_AB (constant speed), then their segments
    omega = math.pi * 800 / 30
    vb = next(t for t in texts if t.startswith("v_B = ω1·l_AB = "))
    assert _dec(re.search(r"= ([\d,]+) m/s", vb)[1]) == pytest.approx(v_b, abs=0.0005)
    ab = next(t for t in texts if t.startswith("a_B = ω1²·l_AB = "))
    assert _dec(re.search(r"= ([\d,]+) m/s²", ab)[1]) == pytest.approx(omega ** 2 * 0.08,
                                                                        abs=0.0005)
    pb_eq = next(t for t in texts if t.startswith("pb = v_B/μ = "))
    assert _dec(re.search(r"= ([\d,]+) mm", pb_eq)[1]) == pytest.approx(v_b / 0.1, abs=0.05)


def test_force_tables_equal_the_json(full: Path) -> None:
    doc = solve_file(TEMPLATES / "v_engine.toml").to_json()
    forces = doc["positions"][0]["forces"]
    d = docx.Document(str(full / "v_engine_project-note.docx"))
    rows = {r[0]: r for t in _tables(d) for r in t}
    for key, r in forces["reactions"].items():
        assert _dec(rows[f"R_{key}"][1]) == pytest.approx(math.hypot(*r), abs=0.05)
        assert _dec(rows[f"R_{key}"][2]) == pytest.approx(math.degrees(math.atan2(r[1], r[0])),
                                                          abs=0.05)
    mb = forces["balancing_moment"]
    texts = _texts(d)
    line = next(t for t in texts if t.startswith("M_b = "))
    assert _dec(re.search(r"= (-?[\d,]+) N·m", line)[1]) == pytest.approx(mb, abs=0.005)
    assert any(t.startswith("Δ = |M_b − ") for t in texts)


def test_engine_gear_and_cam_formulas(full: Path) -> None:
    texts = _texts(docx.Document(str(full / "v_engine_project-note.docx")))
    eng = tomllib.loads((TEMPLATES / "v_engine_dynamics.toml").read_text(encoding="utf-8"))
    r = float(eng["engine"]["crank_radius"].split()[0])
    big_l = float(eng["engine"]["rod_length"].split()[0])
    lam = next(t for t in texts if t.startswith("λ = R/L"))
    assert _dec(lam.split("=")[-1].split()[0]) == pytest.approx(r / big_l, abs=5e-5)
    # Willis: U = 1 − (−z2/z1)(z4/z3) with the chosen z
    gears = solve_file(TEMPLATES / "planetary_two_row.toml").to_json()
    z1, z2, z3, z4 = gears["planetary"]["chosen"]["z"]
    i_w = -(z2 / z1) * (z4 / z3)
    willis = next(t for t in texts if t.startswith("i^h_14"))
    assert f"(−{z2}/{z1})·({z4}/{z3})" in willis
    assert _dec(willis.split("=")[-1].split()[0]) == pytest.approx(i_w)
    u = next(t for t in texts if t.startswith("U = 1 − i^h"))
    assert _dec(u.split("=")[-1].split()[0]) == pytest.approx(1 - i_w)
    assert any(t.startswith(f"z1 + z2 = z4 − z3 = {z4} − {z3} = {z1 + z2}") for t in texts)
    assert z1 + z2 == z4 - z3
    cam = solve_file(TEMPLATES / "cam_cycloidal.toml").to_json()
    r0 = next(t for t in texts if t.startswith("r0 = "))
    assert _dec(r0.split("=")[-1].split()[0]) == pytest.approx(
        cam["base_radius"]["used"] * 1000, rel=1e-4)


def test_pdf_has_the_pages_and_the_numbers(full: Path) -> None:
    pdfplumber = pytest.importorskip("pdfplumber")
    with pdfplumber.open(full / "v_engine_project-note.pdf") as pdf:
        pages = len(pdf.pages)
        text = "\n".join(p.extract_text() or "" for p in pdf.pages)
    assert pages >= 10
    omega = math.pi * 800 / 30
    assert f"{omega:.2f}".replace(".", ",") in text                  # 83,78
    assert f"{80 / 248:.4f}".replace(".", ",") in text               # λ = 0,3226
    assert message("note.h.structure", "vi") in text
    assert "Hình 1." in text


def test_sections_follow_the_studies_and_language(tmp_path: Path) -> None:
    path = _project(tmp_path, "ru", {"cam": ROLES["cam"], "gears": ROLES["gears"]})
    out = tmp_path / "out"
    run_project(path, out, ("docx",))
    d = docx.Document(str(out / "project-note.docx"))
    heads = _headings(d)
    assert message("note.h.task", "ru") in heads and message("note.h.task", "vi") not in heads
    assert not any(h.startswith(message("note.h.structure", "ru")) for h in heads)
    assert not any(h.startswith(message("note.h.engine", "ru", title="")) for h in heads)
    assert any(h.startswith(message("note.h.cam", "ru", title="")) for h in heads)
    assert any(h.startswith(message("note.h.gears", "ru", title="")) for h in heads)
    # ГОСТ page: a frame (page borders) and the main inscription with the sheet number
    body = d.sections[1]
    assert "w:pgBorders" in body._sectPr.xml
    assert body.left_margin.mm == pytest.approx(30, abs=0.1)
    assert "Изм." in body.footer._element.xml


def test_a_missing_study_is_named_and_nothing_is_written(tmp_path: Path) -> None:
    path = _project(tmp_path, "en", {"cam": "no_such_cam.toml"})
    out = tmp_path / "out"
    with pytest.raises(MechplanError) as err:
        run_project(path, out)
    assert err.value.file == str(path) and "studies.cam" in str(err.value)
    assert not out.exists()


def test_a_failing_study_leaves_no_partial_note(tmp_path: Path) -> None:
    bad = tmp_path / "bad.toml"
    text = (TEMPLATES / "slider_crank.toml").read_text(encoding="utf-8")
    bad.write_text(text.replace("[drive]", "[drive]\nnonsense_key = 1", 1), encoding="utf-8")
    path = tmp_path / "p.toml"
    path.write_text(f'[project]\nlanguage = "en"\n[studies]\nlinkage = "{bad.as_posix()}"\n'
                    f'cam = "{(TEMPLATES / ROLES["cam"]).as_posix()}"\n', encoding="utf-8")
    out = tmp_path / "out"
    out.mkdir()
    (out / "p-note.docx").write_bytes(b"old note")
    with pytest.raises(MechplanError) as err:
        run_project(path, out)
    assert str(bad) in (err.value.file or "") + str(err.value)
    assert sorted(p.name for p in out.iterdir()) == ["p-note.docx"]
    assert (out / "p-note.docx").read_bytes() == b"old note"


@pytest.mark.external
def test_libreoffice_opens_and_converts_the_docx(full: Path, tmp_path: Path, require) -> None:
    soffice = shutil.which("soffice") or shutil.which("libreoffice")
    require(soffice is not None, "LibreOffice (apt-get install libreoffice-writer-nogui)")
    src = tmp_path / "note.docx"
    shutil.copy(full / "v_engine_project-note.docx", src)
    subprocess.run([soffice, "--headless", f"-env:UserInstallation=file://{tmp_path}/lo",
                    "--convert-to", "pdf", "--outdir", str(tmp_path), str(src)],
                   check=True, capture_output=True, timeout=300)
    pdfplumber = pytest.importorskip("pdfplumber")
    with pdfplumber.open(tmp_path / "note.pdf") as pdf:
        text = "\n".join(p.extract_text() or "" for p in pdf.pages)
    assert "83,78" in text and message("note.h.structure", "vi") in text


def test_machine_dynamics_chapter(tmp_path: Path) -> None:
    """A linkage with [dynamics] (worked example §2): the constant moment from zero net work,
    the flywheel by each method, in Russian on a ГОСТ page."""
    path = _project(tmp_path, "ru", {"linkage": "machine_unit.toml"})
    run_project(path, tmp_path / "out", ("docx",))
    d = docx.Document(str(tmp_path / "out" / "project-note.docx"))
    assert message("note.h.dynamics", "ru") in _headings(d)
    texts = _texts(d)
    dyn = solve_file(TEMPLATES / "machine_unit.toml").to_json()["dynamics"]
    scene = tomllib.loads((TEMPLATES / "machine_unit.toml").read_text(encoding="utf-8"))
    cycle = math.radians(float(dyn["cycle_deg"]))
    assert cycle == pytest.approx(4 * math.pi)                 # a four-stroke cycle: two turns
    line = next(t for t in texts if t.startswith("M_c = A/Φ_c"))
    work, phi_c, mc = re.match(r"M_c = A/Φ_c = ([\d,]+)/([\d,]+) = ([\d,]+) Н·м", line).groups()
    assert _dec(work) / _dec(phi_c) == pytest.approx(_dec(mc), rel=1e-4)
    assert _dec(phi_c) == pytest.approx(4 * math.pi, rel=1e-4)
    assert _dec(mc) == pytest.approx(dyn["work_driving"] / (4 * math.pi), abs=0.005)
    n = float(scene["drive"]["speed"].split()[0])              # "300 rpm"
    wm = next(t for t in texts if t.startswith("ω_m = π·n/30"))
    assert _dec(re.search(r"= ([\d,]+) рад/с", wm)[1]) == pytest.approx(math.pi * n / 30,
                                                                       abs=0.0005)
    jf = next(t for t in texts if t.startswith("J_fl = J_I − J_pr"))
    j_i, j_pr, j_fl = (_dec(x) for x in re.findall(r"[\d,]+", jf.split("=", 2)[2])[:3])
    assert j_i - j_pr == pytest.approx(j_fl, rel=1e-4)
    flywheel = {r[0]: r for t in _tables(d) for r in t}
    fw = dyn["flywheel"]
    for key, method in (("method.wittenbauer", "wittenbauer"), ("method.merkalov", "merkalov"),
                        ("method.exact", "exact")):
        row = flywheel[message(f"note.{key}", "ru")]
        assert _dec(row[1]) == pytest.approx(fw[method]["J"], rel=1e-4)


def test_command_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from mechplan.cli import main

    missing = _project(tmp_path, "en", {"gears": "nothing_here.toml"})
    assert main(["project", str(missing), "-o", str(tmp_path / "o1")]) == 2
    err = capsys.readouterr().err
    assert "studies.gears" in err and str(missing) in err
    assert not (tmp_path / "o1").exists()
    ok = _project(tmp_path, "zh", {"gears": ROLES["gears"]})
    assert main(["project", str(ok), "-o", str(tmp_path / "o2"), "--format", "docx,svg"]) == 0
    printed = capsys.readouterr().out.split()
    assert sorted(Path(p).name for p in printed) == sorted(
        p.name for p in (tmp_path / "o2").iterdir())
    assert "project-note.docx" in {Path(p).name for p in printed}
    heads = _headings(docx.Document(str(tmp_path / "o2" / "project-note.docx")))
    assert message("note.h.conclusion", "zh") in heads


@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_the_v_engine_note_in_each_language(tmp_path: Path, lang: str) -> None:
    """The bundled project's note in the other languages (vi above): every chapter's heading in
    the DOCX and the PDF, ω1 with the language's decimal mark (figures left out: faster)."""
    import io

    from mechplan.note.build import build_note
    from mechplan.note.project import read_project, solve_project
    from mechplan.note.write import note_files

    text = PROJECT.read_text(encoding="utf-8").replace('language = "vi"', f'language = "{lang}"')
    text = re.sub(r'tradition = "\w+"', "", text).replace("../", f"{TEMPLATES.as_posix()}/")
    path = tmp_path / "p.toml"
    path.write_text(text, encoding="utf-8")
    project = read_project(path)
    assert project.tradition == {"en": "plain", "ru": "gost", "zh": "gb"}[lang]
    note = build_note(project, solve_project(project), [])
    files = note_files(note, "p", ("docx", "pdf"))
    d = docx.Document(io.BytesIO(files["p-note.docx"]))
    heads = _headings(d)
    titles = {role: solve_file(TEMPLATES / name).to_json()["title"] for role, name in
              ROLES.items() if role != "linkage"}
    wanted = [message(f"note.{k}", lang) for k in ("h.task", "h.structure", "h.kinematics",
                                                    "h.forces", "h.conclusion")]
    wanted += [message(f"note.h.{role}", lang, title=titles[role]) for role in titles]
    assert all(w in heads for w in wanted), set(wanted) - set(heads)
    omega = f"{math.pi * 800 / 30:.2f}"
    omega = omega.replace(".", ",") if lang == "ru" else omega
    assert any(t.startswith("ω1 = π·n/30 = ") and f"= {omega} " in t for t in _texts(d))
    pdfplumber = pytest.importorskip("pdfplumber")
    with pdfplumber.open(io.BytesIO(files["p-note.pdf"])) as pdf:
        pdf_text = "\n".join(p.extract_text() or "" for p in pdf.pages)
    assert omega in pdf_text
    flat = re.sub(r"\s+", "", pdf_text)
    assert all(re.sub(r"\s+", "", w) in flat for w in wanted)


def test_the_given_data_table_is_the_scenes(full: Path) -> None:
    scene = tomllib.loads((TEMPLATES / "v_engine.toml").read_text(encoding="utf-8"))
    given = {f"l_{k}": float(v.split()[0]) for link in scene["links"].values()
             for k, v in link.get("lengths", {}).items()}
    given |= {f"m{lid}": float(link["mass"].split()[0]) for lid, link in scene["links"].items()
              if "mass" in link}
    d = docx.Document(str(full / "v_engine_project-note.docx"))
    data = next(t for t in _tables(d) if t[0][2] == message("note.c.unit", "vi"))
    rows = {r[0]: _dec(r[1]) for r in data[1:]}
    assert {k: rows[k] for k in given} == given
    assert rows["n1"] == 800
