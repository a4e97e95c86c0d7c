"""Numbers on sheets and in reports are written only by mechplan.i18n (number, tick, trimmed,
significant, scale_factor, scientific): no module that presents results formats a float itself —
no "{x:.3f}", "{x:g}", "{x:.2e}", and no zero-stripping (".rstrip('0')" turned μ = 1000 into "1").
Error messages (raised, in English) and the CSV (machine format, decimal point) are exempt."""

from __future__ import annotations

import ast
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src" / "mechplan"
PRESENTING = sorted([*SRC.glob("sheet/*.py"), SRC / "report.py", SRC / "trust_report.py",
                     *SRC.glob("studies/*.py")])
#: functions that write machine formats (CSV), not text for a reader
MACHINE = {"to_csv", "_g"}


def _offences(path: Path) -> list[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    exempt: set[int] = set()
    for node in ast.walk(tree):
        calls_error = (isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
                       and node.func.id.endswith("Error"))
        if (isinstance(node, ast.Raise) or calls_error
                or isinstance(node, ast.FunctionDef) and node.name in MACHINE):
            exempt |= {id(n) for n in ast.walk(node)}
    out = []
    for node in ast.walk(tree):
        if id(node) in exempt:
            continue
        if isinstance(node, ast.FormattedValue) and isinstance(node.format_spec, ast.JoinedStr):
            spec = "".join(v.value for v in node.format_spec.values
                           if isinstance(v, ast.Constant) and isinstance(v.value, str))
            if spec and spec[-1] in "fFgGeE%":
                out.append(f"{path.name}:{node.lineno} formats a number with '{spec}'")
        if (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
                and node.func.attr == "rstrip" and node.args
                and isinstance(node.args[0], ast.Constant) and node.args[0].value == "0"):
            out.append(f"{path.name}:{node.lineno} strips zeros")
    return out


def test_presenting_modules_write_numbers_through_i18n():
    assert PRESENTING
    offences = [o for path in PRESENTING for o in _offences(path)]
    assert not offences, "\n".join(offences)
