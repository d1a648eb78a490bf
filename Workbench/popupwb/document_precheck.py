"""Checks an .FCStd file before FreeCAD reads it: FreeCAD's XML reader expands entities without
bound (a "billion laughs" DOCTYPE grows it until memory runs out) and reads a cut-off
Document.xml as far as it goes, silently leaving objects out. No FreeCAD needed here.
"""

import xml.etree.ElementTree as ElementTree
import zipfile

MAX_DOCUMENT_XML_BYTES = 256 << 20  # far beyond any PopUp document


def check_fcstd(path):
    """Raises ValueError saying what is wrong with the document at `path`; returns None if
    FreeCAD may open it."""
    if not zipfile.is_zipfile(path):
        raise ValueError("not a FreeCAD document: an .FCStd file is a zip archive")
    with zipfile.ZipFile(path) as archive:
        try:
            info = archive.getinfo("Document.xml")
        except KeyError:
            raise ValueError("not a FreeCAD document: it has no Document.xml") from None
        if info.file_size > MAX_DOCUMENT_XML_BYTES:
            raise ValueError(
                f"Document.xml is {info.file_size >> 20} MiB, more than the "
                f"{MAX_DOCUMENT_XML_BYTES >> 20} MiB PopUp reads"
            )
        try:
            text = archive.read(info)
        except (zipfile.BadZipFile, OSError, EOFError) as e:
            raise ValueError(f"Document.xml cannot be read from the archive ({e})") from None
    # FreeCAD writes no DOCTYPE; one that declares entities is never a document of ours.
    if b"<!DOCTYPE" in text or b"<!ENTITY" in text:
        raise ValueError(
            "Document.xml declares a DOCTYPE or entities, which FreeCAD never writes; "
            "refused unread (entity expansion could exhaust memory)"
        )
    try:
        root = ElementTree.fromstring(text)
    except ElementTree.ParseError as e:
        raise ValueError(f"Document.xml is damaged ({e}); the document would load incomplete")
    # Two objects of one name: FreeCAD keeps one and silently drops or renames the other.
    seen = set()
    for obj in root.iterfind("./Objects/Object"):
        name = obj.get("name")
        if name in seen:
            raise ValueError(f"Document.xml names object {name!r} twice; the document is damaged")
        seen.add(name)
