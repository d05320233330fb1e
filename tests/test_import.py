"""Tests of the XMI import stage, xslt/import/import.xsl (UML 2.x XMI -> PIM).

Runs the stylesheet with saxonche directly (no driver), validates every PIM
against schemas/pim/1/pim.xsd and asserts content:

- every real-tool sample in ../shared/xmi-samples (explicit table of
  expected outcomes and key content; skipped when ../shared is absent);
- hand-made inputs under tests/data/import/: one per error code (code and
  xmi:id asserted) and small models for the dialect rules;
- the fixtures fixtures/cases/<case>/model.xmi (Papyrus dialect) and
  model.ea.xmi (Enterprise Architect dialect) give the same PIM once ids are
  replaced by qualified names (skipped when the fixtures are missing).
"""
from __future__ import annotations

import os
import re
from pathlib import Path

import pytest
import xmlschema
from lxml import etree
from saxonche import PySaxonApiError, PySaxonProcessor

ROOT = Path(__file__).resolve().parents[1]
STYLESHEET = ROOT / "xslt" / "import" / "import.xsl"
SCHEMA = ROOT / "schemas" / "pim" / "1" / "pim.xsd"
DATA = ROOT / "tests" / "data" / "import"
# ../shared beside the checkout (as CI has it); ROBOMDA_SHARED overrides
SAMPLES = Path(os.environ.get("ROBOMDA_SHARED", Path(__file__).resolve().parents[2] / "shared")) / "xmi-samples"
FIXTURES = ROOT / "fixtures" / "cases"
PIM = "urn:robomda:pim:1"
NS = {"p": PIM}


# ------------------------------------------------------------------ helpers
_PROC = PySaxonProcessor(license=False)
_EXECUTABLE = None
_SCHEMA = None


class ImportFailed(Exception):
    """The stylesheet raised an error; .code and .xmi_id parsed from it."""

    def __init__(self, text: str) -> None:
        super().__init__(text)
        m = re.search(r"\b(IMP\d{3})\b", text)
        self.code = m.group(1) if m else None
        m = re.search(r"\[xmi:id=([^\]]*)\]", text)
        self.xmi_id = m.group(1) if m else None


def _executable():
    global _EXECUTABLE
    if _EXECUTABLE is None:
        _EXECUTABLE = _PROC.new_xslt30_processor().compile_stylesheet(stylesheet_file=str(STYLESHEET))
    return _EXECUTABLE


def run_import(path: Path) -> str:
    """The PIM of the XMI file at ``path`` (serialised), or ImportFailed."""
    ex = _executable()
    ex.clear_parameters()
    ex.set_parameter("source-name", _PROC.make_string_value(path.name))
    try:
        out = ex.transform_to_string(source_file=str(path.resolve()))
    except PySaxonApiError as exc:
        raise ImportFailed(str(exc)) from exc
    if out is None:
        raise ImportFailed(ex.error_message or "no result")
    return out


def validated(text: str) -> etree._Element:
    """Parse a PIM and validate it against pim.xsd (assertion on failure)."""
    global _SCHEMA
    if _SCHEMA is None:
        _SCHEMA = xmlschema.XMLSchema(str(SCHEMA))
    errors = [f"{e.path}: {e.reason}" for e in _SCHEMA.iter_errors(text)]
    assert not errors, "PIM not valid:\n" + "\n".join(errors[:5])
    return etree.fromstring(text.encode("utf-8"))


def count(doc: etree._Element, xpath: str) -> int:
    return int(doc.xpath(f"count({xpath})", namespaces=NS))


def one(doc: etree._Element, xpath: str) -> etree._Element:
    found = doc.xpath(xpath, namespaces=NS)
    assert len(found) == 1, f"{xpath}: {len(found)} matches"
    return found[0]


