"""Batch mode: a folder of models, found by content, in parallel, incremental."""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from robomda.batch import find_models, run_batch
from robomda.cli import main

ROOT = Path(__file__).resolve().parent.parent
CASES = ROOT / "fixtures" / "cases"


@pytest.fixture()
def tree(tmp_path: Path) -> Path:
    src = tmp_path / "models"
    shutil.copytree(CASES / "meka", src / "meka", ignore=shutil.ignore_patterns("expected"))
    shutil.copytree(CASES / "headlamp", src / "headlamp", ignore=shutil.ignore_patterns("expected"))
    # found by content: an XMI model whose name says nothing
    shutil.copy(CASES / "meka" / "model.ea.xmi", src / "meka" / "exported-by-ea.txt")
    # not models: a robomda PIM, a text file, broken XML, Papyrus' diagram and
    # architecture files (XMI documents without UML)
    (src / "meka" / "model.notation").write_text(
        '<?xml version="1.0" encoding="UTF-8"?><xmi:XMI xmi:version="2.0" xmlns:xmi="http://www.omg.org/XMI" '
        'xmlns:notation="http://www.eclipse.org/gmf/runtime/1.0.2/notation"><notation:Diagram xmi:id="d1"/></xmi:XMI>')
    (src / "meka" / "model.di").write_text(
        '<?xml version="1.0" encoding="UTF-8"?><xmi:XMI xmi:version="2.0" xmlns:xmi="http://www.omg.org/XMI"/>')
    (src / "notes.xml").write_text('<pim:model xmlns:pim="urn:robomda:pim:1"/>')
    (src / "readme.txt").write_text("hello")
    (src / "half.xmi").write_text("<xmi:XMI xmlns:xmi='http://www.omg.org/spec/XMI/20131001'")
    # a model with an error
    text = (CASES / "meka" / "model.xmi").read_text(encoding="utf-8")
    (src / "broken").mkdir()
    (src / "broken" / "gazebo.xmi").write_text(text.replace('name="OROCOS"', 'name="Gazebo"', 1), encoding="utf-8")
    return src


def test_models_are_found_by_content(tree: Path) -> None:
    found = [p.relative_to(tree).as_posix() for p in find_models(tree)]
    assert found == ["broken/gazebo.xmi", "headlamp/model.ea.xmi", "headlamp/model.xmi",
                     "meka/exported-by-ea.txt", "meka/model.ea.xmi", "meka/model.xmi"]


def test_batch_reports_each_model_and_goes_on_after_a_failure(tree: Path, tmp_path: Path) -> None:
    out = tmp_path / "out"
    report = run_batch(tree, out, jobs=2)
    status = {r.model: r.status for r in report.results}
    assert status.pop("broken/gazebo.xmi") == "failed"
    assert set(status.values()) == {"ok"} and len(status) == 5
    failed = next(r for r in report.results if r.status == "failed")
    assert "[BND003]" in failed.diagnostics[0] and "gazebo.xmi:" in failed.diagnostics[0]
    assert report.exit_code == 1
    assert (out / "headlamp" / "model.xmi" / "deploy" / "headlamp.xml").is_file()
    assert (out / "meka" / "exported-by-ea.txt" / "CMakeLists.txt").is_file()
    assert not (out / "broken" / "gazebo.xmi").exists()
    # each model's package equals the single-model run
    assert ((out / "meka" / "model.xmi" / "src" / "components.cpp").read_bytes()
            == (CASES / "meka" / "expected" / "orocos" / "files" / "src" / "components.cpp").read_bytes())


