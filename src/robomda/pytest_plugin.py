"""pytest plugin: a repository's own models under golden-file test, one test per model and target.

Loaded by pytest for everyone who installs robomda (entry point ``pytest11``),
it does nothing until the repository opts in with the ini option
``robomda_models`` (``docs/testing.md``). Then every UML model under that
folder that pytest walks (found by content, as batch mode finds them; a
model another one references is a library, tested with it) is a test file,
and each target it is tested on is a test: the package robomda generates
now must be exactly the expected package,
``<robomda_expected>/<target>/<model path under robomda_models>/`` (the
folder ``robomda generate MODELS -o EXPECTED/<target> --target <target>``
writes, so the CLI's ``--check`` reads the same layout). A failing test
lists the files that differ and shows the unified diff of the first ones.

Expected packages are accepted as pytest-regressions accepts its data
files, with its own options: ``--force-regen`` rewrites the expected
package of each failing test (the test still fails, saying so),
``--regen-all`` rewrites every one and lets the tests pass; a missing
expected package is written and its test fails once.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Iterator

import pytest

if TYPE_CHECKING:
    from robomda.output import Drift

__all__ = ["pytest_addoption", "pytest_configure", "pytest_collect_file", "ModelFile", "ModelItem"]

DIFF_LINES = 120  # a failing test shows at most this many lines of diff
DIFF_FILES = 3  # ... of at most this many files


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addini("robomda_models", "robomda: the folder (relative to the ini file) whose UML models are tested "
                  "against their expected packages; unset, robomda's plugin does nothing", default="")
    parser.addini("robomda_expected", "robomda: the folder of the expected packages, "
                  "<it>/<target>/<model path under robomda_models>/ (default: expected)", default="expected")
    parser.addini("robomda_targets", "robomda: the targets every model is tested on (default: the targets "
                  "with an expected package of the model, else the ones the model deploys on)",
                  type="args", default=[])


def _folder(config: pytest.Config, name: str) -> Path | None:
    value = str(config.getini(name) or "").strip()
    if not value:
        return None
    base = config.inipath.parent if config.inipath is not None else config.rootpath
    return (base / value).resolve()


def pytest_configure(config: pytest.Config) -> None:
    if _folder(config, "robomda_models") is not None and not config.pluginmanager.hasplugin("regressions"):
        raise pytest.UsageError("robomda_models is set, but robomda's pytest plugin needs pytest-regressions "
                                "(its --force-regen accepts a change): pip install 'robomda[pytest]'")


def pytest_collect_file(file_path: Path, parent: pytest.Collector) -> ModelFile | None:
    root = _folder(parent.config, "robomda_models")
    if root is None or not file_path.resolve().is_relative_to(root) or file_path.resolve() in _libraries(parent.config, root):
        return None
    from robomda.batch import _is_uml_model

    return ModelFile.from_parent(parent, path=file_path) if _is_uml_model(file_path) else None


_LIBRARIES = pytest.StashKey[frozenset[Path]]()


def _libraries(config: pytest.Config, root: Path) -> frozenset[Path]:
    """The model files under ``root`` that another model there references: tested with it, not alone."""
    if _LIBRARIES not in config.stash:
        from robomda.batch import find_models
        from robomda.diagnostics import linked_files

        config.stash[_LIBRARIES] = frozenset(
            lib.resolve() for model in find_models(root) for lib in linked_files(model)) if root.is_dir() else frozenset()
    return config.stash[_LIBRARIES]


class ModelFile(pytest.File):
    """A model file: one :class:`ModelItem` per target."""

    def collect(self) -> Iterator[ModelItem]:
        for target in self._targets():
            yield ModelItem.from_parent(self, name=target, target=target)

    def _targets(self) -> list[str]:
        config = self.config
        chosen = list(config.getini("robomda_targets"))
        if chosen:
            return chosen
        expected, rel = _expected_root(config), self._rel()
        from robomda.resources import available_targets

        found = [t for t in available_targets() if (expected / t / rel).is_dir()]
        if found:
            return found
        from robomda.api import default_targets
        from robomda.diagnostics import RobomdaError

        try:
            return default_targets(self.path)
        except RobomdaError:
            return ["default"]  # its test reports why the model has no target

    def _rel(self) -> str:
        root = _folder(self.config, "robomda_models")
        assert root is not None
        return self.path.resolve().relative_to(root).as_posix()


def _expected_root(config: pytest.Config) -> Path:
    found = _folder(config, "robomda_expected")
    return found if found is not None else (config.rootpath / "expected").resolve()


@dataclass
class PackageDiffers(Exception):
    """The package generated now is not the expected one."""

    model: str
    target: str
    expected: Path
    drift: Drift


@dataclass
class ModelFails(Exception):
    """The model does not generate: its diagnostics."""

    lines: list[str]


class ModelItem(pytest.Item):
    """One model on one target: the package generated now must be the expected one."""

    def __init__(self, *, target: str, **kwargs: object) -> None:
        super().__init__(**kwargs)  # type: ignore[arg-type]
        self.target = target

    def runtest(self) -> None:
        from lxml import etree

        from robomda.api import generate
        from robomda.diagnostics import RobomdaError, format_all
        from robomda.output import compare_fileset

        parent = self.parent
        assert isinstance(parent, ModelFile)
        expected = _expected_root(self.config) / self.target / parent._rel()
        try:  # diagnostics name the model as the user's shell does: relative to the working folder
            done = generate(_shown(self.path), expected, None if self.target == "default" else self.target, write=False)
        except RobomdaError as exc:
            raise ModelFails(format_all(exc.diagnostics)) from None
        files = etree.fromstring(done.stages["text"].encode("utf-8"))
        if self.config.getoption("regen_all", False):
            _rewrite(files, expected)
            return
        if not expected.is_dir():
            _rewrite(files, expected)
            pytest.fail(f"Expected package not found, created:\n- {expected}", pytrace=False)
        drift = compare_fileset(files, expected, exact=True)
        if not drift:
            return
        if self.config.getoption("force_regen", False):
            _rewrite(files, expected)
            pytest.fail(f"Files differ and --force-regen set, regenerating the expected package at:\n- {expected}\n"
                        + "\n".join(f"  {line}" for line in drift.lines()), pytrace=False)
        raise PackageDiffers(parent._rel(), self.target, expected, drift)

    def repr_failure(self, excinfo: pytest.ExceptionInfo[BaseException], style: object = None) -> str:
        if isinstance(excinfo.value, PackageDiffers):
            return _describe(excinfo.value, self.config.rootpath)
        if isinstance(excinfo.value, ModelFails):
            return "robomda could not generate the package:\n" + "\n".join(excinfo.value.lines)
        return str(super().repr_failure(excinfo))

    def reportinfo(self) -> tuple[Path, int | None, str]:
        return self.path, None, f"{self.name} package of {self.path.name}"


def _shown(path: Path) -> Path:
    relative = Path(os.path.relpath(path))
    return path if relative.parts[:1] == ("..",) else relative


def _rewrite(files: object, expected: Path) -> None:
    """The expected package, afresh: what a first run writes into an empty folder, nothing else."""
    from robomda.output import _remove_tree, write_fileset

    if expected.exists():
        _remove_tree(expected)
    write_fileset(files, expected)  # type: ignore[arg-type]


def _describe(failure: PackageDiffers, rootpath: Path) -> str:
    """What differs: every file, then the diffs of the first ones, bounded, then how to see all and accept."""
    drift = failure.drift
    try:
        shown = failure.expected.relative_to(rootpath).as_posix()
    except ValueError:
        shown = str(failure.expected)
    lines = [f"the {failure.target} package generated from {failure.model} is not the expected one, {shown}/ "
             f"({len(drift.lines())} differing file{'s' if len(drift.lines()) != 1 else ''}; - expected, + generated now):"]
    lines += [f"  {line}" for line in drift.lines()]
    diff: list[str] = []
    paths = sorted(drift.diffs)
    for rel in paths[:DIFF_FILES]:
        diff += drift.diffs[rel].splitlines()
    cut = len(diff) > DIFF_LINES or len(paths) > DIFF_FILES
    lines += diff[:DIFF_LINES]
    if cut:
        lines.append(f"... (diff cut: {len(paths)} files differ; all of it: robomda generate MODEL -o {shown} "
                     f"--target {failure.target} --diff)")
    lines.append("accept the new package with: pytest --force-regen (then review the change, e.g. git diff)")
    return "\n".join(lines)
