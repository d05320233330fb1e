"""Batch generation: every UML model under a folder, in parallel, incrementally.

- Models are found by content, not by file name: any file whose root element
  is a UML model element (``uml:Model``, ``uml:Package``, ``uml:Profile`` in
  any UML namespace version), or an ``xmi:XMI`` document whose first element
  that is not XMI's own is a UML one (Papyrus' ``.notation`` and ``.di``
  files are XMI documents without UML: they are not models), or an XMI 1.x
  ``XMI`` document (refused with IMP001 when generated).
- Each model gets its own output folder, always: OUT/<path of the model
  relative to DIR> (``cases/headlamp/model.xmi`` ->
  ``OUT/cases/headlamp/model.xmi/``), so ``robot.xmi`` and ``robot.uml``
  beside each other never share one.
- Models run in worker processes (``jobs``, default: the number of CPUs);
  each worker keeps one Saxon engine, so each stylesheet is compiled once
  per worker, not once per model.
- A model is skipped when neither its bytes nor the toolchain (stylesheets,
  schemas, manifests, robomda's version, the target and options) changed
  since the last successful run (content hashes in OUT/.robomda/batch.json),
  and every generated file its output folder's state lists is still there
  with the hash robomda wrote: a deleted or edited output is regenerated
  (and an edited one then refused with OUT001). ``force`` regenerates all.
- A model file that another model of the folder references (a component,
  service or type library of a model split over several files) is a
  library: it is not generated on its own (status ``library``, with a note
  naming a model that uses it), and a model's input hash covers the files it
  references, so changing a library regenerates the models that use it; it
  covers the URDF files its «Robot» stereotypes name too (their joints decide
  the DoF checks), so an edited or removed robot description is checked again.
- A failing model is reported with its diagnostics and does not stop the
  others.
- Check mode (``check``) writes nothing, not even the batch state, and skips
  nothing: each model's output folder is compared with what would be
  generated (status ``drifted`` when it differs, with the files and, with
  ``diff``, their unified diffs; ``ok`` when up to date).
- SIGINT (Ctrl-C) or SIGTERM stops the batch at once: queued models are
  cancelled, the workers are terminated (each output folder is then the old
  package or the new one, see output.py), the batch state is written for
  the models done, and the signal goes on to the caller.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import signal
import sys
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import dataclass, field
from multiprocessing import get_context
from pathlib import Path
from typing import Callable, Sequence

from lxml import etree

from robomda import __version__
from robomda.diagnostics import EXIT_FINDINGS, EXIT_OK, as_error, format_all, linked_files
from robomda.inputs import job_files, robot_files
from robomda.output import STATE_FILE as OUTPUT_STATE
from robomda.output import atomic_write
from robomda.resources import resource_root

__all__ = ["run_variants", "ModelResult", "BatchReport", "find_models", "run_batch", "STATE"]

STATE = Path(".robomda") / "batch.json"
_XMI_NS = re.compile(r"^https?://(schema|www)\.omg\.org/(spec/)?XMI(/[0-9.]+)?/?$", re.I)
_UML_NS = re.compile(r"^https?://(www\.eclipse\.org/uml2/[0-9.]+/UML|(schema|www)\.omg\.org/(spec/)?UML(/[0-9.]+)?)/?$",
                     re.I)
_SKIP_DIRS = {".git", ".robomda", ".venv", "node_modules", "__pycache__"}


@dataclass
class ModelResult:
    """What happened to one model."""

    model: str  # relative to the input folder
    status: str  # "ok", "skipped" (unchanged), "library" (used by another model), "drifted" (check) or "failed"
    files_written: int = 0  # check mode: the files that would change
    seconds: float = 0.0
    diagnostics: list[str] = field(default_factory=list)
    exit_code: int = EXIT_OK
    input_hash: str = ""
    drift: list[str] = field(default_factory=list)  # check mode: "added PATH", "changed PATH", "removed PATH"
    diff: str = ""  # check mode with diff: the unified diffs, paths relative to the batch's output folder


@dataclass
class BatchReport:
    results: list[ModelResult]
    seconds: float

    def count(self, status: str) -> int:
        return sum(1 for r in self.results if r.status == status)

    @property
    def exit_code(self) -> int:
        return max((r.exit_code for r in self.results if r.status in ("failed", "drifted")), default=EXIT_OK)


def _is_uml_model(path: Path) -> bool:
    """True when the file holds a UML model (reads only its start; see the module text)."""
    depth = 0
    try:
        for event, element in etree.iterparse(str(path), events=("start", "end"), resolve_entities=False,
                                              no_network=True, huge_tree=True, load_dtd=False):
            if event == "end":
                depth -= 1
                if depth == 0:
                    return False  # an XMI document with nothing but XMI's own elements
                continue
            depth += 1
            uri = etree.QName(element).namespace or ""
            if depth == 1:
                if element.tag == "XMI" or _UML_NS.match(uri):
                    return True  # XMI 1.x, or a bare UML model
                if not _XMI_NS.match(uri):
                    return False
            elif depth == 2 and not _XMI_NS.match(uri):
                return bool(_UML_NS.match(uri))  # the first child that is not XMI's decides
    except (etree.XMLSyntaxError, OSError, ValueError):
        return False
    return False


def find_models(folder: Path, exclude: Path | None = None) -> list[Path]:
    """Every UML model file under ``folder`` (sorted), skipping ``exclude`` and tool folders."""
    found: list[Path] = []
    exclude = exclude.resolve() if exclude is not None else None
    for current, dirs, files in os.walk(folder):
        here = Path(current)
        dirs[:] = sorted(d for d in dirs if d not in _SKIP_DIRS
                         and (exclude is None or (here / d).resolve() != exclude))
        for name in sorted(files):
            path = here / name
            if _is_uml_model(path):
                found.append(path)
    return found


def toolchain_hash(target: str | None, package_name: str, type_map: Path | None = None,
                   package: tuple[str, str, str] = ("", "", "")) -> str:
    """A hash of everything besides the model that decides the output."""
    digest = hashlib.sha256(f"robomda {__version__} {target} {package_name} {package}".encode())
    if type_map is not None:
        digest.update(type_map.read_bytes())
    root = resource_root()
    for sub in ("xslt", "schemas", "pipelines"):
        for path in sorted((root / sub).rglob("*")):
            if path.is_file():
                digest.update(path.relative_to(root).as_posix().encode() + b"\0" + path.read_bytes())
    return digest.hexdigest()


def _prefix(model: Path, folder: Path) -> str:
    """The model's output folder relative to the batch's, as a diff path prefix."""
    return model.relative_to(folder).as_posix() + "/"


def _output_folder(model: Path, folder: Path, out: Path) -> Path:
    """OUT/<the model's path under DIR>: one folder per model file, whatever its siblings."""
    return out / model.relative_to(folder)


