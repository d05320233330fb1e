"""Tests of the Orocos chain: bind, m2m/orocos/psm, m2t/orocos (one module each).

Runs the stylesheets directly with saxonche on hand-written PIMs
(tests/data/orocos/) and, when present, on the fixture models
(import -> bind -> psm -> text).
"""
from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from functools import lru_cache
from pathlib import Path

import pytest
import xmlschema
from saxonche import PySaxonProcessor

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data" / "orocos"
XSLT = ROOT / "xslt"
PIM = "{urn:robomda:pim:1}"
O = "{urn:robomda:psm-orocos:1}"
FS = "{urn:robomda:fileset:1}"

ALLOWED_COMPONENT_CHILDREN = {
    "Activity", "AutoConf", "AutoStart", "AutoConnect", "AutoSave", "AutoUnload", "Ports", "Peers",
    "Properties", "PropertyFile", "UpdateProperties", "LoadProperties", "RunScript", "ProgramScript",
    "StateMachineScript", "Service", "Plugin", "Provides", "Master", "Server", "UseNamingService"}

_PROC = PySaxonProcessor(license=False)
_XSLT = _PROC.new_xslt30_processor()


@lru_cache(maxsize=None)
def _compiled(stylesheet: str):
    return _XSLT.compile_stylesheet(stylesheet_file=str(XSLT / stylesheet))


def run(stylesheet: str, source: Path | str, **params: str) -> str:
    exe = _compiled(stylesheet)
    exe.clear_parameters()
    for k, v in params.items():
        exe.set_parameter(k, _PROC.make_string_value(v))
    if isinstance(source, Path):
        return exe.transform_to_string(source_file=str(source))
    return exe.transform_to_string(xdm_node=_PROC.parse_xml(xml_text=source))


@lru_cache(maxsize=None)
def schema(rel: str) -> xmlschema.XMLSchema:
    return xmlschema.XMLSchema(str(ROOT / "schemas" / rel))


def chain(pim_text: str, package: str = "", model_dir: str = "."):
    bound = run("m2m/bind.xsl", pim_text)
    schema("pim/1/pim.xsd").validate(bound)
    psm = run("m2m/orocos/psm.xsl", bound, **{"package-name": package})
    schema("psm-orocos/1/psm-orocos.xsd").validate(psm)
    files = run("m2t/orocos/main.xsl", psm, **{"model-dir-from-output": model_dir})
    schema("fileset/1/fileset.xsd").validate(files)
    return ET.fromstring(bound), ET.fromstring(psm), {
        f.get("path"): f for f in ET.fromstring(files).iter(FS + "file")}


@lru_cache(maxsize=None)
def case(name: str):
    return chain((DATA / f"{name}.pim.xml").read_text())


# ---------------------------------------------------------------- bind
def test_bind_composite_instances_and_activity():
    bound, _, _ = case("composite")
    b = bound.find(PIM + "binding")
    assert b.get("instances-from") == "parts" and b.get("connections-from") == "connectors"
    inst = {i.get("name"): i for i in b.iter(PIM + "instance")}
    assert list(inst) == ["guppy", "vision", "controller"]
    a = inst["guppy"].find(PIM + "activity")
    assert (a.get("period"), a.get("priority"), a.get("scheduler")) == ("0.003", "50", "RT")
    assert a.get("period-source") == "stereotype"
    assert inst["vision"].find(PIM + "activity").get("cpu-affinity") == "2"
    assert inst["controller"].find(PIM + "activity").get("scheduler-source") == "default"
    assert {i.get("middleware") for i in inst.values()} == {"OROCOS"}
    host = b.find(PIM + "host")
    assert (host.get("hostname"), host.get("address")) == ("robotpc", "10.0.0.2")


