"""The OpenRTM job coordinator (docs/jobs.md "On OpenRTM"): the PSM, the generated tables and start-up.

The model is the `teleop` fixture (fixtures/cases/teleop/make.py) and an edit of it. The last test
(marker ``openrtm_toolchain``) builds teleop on the real OpenRTM-aist 2.0, starts it and switches
jobs through the coordinator's event port while probes watch the shared robot interface.
"""

from __future__ import annotations

import re
import subprocess
import threading
import time
from pathlib import Path

import pytest
from lxml import etree

from robomda.api import generate
from test_openrtm import OPENRTM, _bash, _naming_service, _stop, _wait_for

ROOT = Path(__file__).resolve().parents[1]
TELEOP = ROOT / "fixtures" / "cases" / "teleop" / "model.xmi"
R = {"r": "urn:robomda:psm-openrtm:1"}
FS = "{urn:robomda:fileset:1}file"


def _generated(model: Path = TELEOP):
    done = generate(model, None, "openrtm", write=False)
    files = {f.get("path"): f.text or "" for f in etree.fromstring(done.stages["text"].encode("utf-8")).iter(FS)}
    return done, etree.fromstring(done.stages["psm"].encode("utf-8")), files


def test_the_psm_holds_the_coordinator_and_the_idle_instances() -> None:
    done, psm, _ = _generated()
    assert not [d for d in done.warnings if d.code.startswith("JOB")]
    assert [i.get("name") for i in psm.findall("r:instance[@idle='true']", R)] == ["player"]
    (coordinator,) = psm.findall("r:coordinator", R)
    assert (coordinator.get("name"), coordinator.get("class"), coordinator.get("process"), coordinator.get("initial-job")) == \
        ("arm", "ArmCoordinator", "teleop", "teleoperation")
    jobs = {j.get("name"): [m.get("instance") for m in j.findall("r:member", R)] for j in coordinator.findall("r:job", R)}
    assert jobs == {"teleoperation": ["trackball", "robot", "invkin"], "playback": ["player", "robot", "invkin"]}
    play = coordinator.find("r:transition[@event='play']", R)
    steps = [(step.tag.split("}")[1], step.get("instance"), [(v.get("name"), v.get("value")) for v in step.findall("r:value", R)])
             for step in play]
    assert steps == [("stop", "trackball", []), ("reconfigure", "invkin", [("gain", "2.0")]),
                     ("start", "player", [("duration", "4.0")]), ("keep", "robot", [])]


def test_the_coordinator_runs_the_shared_tables() -> None:
    _, _, files = _generated()
    source = files["src/ArmCoordinator.cpp"]
    assert 'const char * const kInitialJob = "teleoperation";' in source
    assert '  {"teleoperation", {"trackball", "robot", "invkin"}},\n  {"playback", {"player", "robot", "invkin"}},' in source
    assert ('  {"teleoperation", "play", "playback",\n    {"trackball"},\n    {{"invkin", {{"gain", "2.0"}}}},\n'
            '    {{"player", {{"duration", "4.0"}}}},\n    {"robot"}},') in source
    assert ('  {"playback", "teleoperate", "teleoperation",\n    {"player"},\n    {{"invkin", {{"gain", "1.0"}}}},\n'
            '    {{"trackball", {{"scale", "0.5"}}}},\n    {"robot"}},') in source
    assert "std::vector<std::pair<std::string, std::string>> values;" in source
    # the OpenRTM way: ports for events and the job, the lifecycle and configuration over CORBA
    for needle in ('m_eventIn("event", m_event)', 'm_jobOut("job", m_job)', "CORBA_RTCUtil::deactivate(rtc.in(), 0)",
                   "set_configuration_set_values(set.in())", 'activate_configuration_set("default")',
                   'string_to_component("rtcname://*/" + instance)', "manager.getComponent(instance.c_str())",
                   "void ArmCoordinatorInit(RTC::Manager* manager)"):
        assert needle in source, needle
    cmake = files["CMakeLists.txt"]
    assert "add_library(ArmCoordinator MODULE src/ArmCoordinator.cpp)\n" in cmake
    assert cmake.index("ArmCoordinator") < cmake.index("install(DIRECTORY")


