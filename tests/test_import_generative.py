"""Property-based test of the import and bind stages on random UML 2 models (issue 11).

hypothesis builds random models over the metaclasses robomda reads
(packages, interfaces, classes, data types, signals, collaborations,
behaviours, actors, components with ports, parts and connectors,
dependencies of every kind, nodes, devices, execution environments,
artifacts, deployments, manifestations, communication paths, stereotype
applications), written in the dialects of Eclipse UML2 / Papyrus,
Enterprise Architect, MagicDraw and GenMyModel (xsi:type), with optional
attributes left out, types
missing or of unexpected metaclasses, references to ids that are not in the
file, and elements in unusual owners (components in nodes, Visual Paradigm
style deployment-components, connectors under the model), and the shapes of
real exports of issue 30 (template signatures, nested connector ends with a
SysML propertyPath, relationships with several clients, EA exposed
interfaces without an interface, Collaboration roles, a partial export's
dangling relationship). For each model:

- the import never ends with INTERNAL: exit code 0, 1 or 2 only;
- every code it prints is listed in docs/errors.md;
- when it succeeds, nothing is dropped in silence (tests/xmi_invariant.py);
- ``robomda check`` (import, bind, rules, PSM of the deployed targets) ends
  with 0, 1 or 2, never INTERNAL.

Some models reference a second model file (types of attributes and ports in
``lib.uml``, which references the model back): beside the model, missing
(IMP041), or outside the model's folder (IMP040).

CI runs a bounded number of examples (ROBOMDA_HYPOTHESIS_EXAMPLES, default
100, derandomized: the same models each run, ~10 s); run more by hand with e.g.
``ROBOMDA_HYPOTHESIS_EXAMPLES=2000 ROBOMDA_HYPOTHESIS_RANDOM=1 pytest
tests/test_import_generative.py``.
"""

from __future__ import annotations

import os
import re
import tempfile
from pathlib import Path
from xml.sax.saxutils import quoteattr

import pytest

hypothesis = pytest.importorskip("hypothesis", reason="hypothesis not installed (pip install -e '.[test]')")
from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from robomda.api import check  # noqa: E402
from robomda.diagnostics import RobomdaError  # noqa: E402
from xmi_invariant import dropped, import_run  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
DOCUMENTED = set(re.findall(r"^\| ([A-Z]{2,5}[0-9]{3}|NOTE|SCHEMA|INTERNAL|USAGE) \|",
                            (ROOT / "docs" / "errors.md").read_text(encoding="utf-8"), re.M))
EXAMPLES = int(os.environ.get("ROBOMDA_HYPOTHESIS_EXAMPLES", "100"))
RANDOM = os.environ.get("ROBOMDA_HYPOTHESIS_RANDOM", "") not in ("", "0")

DIALECTS = {
    "eclipse": dict(xmi="http://www.omg.org/spec/XMI/20131001", uml="http://www.eclipse.org/uml2/5.0.0/UML",
                    version="20131001", exporter=None),
    "ea": dict(xmi="http://schema.omg.org/spec/XMI/2.1", uml="http://schema.omg.org/spec/UML/2.1",
               version="2.1", exporter="Enterprise Architect"),
    "magicdraw": dict(xmi="http://www.omg.org/spec/XMI/20131001", uml="http://www.omg.org/spec/UML/20131001",
                      version="20131001", exporter="MagicDraw Clean XMI Exporter"),
    # GenMyModel-style: the Eclipse namespaces, every xmi:type written as xsi:type (issue 30)
    "xsi": dict(xmi="http://www.omg.org/spec/XMI/20131001", uml="http://www.eclipse.org/uml2/5.0.0/UML",
                version="20131001", exporter=None),
}
LIBRARY = {
    "eclipse": 'href="pathmap://UML_LIBRARIES/UMLPrimitiveTypes.library.uml#{}"',
    "magicdraw": 'href="http://www.omg.org/spec/UML/20131001/PrimitiveTypes.xmi#{}"',
    "xsi": 'href="pathmap://UML_LIBRARIES/UMLPrimitiveTypes.library.uml#{}"',
}
PRIMITIVES = ["Integer", "Real", "Boolean", "String"]
EA_BUILTINS = ["EAJava_int", "EAJava_double", "EAJava_boolean", "EAnone_float"]
NAMES = ["", "a", "Camera", "ctrl_1", "x y", "int", "Node", "ÄÖ", "very_long_name_" * 3]
MIDDLEWARES = ["OROCOS", "ROS", "ROS2", "rttVision", "", "Orocos RTT"]
# the ids of the second model file (lib.uml), and one it does not have
LIB_IDS = ["_libI", "_libC", "_libK", "_libNowhere"]
LIB = ('<?xml version="1.0" encoding="UTF-8"?>\n'
       '<uml:Model xmi:version="20131001" xmlns:xmi="http://www.omg.org/spec/XMI/20131001" '
       'xmlns:uml="http://www.eclipse.org/uml2/5.0.0/UML" xmi:id="_libM" name="lib">'
       '<packagedElement xmi:type="uml:Interface" xmi:id="_libI" name="ILib"><ownedAttribute xmi:id="_libA" name="v">'
       '<type xmi:type="uml:PrimitiveType" href="pathmap://UML_LIBRARIES/UMLPrimitiveTypes.library.uml#Real"/>'
       '</ownedAttribute></packagedElement>'
       '<packagedElement xmi:type="uml:Class" xmi:id="_libC" name="LibClass"/>'
       '<packagedElement xmi:type="uml:Component" xmi:id="_libK" name="LibComponent">'
       '<ownedAttribute xmi:type="uml:Port" xmi:id="_libP" name="p" type="_libI" aggregation="composite"/>'
       '</packagedElement>'
       # a reference back into the model file: files that reference each other
       '<packagedElement xmi:type="uml:Dependency" xmi:id="_libD" client="_libC">'
       '<supplier xmi:type="uml:Class" href="model.xmi#_nothere"/></packagedElement>'
       '</uml:Model>\n')


