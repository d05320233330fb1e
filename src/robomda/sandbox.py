"""The folders a model may read other files from (its sandbox), as the import decides them.

The same rules as ``xslt/import/files.xsl`` (fp:sandbox, fp:in-sandbox,
fp:ref-uri), so that batch hashing, watch and diagnostics name the files the
import reads:

- the model's folder and the folders of the model path (``--model-path``);
- the model's *project*: the nearest folder at or above the model's folder
  that holds a project marker (:data:`MARKERS`: an Eclipse ``.project``, a
  git, Mercurial or Subversion root); without one, the model's folder alone;
- the other projects of its *workspace* (the folder holding the project's
  folder): a folder beside the project that holds a marker itself. An
  ``href`` ``platform:/resource/<Project>/<path>`` names ``<path>`` in the
  workspace's project ``<Project>`` (else in a model-path folder named
  ``<Project>`` or holding it).

Never anything else, and never the network.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from pathlib import Path

__all__ = ["MARKERS", "Sandbox", "is_project", "project_of"]

# files whose presence makes a folder a project (the XSLT tests them with
# unparsed-text-available: files, not folders): Eclipse, git (repository or
# worktree / submodule, where .git is a file), Mercurial, Subversion
MARKERS = (".project", ".git/HEAD", ".git", ".hg/requires", ".svn/entries")
_SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.\-]*:")
_PLATFORM = re.compile(r"^platform:/resource/([^/]+)/(.*)$", re.I)


def is_project(folder: Path) -> bool:
    """Whether ``folder`` holds a project marker (:data:`MARKERS`)."""
    return any((folder / marker).is_file() for marker in MARKERS)


def project_of(folder: Path) -> Path | None:
    """The nearest folder at or above ``folder`` that is a project, if any."""
    for candidate in (folder, *folder.parents):
        if is_project(candidate):
            return candidate
    return None


def _lexical(path: Path) -> Path:
    return Path(os.path.normpath(path.absolute()))


@dataclass(frozen=True)
class Sandbox:
    """The sandbox of a model: its folder, its model path ``search``, its project and workspace."""

    folder: Path
    search: tuple[Path, ...]
    project: Path | None
    workspace: Path | None

    @classmethod
    def of(cls, model: Path, search: tuple[Path, ...] = ()) -> Sandbox:
        """The sandbox of ``model`` (its folder as the import sees it: symbolic links resolved)."""
        folder = model.resolve().parent
        project = project_of(folder)
        workspace = project.parent if project is not None and project.parent != project else None
        return cls(folder, tuple(_lexical(d) for d in search), project, workspace)

    @property
    def roots(self) -> tuple[Path, ...]:
        """The folders whose files may all be read: the model's, the model path's, the project's."""
        return (self.folder, *self.search, *((self.project,) if self.project else ()))

    def contains(self, path: Path) -> bool:
        """Whether the file ``path`` (lexically absolute) may be read."""
        if any(path.is_relative_to(root) for root in self.roots):
            return True
        if self.workspace is None or not path.is_relative_to(self.workspace):
            return False
        steps = path.relative_to(self.workspace).parts
        return len(steps) > 1 and is_project(self.workspace / steps[0])

    def resolve(self, ref: str, base: Path) -> Path | None:
        """The file a reference's document part ``ref`` (URL-decoded) names, written in a file of folder
        ``base``: a relative path, a ``file:`` URI or ``platform:/resource/<Project>/<path>``; None for any
        other scheme."""
        platform = _PLATFORM.match(ref)
        if platform:
            return self._platform(platform.group(1), platform.group(2))
        if ref.lower().startswith("file:"):
            return _lexical(Path("/") / ref[5:].lstrip("/"))
        return None if _SCHEME.match(ref) else _lexical(base / ref)

    def _platform(self, project: str, rest: str) -> Path | None:
        """Where ``platform:/resource/<project>/<rest>`` is: the first of the workspace's project, a
        model-path folder holding the project, a model-path folder that is it, that holds the file."""
        folders = [*((self.workspace / project,) if self.workspace else ()),
                   *(root / project for root in self.search),
                   *(root for root in self.search if root.name == project)]
        candidates = [_lexical(folder / rest) for folder in folders]
        return next((c for c in candidates if c.is_file()), candidates[0] if candidates else None)
