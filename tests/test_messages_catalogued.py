"""Issue 35: every message a user can cause is a catalogue text.

An AST scan of src/mechplan finds the errors of the mechplan.errors family (and the ``.error(key,
message)`` of scene tables) raised with a message written as a str literal or f-string, i.e. English
text outside the catalogues. Internal invariants that no scene can reach are allowed with their
reason; the files not converted yet are listed, with their count of literal sites, as open work:
the scan fails on any NEW literal site. Every id of a ``Text("…")`` literal exists in all four
languages, and a literal argument dict gives every placeholder of its message.
"""

from __future__ import annotations

import ast
import re
import string
from collections import Counter
from pathlib import Path

import pytest

from mechplan.i18n import LANGUAGES, catalogue

SRC = Path(__file__).resolve().parents[1] / "src" / "mechplan"

#: the error family; subclasses defined in src are found by the scan
FAMILY = {"MechplanError", "SceneError", "TopologyError", "UnreachableError", "SingularError",
          "DrawingError", "CheckError", "LimitError"}

#: internal checks, not user errors: (file, pattern of the message's source, reason)
ALLOWED = [
    ("render/dxf.py", r"backend cannot draw",
     "a backend given an unknown primitive type: a programming error"),
    ("render/mpl.py", r"backend cannot draw", "as above"),
    ("render/svg.py", r"backend cannot draw", "as above"),
    ("render/html.py", r"page cannot draw", "as above"),
    ("render/dxf.py", r"DXF audit must report no errors", "self-check of the written DXF: a bug"),
    ("render/profile_dxf.py", r"DXF audit must report no errors", "as above"),
    ("render/dxf.py", r"must be placed on the sheet, not inside a layout", "layout invariant"),
    ("render/mpl.py", r"matplotlib format must be", "the CLI only passes pdf or png"),
    ("render/profile_dxf.py", r"closed profile must have at least 3 points",
     "cam profiles are sampled by the program, never given by the user"),
    ("sheet/layout.py", r"cannot move a", "layout of an unknown primitive type: a bug"),
    ("sheet/layout.py", r"no enlargement to try", "layout search invariant"),
    ("sheet/room.py", r"drawing area must be a rectangle less rectangles", "layout invariant"),
    # the drawing primitives validate what the program builds (a NaN from a construction, a text
    # height off the ISO series, a block inside a block): invariants of the drafting layer
    ("drafting/primitives.py", r".", "invariants of the drawing primitives built by mechplan"),
]

#: OPEN WORK (issue 35): files whose user errors are still English literals, with how many literal
#: sites each has today. Lower a count (or drop the file) when converting; never raise one.
NOT_YET_CONVERTED: dict[str, int] = {}      # none left


def _family(trees: dict[str, ast.Module]) -> set[str]:
    names = set(FAMILY)
    grew = True
    while grew:
        grew = False
        for tree in trees.values():
            for node in ast.walk(tree):
                if (isinstance(node, ast.ClassDef) and node.name not in names
                        and any(isinstance(b, ast.Name) and b.id in names
                                or isinstance(b, ast.Attribute) and b.attr in names
                                for b in node.bases)):
                    names.add(node.name)
                    grew = True
    return names


def _literal(arg: ast.expr) -> bool:
    if isinstance(arg, ast.JoinedStr):
        return True
    if isinstance(arg, ast.Constant):
        return isinstance(arg.value, str)
    if isinstance(arg, ast.BinOp):
        return _literal(arg.left) or _literal(arg.right)
    if isinstance(arg, ast.Call) and isinstance(arg.func, ast.Attribute):
        return arg.func.attr == "format" and _literal(arg.func.value)
    return False


def _trees() -> dict[str, ast.Module]:
    return {p.relative_to(SRC).as_posix(): ast.parse(p.read_text(encoding="utf-8"))
            for p in sorted(SRC.rglob("*.py"))}


def literal_sites(trees: dict[str, ast.Module]) -> list[tuple[str, int, str]]:
    """(file, line, message source) of each error raised with a literal message."""
    family = _family(trees)
    sites = []
    for rel, tree in trees.items():
        source = (SRC / rel).read_text(encoding="utf-8")
        for node in ast.walk(tree):
            if not isinstance(node, ast.Call):
                continue
            f = node.func
            name = f.attr if isinstance(f, ast.Attribute) else f.id if isinstance(f, ast.Name) \
                else ""
            message = None
            if name in family:
                message = node.args[0] if node.args else next(
                    (k.value for k in node.keywords if k.arg == "message"), None)
            elif name == "error" and isinstance(f, ast.Attribute) and len(node.args) >= 2:
                message = node.args[1]              # Table.error(key, message)
            if message is not None and _literal(message):
                sites.append((rel, node.lineno, ast.get_source_segment(source, message) or ""))
    return sites


