"""Who handed in what: the participants of a Moodle "Download all submissions" archive (a folder
``Full Name_<id>_assignsubmission_file_`` per participant) or of a Canvas submissions download
(``<login>_<user id>_<submission id>_<file>``, ``late_`` before it when late)."""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from .archive import Member

#: a Moodle participant's folder: full name, participant id, the plugin
MOODLE = re.compile(r"^(?P<name>.+?)_(?P<id>\d+)_assign(?:submission|feedback)_"
                    r"(?P<plugin>[a-z]+)_?$")
#: Moodle without "Download submissions in folders": ``Full Name_<id>_assignsubmission_file_<file>``
MOODLE_FLAT = re.compile(r"^(?P<name>.+?)_(?P<id>\d+)_assignsubmission_(?P<plugin>[a-z]+)_"
                         r"(?P<file>.+)$")
#: a Canvas file: optional "late_", login, user id, submission id, the student's file name
CANVAS = re.compile(r"^(?P<late>late_)?(?P<login>[^/]+?)(?:_late)?_(?P<id>\d+)_(?P<sub>\d+)_"
                    r"(?P<file>.+)$", re.IGNORECASE)


@dataclass
class Participant:
    """One student of the download and the files they handed in."""

    key: str                   # "moodle:<id>", "canvas:<id>", "file:<name>"
    name: str                  # full name (Moodle) or login (Canvas)
    id: str                    # participant id (Moodle) or user id (Canvas); "" when unknown
    lms: str                   # "moodle", "canvas" or "folder"
    folder: str = ""           # Moodle's folder name, kept for the feedback files
    late: bool = False
    files: list[Member] = field(default_factory=list)


def participants(members: list[Member]) -> tuple[list[Participant], list[Member]]:
    """Group a download's files by participant; also return the files no one could be told from."""
    found: dict[str, Participant] = {}
    loose: list[Member] = []
    for m in members:
        moodle = next((i for i, p in enumerate(m.parts[:-1]) if MOODLE.match(p)), None)
        if moodle is not None:
            folder = m.parts[moodle]
            g = MOODLE.match(folder)
            assert g is not None
            key = f"moodle:{g['id']}"
            p = found.setdefault(key, Participant(key, g["name"], g["id"], "moodle", folder))
            p.files.append(Member(m.parts[moodle + 1:], m.data))
            continue
        flat = MOODLE_FLAT.match(m.parts[0]) if len(m.parts) == 1 else None
        if flat:
            key = f"moodle:{flat['id']}"
            folder = f"{flat['name']}_{flat['id']}_assignsubmission_file_"
            p = found.setdefault(key, Participant(key, flat["name"], flat["id"], "moodle", folder))
            p.files.append(Member((flat["file"],), m.data))
            continue
        c = CANVAS.match(m.parts[0]) if m.parts else None
        if c:
            key = f"canvas:{c['id']}"
            p = found.setdefault(key, Participant(key, c["login"], c["id"], "canvas"))
            p.late |= bool(c["late"]) or "_late_" in m.parts[0].lower()
            p.files.append(Member((c["file"], *m.parts[1:]), m.data))
            continue
        loose.append(m)
    return sorted(found.values(), key=lambda p: (p.name.casefold(), p.id)), loose