# ------------------------------------------------- real-tool samples table
# file -> expected outcome: model attributes, element counts, and xpaths
# that must each match exactly one element.
SAMPLE_TABLE = {
    "enterprise-architect/ea-xmi21-component-dep.xml": dict(
        model={"name": "Model", "tool": "enterprise-architect", "xmi-version": "2.1",
               "id": "EAPK_9EF29F04_E17F_4e7b_9E5D_FF8F7F1CCCF9"},
        counts={"component": 3, "interface": 3, "provides": 2, "requires": 2, "port": 0},
        one=["//p:component[@name='RootComponent']/p:requires"
             "[@interface='EAID_B1902E31_7CF8_4f1e_AE5E_B399157CDF85']",
             "//p:parameter[@name='options'][@type='EAID_7A542FF0_E6C3_437a_8D2A_21BAE2C8AD97']"
             "[@qualified-name='Model::Classes::IHttp::ajax::options']",
             # a void return (EAJava_void, a built-in without element) is no return
             "//p:operation[@name='getConfig'][not(p:parameter)]"]),
    "enterprise-architect/ea-xmi241-uml-elements.xmi": dict(
        model={"name": "Model", "tool": "enterprise-architect", "xmi-version": "2.4.1"},
        counts={"component": 7, "port": 2, "stereotype": 2, "package": 4},
        one=["//p:port[@name='Port A']/p:stereotype[@name='REST'][@profile='thecustomprofile']"
             "[@profile-uri='http://www.sparxsystems.com/profiles/thecustomprofile/1.0']"]),
    "magicdraw/magicdraw-19.0-mdzip-arrowhead-WP9UseCase.xmi": dict(
        model={"name": "Model", "tool": "magicdraw", "uml-namespace": "http://www.omg.org/spec/UML/20131001"},
        counts={"class": 12, "port": 12, "part": 6, "connector": 7, "generalization": 4},
        one=["//p:port[@type-library='external'][@type-name='HTTP Orchestration']"
             "[@conjugated='true'][@id='_19_0_3_219804d8_1584455426567_291649_14432']",
             "//p:part[@name='IndoorSensor1']/p:stereotype[@name='DeployedSystem'][@profile='arrowhead']"
             "/p:tag[@name='address'][@value='127.8.1.2']",
             "/p:model/p:doc"]),
    "modelio/modelio-objing-3.0.0-test5.xmi": dict(
        model={"name": "test", "tool": "modelio"},
        counts={"class": 2, "stereotype": 0, "component": 0},
        one=["//p:class[@name='Block']"]),
    "papyrus-carisma/carisma-componentdiagram-realization.uml": dict(
        model={"name": "componentModel", "tool": "eclipse-uml2", "id": "idModel"},
        counts={"component": 3, "interface": 1, "port": 1, "provides": 1, "requires": 1, "realization": 1},
        one=["//p:component[@name='Component2']/p:realization[@classifier='_UGXFwPgtEeKLAZ4gPThXMQ']",
             "//p:component[@name='Component1'][p:doc='Comment1']"]),
    "papyrus-carisma/carisma-deploymentdiagram-ee-manifestation.uml": dict(
        model={"name": "deploymentdiagramModel", "tool": "eclipse-uml2"},
        counts={"node": 3, "artifact": 2, "communication-path": 1, "deployment": 1, "manifestation": 1},
        one=["//p:node[@kind='device'][@name='Device1']/p:deployment[@deployed='_zGReEPguEeKLAZ4gPThXMQ']",
             "//p:node[@kind='execution-environment']",
             "//p:communication-path[p:end[1]/@node='_yMLNUPguEeKLAZ4gPThXMQ']"
             "[p:end[2]/@node='_yifbkPguEeKLAZ4gPThXMQ']",
             "//p:artifact[@name='DeploymentSpecification1']/p:manifestation"
             "[@element='_zGReEPguEeKLAZ4gPThXMQ']"]),
    "papyrus-robotml/robotml-AirOARPFSM.uml": dict(
        model={"name": "Talc", "tool": "papyrus", "xmi-version": "20110701"},
        counts={"class": 17, "interface": 2, "port": 24, "connector": 18},
        one=["/p:model/p:doc[contains(., 'Orocos')]"]),
    "papyrus-robotml/robotml-RoboCab.uml": dict(
        model={"name": "RoboCab", "tool": "papyrus"},
        # parts: the 22 attributes typed by a class of the «System» family (RobotML writes no aggregation)
        counts={"class": 32, "port": 66, "connector": 39, "part": 22},
        one=["//p:package[@name='CoreModel'][@qualified-name='RoboCab::CoreModel']",
             "//p:*[@type-library='ecore'][@type-name='EDouble'][@primitive='float64']"
             "[not(preceding::p:*[@type-name='EDouble'])]"]),
    "papyrus/papyrus-designer-ClientServerTimer.uml": dict(
        model={"name": "ClientServerTimer", "tool": "papyrus", "xmi-version": "20131001"},
        counts={"interface": 1, "port": 3, "node": 2, "connector": 1, "part": 3},
        one=["//p:class[@name='CServer_impl']/p:provides[@interface='_cn-H0DLbEd2qeKRLMdIx_A']",
             "//p:port[@name='p'][@type='_cn-H0DLbEd2qeKRLMdIx_A']/p:stereotype[@name='Port'][@profile='fcm']"
             "/p:tag[@name='type'][@ref='true'][@value='_cn-H0DLbEd2qeKRLMdIx_A']",
             "//p:connector[@name='qpconnector'][@kind='assembly']/p:end"
             "[@role='_DtWn4DLcEd2qeKRLMdIx_A'][@part='_i-I7gDLiEd2RVeNawwNNzg']",
             "//p:class[@name='Use_ICompute']/p:requires[@interface='_cn-H0DLbEd2qeKRLMdIx_A']",
             "//p:node[@name='LinuxHost'][@qualified-name='ClientServerTimer::PlatformModel::LinuxHost']"]),
    "papyrus/papyrus-designer-ProducerConsumer.uml": dict(
        model={"name": "ProducerConsumer", "tool": "papyrus"},
        counts={"interface": 2, "port": 3, "node": 1, "connector": 2},
        one=[]),
    "staruml/staruml-xmi21-uml_ninja-ops-params.xmi": dict(
        model={"name": "RootModel", "tool": "staruml", "xmi-version": "2.1"},
        counts={"class": 4, "operation": 18, "datatype": 3, "attribute": 13},
        one=["//p:attribute[@name='nameLengthLimit'][@static='true'][@default='250'][@primitive='int32']"
             "[ancestor::p:class/@name='UMLGateway']",
             "//p:package[@name='Model1'][@qualified-name='RootModel::Model1']"]),
}