def test_second_run_skips_unchanged_models_and_redoes_changed_ones(tree: Path, tmp_path: Path) -> None:
    out = tmp_path / "out"
    run_batch(tree, out, jobs=1)
    again = run_batch(tree, out, jobs=1)
    assert {r.model: r.status for r in again.results if r.status != "failed"} == {
        m: "skipped" for m in ["headlamp/model.ea.xmi", "headlamp/model.xmi", "meka/exported-by-ea.txt",
                               "meka/model.ea.xmi", "meka/model.xmi"]}
    model = tree / "meka" / "model.xmi"
    model.write_text(model.read_text(encoding="utf-8").replace("0.05", "0.1"), encoding="utf-8")
    third = run_batch(tree, out, jobs=1)
    assert {r.model for r in third.results if r.status == "ok"} == {"meka/model.xmi"}
    assert "0.1" in (out / "meka" / "model.xmi" / "deploy" / "meka.ops").read_text()
    forced = run_batch(tree, out, jobs=1, force=True)
    assert forced.count("skipped") == 0 and forced.count("ok") == 5


def test_cli_prints_a_summary_and_exits_non_zero(tree: Path, tmp_path: Path,
                                                 capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["generate", str(tree), "-o", str(tmp_path / "out"), "-j", "2"])
    out, err = capsys.readouterr()
    assert code == 1
    assert "6 models: 5 ok, 0 unchanged, 1 failed" in out
    assert "broken/gazebo.xmi" in out and "[BND003]" in err
    assert "[####" not in err  # no progress bar when stderr is not a terminal


def test_models_named_alike_get_folders_of_their_own(tmp_path: Path) -> None:
    """robot.xmi and robot.uml side by side were written into one folder (mixed sources, then OUT001)."""
    src = tmp_path / "models"
    src.mkdir()
    shutil.copy(CASES / "meka" / "model.xmi", src / "robot.xmi")
    shutil.copy(CASES / "headlamp" / "model.xmi", src / "robot.uml")
    out = tmp_path / "out"
    first = run_batch(src, out, jobs=1)
    assert first.count("ok") == 2, [r.diagnostics for r in first.results]
    assert (out / "robot.xmi" / "deploy" / "meka.xml").is_file() and not (out / "robot.xmi" / "deploy" / "headlamp.xml").exists()
    assert (out / "robot.uml" / "deploy" / "headlamp.xml").is_file()
    assert run_batch(src, out, jobs=1, force=True).count("ok") == 2


def test_a_model_whose_outputs_were_deleted_is_regenerated(tree: Path, tmp_path: Path) -> None:
    out = tmp_path / "out"
    run_batch(tree, out, jobs=1)
    (out / "meka" / "model.xmi" / "deploy" / "meka.ops").unlink()
    again = run_batch(tree, out, jobs=1)
    status = {r.model: r.status for r in again.results}
    assert status["meka/model.xmi"] == "ok" and status["meka/model.ea.xmi"] == "skipped"
    assert (out / "meka" / "model.xmi" / "deploy" / "meka.ops").is_file()


