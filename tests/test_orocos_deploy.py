"""Build and deploy generated Orocos packages on a real RTT / OCL 2.10 toolchain.

Not in CI (marker ``orocos_toolchain``, deselected there by conftest.py): the
toolchain is built from public sources with the project's
toolchains/orocos/build.sh, which CI cannot do. Where the toolchain is
installed (``$OROCOS_INSTALL``, default ``~/orocos/install``) these tests run
every fixture through the helpers of toolchains/orocos/env.sh:

- build the package (``oro_build_pkg``, cmake + make + install);
- deploy its XML, .ops and Lua files with ``oro_deploy_verify`` (every
  component Running, no undeclared property, clean shutdown) under
  ``oro_verdict`` (no ERROR line): XML and .ops in their own folder, Lua from
  a folder that holds a folder named like the package (RTT's import() used to
  take that folder instead of RTT_COMPONENT_PATH);
- the user's tuned values (``deploy/<instance>.user.cpf``) win over the
  model's in every format, and XML / .ops run elsewhere fail loudly;
- run the generated ``-check.lua`` (modelled periods, CPU affinity and
  property values read back) and require no warning in the RTT log;
- the broken variant (a configure() that fails on a property value) must
  fail in all three formats with an ERROR line;
- a downstream CMake package that uses the installed package's headers and
  library must build.
"""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

from robomda.api import generate

ROOT = Path(__file__).resolve().parents[1]
ENV_SH = ROOT / "toolchains" / "orocos" / "env.sh"
INSTALL = Path(os.environ.get("OROCOS_INSTALL", Path.home() / "orocos" / "install"))
CASES = ROOT / "fixtures" / "cases"

pytestmark = [
    pytest.mark.orocos_toolchain,
    pytest.mark.skipif(not (INSTALL / "bin" / "deployer").exists(),
                       reason=f"no Orocos toolchain in {INSTALL}: build it with toolchains/orocos/build.sh"),
]

MODELS = ["headlamp/model.xmi", "headlamp/model.ea.xmi", "meka/model.xmi", "meka/model.ea.xmi",
          "pid/model.xmi", "tuned/model.xmi", "split/model.xmi", "calligraphy/model.xmi", "learning/model.xmi",
          # structured data: a typekit, struct / enum / array ports and properties
          "quadarm/model.xmi", "structured/model.xmi",
          # seed 004: a configuration constant, read by the controller in its configureHook
          "pidswap/model.xmi",
          # components drawn as classes in the modelling tools' own profiles (issue 51)
          "robotml/model.xmi", "p4r/model.xmi", "umlrt/model.xmi", "sysml/model.xmi"]



def _bash(script: str, cwd: Path, timeout: int = 1200) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, OROCOS_INSTALL=str(INSTALL))
    return subprocess.run(["bash", "-c", f"source {ENV_SH} >/dev/null && {script}"], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=timeout)


_BUILT: dict[str, tuple[Path, str]] = {}


def _built(model: str, tmp_root: Path) -> tuple[Path, str]:
    """Generate ``model`` into TMP/<n>/<pkg>/ and build it; (package folder, package name)."""
    if model in _BUILT:
        return _BUILT[model]
    work = tmp_root / str(len(_BUILT))
    gen = generate(CASES / model, work / "pkg", "orocos", write=False)
    pkg = gen.stages["psm"].split('package="', 1)[1].split('"', 1)[0]
    out = work / pkg  # the output folder is named like the package, as in the README's example
    generate(CASES / model, out, "orocos")
    built = _bash(f"oro_build_pkg {out}", work)
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    _BUILT[model] = (out, pkg)
    return out, pkg


@pytest.fixture(scope="module")
def tmp_root(tmp_path_factory) -> Path:
    return tmp_path_factory.mktemp("orocos")


def _deployment(out: Path, fmt: str) -> Path:
    return next(p for p in (out / "deploy").glob(f"*.{fmt}") if not p.name.endswith("-check.lua"))