def _sample_files() -> list[str]:
    return sorted(SAMPLE_TABLE)


@pytest.mark.parametrize("rel", _sample_files())
def test_sample(rel: str) -> None:
    path = SAMPLES / rel
    if not SAMPLES.is_dir():
        pytest.skip(f"shared samples absent: {SAMPLES}")
    assert path.is_file(), f"sample missing: {path}"
    expected = SAMPLE_TABLE[rel]
    if "error" in expected:
        with pytest.raises(ImportFailed) as info:
            run_import(path)
        assert info.value.code == expected["error"]
        return
    doc = validated(run_import(path))
    assert doc.tag == f"{{{PIM}}}model"
    assert doc.get("source") == path.name
    for attr, value in expected["model"].items():
        assert doc.get(attr) == value, attr
    for name, n in expected["counts"].items():
        assert count(doc, f"//p:{name}") == n, name
    for xpath in expected["one"]:
        one(doc, xpath)


def test_every_sample_is_in_the_table() -> None:
    if not SAMPLES.is_dir():
        pytest.skip(f"shared samples absent: {SAMPLES}")
    found = {str(p.relative_to(SAMPLES)) for p in SAMPLES.glob("*/*") if p.suffix in (".xmi", ".uml", ".xml")}
    assert found == set(SAMPLE_TABLE)


