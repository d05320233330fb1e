"""The files a model is made of: the model file, the model files it references, the URDF files they name,
the product line files its jobs name.

Batch mode hashes them (a changed library or robot description regenerates
the models that use it) and watch mode stats them (a save of any of them
regenerates the model); both ask this module, so they agree on what a
model reads.
"""

from __future__ import annotations

import functools
import os
from pathlib import Path
from urllib.parse import unquote

from lxml import etree

from robomda.diagnostics import file_ref_path, linked_files

__all__ = ["urdf_files", "robot_files", "job_files", "model_files"]

_PROFILE_URI = "http://robomda.org/profile/robomda/1"


# the file-naming tags of the robomda profile: stereotype -> tag
_FILE_TAGS = {"Robot": "urdf", "Job": "configuration"}


@functools.lru_cache(maxsize=16)
def _named(model: str, stamp: tuple[int, ...]) -> dict[str, tuple[str, ...]]:
    """What the stereotype applications of ``model`` name in the tags of _FILE_TAGS, by stereotype: one
    parse per version of the file (``stamp``: its modification and change times, size and inode), however
    many ask (batch mode hashes the URDF files and the jobs' configurations of one model)."""
    try:
        root = etree.parse(model, etree.XMLParser(huge_tree=True, resolve_entities=False, no_network=True)).getroot()
    except (OSError, etree.XMLSyntaxError):
        return {}
    found: dict[str, list[str]] = {}
    for app in root:
        stereotype = etree.QName(app).localname if isinstance(app.tag, str) else ""
        if stereotype not in _FILE_TAGS:
            continue
        if (app.prefix or "").lower() != "robomda" and etree.QName(app).namespace != _PROFILE_URI:
            continue
        tag = _FILE_TAGS[stereotype]
        named = (app.get(tag) or app.findtext(tag) or "").strip().replace("\\", "/")
        if named:
            found.setdefault(stereotype, []).append(named)
    return {k: tuple(v) for k, v in found.items()}


def _tagged_files(model: Path, stereotype: str) -> list[Path]:
    """The files the ``stereotype`` applications of ``model`` name in its tag of _FILE_TAGS (relative to
    the model file; no other URI scheme than file:), there or not."""
    try:
        stat = model.stat()
    except OSError:
        return []
    found = []
    stamp = (stat.st_mtime_ns, stat.st_ctime_ns, stat.st_size, stat.st_ino)
    for named in _named(str(model), stamp).get(stereotype, ()):
        path = file_ref_path(unquote(named), model.parent)
        if path is not None:
            found.append(Path(os.path.normpath(path)))
    return found


def urdf_files(model: Path) -> list[Path]:
    """The URDF files the «Robot» stereotype applications of ``model`` name (tag urdf), as the import reads
    them (xslt/import/urdf.xsl), there or not."""
    return _tagged_files(model, "Robot")


def job_files(model: Path) -> list[Path]:
    """The configurations the «Job» stereotype applications of ``model`` name (tag configuration:
    docs/jobs.md) and the places of the feature model and resolution model of each (its folder and the one
    above, as xslt/m2m/variability/jobs.xsl looks for them), there or not."""
    return list(dict.fromkeys(path for config in _tagged_files(model, "Job")
                              for path in (config, *(folder / name for folder in (config.parent, config.parent.parent)
                                                     for name in ("model.xml", "resolution.xml")))))


def robot_files(model: Path, linked: list[Path]) -> list[Path]:
    """The URDF files ``model`` and the model files it references (``linked``) name (:func:`urdf_files`),
    in that order."""
    return [path for source in (model, *linked) for path in urdf_files(source)]


def model_files(model: Path, search: tuple[Path, ...] = ()) -> list[Path]:
    """``model``, the model files it references (:func:`linked_files`, ``search`` being the model path)
    and the URDF files any of them names, then the product line files its jobs name (:func:`job_files`), there
    or not, each once, in that order."""
    linked = linked_files(model, search)
    return list(dict.fromkeys([model, *linked, *robot_files(model, linked), *job_files(model)]))
