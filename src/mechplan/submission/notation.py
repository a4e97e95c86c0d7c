"""Quantity names as students write them, read through the notation catalogue ``notation.toml``.

``read("VC2B2", mech)`` → ``Reading("v_CB", "velocity")``; ``read("aC2", mech)`` → ``a_C``;
``read("Mtt", mech)`` → ``M_red``. A name that does not parse is ``None`` (never another
quantity); :func:`closest` gives the candidates to suggest.
"""

from __future__ import annotations

import difflib
import functools
import re
import tomllib
import unicodedata
from collections.abc import Iterable
from dataclasses import dataclass
from importlib import resources
from typing import Any

from ..model.mechanism import Mechanism
from ..units import parse_quantity

SUBSCRIPTS = str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")
_SUP_DIGITS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹", "0123456789")
_SUP_MARK = {"ⁿ": "^n", "ᵗ": "^t", "ᵏ": "^k", "ʳ": "^r", "ᶜ": "^c"}
_TRAILING_MARK = re.compile(r"^([^\W\d_]+)_?\{?(\w+)\}?\^\{?([ntkrτ])\}?$")
_DIGITS = re.compile(r"\d+")
#: characters of a name that can be a quantity ("a^t_E4D4" is 8): a longer one is not understood,
#: without reading it (_TRAILING_MARK takes quadratic time on a long word)
MAX_NAME_CHARS = 100
_DROP = re.compile(r"[\s_{}^$\\()\[\]]")


@dataclass(frozen=True, slots=True)
class Reading:
    """What a written name means: the canonical quantity name and its dimension."""

    canonical: str          # "v_CB", "a^n_CB", "omega_2", "R^t_12", "Q_2", "F@3", "M_red"
    dimension: str


@dataclass(frozen=True, slots=True)
class _Symbol:
    spelling: str           # compact; lower case unless ``case``
    canonical: str
    dimension: str
    subscripts: tuple[str, ...]
    case: bool


@functools.cache
def catalogue() -> dict[str, Any]:
    """The notation catalogue (package data ``submission/notation.toml``)."""
    with (resources.files("mechplan.submission") / "notation.toml").open("rb") as fh:
        return tomllib.load(fh)


@functools.cache
def _tables() -> tuple[dict[str, str], dict[str, str], tuple[_Symbol, ...], dict[str, str]]:
    data = catalogue()
    homo = dict(data["homoglyphs"])
    names = {compact(s, homo): canonical for canonical, spellings in data["names"].items()
             for s in [canonical, *spellings]}
    symbols = [_Symbol(compact(sp, homo, entry.get("case", False)), entry["canonical"],
                       entry["dimension"], tuple(entry["subscripts"]), entry.get("case", False))
               for entry in data["symbols"].values() for sp in entry["spellings"]]
    symbols.sort(key=lambda s: -len(s.spelling))       # longest spelling first: "an" before "a"
    dims = {e["canonical"]: e["dimension"] for e in data["symbols"].values()}
    dims |= {"M_b": "moment", "M_red": "moment", "J_red": "inertia"}
    return names, homo, tuple(symbols), dims


def compact(name: str, homo: dict[str, str] | None = None, case: bool = False) -> str:
    """A name with scripts, look-alike letters and decoration normalised (lower case unless
    ``case``)."""
    t = unicodedata.normalize("NFC", name.strip()).translate(SUBSCRIPTS)
    for ch, rep in _SUP_MARK.items():
        t = t.replace(ch, rep)
    t = t.translate(_SUP_DIGITS)
    m = _TRAILING_MARK.match(t) if len(t) <= MAX_NAME_CHARS else None
    if m:                                   # a_CB^n → a^n_CB
        t = f"{m.group(1)}^{m.group(3)}_{m.group(2)}"
    for ch, rep in (homo if homo is not None else _tables()[1]).items():
        t = t.replace(ch, rep)
    t = _DROP.sub("", t).replace("′", "'")
    return t if case else t.lower()


def key(canonical: str) -> str:
    """The lookup key of a canonical or construction quantity name ("R^t_12" → "rt12")."""
    return re.sub(r"[_^{}\s]", "", canonical).lower()


def read(name: str, mech: Mechanism | None) -> Reading | None:
    """The quantity a written name stands for, or None when it is not understood."""
    if len(name) > MAX_NAME_CHARS:
        return None
    names, homo, symbols, dims = _tables()
    raw = unicodedata.normalize("NFC", name.strip()).translate(SUBSCRIPTS)
    for text in (_DROP.sub("", raw).lower(), compact(name, homo)):
        if text in names:
            return Reading(names[text], dims[names[text]])
    for sym, sub in _symbols(name, homo, symbols):
        for kind in sym.subscripts:
            canonical = _subscript(sym.canonical, kind, sub, mech)
            if canonical is not None:
                return Reading(canonical, sym.dimension)
    return None


