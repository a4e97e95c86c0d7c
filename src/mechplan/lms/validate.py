"""Checks of the quiz files against the schemas in ``schemas/`` (XSD 1.1, xmlschema): the
Moodle XML question bank (``moodle_xml.xsd``, derived from Moodle's documented format and its
importer) and the Canvas QTI 1.2 package (``qti_asi_1p2.xsd`` for each assessment; the manifest
checked for the files it lists). Each returns the problems found, empty when the file is valid."""

from __future__ import annotations

import functools
import io
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path
from typing import Any

SCHEMAS = Path(__file__).with_name("schemas")
MOODLE_XSD = SCHEMAS / "moodle_xml.xsd"
QTI_XSD = SCHEMAS / "qti_asi_1p2.xsd"


@functools.lru_cache(maxsize=2)
def _schema(path: Path) -> Any:
    import xmlschema

    return xmlschema.XMLSchema11(str(path))


def _errors(schema: Any, data: bytes, where: str = "") -> list[str]:
    import xmlschema

    try:
        found = list(schema.iter_errors(data.decode("utf-8")))
    except (xmlschema.XMLSchemaException, ET.ParseError, UnicodeDecodeError) as exc:
        return [f"{where}{exc}"]
    return [f"{where}{e.path}: {e.reason}" for e in found]


def moodle_quiz_errors(data: bytes) -> list[str]:
    """What makes a Moodle XML question bank invalid (path: reason)."""
    return _errors(_schema(MOODLE_XSD), data)


def qti_errors(data: bytes) -> list[str]:
    """What makes one QTI 1.2 assessment document invalid."""
    return _errors(_schema(QTI_XSD), data)


def canvas_package_errors(package: bytes) -> list[str]:
    """What makes a Canvas QTI package invalid: a manifest without resources, a resource whose
    file is missing or not QTI 1.2, an assessment the schema refuses."""
    out: list[str] = []
    with zipfile.ZipFile(io.BytesIO(package)) as zf:
        names = set(zf.namelist())
        if "imsmanifest.xml" not in names:
            return ["imsmanifest.xml: missing"]
        root = ET.fromstring(zf.read("imsmanifest.xml"))
        resources = [r for r in root.iter() if r.tag.endswith("}resource")]
        if not resources:
            out.append("imsmanifest.xml: no resource")
        for r in resources:
            if r.get("type") != "imsqti_xmlv1p2":
                out.append(f"imsmanifest.xml: resource {r.get('identifier')}: type "
                           f"{r.get('type')!r}, expected 'imsqti_xmlv1p2'")
            for f in (f for f in r if f.tag.endswith("}file")):
                href = f.get("href", "")
                if href not in names:
                    out.append(f"imsmanifest.xml: {href}: listed, not in the package")
                else:
                    out += [f"{href}{e}" for e in qti_errors(zf.read(href))]
    return out