def test_output_is_deterministic() -> None:
    if not SAMPLES.is_dir():
        pytest.skip(f"shared samples absent: {SAMPLES}")
    path = SAMPLES / "papyrus/papyrus-designer-ClientServerTimer.uml"
    assert run_import(path) == run_import(path)


# ------------------------------------------------------------ error cases
ERROR_CASES = [
    ("xmi1x.xmi", "IMP001", ""),
    ("not-uml.xml", "IMP002", ""),
    ("no-model.xmi", "IMP003", ""),
    ("duplicate-id.uml", "IMP004", "dup1"),
    ("dangling-type.uml", "IMP010", "attr1"),
    ("dangling-port-type.uml", "IMP011", "port1"),
    ("dangling-general.uml", "IMP012", "gen1"),
    ("dangling-realizing.uml", "IMP013", "real1"),
    ("dangling-interface-realization.uml", "IMP014", "ir1"),
    ("dangling-usage.xmi", "IMP015", "usage1"),
    ("dangling-deployment.uml", "IMP016", "dep1"),
    ("dangling-manifestation.uml", "IMP017", "man1"),
    ("dangling-connector.uml", "IMP018", "end2"),
    ("dangling-communication-path.uml", "IMP019", "path1"),
]


@pytest.mark.parametrize("name,code,xmi_id", ERROR_CASES)
def test_error(name: str, code: str, xmi_id: str) -> None:
    with pytest.raises(ImportFailed) as info:
        run_import(DATA / name)
    assert info.value.code == code, str(info.value)
    assert info.value.xmi_id == xmi_id, str(info.value)
    if code == "IMP001":
        assert "unsupported: XMI 1.x" in str(info.value)
    if code in ("IMP002", "IMP003"):
        assert "unsupported" in str(info.value)
    if code.startswith("IMP01"):
        assert "missing" in str(info.value)   # the missing id is named


# ------------------------------------------------------- dialect details
def test_features() -> None:
    """Values, multiplicities, library types, stereotypes, external hrefs."""
    doc = validated(run_import(DATA / "features.uml"))
    assert doc.get("tool") == "eclipse-uml2"
    a = one(doc, "//p:attribute[@name='speed']")
    assert (a.get("default"), a.get("lower"), a.get("upper"), a.get("visibility")) == ("0.5", "0", "*", "private")
    assert (a.get("type-library"), a.get("type-name"), a.get("primitive")) == ("uml", "Real", "float64")
    assert one(doc, "//p:attribute[@name='count']").get("default") == "3"
    assert one(doc, "//p:attribute[@name='label']").get("default") == "hello"
    assert one(doc, "//p:attribute[@name='flag']").get("default") == "true"
    assert one(doc, "//p:attribute[@name='expr']").get("default") == "2*PI"
    assert one(doc, "//p:attribute[@name='empty']").get("default") is None
    assert one(doc, "//p:attribute[@name='e']").get("primitive") == "int32"
    assert one(doc, "//p:attribute[@name='ext']").get("type-library") == "external"
    op = one(doc, "//p:operation[@name='compute']")
    assert (op.get("query"), op.get("static"), op.get("abstract"), op.get("visibility")) == \
        ("true", "true", "true", "protected")
    assert [p.get("direction") for p in op.xpath("p:parameter", namespaces=NS)] == ["in", "out", "return"]
    st = one(doc, "//p:component[@name='Camera']/p:stereotype[@name='Activity']")
    assert st.get("profile") == "robomda" and st.get("profile-uri") == "http://robomda.org/profile/robomda/1"
    assert one(st, "p:tag[@name='period']").get("value") == "0.003"
    assert [t.get("value") for t in st.xpath("p:tag[@name='peers']", namespaces=NS)] == ["cls1", "cls1"]
    assert {t.get("ref") for t in st.xpath("p:tag[@name='peers']", namespaces=NS)} == {"true"}
    one(doc, "//p:component[@name='Camera']/p:realization[@classifier='cls1']")
    one(doc, "//p:component[@name='Camera']/p:port[@name='out'][@type='if1']/p:required[@interface='if2']")
    one(doc, "//p:component[@name='Camera'][p:doc='The camera.']")
    one(doc, "//p:platform/p:node[@name='PC']/p:node[@kind='execution-environment'][@name='OROCOS']")