def _outputs_intact(dest: Path) -> bool:
    """True when every generated file ``dest``'s state lists is there with the hash robomda wrote."""
    try:
        files = json.loads((dest / OUTPUT_STATE).read_text(encoding="utf-8")).get("files", {})
        return bool(files) and all(
            (dest / rel).is_file() and hashlib.sha256((dest / rel).read_bytes()).hexdigest() == digest
            for rel, digest in files.items())
    except (OSError, ValueError, AttributeError):
        return False


def _generate_one(model: str, out: str, target: str | None, package_name: str, type_map: str | None,
                  package: tuple[str, str, str] = ("", "", ""), model_path: tuple[str, ...] = (),
                  check: str = "", prefix: str = "", features: str | None = None) -> ModelResult:
    """Worker: one model (the process's engine is reused across calls); ``check``: "", "check" or "diff"
    (the diff's paths start with ``prefix``, the model's folder under the batch's output)."""
    from robomda.api import PackageInfo, generate

    started = time.perf_counter()
    result = ModelResult(model=model, status="ok")
    try:
        done = generate(model, out, target, package_name=package_name, type_map=type_map,
                        package=PackageInfo(*package), model_path=model_path, check=bool(check), features=features)
        result.files_written = len(done.report.written) if done.report else 0
        result.diagnostics = format_all(done.warnings)
        if done.drift:
            result.status, result.exit_code = "drifted", EXIT_FINDINGS
            result.drift, result.files_written = done.drift.lines(), len(done.drift.lines())
            result.diff = done.drift.diff(prefix) if check == "diff" else ""
    except Exception as exc:  # noqa: BLE001 - one model's bug must not stop the batch
        failed = as_error(exc, model)
        result.status, result.exit_code = "failed", failed.exit_code
        result.diagnostics = format_all(failed.diagnostics)
    result.seconds = time.perf_counter() - started
    return result


def _read_state(out: Path) -> dict[str, dict[str, str]]:
    try:
        data = json.loads((out / STATE).read_text(encoding="utf-8"))
        return data.get("models", {}) if isinstance(data, dict) else {}
    except (OSError, ValueError):
        return {}