@pytest.mark.parametrize("model", MODELS)
@pytest.mark.parametrize("fmt", ["xml", "ops", "lua"])
def test_deploys_every_format(model: str, fmt: str, tmp_root: Path) -> None:
    """XML and .ops run in their own folder (the user's tuned values are read from the working
    directory); the Lua deployment runs from the folder above the package, which holds a folder
    named like the package (RTT's import() used to take it instead of RTT_COMPONENT_PATH)."""
    out, pkg = _built(model, tmp_root)
    deploy = _deployment(out, fmt)
    log = out.parent / f"{fmt}.log"
    where = "ORO_RUN_IN_CWD=1 " if fmt == "lua" else ""
    run = _bash(f"oro_add_prefix {out}/install && {where}ORO_LOGFILE={log} "
                f"oro_verdict oro_deploy_verify {deploy} 2", out.parent)
    assert run.returncode == 0 and "oro_verdict: OK" in run.stdout, run.stdout[-4000:]
    assert (out.parent / pkg).is_dir()  # the folder RTT's import() would have taken
    warnings = [l for l in log.read_text(errors="replace").splitlines() if "[ Warning]" in l and "Logging Activated" not in l]
    assert not warnings, warnings[:10]


@pytest.mark.parametrize("model", MODELS)
def test_self_check_reads_back_the_modelled_values(model: str, tmp_root: Path) -> None:
    out, _ = _built(model, tmp_root)
    check = next((out / "deploy").glob("*-check.lua"))
    run = _bash(f"oro_add_prefix {out}/install && timeout -s INT 120 rttlua {check} </dev/null", out.parent)
    assert run.returncode == 0 and "DEPLOY-RESULT: OK" in run.stdout, run.stdout[-4000:] + run.stderr[-2000:]


@pytest.mark.parametrize("model", MODELS)
def test_ctest_runs_the_self_check_and_it_passes(model: str, tmp_root: Path) -> None:
    """The package's own test (issue 52): after make install, ctest runs each process's -check.lua; the build
    had -Wall -Wextra -Wpedantic on (ROBOMDA_WARNINGS) and no warning points into the generated package."""
    out, _ = _built(model, tmp_root)
    cache = (out / "build" / "CMakeCache.txt").read_text()
    assert "ROBOMDA_WARNINGS:BOOL=ON" in cache
    run = _bash(f"ctest --test-dir {out}/build --output-on-failure", out.parent)
    assert run.returncode == 0 and "tests passed" in run.stdout and "0 tests failed" in run.stdout, run.stdout[-4000:]
    rebuilt = _bash(f"touch {out}/src/components.cpp && cmake --build {out}/build 2>&1", out.parent)
    ours = [line for line in rebuilt.stdout.splitlines() if "warning:" in line and str(out) in line]
    assert rebuilt.returncode == 0 and not ours, "\n".join(ours[:20])


def test_the_self_check_names_a_connection_the_deployment_does_not_make(tmp_root: Path) -> None:
    """One connect() taken out of (a copy of) the Lua deployment: its check fails, naming the connection."""
    out, _ = _built("headlamp/model.xmi", tmp_root)
    broken = tmp_root / "broken"
    shutil.rmtree(broken, ignore_errors=True)
    shutil.copytree(out / "deploy", broken)
    lua = broken / "headlamp.lua"
    text = lua.read_text(encoding="utf-8")
    line = next(l for l in text.splitlines() if "depl:connect(\"camera.visionValue\"" in l)
    lua.write_text(text.replace(line + "\n", ""), encoding="utf-8")
    run = _bash(f"oro_add_prefix {out}/install && timeout -s INT 120 rttlua {broken}/headlamp-check.lua </dev/null", tmp_root)
    assert run.returncode != 0 and "DEPLOY-CHECK FAILED: connection visionValueConn: camera.visionValue connected" in run.stdout, \
        run.stdout[-3000:]


def test_a_constant_read_before_its_writer_configures_fails_the_configure(tmp_root: Path) -> None:
    """pidswap's controller reads the robot interface's torque limit («Constant») in configureHook: it
    configures (the deployment above runs) because a StartAfter puts the robot interface first. Without it
    the deployer configures the controller first, which finds nothing written and refuses (SUB020 warned)."""
    out, _ = _built("pidswap/model.xmi", tmp_root)
    text = (CASES / "pidswap" / "model.xmi").read_text(encoding="utf-8")
    unordered = tmp_root / "unordered" / "model.xmi"
    unordered.parent.mkdir(exist_ok=True)
    unordered.write_text("\n".join(l for l in text.splitlines() if "_pswD01" not in l) + "\n", encoding="utf-8")
    generate(unordered, tmp_root / "unordered" / "pkg", "orocos")
    deploy = tmp_root / "unordered" / "pkg" / "deploy" / "pidswap.xml"
    run = _bash(f"oro_add_prefix {out}/install && oro_verdict oro_deploy_verify {deploy} 2", deploy.parent)
    assert "oro_verdict: FAILED" in run.stdout, run.stdout[-3000:]
    assert "Component PIDController returns false in configure()" in run.stdout + run.stderr, run.stdout[-3000:]


