"""ROS 1 and ROS 2 user code (issue 31 item 3): a component without a realizing class gets a
generated <Class>Base, the hooks the node calls (pure virtual) and the parameters' members, and
the user's <Class>Impl written once, from which the node derives. Models come from
tests/user_code_models.py.

- the files and what each declares, on both ROS versions; the build compiles the user's source;
- a hook the model drops stops the user's untouched class compiling ("override" of nothing),
  a hook it adds leaves the class abstract (the node cannot be made): g++ on the user's files
  against the generated base, no ROS needed; OUT004 names the changes;
- a renamed component: OUT003 names the user files and their new names (nothing written);
- two components whose classes would meet (Arm's ArmImpl and a component ArmImpl): ROS030;
- the skeletons build as written: fixtures/ros/usercode (the same model, rich) is one of the
  packages tests/test_ros.py builds with catkin (its executables link only with the user's
  sources compiled: the node calls each hook by its qualified name) and
  tests/test_ros2_toolchain.py with colcon (-Wall -Wextra, marker ros2_toolchain).
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest
from lxml import etree

from robomda.api import generate
from robomda.diagnostics import RobomdaError
from user_code_models import Comp, Port, write

ROOT = Path(__file__).resolve().parents[1]
FS = "{urn:robomda:fileset:1}"
ARM = Comp("1", "Arm", (Port("1", "cmd", "in"), Port("2", "state", "out")), (("1", "gain"),))
PLANNER = Comp("2", "Planner", (Port("1", "state", "in"), Port("2", "cmd", "out")), ())


def _fileset(model: Path, target: str) -> dict[str, tuple[str, str]]:
    done = generate(model, None, target, write=False)
    root = etree.fromstring(done.stages["text"].encode("utf-8"))
    return {n.get("path"): (n.get("mode"), n.text or "") for n in root.iter(f"{FS}file")}


def _gxx() -> str:
    gxx = shutil.which("g++")
    if gxx is None:
        pytest.skip("g++ not installed")
    return gxx


def _compile(gxx: str, out: Path, source: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([gxx, "-std=c++14", "-fsyntax-only", "-Wall", "-Wextra", "-I", str(out / "include"), "-x", "c++", "-"],
                          input=source, capture_output=True, text=True, timeout=120)


@pytest.mark.parametrize("target", ["ros1", "ros2"])
def test_a_component_without_class_gets_a_base_and_a_user_class(target: str, tmp_path: Path) -> None:
    files = _fileset(write(tmp_path / "model.xmi", (ARM, PLANNER), rich=True), target)
    assert files["include/usercode/ArmBase.hpp"][0] == "generated"
    assert files["include/usercode/ArmImpl.hpp"][0] == files["src/ArmImpl.cpp"][0] == "user"
    base = files["include/usercode/ArmBase.hpp"][1]
    for decl in ("virtual bool configure() = 0;", "virtual void setCmd(const double & value) = 0;",
                 "virtual double getState() const = 0;", "virtual void reset() = 0;", "virtual bool calibrate() = 0;",
                 "virtual void enable(bool data) = 0;", "::usercode::types::Mode mode = ::usercode::types::Mode::IDLE;", "::usercode::types::Gains gains;",
                 'std::string label = "left";', "int count = 3;", "double gain = 1.5;", "#include <Gains.hpp>"):
        assert decl in base, decl
    user = files["include/usercode/ArmImpl.hpp"][1]
    assert "This file is yours" in user and "class ArmImpl : public ArmBase" in user
    assert "void setCmd(const double & value) override;" in user and "double getState() const override;" in user
    assert "bool ArmImpl::calibrate()\n{\n  return true;\n}" in files["src/ArmImpl.cpp"][1]
    # the node derives from the user's class and calls it; the build compiles the user's source
    node = files["include/usercode/Arm.hpp"][1]
    include = '#include "usercode/ArmImpl.hpp"' if target == "ros2" else "#include <usercode/ArmImpl.hpp>"  # cpplint
    assert include in node and "public ::usercode::ArmImpl" in node
    assert "::usercode::ArmImpl::setCmd(" in files["src/Arm.cpp"][1]
    assert "src/ArmImpl.cpp" in files["CMakeLists.txt"][1] and "src/PlannerImpl.cpp" in files["CMakeLists.txt"][1]
    # what the user file implements, for OUT003 / OUT004
    done = generate(tmp_path / "model.xmi", None, target, write=False)
    node_el = next(n for n in etree.fromstring(done.stages["text"].encode()).iter(f"{FS}file") if n.get("path") == "src/ArmImpl.cpp")
    assert node_el.get("implements") == "_u1" and "hook void setCmd(const double & value)" in node_el.get("signature")


def test_a_hook_the_model_drops_or_adds_stops_the_users_class_compiling(tmp_path: Path) -> None:
    gxx = _gxx()
    out = tmp_path / "out"
    generate(write(tmp_path / "model.xmi", (ARM,)), out, "ros1")
    use = "#include <usercode/ArmImpl.hpp>\nstruct Node : usercode::ArmImpl {};\nint main() { Node node; (void)node; }\n"
    impl = (out / "src" / "ArmImpl.cpp").read_text()
    ok = _compile(gxx, out, impl + use.split("\n", 1)[1])
    assert ok.returncode == 0 and not ok.stderr, ok.stderr
    # the input port cmd is renamed order: setCmd is gone from the base, setOrder is new
    renamed = Comp("1", "Arm", (Port("1", "order", "in"), Port("2", "state", "out")), (("1", "gain"),))
    done = generate(write(tmp_path / "model.xmi", (renamed,)), out, "ros1")
    drift = [w.message for w in done.warnings if w.code == "OUT004"]
    assert any("no more hook void setCmd(const double & value)" in m and "new hook void setOrder(const double & value)" in m
               for m in drift), drift
    assert (out / "src" / "ArmImpl.cpp").read_text() == impl  # the user's file as it was
    dropped = _compile(gxx, out, impl)
    assert dropped.returncode != 0 and "setCmd" in dropped.stderr and "override" in dropped.stderr, dropped.stderr
    # with the stale hook taken out, the class is abstract: the node cannot be made until setOrder is written
    header = out / "include" / "usercode" / "ArmImpl.hpp"
    header.write_text(header.read_text().replace("  void setCmd(const double & value) override;\n", ""))
    added = _compile(gxx, out, use)
    assert added.returncode != 0 and "abstract" in added.stderr and "setOrder" in added.stderr, added.stderr


@pytest.mark.parametrize("target", ["ros1", "ros2"])
def test_a_renamed_component_names_where_the_users_code_goes(target: str, tmp_path: Path) -> None:
    out = tmp_path / "out"
    generate(write(tmp_path / "model.xmi", (ARM,)), out, target)
    impl = out / "src" / "ArmImpl.cpp"
    impl.write_text(impl.read_text() + "// my arm code\n")
    before = {p: p.read_bytes() for p in out.rglob("*") if p.is_file()}
    with pytest.raises(RobomdaError) as refused:
        generate(write(tmp_path / "model.xmi", (Comp("1", "Gripper", ARM.ports, ARM.properties),)), out, target)
    messages = [d.message for d in refused.value.diagnostics if d.code == "OUT003"]
    assert any("user file src/ArmImpl.cpp" in m and "it is now src/GripperImpl.cpp: move your code there" in m for m in messages)
    assert {p: p.read_bytes() for p in out.rglob("*") if p.is_file()} == before


def test_classes_of_two_components_that_meet_are_an_error(tmp_path: Path) -> None:
    model = write(tmp_path / "model.xmi", (ARM, Comp("2", "ArmImpl", (Port("1", "state", "in"),))))
    with pytest.raises(RobomdaError) as refused:
        generate(model, None, "ros1", write=False)
    found = [d for d in refused.value.diagnostics if d.code == "ROS030"]
    assert found and "components 'Arm', 'ArmImpl' both need C++ class ArmImpl" in found[0].message
    assert found[0].line is not None  # located on the component in the model
