"""What real exports hold that the import misread (issue 30, classes 4-9), one test per class and dialect.

The models are built here, in the dialect each shape occurs in: Eclipse UML2
/ Papyrus (xmi:type, SysML NestedConnectorEnd of Papyrus), UML Designer
(Eclipse namespace, several clients in one attribute), GenMyModel (xsi:type
instead of xmi:type), Enterprise Architect (exposed interfaces, EAID_ ids,
built-in types) and MagicDraw / Cameo (NestedConnectorEnd whose last step is
also partWithPort). For each model, ``import``, ``check`` and ``generate``
agree: the same warnings name what is left out, and what the PIM holds is
what the generated files are made of.

4. template parameters are no classes (IMP118 names the template);
5. xsi:type is read as xmi:type, and IMP030 tells the truth about a file;
6. a relationship with several clients gives each pair its own id;
7. nested connector ends join the nested instance, or are refused (IMP110);
8. EA's exposed interfaces and a Collaboration's roles are named (IMP119, IMP116);
9. a dangling end of a relationship robomda would not import is IMP112, not an error.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

from robomda.api import check, import_model
from robomda.cli import main
from robomda.diagnostics import Diagnostic, RobomdaError
from xmi_invariant import dropped, import_run

NS = {"p": "urn:robomda:pim:1"}
XSI = "http://www.w3.org/2001/XMLSchema-instance"

# --------------------------------------------------------------- builders
DIALECTS = {
    # (XMI namespace, UML namespace, exporter, wrapped in xmi:XMI)
    "eclipse": ("http://www.omg.org/spec/XMI/20131001", "http://www.eclipse.org/uml2/5.0.0/UML", None),
    "xsi": ("http://www.omg.org/spec/XMI/20131001", "http://www.eclipse.org/uml2/5.0.0/UML", None),
    "magicdraw": ("http://www.omg.org/spec/XMI/20131001", "http://www.omg.org/spec/UML/20131001",
                  "MagicDraw Clean XMI Exporter"),
    "ea": ("http://schema.omg.org/spec/XMI/2.1", "http://schema.omg.org/spec/UML/2.1", "Enterprise Architect"),
}
SYSML = {"eclipse": "http://www.eclipse.org/papyrus/sysml/1.6/SysML/Blocks",
         "magicdraw": "http://www.omg.org/spec/SysML/20181001/SysML"}


class Xmi:
    """A model written in one dialect: ``t('Class')`` is its type attribute, ``real()`` a Real type reference."""

    def __init__(self, dialect: str) -> None:
        self.d = dialect

    def t(self, meta: str) -> str:
        return f'{"xsi" if self.d == "xsi" else "xmi"}:type="uml:{meta}"'

    def real(self) -> str:
        if self.d == "ea":
            return '<type xmi:idref="EAJava_double"/>'
        if self.d == "magicdraw":
            return '<type href="http://www.omg.org/spec/UML/20131001/PrimitiveTypes.xmi#Real"/>'
        return f'<type {self.t("PrimitiveType")} href="pathmap://UML_LIBRARIES/UMLPrimitiveTypes.library.uml#Real"/>'

    def ref(self, prop: str, xid: str) -> str:
        """A reference as the dialect writes it: EA a child with xmi:idref, the others an attribute."""
        return f'<{prop} xmi:idref="{xid}"/>' if self.d == "ea" else f' {prop}="{xid}"'

    def typed(self, tag: str, xid: str, name: str, type_id: str, extra: str = "", meta: str = "Property") -> str:
        if self.d == "ea":
            return f'<{tag} {self.t(meta)} xmi:id="{xid}" name="{name}"{extra}><type xmi:idref="{type_id}"/></{tag}>'
        return f'<{tag} {self.t(meta)} xmi:id="{xid}" name="{name}" type="{type_id}"{extra}/>'

    def document(self, body: str, applications: str = "", platform: bool = True) -> str:
        xmi, uml, exporter = DIALECTS[self.d]
        if platform:
            body += (f'<packagedElement {self.t("Node")} xmi:id="pc" name="pc">'
                     f'<nestedNode {self.t("ExecutionEnvironment")} xmi:id="ee" name="OROCOS"/></packagedElement>')
        extra = f' xmlns:xsi="{XSI}"' if self.d == "xsi" else ""
        sysml = f' xmlns:sysml="{SYSML[self.d]}"' if self.d in SYSML else ""
        if self.d == "ea":
            model = (f'<uml:Model xmi:type="uml:Model" name="EA_Model"><packagedElement xmi:type="uml:Package" '
                     f'xmi:id="EAPK_R" name="m">{body}</packagedElement></uml:Model>')
        else:
            model = f'<uml:Model xmi:id="m" name="m">{body}</uml:Model>'
        doc = f'<xmi:Documentation exporter="{exporter}"/>' if exporter else ""
        if self.d == "xsi" and not applications:  # GenMyModel: a bare uml:Model
            return (f'<?xml version="1.0" encoding="UTF-8"?>\n<uml:Model xmi:version="20131001" xmlns:xmi="{xmi}" '
                    f'xmlns:uml="{uml}"{extra} xmi:id="m" name="m">{body}</uml:Model>\n')
        return (f'<?xml version="1.0" encoding="UTF-8"?>\n<xmi:XMI xmi:version="20131001" xmlns:xmi="{xmi}" '
                f'xmlns:uml="{uml}"{extra}{sysml} xmlns:other="http://example.org/other">{doc}{model}{applications}'
                f'</xmi:XMI>\n')

    def interface(self, xid: str, name: str) -> str:
        return (f'<packagedElement {self.t("Interface")} xmi:id="{xid}" name="{name}">'
                f'<ownedAttribute {self.t("Property")} xmi:id="{xid}V" name="v">{self.real()}</ownedAttribute>'
                f'</packagedElement>')

    def component(self, xid: str, name: str, inner: str) -> str:
        return f'<packagedElement {self.t("Component")} xmi:id="{xid}" name="{name}">{inner}</packagedElement>'

    def port(self, xid: str, name: str, interface: str, *, conjugated: bool = False) -> str:
        conj = ' isConjugated="true"' if conjugated else ""
        return self.typed("ownedAttribute", xid, name, interface, f'{conj} aggregation="composite"', meta="Port")

    def part(self, xid: str, name: str, component: str) -> str:
        return self.typed("ownedAttribute", xid, name, component, ' aggregation="composite"')

    def end(self, xid: str, role: str, part: str | None) -> str:
        if self.d == "ea":
            pwp = f'<partWithPort xmi:idref="{part}"/>' if part else ""
            return f'<end xmi:type="uml:ConnectorEnd" xmi:id="{xid}"><role xmi:idref="{role}"/>{pwp}</end>'
        pwp = f' partWithPort="{part}"' if part else ""
        return f'<end {self.t("ConnectorEnd")} xmi:id="{xid}" role="{role}"{pwp}/>'


def _write(tmp_path: Path, dialect: str, text: str) -> Path:
    path = tmp_path / ("model.uml" if dialect in ("eclipse", "xsi") else "model.xmi")
    path.write_text(text, encoding="utf-8")
    return path


def _import(path: Path, *, bind: bool = True) -> tuple[etree._Element, list[Diagnostic]]:
    found: list[Diagnostic] = []
    text = import_model(path, bind=bind, warnings=found)
    return etree.fromstring(text.encode("utf-8")), found


def _codes(found: list[Diagnostic]) -> set[tuple[str, str | None]]:
    return {(d.code, d.xmi_id) for d in found}


def _agree(path: Path, tmp_path: Path, found: list[Diagnostic]) -> None:
    """``check`` and ``generate`` see what ``import`` saw: the same import warnings, no error, files written."""
    done = check(path)
    assert done.exit_code == 0, [d.format() for d in done.diagnostics]
    imp = {(d.code, d.xmi_id) for d in done.diagnostics if d.code.startswith("IMP")}
    assert imp == {c for c in _codes(found) if c[0].startswith("IMP")}
    code, pim, messages = import_run(path)
    assert code == 0 and not dropped(path, pim, messages), dropped(path, pim, messages)
    assert main(["generate", str(path), "-o", str(tmp_path / "out"), "--target", "orocos"]) == 0


# ---------------------------------------------------- class 4: templates
def _template_model(x: Xmi) -> str:
    sig = x.t("RedefinableTemplateSignature")
    tp = x.t("ClassifierTemplateParameter")
    return x.document(
        x.interface("ifI", "Img")
        + f'<packagedElement {x.t("Class")} xmi:id="buf" name="Buffer">'
          f'<ownedTemplateSignature {sig} xmi:id="sig" parameter="tpT">'
          f'<ownedParameter {tp} xmi:id="tpT" parameteredElement="peT">'
          f'<ownedParameteredElement {x.t("Class")} xmi:id="peT" name="TemplateParameter1" templateParameter="tpT"/>'
          f'<ownedDefault {x.t("Class")} xmi:id="dfT" name="Default1"/>'
          f'</ownedParameter></ownedTemplateSignature>'
          + x.typed("ownedAttribute", "bufItem", "item", "peT")
          + '</packagedElement>'
        + f'<packagedElement {x.t("Class")} xmi:id="bnd" name="ImageBuffer">'
          f'<templateBinding xmi:id="tb" signature="sig"><parameterSubstitution xmi:id="ps" formal="tpT">'
          f'<ownedActual {x.t("Class")} xmi:id="act" name="Actual1"/></parameterSubstitution></templateBinding>'
          f'</packagedElement>'
        + x.component("cam", "Camera", x.port("camOut", "out", "ifI")))


@pytest.mark.parametrize("dialect", ["eclipse", "xsi", "magicdraw"])
def test_template_parameters_are_no_classes(dialect: str, tmp_path: Path) -> None:
    path = _write(tmp_path, dialect, _template_model(Xmi(dialect)))
    doc, found = _import(path)
    # the placeholders are not classes, nor anything else of the PIM
    assert doc.xpath("//p:class/@name", namespaces=NS) == ["Buffer", "ImageBuffer"]
    assert not doc.xpath("//*[@id='peT' or @id='dfT' or @id='act']", namespaces=NS)
    assert not [n for n in doc.xpath("//@qualified-name") if "::::" in n or "TemplateParameter" in n]
    # a feature typed by a parameter names it, and says it has no type robomda reads
    item = doc.xpath("//p:attribute[@id='bufItem']", namespaces=NS)[0]
    assert (item.get("type"), item.get("type-name"), item.get("type-metaclass")) == \
        (None, "TemplateParameter1", "TemplateParameter")
    assert ("IMP102", "bufItem") in _codes(found)
    # one warning per templated or bound classifier, naming the parameters
    imp118 = {d.xmi_id: d.message for d in found if d.code == "IMP118"}
    assert set(imp118) == {"buf", "bnd"}
    assert "a template (parameters: TemplateParameter1)" in imp118["buf"]
    assert "bound to Class 'Buffer'" in imp118["bnd"]
    _agree(path, tmp_path, found)
    header = (tmp_path / "out").rglob("*.hpp")
    assert not [h for h in header if "TemplateParameter" in h.read_text(encoding="utf-8")]


# ------------------------------------------------------ class 5: xsi:type
def _plain_model(x: Xmi) -> str:
    return x.document(
        x.interface("ifI", "Img")
        + x.component("cam", "Camera", x.port("camOut", "out", "ifI"))
        + x.component("view", "Viewer", x.port("viewIn", "in", "ifI", conjugated=True)))


def test_xsi_type_is_read_as_xmi_type(tmp_path: Path) -> None:
    path = _write(tmp_path, "xsi", _plain_model(Xmi("xsi")))
    assert "xmi:type" not in path.read_text(encoding="utf-8")
    doc, found = _import(path)
    assert doc.xpath("//p:component/@name", namespaces=NS) == ["Camera", "Viewer"]
    assert doc.xpath("//p:node/@name", namespaces=NS) == ["pc", "OROCOS"]
    assert doc.xpath("//p:component[@id='cam']/p:port[@id='camOut']/@type", namespaces=NS) == ["ifI"]
    assert not [d for d in found if d.code == "IMP030"]
    # the diagnostics name the metaclass xsi:type gives
    assert all("uml:" in d.format() for d in found if d.xmi_id)
    _agree(path, tmp_path, found)
    assert (tmp_path / "out" / "src" / "Camera.hpp").exists() or list((tmp_path / "out").rglob("*Camera*"))


def test_xmi_type_wins_over_xsi_type(tmp_path: Path) -> None:
    text = _plain_model(Xmi("xsi")).replace('xsi:type="uml:Component" xmi:id="view"',
                                             'xsi:type="uml:Class" xmi:type="uml:Component" xmi:id="view"')
    text = text.replace("<uml:Model ", "<uml:Model ", 1)
    path = _write(tmp_path, "xsi", text)
    doc, _ = _import(path)
    assert doc.xpath("//p:component/@name", namespaces=NS) == ["Camera", "Viewer"]


def test_imp030_does_not_count_what_a_profile_holds(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # a model whose only components are in a profile it defines, plus a use case
    x = Xmi("xsi")
    body = (f'<packagedElement {x.t("Profile")} xmi:id="prof" name="Robots">'
            + x.component("pc1", "ProfileComponent", "") + x.component("pc2", "Other", "")
            + f'</packagedElement><packagedElement {x.t("UseCase")} xmi:id="uc" name="Drive"/>')
    path = _write(tmp_path, "xsi", x.document(body, platform=False))
    assert main(["import", str(path), "-o", str(tmp_path / "p.xml")]) == 0
    err = capsys.readouterr().err
    assert "[IMP030] nothing to generate from: Model 'm' holds no component, class, interface or node" in err
    assert "(it holds 1 Profile, 1 UseCase)" in err and "Component" not in err.split("[IMP030]")[1]


def test_imp030_says_when_the_file_holds_components_it_does_not_import(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # a second top-level model: its component is outside the model robomda reads
    x = Xmi("eclipse")
    text = x.document(f'<packagedElement {x.t("UseCase")} xmi:id="uc" name="Drive"/>', platform=False)
    text = text.replace("</xmi:XMI>", '<uml:Model xmi:id="m2" name="second">'
                        + x.component("far", "Far", "") + "</uml:Model></xmi:XMI>")
    path = _write(tmp_path, "eclipse", text)
    assert main(["import", str(path), "-o", str(tmp_path / "p.xml")]) == 0
    err = capsys.readouterr().err
    assert "[IMP116] Component 'Far'" in err
    assert "holds no component, class, interface or node that robomda imports" in err


# ------------------------------------------- class 6: several clients
def _multi_model(x: Xmi, clients: str) -> str:
    def rel(meta: str, xid: str, **refs: str) -> str:
        """Client, supplier ... as id lists, or (MagicDraw) as one child element per id."""
        if x.d == "magicdraw":
            kids = "".join(f'<{p} xmi:idref="{i}"/>' for p, ids in refs.items() for i in ids.split())
            return f'<packagedElement {x.t(meta)} xmi:id="{xid}">{kids}</packagedElement>'
        return f'<packagedElement {x.t(meta)} xmi:id="{xid}"' + "".join(f' {p}="{v}"' for p, v in refs.items()) + "/>"

    return x.document(
        x.interface("ifA", "A") + x.interface("ifB", "B")
        + f'<packagedElement {x.t("Class")} xmi:id="impl" name="Impl"/>'
        + f'<packagedElement {x.t("Package")} xmi:id="pkg" name="pk"/>'
        + x.component("cmp", "Cmp", x.port("prt", "p", "ifA"))
        + x.component("cmp2", "Cmp2", x.port("prt2", "q", "ifA", conjugated=True))
        + rel("InterfaceRealization", "ir", client=clients, supplier="ifA ifB", contract="ifA ifB")
        + rel("Realization", "rl", client=clients, supplier="ifA")
        + rel("Usage", "us", client="cmp2 pkg", supplier="ifA ifB"))


@pytest.mark.parametrize("dialect", ["eclipse", "xsi", "magicdraw"])
def test_a_relationship_with_several_clients_gives_each_pair_an_id(dialect: str, tmp_path: Path) -> None:
    path = _write(tmp_path, dialect, _multi_model(Xmi(dialect), "impl prt cmp pkg"))
    doc, found = _import(path)
    ids = doc.xpath("//@id")
    assert len(ids) == len(set(ids)), "duplicate ids in the PIM"

    def provides(owner: str) -> list[tuple[str, str]]:
        return [(e.get("id"), e.get("interface")) for e in doc.xpath(f"//*[@id='{owner}']/p:provides", namespaces=NS)]

    # the first client keeps the relationship's id, the others get robomda.<id>.<n>
    assert provides("impl") == [("ir", "ifA"), ("robomda.ir.2", "ifB"), ("rl", "ifA")]
    assert provides("cmp") == [("robomda.ir.5", "ifA"), ("robomda.ir.6", "ifB"), ("robomda.rl.3", "ifA")]
    assert [(e.get("id"), e.get("interface")) for e in doc.xpath("//*[@id='cmp2']/p:requires", namespaces=NS)] \
        == [("us", "ifA"), ("robomda.us.2", "ifB")]
    # the port's pairs are recorded by via
    assert doc.xpath("//p:port[@id='prt']/p:provided/@via", namespaces=NS) == ["ir rl", "ir"]
    # the package is no client robomda reads: named, located on the relationship
    pairs = {d.xmi_id: d.message for d in found if d.code == "IMP112"}
    assert set(pairs) == {"ir", "rl", "us"}
    assert all("not for Package 'pk' (client)" in m for m in pairs.values())
    _agree(path, tmp_path, found)


def test_several_clients_in_the_ea_dialect(tmp_path: Path) -> None:
    # EA writes client and supplier as attributes too; a Realization to two components
    x = Xmi("ea")
    text = x.document(
        x.interface("EAID_IF", "A")
        + '<packagedElement xmi:type="uml:Class" xmi:id="EAID_CL" name="Impl"/>'
        + x.component("EAID_C1", "One", x.port("EAID_P1", "p", "EAID_IF"))
        + x.component("EAID_C2", "Two", x.port("EAID_P2", "q", "EAID_IF", conjugated=True))
        + '<packagedElement xmi:type="uml:Realization" xmi:id="EAID_RL" client="EAID_CL" supplier="EAID_C1 EAID_C2"/>'
        + '<packagedElement xmi:type="uml:Usage" xmi:id="EAID_US" client="EAID_C1 EAID_C2" supplier="EAID_IF"/>')
    path = _write(tmp_path, "ea", text)
    doc, found = _import(path)
    ids = doc.xpath("//@id")
    assert len(ids) == len(set(ids))
    assert [(e.get("id"), e.get("classifier")) for e in doc.xpath("//p:realization", namespaces=NS)] == \
        [("EAID_RL", "EAID_CL"), ("robomda.EAID_RL.2", "EAID_CL")]
    assert doc.xpath("//p:requires/@id", namespaces=NS) == ["EAID_US", "robomda.EAID_US.2"]
    _agree(path, tmp_path, found)


# ----------------------------------------- class 7: nested connector ends
def _nested_model(x: Xmi, *, nested: str, second: bool = False, pwp: bool = True) -> tuple[str, str]:
    """System = a: Sub (+ a2: Sub) + b: Sink; Sub = s: Sensor. Connector c1 of System joins a.s.out to b.in.

    ``nested``: 'sysml' (a NestedConnectorEnd with propertyPath "a s"), 'role' (propertyPath "a s sOut": some
    exporters end the path in the role itself), 'broken' (propertyPath "b s"), 'uml' (partWithPort s only, a
    part of a part).
    """
    end1 = x.end("e1", "sOut", "s" if pwp else None)
    body = (x.interface("ifI", "Img")
            + x.component("sensor", "Sensor", x.port("sOut", "out", "ifI"))
            + x.component("sink", "Sink", x.port("kIn", "in", "ifI", conjugated=True))
            + x.component("sub", "Sub", x.part("s", "s", "sensor"))
            + x.component("sys", "System", x.part("a", "a", "sub") + (x.part("a2", "a2", "sub") if second else "")
                          + x.part("b", "b", "sink")
                          + f'<ownedConnector {x.t("Connector")} xmi:id="c1" name="c1">{end1}'
                          + x.end("e2", "kIn", "b") + "</ownedConnector>"))
    apps = ""
    if nested in ("sysml", "broken", "role"):
        path = {"sysml": "a s", "broken": "b s", "role": "a s sOut"}[nested]
        if x.d == "magicdraw":  # MagicDraw: child elements, the last step also partWithPort
            steps = "".join(f'<propertyPath xmi:idref="{p}"/>' for p in path.split())
            apps = f'<sysml:NestedConnectorEnd xmi:id="nce" base_ConnectorEnd="e1">{steps}</sysml:NestedConnectorEnd>'
        else:
            apps = f'<sysml:NestedConnectorEnd xmi:id="nce" base_ConnectorEnd="e1" propertyPath="{path}"/>'
    return x.document(body, apps), apps


def _connections(doc: etree._Element) -> list[tuple[str, str]]:
    return [(c.xpath("p:writer/@instance", namespaces=NS)[0], c.xpath("p:reader/@instance", namespaces=NS)[0])
            for c in doc.xpath("//p:binding/p:connection", namespaces=NS)]


@pytest.mark.parametrize(("dialect", "pwp"), [("eclipse", False), ("eclipse", True), ("magicdraw", True)])
def test_a_nested_connector_end_joins_the_nested_instance(dialect: str, pwp: bool, tmp_path: Path) -> None:
    text, _ = _nested_model(Xmi(dialect), nested="sysml", second=True, pwp=pwp)
    path = _write(tmp_path, dialect, text)
    doc, found = _import(path)
    end = doc.xpath("//p:connector[@id='c1']/p:end[@id='e1']", namespaces=NS)[0]
    assert (end.get("part"), end.get("path"), end.get("role")) == ("s", "a s", "sOut")
    # the instance at the path, not a.s's twin a2.s nor a part s of System
    assert sorted(doc.xpath("//p:binding/p:instance/@name", namespaces=NS)) == ["a2_s", "a_s", "b"]
    assert _connections(doc) == [("a_s", "b")]
    _agree(path, tmp_path, found)
    deploy = "\n".join(p.read_text(encoding="utf-8") for p in (tmp_path / "out").rglob("*.ops"))
    assert 'loadComponent("a2_s"' in deploy and 'connect("a_s.out", "b.in"' in deploy
    assert "a2_s.out" not in deploy
    # the stereotype was read: no IMP115 for it
    assert not [d for d in found if d.code == "IMP115"]


@pytest.mark.parametrize("dialect", ["eclipse", "magicdraw"])
def test_a_nested_end_whose_path_ends_in_its_role_is_followed_once(dialect: str, tmp_path: Path) -> None:
    """Issue 51 item 5: a propertyPath that ends in the role itself is the path to the role's part, not a
    path broken at its partWithPort (the last step followed twice)."""
    text, _ = _nested_model(Xmi(dialect), nested="role", second=True)
    path = _write(tmp_path, dialect, text)
    doc, found = _import(path)
    end = doc.xpath("//p:connector[@id='c1']/p:end[@id='e1']", namespaces=NS)[0]
    assert (end.get("part"), end.get("path"), end.get("role")) == ("s", "a s", "sOut")
    assert _connections(doc) == [("a_s", "b")]
    assert not [d for d in found if d.code == "IMP110"]


@pytest.mark.parametrize("dialect", ["eclipse", "xsi", "ea"])
def test_a_part_of_a_part_without_sysml_is_followed_when_there_is_one_way(dialect: str, tmp_path: Path) -> None:
    text, _ = _nested_model(Xmi(dialect), nested="uml")
    path = _write(tmp_path, dialect, text)
    doc, found = _import(path)
    assert doc.xpath("//p:end[@id='e1']/@path", namespaces=NS) == ["a s"]
    assert _connections(doc) == [("a_s", "b")]
    _agree(path, tmp_path, found)


@pytest.mark.parametrize(("dialect", "nested", "why"), [
    ("eclipse", "uml", "is a part of a part that Component 'System' holds 2 times"),
    ("eclipse", "broken", "its path b.s is broken at Property 's', which is no part of the type of Property 'b'"),
    ("magicdraw", "broken", "its path b.s is broken at Property 's'"),
])
def test_a_nested_end_that_cannot_be_followed_refuses_its_connector(dialect: str, nested: str, why: str,
                                                                    tmp_path: Path) -> None:
    text, _ = _nested_model(Xmi(dialect), nested=nested, second=True)
    path = _write(tmp_path, dialect, text)
    doc, found = _import(path)
    assert not doc.xpath("//p:connector[@id='c1']", namespaces=NS)
    # without the connector, the bind step connects by interfaces (README "Composites")
    assert doc.xpath("//p:binding/@connections-from", namespaces=NS) == ["interfaces"]
    refused = [d for d in found if d.code == "IMP110"]
    assert [d.xmi_id for d in refused] == ["c1"] and why in refused[0].message
    assert refused[0].line is not None
    _agree(path, tmp_path, found)


# ------------------------------- class 8: EA exposed interfaces, roles
def _ea_exposed_model(x: Xmi) -> str:
    return x.document(
        x.interface("EAID_IF", "IImage")
        + '<packagedElement xmi:type="uml:Class" xmi:id="EAID_CL" name="NotAnInterface"/>'
        + x.component("EAID_A", "CompA",
                      '<required xmi:id="EAID_REQ0" name="Required B"/>'
                      '<provided xmi:id="EAID_PROVC" xmi:idref="EAID_IF" name="IImage"/>'
                      '<ownedAttribute xmi:type="uml:Port" xmi:id="EAID_PA" name="PortA" aggregation="composite">'
                      '<provided xmi:id="EAID_PUB" name="Public A"/>'
                      '<provided xmi:type="uml:Interface" xmi:id="EAID_PROVP" xmi:idref="EAID_IF" name="IImage"/>'
                      '<required xmi:type="uml:Interface" xmi:id="EAID_REQX" name="Unclassified"/>'
                      '<required xmi:id="EAID_REQC" xmi:idref="EAID_CL" name="NotAnInterface"/>'
                      '</ownedAttribute>')
        + '<packagedElement xmi:type="uml:Collaboration" xmi:id="EAID_COL" name="Scenario">'
          '<ownedAttribute xmi:type="uml:Property" xmi:id="EAID_ROLE" name="driver"><type xmi:idref="EAID_A"/>'
          '</ownedAttribute></packagedElement>',
        '<other:Custom xmi:id="EAID_ST1" base_Element="EAID_PUB"/>')


def test_ea_exposed_interfaces_reach_the_pim_or_are_named(tmp_path: Path) -> None:
    path = _write(tmp_path, "ea", _ea_exposed_model(Xmi("ea")))
    doc, found = _import(path)
    # classified by an interface: the classifier's provides, the port's provided (via names it)
    assert doc.xpath("//p:component/p:provides/@id", namespaces=NS) == ["EAID_PROVC"]
    assert doc.xpath("//p:port[@id='EAID_PA']/p:provided/@via", namespaces=NS) == ["EAID_PROVP"]
    # an unclassified one, even with xmi:type uml:Interface, is no interface of the model
    assert doc.xpath("//p:interface/@name", namespaces=NS) == ["IImage"]
    assert {d.xmi_id for d in found if d.code == "IMP119"} == {"EAID_REQ0", "EAID_PUB", "EAID_REQX", "EAID_REQC"}
    why = {d.xmi_id: d.message for d in found if d.code == "IMP119"}
    assert "names no interface" in why["EAID_PUB"] and "names Class 'NotAnInterface'" in why["EAID_REQC"]
    # the stereotype on an exposed interface, and a Collaboration's role
    assert ("IMP115", "EAID_ST1") in _codes(found)
    assert ("IMP116", "EAID_ROLE") in _codes(found)
    assert "Collaboration only as the protocol" in next(d.message for d in found if d.xmi_id == "EAID_ROLE")
    _agree(path, tmp_path, found)


@pytest.mark.parametrize("dialect", ["eclipse", "magicdraw"])
def test_collaboration_roles_are_named(dialect: str, tmp_path: Path) -> None:
    x = Xmi(dialect)
    text = x.document(x.interface("ifI", "Img") + x.component("cam", "Camera", x.port("camOut", "out", "ifI"))
                      + f'<packagedElement {x.t("Collaboration")} xmi:id="col" name="Scenario">'
                      + x.typed("ownedAttribute", "role1", "camera", "cam") + "</packagedElement>")
    path = _write(tmp_path, dialect, text)
    _, found = _import(path)
    assert ("IMP116", "role1") in _codes(found)
    _agree(path, tmp_path, found)


# ------------------------------ class 9: dangling ends of partial exports
@pytest.mark.parametrize("dialect", ["eclipse", "xsi", "ea"])
def test_a_dangling_end_of_a_relationship_robomda_would_not_import_is_a_warning(dialect: str,
                                                                                 tmp_path: Path) -> None:
    x = Xmi(dialect)
    pk = "EAPK_A" if dialect == "ea" else "pkA"
    body = (x.interface("ifI", "Img") + x.component("cam", "Camera", x.port("camOut", "out", "ifI"))
            + f'<packagedElement {x.t("Package")} xmi:id="{pk}" name="pa">'
              f'<ownedComment xmi:id="cm1" body="note"/></packagedElement>'
            + f'<packagedElement {x.t("Realization")} xmi:id="rl" client="{pk}" supplier="pkGone"/>'
            + f'<packagedElement {x.t("Usage")} xmi:id="us" client="cm1" supplier="ifGone"/>'
            + f'<packagedElement {x.t("Dependency")} xmi:id="dp" client="cm1" supplier="cmGone"/>')
    path = _write(tmp_path, dialect, x.document(body))
    _, found = _import(path)
    why = {d.xmi_id: d.message for d in found if d.code == "IMP112"}
    assert set(why) == {"rl", "us"}
    assert "supplier: 'pkGone' (not in the file)" in why["rl"] and "'ifGone' (not in the file)" in why["us"]
    assert ("IMP111", "dp") in _codes(found)
    _agree(path, tmp_path, found)


@pytest.mark.parametrize("dialect", ["eclipse", "xsi", "ea"])
def test_a_dangling_reference_robomda_needs_stays_an_error(dialect: str, tmp_path: Path) -> None:
    x = Xmi(dialect)
    body = (x.interface("ifI", "Img") + x.component("cam", "Camera", x.port("camOut", "out", "ifGone"))
            + f'<packagedElement {x.t("Usage")} xmi:id="us" client="cam" supplier="ifAlsoGone"/>')
    path = _write(tmp_path, dialect, x.document(body))
    with pytest.raises(RobomdaError) as info:
        import_model(path)
    assert [(d.code, d.xmi_id) for d in info.value.diagnostics if d.severity == "error"] == \
        [("IMP011", "camOut"), ("IMP015", "us")]
    assert main(["check", str(path)]) == 1
    assert main(["generate", str(path), "-o", str(tmp_path / "out")]) == 1
    assert not (tmp_path / "out").exists()
