"""Jobs and subsystems (seed 004 §4.3, docs/jobs.md): the PIM, bind, the check report, the Orocos coordinator.

The models are the `teleop` fixture (written by fixtures/cases/teleop/make.py) and edits of it. The
last test runs the Orocos coordinator on the real toolchain (marker ``orocos_toolchain``).
"""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest
from lxml import etree

from robomda.api import check, generate, import_model

ROOT = Path(__file__).resolve().parents[1]
TELEOP = ROOT / "fixtures" / "cases" / "teleop" / "model.xmi"
PIM = {"pim": "urn:robomda:pim:1"}
OROCOS = {"o": "urn:robomda:psm-orocos:1"}
FS = "{urn:robomda:fileset:1}file"


def _edited(tmp_path: Path, *edits: tuple[str, str]) -> Path:
    text = TELEOP.read_text(encoding="utf-8")
    for old, new in edits:
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    model = tmp_path / "model.xmi"
    model.write_text(text, encoding="utf-8")
    return model


def _files(done) -> dict[str, str]:
    tree = etree.fromstring(done.stages["text"].encode("utf-8"))
    return {f.get("path"): f.text or "" for f in tree.iter(FS)}


def test_the_import_keeps_jobs_and_the_subsystem_as_drawn() -> None:
    pim = etree.fromstring(import_model(TELEOP, bind=False).encode("utf-8"))
    jobs = pim.findall("pim:coordination/pim:job", PIM)
    assert [j.get("name") for j in jobs] == ["teleoperation", "playback"]
    assert [m.get("part") for m in jobs[1].findall("pim:member", PIM)] == ["_telP_player", "_telP_invkin", "_telP_robot"]
    value = jobs[1].find("pim:member[@part='_telP_invkin']/pim:value", PIM)
    assert (value.get("attribute"), value.get("value")) == ("_telGeneralizedInverseKinematics_gain", "2.0")
    subsystem = pim.find("pim:coordination/pim:subsystem", PIM)
    assert subsystem.get("name") == "arm"
    assert [(s.get("name"), s.get("kind")) for s in subsystem.findall("pim:state", PIM)] == [
        ("", "initial"), ("teleoperation", "state"), ("playback", "state")]
    assert [t.get("event") for t in subsystem.findall("pim:transition", PIM)] == [None, "play", "teleoperate"]


def test_bind_says_what_each_switch_stops_reconfigures_starts_and_keeps() -> None:
    pim = etree.fromstring(import_model(TELEOP).encode("utf-8"))
    binding = pim.find("pim:binding", PIM)
    subsystem = binding.find("pim:bound-subsystem", PIM)
    assert subsystem.get("initial-job") == "teleoperation"
    play = subsystem.find("pim:transition[@event='play']", PIM)
    steps = [(step.tag.split("}")[1], step.get("instance"), [(s.get("name"), s.get("value")) for s in step])
             for step in play]
    assert steps == [("stop", "trackball", []), ("reconfigure", "invkin", [("gain", "2.0")]),
                     ("start", "player", [("duration", "4.0")]), ("keep", "robot", [])]
    # the initial job's values are the deployed ones; the other jobs' wait for their switch
    trackball = binding.find("pim:instance[@name='trackball']/pim:property-value", PIM)
    assert (trackball.get("name"), trackball.get("value"), trackball.get("source")) == ("scale", "0.5", "job")
    assert binding.find("pim:instance[@name='player']/pim:property-value", PIM) is None
    # playback restores invkin's own gain when teleoperation comes back
    back = subsystem.find("pim:transition[@event='teleoperate']/pim:reconfigure/pim:set", PIM)
    assert (back.get("value"), back.get("holder")) == ("1.0", None)


def test_check_reports_every_switch() -> None:
    done = check(TELEOP)
    assert done.exit_code == 0
    reports = [d.message for d in done.diagnostics if d.code == "JOB020"]
    assert reports == [
        "subsystem 'arm', teleoperation -> playback on 'play': stops trackball; reconfigures invkin (gain = 2.0); "
        "starts player (duration = 4.0); keeps robot",
        "subsystem 'arm', playback -> teleoperation on 'teleoperate': stops player; reconfigures invkin (gain = 1.0); "
        "starts trackball (scale = 0.5); keeps robot"]