class Model:
    """One random model, written in one dialect as it is drawn."""

    def __init__(self, draw, dialect: str) -> None:
        self.draw = draw
        self.d = dialect
        # a sound model (valid names, one datum per interface, a platform)
        # reaches bind, the rules and the PSM; the others stress the import
        self.sound = draw(st.booleans())
        self.n = 0
        self.ids: dict[str, list[str]] = {}  # metaclass -> ids
        self.stereotypes: list[str] = []
        self.stray: list[str] = []  # elements written under the model root
        self.composites: list[tuple[str, list[str]]] = []  # (composite id, its part ids)
        # a second model file the model references (models split over
        # several files): beside it, missing, or outside the sandbox
        self.lib = draw(st.sampled_from(["none", "present", "missing", "outside"]))

    def new_id(self, meta: str) -> str:
        self.n += 1
        xid = f"EAID_{self.n:04d}" if self.d == "ea" else f"_g{self.n}"
        self.ids.setdefault(meta, []).append(xid)
        return xid

    def maybe(self, p: float = 0.5) -> bool:
        return self.draw(st.floats(0, 1)) < p

    def pick(self, seq):
        return self.draw(st.sampled_from(list(seq)))

    def some(self, meta: str) -> str | None:
        return self.pick(self.ids[meta]) if self.ids.get(meta) else None

    def name(self) -> str:
        if self.sound:
            return f' name="n{self.n}"'
        return "" if self.maybe(0.1) else f' name={quoteattr(self.pick(NAMES) or "n" + str(self.n))}'

    def tp(self, meta: str) -> str:
        """xmi:type, left out where the dialect may (Eclipse UML2, default type of the feature)."""
        if self.d == "eclipse" and meta in ("Property", "Operation", "Parameter") and self.maybe(0.7):
            return ""
        return f' xmi:type="uml:{meta}"'

    # ------------------------------------------------------ references
    def type_ref(self, choices: list[str]) -> tuple[str, str]:
        """(attribute text, child text) typing an element by one of ``choices``."""
        kind = self.pick(choices)
        if kind == "none":
            return "", ""
        if kind == "dangling":
            target = "_nowhere" + str(self.n)
        elif kind == "library":
            if self.d == "ea":
                return "", f'<type xmi:idref="{self.pick(EA_BUILTINS)}"/>'
            return "", f'<type xmi:type="uml:PrimitiveType" {LIBRARY[self.d].format(self.pick(PRIMITIVES))}/>'
        elif kind == "href":
            return "", '<type xmi:type="uml:Class" href="other.uml#_elsewhere"/>'
        elif kind == "lib":
            if self.lib == "none":
                return "", ""
            where = "../outside/lib.uml" if self.lib == "outside" else "lib.uml"
            return "", f'<type xmi:type="uml:Interface" href="{where}#{self.pick(LIB_IDS)}"/>'
        else:
            target = self.some(kind)
            if target is None:
                return "", ""
        if self.d == "ea" or self.maybe(0.2):
            return "", f'<type xmi:idref="{target}"/>'
        return f' type="{target}"', ""

    def mult(self) -> str:
        if not self.maybe(0.2):
            return ""
        up = self.pick(["1", "*", "-1", "3"])
        return (f'<lowerValue xmi:type="uml:LiteralInteger" xmi:id="{self.new_id("Value")}" value="0"/>'
                f'<upperValue xmi:type="uml:LiteralUnlimitedNatural" xmi:id="{self.new_id("Value")}" value="{up}"/>')

    # --------------------------------------------------------- features
    def attribute(self, choices: list[str], *, composite: bool = False) -> str:
        xid = self.new_id("Property")
        attr, child = self.type_ref(choices)
        agg = ' aggregation="composite"' if composite or self.maybe(0.1) else ""
        vis = f' visibility="{self.pick(["public", "protected", "private"])}"' if self.maybe() else ""
        default = ""
        if self.maybe(0.2):
            default = (f'<defaultValue xmi:type="uml:{self.pick(["LiteralInteger", "LiteralString", "LiteralReal"])}" '
                       f'xmi:id="{self.new_id("Value")}" value={quoteattr(self.pick(["1", "x", "0.5", ""]))}/>')
        return (f'<ownedAttribute{self.tp("Property")} xmi:id="{xid}"{self.name()}{vis}{agg}{attr}>'
                f'{child}{self.mult()}{default}</ownedAttribute>')

    def operation(self) -> str:
        xid = self.new_id("Operation")
        params = ""
        for _ in range(self.draw(st.integers(0, 2))):
            attr, child = self.type_ref(["library", "none", "Interface", "DataType", "Class"])
            direction = f' direction="{self.pick(["in", "out", "return", "inout"])}"' if self.maybe() else ""
            params += (f'<ownedParameter{self.tp("Parameter")} xmi:id="{self.new_id("Parameter")}"{self.name()}'
                       f'{direction}{attr}>{child}</ownedParameter>')
        return f'<ownedOperation{self.tp("Operation")} xmi:id="{xid}"{self.name()}>{params}</ownedOperation>'

    def port(self, port_types: list[str]) -> str:
        xid = self.new_id("Port")
        attr, child = self.type_ref(port_types)
        conj = f' isConjugated="{self.pick(["true", "false"])}"' if self.maybe(0.4) else ""
        exposed = ""
        if self.d == "ea" and self.maybe(0.3) and self.ids.get("Interface"):
            which = self.pick(["provided", "required"])
            exposed = f'<{which} xmi:type="uml:Interface" xmi:id="{self.new_id("Exposed")}" xmi:idref="{self.some("Interface")}"/>'
        if self.maybe(0.15) and self.ids.get("Interface"):
            dep = self.pick(["Usage", "InterfaceRealization"])
            self.stray.append(f'<packagedElement xmi:type="uml:{dep}" xmi:id="{self.new_id(dep)}" client="{xid}" '
                              f'supplier="{self.some("Interface")}"/>')
        return (f'<ownedAttribute xmi:type="uml:Port" xmi:id="{xid}"{self.name()}{conj} aggregation="composite"{attr}>'
                f'{child}{exposed}</ownedAttribute>')

    # ------------------------------------------------------ classifiers
    def interface(self) -> str:
        xid = self.new_id("Interface")
        if self.sound:
            attrs = self.attribute(["library"])
        else:
            attrs = "".join(self.attribute(["library", "none", "DataType"]) for _ in range(self.draw(st.integers(0, 2))))
        ops = "".join(self.operation() for _ in range(self.draw(st.integers(0, 1))))
        return f'<packagedElement xmi:type="uml:Interface" xmi:id="{xid}"{self.name()}>{attrs}{ops}</packagedElement>'

    def data_type(self, meta: str) -> str:
        xid = self.new_id(meta)
        attrs = "".join(self.attribute(["library", "none"]) for _ in range(self.draw(st.integers(0, 2))))
        return f'<packagedElement xmi:type="uml:{meta}" xmi:id="{xid}"{self.name()}>{attrs}</packagedElement>'

    def behaviour(self) -> str:
        meta = self.pick(["OpaqueBehavior", "Activity", "StateMachine"])
        return f'<packagedElement xmi:type="uml:{meta}" xmi:id="{self.new_id("Behavior")}"{self.name()}/>'

    def collaboration(self) -> str:
        xid = self.new_id("Collaboration")
        inner = ""
        if self.ids.get("Interface") and self.maybe(0.8):
            inner = (f'<interfaceRealization xmi:id="{self.new_id("InterfaceRealization")}" client="{xid}" '
                     f'supplier="{self.some("Interface")}" contract="{self.some("Interface")}"/>')
        if self.ids.get("Interface") and self.maybe(0.8):
            self.stray.append(f'<packagedElement xmi:type="uml:Usage" xmi:id="{self.new_id("Usage")}" '
                              f'client="{xid}" supplier="{self.some("Interface")}"/>')
        return f'<packagedElement xmi:type="uml:Collaboration" xmi:id="{xid}"{self.name()}>{inner}</packagedElement>'

    def klass(self) -> str:
        xid = self.new_id("Class")
        attrs = "".join(self.attribute(["library", "none", "Interface", "DataType", "Behavior", "Actor", "href", "lib"])
                        for _ in range(self.draw(st.integers(0, 3))))
        ops = "".join(self.operation() for _ in range(self.draw(st.integers(0, 2))))
        real = ""
        if self.ids.get("Interface") and self.maybe(0.5):
            real = (f'<interfaceRealization xmi:id="{self.new_id("InterfaceRealization")}"'
                    f'{"" if self.maybe(0.3) else f" client={quoteattr(xid)}"} supplier="{self.some("Interface")}"'
                    f' contract="{self.some("Interface")}"/>')
        if self.ids.get("Interface") and self.maybe(0.3):
            self.stray.append(f'<packagedElement xmi:type="uml:Usage" xmi:id="{self.new_id("Usage")}" client="{xid}" '
                              f'supplier="{self.some("Interface")}"/>')
        return f'<packagedElement xmi:type="uml:Class" xmi:id="{xid}"{self.name()}>{attrs}{ops}{real}</packagedElement>'

    def component(self, tag: str = "packagedElement") -> tuple[str, str]:
        xid = self.new_id("Component")
        port_types = ["Interface", "Interface", "Class", "DataType", "Signal", "Collaboration", "Actor", "Behavior",
                      "library", "none", "href", "lib"] + (["dangling"] if self.maybe(0.1) and not self.sound else [])
        ports = "".join(self.port(port_types) for _ in range(self.draw(st.integers(0, 3))))
        attrs = "".join(self.attribute(["library", "none", "Behavior", "DataType", "Actor"])
                        for _ in range(self.draw(st.integers(0, 2))))
        ops = "".join(self.operation() for _ in range(self.draw(st.integers(0, 1))))
        real = ""
        if self.ids.get("Class") and self.maybe(0.6):
            cls = self.some("Class")
            if self.d == "ea":
                self.stray.append(f'<packagedElement xmi:type="uml:Realization" xmi:id="{self.new_id("Realization")}" '
                                  f'client="{cls}" supplier="{xid}"/>')
            else:
                real = (f'<realization xmi:type="uml:ComponentRealization" xmi:id="{self.new_id("ComponentRealization")}"'
                        f' client="{xid}" supplier="{cls}" realizingClassifier="{cls}"/>')
        return xid, f'<{tag} xmi:type="uml:Component" xmi:id="{xid}"{self.name()}>{ports}{attrs}{ops}{real}</{tag}>'

    def composite(self, parts_of: list[str]) -> str:
        xid = self.new_id("Component")
        parts = []
        body = ""
        for comp in parts_of:
            pid = self.new_id("Property")
            parts.append(pid)
            typ = f'<type xmi:idref="{comp}"/>' if self.d == "ea" else ""
            attr = "" if self.d == "ea" else f' type="{comp}"'
            body += f'<ownedAttribute{self.tp("Property")} xmi:id="{pid}"{self.name()} aggregation="composite"{attr}>{typ}</ownedAttribute>'
        if self.maybe(0.2):
            body += self.attribute(["none"], composite=True)
        ports = self.ids.get("Port", [])
        for _ in range(self.draw(st.integers(0, 3))):
            kid = self.new_id("Connector")
            ends = ""
            for _ in range(self.draw(st.integers(1, 2)) if self.maybe(0.2) else 2):
                role = self.pick(ports) if ports else (self.pick(parts) if parts else xid)
                pwp = f' partWithPort="{self.pick(parts)}"' if parts and self.maybe(0.8) else ""
                ends += f'<end xmi:type="uml:ConnectorEnd" xmi:id="{self.new_id("ConnectorEnd")}" role="{role}"{pwp}/>'
            if self.maybe(0.3):  # Visual Paradigm: under the model
                self.stray.append(f'<packagedElement xmi:type="uml:Connector" xmi:id="{kid}"{self.name()}>{ends}</packagedElement>')
            else:
                body += f'<ownedConnector xmi:type="uml:Connector" xmi:id="{kid}"{self.name()}>{ends}</ownedConnector>'
        self.composites.append((xid, parts))
        if len(parts) >= 2 and self.maybe(0.4):
            dname = ' name="startAfter"' if self.maybe() else self.name()
            self.stray.append(f'<packagedElement xmi:type="uml:Dependency" xmi:id="{self.new_id("Dependency")}"{dname} '
                              f'client="{parts[0]}" supplier="{parts[1]}"/>')
        return f'<packagedElement xmi:type="uml:Component" xmi:id="{xid}"{self.name()}>{body}</packagedElement>'

    # --------------------------------------------------------- platform
    def node(self, meta: str = "Node", depth: int = 0) -> str:
        xid = self.new_id(meta)
        inner = ""
        for _ in range(self.draw(st.integers(0, 2)) if depth == 0 else 0):
            eid = self.new_id("ExecutionEnvironment")
            deps = ""
            targets = self.ids.get("Component", []) + self.ids.get("Artifact", [])
            for _ in range(self.draw(st.integers(0, 2))):
                target = self.pick(targets) if targets and (self.sound or self.maybe(0.9)) else "_gone" + str(self.n)
                if target.startswith("_gone") and not self.maybe(0.3):
                    continue
                deps += f'<deployment xmi:id="{self.new_id("Deployment")}" client="{eid}" supplier="{target}"/>'
            middleware = self.pick(MIDDLEWARES[:3] if self.sound else MIDDLEWARES)
            inner += (f'<nestedNode xmi:type="uml:ExecutionEnvironment" xmi:id="{eid}" '
                      f'name={quoteattr(middleware)}>{deps}</nestedNode>')
            if self.maybe(0.5):
                kind = "" if self.maybe() else f' kind={quoteattr(self.pick(["OROCOS", "ROS", "ROS2", "Bogus"]))}'
                self.stereotypes.append(f'<robomda:Middleware xmi:id="{self.new_id("Stereotype")}" '
                                        f'base_ExecutionEnvironment="{eid}"{kind}/>')
        if depth == 0 and self.maybe(0.3):
            inner += self.node("Device", depth + 1).replace("packagedElement", "nestedNode")
        if depth == 0 and self.maybe(0.3):  # components owned by the node
            tag = "nestedClassifier" if self.d == "ea" else self.pick(["nestedClassifier", "deployment", "packagedElement"])
            inner += self.component(tag)[1]
        if self.maybe(0.2):
            inner += self.attribute(["library", "none"])
        return f'<packagedElement xmi:type="uml:{meta}" xmi:id="{xid}"{self.name()}>{inner}</packagedElement>'

    def artifact(self) -> str:
        xid = self.new_id("Artifact")
        man = ""
        if self.ids.get("Class") and self.maybe(0.7):
            man = (f'<manifestation xmi:type="uml:Manifestation" xmi:id="{self.new_id("Manifestation")}" '
                   f'client="{xid}" supplier="{self.some("Class")}" utilizedElement="{self.some("Class")}"/>')
        fname = f' fileName={quoteattr(self.pick(["lib", "/opt/lib", "", "a b"]))}' if self.maybe() else ""
        return f'<packagedElement xmi:type="uml:Artifact" xmi:id="{xid}"{self.name()}{fname}>{man}</packagedElement>'

    def path(self) -> str:
        nodes = self.ids.get("Node", [])
        xid = self.new_id("CommunicationPath")
        ends = ""
        if self.sound and len(nodes) < 2:
            return ""
        for _ in range(2 if self.sound else self.draw(st.integers(1, 2))):
            target = self.pick(nodes) if nodes else "_none"
            ends += f'<ownedEnd xmi:type="uml:Property" xmi:id="{self.new_id("End")}" type="{target}"/>'
        return f'<packagedElement xmi:type="uml:CommunicationPath" xmi:id="{xid}"{self.name()}>{ends}</packagedElement>'

    # ---------------------------------- issue 30: shapes of real exports
    def template_class(self) -> str:
        """A class template (its parameters' placeholders are no classes), and a class bound to it."""
        xid, sig, tp, pe = (self.new_id("Class"), self.new_id("Signature"), self.new_id("TemplateParameter"),
                            self.new_id("Placeholder"))
        default = (f'<ownedDefault xmi:type="uml:Class" xmi:id="{self.new_id("Placeholder")}" name="D"/>'
                   if self.maybe() else "")
        typed = (f'<ownedAttribute xmi:id="{self.new_id("Property")}" name="item" type="{pe}"/>'
                 if self.maybe(0.7) else "")
        text = (f'<packagedElement xmi:type="uml:Class" xmi:id="{xid}"{self.name()}>'
                f'<ownedTemplateSignature xmi:type="uml:RedefinableTemplateSignature" xmi:id="{sig}" parameter="{tp}">'
                f'<ownedParameter xmi:type="uml:ClassifierTemplateParameter" xmi:id="{tp}" parameteredElement="{pe}">'
                f'<ownedParameteredElement xmi:type="uml:Class" xmi:id="{pe}" name="TemplateParameter1" '
                f'templateParameter="{tp}"/>{default}</ownedParameter></ownedTemplateSignature>{typed}</packagedElement>')
        if self.maybe():
            text += (f'<packagedElement xmi:type="uml:Class" xmi:id="{self.new_id("Class")}"{self.name()}>'
                     f'<templateBinding xmi:id="{self.new_id("Binding")}" signature="{sig}">'
                     f'<parameterSubstitution xmi:id="{self.new_id("Substitution")}" formal="{tp}">'
                     f'<ownedActual xmi:type="uml:Class" xmi:id="{self.new_id("Placeholder")}" name="A"/>'
                     f'</parameterSubstitution></templateBinding></packagedElement>')
        return text

    def nested_composite(self) -> str:
        """A composite with a part typed by a composite, and a connector to a port of a part of that part.

        The end's path is a SysML NestedConnectorEnd (propertyPath as ids or child elements; right,
        broken or dangling), or only a partWithPort that is a part of a part (UML without SysML).
        """
        inner, parts = self.composites[-1]
        ports = self.ids.get("Port", [])
        if not parts or not ports:
            return ""
        xid, outer = self.new_id("Component"), self.new_id("Property")
        twin = self.new_id("Property") if self.maybe(0.3) else None  # a second part of the same type
        body = f'<ownedAttribute xmi:id="{outer}" name="o" aggregation="composite" type="{inner}"/>'
        if twin:
            body += f'<ownedAttribute xmi:id="{twin}" name="o2" aggregation="composite" type="{inner}"/>'
        kid, e1, e2 = self.new_id("Connector"), self.new_id("ConnectorEnd"), self.new_id("ConnectorEnd")
        inner_part = self.pick(parts)
        pwp = f' partWithPort="{inner_part}"' if self.maybe(0.8) else ""
        body += (f'<ownedConnector xmi:type="uml:Connector" xmi:id="{kid}"{self.name()}>'
                 f'<end xmi:type="uml:ConnectorEnd" xmi:id="{e1}" role="{self.pick(ports)}"{pwp}/>'
                 f'<end xmi:type="uml:ConnectorEnd" xmi:id="{e2}" role="{self.pick(ports)}" partWithPort="{outer}"/>'
                 f'</ownedConnector>')
        if self.maybe(0.7):
            path = self.pick([[outer, inner_part], [outer, inner_part], [inner_part, outer], [outer, "_nopath"]])
            if self.maybe():
                steps = "".join(f'<propertyPath xmi:idref="{p}"/>' for p in path)
                self.stereotypes.append(f'<sysml:NestedConnectorEnd xmi:id="{self.new_id("Stereotype")}" '
                                        f'base_ConnectorEnd="{e1}">{steps}</sysml:NestedConnectorEnd>')
            else:
                self.stereotypes.append(f'<sysml:NestedConnectorEnd xmi:id="{self.new_id("Stereotype")}" '
                                        f'base_ConnectorEnd="{e1}" propertyPath="{" ".join(path)}"/>')
        return f'<packagedElement xmi:type="uml:Component" xmi:id="{xid}"{self.name()}>{body}</packagedElement>'

    def several_clients(self) -> str:
        """A relationship with several clients and suppliers (UML Designer: client="class port component")."""
        every = [i for v in self.ids.values() for i in v]
        meta = self.pick(["InterfaceRealization", "Realization", "Usage", "ComponentRealization"])
        clients = " ".join(self.pick(every) for _ in range(self.draw(st.integers(2, 4))))
        targets = self.ids.get("Interface", []) + self.ids.get("Class", []) + every[:1]
        suppliers = " ".join(self.pick(targets) for _ in range(self.draw(st.integers(1, 2))))
        contract = f' contract="{suppliers}"' if meta == "InterfaceRealization" and self.maybe() else ""
        return (f'<packagedElement xmi:type="uml:{meta}" xmi:id="{self.new_id(meta)}" client="{clients}" '
                f'supplier="{suppliers}"{contract}/>')

    def shapes_of_real_exports(self) -> list[str]:
        """The issue-30 shapes: templates, nested ends, several clients, EA exposed interfaces, roles."""
        body = []
        if self.maybe(0.3):
            body.append(self.template_class())
        if self.composites and self.maybe(0.5):
            body.append(self.nested_composite())
        if self.ids and self.maybe(0.3):
            body.append(self.several_clients())
        if self.d == "ea" and self.ids.get("Component") and self.maybe(0.4):
            # exposed interfaces EA leaves unclassified, or classified by a class
            which = self.pick(["provided", "required"])
            idref = f' xmi:idref="{self.some("Class")}"' if self.ids.get("Class") and self.maybe() else ""
            body.append(f'<packagedElement xmi:type="uml:Component" xmi:id="{self.new_id("Component")}" name="x">'
                        f'<{which} xmi:id="{self.new_id("Exposed")}" name="e"{idref}/></packagedElement>')
        if self.ids.get("Component") and self.maybe(0.2):
            # a Collaboration as an interaction's context: its roles
            body.append(f'<packagedElement xmi:type="uml:Collaboration" xmi:id="{self.new_id("Collaboration")}" '
                        f'name="ctx"><ownedAttribute xmi:id="{self.new_id("Property")}" name="r" '
                        f'type="{self.some("Component")}"/></packagedElement>')
        if self.maybe(0.15):
            # a partial export: a Realization between packages whose supplier is not in the file
            pkg = self.new_id("Package")
            body.append(f'<packagedElement xmi:type="uml:Package" xmi:id="{pkg}" name="p"/>'
                        f'<packagedElement xmi:type="uml:Realization" xmi:id="{self.new_id("Realization")}" '
                        f'client="{pkg}" supplier="_notInThisFile"/>')
        return body

    # ------------------------------------------------------------ model
    def write(self) -> str:
        body = []
        body += [self.interface() for _ in range(self.draw(st.integers(0, 3)))]
        if self.maybe(0.5):
            body.append(self.data_type("DataType"))
        if self.maybe(0.3):
            body.append(self.data_type("Signal"))
        if self.maybe(0.3):
            body.append(f'<packagedElement xmi:type="uml:Actor" xmi:id="{self.new_id("Actor")}" name="Operator"/>')
        if self.maybe(0.4):
            body.append(self.behaviour())
        if self.maybe(0.3):
            body.append(self.collaboration())
        body += [self.klass() for _ in range(self.draw(st.integers(0, 2)))]
        comps = [self.component() for _ in range(self.draw(st.integers(0, 3)))]
        body += [c[1] for c in comps]
        if comps and self.maybe(0.6):
            body.append(self.composite([c[0] for c in comps]))
        if self.maybe(0.2) and self.ids:
            dep = self.pick(["Dependency", "Abstraction", "Usage", "Realization"])
            every = [i for v in self.ids.values() for i in v]
            body.append(f'<packagedElement xmi:type="uml:{dep}" xmi:id="{self.new_id(dep)}" '
                        f'client="{self.pick(every)}" supplier="{self.pick(every)}"/>')
        body += [self.artifact() for _ in range(self.draw(st.integers(0, 1)))]
        body += self.shapes_of_real_exports()
        body += [self.node() for _ in range(self.draw(st.integers(1 if self.sound else 0, 2)))]
        if self.maybe(0.3):
            body.append(self.path())
        if self.maybe(0.3) and self.ids:
            every = [i for v in self.ids.values() for i in v]
            sid = "" if self.d == "ea" and self.maybe() else f' xmi:id="{self.new_id("Stereotype")}"'
            self.stereotypes.append(f'<other:Thing{sid} base_Element="{self.pick(every + ["_absent"])}"/>')
        if self.ids.get("Component") and self.maybe(0.3):
            period = self.pick(["0.01", "0"] if self.sound else ["0.01", "0", "x", "-1"])
            self.stereotypes.append(f'<robomda:Activity xmi:id="{self.new_id("Stereotype")}" '
                                    f'base_Component="{self.pick(self.ids["Component"])}" period="{period}"/>')
        content = "".join(body) + "".join(self.stray)
        if self.maybe(0.2):  # one package level
            content = f'<packagedElement xmi:type="uml:Package" xmi:id="{self.new_id("Package")}" name="pkg">{content}</packagedElement>'
        ns = DIALECTS[self.d]
        if self.d == "ea":
            model = (f'<uml:Model xmi:type="uml:Model" name="EA_Model" visibility="public">'
                     f'<packagedElement xmi:type="uml:Package" xmi:id="EAPK_ROOT" name="gen">{content}</packagedElement>'
                     f'</uml:Model>')
        else:
            model = f'<uml:Model xmi:type="uml:Model" xmi:id="_root" name="gen">{content}</uml:Model>'
        doc = f'<xmi:Documentation exporter="{ns["exporter"]}"/>' if ns["exporter"] else ""
        text = (f'<?xml version="1.0" encoding="UTF-8"?>\n<xmi:XMI xmi:version="{ns["version"]}" '
                f'xmlns:xmi="{ns["xmi"]}" xmlns:uml="{ns["uml"]}" '
                f'xmlns:robomda="http://robomda.org/profile/robomda/1" xmlns:other="http://example.org/other" '
                f'xmlns:sysml="http://www.omg.org/spec/SysML/20181001/SysML">'
                f'{doc}{model}{"".join(self.stereotypes)}</xmi:XMI>\n')
        if self.d == "xsi":  # GenMyModel writes xsi:type where the others write xmi:type
            text = text.replace(' xmi:type="', ' xsi:type="').replace(
                "<xmi:XMI ", '<xmi:XMI xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" ', 1)
        return text


