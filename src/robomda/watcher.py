"""Watch mode: regenerate a package on each save of its model or of any file the model reads.

A :class:`Watcher` keeps a list of models and, on each :meth:`Watcher.poll`,
regenerates those whose files changed since the last one: the model file,
the model files it references (libraries, split models) and the URDF files
they name (:func:`robomda.inputs.model_files`, the files batch mode hashes).
Every run happens in this process, so each stylesheet, schema and rule set
is compiled once, by the first run, and a regeneration costs only the
transforms (about 0.05 s of CPU for the headlamp model).

Changes are seen by polling ``os.stat``: modification time, size and inode
of each file (an editor that saves by renaming a new file over the old one
changes the inode). A few stats a poll cost nothing beside a regeneration,
and polling needs no dependency and works on every file system, network
mounts included, where inotify does not.

A model saved half-way (not yet well-formed, or referencing a file not yet
written) fails like any run, with located diagnostics and nothing written
(the output folder is replaced in one atomic step, or not at all, see
:mod:`robomda.output`); the next save regenerates it.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from robomda.diagnostics import EXIT_OK, Diagnostic, as_error
from robomda.inputs import model_files

if TYPE_CHECKING:  # robomda.api (the engine) is imported by the first run
    from robomda.api import PackageInfo

__all__ = ["Regeneration", "Watcher", "watch", "output_folders"]

# what a file looked like at a poll: (modification time in ns, size, inode), or None when absent
_Stamp = tuple[int, int, int] | None


@dataclass
class Regeneration:
    """One run of a watched model: what it found and what it wrote."""

    model: Path
    out: Path
    exit_code: int
    diagnostics: list[Diagnostic] = field(default_factory=list)
    summary: str = ""  # what was written, or why nothing was
    seconds: float = 0.0  # wall time
    cpu_seconds: float = 0.0  # CPU time of this process (SaxonC runs in it)

    def count(self, severity: str) -> int:
        return sum(1 for d in self.diagnostics if d.severity == severity)

    def line(self) -> str:
        """The one-line result: model, outcome, counts, time."""
        if self.exit_code == EXIT_OK:
            found = f", {_counted(self.count('warning'), 'warning')}" if self.count("warning") else ""
            return f"{self.model}: {self.summary}{found} ({self.seconds:.2f} s)"
        first = next((d for d in self.diagnostics if d.severity == "error"), None)
        cause = f": first {first.format()}" if first is not None else ""
        errors = _counted(self.count("error"), "error")
        return f"{self.model}: failed, {errors}, nothing written{cause} ({self.seconds:.2f} s)"


def _counted(count: int, noun: str) -> str:
    return f"{count} {noun}" + ("" if count == 1 else "s")


def output_folders(models: Sequence[Path], out: Path) -> dict[Path, Path]:
    """Where each model's package goes: ``out`` itself for one model (as ``generate`` does); for several,
    ``out``/<the model's path below the folder that holds them all> (as ``generate DIR`` does)."""
    if len(models) == 1:
        return {models[0]: out}
    common = Path(os.path.commonpath([m.absolute().parent for m in models]))
    return {m: out / m.absolute().relative_to(common) for m in models}


def _stamp(path: Path) -> _Stamp:
    try:
        status = path.stat()
    except OSError:
        return None
    return status.st_mtime_ns, status.st_size, status.st_ino


class Watcher:
    """Regenerates the models whose files changed, each into its output folder, in this process.

    The options are those of :func:`robomda.generate`. The first
    :meth:`poll` regenerates every model.
    """

    def __init__(self, models: Sequence[Path | str], out: Path | str, target: str | None = None, *,
                 package_name: str = "", type_map: Path | str | None = None, package: PackageInfo | None = None,
                 model_path: Sequence[Path | str] = ()) -> None:
        self.outputs = output_folders([Path(m) for m in models], Path(out))
        self.options = {"target": target, "package_name": package_name, "type_map": type_map, "package": package,
                        "model_path": model_path}
        self._search = tuple(Path(d) for d in model_path)
        self._extra = [Path(type_map)] if type_map is not None else []
        self._stamps: dict[Path, dict[Path, _Stamp]] = {}

    def _files(self, model: Path) -> list[Path]:
        return [*model_files(model, self._search), *self._extra]

    def poll(self) -> list[Regeneration]:
        """Regenerate every model one of whose files changed (or appeared, or went) since the last poll."""
        done = []
        for model, out in self.outputs.items():
            known = self._stamps.get(model)
            now = {path: _stamp(path) for path in (known or {model: None})}
            if known is not None and now == known:
                continue
            done.append(self.regenerate(model, out))
            # the stamps from before the run: a save during it is seen by the next poll; files the
            # model has read since (a new reference) from now
            self._stamps[model] = {path: now[path] if path in now else _stamp(path) for path in self._files(model)}
        return done

    def regenerate(self, model: Path, out: Path) -> Regeneration:
        """One run of ``generate`` on ``model``; a failure is returned, never raised."""
        from robomda.api import generate

        started, cpu = time.perf_counter(), time.process_time()
        try:
            done = generate(model, out, **self.options)
        except Exception as exc:  # noqa: BLE001 - a failed save is reported, and the watch goes on
            failed = as_error(exc, str(model))
            result = Regeneration(model, out, failed.exit_code, failed.diagnostics)
        else:
            report = done.report
            written = (f"{len(report.written)} written, {len(report.unchanged)} unchanged" if report is not None
                       else "nothing to write")
            result = Regeneration(model, out, EXIT_OK, done.warnings, f"{done.target} package in {out}: {written}")
        result.seconds, result.cpu_seconds = time.perf_counter() - started, time.process_time() - cpu
        return result


def watch(models: Sequence[Path | str], out: Path | str, *, interval: float = 0.25,
          stop: Callable[[], bool] | None = None, on_result: Callable[[Regeneration], None] | None = None,
          **options: Any) -> int:
    """Poll ``models`` every ``interval`` seconds and regenerate on change, until ``stop()`` says so.

    Each regeneration goes to ``on_result``. Returns the exit code of the
    latest run of each model, the worst one (0 when all succeeded).
    """
    watcher = Watcher(models, out, **options)
    latest: dict[Path, int] = {}
    while True:
        for result in watcher.poll():
            latest[result.model] = result.exit_code
            if on_result is not None:
                on_result(result)
        if stop is not None and stop():
            return max(latest.values(), default=EXIT_OK)
        time.sleep(interval)

