"""Class rosters: a Moodle participants export or a Canvas roster (gradebook) CSV, and which
variant each student solves."""

from __future__ import annotations

import csv
import io
import unicodedata
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import CheckError
from ..userfiles import TABLE, read_bytes
from .texts import say

#: the roster's column naming the variant (any case)
VARIANT_COLUMNS = ("variant", "вариант", "biến thể", "đề", "变体", "题号")
_FIRST = ("first name", "имя", "tên")
_LAST = ("last name", "surname", "фамилия", "họ")
_NAME = ("student", "full name", "name", "фио", "họ và tên", "姓名")
_ID = ("id", "user id", "participant id")
_IDNUMBER = ("id number", "sis user id", "student id", "номер", "mssv", "学号")
_EMAIL = ("email address", "email", "e-mail")
_LOGIN = ("username", "sis login id", "login id", "login")
_SECTION = ("section", "group", "groups", "группа", "lớp", "班级")


def norm(text: str) -> str:
    """A name as compared: NFC, case-folded, blanks squeezed, ``_`` as a blank."""
    return " ".join(unicodedata.normalize("NFC", text).replace("_", " ").casefold().split())


@dataclass
class Person:
    """One row of a roster."""

    name: str
    id: str = ""
    id_number: str = ""
    email: str = ""
    login: str = ""
    section: str = ""
    variant: str = ""
    row: dict[str, str] = field(default_factory=dict)


def _pick(row: dict[str, str], names: tuple[str, ...]) -> str:
    for k, v in row.items():
        if k is not None and norm(k) in names and v:
            return v.strip()
    return ""


def decode(data: bytes) -> tuple[str, str]:
    """The text of a CSV and its encoding ("utf-8-sig" with a BOM, "utf-8", else cp1251)."""
    for enc in ("utf-8-sig", "utf-8", "cp1251"):
        try:
            text = data.decode(enc)
        except UnicodeDecodeError:
            continue
        if enc == "utf-8-sig" and not data.startswith(b"\xef\xbb\xbf"):
            enc = "utf-8"        # written back without a BOM, as it came
        return text, enc
    return data.decode("latin-1"), "latin-1"


def read_roster(path: Path) -> list[Person]:
    """The students of a roster CSV (comma, semicolon or tab separated)."""
    text, _ = decode(read_bytes(path, TABLE, error=CheckError))
    try:
        dialect = csv.Sniffer().sniff(text[:4096], delimiters=",;\t")
    except csv.Error:
        dialect = csv.excel  # type: ignore[assignment]
    rows = list(csv.DictReader(io.StringIO(text), dialect=dialect))
    if not rows:
        raise CheckError(say("roster_empty"), file=str(path))
    out = []
    for row in rows:
        name = _pick(row, _NAME) or " ".join(x for x in (_pick(row, _FIRST), _pick(row, _LAST))
                                             if x)
        if not name or norm(name) == "points possible":
            continue
        out.append(Person(name, _pick(row, _ID), _pick(row, _IDNUMBER), _pick(row, _EMAIL),
                          _pick(row, _LOGIN), _pick(row, _SECTION), _pick(row, VARIANT_COLUMNS),
                          {k: v for k, v in row.items() if k is not None}))
    return out


def find(roster: list[Person], *, name: str = "", id: str = "", login: str = "",
         email: str = "") -> Person | None:
    """The roster's person with this id, login, e-mail or full name (in that order); None when
    none or several match."""
    for attr, value in (("id", id), ("login", login), ("email", email), ("name", name)):
        if not value:
            continue
        hits = [p for p in roster if getattr(p, attr) and norm(getattr(p, attr)) == norm(value)]
        if attr == "name" and not hits:          # "Last First" in one, "First Last" in the other
            key = sorted(norm(value).split())
            hits = [p for p in roster if sorted(norm(p.name).split()) == key]
        if len(hits) == 1:
            return hits[0]
    return None