@pytest.mark.parametrize("fmt", ["xml", "ops", "lua"])
def test_a_failing_configure_fails_every_format(fmt: str, tmp_root: Path) -> None:
    out, _ = _built("tuned/broken/model.xmi", tmp_root)
    deploy = _deployment(out, fmt)
    run = _bash(f"oro_add_prefix {out}/install && oro_verdict oro_deploy_verify {deploy} 2", out.parent)
    assert run.returncode != 0, run.stdout[-3000:]
    assert "oro_verdict: FAILED" in run.stdout, run.stdout[-3000:]
    # the deployment itself says what failed, as an RTT ERROR line
    said = {"xml": "Component controller returns false in configure()",
            "ops": "[ScriptingService] tuned_broken.ops: controller.configure() failed",
            "lua": "tuned_broken.lua: controller.configure() failed"}[fmt]
    assert any("[ ERROR  ]" in line and said in line for line in run.stdout.splitlines()), run.stdout[-3000:]


def test_a_downstream_package_builds_against_the_installed_headers(tmp_root: Path) -> None:
    out, pkg = _built("headlamp/model.xmi", tmp_root)
    down = tmp_root / "downstream"
    shutil.rmtree(down, ignore_errors=True)
    (down / "src").mkdir(parents=True)
    (down / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.5)\nproject(downstream)\nset(CMAKE_CXX_STANDARD 14)\n"
        "find_package(OROCOS-RTT REQUIRED)\ninclude(${OROCOS-RTT_USE_FILE_PATH}/UseOROCOS-RTT.cmake)\n"
        f"orocos_use_package({pkg})\norocos_component(downstream src/user.cpp)\n", encoding="utf-8")
    (down / "src" / "user.cpp").write_text(
        f"#include <{pkg}/Guppy80.hpp>\n#include <rtt/Component.hpp>\n"
        "struct User : public RTT::TaskContext {\n"
        f"  {pkg}::Guppy80 camera;\n"
        "  User(const std::string& n) : RTT::TaskContext(n), camera(n + \"_camera\") {}\n};\n"
        "ORO_CREATE_COMPONENT(User)\n", encoding="utf-8")
    run = _bash(f"oro_add_prefix {out}/install && oro_build_pkg {down}", tmp_root)
    assert run.returncode == 0, run.stdout[-4000:] + run.stderr[-4000:]


# reads one property back after running a deployment file the way `deployer -s FILE` does
_READBACK = """require("rttlib")
local tc = rtt.getTC()
local depl = tc:getName() == "Deployer" and tc or tc:getPeer("Deployer")
local file = os.getenv("DEPLOY_FILE")
local ok
if file:match("%.xml$") then ok = depl:kickStart(file) else ok = depl:runScript(file) end
local c = depl:getPeer("controller")
print("READBACK " .. tostring(ok) .. " " .. tostring(c and c:getProperty("stiffness"):get())
      .. " " .. tostring(c and c:getState()))
for _, n in ipairs(depl:getPeers()) do local p = depl:getPeer(n); p:stop(); p:cleanup() end
os.exit(0)
"""


@pytest.mark.parametrize("fmt", ["xml", "ops", "lua"])
def test_tuned_values_of_the_user_file_win_in_every_format(fmt: str, tmp_root: Path) -> None:
    """Tuning on the robot meant editing a generated file (issue 10 item 6): the user's
    deploy/<instance>.user.cpf is loaded after the model's values by all three formats."""
    out, _ = _built("tuned/model.xmi", tmp_root)
    cpf = out / "deploy" / "controller.user.cpf"
    pristine = cpf.read_text()
    cpf.write_text(pristine.replace("<properties>\n",
                                    '<properties>\n  <simple name="stiffness" type="long"><value>700</value></simple>\n'))
    try:
        (tmp_root / "readback.lua").write_text(_READBACK)
        deploy = _deployment(out, fmt)
        run = _bash(f"oro_add_prefix {out}/install && DEPLOY_FILE={deploy.name} timeout -s INT 120 "
                    f"rttlua {tmp_root / 'readback.lua'} </dev/null", deploy.parent)
        assert "READBACK true 700 Running" in run.stdout, run.stdout[-3000:] + run.stderr[-2000:]  # the model says 650
        check = _bash(f"oro_add_prefix {out}/install && timeout -s INT 120 rttlua {out}/deploy/tuned-check.lua "
                      "</dev/null", tmp_root)
        assert check.returncode == 0 and "DEPLOY-RESULT: OK" in check.stdout, check.stdout[-3000:]
        # run from another folder, XML and .ops cannot find the user file: they say so and start nothing
        if fmt != "lua":
            lost = _bash(f"oro_add_prefix {out}/install && DEPLOY_FILE={deploy} timeout -s INT 120 "
                         f"rttlua {tmp_root / 'readback.lua'} </dev/null", tmp_root)
            said = lost.stdout + lost.stderr
            assert "Running" not in [line.split()[-1] for line in said.splitlines() if line.startswith("READBACK")], said
            assert "Could not load controller.user.cpf" in said, said[-3000:]
            if fmt == "ops":
                assert ("tuned.ops: controller.user.cpf not loaded: it is not in the working directory "
                        "(run from the folder of tuned.ops)") in said
    finally:
        cpf.write_text(pristine)