def test_only_the_initial_job_is_activated_at_start() -> None:
    _, _, files = _generated()
    conf = files["deploy/teleop.rtc.conf"]
    assert "manager.preload.modules: Trackball.so, Playback.so, PumaInterface.so, InverseKinematics.so, ArmCoordinator.so\n" in conf
    assert ("manager.components.precreate: Trackball?instance_name=trackball, Playback?instance_name=player, "
            "PumaInterface?instance_name=robot, InverseKinematics?instance_name=invkin, ArmCoordinator?instance_name=arm\n") in conf
    assert "manager.components.preactivation: trackball, robot, invkin, arm\n" in conf
    assert "teleop.arm.exec_cxt.periodic.rate: 20\n" in conf
    # both trajectory sources stay connected to the kinematics: only the active one writes
    assert "trackball.desiredPose?port=invkin.desiredPose&" in conf and "player.desiredPose?port=invkin.desiredPose&" in conf
    assert "wait_active teleop.log trackball robot invkin arm\n" in files["deploy/start_localhost.sh"]


def test_a_configuration_constant_is_read_before_configure() -> None:
    """invkin's configure() needs the robot's link length («Constant», docs/substitution.md): on
    OpenRTM it runs on the first activation, once the constant has arrived, not in onInitialize."""
    _, _, files = _generated()
    source = files["src/InverseKinematics.cpp"]
    initialize = source.split("InverseKinematics::onInitialize()", 1)[1].split("\n}\n", 1)[0]
    assert "configure()" not in initialize.replace("// configure() runs", "")
    activated = source.split("InverseKinematics::onActivated(RTC::UniqueId ec_id)", 1)[1].split("\n}\n", 1)[0]
    # (the port's first sample is logged, docs/openrtm.md, as on every input)
    logged = ('    if (!m_linkLengthInReceived) {\n      m_linkLengthInReceived = true;\n      RTC_INFO(("input port '
              '%s.linkLength: first sample received", RTC::RTObject_impl::getInstanceName()));\n    }\n')
    assert activated.count(logged) == 1
    activated = activated.replace(logged, "")
    assert ("  if (!m_configured) {\n" in activated and "!(m_linkLengthIn.isNew())" in activated
            and "    m_linkLengthIn.read();\n    ::GeneralizedInverseKinematics::setLinkLength(static_cast<double>(m_linkLength.data));\n"
            "    if (!::GeneralizedInverseKinematics::configure()) {\n      return RTC::RTC_ERROR;\n    }\n"
            "    m_configured = true;\n  }\n  return ::GeneralizedInverseKinematics::start() ? RTC::RTC_OK : RTC::RTC_ERROR;") in activated
    # the writer is unchanged, and a component without constant inputs configures in onInitialize
    assert "return ::Puma560Interface::configure() ? RTC::RTC_OK : RTC::RTC_ERROR;" in files["src/PumaInterface.cpp"]


def test_a_job_value_on_no_configuration_parameter_is_named(tmp_path: Path) -> None:
    # the playback job sets the player's sample (an activity convention, no configuration parameter)
    text = TELEOP.read_text(encoding="utf-8")
    old = 'xmi:id="_telJ_playback_player_duration" definingFeature="_telRecordedTrajectory_duration"'
    assert text.count(old) == 1
    model = tmp_path / "model.xmi"
    model.write_text(text.replace(old, old.replace("Trajectory_duration", "Trajectory_sample")), encoding="utf-8")
    done, psm, _ = _generated(model)
    found = [d for d in done.warnings if d.code.startswith("JOB")]
    assert [(d.code, d.severity) for d in found] == [("JOB042", "warning")]
    assert "'sample' of instance 'player'" in found[0].message and found[0].line
    start = psm.find("r:coordinator/r:transition[@event='play']/r:start", R)
    assert start.get("instance") == "player" and start.find("r:value", R) is None


