"""The OpenRTM-aist target (pipelines/openrtm.xml, docs/openrtm.md).

Every fixture's RTC.xml files and RtsProfile are valid against the XSDs of
schemas/openrtm/ (written from the published formats), and say what the
model says: ports, configuration, connections, the deployment sequence.
Tests marked ``openrtm_toolchain`` build a generated package on a real
OpenRTM-aist 2.0 (toolchains/openrtm/build.sh), start it with its start
script and a naming service of their own, and check the components reach
Active in the modelled order and data flows on a modelled connection.
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import socket
import subprocess
import time
from pathlib import Path

import pytest
from lxml import etree

from robomda.api import generate

ROOT = Path(__file__).resolve().parent.parent
CASES = sorted(p.parent for p in (ROOT / "fixtures" / "cases").glob("*/model.xmi"))
FS = "{urn:robomda:fileset:1}"
RTC = "{http://www.openrtp.org/namespaces/rtc}"
RTS = "{http://www.openrtp.org/namespaces/rts}"
SCHEMAS = ROOT / "schemas" / "openrtm"


def _files(case: Path) -> dict[str, str]:
    done = generate(case / "model.xmi", case / "out", "openrtm", write=False)
    files = etree.fromstring(done.stages["text"].encode("utf-8"))
    return {node.get("path"): node.text or "" for node in files.iter(f"{FS}file")}


@pytest.fixture(scope="module")
def schemas() -> tuple[etree.XMLSchema, etree.XMLSchema]:
    return (etree.XMLSchema(etree.parse(str(SCHEMAS / "rtc-profile.xsd"))),
            etree.XMLSchema(etree.parse(str(SCHEMAS / "rts-profile.xsd"))))


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_profiles_are_valid(case: Path, schemas: tuple[etree.XMLSchema, etree.XMLSchema]) -> None:
    rtc_schema, rts_schema = schemas
    files = _files(case)
    profiles = [p for p in files if p.endswith("/RTC.xml")]
    systems = [p for p in files if p.endswith(".rtsys.xml")]
    assert profiles and len(systems) == 1
    for path in profiles + systems:
        doc = etree.fromstring(files[path].encode("utf-8"))
        schema = rtc_schema if path in profiles else rts_schema
        assert schema.validate(doc), f"{path}: {schema.error_log}"


def test_the_schemas_reject_what_openrtm_would(schemas: tuple[etree.XMLSchema, etree.XMLSchema]) -> None:
    rtc_schema, rts_schema = schemas
    files = _files(ROOT / "fixtures" / "cases" / "headlamp")
    profile = files["rtc/VisionProcessing/RTC.xml"]
    for bad in (profile.replace('rtc:portType="DataInPort"', 'rtc:portType="InPort"', 1),
                re.sub(r"<rtc:OnFinalize [^>]*/>", "", profile),
                profile.replace("rtc:executionRate=", "rtc:rate=")):
        assert bad != profile and not rtc_schema.validate(etree.fromstring(bad.encode("utf-8")))
    system = files["deploy/headlamp.rtsys.xml"]
    # a connector to a port no component has, a Preceding component that is not in the system
    for bad in (system.replace('rts:portName="vision.visionValue"', 'rts:portName="vision.nothing"', 1),
                system.replace('rts:PrecedingComponents rts:componentId="RTC:robomda:headlamp:IndustrialArm:1.0.0" '
                               'rts:instanceName="arm"', 'rts:PrecedingComponents rts:componentId="x" rts:instanceName="nobody"', 1)):
        assert bad != system and not rts_schema.validate(etree.fromstring(bad.encode("utf-8")))


def test_headlamp_says_what_the_model_says() -> None:
    files = _files(ROOT / "fixtures" / "cases" / "headlamp")
    system = etree.fromstring(files["deploy/headlamp.rtsys.xml"].encode("utf-8"))
    # the deployment sequence: arm before controller (StartAfter arm, vision), in both messages
    for message in ("StartUp", "Activation"):
        targets = system.findall(f"{RTS}{message}/{RTS}targets")
        names = [t.find(f"{RTS}TargetComponent").get(f"{RTS}instanceName") for t in targets]
        assert names == ["camera", "forceSensor", "vision", "arm", "controller"]
        preceding = targets[-1].findall(f"{RTS}Preceding/{RTS}PrecedingComponents")
        assert [p.get(f"{RTS}instanceName") for p in preceding] == ["arm", "vision"]
    connectors = {(c.find(f"{RTS}sourceDataPort").get(f"{RTS}portName"), c.find(f"{RTS}targetDataPort").get(f"{RTS}portName"))
                  for c in system.findall(f"{RTS}DataPortConnectors")}
    assert ("camera.visionValue", "vision.visionValue") in connectors and len(connectors) == 6
    rates = {c.get(f"{RTS}instanceName"): c.find(f"{RTS}ExecutionContexts").get(f"{RTS}rate")
             for c in system.findall(f"{RTS}Components")}
    assert rates["camera"] == "333.333333"
    conf = files["deploy/headlamp.rtc.conf"]
    assert "manager.components.preactivation: camera, forceSensor, vision, arm, controller\n" in conf
    assert "camera.visionValue?port=vision.visionValue&dataflow_type=push" in conf
    assert "headlamp.vision.config_file: ../conf/vision.conf\n" in conf
    assert "conf.default.threshold: 100\n" in files["conf/vision.conf"]
    profile = etree.fromstring(files["rtc/VisionProcessing/RTC.xml"].encode("utf-8"))
    ports = [(p.get(f"{RTC}portType"), p.get(f"{RTC}name"), p.get(f"{RTC}type")) for p in profile.findall(f"{RTC}DataPorts")]
    assert ports == [("DataInPort", "visionValue", "RTC::TimedLong"), ("DataOutPort", "channelPosition", "RTC::TimedLong"),
                     ("DataInPort", "toolPose", "RTC::TimedLong")]
    source = files["src/VisionProcessing.cpp"]
    assert "class VisionProcessing : public RTC::DataFlowComponentBase, public ::GumChannelDetector" in \
        files["include/headlamp/VisionProcessing.h"]
    assert 'bindParameter("threshold", ::GumChannelDetector::threshold, "100");' in source
    assert "return ::GumChannelDetector::configure() ? RTC::RTC_OK : RTC::RTC_ERROR;" in source


def test_connections_a_timed_type_cannot_carry_are_named(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    from robomda.cli import main
    case = ROOT / "fixtures" / "cases" / "quadarm"
    assert main(["generate", str(case / "model.xmi"), "-o", str(tmp_path / "out"), "--target", "openrtm"]) == 0
    err = capsys.readouterr().err
    assert "[RTM001] port 'jointState' of component 'ArmInterface' carries JointState" in err
    assert "[RTM001] connection 'state1' carries JointState" in err
    assert "manager.components.preconnect: \n" in (tmp_path / "out" / "deploy" / "quadarm.rtc.conf").read_text()


# ---------------------------------------------------------------- real OpenRTM
OPENRTM = Path(os.environ.get("OPENRTM_INSTALL", Path.home() / "openrtm" / "install"))
ENV_SH = ROOT / "toolchains" / "openrtm" / "env.sh"


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _bash(script: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    # unoptimised (build type None): the test needs components that run, and builds them at nice 19
    env = dict(os.environ, RTM_CMAKE_ARGS=os.environ.get("RTM_CMAKE_ARGS", "-DCMAKE_BUILD_TYPE=None"))
    return subprocess.run(["bash", "-c", f"source {ENV_SH} && {script}"], cwd=cwd, capture_output=True, text=True,
                          timeout=3600, check=False, env=env)


def _wait_for(predicate, seconds: float) -> bool:
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(0.2)
    return predicate()


def _stop(process: subprocess.Popen[str]) -> None:
    if process.poll() is None:
        os.killpg(process.pid, signal.SIGTERM)
        try:
            process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()


@pytest.mark.openrtm_toolchain
def test_headlamp_runs_on_openrtm(tmp_path: Path) -> None:
    if not (OPENRTM / "bin" / "rtcd2").exists():
        pytest.skip(f"no OpenRTM-aist in {OPENRTM} (toolchains/openrtm/build.sh builds it)")
    case = ROOT / "fixtures" / "cases" / "headlamp"
    out = tmp_path / "headlamp"
    generate(case / "model.xmi", out, "openrtm", write=True)
    built = _bash(f"rtm_build_pkg {out} && rtm_build_probe {tmp_path / 'probe'}", tmp_path)
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    port = _free_port()
    names = subprocess.Popen(["omniNames", "-start", str(port), "-logdir", str(tmp_path)], stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL, start_new_session=True, text=True)
    env = dict(os.environ, RTM_NAMESERVER=f"localhost:{port}", RTM_MODULES=str(out / "build"),
               LD_LIBRARY_PATH=f"{OPENRTM / 'lib'}:{os.environ.get('LD_LIBRARY_PATH', '')}",
               PATH=f"{OPENRTM / 'bin'}:{os.environ['PATH']}")
    started = probe = None
    try:
        time.sleep(1)
        started = subprocess.Popen(["sh", str(out / "deploy" / "start_controlpc.sh")], env=env, stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT, start_new_session=True, text=True)
        log = out / "deploy" / "headlamp.log"
        order = ["camera", "forceSensor", "vision", "arm", "controller"]

        def activated() -> list[str]:
            text = log.read_text(errors="replace") if log.exists() else ""
            return re.findall(r"(\w+) activated\.", text)
        assert _wait_for(lambda: len(activated()) == len(order), 60), log.read_text(errors="replace")[-3000:]
        assert activated() == order
        text = log.read_text(errors="replace")
        # (a manager that is no master says "Master manager not found": a warning, no error)
        assert "Connection error" not in text and " ERROR: " not in text, text[-3000:]
        # a probe in a manager of its own reads vision.channelPosition: it grows only while
        # camera.visionValue reaches vision over the modelled connection visionValueConn
        conf = tmp_path / "probe.rtc.conf"
        conf.write_text(f"corba.nameservers: localhost:{port}\nnaming.formats: %n.rtc\nlogger.enable: NO\n"
                        f"manager.modules.load_path: {tmp_path / 'probe'}\nmanager.preload.modules: Probe.so\n"
                        "manager.components.precreate: Probe?instance_name=probe\n"
                        "manager.components.preconnect: rtcname://*/vision.channelPosition?port=probe.in\n"
                        "manager.components.preactivation: probe\nexec_cxt.periodic.rate: 100\n")
        probe = subprocess.Popen(["rtcd2", "-f", str(conf)], env=env, cwd=tmp_path, stdout=subprocess.PIPE,
                                 stderr=subprocess.STDOUT, start_new_session=True, text=True)
        values: list[int] = []
        end = time.monotonic() + 30
        while time.monotonic() < end and len(values) < 20:
            line = probe.stdout.readline() if probe.stdout else ""
            match = re.match(r"probe: (-?\d+)", line)
            if match:
                values.append(int(match.group(1)))
        assert len(values) >= 20 and values[-1] > values[0] > 0, values
    finally:
        for process in (probe, started, names):
            if process is not None:
                _stop(process)
        shutil.rmtree(out / "build", ignore_errors=True)