def test_bind_composite_ports_and_connections():
    bound, _, _ = case("composite")
    b = bound.find(PIM + "binding")
    vis = [c for c in b.iter(PIM + "bound-component") if c.get("component") == "CVis"][0]
    dirs = {p.get("name"): p.get("direction") for p in vis.iter(PIM + "data-port")}
    assert dirs == {"imageIn_IForce": "out", "imageIn_IVisionValue": "in"}
    conns = {c.get("name"): c for c in b.iter(PIM + "connection")}
    assert list(conns) == ["IVisionValueConn", "forceConn"]
    c = conns["IVisionValueConn"]
    assert [r.get("instance") for r in c.iter(PIM + "reader")] == ["vision", "controller"]
    pol = c.find(PIM + "policy")
    assert (pol.get("type"), pol.get("size"), pol.get("lock-policy"), pol.get("init")) == \
        ("CIRCULAR_BUFFER", "10", "LOCKED", "true")
    assert conns["forceConn"].find(PIM + "policy").get("source") == "interface"
    libs = {l.get("name"): l for l in b.iter(PIM + "library")}
    assert set(libs) == {"guppy", "vision_algo"}  # A3 is not stereotyped Library
    assert libs["guppy"].get("target") == "guppy_driver" and libs["vision_algo"].get("absolute") == "true"


def test_bind_unprofiled_conventions():
    bound, _, _ = case("unprofiled")
    b = bound.find(PIM + "binding")
    assert b.get("connections-from") == "interfaces"
    inst = {i.get("name"): i.find(PIM + "activity") for i in b.iter(PIM + "instance")}
    assert list(inst) == ["Prosilica", "ImageProcessor", "Planner"]  # abstract component skipped
    p = inst["Prosilica"]
    assert (p.get("period"), p.get("period-source"), p.get("priority"), p.get("scheduler"),
            p.get("scheduler-source")) == ("0.05", "realizing-class", "50", "OTHER", "execution-environment")
    assert inst["Planner"].get("period") == "0"
    names = [c.get("name") for c in b.iter(PIM + "connection")]
    assert names == ["IImageConn", "IScrewPositionConn"]
    host = b.find(PIM + "host")
    assert host.get("address") == "localhost"


def _mutate(name: str, old: str, new: str) -> str:
    text = (DATA / f"{name}.pim.xml").read_text()
    assert old in text
    return text.replace(old, new, 1)


@pytest.mark.parametrize("name,old,new,code", [
    ("unprofiled", 'name="OROCOS" qualified-name="MekaPC::OROCOS"', 'name="Zenoh" qualified-name="MekaPC::OROCOS"', "BND003"),
    ("unprofiled", '<pim:attribute id="IPos.a"', '<pim:attribute id="IPos.b" name="extra" qualified-name="x" visibility="public"/><pim:attribute id="IPos.a"', "BND005"),
    ("unprofiled", 'type="IImg" type-name="IImage" type-library="local"/>\n    </pim:component>\n    <pim:component id="C2"',
     'type="NoSuch" type-name="IImage" type-library="local"/>\n    </pim:component>\n    <pim:component id="C2"', "BND002"),
    ("composite", '<pim:realization id="CCam.r" classifier="Guppy"/>', '<pim:realization id="CCam.r" classifier="Gone"/>', "BND001"),
])
def test_bind_errors(name, old, new, code):
    with pytest.raises(Exception) as exc:
        run("m2m/bind.xsl", _mutate(name, old, new))
    assert code in str(exc.value) and "xmi:id=" in str(exc.value)


def test_bind_interface_without_datum():
    """An interface with no datum and no operation (a Papyrus for Robotics service carries none by design)
    is no refusal: bind leaves its ports out, with warning BND004 (issue 51 item 5); import and check keep
    the ports in the PIM."""
    text = _mutate("unprofiled", '''      <pim:attribute id="IPos.a" name="screwPosition" qualified-name="IScrewPosition::screwPosition" type-name="double" type-library="c" primitive="float64" visibility="public"/>\n''', "")
    from lxml import etree
    bound = etree.fromstring(run("m2m/bind.xsl", text).encode())
    ns = {"p": "urn:robomda:pim:1"}
    assert bound.xpath("//p:port[@id='C2.out']", namespaces=ns) and bound.xpath("//p:port[@id='C3.in']", namespaces=ns)
    assert not bound.xpath("//p:data-port[@port='C2.out' or @port='C3.in']", namespaces=ns)
    assert not bound.xpath("//p:connection[p:writer/@port='C2.out']", namespaces=ns)