def test_two_sources_of_one_job_feeding_one_input_are_still_an_error(tmp_path: Path) -> None:
    # the player in the teleoperation job too: it and the trackball would write invkin.desiredPose at once
    model = _edited(tmp_path, ('<slot xmi:type="uml:Slot" xmi:id="_telJ_teleoperation_robot" definingFeature="_telP_robot"/>',
                               '<slot xmi:type="uml:Slot" xmi:id="_telJ_teleoperation_robot" definingFeature="_telP_robot"/>\n'
                               '      <slot xmi:type="uml:Slot" xmi:id="_telJ_teleoperation_p" definingFeature="_telP_player"/>'))
    done = check(model)
    assert done.exit_code == 1
    assert [d.code for d in done.diagnostics if d.severity == "error"] == ["BND008"]


def test_a_subsystem_named_like_an_instance_is_refused(tmp_path: Path) -> None:
    model = _edited(tmp_path, ('xmi:id="_telSM" name="arm"', 'xmi:id="_telSM" name="robot"'))
    errors = [d for d in check(model).diagnostics if d.severity == "error"]
    assert [d.code for d in errors] == ["JOB012"] and "'robot'" in errors[0].message


def test_orocos_starts_the_initial_job_and_loads_the_coordinator_everywhere() -> None:
    done = generate(TELEOP, None, "orocos", write=False)
    psm = etree.fromstring(done.stages["psm"].encode("utf-8"))
    assert [i.get("name") for i in psm.findall("o:instance[@idle='true']", OROCOS)] == ["player"]
    files = _files(done)
    xml, ops, lua = files["deploy/teleop.xml"], files["deploy/teleop.ops"], files["deploy/teleop.lua"]
    player = xml.split('<struct name="player"', 1)[1].split("</struct>\n\n", 1)[0]
    assert '<simple name="AutoStart" type="boolean"><value>0</value></simple>' in player
    assert '<struct name="arm" type="OCL::LuaComponent">' in xml
    assert '<simple name="lua_file" type="string"><value>teleop_arm.lua</value></simple>' in xml
    assert '<simple name="Import" type="string"><value>ocl</value></simple>' in xml
    assert 'loadComponent("arm", "OCL::LuaComponent")' in ops and 'arm.lua_file = "teleop_arm.lua"' in ops
    assert "player.start()" not in ops and "if ( !arm.start() )" in ops
    assert 'local idle = {["player"] = true}' in lua and 'here .. "/teleop_arm.lua"' in lua
    script = files["deploy/teleop_arm.lua"]
    assert 'local initial = "teleoperation"' in script
    assert ('["play"] = { to = "playback",\n      stop = {"trackball"},\n'
            '      reconfigure = {{ name = "invkin", set = { {"gain", 2.0} } }},\n'
            '      start = {{ name = "player", set = { {"duration", 4.0} } }},\n      keep = {"robot"} },') in script
    assert "tc:addEventPort(events)" in script


@pytest.mark.parametrize("target,code", [("ros1", "JOB050")])  # ROS 2, OpenRTM: no warning (docs/jobs.md)
def test_targets_without_a_coordinator_say_so(target: str, code: str) -> None:
    done = generate(TELEOP, None, target, write=False)
    found = [d for d in done.warnings if d.code.startswith("JOB")]
    assert [(d.code, d.severity) for d in found] == [(code, "warning")]
    assert "subsystem 'arm'" in found[0].message and found[0].line


# ---------------------------------------------------------------- the real Orocos toolchain
ENV_SH = ROOT / "toolchains" / "orocos" / "env.sh"
INSTALL = Path(os.environ.get("OROCOS_INSTALL", Path.home() / "orocos" / "install"))