@st.composite
def models(draw) -> tuple[str, str, str]:
    dialect = draw(st.sampled_from(sorted(DIALECTS)))
    model = Model(draw, dialect)
    return dialect, model.write(), model.lib


@settings(max_examples=EXAMPLES, derandomize=not RANDOM, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(models())
def test_random_models_never_crash_and_drop_nothing_in_silence(model: tuple[str, str, str]) -> None:
    dialect, text, lib = model
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "m" / ("model.xmi" if dialect not in ("eclipse", "xsi") else "model.uml")
        path.parent.mkdir()
        path.write_text(text, encoding="utf-8")
        if lib in ("present", "outside"):
            where = path.parent / "lib.uml" if lib == "present" else Path(tmp) / "outside" / "lib.uml"
            where.parent.mkdir(exist_ok=True)
            where.write_text(LIB, encoding="utf-8")
        code, pim, messages = import_run(path)
        assert code in (0, 1, 2), f"{dialect}:\n" + "\n".join(messages) + "\n" + text
        codes = {m.split(":", 1)[0] for m in messages}
        assert codes <= DOCUMENTED, f"undocumented codes {codes - DOCUMENTED}:\n" + text
        if code == 0:
            lost = dropped(path, pim, messages)
            assert not lost, f"{dialect}: dropped in silence: {lost}\n{text}"
        try:
            done = check(path)
        except RobomdaError as exc:
            assert exc.exit_code in (1, 2), "\n".join(d.format() for d in exc.diagnostics) + "\n" + text
        else:
            assert done.exit_code in (0, 1), "\n".join(d.format() for d in done.diagnostics) + "\n" + text
            assert not [d for d in done.diagnostics if d.code in ("INTERNAL", "SCHEMA")], text


# ============================================ several files sharing ids
# issue 30, class 3: EMF ids are unique within a file only ("file#id" is the
# identity), so two files of one model may use the same xmi:id. A system
# model and two component files draw their ids from one small pool: they
# share ids with each other and with the model, and references inside each
# file (a port's type, a realization, a comment) and across files (parts,
# connector ends: hrefs) must reach the right file's element. Sometimes one
# file repeats an id itself: that is still IMP004. Self-contained: its own
# builder and test, its own (smaller) example count.
SHARED_POOL = [f"_s{i}" for i in range(7)]
SHARED_EXAMPLES = max(1, EXAMPLES // 4)


def _shared_component_file(ns: dict, name: str, ids: list[str], dup: bool) -> str:
    """Component file ``name``.uml: interface I<name>, class Cls<name> realizing component Comp<name>, whose
    port is typed by I<name>, all by ids of this file (``ids``: distinct unless ``dup``)."""
    m, i, a, c, k, p, r = ids
    if dup:  # the interface's attribute repeats the class's id
        a = c
    return (f'<?xml version="1.0" encoding="UTF-8"?>\n<xmi:XMI xmi:version="{ns["version"]}" xmlns:xmi="{ns["xmi"]}" '
            f'xmlns:uml="{ns["uml"]}"><uml:Model xmi:type="uml:Model" xmi:id="{m}" name="{name}_def">'
            f'<packagedElement xmi:type="uml:Interface" xmi:id="{i}" name="I{name}">'
            f'<ownedAttribute xmi:type="uml:Property" xmi:id="{a}" name="v{name}"><type xmi:type="uml:PrimitiveType" '
            f'href="pathmap://UML_LIBRARIES/UMLPrimitiveTypes.library.uml#Real"/></ownedAttribute></packagedElement>'
            f'<packagedElement xmi:type="uml:Class" xmi:id="{c}" name="Cls{name}"/>'
            f'<packagedElement xmi:type="uml:Component" xmi:id="{k}" name="Comp{name}">'
            f'<ownedAttribute xmi:type="uml:Port" xmi:id="{p}" name="port{name}" type="{i}" aggregation="composite"/>'
            f'<realization xmi:type="uml:ComponentRealization" xmi:id="{r}" client="{k}" supplier="{c}" '
            f'realizingClassifier="{c}"/>'
            f'<ownedComment xmi:type="uml:Comment" xmi:id="{r}c" annotatedElement="{k}" body="about Comp{name}"/>'
            f'</packagedElement></uml:Model></xmi:XMI>\n')


@st.composite
def shared_id_models(draw) -> tuple[dict[str, str], dict[str, list[str]], str | None]:
    """(file name -> text, file -> its ids, the file that repeats an id or None)."""
    ns = DIALECTS[draw(st.sampled_from(["eclipse", "magicdraw"]))]
    ids = {f: list(draw(st.permutations(SHARED_POOL))) for f in ("model.uml", "A.uml", "B.uml")}
    dup = draw(st.sampled_from([None, None, None, "A.uml"]))
    files = {f"{n}.uml": _shared_component_file(ns, n, ids[f"{n}.uml"], dup == f"{n}.uml") for n in ("A", "B")}
    m, sysk, pa, pb, con, ea, eb = ids["model.uml"]
    ka, kb = ids["A.uml"][4], ids["B.uml"][4]
    porta, portb = ids["A.uml"][5], ids["B.uml"][5]
    files["model.uml"] = (
        f'<?xml version="1.0" encoding="UTF-8"?>\n<xmi:XMI xmi:version="{ns["version"]}" xmlns:xmi="{ns["xmi"]}" '
        f'xmlns:uml="{ns["uml"]}"><uml:Model xmi:type="uml:Model" xmi:id="{m}" name="system">'
        f'<packagedElement xmi:type="uml:Component" xmi:id="{sysk}" name="System">'
        f'<ownedAttribute xmi:type="uml:Property" xmi:id="{pa}" name="a" aggregation="composite">'
        f'<type xmi:type="uml:Component" href="A.uml#{ka}"/></ownedAttribute>'
        f'<ownedAttribute xmi:type="uml:Property" xmi:id="{pb}" name="b" aggregation="composite">'
        f'<type xmi:type="uml:Component" href="B.uml#{kb}"/></ownedAttribute>'
        f'<ownedConnector xmi:type="uml:Connector" xmi:id="{con}" name="link">'
        f'<end xmi:type="uml:ConnectorEnd" xmi:id="{ea}" partWithPort="{pa}"><role xmi:type="uml:Port" href="A.uml#{porta}"/></end>'
        f'<end xmi:type="uml:ConnectorEnd" xmi:id="{eb}" partWithPort="{pb}"><role xmi:type="uml:Port" href="B.uml#{portb}"/></end>'
        f'</ownedConnector></packagedElement></uml:Model></xmi:XMI>\n')
    return files, ids, dup


@settings(max_examples=SHARED_EXAMPLES, derandomize=not RANDOM, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(shared_id_models())
def test_files_that_share_ids_resolve_each_reference_in_its_own_file(model) -> None:
    from lxml import etree

    files, ids, dup = model
    pim_ns = "{urn:robomda:pim:1}"
    with tempfile.TemporaryDirectory() as tmp:
        for name, text in files.items():
            (Path(tmp) / name).write_text(text, encoding="utf-8")
        path = Path(tmp) / "model.uml"
        code, pim_text, messages = import_run(path)
        codes = {m.split(":", 1)[0] for m in messages}
        assert codes <= DOCUMENTED and "INTERNAL" not in codes, messages
        if dup:
            assert code == 1 and codes == {"IMP004"}, messages
            assert any(f"A.uml#{ids['A.uml'][3]}" in m or ids["A.uml"][3] in m for m in messages), messages
            return
        assert code == 0, "\n".join(messages) + "\n" + "\n".join(files.values())
        assert not dropped(path, pim_text, messages), messages
        assert import_run(path)[1] == pim_text  # deterministic
        pim = etree.fromstring(pim_text.encode("utf-8"))
        all_ids = [e.get("id") for e in pim.iter() if e.get("id")]
        assert len(all_ids) == len(set(all_ids)), all_ids
        by_id = {e.get("id"): e for e in pim.iter() if e.get("id")}
        parts = {p.get("name"): by_id[p.get("type")].get("name") for p in pim.iter(f"{pim_ns}part")}
        assert parts == {"a": "CompA", "b": "CompB"}
        for name in ("A", "B"):
            comp = next(c for c in pim.iter(f"{pim_ns}component") if c.get("name") == f"Comp{name}")
            port = comp.find(f"{pim_ns}port")
            assert port.get("type-name") == f"I{name}" and by_id[port.get("type")].get("name") == f"I{name}"
            assert f"about Comp{name}" in etree.tostring(comp, encoding="unicode")
            assert [by_id[r.get("classifier")].get("name") for r in comp.iter(f"{pim_ns}realization")] == [f"Cls{name}"]
        ends = {e.get("role") for e in pim.iter(f"{pim_ns}end")}
        assert {by_id[r].get("name") for r in ends} == {"portA", "portB"}