@pytest.mark.parametrize("sig,code", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_a_signal_stops_the_batch_at_once_with_one_line(tmp_path: Path, sig: signal.Signals, code: int) -> None:
    """Ctrl-C ran queued models on for 30 s, then a traceback; SIGTERM left workers alive."""
    src = tmp_path / "models"
    for n in range(12):
        (src / f"m{n}").mkdir(parents=True)
        shutil.copy(CASES / "headlamp" / "model.xmi", src / f"m{n}" / "model.xmi")
    out = tmp_path / "out"
    child = subprocess.Popen([sys.executable, "-m", "robomda", "generate", str(src), "-o", str(out), "-j", "2"],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True,
                             env=dict(os.environ, PYTHONPATH=str(ROOT / "src")),
                             # as from a terminal: a run started in the background by a non-interactive shell
                             # (`.ci/run &`) inherits SIGINT ignored, and the batch then rightly runs on
                             preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    deadline = time.monotonic() + 60
    while not (out / "m0" / "model.xmi").exists() and not (out / "m1" / "model.xmi").exists() \
            and time.monotonic() < deadline and child.poll() is None:
        time.sleep(0.05)  # wait until the workers are at work
    child.send_signal(sig)
    stopped = time.monotonic()
    _, err = child.communicate(timeout=30)
    assert time.monotonic() - stopped < 10
    assert child.returncode == code, err
    text = err.decode()
    assert "Traceback" not in text and text.strip().splitlines()[-1].startswith("robomda: interrupted")
    time.sleep(0.5)
    assert not _running_in_group(child.pid)  # no worker of the batch is left running
    # every folder is a whole package or absent, and a second run finishes the job
    assert run_batch(src, out, jobs=2).count("failed") == 0


def _running_in_group(pgid: int) -> list[str]:
    """The processes of group ``pgid`` that still run (a zombie awaiting its reaper does not)."""
    running = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[2]) == pgid and fields[0] != "Z":
            running.append(stat.parent.name)
    return running


def test_a_changed_urdf_file_is_checked_again(tmp_path: Path) -> None:
    """A «Robot»'s URDF file decides the DoF checks: the model is not skipped when that file changed."""
    src = tmp_path / "models"
    shutil.copytree(ROOT / "fixtures" / "broken" / "urdf-dof-mismatch", src / "arms")
    out = tmp_path / "out"
    first = run_batch(src, out, jobs=1)
    assert first.count("ok") == 1, [r.diagnostics for r in first.results]
    assert run_batch(src, out, jobs=1).count("skipped") == 1
    urdf = src / "arms" / "lwr1.urdf"
    urdf.write_text(urdf.read_text(encoding="utf-8").replace("</robot>", ""), encoding="utf-8")
    broken = run_batch(src, out, jobs=1)
    assert broken.count("failed") == 1 and "[IMP043]" in broken.results[0].diagnostics[0]
    urdf.unlink()
    missing = run_batch(src, out, jobs=1)
    assert missing.count("failed") == 1 and "[IMP042]" in missing.results[0].diagnostics[0]


def test_check_mode_says_which_models_drifted_and_writes_nothing(tmp_path: Path,
                                                                 capsys: pytest.CaptureFixture[str]) -> None:
    """CI over a repository of models: generate DIR -o OUT --check / --diff."""
    src, out = tmp_path / "models", tmp_path / "out"
    shutil.copytree(CASES / "headlamp", src / "headlamp", ignore=shutil.ignore_patterns("expected", "model.ea.xmi"))
    shutil.copytree(CASES / "pid", src / "pid", ignore=shutil.ignore_patterns("expected", "model.*.xmi"))
    assert main(["generate", str(src), "-o", str(out), "-j", "1"]) == 0
    capsys.readouterr()
    state = (out / ".robomda" / "batch.json").read_bytes()
    code = main(["generate", str(src), "-o", str(out), "-j", "1", "--check"])
    stdout, err = capsys.readouterr()
    assert code == 0 and stdout == ""
    assert "2 models: 2 up to date, 0 drifted, 0 failed; 0 files would change" in err
    launch = next((out / "pid" / "model.xmi" / "launch").glob("*.launch"))
    launch.write_text(launch.read_text() + "<!-- mine -->\n")
    (out / "headlamp" / "model.xmi" / "package.xml").unlink()
    rel = launch.relative_to(out).as_posix()
    code = main(["generate", str(src), "-o", str(out), "-j", "2", "--diff"])
    stdout, err = capsys.readouterr()
    assert code == 1
    rows = {line.split()[0]: line.split()[1:3] for line in err.splitlines() if line.endswith(tuple("0123456789"))
            and line.split()[0].endswith(".xmi")}
    assert rows == {"headlamp/model.xmi": ["drifted", "1"], "pid/model.xmi": ["drifted", "1"]}
    assert "robomda: headlamp/model.xmi: its output would change (1 file):\n  added   package.xml" in err
    assert "2 models: 0 up to date, 2 drifted, 0 failed; 2 files would change" in err
    assert f"--- a/{rel}\n+++ b/{rel}\n" in stdout and "-<!-- mine -->\n" in stdout
    assert "--- /dev/null\n+++ b/headlamp/model.xmi/package.xml\n" in stdout
    assert (out / ".robomda" / "batch.json").read_bytes() == state and not (out / "headlamp" / "model.xmi" /
                                                                            "package.xml").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["models", "out"]
