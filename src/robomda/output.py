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
- a user file of an earlier run that the new run no longer produces (its
  component was renamed or removed) while it is still there stops the run
  before anything is written (OUT003): the build would no longer compile it,
  so the user's code would drop out of the robot in silence. The message
  names the file and, for a rename, the new file to move the code into.
  So does a user file whose path now belongs to another element (its own
  was removed or renamed and a renamed one took its name) while that
  element's earlier user file is still there: two codes for one file.
- a user file whose element changed what the generated code requires of it
  (ports, operations, hooks: the file set's ``signature``) gets a warning
  naming the file and the changes (OUT004); its fresh copy goes beside it.
- a user property file (``*.cpf``, Orocos tuned values) that sets a property
  its instance does not declare, or gives one another type, gets a located
  warning (OUT005): the deployer would ignore or refuse it.

All or nothing, even when robomda is killed: the new package is built in a
staging folder beside the output (``.<name>.robomda-new``): every file the
output already holds and the run keeps (user files, the user's own files,
unchanged generated files) is carried over as a hard link (a copy where the
file system has none), the new and changed files are written, and the state
file comes last. Then the staging folder and the output trade places in one
atomic step (``renameat2(RENAME_EXCHANGE)`` on Linux; elsewhere two renames
that the next run completes), and the old tree is removed. Killed at any
instant, the output is the old package or the new one; the next run clears
what an interrupted one left beside it (``recover``). A shell whose working
directory is inside the output stays in the old, removed tree: ``cd .``.
"""

from __future__ import annotations

import ctypes
import errno
import hashlib
import json
import os
import re
import shutil
import stat
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree

from robomda.diagnostics import EXIT_INPUT, Diagnostic, RobomdaError
from robomda.ros_params import legacy_user_params

__all__ = ["WriteReport", "Drift", "write_fileset", "compare_fileset", "user_findings", "atomic_write", "recover",
           "STATE_FILE", "NEW_SUFFIX"]

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
    warnings: list[Diagnostic] = field(default_factory=list)


@dataclass
class Drift:
    """How a folder differs from the file set a run would write (:func:`compare_fileset`); paths relative
    to the folder, sorted. ``diffs`` holds a unified diff per path (``a/PATH`` is the folder's file,
    ``b/PATH`` the new one, ``/dev/null`` for a missing side)."""

    added: list[str] = field(default_factory=list)
    changed: list[str] = field(default_factory=list)
    removed: list[str] = field(default_factory=list)
    diffs: dict[str, str] = field(default_factory=dict)

    def __bool__(self) -> bool:
        return bool(self.added or self.changed or self.removed)

    def lines(self) -> list[str]:
        """One line per path, ``added   PATH`` / ``changed PATH`` / ``removed PATH``, sorted by path."""
        rows = [(rel, kind) for kind, paths in (("added", self.added), ("changed", self.changed),
                                                ("removed", self.removed)) for rel in paths]
        return [f"{kind:<7} {rel}" for rel, kind in sorted(rows)]

    def diff(self, prefix: str = "") -> str:
        """Every path's diff, in path order; ``prefix`` (a folder, ending in "/") goes before each path."""
        if not prefix:
            return "".join(self.diffs[rel] for rel in sorted(self.diffs))
        parts = []
        for rel in sorted(self.diffs):
            old, new, rest = self.diffs[rel].split("\n", 2)
            parts.append("\n".join(re.sub(r"^(---|\+\+\+) ([ab])/", lambda m: f"{m[1]} {m[2]}/{prefix}", line) for line in (old, new))
                         + "\n" + rest)
        return "".join(parts)


def _unified(rel: str, old: bytes | None, new: bytes | None) -> str:
    """A git-style unified diff of one file (``patch -p1`` inside the folder applies it)."""
    def text(data: bytes | None) -> list[str]:
        return data.decode("utf-8", "replace").splitlines(keepends=True) if data is not None else []

    import difflib  # only to compare a folder with a file set: a command that writes one never loads it

    lines = list(difflib.unified_diff(text(old), text(new), "a/" + rel if old is not None else "/dev/null",
                                      "b/" + rel if new is not None else "/dev/null"))
    return "".join(line if line.endswith("\n") else line + "\n\\ No newline at end of file\n" for line in lines)


def _folder_files(out: Path) -> list[str]:
    """Every regular file under ``out`` (relative, posix), without robomda's own bookkeeping and fresh copies."""
    found = []
    for top, dirs, names in os.walk(out):
        rel_dir = Path(top).relative_to(out)
        if rel_dir == Path("."):
            dirs[:] = [d for d in dirs if d != STATE_FILE.parts[0]]
        found += [(rel_dir / n).as_posix() for n in names if not n.endswith(NEW_SUFFIX)]
    return found


def compare_fileset(files: etree._Element, out: Path, *, exact: bool = False) -> Drift:
    """How folder ``out`` differs from what :func:`write_fileset` would make of it; reads only.

    A generated file is ``added`` when missing, ``changed`` when its bytes
    differ (edited or out of date). A user file (written once, the user's to
    edit) counts only when missing: its content is the user's. ``removed``
    are the generated files of the folder's state that the file set no
    longer has. With ``exact`` (a golden copy, no user edits), user files are
    compared by content too and every other file of the folder (robomda's
    ``.robomda/`` and ``*.robomda-new`` aside) counts as ``removed``.
    """
    out = Path(out)
    drift = Drift()
    produced: set[str] = set()
    for node in files.iterchildren(f"{{{_FS}}}file"):
        rel, mode = node.get("path"), node.get("mode", "generated")
        data = (node.text or "").encode("utf-8")
        produced.add(rel)
        target = out / rel
        if not target.is_file():
            drift.added.append(rel)
            drift.diffs[rel] = _unified(rel, None, data)
        elif mode == "generated" or exact:
            current = target.read_bytes()
            if current != data:
                drift.changed.append(rel)
                drift.diffs[rel] = _unified(rel, current, data)
    gone = _folder_files(out) if exact and out.is_dir() else _read_state(out)
    for rel in sorted(set(gone) - produced):
        if (out / rel).is_file():
            drift.removed.append(rel)
            drift.diffs[rel] = _unified(rel, (out / rel).read_bytes(), None)
    drift.added.sort()
    drift.changed.sort()
    return drift


def _sha(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _read_state(out: Path, part: str = "files") -> dict:
    """``files`` (path -> hash of each generated file) or ``user`` (path -> what each user file implements)."""
    try:
        data = json.loads((out / STATE_FILE).read_text(encoding="utf-8"))
        found = data.get(part, {})
        return dict(found) if isinstance(found, dict) else {}
    except (OSError, ValueError, AttributeError):
        return {}


def recorded_paths(out: Path) -> list[str]:
    """Every path the writer's record in ``out`` says it wrote (generated and user files), sorted."""
    return sorted({path for part in ("files", "user") for path in _read_state(out, part)})


def _signature_items(signature: str) -> list[str]:
    """The items of a user file's signature, separated by "; " (by line ends in older states)."""
    return [item for item in re.split(r"; |\n", signature) if item]


def _rival(out: Path, before: dict, rel: str, was: dict, node: etree._Element) -> str | None:
    """The user file of the element that now owns path ``rel`` while ``rel`` holds the work on another one
    (removed or renamed, and the new element took its name): that element's own earlier user file, still
    there, which OUT003 asks to move to ``rel``; else None (a new element by an old name takes the file)."""
    old, new = was.get("implements"), node.get("implements")
    if not old or not new or old == new:
        return None
    return next((path for path, info in sorted(before.items()) if path != rel and isinstance(info, dict)
                 and info.get("implements") == new and Path(path).suffix == Path(rel).suffix
                 and (out / path).is_file()), None)


def _taken_over(out: Path, rel: str, was: dict, node: etree._Element, rival: str) -> Diagnostic:
    """OUT003 for user file ``rel``: its path is now the user file of another element, whose own earlier
    user file ``rival`` would move there."""
    return Diagnostic(
        "error", "OUT003", f"user file {rel} holds your work on {was.get('name')} ({was['implements']}), which the new "
        f"package no longer uses, and its path is now the user file of {node.get('implements-name')} "
        f"({node.get('implements')}), whose code is in {rival}: move your work out of {rel} and remove it "
        f"(then move {rival} there); nothing was written", file=str(out / rel))


def _user_drift(out: Path, nodes: list[etree._Element],
                skip: frozenset[str] = frozenset()) -> tuple[list[Diagnostic], list[Diagnostic]]:
    """(OUT003 errors for orphaned user files, OUT004 warnings for user files whose element changed);
    the paths in ``skip`` are judged elsewhere (an earlier layout's file: ros_params)."""
    before = _read_state(out, "user")
    now = {n.get("path"): n for n in nodes}
    errors, warnings = [], []
    for rel, was in sorted(before.items()):
        if not isinstance(was, dict) or not (out / rel).is_file() or rel in skip:
            continue
        node = now.get(rel)
        if node is None:
            moved = [n.get("path") for n in nodes if was.get("implements") and n.get("implements") == was.get("implements")
                     and Path(n.get("path")).suffix == Path(rel).suffix]
            what = f"{was['name']} ({was['implements']})" if was.get("implements") else "an element of the model"
            hint = (f"it is now {moved[0]}: move your code there (rename the class too), then remove {rel}"
                    if moved else "nothing in the new package takes its place (the element is gone or renamed, or "
                    "got a realizing class): move your work out of the package or remove the file")
            errors.append(Diagnostic(
                "error", "OUT003", f"user file {rel} holds your work on {what}, which the new package no longer "
                f"uses: {hint}; nothing was written", file=str(out / rel)))
            continue
        rival = _rival(out, before, rel, was, node)
        if rival:
            errors.append(_taken_over(out, rel, was, node, rival))
            continue
        old_items = set(_signature_items(str(was.get("signature", ""))))
        new_items = set(_signature_items(node.get("signature") or ""))
        if old_items != new_items:
            changes = [f"no more {i}" for i in sorted(old_items - new_items)] + [f"new {i}" for i in sorted(new_items - old_items)]
            warnings.append(Diagnostic(
                "warning", "OUT004", f"{node.get('implements-name')} changed what user file {rel} implements "
                f"({'; '.join(changes)}): update it (the fresh version is beside it as {rel}{NEW_SUFFIX})",
                file=str(out / rel)))
    return errors, warnings


def user_findings(files: etree._Element, out: Path) -> tuple[list[Diagnostic], list[Diagnostic]]:
    """What :func:`write_fileset` would say of the user files in ``out``, writing nothing: (OUT003
    errors, which stop it, and OUT004 / OUT005 warnings)."""
    out = Path(out).resolve()
    nodes = [n for n in files.iterchildren(f"{{{_FS}}}file") if n.get("mode") == "user"]
    legacy = legacy_user_params(files, out)
    errors, warnings = _user_drift(out, nodes, frozenset(legacy.judged))
    return errors + legacy.errors, warnings + legacy.warnings + _user_cpf_names(out, nodes)


def _user_cpf_names(out: Path, nodes: list[etree._Element]) -> list[Diagnostic]:
    """OUT005 for each property a user's .cpf sets that its instance does not declare.

    The deployer's UpdateProperties ignores such a property without a word, so
    a misspelt tuned value would never reach the robot. The instance's
    properties are the ``property NAME TYPE`` items of the file's signature.
    """
    found = []
    for node in nodes:
        rel = node.get("path") or ""
        target = out / rel
        if not rel.endswith(".cpf") or not target.is_file():
            continue
        declared = {}
        for item in _signature_items(node.get("signature") or ""):
            parts = item.split()
            if len(parts) == 3 and parts[0] == "property":
                declared[parts[1]] = parts[2]
        try:
            root = etree.parse(str(target), etree.XMLParser(resolve_entities=False, no_network=True,
                                                             load_dtd=False)).getroot()
        except (etree.XMLSyntaxError, OSError) as exc:
            found.append(Diagnostic("warning", "OUT005", f"user file {rel} is not well-formed XML ({exc}): "
                                    "the deployer will refuse it", file=str(target)))
            continue
        for prop in root.iterchildren("simple", "struct", "sequence"):
            name, kind = prop.get("name"), prop.get("type")
            if name not in declared:
                found.append(Diagnostic(
                    "warning", "OUT005", f"user file {rel} sets property '{name}', which "
                    f"{node.get('implements-name')} does not have (it has: {', '.join(declared) or 'none'}): "
                    "the deployer ignores it", file=str(target), line=prop.sourceline))
            elif prop.tag == "simple" and kind != declared[name]:
                found.append(Diagnostic(
                    "warning", "OUT005", f"user file {rel} gives property '{name}' type '{kind}', but it is "
                    f"'{declared[name]}': the deployer refuses the file", file=str(target), line=prop.sourceline))
            elif prop.tag != "simple":
                shape = _shape(node.get("shape") or "")
                found += _cpf_members(prop, name, shape, f"user file {rel}", str(target))
    return found


def _shape(text: str) -> dict[str, str]:
    """A user .cpf file's shape (its file node's ``shape``): the type of each property path."""
    pairs = (item.rsplit(" ", 1) for item in _signature_items(text))
    return {pair[0]: pair[1] for pair in pairs if len(pair) == 2}


def _cpf_members(struct: etree._Element, path: str, shape: dict[str, str], what: str,
                 file: str) -> list[Diagnostic]:
    """OUT005 below a property: members and elements its type does not have, or of another type.

    The deployer's UpdateProperties ignores a member the type lacks without a word (measured on RTT 2.10:
    the other members are set, the misspelt one keeps its value) and converts a member of another type
    where it can. Elements of an array whose element shape the model does not show (an empty unbounded
    array) are not checked.
    """
    array = shape.get(path, "") == "array" or shape.get(path, "").startswith("/std/vector<")
    found: list[Diagnostic] = []
    for member in struct.iterchildren("simple", "struct", "sequence"):
        name = member.get("name") or ""
        sub = f"{path}[]" if array and re.fullmatch(r"Element[0-9]+", name) else f"{path}.{name}"
        if sub not in shape:
            if array and not any(p.startswith(f"{path}[]") for p in shape):
                continue
            has = sorted({p[len(path):].lstrip(".").split(".")[0].split("[")[0] or "Element<n>"
                          for p in shape if p.startswith((f"{path}.", f"{path}[]"))})
            kind = "elements are" if array else "members are"
            found.append(Diagnostic(
                "warning", "OUT005", f"{what} sets '{name}' in property '{path}' ({sub}), which its type "
                f"'{shape.get(path, '?')}' does not have (its {kind}: {', '.join(has) or 'none'}): the deployer "
                "ignores it without a word (the member you meant keeps the model's value)", file=file,
                line=member.sourceline))
        elif member.tag == "simple" and member.get("type") != shape[sub]:
            found.append(Diagnostic(
                "warning", "OUT005", f"{what} gives '{sub}' type '{member.get('type')}', but it is '{shape[sub]}': "
                "the deployer converts the value where RTT can (a long to a double) and refuses the file where it "
                "cannot", file=file, line=member.sourceline))
        elif member.tag != "simple":
            found += _cpf_members(member, sub, shape, what, file)
    return found


def atomic_write(path: Path, data: bytes) -> None:
    """Write one file so that it is the old or the new version, never half of one."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def _staging(out: Path) -> Path:
    return out.with_name(f".{out.name}.robomda-new")


def _retired(out: Path) -> Path:
    return out.with_name(f".{out.name}.robomda-old")


def _remove_tree(path: Path) -> None:
    if path.is_symlink() or path.is_file():
        path.unlink()
    elif path.exists():
        shutil.rmtree(path)


def recover(out: Path) -> None:
    """Finish or undo what a run interrupted while swapping ``out`` left beside it.

    The staging folder is complete once its state file exists (written last).
    Without ``out``: a complete staging folder becomes ``out`` (the run was
    between its two renames), else the retired old tree goes back. With
    ``out``: whatever is left beside it is an unfinished new tree or the old
    tree after the swap, and is removed.
    """
    out = Path(out).resolve()
    new, old = _staging(out), _retired(out)
    if not out.exists():
        if (new / STATE_FILE).is_file():
            os.rename(new, out)
        elif old.is_dir():
            os.rename(old, out)
    for leftover in (new, old):
        if leftover.exists() or leftover.is_symlink():
            _remove_tree(leftover)


_RENAME_EXCHANGE = 2
_AT_FDCWD = -100


def _exchange(a: Path, b: Path) -> bool:
    """Swap ``a`` and ``b`` atomically (Linux renameat2); False where the system cannot."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        renameat2 = libc.renameat2
    except (OSError, AttributeError):
        return False
    renameat2.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_uint]
    if renameat2(_AT_FDCWD, os.fsencode(a), _AT_FDCWD, os.fsencode(b), _RENAME_EXCHANGE) == 0:
        return True
    err = ctypes.get_errno()
    if err in (errno.ENOSYS, errno.EINVAL, errno.ENOTSUP, errno.EOPNOTSUPP):
        return False
    raise OSError(err, os.strerror(err), str(b))


def _carry_over(out: Path, staging: Path, replaced: set[str]) -> list[tuple[str, Path]]:
    """Recreate ``out`` in ``staging`` without the paths in ``replaced``: hard links, else copies.

    Returns (folder of ``out``, its copy) pairs: their modes are copied once the new files are in.
    """
    folders: list[tuple[str, Path]] = []
    for top, dirs, names in os.walk(out):
        rel_dir = Path(top).relative_to(out)
        (staging / rel_dir).mkdir(exist_ok=True)
        folders.append((top, staging / rel_dir))
        for name in dirs + names:
            src, rel = Path(top) / name, (rel_dir / name).as_posix()
            dst = staging / rel
            mode = os.lstat(src).st_mode
            if stat.S_ISLNK(mode):
                os.symlink(os.readlink(src), dst)
                if name in dirs:
                    dirs.remove(name)  # os.walk does not descend into links; keep it so
            elif stat.S_ISDIR(mode):
                continue
            elif not stat.S_ISREG(mode):
                raise RobomdaError([Diagnostic(
                    "error", "OUT002", f"cannot carry {src} over into the new package: not a regular file, "
                    "folder or link; move it out of the output folder", file=str(src))], EXIT_INPUT)
            elif rel not in replaced:
                try:
                    os.link(src, dst)
                except OSError:
                    shutil.copy2(src, dst)
    return folders


def write_fileset(files: etree._Element, out: Path) -> WriteReport:
    """Write the validated file set ``files`` into folder ``out``, all or nothing."""
    out = Path(out).resolve()
    if out.exists() and not out.is_dir():
        raise RobomdaError([Diagnostic("error", "IO001", f"output {out} exists and is not a folder")], EXIT_INPUT)
    recover(out)
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
                    f"refusing to overwrite {target}: robomda did not write it, or it was edited since (generate "
                    "--diff shows what differs); move your changes into the user files (the ones robomda writes "
                    "once) or remove it",
                    file=str(target)))
        plan.append((rel, data, mode))
    user_nodes = [n for n in files.iterchildren(f"{{{_FS}}}file") if n.get("mode") == "user"]
    legacy = legacy_user_params(files, out)
    orphans, drift = _user_drift(out, user_nodes, frozenset(legacy.judged))
    if conflicts or orphans or legacy.errors:
        raise RobomdaError(conflicts + orphans + legacy.errors, EXIT_INPUT)

    report = WriteReport()
    new_state: dict[str, str] = {}
    writes: dict[str, bytes] = {}  # what the new package has that the old one has not, by path
    drops: set[str] = set()  # what the old package has that the new one has not
    produced = {rel for rel, _, _ in plan}
    for rel, data, mode in plan:
        target = out / rel
        if mode == "user" and target.exists():
            report.kept_user.append(rel)
            side = rel + NEW_SUFFIX
            if target.read_bytes() != data:
                writes[side] = data
                report.fresh_copies.append(side)
            elif (out / side).exists():
                drops.add(side)
            continue
        if target.is_file() and target.read_bytes() == data:
            report.unchanged.append(rel)
        else:
            writes[rel] = data
            report.written.append(rel)
        if mode == "generated":
            new_state[rel] = _sha(data)
    for rel, digest in sorted(state.items()):
        if rel in produced:
            continue
        target = out / rel
        if target.is_file() and _sha(target.read_bytes()) == digest:
            drops.add(rel)
            report.removed.append(rel)
        elif target.exists():
            report.kept_stale.append(rel)
    for rel in sorted(legacy.drops):
        drops.add(rel)
        report.removed.append(rel)
    report.warnings.extend(drift + legacy.warnings)
    report.warnings.extend(_user_cpf_names(out, user_nodes))
    users = {n.get("path"): {"implements": n.get("implements", ""), "name": n.get("implements-name", ""),
                             "signature": n.get("signature", "")} for n in user_nodes}
    payload = {"generator": "robomda", "files": dict(sorted(new_state.items())), "user": dict(sorted(users.items()))}
    writes[STATE_FILE.as_posix()] = (json.dumps(payload, indent=1) + "\n").encode("utf-8")
    _swap_in(out, writes, drops)
    return report