# ----------------------------------------------------------------- PSM
def test_psm_task_contexts():
    _, psm, _ = case("composite")
    tcs = {t.get("class"): t for t in psm.iter(O + "task-context")}
    assert set(tcs) == {"Camera", "Vision", "ForceController"}
    cam = tcs["Camera"]
    assert cam.get("type-name") == "headlamp_assembly::Camera" and cam.get("kind") == "wrapper"
    assert cam.find(O + "realizing-class").get("cpp-name") == "::atomic::GuppyF080C"
    port = cam.find(O + "port")
    assert (port.get("rtt-class"), port.get("xml-type"), port.get("accessor")) == \
        ("RTT::OutputPort<int>", "long", "getVisionValue")
    ops = {o.get("name"): o for o in cam.iter(O + "operation")}
    assert set(ops) == {"setWidth", "getWidth", "setName"}  # protected only, lifecycle excluded
    assert ops["getWidth"].get("thread") == "RTT::ClientThread"      # query
    assert ops["setName"].get("thread") == "RTT::ClientThread"       # OperationThread tag
    assert ops["setWidth"].get("thread") == "RTT::OwnThread"
    assert [p.get("decl-type") for p in ops["setName"].iter(O + "parameter")] == ["const std::string&", "std::string&"]
    assert [p.get("name") for p in cam.iter(O + "property")] == ["ip"]  # Configurable only
    assert [p.get("name") for p in tcs["Vision"].iter(O + "property")] == ["threshold", "debug"]
    assert tcs["ForceController"].get("kind") == "base"


def test_psm_connections_and_instances():
    _, psm, _ = case("composite")
    k = {c.get("name"): c for c in psm.iter(O + "connection")}
    assert (k["IVisionValueConn"].get("type-code"), k["IVisionValueConn"].get("lock-policy-code")) == ("2", "1")
    assert (k["forceConn"].get("type-code"), k["forceConn"].get("size")) == ("1", "5")
    inst = {i.get("name"): i for i in psm.iter(O + "instance")}
    assert inst["guppy"].find(O + "activity").get("scheduler") == "ORO_SCHED_RT"
    assert inst["controller"].find(O + "activity").get("periodic") == "false"
    assert {(p.get("name"), p.get("value")) for p in inst["vision"].iter(O + "property-value")} == \
        {("threshold", "12"), ("debug", "1")}


def test_psm_package_parameter():
    bound = run("m2m/bind.xsl", DATA / "unprofiled.pim.xml")
    psm = ET.fromstring(run("m2m/orocos/psm.xsl", bound, **{"package-name": "My Robot"}))
    assert psm.get("package") == "my_robot"
    tc = [t for t in psm.iter(O + "task-context") if t.get("class") == "Prosilica"][0]
    # unprofiled R4: public/protected, not read-only, not a convention name, mappable type
    assert [p.get("name") for p in tc.iter(O + "property")] == ["ip", "width"]
    assert [p.get("xml-default") for p in tc.iter(O + "property")] == ["10.0.0.9", "640"]


def test_psm_unsupported_type():
    text = _mutate("unprofiled", 'type-name="double" type-library="c" primitive="float64" visibility="public"/>',
                   'type-name="Pose" type-library="c" visibility="public"/>')
    with pytest.raises(Exception) as exc:
        run("m2m/orocos/psm.xsl", run("m2m/bind.xsl", text))
    assert "ORO001" in str(exc.value) and "screws" in str(exc.value)


# ---------------------------------------------------------------- text
def _deploy_xml(files, name):
    text = files[f"deploy/{name}.xml"].text
    assert '<!DOCTYPE properties SYSTEM "cpf.dtd">' in text
    return text, ET.fromstring(text.encode())