def test_a_member_on_another_middleware_is_named(tmp_path: Path) -> None:
    # teleop deployed: the player in a ROS process, the rest in an OpenRTM one (unprofiled: the
    # execution environment's name is its middleware)
    def environment(name: str, parts: tuple[str, ...]) -> str:
        return (f'<nestedNode xmi:type="uml:ExecutionEnvironment" xmi:id="_tE{name}" name="{name}">'
                + "".join(f'<deployment xmi:type="uml:Deployment" xmi:id="_tD{part}" client="_tE{name}" '
                          f'supplier="_telP_{part}" deployedArtifact="_telP_{part}"/>' for part in parts) + "</nestedNode>")
    node = ('<packagedElement xmi:type="uml:Node" xmi:id="_tN" name="pc">' + environment("OPENRTM", ("trackball", "invkin", "robot"))
            + environment("ROS", ("player",)) + "</packagedElement>\n    ")
    text = TELEOP.read_text(encoding="utf-8")
    anchor = '<packagedElement xmi:type="uml:InstanceSpecification" xmi:id="_telJ_teleoperation"'
    assert text.count(anchor) == 1
    model = tmp_path / "model.xmi"
    model.write_text(text.replace(anchor, node + anchor), encoding="utf-8")
    (tmp_path / "atomic").symlink_to(TELEOP.parent / "atomic")
    done, psm, _ = _generated(model)
    found = [d for d in done.warnings if d.code.startswith("JOB")]
    assert [(d.code, d.severity) for d in found] == [("JOB041", "warning")], found
    assert "instance 'player' of the jobs of subsystem 'arm' is not in the OpenRTM package" in found[0].message and found[0].line
    play = psm.find("r:coordinator/r:transition[@event='play']", R)
    assert [(s.tag.split("}")[1], s.get("instance")) for s in play] == [("stop", "trackball"), ("reconfigure", "invkin"),
                                                                        ("keep", "robot")]


# ---------------------------------------------------------------- the real OpenRTM
class _Lines:
    """The lines a process prints, each with the monotonic time it was read, collected by a thread."""

    def __init__(self, process: subprocess.Popen[str]) -> None:
        self.lines: list[tuple[float, str]] = []
        self._thread = threading.Thread(target=self._read, args=(process,), daemon=True)
        self._thread.start()

    def _read(self, process: subprocess.Popen[str]) -> None:
        assert process.stdout is not None
        for line in process.stdout:
            self.lines.append((time.monotonic(), line.rstrip("\n")))

    def samples(self, since: float = 0.0) -> list[tuple[int, int, float]]:
        """(sec, nsec, datum) of the samples a probe printed after $since (its datum: a TimedLong's or TimedDouble's)."""
        found = []
        for when, line in list(self.lines):
            match = re.match(r"probe: (\d+) (\d+)(?: (\S+))?$", line)
            if match and since <= when:
                found.append((int(match.group(1)), int(match.group(2)), float(match.group(3) or 0)))
        return found


def _rtcd2(conf: Path, env: dict[str, str], stdin: bool = False) -> subprocess.Popen[str]:
    return subprocess.Popen(["rtcd2", "-f", str(conf)], env=env, cwd=conf.parent, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, stdin=subprocess.PIPE if stdin else subprocess.DEVNULL,
                            start_new_session=True, text=True)


def _side_conf(path: Path, ns_port: int, modules: Path, module: str, name: str, connect: str) -> Path:
    path.write_text(f"corba.nameservers: localhost:{ns_port}\nnaming.formats: %n.rtc\nlogger.enable: NO\n"
                    f"manager.instance_name: {name}_manager\nmanager.modules.load_path: {modules}\n"
                    f"manager.preload.modules: {module}.so\nmanager.components.precreate: {module}?instance_name={name}\n"
                    f"manager.components.preconnect: {connect}\nmanager.components.preactivation: {name}\n"
                    "exec_cxt.periodic.rate: 100\n", encoding="utf-8")
    return path


def _build(out: Path, tmp_path: Path) -> None:
    for script in (f"rtm_build_pkg {out}", f"rtm_build_probe {tmp_path / 'probe_long'}",
                   f"rtm_build_probe {tmp_path / 'probe_double'} -DPROBE_TYPE=RTC::TimedDouble",
                   f"rtm_build_events {tmp_path / 'events'}"):
        built = _bash(script, tmp_path)
        assert built.returncode == 0, script + "\n" + built.stdout[-3000:] + built.stderr[-3000:]