def _input_hash(model: Path, linked: list[Path], features: Sequence[Path] = ()) -> str:
    """A hash of the model file, of every model file it references, of the URDF files they name and of the
    product line files its jobs name (and of a variant's configuration, feature model and resolution model:
    ``features``)."""
    digest = hashlib.sha256(model.read_bytes())
    for path in features:
        digest.update(b"\0features\0" + path.name.encode() + b"\0" + path.read_bytes())
    for path in linked:
        digest.update(b"\0" + path.as_posix().encode() + b"\0" + path.read_bytes())
    for path in robot_files(model, linked):
        digest.update(b"\0urdf\0" + path.as_posix().encode() + b"\0"
                      + (path.read_bytes() if path.is_file() else b"(missing)"))
    for path in job_files(model):  # the configurations its jobs name (docs/jobs.md)
        digest.update(b"\0job\0" + path.as_posix().encode() + b"\0"
                      + (path.read_bytes() if path.is_file() else b"(missing)"))
    return digest.hexdigest()


def run_batch(folder: Path, out: Path, target: str | None = None, *, package_name: str = "", jobs: int | None = None,
              force: bool = False, type_map: Path | None = None, package: tuple[str, str, str] = ("", "", ""),
              model_path: Sequence[Path] = (),
              progress: Callable[[int, int, ModelResult], None] | None = None, check: str = "") -> BatchReport:
    """Generate every model under ``folder`` into ``out``; never raises for one model's failure.

    ``check`` ("check" or "diff"): write nothing, compare each model's output folder instead."""
    started = time.perf_counter()
    folder, out = folder.resolve(), out.resolve()
    models = find_models(folder, exclude=out)
    tools = toolchain_hash(target, package_name, type_map, package)
    search = tuple(Path(d).resolve() for d in model_path)
    results, todo = _plan(models, folder, out, search, tools, force or bool(check))
    total = len(models)
    for index, skipped in enumerate(results, start=1):
        if progress:
            progress(index, total, skipped)
    # what each model's generation takes besides its model, its output folder and its prefix
    args = (target, package_name, str(type_map.resolve()) if type_map is not None else None, package,
            tuple(str(d) for d in search), check)
    try:
        _generate_all(todo, folder, args, jobs, results, lambda done, result: progress and progress(done, total, result))
    finally:  # the models done are recorded, also when a signal stops the batch (check mode writes nothing)
        if not check:
            _write_state(out, target, tools, results)
    results.sort(key=lambda r: r.model)
    return BatchReport(results, time.perf_counter() - started)


def _plan(models: list[Path], folder: Path, out: Path, search: tuple[Path, ...], tools: str,
          regenerate: bool) -> tuple[list[ModelResult], list[tuple[Path, Path, str]]]:
    """The models not to generate (libraries of other models, unchanged since the last run unless
    ``regenerate``), as results, and the (model, output folder, input digest) of the others."""
    links = {model: linked_files(model, search) for model in models}
    # by real path: a model may reach a library of the batch through a symlinked folder
    used_by = {lib.resolve(): model for model in models for lib in links[model]}
    state = _read_state(out)
    results: list[ModelResult] = []
    todo: list[tuple[Path, Path, str]] = []
    for model in models:
        rel = model.relative_to(folder).as_posix()
        if model.resolve() in used_by:
            user = os.path.relpath(used_by[model.resolve()], folder)
            results.append(ModelResult(model=rel, status="library", diagnostics=[
                f"{model}: note: a library of {Path(user).as_posix()} (it references this file): generated with it, "
                "not on its own"]))
            continue
        digest = _input_hash(model, links[model])
        dest = _output_folder(model, folder, out)
        seen = state.get(rel, {})
        if (not regenerate and seen.get("input") == digest and seen.get("toolchain") == tools
                and _outputs_intact(dest)):
            results.append(ModelResult(model=rel, status="skipped", input_hash=digest))
        else:
            todo.append((model, dest, digest))
    return results, todo