@pytest.mark.parametrize("name", ["composite", "unprofiled"])
def test_text_common(name):
    _, psm, files = case(name)
    pkg = psm.get("package")
    for path, f in files.items():
        assert "robomda" in f.text.split("\n")[0] + f.text.split("\n")[1] + f.text.split("\n")[2]
        assert "/work/" not in f.text and "\r" not in f.text
        assert f.get("stylesheet", "").startswith("m2t/orocos/")
    text, root = _deploy_xml(files, psm.get("deploy-name"))
    declared = {t.get("type-name"): {p.get("name") for p in t.iter(O + "property")} for t in psm.iter(O + "task-context")}
    conn_names = [s.get("name") for s in root.findall("struct") if s.get("type") == "ConnPolicy"]
    # LoadLibrary, not Import: RTT's import("pkg") takes a folder named pkg in the working
    # directory instead of RTT_COMPONENT_PATH (issue 17)
    assert root.find("simple[@name='Import']") is None
    assert root.find("simple[@name='LoadLibrary']/value").text == f"{pkg}/{pkg}"
    assert 'type="short"' not in text  # RTT 2.10 logs two deprecation warnings per short
    port_uses: dict[str, int] = {}
    for comp in root.findall("struct"):
        if comp.get("type") == "ConnPolicy":
            fields = [c.get("name") for c in comp]
            assert fields[:4] == ["type", "size", "lock_policy", "init"]
            continue
        kids = [c.get("name") for c in comp]
        assert set(kids) <= ALLOWED_COMPONENT_CHILDREN, kids
        act = comp.find("struct[@name='Activity']")
        assert {"Period", "Priority", "Scheduler"} <= {c.get("name") for c in act}
        assert act.find("simple[@name='Scheduler']/value").text in ("ORO_SCHED_RT", "ORO_SCHED_OTHER")
        for p in comp.findall("struct[@name='Properties']/simple"):
            assert p.get("name") in declared[comp.get("type")]
            assert p.get("type") != "int"
        for p in comp.findall("struct[@name='Ports']/simple"):
            port_uses[p.find("value").text] = port_uses.get(p.find("value").text, 0) + 1
    assert all(port_uses.get(n, 0) >= 2 for n in conn_names)  # no dangling connection names
    cmake = files["CMakeLists.txt"].text
    assert f"project({pkg})" in cmake and "find_package(OROCOS-RTT REQUIRED)" in cmake
    assert "UseOROCOS-RTT.cmake" in cmake and "orocos_generate_package()" in cmake
    assert re.search(r"CMAKE_CXX_STANDARD (14|17)\b", cmake) and "20" not in re.findall(r"CMAKE_CXX_STANDARD (\d+)", cmake)
    assert f"orocos_component({pkg} " in cmake
    comps = files["src/components.cpp"].text
    assert "ORO_CREATE_COMPONENT_LIBRARY()" in comps
    for t in psm.iter(O + "task-context"):
        assert f"ORO_LIST_COMPONENT_TYPE({t.get('type-name')})" in comps
    pkgxml = ET.fromstring(files["package.xml"].text.encode())
    assert pkgxml.get("format") == "3" and pkgxml.find("name").text == pkg
    name = psm.get("deploy-name")
    ops = files[f"deploy/{name}.ops"].text
    assert f'loadLibrary("{pkg}/{pkg}")' in ops and "import(" not in ops and "var ConnPolicy" in ops
    _assert_ops_comments_alone(ops)
    _assert_ops_lifecycle_checked(ops, [i.get("name") for i in psm.iter(O + "instance")])
    lua = files[f"deploy/{name}.lua"].text
    # a deployment: it keeps running (no stop, no unload, no exit) and fails loudly
    assert f'depl:loadLibrary("{pkg}/{pkg}")' in lua
    assert "os.exit" not in lua and ":stop()" not in lua and "unloadComponent" not in lua and "rtt.sleep" not in lua
    assert 'rtt.logl("Error"' in lua and "error(" in lua
    check = files[f"deploy/{name}-check.lua"].text
    assert f'dofile, here .. "/{name}.lua"' in check
    assert "os.exit(ok and 0 or 1)" in check and '"Running"' in check and "getPeriod()" in check