@pytest.mark.openrtm_toolchain
def test_teleop_switches_jobs_on_openrtm_and_never_stops_the_robot(tmp_path: Path) -> None:
    """Only the initial job's instances are active at start; 'play' deactivates the trackball, sets
    invkin's gain while it runs and activates the player; 'teleoperate' the reverse; an unknown event
    changes nothing. The robot interface is activated once and its cycle count, which its start()
    resets, grows through both switches; data flows after each; the managers stop with no ERROR."""
    if not (OPENRTM / "bin" / "rtcd2").exists():
        pytest.skip(f"no OpenRTM-aist in {OPENRTM} (toolchains/openrtm/build.sh builds it)")
    out = tmp_path / "teleop"
    generate(TELEOP, out, "openrtm", write=True)
    _build(out, tmp_path)
    names, ns_port, env = _naming_service(tmp_path, out)
    log = out / "deploy" / "teleop.log"

    def text() -> str:
        return log.read_text(errors="replace") if log.exists() else ""
    started: list[subprocess.Popen[str]] = []
    try:
        time.sleep(1)
        started.append(subprocess.Popen(["sh", str(out / "deploy" / "start_localhost.sh")], env=env, stdout=subprocess.PIPE,
                                        stderr=subprocess.STDOUT, start_new_session=True, text=True))
        assert _wait_for(lambda: "arm activated" in text(), 120), text()[-4000:]
        activated = re.findall(r"(\w+) activated\.", text())
        assert activated == ["trackball", "robot", "invkin", "arm"], activated
        side = {
            "cycles": _side_conf(tmp_path / "cycles.rtc.conf", ns_port, tmp_path / "probe_long", "Probe", "probe_cycles",
                                 "rtcname://*/robot.cycles?port=probe_cycles.in"),
            "player": _side_conf(tmp_path / "player.rtc.conf", ns_port, tmp_path / "probe_double", "Probe", "probe_player",
                                 "rtcname://*/player.desiredPose?port=probe_player.in"),
            "command": _side_conf(tmp_path / "command.rtc.conf", ns_port, tmp_path / "probe_double", "Probe", "probe_command",
                                  "rtcname://*/invkin.jointCommand?port=probe_command.in"),
        }
        probes = {key: _rtcd2(conf, env) for key, conf in side.items()}
        started += probes.values()
        seen = {key: _Lines(p) for key, p in probes.items()}
        events = _rtcd2(_side_conf(tmp_path / "events.rtc.conf", ns_port, tmp_path / "events", "EventSource", "events",
                                   "events.out?port=rtcname://*/arm.event"), env, stdin=True)
        started.append(events)
        assert _wait_for(lambda: len(seen["cycles"].samples()) >= 20 and len(seen["command"].samples()) >= 20, 60), text()[-3000:]
        assert seen["player"].samples() == [], "the player writes before it is activated"

        def send(event: str, answer: str) -> float:
            assert events.stdin is not None
            events.stdin.write(event + "\n")
            events.stdin.flush()
            assert _wait_for(lambda: answer in text(), 60), text()[-4000:]
            return time.monotonic()

        played = send("play", "job playback active (event play)")
        assert _wait_for(lambda: len(seen["player"].samples(since=played)) >= 20, 30), text()[-3000:]
        assert _wait_for(lambda: len(seen["command"].samples(since=played)) >= 20, 30)
        # the player's trajectory falls by sample / duration each cycle: 0.01 / 4.0, the duration its
        # job sets before activating it (its .conf says 2.0), some cycles unread by the probe
        poses = [value for _, _, value in seen["player"].samples(since=played)]
        steps = [a - b for a, b in zip(poses, poses[1:])]
        assert 0 < poses[0] <= 1.0 and all(s > 0 and abs(s / 0.0025 - round(s / 0.0025)) < 1e-6 for s in steps), poses
        assert abs(min(steps) - 0.0025) < 1e-9, steps
        send("nothing", "event nothing: no switch from job playback: ignored")
        back = send("teleoperate", "job teleoperation active (event teleoperate)")
        assert _wait_for(lambda: len(seen["command"].samples(since=back)) >= 20, 30)
        time.sleep(2)
        assert seen["player"].samples(since=back + 1.0) == [], "the player writes after it was deactivated"
        log_text = text()
        for step in ("deactivate trackball: Inactive", "configure invkin: gain = 2.0", "configure player: duration = 4.0",
                     "activate player: Active", "deactivate player: Inactive", "configure invkin: gain = 1.0",
                     "configure trackball: scale = 0.5", "activate trackball: Active"):
            assert step in log_text, step
        assert "robot: Inactive" not in log_text and re.findall(r"(\w+) activated\.", log_text).count("robot") == 1
        cycles = [value for _, _, value in seen["cycles"].samples()]
        # the robot's start() resets its count: one that only grows was never deactivated and activated again
        assert len(cycles) >= 100 and all(b > a for a, b in zip(cycles, cycles[1:])), cycles[:5] + cycles[-5:]
        assert "setRate(20.000000) done" in log_text  # the coordinator polls at 20 Hz (rtc.conf)
        assert not re.search(r" (ERROR|FATAL): ", log_text), log_text[-4000:]
    finally:
        for process in [*reversed(started), names]:
            _stop(process)
    final = text()
    assert not re.search(r" (ERROR|FATAL): ", final), final[-4000:]
