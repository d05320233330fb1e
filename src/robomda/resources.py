"""Where the stylesheets, schemas and pipeline manifests live.

In a wheel they are packaged under ``robomda/resources``; in a source checkout
(editable install, tests) they are the top-level folders of the repository.
Either way the layout below the root is the same, so the manifests' relative
paths hold.
"""

from __future__ import annotations

from pathlib import Path

__all__ = ["resource_root", "pipeline_path", "available_targets"]


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


def available_targets() -> list[str]:
    """Targets = pipelines that yield files (not ``import`` or ``check``, which yield a model)."""
    return sorted(p.stem for p in (resource_root() / "pipelines").glob("*.xml")
                  if 'yields="files"' in p.read_text(encoding="utf-8"))
