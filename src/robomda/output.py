"""Write a file set into an output folder, all or nothing, never losing user work.

Rules (the file set's ``mode`` says which applies):

- ``generated`` files are rewritten on every run, but only over a file that
  robomda itself wrote there and nobody changed since (its hash is in the
  folder's state file ``.robomda/state.json``). Any other existing file at
  that path stops the run *before anything is written*.
- ``user`` files are the user's to edit: written only when absent; when the
  user's copy differs from the fresh one, the fresh one goes beside it as
  ``PATH.robomda-new`` for diffing.
- generated files of an earlier run that the new run no longer produces are
  removed if unchanged, kept (and reported) if edited.

Every file is written to a temporary name first and then renamed, so a file
is either the old or the new version, never half of one.
"""

from __future__ import annotations

import hashlib
import json
import os
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree

from robomda.diagnostics import EXIT_INPUT, Diagnostic, RobomdaError

__all__ = ["WriteReport", "write_fileset", "atomic_write", "STATE_FILE", "NEW_SUFFIX"]

STATE_FILE = Path(".robomda") / "state.json"
NEW_SUFFIX = ".robomda-new"
_FS = "urn:robomda:fileset:1"


@dataclass
class WriteReport:
    written: list[str] = field(default_factory=list)
    unchanged: list[str] = field(default_factory=list)
    kept_user: list[str] = field(default_factory=list)
    fresh_copies: list[str] = field(default_factory=list)
    removed: list[str] = field(default_factory=list)
    kept_stale: list[str] = field(default_factory=list)


def _sha(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _read_state(out: Path) -> dict[str, str]:
    try:
        data = json.loads((out / STATE_FILE).read_text(encoding="utf-8"))
        files = data.get("files", {})
        return {str(k): str(v) for k, v in files.items()} if isinstance(files, dict) else {}
    except (OSError, ValueError):
        return {}


def atomic_write(path: Path, data: bytes) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def write_fileset(files: etree._Element, out: Path) -> WriteReport:
    """Write the validated file set ``files`` into folder ``out``."""
    out = out.resolve()
    if out.exists() and not out.is_dir():
        raise RobomdaError([Diagnostic("error", "IO001", f"output {out} exists and is not a folder")], EXIT_INPUT)
    state = _read_state(out)
    plan: list[tuple[str, bytes, str]] = []  # (path, data, mode)
    conflicts: list[Diagnostic] = []
    for node in files.iterchildren(f"{{{_FS}}}file"):
        rel, mode = node.get("path"), node.get("mode", "generated")
        data = (node.text or "").encode("utf-8")
        target = out / rel
        if mode == "generated" and target.exists():
            current = _sha(target.read_bytes()) if target.is_file() else None
            if current is None or state.get(rel) != current:
                conflicts.append(Diagnostic(
                    "error", "OUT001",
                    f"refusing to overwrite {target}: robomda did not write it, or it was edited since; "
                    "move your changes into the user files (the ones robomda writes once) or remove it",
                    file=str(target)))
        plan.append((rel, data, mode))
    if conflicts:
        raise RobomdaError(conflicts, EXIT_INPUT)

    report = WriteReport()
    new_state: dict[str, str] = {}
    produced = {rel for rel, _, _ in plan}
    for rel, data, mode in plan:
        target = out / rel
        digest = _sha(data)
        if mode == "user" and target.exists():
            report.kept_user.append(rel)
            side = target.with_name(target.name + NEW_SUFFIX)
            if target.read_bytes() != data:
                atomic_write(side, data)
                report.fresh_copies.append(rel + NEW_SUFFIX)
            elif side.exists():
                side.unlink()
            continue
        if target.exists() and target.read_bytes() == data:
            report.unchanged.append(rel)
        else:
            atomic_write(target, data)
            report.written.append(rel)
        if mode == "generated":
            new_state[rel] = digest
    for rel, digest in sorted(state.items()):
        if rel in produced:
            continue
        target = out / rel
        if target.is_file() and _sha(target.read_bytes()) == digest:
            target.unlink()
            report.removed.append(rel)
        elif target.exists():
            report.kept_stale.append(rel)
    payload = {"generator": "robomda", "files": dict(sorted(new_state.items()))}
    atomic_write(out / STATE_FILE, (json.dumps(payload, indent=1) + "\n").encode("utf-8"))
    return report