def _swap_in(out: Path, writes: dict[str, bytes], drops: set[str]) -> None:
    """Build the new package beside ``out`` and trade places with it (see the module text)."""
    staging = _staging(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    staging.mkdir()
    try:
        folders = _carry_over(out, staging, set(writes) | drops) if out.exists() else []
        state = writes[STATE_FILE.as_posix()]
        for rel, data in writes.items():
            if rel != STATE_FILE.as_posix():
                path = staging / rel
                path.parent.mkdir(parents=True, exist_ok=True)
                path.write_bytes(data)
                if data.startswith(b"#!"):  # a script (a start script of the deployment): runnable
                    path.chmod(path.stat().st_mode | 0o111)
        # the folders' modes last: a read-only folder of the user's is filled first
        for src_dir, dst_dir in reversed(folders):
            shutil.copymode(src_dir, dst_dir)
        (staging / STATE_FILE).parent.mkdir(parents=True, exist_ok=True)
        (staging / STATE_FILE).write_bytes(state)  # last: the staging folder is complete
    except BaseException:
        _remove_tree(staging)
        raise
    if not out.exists():
        os.rename(staging, out)
    elif _exchange(staging, out):
        _remove_tree(staging)  # now the old tree
    else:
        retired = _retired(out)
        os.rename(out, retired)
        os.rename(staging, out)
        _remove_tree(retired)