def test_ea_model_root_and_builtin_types() -> None:
    doc = validated(run_import(DATA / "ea-mini.xmi"))
    assert (doc.get("id"), doc.get("name"), doc.get("tool")) == ("EAPK_ROOT", "demo", "enterprise-architect")
    a = one(doc, "//p:attribute[@name='width']")
    assert (a.get("type-library"), a.get("type-name"), a.get("primitive")) == ("c", "int", "int32")
    assert a.get("qualified-name") == "demo::Cam::width"
    one(doc, "//p:component[@name='CamComp']/p:realization[@classifier='EAID_CAM']")
    one(doc, "//p:component[@name='CamComp']/p:port[@name='p']/p:provided[@interface='EAID_IF']")
    st = one(doc, "//p:component[@name='CamComp']/p:stereotype[@name='Activity']")
    assert st.get("id").startswith("robomda.")


# ---------------------------------------------------- fixture equivalence
_IDREF_ATTRS = {"type", "general", "interface", "classifier", "role", "part", "element", "node"}
_IGNORED = {"source", "tool", "xmi-version", "uml-namespace"}


def _normalised(doc: etree._Element) -> str:
    """The PIM with ids replaced by qualified names, dialect-only attributes
    dropped and siblings sorted: equal for equal models."""
    labels: dict[str, str] = {}

    def label(e: etree._Element) -> str:
        if e.get("qualified-name") is not None:
            return e.get("qualified-name")
        parent = e.getparent()
        base = label(parent) if parent is not None and parent.tag != f"{{{PIM}}}model" else doc.get("name", "")
        key = e.get("name") or ""
        return f"{base}/{etree.QName(e).localname}({key})"

    for e in doc.iter():
        if e.get("id") is not None:
            labels[e.get("id")] = label(e)

    def ref(v: str) -> str:
        return labels.get(v, v)

    # second pass for elements labelled by what they reference
    for e in doc.iter():
        if e.get("id") is not None and e.get("qualified-name") is None:
            refs = ",".join(ref(e.get(a)) for a in sorted(_IDREF_ATTRS) if e.get(a) is not None)
            if refs:
                labels[e.get("id")] = labels[e.get("id")] + "[" + refs + "]"

    def canon(e: etree._Element) -> etree._Element:
        out = etree.Element(e.tag)
        for k, v in sorted(e.attrib.items()):
            if k in _IGNORED:
                continue
            if k in ("type-name", "type-library") and e.get("primitive") is not None:
                continue
            if k == "id" or k in _IDREF_ATTRS:
                v = ref(v)
            elif k == "deployed":
                v = " ".join(sorted(ref(t) for t in v.split()))
            elif k == "value" and e.get("ref") == "true":
                v = ref(v)
            out.set(k, v)
        if e.text and e.text.strip():
            out.text = e.text.strip()
        children = [canon(c) for c in e]
        children.sort(key=lambda c: etree.tostring(c))
        out.extend(children)
        return out

    return etree.tostring(canon(doc), pretty_print=True).decode()