def _assert_ops_comments_alone(ops: str) -> None:
    """In Orocos scripting a comment after a statement swallows its line end: comments stand alone."""
    for line in ops.splitlines():
        code = re.sub(r'"(\\.|[^"\\])*"', '""', line)
        if not code.lstrip().startswith("//"):
            assert "//" not in code, line


def _assert_ops_lifecycle_checked(ops: str, names: list[str]) -> None:
    """Every configure() / start() of the .ops is tested and logs an [ ERROR ] line when it fails."""
    assert 'require("print")' in ops
    for n in names:
        assert f"if ( !{n}.configure() ) then {{" in ops
        assert f"if ( !{n}.start() ) then print.log(Error, " in ops
    bare = [l for l in ops.splitlines()
            if re.search(r"\.(configure|start)\(\)", re.sub(r'"[^"]*"', '""', l)) and "if ( !" not in l]
    assert not bare, bare


def test_text_wrapper_cpp():
    _, _, files = case("composite")
    hpp = files["include/headlamp_assembly/Camera.hpp"].text
    assert "class Camera : public RTT::TaskContext, public ::atomic::GuppyF080C" in hpp
    # quotes: the installed header finds the atomic header installed beside it
    assert '#include "guppy/GuppyF080C.hpp"' in hpp and "RTT::OutputPort<int> port_image;" in hpp
    cpp = files["src/Camera.cpp"].text
    assert 'this->ports()->addPort(port_image).doc("Vision value");' in cpp
    assert "port_image.setDataSample(0);" in cpp
    assert 'this->addProperty("ip", ::atomic::GuppyF080C::ip).doc("Camera IP address");' in cpp
    assert 'this->addOperation("setWidth", &Camera::setWidth, this, RTT::OwnThread)' in cpp
    assert "return ::atomic::GuppyF080C::configure();" in cpp
    assert "port_image.write(::atomic::GuppyF080C::getVisionValue());" in cpp
    vis = files["src/Vision.cpp"].text
    assert "addEventPort(port_imageIn_IVisionValue)" in vis
    assert "::VisionAlgo::setVisionValue(imageIn_IVisionValue_sample);" in vis
    assert vis.index("setVisionValue(") < vis.index("::VisionAlgo::update();") < vis.index("port_imageIn_IForce.write(")
    assert cpp.count("{") == cpp.count("}") and vis.count("(") == vis.count(")")


def test_text_base_and_user_files():
    _, _, files = case("composite")
    assert files["include/headlamp_assembly/ForceControllerBase.hpp"].get("mode") == "generated"
    user = files["src/ForceController.cpp"]
    assert user.get("mode") == "user" and "Written once" in user.text
    assert "class ForceController : public ForceControllerBase" in files["include/headlamp_assembly/ForceController.hpp"].text
    assert "stiffness(100.0)" in files["src/ForceControllerBase.cpp"].text
    _, _, files2 = case("unprofiled")
    base = files2["include/meka/PlannerBase.hpp"].text
    assert "virtual bool reset() = 0;" in base
    assert "bool Planner::reset()" in files2["src/Planner.cpp"].text