# every property of ctrl1 as text, as deep as its type goes (arrays: size, then elements), after
# running a deployment file the way `deployer -s FILE` does
_DUMP = """require("rttlib")
local tc = rtt.getTC()
local depl = tc:getName() == "Deployer" and tc or tc:getPeer("Deployer")
local file = os.getenv("DEPLOY_FILE")
local ok
if file:match("%.xml$") then ok = depl:kickStart(file) else ok = depl:runScript(file) end
local function text(v)
  if type(v) ~= "userdata" then return tostring(v) end
  local names = v:getMemberNames()
  local sequence = false
  for _, n in ipairs(names) do if n == "capacity" then sequence = true end end
  if sequence then
    local items = {}
    for i = 0, v.size - 1 do items[#items + 1] = text(v[i]) end
    return "[" .. v.size .. ":" .. table.concat(items, ",") .. "]"
  end
  if #names == 0 then  -- an enumeration: its number
    local i = rtt.Variable("int"); i:assign(v); return tostring(i:tolua())
  end
  local items = {}
  for _, n in ipairs(names) do items[#items + 1] = n .. "=" .. text(v[n]) end
  return "{" .. table.concat(items, ",") .. "}"
end
local c = depl:getPeer("ctrl1")
print("STATE " .. tostring(ok) .. " " .. tostring(c and c:getState()))
for _, n in ipairs(c:getPropertyNames()) do print("PROPERTY " .. n .. " " .. text(c:getProperty(n):get())) end
for _, n in ipairs(depl:getPeers()) do local p = depl:getPeer(n); p:stop(); p:cleanup() end
os.exit(0)
"""

_GAINS = "{stiffness=300,damping=20,maxTorque=80}"
_STRUCTURED = {  # ctrl1's model values, as _DUMP writes them
    "gains": _GAINS,
    "desired": "[7:0,0.5,0,-1,0,0.5,0]",
    "fallback": "2",  # TORQUE
    "offsets": "[7:1,-2,3,0,0,0,7]",
    "limits": "[2:1.5,2.5]",
    "history": "[0:]",
    "stages": "[7:" + ",".join([_GAINS] * 7) + "]",
    "limit": "{torque=[7:0,0,0,0,0,0,0],gains=" + _GAINS + "}",
}


def test_structured_values_are_the_same_in_every_format(tmp_root: Path) -> None:
    """Issue 37: a property of each structured kind (struct, enum, fixed and unbounded arrays, an
    array of structs, a nested struct) has the model's value read back from the running component,
    the same in XML, .ops and Lua. The atomic class starts its arrays empty (or at other sizes), so
    a format that sets no array size or leaves a member out shows here."""
    out, _ = _built("structured/model.xmi", tmp_root)
    (tmp_root / "dump.lua").write_text(_DUMP)
    seen = {}
    for fmt in ("xml", "ops", "lua"):
        deploy = _deployment(out, fmt)
        run = _bash(f"oro_add_prefix {out}/install && DEPLOY_FILE={deploy.name} timeout -s INT 120 "
                    f"rttlua {tmp_root / 'dump.lua'} </dev/null", deploy.parent)
        assert "STATE true Running" in run.stdout, run.stdout[-3000:] + run.stderr[-2000:]
        seen[fmt] = dict(line.split(" ", 2)[1:] for line in run.stdout.splitlines() if line.startswith("PROPERTY "))
        for name, value in _STRUCTURED.items():
            assert seen[fmt].get(name) == value, (fmt, name, seen[fmt].get(name))
    assert seen["xml"] == seen["ops"] == seen["lua"]