@pytest.mark.parametrize("case", ["headlamp", "meka"])
def test_fixture_dialects_give_the_same_pim(case: str) -> None:
    papyrus, ea = FIXTURES / case / "model.xmi", FIXTURES / case / "model.ea.xmi"
    if not (papyrus.is_file() and ea.is_file()):
        pytest.skip(f"fixture {case} missing")
    a = validated(run_import(papyrus))
    b = validated(run_import(ea))
    assert a.get("tool") in ("papyrus", "eclipse-uml2")
    assert b.get("tool") == "enterprise-architect"
    assert count(a, "//p:component") > 0 and count(a, "//p:node") > 0
    na, nb = _normalised(a), _normalised(b)
    if na != nb:
        import difflib
        diff = "\n".join(difflib.unified_diff(na.splitlines(), nb.splitlines(), "papyrus", "ea", lineterm="", n=2))
        pytest.fail(f"{case}: Papyrus and EA PIMs differ:\n{diff[:6000]}")


def test_a_deployment_owned_by_one_node_with_another_as_client_deploys_once_on_its_client(tmp_path: Path) -> None:
    """The camera's Deployment stays inside process rttCamera but names rttVision as its client: it is
    imported once, on rttVision (before, it was imported on both and the PIM broke its own schema),
    and IMP117 names both nodes."""
    from edits import distributed_variant
    from robomda.api import generate

    model = distributed_variant(tmp_path, ('client="_dstRttCameraEEw2X3y4Z5a" supplier="_ZFkQzwZWOKVfkNutf1AcmA"',
                                           'client="_dstRttVisionEEb6C7d8E9f" supplier="_ZFkQzwZWOKVfkNutf1AcmA"', 1))
    done = generate(model, None, "orocos", write=False)
    moved = [w for w in done.warnings if w.code == "IMP117"]
    assert len(moved) == 1 and "'rttCamera'" in moved[0].message and "'rttVision'" in moved[0].message
    pim = etree.fromstring(done.stages["import"].encode())
    deployments = pim.findall(".//{urn:robomda:pim:1}deployment[@id='_7r_06xjuD8PlcTvtlRdcOv']")
    assert len(deployments) == 1 and deployments[0].getparent().get("name") == "rttVision"


def _class_model(features: str) -> str:
    """A Papyrus model of one class holding ``features`` (ownedAttribute / ownedOperation elements)."""
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<xmi:XMI xmi:version="20131001" xmlns:xmi="http://www.omg.org/spec/XMI/20131001" xmlns:uml="http://www.eclipse.org/uml2/5.0.0/UML">
  <uml:Model xmi:id="_m" name="M">
    <packagedElement xmi:type="uml:Class" xmi:id="_C" name="C">
{features}
    </packagedElement>
  </uml:Model>
</xmi:XMI>
"""


def test_elements_without_ids_are_numbered_among_their_siblings_of_that_name(tmp_path: Path) -> None:
    """An element without xmi:id gets "robomda.<anchor>.<name>-<n>", n its place among its parent's
    children of its name, those with ids included (a look-up per element, not a count of the siblings:
    issue 35); a name alone under its parent has no number; many siblings keep their places."""
    many = 300
    attributes = "\n".join(f'      <ownedAttribute name="a{i}"/>' if i != 2 else '      <ownedAttribute xmi:id="_A2" name="a2"/>'
                           for i in range(1, many + 1))
    model = tmp_path / "model.uml"
    model.write_text(_class_model(attributes + '\n      <ownedOperation name="run"/>'))
    doc = validated(run_import(model))
    ids = {a.get("name"): a.get("id") for a in doc.iterfind(".//p:attribute", NS)}
    assert ids["a1"] == "robomda._C.ownedAttribute-1"
    assert ids["a2"] == "_A2"
    assert ids["a3"] == "robomda._C.ownedAttribute-3"
    assert ids[f"a{many}"] == f"robomda._C.ownedAttribute-{many}"
    assert len(set(ids.values())) == many
    assert one(doc, ".//p:operation").get("id") == "robomda._C.ownedOperation"