def _generate_all(todo: list[tuple[Path, Path, str]], folder: Path, args: tuple, jobs: int | None,
                  results: list[ModelResult], progress: Callable[[int, ModelResult], object]) -> None:
    """Generate the models of ``todo`` (``args``: the rest of ``_generate_one``'s arguments), in this
    process or in a pool of ``jobs`` worker processes, appending each result to ``results`` as it ends."""
    workers = max(1, min(jobs or os.cpu_count() or 1, len(todo) or 1))

    def finish(result: ModelResult, model: Path, digest: str) -> None:
        result.model = model.relative_to(folder).as_posix()
        result.input_hash = digest
        results.append(result)
        progress(len(results), result)

    if todo and workers == 1:
        for model, dest, digest in todo:
            finish(_generate_one(str(model), str(dest), *args, _prefix(model, folder)), model, digest)
    elif todo:
        # spawn, not fork: each worker starts its own Saxon engine cleanly
        pool = ProcessPoolExecutor(max_workers=workers, mp_context=get_context("spawn"), initializer=_worker_init)
        try:
            futures = {pool.submit(_generate_one, str(m), str(d), *args, _prefix(m, folder)): (m, dg)
                       for m, d, dg in todo}
            for future in as_completed(futures):
                finish(future.result(), *futures[future])
        except BaseException:
            _stop(pool)
            raise
        pool.shutdown()


def _write_state(out: Path, target: str | None, tools: str, results: list[ModelResult]) -> None:
    if not results:
        return
    new_state = {r.model: {"input": r.input_hash, "toolchain": tools}
                 for r in sorted(results, key=lambda r: r.model) if r.status not in ("failed", "library")}
    payload = {"generator": f"robomda {__version__}", "target": target, "models": new_state}
    atomic_write(out / STATE, (json.dumps(payload, indent=1, sort_keys=True) + "\n").encode("utf-8"))


def _worker_init() -> None:
    """Workers leave Ctrl-C to the parent, which stops them (no traceback from each worker)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)


def _stop(pool: ProcessPoolExecutor) -> None:
    """Cancel what is queued and terminate the running workers now."""
    processes = list(getattr(pool, "_processes", {}).values())  # the executor has no public handle
    pool.shutdown(wait=False, cancel_futures=True)
    for process in processes:
        if process.is_alive():
            process.terminate()
    for process in processes:
        process.join(timeout=5)


class ProgressBar:
    """A one-line progress bar on a terminal; silent otherwise."""

    def __init__(self, stream=sys.stderr, width: int = 30) -> None:
        self.stream = stream
        self.width = width
        self.enabled = stream.isatty()
        self.failed = 0

    def __call__(self, done: int, total: int, result: ModelResult) -> None:
        if result.status == "failed":
            self.failed += 1
        if not self.enabled or total == 0:
            return
        filled = self.width * done // total
        bar = "#" * filled + "." * (self.width - filled)
        self.stream.write(f"\r[{bar}] {done}/{total} models, {self.failed} failed")
        if done == total:
            self.stream.write("\n")
        self.stream.flush()


def run_variants(model: Path, configs: Path, out: Path, target: str | None = None, *, jobs: int | None = None,
                 force: bool = False, package: tuple[str, str, str] = ("", "", ""),
                 progress: Callable[[int, int, ModelResult], None] | None = None) -> BatchReport:
    """Generate ``model`` once per configuration in the folder ``configs`` (``generate --all-configurations``),
    each into ``out``/<configuration name>, in parallel; a variant whose inputs (model, linked files,
    configuration, feature model, resolution model) and toolchain did not change is skipped."""
    from robomda.variability import configurations, product_line_files

    started = time.perf_counter()
    model, out = model.resolve(), out.resolve()
    tools = toolchain_hash(target, "", None, package)
    linked = linked_files(model)
    state = _read_state(out)
    results: list[ModelResult] = []
    todo: list[tuple[Path, Path, str]] = []
    for config in configurations(configs):
        try:
            digest = _input_hash(model, linked, list(product_line_files(config).values()))
        except Exception:  # noqa: BLE001 - a missing feature model: the variant's run reports it
            digest = ""
        seen = state.get(config.stem, {})
        if not force and digest and seen.get("input") == digest and seen.get("toolchain") == tools \
                and _outputs_intact(out / config.stem):
            results.append(ModelResult(model=config.stem, status="skipped", input_hash=digest))
        else:
            todo.append((config, out / config.stem, digest))
    workers = max(1, min(jobs or os.cpu_count() or 1, len(todo) or 1))
    with ProcessPoolExecutor(max_workers=workers, mp_context=get_context("spawn"), initializer=_worker_init) as pool:
        futures = {pool.submit(_generate_one, str(model), str(dest), target, "", None, package, (), "", "",
                               str(config)): (config, digest) for config, dest, digest in todo}
        for future in as_completed(futures):
            config, digest = futures[future]
            result = future.result()
            result.model, result.input_hash = config.stem, digest
            results.append(result)
            if progress:
                progress(len(results), len(todo), result)
    _write_state(out, target, tools, results)
    results.sort(key=lambda r: r.model)
    return BatchReport(results, time.perf_counter() - started)