def _allowed(rel: str, text: str) -> bool:
    return any(rel == f and re.search(p, text) for f, p, _ in ALLOWED)


@pytest.fixture(scope="module")
def trees() -> dict[str, ast.Module]:
    return _trees()


def test_the_scan_finds_a_literal_message():
    """The scan itself: an f-string, a literal and a ``.error`` literal are found; a Text is not."""
    code = ("from .errors import SceneError\nclass MyError(SceneError): ...\n"
            "def f(t, x):\n    raise SceneError(f'bad {x}')\n"
            "def g(t):\n    raise t.error('key', 'must be ' + 'positive')\n"
            "def h(t):\n    raise MyError('no')\n"
            "def k(t):\n    raise SceneError(Text('errmsg2.builder.left'))\n")
    tree = ast.parse(code)
    family = _family({"x.py": tree})
    assert "MyError" in family
    calls = [n for n in ast.walk(tree) if isinstance(n, ast.Call)
             and (getattr(n.func, "id", "") in family or getattr(n.func, "attr", "") == "error")]
    literal = [n.lineno for n in calls
               if _literal(n.args[1] if getattr(n.func, "attr", "") == "error" else n.args[0])]
    assert literal == [4, 6, 8]


def test_no_new_user_message_outside_the_catalogues(trees):
    left = Counter()
    new = []
    for rel, line, text in literal_sites(trees):
        if _allowed(rel, text):
            continue
        left[rel] += 1
        if rel not in NOT_YET_CONVERTED:
            new.append(f"{rel}:{line}: {text[:90]}")
    assert not new, ("user-facing text outside the catalogues (use mechplan.i18n.Text with an "
                     "id in a locale/*/<area>.po):\n" + "\n".join(new))
    grown = {rel: (n, NOT_YET_CONVERTED[rel]) for rel, n in left.items()
             if n > NOT_YET_CONVERTED[rel]}
    assert not grown, f"new literal messages in files not converted yet (found, listed): {grown}"


def test_converted_files_stay_converted(trees):
    """The files of this conversion (scene loader, geometry, drivers, centres, textbook,
    structure, assembly) hold no literal."""
    sites = [s for s in literal_sites(trees) if s[0] in
             ("scene/loader.py", "scene/geometry.py", "scene/drivers.py", "scene/second_driver.py",
              "scene/centres.py", "scene/textbook.py", "model/structure.py",
              "construct/builder.py", "construct/extremes.py", "construct/trust.py",
              "construct/plans/drivers.py", "construct/plans/force_friction.py",
              "construct/plans/triad.py", "solve.py", "textbook_report.py",
              "synthesis/linkage/__init__.py", "limits.py")]
    assert not sites, sites


def _text_ids(trees: dict[str, ast.Module]) -> list[tuple[str, int, str, ast.expr | None]]:
    out = []
    for rel, tree in trees.items():
        for node in ast.walk(tree):
            if (isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
                    and node.func.id == "Text" and node.args
                    and isinstance(node.args[0], ast.Constant)
                    and isinstance(node.args[0].value, str)):
                out.append((rel, node.lineno, node.args[0].value,
                            node.args[1] if len(node.args) > 1 else None))
    return out


def test_every_text_id_is_in_every_language(trees):
    ids = _text_ids(trees)
    assert len(ids) > 300
    missing = [f"{rel}:{line}: {key} ({lang})" for rel, line, key, _ in ids
               if not key.startswith("_") for lang in LANGUAGES if key not in catalogue(lang)]
    assert not missing, "\n".join(missing)


def test_literal_arguments_give_every_placeholder(trees):
    """A ``Text("id", {...})`` whose dict is literal gives each placeholder of the message."""
    en = catalogue("en")
    wrong = []
    for rel, line, key, args in _text_ids(trees):
        if key.startswith("_") or key not in en:
            continue
        wanted = {f.split(".")[0].split("[")[0]
                  for _, f, _, _ in string.Formatter().parse(en[key]) if f}
        if args is None:
            given: set[str] | None = set()
        elif isinstance(args, ast.Dict) and all(isinstance(k, ast.Constant) for k in args.keys):
            given = {k.value for k in args.keys}           # type: ignore[union-attr]
        else:
            given = None                                   # built elsewhere: not checked here
        if given is not None and not wanted <= given:
            wrong.append(f"{rel}:{line}: {key} lacks {sorted(wanted - given)}")
    assert not wrong, "\n".join(wrong)
