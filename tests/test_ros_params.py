"""The ROS 2 user parameter file of the earlier layout (src/robomda/ros_params.py, ROS031 / ROS032).

A package generated before the per-instance files had one config/params.user.yaml
keyed by node name; no launch file loads it now. Its tuned values must not drop
out in silence: the run stops naming each node's new file (ROS031), or, when it
holds no value, removes it and says so (ROS032).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from robomda.api import generate
from robomda.diagnostics import RobomdaError

ROOT = Path(__file__).resolve().parent.parent
LEARNING = ROOT / "fixtures" / "cases" / "learning" / "model.xmi"
OLD = "config/params.user.yaml"


def _old_layout(out: Path, text: str) -> None:
    """Turns a fresh package in OUT into one with the earlier layout's user file (as robomda recorded it)."""
    (out / OLD).write_text(text)
    state = out / ".robomda" / "state.json"
    data = json.loads(state.read_text())
    data["user"][OLD] = {"implements": "", "name": "", "signature": ""}
    state.write_text(json.dumps(data, indent=1) + "\n")


@pytest.fixture(scope="module")
def fresh(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("learning") / "pkg"
    generate(LEARNING, out, "ros2")
    return out


def _copy(fresh: Path, tmp_path: Path) -> Path:
    import shutil
    out = tmp_path / "pkg"
    shutil.copytree(fresh, out)
    return out


def test_each_instance_has_its_own_files_keyed_for_any_namespace(fresh: Path) -> None:
    assert not (fresh / OLD).exists() and not (fresh / "config" / "params.yaml").exists()
    fri = (fresh / "config" / "atf_driver_fri.yaml").read_text()
    assert "\n/**:\n  ros__parameters:\n    update_period: 0.01\n" in fri
    assert "gain: 12.5" in (fresh / "config" / "atf_driver_jointCtrl.yaml").read_text()
    assert (fresh / "config" / "learner.user.yaml").read_text().endswith("\n/**:\n  ros__parameters: {}\n")


def test_an_old_user_file_with_values_stops_the_run_naming_each_nodes_new_file(fresh: Path, tmp_path: Path) -> None:
    out = _copy(fresh, tmp_path)
    _old_layout(out, "# mine\nlearner:\n  ros__parameters:\n    window: 80\n/atf/driver/jointCtrl:\n"
                     "  ros__parameters:\n    gain: 3.0\nghost:\n  ros__parameters:\n    x: 1\n")
    before = (out / "config" / "learner.yaml").stat().st_mtime_ns
    with pytest.raises(RobomdaError) as caught:
        generate(LEARNING, out, "ros2")
    found = [(d.code, d.line, d.message) for d in caught.value.diagnostics]
    assert [(c, n) for c, n, _ in found] == [("ROS031", 2), ("ROS031", 5), ("ROS031", 8)], found
    assert "in config/learner.user.yaml" in found[0][2] and "in config/atf_driver_jointCtrl.user.yaml" in found[1][2]
    assert "no instance of the new package is node 'ghost'" in found[2][2]
    assert all(d.file == str(out / OLD) for d in caught.value.diagnostics)
    assert not any(d.code == "OUT003" for d in caught.value.diagnostics)
    # nothing written: the old file and the package are as they were
    assert "window: 80" in (out / OLD).read_text() and (out / "config" / "learner.yaml").stat().st_mtime_ns == before


def test_an_old_user_file_moved_by_hand_lets_the_run_go_on(fresh: Path, tmp_path: Path) -> None:
    out = _copy(fresh, tmp_path)
    _old_layout(out, "learner:\n  ros__parameters:\n    window: 80\n")
    user = out / "config" / "learner.user.yaml"
    user.write_text(user.read_text().replace("ros__parameters: {}", "ros__parameters:\n    window: 80"))
    (out / OLD).unlink()
    done = generate(LEARNING, out, "ros2")
    assert "window: 80" in user.read_text() and "config/learner.user.yaml" in done.report.kept_user


def test_an_old_user_file_without_values_is_removed_with_a_warning(fresh: Path, tmp_path: Path) -> None:
    out = _copy(fresh, tmp_path)
    _old_layout(out, "# Written once by robomda\n# This file is yours\n{}\n")
    done = generate(LEARNING, out, "ros2")
    assert not (out / OLD).exists() and OLD in done.report.removed
    warned = [d for d in done.warnings if d.code == "ROS032"]
    assert len(warned) == 1 and warned[0].file == str(out / OLD) and "config/learner.user.yaml" in warned[0].message
    assert OLD not in json.loads((out / ".robomda" / "state.json").read_text())["user"]


def test_another_target_leaves_a_file_of_that_name_to_the_writer(tmp_path: Path) -> None:
    out = tmp_path / "pkg"
    generate(LEARNING, out, "ros1")
    _old_layout(out, "learner:\n  window: 80\n")
    with pytest.raises(RobomdaError) as caught:
        generate(LEARNING, out, "ros1")
    assert [d.code for d in caught.value.diagnostics] == ["OUT003"]