# deploys FILE (xml / ops / lua) inside rttlua, then drives the coordinator through its event port while
# a probe watches the shared robot interface (its state, and its cycle count, which a restart resets)
SWITCH_LUA = r'''
require("rttlib")
rttlib.color = false
local FILE = os.getenv("JOBS_FILE")
local ok = true
local function check(cond, what)
  print((cond and "JOBS-CHECK ok: " or "JOBS-CHECK FAILED: ") .. what)
  if not cond then ok = false end
end
local tc = rtt.getTC()
local depl = tc:getPeer("Deployer")
if FILE:match("%.xml$") then check(depl:kickStart(FILE), "kickStart " .. FILE)
elseif FILE:match("%.ops$") then check(depl:runScript(FILE), "runScript " .. FILE)
else dofile(FILE) end
local function comp(n) return depl:getPeer(n) end
local arm, robot = comp("arm"), comp("robot")
local cycles = rtt.InputPort("int")
tc:addPort(cycles, "cycles_probe", "")
check(cycles:connect(robot:getPort("cycles")), "probe connected to robot.cycles")
local events = rtt.OutputPort("string")
tc:addPort(events, "events_probe", "")
check(events:connect(arm:getPort("events")), "probe connected to arm.events")
local last, robot_stopped = -1, false
local function watch(secs)
  for _ = 1, math.floor(secs / 0.002) do
    if robot:getState() ~= "Running" then robot_stopped = true end
    local fs, c = cycles:read()
    if fs ~= "NoData" then
      if c < last then check(false, "robot cycle count went back from " .. last .. " to " .. c) end
      last = c
    end
    rtt.sleep(0, 2000000)
  end
end
local function states(want)
  for n, s in pairs(want) do
    local is = comp(n):getState()
    check(is == s, n .. " " .. s .. " (is " .. tostring(is) .. ")")
  end
end
local function prop(n, p) return comp(n):getProperty(p):get() end
watch(0.5)
check(arm:getState() == "Running", "coordinator arm Running")
check(prop("arm", "job") == "teleoperation", "initial job teleoperation")
states({trackball = "Running", player = "Stopped", invkin = "Running", robot = "Running"})
local before = last
events:write("play")
watch(0.5)
check(prop("arm", "job") == "playback", "job playback after 'play'")
states({trackball = "Stopped", player = "Running", invkin = "Running", robot = "Running"})
check(prop("invkin", "gain") == 2.0, "invkin.gain 2.0 in playback")
check(prop("player", "duration") == 4.0, "player.duration 4.0 in playback")
events:write("bogus")
watch(0.2)
check(prop("arm", "job") == "playback", "an unknown event switches nothing")
events:write("teleoperate")
watch(0.5)
check(prop("arm", "job") == "teleoperation", "job teleoperation after 'teleoperate'")
states({trackball = "Running", player = "Stopped", invkin = "Running", robot = "Running"})
check(prop("invkin", "gain") == 1.0, "invkin.gain back to 1.0")
check(not robot_stopped, "the robot interface was never stopped")
check(last > before and before > 0, "robot cycle count grew through both switches, never reset (" .. before .. " -> " .. last .. ")")
arm:stop(); arm:cleanup()
for _, n in ipairs({"invkin", "robot", "player", "trackball"}) do
  local c = comp(n)
  if c:getState() == "Running" then c:stop() end
  c:cleanup()
end
for _, n in ipairs({"arm", "invkin", "robot", "player", "trackball"}) do check(depl:unloadComponent(n), "unload " .. n) end
print("JOBS-RESULT: " .. (ok and "OK" or "FAILED"))
os.exit(ok and 0 or 1)
'''


def _bash(script: str, cwd: Path, timeout: int = 1500) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, OROCOS_INSTALL=str(INSTALL))
    return subprocess.run(["bash", "-c", f"source {ENV_SH} >/dev/null && {script}"], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=timeout)


def switch_package(model: Path, out: Path) -> Path:
    """MODEL's Orocos package generated into OUT and built, with the switching script beside it
    (tests/test_jobs_variability.py runs the product line's variants the same way)."""
    if not (INSTALL / "bin" / "deployer").exists():
        pytest.skip(f"no Orocos toolchain in {INSTALL}: build it with toolchains/orocos/build.sh")
    generate(model, out, "orocos")
    built = _bash(f"nice -n 19 bash -c 'source {ENV_SH} >/dev/null && oro_build_pkg {out}'", out.parent)
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    (out / "switch.lua").write_text(SWITCH_LUA, encoding="utf-8")
    return out


@pytest.fixture(scope="module")
def teleop_package(tmp_path_factory) -> Path:
    return switch_package(TELEOP, tmp_path_factory.mktemp("jobs") / "teleop")


@pytest.mark.orocos_toolchain
@pytest.mark.parametrize("fmt", ["xml", "ops", "lua"])
def test_orocos_switches_jobs_without_stopping_the_robot_interface(teleop_package: Path, fmt: str) -> None:
    deploy = teleop_package / "deploy"
    run = _bash(f"oro_add_prefix {teleop_package / 'install'} && JOBS_FILE=teleop.{fmt} timeout 120 rttlua ../switch.lua",
                deploy, timeout=300)
    out = run.stdout + run.stderr
    assert run.returncode == 0, out[-4000:]
    assert "JOBS-RESULT: OK" in out and "JOBS-CHECK FAILED" not in out, out[-4000:]
    assert "the robot interface was never stopped" in out
    # the one warning the run may log is the coordinator's about the unknown event
    assert "[ ERROR" not in out, out[-4000:]
    assert out.count("switches nothing in job playback") == 1
