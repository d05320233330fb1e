"""Watch mode (robomda.watcher, ``robomda watch``): what regenerates, what a failed save leaves, the one line.

Driven poll by poll (no sleeping, no timing): a "save" rewrites a file and
moves its modification time on explicitly, so two saves within the file
system's time resolution still differ.
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

from robomda.api import generate
from robomda.cli import main
from robomda.inputs import model_files
from robomda.output import STATE_FILE
from robomda.watcher import Watcher, output_folders

ROOT = Path(__file__).resolve().parent.parent
CASES = ROOT / "fixtures" / "cases"


def save(path: Path, data: bytes) -> None:
    """Write ``path`` as an editor would, its modification time a second on from the last one."""
    before = path.stat().st_mtime_ns if path.exists() else 0
    path.write_bytes(data)
    os.utime(path, ns=(before + 10**9, before + 10**9))


def files(folder: Path) -> dict[str, bytes]:
    return {p.relative_to(folder).as_posix(): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


@pytest.fixture()
def headlamp(tmp_path: Path) -> Path:
    shutil.copytree(CASES / "headlamp", tmp_path / "headlamp", ignore=shutil.ignore_patterns("expected"))
    return tmp_path / "headlamp" / "model.xmi"


def test_a_save_regenerates_and_an_unchanged_model_does_not(headlamp: Path, tmp_path: Path) -> None:
    watcher = Watcher([headlamp], tmp_path / "out")
    [first] = watcher.poll()
    assert first.exit_code == 0 and first.model == headlamp and first.out == tmp_path / "out"
    assert watcher.poll() == []
    save(headlamp, headlamp.read_bytes().replace(b'name="forceSensor"', b'name="forceSensor"', 1))
    [again] = watcher.poll()
    assert again.exit_code == 0 and "0 written" in again.line()
    assert watcher.poll() == []
    # the same package a fresh generate writes
    generate(headlamp, tmp_path / "fresh")
    assert files(tmp_path / "out") == files(tmp_path / "fresh")


def test_a_model_saved_half_way_writes_nothing_and_the_next_save_recovers(headlamp: Path, tmp_path: Path) -> None:
    out = tmp_path / "out"
    whole = headlamp.read_bytes()
    watcher = Watcher([headlamp], out)
    assert watcher.poll()[0].exit_code == 0
    before = files(out)
    save(headlamp, whole[:len(whole) // 2])
    [broken] = watcher.poll()
    assert broken.exit_code == 2 and [d.code for d in broken.diagnostics] == ["XML001"]
    assert broken.diagnostics[0].line and broken.diagnostics[0].file == str(headlamp)
    assert "failed, 1 error, nothing written: first " in broken.line() and "[XML001]" in broken.line()
    assert files(out) == before
    assert watcher.poll() == []  # a failed save is not retried until the next one
    save(headlamp, whole.replace(b"_0R9NxJby6L7s3E0jUY2jf5", b"_0R9NxJby6L7s3E0jUY2jf5", 1))
    [recovered] = watcher.poll()
    assert recovered.exit_code == 0 and files(out) == before


def test_a_save_of_a_referenced_file_regenerates_the_model_and_other_files_do_not(tmp_path: Path) -> None:
    shutil.copytree(CASES / "split", tmp_path / "split", ignore=shutil.ignore_patterns("expected"))
    model = tmp_path / "split" / "model.xmi"
    library = tmp_path / "split" / "services" / "joint.servicedef.uml"
    assert library in model_files(model)
    watcher = Watcher([model], tmp_path / "out")
    assert watcher.poll()[0].exit_code == 0
    save(tmp_path / "split" / "notes.txt", b"not read by the model")
    assert watcher.poll() == []
    save(library, library.read_bytes()[:200])
    [broken] = watcher.poll()
    assert broken.exit_code in (1, 2) and "INTERNAL" not in [d.code for d in broken.diagnostics]
    save(library, (CASES / "split" / "services" / "joint.servicedef.uml").read_bytes())
    assert watcher.poll()[0].exit_code == 0


def test_the_files_of_a_model_are_its_references_and_the_urdf_files_they_name(tmp_path: Path) -> None:
    shutil.copytree(ROOT / "fixtures" / "broken" / "urdf-dof-mismatch", tmp_path / "arms")
    model = next(p for p in (tmp_path / "arms").iterdir() if p.suffix in (".xmi", ".uml"))
    found = model_files(model)
    assert found[0] == model and tmp_path / "arms" / "lwr1.urdf" in found
    watcher = Watcher([model], tmp_path / "out")
    watcher.poll()
    (tmp_path / "arms" / "lwr1.urdf").unlink()  # a file that goes is a change too
    [missing] = watcher.poll()
    assert "IMP042" in [d.code for d in missing.diagnostics]


def test_several_models_go_to_folders_named_by_their_paths(tmp_path: Path) -> None:
    models = [tmp_path / "a" / "model.xmi", tmp_path / "b" / "model.xmi"]
    assert output_folders(models, tmp_path / "out") == {models[0]: tmp_path / "out" / "a" / "model.xmi",
                                                       models[1]: tmp_path / "out" / "b" / "model.xmi"}
    assert output_folders(models[:1], tmp_path / "out") == {models[0]: tmp_path / "out"}


def test_the_command_prints_one_line_per_run_and_the_diagnostics_once(headlamp: Path, tmp_path: Path,
                                                                       capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["watch", str(headlamp), "-o", str(tmp_path / "out"), "--polls", "2", "--interval", "0"])
    out, err = capsys.readouterr()
    assert code == 0
    [line] = out.splitlines()
    assert f"{headlamp}: orocos package in {tmp_path / 'out'}: 22 written, 0 unchanged, 6 warnings" in line
    assert err.count("[CMP009]") == 5 and "Traceback" not in err


def test_the_command_reports_a_broken_model_located_and_exits_with_its_code(tmp_path: Path,
                                                                           capsys: pytest.CaptureFixture[str]) -> None:
    model = tmp_path / "half.xmi"
    model.write_text("<xmi:XMI xmlns:xmi='http://www.omg.org/spec/XMI/20131001'>\n  <uml:Model")
    missing = tmp_path / "missing.xmi"
    code = main(["watch", str(model), str(missing), "-o", str(tmp_path / "out"), "--polls", "1"])
    out, err = capsys.readouterr()
    assert code == 2 and "Traceback" not in err + out and "INTERNAL" not in err + out
    assert len(out.splitlines()) == 2 and f"{model}:2:" in err and "[XML001]" in err and "[IO001]" in err
    assert not (tmp_path / "out" / "half.xmi" / STATE_FILE).exists()