def test_text_deploy_values():
    _, _, files = case("composite")
    text = files["deploy/headlamp_assembly.xml"].text
    root = ET.fromstring(text.encode())
    cp = root.find("struct[@name='IVisionValueConn']")
    assert [cp.find(f"simple[@name='{n}']/value").text for n in ("type", "size", "lock_policy", "init")] == ["2", "10", "1", "1"]
    vis = root.find("struct[@name='vision']")
    assert vis.find("struct[@name='Activity']/simple[@name='CpuAffinity']/value").text == "2"
    assert vis.find("struct[@name='Properties']/simple[@name='debug']/value").text == "1"
    ops = files["deploy/headlamp_assembly.ops"].text
    assert 'setActivity("guppy", 0.003, 50, ORO_SCHED_RT)' in ops
    assert ('setActivity("vision", 0.0, 20, ORO_SCHED_RT)\n// CpuAffinity mask 2 (CPU 1)\n'
            'if ( !vision.setCpuAffinity(2) ) then print.log(Error, ') in ops
    lua = files["deploy/headlamp_assembly.lua"].text
    assert 'check(comps["vision"]:setCpuAffinity(2), "vision.setCpuAffinity(2)")' in lua
    check = files["deploy/headlamp_assembly-check.lua"].text
    assert 'comps["vision"]:getCpuAffinity() == 2' in check
    assert 'connect("guppy.image", "controller.vision", cp_IVisionValueConn)' in ops
    assert 'guppy.ip = "192.168.0.10"' in ops


def test_text_library_paths():
    _, _, files = chain((DATA / "composite.pim.xml").read_text(), model_dir="../models/")
    cmake = files["CMakeLists.txt"].text
    assert 'set(HEADLAMP_ASSEMBLY_GUPPY_DIR "${CMAKE_CURRENT_SOURCE_DIR}/../models/atomic/guppy" CACHE PATH' in cmake
    assert 'set(HEADLAMP_ASSEMBLY_VISION_ALGO_DIR "/opt/atomic/vision" CACHE PATH' in cmake
    assert "add_subdirectory(\"${HEADLAMP_ASSEMBLY_GUPPY_DIR}\" guppy-build)" in cmake
    assert "target_link_libraries(headlamp_assembly guppy_driver)" in cmake


def test_deterministic():
    a = run("m2m/bind.xsl", DATA / "composite.pim.xml")
    assert a == run("m2m/bind.xsl", DATA / "composite.pim.xml")


# ------------------------------------------------------------ fixtures
@pytest.mark.parametrize("case_name", ["headlamp", "meka"])
def test_fixture_chain(case_name):
    xmi = ROOT / "fixtures" / "cases" / case_name / "model.xmi"
    if not xmi.exists() or not (XSLT / "import" / "import.xsl").exists():
        pytest.skip("fixture or importer missing")
    pim = run("import/import.xsl", xmi, **{"source-name": "model.xmi"})
    bound, psm, files = chain(pim, model_dir="..")
    acts = {a.find(O + "activity").get("scheduler") for a in psm.iter(O + "instance")}
    periods = {a.find(O + "activity").get("period") for a in psm.iter(O + "instance")}
    if case_name == "headlamp":
        assert acts == {"ORO_SCHED_RT"} and periods == {"0.003"}
    else:
        assert acts == {"ORO_SCHED_OTHER"} and periods == {"0.05"}
    assert all(a.find(O + "activity").get("priority") == "50" for a in psm.iter(O + "instance"))
    assert len(list(psm.iter(O + "connection"))) >= 1
    assert "../atomic" in files["CMakeLists.txt"].text
    # every instance is periodic: input ports must not also trigger updateHook
    sources = "".join(node.text for path, node in files.items() if path.endswith(".cpp"))
    assert "addEventPort" not in sources and "this->ports()->addPort(port_" in sources