def _symbols(name: str, homo: dict[str, str],
             symbols: tuple[_Symbol, ...]) -> Iterable[tuple[_Symbol, str]]:
    """The symbols a name starts with (longest first) and the subscript after each."""
    text, cased = compact(name, homo), compact(name, homo, True)
    for sym in symbols:
        if (cased if sym.case else text).startswith(sym.spelling):
            yield sym, text[len(sym.spelling):]


def dimension(name: str) -> str | None:
    """The dimension a name's symbol says, without a mechanism ("R12" → force), or None."""
    if len(name) > MAX_NAME_CHARS:
        return None
    names, homo, symbols, dims = _tables()
    if (text := compact(name, homo)) in names:
        return dims[names[text]]
    for sym, sub in _symbols(name, homo, symbols):
        kinds = {"numeric" if k in ("link", "links", "force") else "points"
                 for k in sym.subscripts}
        if sub and ("numeric" if sub.isdigit() else "points") in kinds:
            return sym.dimension
    return None


def _subscript(symbol: str, kind: str, sub: str, mech: Mechanism | None) -> str | None:
    if not sub or mech is None:
        return None
    if kind in ("link", "force"):
        link = _link(sub, mech)
        if link is None:
            return None
        return f"{symbol}@{link}" if kind == "force" else f"{symbol}_{link}"
    if kind == "links":
        links = _split_links(sub, mech)
        return f"{symbol}_{links[0]}{links[1]}" if links else None
    points_ = points(sub, mech)
    if points_ is None or len(points_) != (1 if kind == "point" else 2):
        return None
    return f"{symbol}_{''.join(points_)}"


def _link(sub: str, mech: Mechanism) -> str | None:
    return next((lid for lid in mech.links if lid.lower() == sub), None)


def _split_links(sub: str, mech: Mechanism) -> tuple[str, str] | None:
    ids = {lid.lower(): lid for lid in mech.links}
    for i in range(1, len(sub)):
        if sub[:i] in ids and sub[i:] in ids and sub[:i] != sub[i:]:
            return ids[sub[:i]], ids[sub[i:]]
    return None


def points(sub: str, mech: Mechanism) -> list[str] | None:
    """Split "c2b2" / "cb" / "s2" / "e4d4" into point names (a digit after a point may name
    the link it belongs to)."""
    names = sorted({p for link in mech.links.values() for p in link.points}, key=len,
                   reverse=True)
    member = {(p.lower(), lid.lower()) for lid, link in mech.links.items() for p in link.points}
    # the first split a depth-first search in this order finds, computed from the end of the
    # subscript: no recursion (a subscript may be thousands of characters long) and each suffix
    # is split once (a search could try every way of reading "b2b2b2…")
    n = len(sub)
    step: list[tuple[str, int] | None] = [None] * (n + 1)
    for i in range(n - 1, -1, -1):
        for p in names:
            low = p.lower()
            if not sub.startswith(low, i):
                continue
            j = i + len(low)
            m = _DIGITS.match(sub, j)
            options = [j]
            if m and (low, m.group(0)) in member:
                options.insert(0, m.end())
            found = next((r for r in options if r == n or step[r] is not None), None)
            if found is not None:
                step[i] = (p, found)
                break
    if n and step[0] is None:
        return None
    out, i = [], 0
    while i < n:
        p, i = step[i]  # type: ignore[misc]
        out.append(p)
    return out


def reversed_points(sub: str, mech: Mechanism) -> str | None:
    """Two points of a subscript named from the other end ("cb" → "BC"), or None when the
    subscript is not two points."""
    names = points(sub, mech)
    return names[1] + names[0] if names and len(names) == 2 else None


def closest(name: str, candidates: Iterable[str], n: int = 4) -> list[str]:
    """The candidate names closest to a written name (for "not understood" notes)."""
    everything = list(candidates)
    dim = dimension(name)         # an acceleration name gets accelerations first
    same = [c for c in everything if dim is not None and dimension(c) == dim]
    pool = {compact(c): c for c in same or everything}
    hits = difflib.get_close_matches(compact(name), list(pool), n=n, cutoff=0.3)
    return [pool[h] for h in hits]


# -- legacy Vietnamese encodings ------------------------------------------------------------------
_VIETNAMESE = re.compile(r"[\u1ea0-\u1ef9ơưđăƠƯĐĂ]")


@functools.cache
def _tcvn3() -> tuple[dict[str, str], frozenset[str]]:
    table = catalogue()["tcvn3"]
    pairs = {tok[0]: tok[1:] for tok in table["map"].split()}
    pairs["\u00ad"] = "ư"                           # soft hyphen: invisible in the data file
    return pairs, frozenset(table["weak"])