# both packages' arm and controller in one deployer, each loop closed within its package; the
# controllers start at desired[1] = 0.5, so an arm whose joint 1 moved has had torques through
# its package's ports, and the controller its joint states
_SIDE_BY_SIDE = """require("rttlib")
local tc = rtt.getTC()
local depl = tc:getName() == "Deployer" and tc or tc:getPeer("Deployer")
local function need(c, what) if not c then print("FAILED " .. what) end return c end
local cp = rtt.Variable("ConnPolicy")
local packages = {"quadarm", "structured"}
for _, pkg in ipairs(packages) do
  need(depl:loadLibrary(pkg .. "/" .. pkg .. "-typekit"), "loadLibrary " .. pkg .. "-typekit")
  need(depl:loadLibrary(pkg .. "/" .. pkg), "loadLibrary " .. pkg)
  local arm, ctrl = pkg .. "_arm", pkg .. "_ctrl"
  need(depl:loadComponent(arm, pkg .. "::ArmInterface"), "loadComponent " .. arm)
  need(depl:loadComponent(ctrl, pkg .. "::JointPositionController"), "loadComponent " .. ctrl)
  for _, n in ipairs({arm, ctrl}) do
    need(depl:setActivity(n, 0.01, 0, rtt.globals.ORO_SCHED_OTHER), "setActivity " .. n)
  end
  need(depl:connect(arm .. ".jointState", ctrl .. ".jointState", cp), "connect " .. arm)
  need(depl:connect(ctrl .. ".torques", arm .. ".torques", cp), "connect " .. ctrl)
  local p = depl:getPeer(ctrl):getProperty("desired")
  local v = p:get(); v[1] = 0.5; p:set(v)
  for _, n in ipairs({arm, ctrl}) do
    local t = depl:getPeer(n)
    need(t:configure(), "configure " .. n)
    need(t:start(), "start " .. n)
  end
end
local readers = {}
for _, pkg in ipairs(packages) do
  readers[pkg] = rttlib.port_clone_conn(depl:getPeer(pkg .. "_arm"):getPort("jointState"))
end
rtt.sleep(1, 0)
for _, pkg in ipairs(packages) do
  for _, n in ipairs({"_arm", "_ctrl"}) do
    local t = depl:getPeer(pkg .. n)
    for _, port in ipairs({"jointState", "torques"}) do
      print("TYPE " .. pkg .. n .. "." .. port .. " " .. t:getPort(port):info().type)
    end
    print("STATE " .. pkg .. n .. " " .. t:getState())
  end
  local fs, js = readers[pkg]:read()
  print("JOINT1 " .. pkg .. " " .. tostring(fs) .. " " .. tostring(js.position[1]))
end
for _, n in ipairs(depl:getPeers()) do local p = depl:getPeer(n); p:stop(); p:cleanup() end
os.exit(0)
"""


def test_two_packages_with_a_type_of_one_name_run_side_by_side(tmp_root: Path) -> None:
    """Issue 37 item 4: quadarm and structured each define JointState, JointTorques, Gains and
    ControlMode (C++ quadarm::types::JointState and structured::types::JointState, RTT
    /quadarm/JointState and /structured/JointState). Both typekits and both component libraries
    load into one deployer, every component runs, each port has its own package's type, and
    data flows around each package's loop. With global C++ types, the second package's
    components threw in their constructors."""
    out_q, _ = _built("quadarm/model.xmi", tmp_root)
    out_s, _ = _built("structured/model.xmi", tmp_root)
    (tmp_root / "side.lua").write_text(_SIDE_BY_SIDE)
    log = tmp_root / "side.log"
    run = _bash(f"oro_add_prefix {out_q}/install && oro_add_prefix {out_s}/install && ORO_LOGFILE={log} "
                f"timeout -s INT 120 rttlua {tmp_root / 'side.lua'} </dev/null", tmp_root)
    said = run.stdout + run.stderr
    assert "FAILED" not in said, said[-3000:]
    for pkg in ("quadarm", "structured"):
        for comp in ("_arm", "_ctrl"):
            assert f"STATE {pkg}{comp} Running" in said, said[-3000:]
            assert f"TYPE {pkg}{comp}.jointState /{pkg}/JointState" in said, said[-3000:]
            assert f"TYPE {pkg}{comp}.torques /{pkg}/JointTorques" in said, said[-3000:]
        joint1 = next(line.split() for line in said.splitlines() if line.startswith(f"JOINT1 {pkg} "))
        assert joint1[2] in ("NewData", "OldData") and float(joint1[3]) > 0.0, joint1
    errors = [l for l in log.read_text(errors="replace").splitlines() if "ERROR" in l or "[ Warning]" in l
              and "Logging Activated" not in l]
    assert not errors, errors[:10]