def test_text_multi_cpu_affinity_reaches_every_file():
    """A mask of several CPUs is set in XML, .ops and Lua alike (issue 17: it was XML only)."""
    bound = run("m2m/bind.xsl", (DATA / "composite.pim.xml").read_text())
    psm = run("m2m/orocos/psm.xsl", bound, **{"package-name": ""})
    psm = psm.replace('cpu-affinity="2"', 'cpu-affinity="6"')
    assert 'cpu-affinity="6"' in psm
    files = {f.get("path"): f.text for f in ET.fromstring(run("m2t/orocos/main.xsl", psm, **{"model-dir-from-output": "."})).iter(FS + "file")}
    root = ET.fromstring(files["deploy/headlamp_assembly.xml"].encode())
    assert root.find("struct[@name='vision']/struct[@name='Activity']/simple[@name='CpuAffinity']/value").text == "6"
    ops = files["deploy/headlamp_assembly.ops"]
    assert "// CpuAffinity mask 6 (CPUs 1, 2)\nif ( !vision.setCpuAffinity(6) ) then print.log(Error, " in ops
    _assert_ops_comments_alone(ops)
    assert 'check(comps["vision"]:setCpuAffinity(6), "vision.setCpuAffinity(6)")' in files["deploy/headlamp_assembly.lua"]
    assert 'comps["vision"]:getCpuAffinity() == 6' in files["deploy/headlamp_assembly-check.lua"]


def test_text_build_defaults_and_relocation():
    """Release unless a build type is set; a moved package names the -D option; headers usable downstream."""
    _, psm, files = case("composite")
    cmake = files["CMakeLists.txt"].text
    assert "set(CMAKE_BUILD_TYPE Release CACHE STRING" in cmake
    for lib in psm.iter(O + "library"):
        var = lib.get("cmake-var")
        assert f"give its place with -D{var}=DIR" in cmake and "message(WARNING" not in cmake
        assert f'install(DIRECTORY "${{{var}}}/{lib.get("include-dir")}/" DESTINATION include/orocos/{psm.get("package")}' in cmake


def test_text_user_tuned_values_file_per_instance_with_properties():
    """Tuning on the robot meant editing generated deployment files, which then blocked
    regeneration (issue 10 item 6): every instance with properties gets a .cpf of the user's,
    written once and loaded after the model's values by all three deployment formats."""
    _, _, files = case("composite")
    cpf = files["deploy/vision.user.cpf"]
    assert cpf.get("mode") == "user" and cpf.get("implements") and "property debug boolean" in cpf.get("signature")
    root = ET.fromstring(cpf.text.encode())
    assert root.tag == "properties" and len(root) == 0  # empty: changes nothing until the user fills it
    assert '<simple name="debug" type="boolean"><value>1</value></simple>' in cpf.text  # in the comment, to copy
    with_props = {i for i, f in files.items() if i.endswith(".user.cpf")}
    xml = ET.fromstring(files["deploy/headlamp_assembly.xml"].text.encode())
    update = "simple[@name='UpdateProperties']"
    assert with_props == {"deploy/" + s.find(update + "/value").text
                          for s in xml.findall("struct") if s.find(update) is not None}
    for s in xml.findall("struct"):  # after the model's values: the deployer applies Properties first
        names = [c.get("name") for c in s]
        if "UpdateProperties" in names:
            assert names.index("Properties") < names.index("UpdateProperties")
    ops = files["deploy/headlamp_assembly.ops"].text
    assert ('loadService("vision", "marshalling")\nif ( !vision.marshalling.updateProperties("vision.user.cpf") ) then {'
            in ops)
    assert ops.index("vision.debug = true") < ops.index('updateProperties("vision.user.cpf")') < ops.index("vision.configure()")
    lua = files["deploy/headlamp_assembly.lua"].text
    assert ('getOperation("updateProperties")(here .. "/vision.user.cpf"), "load vision.user.cpf")' in lua)
    check = files["deploy/headlamp_assembly-check.lua"].text
    assert 'want("vision", "debug", true)' in check and '.user.cpf' in check


