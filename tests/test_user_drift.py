"""User code and model drift (issue 10 item 2).

A component without a realizing class gets a generated base class and a
user class the user fills in (written once). Renaming the component used
to leave the user's files on disk while CMake compiled a fresh, empty user
class: the robot ran a controller that did nothing. Now an orphaned user
file stops the run before anything is written (OUT003), naming the file
and where its code goes; a changed signature gets a warning (OUT004).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from robomda.api import generate
from robomda.diagnostics import RobomdaError

ROOT = Path(__file__).resolve().parents[1]
PID = ROOT / "fixtures" / "cases" / "pid"
# the robot interface loses its realizing class: it gets a base class and a user class
NO_REALIZATION = ('      <realization xmi:type="uml:ComponentRealization" xmi:id="_pid087z" '
                  'name="TorqueRobotInterface_RobotInterface" client="_pid046c" supplier="_pid083k" '
                  'realizingClassifier="_pid046c"/>\n', '')


def _model(tmp_path: Path, *edits: tuple[str, str]) -> Path:
    text = (PID / "model.xmi").read_text(encoding="utf-8")
    for old, new in (NO_REALIZATION, *edits):
        assert text.count(old) >= 1, old
        text = text.replace(old, new)
    model = tmp_path / "model.xmi"
    model.write_text(text, encoding="utf-8")
    if not (tmp_path / "atomic").exists():
        (tmp_path / "atomic").symlink_to(PID / "atomic")
    return model


def test_renaming_a_component_with_user_code_stops_before_writing(tmp_path: Path) -> None:
    out = tmp_path / "out"
    generate(_model(tmp_path), out, "orocos")
    user = out / "src" / "RobotInterface.cpp"
    assert "Written once" in user.read_text()
    user.write_text(user.read_text() + "// my controller code\n")
    before = {p: p.read_bytes() for p in out.rglob("*") if p.is_file()}
    renamed = _model(tmp_path, ('name="RobotInterface"', 'name="JointRobot"'))
    with pytest.raises(RobomdaError) as refused:
        generate(renamed, out, "orocos")
    codes = [d.code for d in refused.value.diagnostics]
    assert set(codes) == {"OUT003"}
    message = next(d.message for d in refused.value.diagnostics if "src/RobotInterface.cpp" in d.message)
    assert "it is now src/JointRobot.cpp: move your code there" in message
    assert {p: p.read_bytes() for p in out.rglob("*") if p.is_file()} == before  # nothing written
    # once the user moved the code, the run goes on
    for old, new in (("src/RobotInterface.cpp", "src/JointRobot.cpp"),
                     ("include/pid/RobotInterface.hpp", "include/pid/JointRobot.hpp")):
        (out / old).rename(out / new)
    done = generate(renamed, out, "orocos")
    assert "// my controller code" in (out / "src" / "JointRobot.cpp").read_text()
    assert "src/JointRobot.cpp" in (out / "CMakeLists.txt").read_text()
    assert not [w for w in done.warnings if w.code == "OUT003"]


def test_a_removed_component_with_user_code_stops_too(tmp_path: Path) -> None:
    out = tmp_path / "out"
    generate(_model(tmp_path), out, "orocos")
    # the robot interface gets a realizing class again: no user class any more
    text = (PID / "model.xmi").read_text(encoding="utf-8")
    (tmp_path / "model.xmi").write_text(text, encoding="utf-8")
    with pytest.raises(RobomdaError) as refused:
        generate(tmp_path / "model.xmi", out, "orocos")
    # OUT003 for the user source; the user header also stands where the new wrapper header goes (OUT001)
    assert {d.code for d in refused.value.diagnostics} == {"OUT001", "OUT003"}
    orphan = next(d for d in refused.value.diagnostics if d.code == "OUT003" and "src/RobotInterface.cpp" in d.message)
    assert "which the new package no longer uses" in orphan.message


def test_a_changed_signature_names_the_user_file_and_the_changes(tmp_path: Path) -> None:
    out = tmp_path / "out"
    generate(_model(tmp_path), out, "orocos")
    renamed_port = _model(tmp_path, ('name="measuredPosition" visibility="public" type="_pid067i"',
                                     'name="jointPosition" visibility="public" type="_pid067i"'))
    done = generate(renamed_port, out, "orocos")
    drift = [w for w in done.warnings if w.code == "OUT004"]
    assert drift and all("RobotInterface changed what user file" in w.message for w in drift)
    assert "no more port measuredPosition out" in drift[0].message and "new port jointPosition out" in drift[0].message
    assert (out / "src" / "RobotInterface.cpp.robomda-new").is_file() or \
        (out / "include" / "pid" / "RobotInterface.hpp.robomda-new").is_file()
