"""The files a model is made of: the model file, the model files it references, the URDF files they name.

Batch mode hashes them (a changed library or robot description regenerates
the models that use it) and watch mode stats them (a save of any of them
regenerates the model); both ask this module, so they agree on what a
model reads.
"""

from __future__ import annotations

import os
from pathlib import Path
from urllib.parse import unquote

from lxml import etree

from robomda.diagnostics import file_ref_path, linked_files

__all__ = ["urdf_files", "robot_files", "model_files"]

_PROFILE_URI = "http://robomda.org/profile/robomda/1"


def urdf_files(model: Path) -> list[Path]:
    """The URDF files the «Robot» stereotype applications of ``model`` name (tag urdf), as the import reads
    them (xslt/import/urdf.xsl: relative to the model file; no other URI scheme than file:), there or not."""
    try:
        root = etree.parse(str(model), etree.XMLParser(huge_tree=True, resolve_entities=False,
                                                       no_network=True)).getroot()
    except (OSError, etree.XMLSyntaxError):
        return []
    found = []
    for app in root:
        if not isinstance(app.tag, str) or etree.QName(app).localname != "Robot":
            continue
        if (app.prefix or "").lower() != "robomda" and etree.QName(app).namespace != _PROFILE_URI:
            continue
        named = (app.get("urdf") or app.findtext("urdf") or "").strip().replace("\\", "/")
        path = file_ref_path(unquote(named), model.parent) if named else None
        if path is not None:
            found.append(Path(os.path.normpath(path)))
    return found


def robot_files(model: Path, linked: list[Path]) -> list[Path]:
    """The URDF files ``model`` and the model files it references (``linked``) name (:func:`urdf_files`),
    in that order."""
    return [path for source in (model, *linked) for path in urdf_files(source)]


def model_files(model: Path, search: tuple[Path, ...] = ()) -> list[Path]:
    """``model``, the model files it references (:func:`linked_files`, ``search`` being the model path)
    and the URDF files any of them names (there or not), each once, in that order."""
    linked = linked_files(model, search)
    return list(dict.fromkeys([model, *linked, *robot_files(model, linked)]))