def test_tuned_values_survive_regeneration_and_misspelt_ones_are_named(tmp_path):
    from robomda.api import generate
    model = ROOT / "fixtures" / "cases" / "tuned" / "model.xmi"
    out = tmp_path / "tuned"
    generate(model, out, "orocos")
    cpf = out / "deploy" / "controller.user.cpf"
    cpf.write_text(cpf.read_text().replace(
        "<properties>\n", '<properties>\n  <simple name="stiffness" type="long"><value>700</value></simple>\n'
        '  <simple name="stifness" type="long"><value>1</value></simple>\n'
        '  <simple name="damping" type="double"><value>3.5</value></simple>\n'))
    tuned = cpf.read_text()
    again = generate(model, out, "orocos")
    assert cpf.read_text() == tuned  # never overwritten
    out005 = [w for w in again.warnings if w.code == "OUT005"]
    assert [(w.line, "property 'stifness'" in w.message, "property 'damping'" in w.message) for w in out005] == \
        [(tuned.splitlines().index('  <simple name="stifness" type="long"><value>1</value></simple>') + 1, True, False),
         (tuned.splitlines().index('  <simple name="damping" type="double"><value>3.5</value></simple>') + 1, False, True)]
    assert all(w.file == str(cpf) for w in out005)
    assert "'long'" in out005[1].message and "refuses" in out005[1].message


def test_a_user_file_is_checked_as_deep_as_the_type_goes(tmp_path):
    """OUT005 below the top level (issue 37): a misspelt member of a data type, a member of another
    type, a misspelt member of a nested data type, a name no array element has; an element of an
    array the model leaves empty is not checked (its element shape is unknown)."""
    from robomda.api import generate
    model = ROOT / "fixtures" / "cases" / "structured" / "model.xmi"
    out = tmp_path / "structured"
    generate(model, out, "orocos")
    cpf = out / "deploy" / "ctrl1.user.cpf"
    simple = '<simple name="{}" type="{}"><value>1</value></simple>'
    cpf.write_text(cpf.read_text().replace("<properties>\n", "<properties>\n" + "\n".join([
        '<struct name="gains" type="/structured/Gains">', simple.format("stifness", "double"),
        simple.format("damping", "long"), simple.format("maxTorque", "double"), "</struct>",
        '<struct name="limit" type="/structured/JointTorques">', '<struct name="gains" type="/structured/Gains">',
        simple.format("maxTorq", "double"), "</struct>", '<struct name="torque" type="array">',
        simple.format("Element0", "double"), simple.format("First", "double"), "</struct>", "</struct>",
        '<struct name="history" type="array">', simple.format("Element0", "double"), "</struct>"]) + "\n"))
    lines = cpf.read_text().splitlines()
    found = [w for w in generate(model, out, "orocos").warnings if w.code == "OUT005"]
    assert [w.line for w in found] == [lines.index(simple.format(n, t)) + 1 for n, t in
                                       [("stifness", "double"), ("damping", "long"), ("maxTorq", "double"),
                                        ("First", "double")]]
    said = [w.message for w in found]
    assert "'stifness' in property 'gains'" in said[0] and "damping, maxTorque, stiffness" in said[0]
    assert "'gains.damping' type 'long', but it is 'double'" in said[1] and "converts" in said[1]
    assert "ignores it without a word" in said[0]
    assert "(limit.gains.maxTorq)" in said[2] and "(limit.torque.First)" in said[3]


def test_a_process_named_rtt_keeps_its_name(tmp_path):
    """RTT is kept out of C++ identifiers (a class RTT would hide RTT's namespace), not out of
    process names: a process named RTT is 'RTT' in the PSM and messages, 'rtt' in its files."""
    from edits import distributed_variant
    from robomda.api import generate
    model = distributed_variant(tmp_path, ('name="rttControl"', 'name="RTT"', 1))
    out = tmp_path / "out"
    generate(model, out, "orocos")
    deploy = out / "deploy"
    assert (deploy / "control_pc_rtt.xml").is_file() and not list(deploy.glob("*rtt_.*"))
    lua = (deploy / "control_pc_rtt.lua").read_text()
    assert "-- Process 'RTT' of host 'controlPC'" in lua and "'RTT_'" not in lua
    start = (deploy / "start_control_pc.sh").read_text()
    assert "# 3. process 'RTT'" in start and "stop_process \"$pid_3\" control_pc_rtt controller arm controlLoop" in start
