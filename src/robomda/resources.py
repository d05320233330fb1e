"""Where the stylesheets, schemas and pipeline manifests live.

In a wheel they are packaged under ``robomda/resources``; in a source checkout
(editable install, tests) they are the top-level folders of the repository.
Either way the layout below the root is the same, so the manifests' relative
paths hold.
"""

from __future__ import annotations

import functools
from pathlib import Path

from lxml import etree

__all__ = ["resource_root", "pipeline_path", "available_targets", "target_of_middleware", "default_target"]


def resource_root() -> Path:
    """The folder holding ``xslt/``, ``schemas/`` and ``pipelines/``."""
    here = Path(__file__).resolve().parent
    for root in (here / "resources", here.parent.parent):
        if (root / "pipelines").is_dir() and (root / "xslt").is_dir():
            return root
    raise FileNotFoundError(f"robomda resources not found near {here}")


def pipeline_path(name: str) -> Path:
    """The manifest of pipeline ``name`` (``import``, ``orocos`` ...)."""
    return resource_root() / "pipelines" / f"{name}.xml"


_PIPELINE_NS = "{urn:robomda:pipeline:1}"


@functools.lru_cache(maxsize=None)
def _manifests() -> tuple[tuple[str, tuple[str, ...], bool], ...]:
    """(name, middlewares served, default) of every target, by name: the pipelines that yield files."""
    found = []
    for path in sorted((resource_root() / "pipelines").glob("*.xml")):
        root = etree.parse(str(path)).getroot()
        if (root.tag == f"{_PIPELINE_NS}pipeline" and root.get("yields") == "files"
                and root.get("target") not in ("false", "0")):
            found.append((path.stem, tuple((root.get("serves") or "").split()),
                          root.get("default") in ("true", "1")))
    return tuple(found)


def available_targets() -> list[str]:
    """Targets = pipelines that yield files (not ``import`` or ``check``, which yield a model, nor
    ``diagrams``, marked ``target="false"``: its files join a target's or are written alone)."""
    return [name for name, _, _ in _manifests()]


def target_of_middleware() -> dict[str, str]:
    """Middleware name (as the PIM writes it: OROCOS, ROS, ROS2 ...) -> the target that serves it."""
    return {middleware: name for name, serves, _ in _manifests() for middleware in serves}


def default_target() -> str:
    """The target for a model deployed on no middleware a target serves (the manifest marked default)."""
    return next(name for name, _, default in _manifests() if default)