def decode_legacy(text: str, font: str = "") -> tuple[str, str | None]:
    """Decode a text written in a legacy Vietnamese font encoding.

    Return the text and the encoding found: ``"tcvn3"`` (decoded), ``"vni"`` (recognised, not
    decoded) or None (the text is left as it is). The style's font decides when it is known
    (".VnTime" → TCVN3, "VNI-Times" → VNI); otherwise two or more TCVN3 characters, one of them a
    Latin-1 symbol (®, «, ¬ …), in a text without Unicode Vietnamese letters do.
    """
    data = catalogue()
    low = font.lower()
    table, weak = _tcvn3()
    if any(f in low for f in data["vni"]["fonts"]):
        return text, "vni"
    by_font = any(low.startswith(f) or f"/{f}" in low for f in data["tcvn3"]["fonts"])
    strong = sum(1 for ch in text if ch in table and ch not in weak)
    # TCVN3 text shows Latin-1 symbols (® for đ, « for ô, ¬ for ơ …), not only accented letters:
    # French or German text ("accélération") is never taken for it
    symbols = any(ch in table and ch not in weak and not unicodedata.category(ch).startswith("L")
                  for ch in text)
    if not by_font and (strong < 2 or not symbols or _VIETNAMESE.search(text)):
        return text, None
    decoded = "".join(table.get(ch, ch) for ch in text)
    return (decoded, "tcvn3") if decoded != text else (text, None)


def units_ascii(text: str) -> str:
    """Units as the unit parser reads them: "м/с/мм" → "m/s/mm", "(m/s²)/mm", "кН" → "kN"."""
    for written, read_as in catalogue()["units"].items():
        text = text.replace(written, read_as)
    return text


# -- answers of the dynamics, engine, cam and gear studies ---------------------------------------
#: the catalogue's answer tables of each study kind
ANSWER_TABLES = {"dynamics": ("dynamics",), "engine": ("engine",), "cam": ("cam",),
                 "gears": ("gears", "gears_pair"), "linkage": ("linkage",)}


@dataclass(frozen=True, slots=True)
class AnswerSpec:
    """An answer quantity of a study in the catalogue: its dimension and how it is graded."""

    canonical: str
    dimension: str
    pct: float = 0.0
    floor: str | None = None
    span_pct: float = 0.0
    per_angle: bool = False
    integer: bool = False
    magnitude: bool = False

    def floor_value(self) -> float:
        """The absolute floor of the tolerance in SI (0 when the catalogue gives none)."""
        if not self.floor:
            return 0.0
        dim = "dimensionless" if re.fullmatch(r"[\d.]+", self.floor) else self.dimension
        return parse_quantity(self.floor, dim)


@functools.cache
def answer_names() -> dict[str, dict[str, list[AnswerSpec]]]:
    """table → compact spelling → the quantities it may mean."""
    data = catalogue()["answers"]
    out: dict[str, dict[str, list[AnswerSpec]]] = {}
    for table in ("dynamics", "engine", "cam", "gears", "gears_pair", "linkage"):
        names: dict[str, list[AnswerSpec]] = {}
        for canonical, e in data[table].items():
            spec = AnswerSpec(canonical, e["dimension"], float(e.get("pct", 0)), e.get("floor"),
                        float(e.get("span_pct", 0)), bool(e.get("per_angle", False)),
                        bool(e.get("integer", False)), bool(e.get("magnitude", False)))
            for sp in [canonical, *e["spellings"]]:
                names.setdefault(compact(sp), []).append(spec)
                names.setdefault("=" + compact(sp, case=True), []).append(spec)
        out[table] = names
    return out


def answer_section(section: str | None) -> str | None:
    """The part of a gear study a table's section names (\"planetary\", \"pair\"), or None."""
    if not section:
        return None
    low = section.strip().lower()
    for kind, names in catalogue()["answers"]["sections"].items():
        if low in names:
            return str(kind)
    return None


def is_angle_column(name: str) -> bool:
    """True for the name of an angle column or key (φ, phi, угол, góc …)."""
    key = compact(_without_unit(name))
    return any(s.canonical == "phi" for t in answer_names().values() for s in t.get(key, []))


def _without_unit(name: str) -> str:
    return re.sub(r"\s*[\[(].*[\])]\s*$", "", name)


def read_answer(name: str, tables: tuple[str, ...],
                has_angle: bool) -> tuple[AnswerSpec, str] | None:
    """The answer quantity a written name means in the first of ``tables`` that knows it, and
    its key (``"pair."`` before the gear pair's names); a name written with the exact case of a
    spelling wins (the engine's pressure ``p`` and force ``P``)."""
    for table in tables:
        names = answer_names()[table]
        exact_case = names.get("=" + compact(name, case=True), [])
        for spec in exact_case + names.get(compact(name), []):
            if spec.canonical == "phi" or spec.per_angle != has_angle:
                continue
            return spec, ("pair." if table == "gears_pair" else "") + spec.canonical
    return None


def closest_answers(name: str, kind: str) -> list[str]:
    """Up to four answer names of a study kind that look like ``name`` (to suggest)."""
    pool = {k: specs[0].canonical for t in ANSWER_TABLES[kind]
            for k, specs in answer_names()[t].items() if not k.startswith("=")}
    hits = difflib.get_close_matches(compact(name), list(pool), n=6, cutoff=0.3)
    return list(dict.fromkeys(pool[h] for h in hits))[:4]
