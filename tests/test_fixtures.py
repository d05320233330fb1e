"""Checks of the case-study fixtures (fixtures/cases/*) and of the robomda profile.

- every fixture XMI file and the profile are well-formed XML;
- the Papyrus (model.xmi) and Enterprise Architect (model.ea.xmi) versions of a
  case describe the same model: same classes (attributes with types, defaults
  and visibilities; operations with parameters), interfaces, components (ports,
  provided / required interfaces, realizing class), composite structure,
  platform and stereotype applications (tag values compared after applying the
  profile's defaults, which Eclipse UML2 does not serialize);
- the stereotype applications name stereotypes and tags of profiles/robomda.profile.uml,
  and the Papyrus profile application resolves into that file;
- each atomic-code library matches its UML classes (C++ declarations), builds
  with the real cmake + make (-Wall -Wextra -Werror), and a small C++ program
  linked against it runs its lifecycle and checks the values it computes.

Run: cd /work/main && python -m pytest tests/test_fixtures.py -q
"""
from __future__ import annotations

import re
import shutil
import subprocess
import textwrap
from pathlib import Path

import pytest
from lxml import etree

ROOT = Path(__file__).resolve().parents[1]
CASES_DIR = ROOT / "fixtures" / "cases"
PROFILE = ROOT / "profiles" / "robomda.profile.uml"
CASES = ["headlamp", "meka"]

XMI_NS = {"papyrus": "http://www.omg.org/spec/XMI/20131001",
          "ea": "http://schema.omg.org/spec/XMI/2.1"}
UML_NS = {"papyrus": "http://www.eclipse.org/uml2/5.0.0/UML",
          "ea": "http://schema.omg.org/spec/UML/2.1"}
ROBOMDA_NS = "http://robomda.org/profile/robomda/1"
ECORE_NS = "http://www.eclipse.org/emf/2002/Ecore"
PROFILE_UML_NS = "http://www.eclipse.org/uml2/5.0.0/UML"

# primitive types of both dialects -> C++ type (docs: Integer->int, Real->double ...)
PRIMITIVE = {"Integer": "int", "Real": "double", "Boolean": "bool", "String": "std::string",
             "EAnone_int": "int", "EAnone_double": "double", "EAnone_bool": "bool",
             "EAnone_string": "std::string", "EAnone_void": "void"}
# Eclipse UML2 leaves a literal's value out when it is the type's zero value
ZERO_DEFAULT = {"uml:LiteralInteger": "0", "uml:LiteralReal": "0", "uml:LiteralBoolean": "false",
                "uml:LiteralString": ""}
IMPLIED_TYPE = {"ownedOperation": "uml:Operation", "ownedParameter": "uml:Parameter",
                "interfaceRealization": "uml:InterfaceRealization"}
LIBRARY_TARGETS = {"headlamp": "headlamp_atomic", "meka": "meka_atomic"}


def model_files(case: str) -> dict[str, Path]:
    return {"papyrus": CASES_DIR / case / "model.xmi", "ea": CASES_DIR / case / "model.ea.xmi"}


def all_xml_files() -> list[Path]:
    return [PROFILE] + [f for c in CASES for f in model_files(c).values()]


# ------------------------------------------------------------------ profile
def load_profile() -> dict:
    """Stereotypes of the profile: {name: {"metas": [...], "tags": {tag: default or None}}}."""
    doc = etree.parse(str(PROFILE))
    xt = "{%s}type" % XMI_NS["papyrus"]
    epkg = doc.find(".//contents")
    enums = {e.get("{%s}id" % XMI_NS["papyrus"]): [lit.get("name") for lit in e.findall("eLiterals")]
             for e in epkg.findall("eClassifiers") if e.get(xt) == "ecore:EEnum"}
    out = {}
    for ec in epkg.findall("eClassifiers"):
        if ec.get(xt) != "ecore:EClass":
            continue
        metas, tags = [], {}
        for f in ec.findall("eStructuralFeatures"):
            name = f.get("name")
            if name.startswith("base_"):
                metas.append(name[5:])
                continue
            default = f.get("defaultValueLiteral")
            if default is None and f.get("eType") in enums:
                default = enums[f.get("eType")][0]   # EMF: first literal
            tags[name] = default
        out[ec.get("name")] = {"metas": metas, "tags": tags}
    return out


# ------------------------------------------------------------- XMI reader
class Model:
    """A tool-neutral summary of one fixture XMI file (just enough to compare dialects)."""

    def __init__(self, path: Path, dialect: str):
        self.dialect = dialect
        self.doc = etree.parse(str(path))
        self.XMI = XMI_NS[dialect]
        self.byid = {}
        for el in self.doc.iter():
            if isinstance(el.tag, str) and el.get(self.a("id")):
                self.byid[el.get(self.a("id"))] = el
        root = self.doc.getroot()
        # the UML content; EA's xmi:Extension repeats element types and names (ignored)
        self.uml = root if etree.QName(root).localname == "Model" else root.find("{%s}Model" % UML_NS[dialect])

    def a(self, name: str) -> str:
        return "{%s}%s" % (self.XMI, name)

    def typ(self, el) -> str | None:
        """xmi:type; EA leaves it out on some elements whose role implies it."""
        return el.get(self.a("type")) or IMPLIED_TYPE.get(el.tag)

    def elems(self, xmi_type: str):
        return [el for el in self.uml.iter() if isinstance(el.tag, str) and self.typ(el) == xmi_type]

    def ref(self, el, attr: str):
        """An id reference held in an attribute or in a child with xmi:idref."""
        if el.get(attr):
            return el.get(attr)
        child = el.find(attr)
        if child is not None:
            return child.get(self.a("idref"))
        return None

    def name_of(self, ident: str | None) -> str | None:
        return None if ident is None else self.byid[ident].get("name")

    def prim(self, el) -> str:
        """C++ type of a typed element (attribute / parameter)."""
        if el.get("type"):
            t = el.get("type")
            return PRIMITIVE.get(t) or self.name_of(t)
        t = el.find("type")
        if t is None:
            return "void"
        if t.get("href"):
            return PRIMITIVE[t.get("href").split("#")[1]]
        idref = t.get(self.a("idref"))
        return PRIMITIVE.get(idref) or self.name_of(idref)

    def default(self, el) -> str | None:
        d = el.find("defaultValue")
        if d is None:
            return None
        if d.get("value") is not None:
            return d.get("value")
        return ZERO_DEFAULT[self.typ(d)]

    # --------------------------------------------------------- summaries
    def classes(self) -> dict:
        out = {}
        for c in self.elems("uml:Class"):
            attrs = [(p.get("name"), self.prim(p), self.default(p), p.get("visibility", "public"))
                     for p in c.findall("ownedAttribute")]
            ops = []
            for o in c.findall("ownedOperation"):
                params, ret = [], "void"
                for p in o.findall("ownedParameter"):
                    if p.get("direction") == "return":
                        ret = self.prim(p)
                    else:
                        params.append((p.get("name"), self.prim(p), p.get("direction", "in")))
                ops.append((o.get("name"), o.get("visibility", "public"),
                            o.get("isQuery", "false"), tuple(params), ret))
            out[c.get("name")] = {"attrs": attrs, "ops": ops}
        return out

    def interfaces(self) -> dict:
        return {i.get("name"): [(p.get("name"), self.prim(p)) for p in i.findall("ownedAttribute")]
                for i in self.elems("uml:Interface")}

    def realizing_class(self, comp) -> str | None:
        cid = comp.get(self.a("id"))
        for r in comp.findall("realization"):              # UML2: ComponentRealization
            return self.name_of(r.get("realizingClassifier"))
        for r in self.elems("uml:Realization"):            # EA: Realization class -> component
            if r.get("supplier") == cid and self.typ(self.byid[r.get("client")]) == "uml:Class":
                return self.name_of(r.get("client"))
        return None

    def components(self) -> dict:
        usages = {}
        for u in self.elems("uml:Usage"):
            usages.setdefault(u.get("client"), []).append(self.name_of(u.get("supplier")))
        out = {}
        for c in self.elems("uml:Component"):
            cid = c.get(self.a("id"))
            ports = sorted((p.get("name"), self.name_of(self.ref(p, "type")))
                           for p in c.findall("ownedAttribute") if self.typ(p) == "uml:Port")
            parts = sorted((p.get("name"), self.name_of(self.ref(p, "type")))
                           for p in c.findall("ownedAttribute") if self.typ(p) == "uml:Property")
            connectors = sorted(
                (k.get("name"), tuple(sorted((self.name_of(e.get("partWithPort")), self.name_of(e.get("role")))
                                             for e in k.findall("end"))))
                for k in c.findall("ownedConnector"))
            out[c.get("name")] = {
                "ports": ports,
                "provided": sorted(self.name_of(r.get("contract")) for r in c.findall("interfaceRealization")),
                "required": sorted(usages.get(cid, [])),
                "realizedBy": self.realizing_class(c),
                "parts": parts,
                "connectors": connectors,
            }
        return out

    def platform(self) -> dict:
        out = {"nodes": {}, "devices": [], "paths": {}, "artifacts": {}}
        for n in self.elems("uml:Node"):
            out["nodes"][n.get("name")] = {
                ee.get("name"): sorted(self.name_of(d.get("deployedArtifact") or d.get("supplier"))
                                       for d in ee.findall("deployment"))
                for ee in n.findall("nestedNode")}
        out["devices"] = sorted(d.get("name") for d in self.elems("uml:Device"))
        for p in self.elems("uml:CommunicationPath"):
            out["paths"][p.get("name")] = sorted(self.name_of(self.ref(e, "type")) for e in p.findall("ownedEnd"))
        for art in self.elems("uml:Artifact"):
            out["artifacts"][art.get("name")] = {
                "fileName": art.get("fileName"),
                "manifests": sorted(self.name_of(m.get("utilizedElement") or m.get("supplier"))
                                    for m in art.findall("manifestation"))}
        return out

    def qualified(self, ident: str) -> str:
        el = self.byid[ident]
        owner = el.getparent()
        kind = self.typ(el)
        if self.typ(owner) in ("uml:Class", "uml:Component", "uml:Interface", "uml:Node"):
            return f"{kind}:{owner.get('name')}.{el.get('name')}"
        return f"{kind}:{el.get('name')}"

    def stereotypes(self, profile: dict) -> list:
        out = []
        root = self.doc.getroot()
        for app in root.iter("{%s}*" % ROBOMDA_NS):
            st = etree.QName(app).localname
            assert st in profile, f"{self.dialect}: unknown stereotype {st}"
            bases = [(k, v) for k, v in app.attrib.items() if k.startswith("base_")]
            assert len(bases) == 1, f"{self.dialect}: {st} must have one base_ reference"
            meta, target = bases[0][0][5:], bases[0][1]
            assert meta in profile[st]["metas"], f"{st} does not extend {meta}"
            assert target in self.byid, f"{self.dialect}: {st} applied to unknown id {target}"
            assert self.typ(self.byid[target]) == f"uml:{meta}", (st, meta, self.typ(self.byid[target]))
            tags = {}
            for tag, default in profile[st]["tags"].items():
                v = app.get(tag)
                if v == "":          # EA writes unset tags as empty strings
                    v = None
                tags[tag] = v if v is not None else default
            unknown = {k for k in app.attrib if not k.startswith("base_") and not k.startswith("{")} \
                - set(profile[st]["tags"])
            assert not unknown, f"{self.dialect}: {st} has unknown tags {unknown}"
            out.append((st, self.qualified(target), tuple(sorted(tags.items(), key=lambda kv: kv[0]))))
        return sorted(out, key=repr)


@pytest.fixture(scope="module")
def profile() -> dict:
    return load_profile()


@pytest.fixture(scope="module", params=CASES)
def models(request) -> tuple[str, Model, Model]:
    files = model_files(request.param)
    return request.param, Model(files["papyrus"], "papyrus"), Model(files["ea"], "ea")


# ------------------------------------------------------------ well-formed
@pytest.mark.parametrize("path", all_xml_files(), ids=lambda p: str(p.relative_to(ROOT)))
def test_well_formed(path: Path):
    doc = etree.parse(str(path))      # raises on malformed XML
    assert doc.getroot() is not None
    first = path.read_text(encoding="windows-1252" if path.name.endswith(".ea.xmi") else "utf-8")
    # honest provenance: the first node after the declaration is a comment saying what this is
    assert re.match(r"<\?xml[^>]*\?>\s*<!--\s*robomda", first), path


@pytest.mark.parametrize("case", CASES)
def test_dialect_markers(case: str):
    pap, ea = (etree.parse(str(f)).getroot() for f in model_files(case).values())
    uml = pap if etree.QName(pap).localname == "Model" else pap.find("{%s}Model" % UML_NS["papyrus"])
    assert uml is not None and uml.nsmap["uml"] == UML_NS["papyrus"]
    assert etree.QName(ea).namespace == XMI_NS["ea"] and ea.get("{%s}version" % XMI_NS["ea"]) == "2.1"
    doc = ea.find("{%s}Documentation" % XMI_NS["ea"])
    assert doc.get("exporter") == "Enterprise Architect"
    ea_model = ea.find("{%s}Model" % UML_NS["ea"])
    assert ea_model.get("name") == "EA_Model"
    roots = ea_model.findall("packagedElement")
    assert [r.get("name") for r in roots] == [uml.get("name")] == [case]
    assert ea.find("{%s}Extension" % XMI_NS["ea"]).get("extender") == "Enterprise Architect"


REF_ATTRS = {"type", "client", "supplier", "contract", "realizingClassifier", "partWithPort", "role",
             "deployedArtifact", "utilizedElement", "memberEnd", "association", "annotatedElement",
             "metaclassReference", "references", "eType", "instance", "general"}


@pytest.mark.parametrize("path", all_xml_files(), ids=lambda p: str(p.relative_to(ROOT)))
def test_no_dangling_references(path: Path):
    """Every id reference (attribute, xmi:idref, base_* of a stereotype application) resolves."""
    doc = etree.parse(str(path))
    xmi = XMI_NS["ea"] if path.name.endswith(".ea.xmi") else XMI_NS["papyrus"]
    ids = {el.get("{%s}id" % xmi) for el in doc.iter() if isinstance(el.tag, str)} - {None}
    ext = doc.getroot().find("{%s}Extension" % xmi)
    checked = 0
    for el in doc.iter():
        if not isinstance(el.tag, str) or (ext is not None and (el is ext or ext in el.iterancestors())):
            continue
        for k, v in el.attrib.items():
            local = etree.QName(k).localname
            if k == "{%s}idref" % xmi or (local in REF_ATTRS or local.startswith("base_")) \
                    and etree.QName(k).namespace is None:
                if local == "type" and etree.QName(el).namespace == ROBOMDA_NS:
                    continue        # ConnectionPolicy::type is a tag, not a reference
                for ref in v.split():
                    checked += 1
                    assert ref in ids, f"{path.name}: <{etree.QName(el).localname}> {local}={ref} unresolved"
    assert checked > 50


# ------------------------------------------------- Papyrus == EA, per case
def test_same_classes(models):
    case, pap, ea = models
    assert pap.classes() == ea.classes()
    assert len(pap.classes()) == {"headlamp": 5, "meka": 6}[case]


def test_same_interfaces(models):
    _, pap, ea = models
    ifs = pap.interfaces()
    assert ifs == ea.interfaces()
    assert len(ifs) == 6
    for name, attrs in ifs.items():           # each interface carries exactly one Integer datum
        assert len(attrs) == 1 and attrs[0][1] == "int", name


def test_same_components(models):
    _, pap, ea = models
    assert pap.components() == ea.components()


def test_same_platform(models):
    _, pap, ea = models
    assert pap.platform() == ea.platform()


def test_same_stereotype_applications(models, profile):
    _, pap, ea = models
    assert pap.stereotypes(profile) == ea.stereotypes(profile)


# ---------------------------------------------------- case structure rules
def test_each_interface_one_provider_one_requirer(models):
    _, pap, _ = models
    comps = {n: c for n, c in pap.components().items() if c["realizedBy"]}
    for iface in pap.interfaces():
        providers = [n for n, c in comps.items() if iface in c["provided"]]
        requirers = [n for n, c in comps.items() if iface in c["required"]]
        assert len(providers) == 1 and len(requirers) == 1, (iface, providers, requirers)
        assert providers != requirers


def test_ports_match_interfaces(models):
    _, pap, _ = models
    for name, c in pap.components().items():
        if not c["realizedBy"]:
            continue
        assert sorted(t for _, t in c["ports"]) == sorted(c["provided"] + c["required"]), name
        ifs = pap.interfaces()
        for port, iface in c["ports"]:          # port named after the datum it carries
            assert port == ifs[iface][0][0], (name, port)


def test_atomic_code_conventions(models):
    """Lifecycle and get/set<Datum> operations as docs/profile.md requires."""
    _, pap, _ = models
    classes, ifs = pap.classes(), pap.interfaces()
    for comp, c in pap.components().items():
        if not c["realizedBy"]:
            continue
        ops = {o[0]: o for o in classes[c["realizedBy"]]["ops"]}
        assert ops["configure"][4] == "bool" and ops["configure"][1] == "public"
        assert "update" in ops
        for iface in c["provided"]:
            datum = ifs[iface][0][0]
            g = ops["get" + datum[0].upper() + datum[1:]]
            assert g[1] == "public" and g[4] == "int" and g[3] == (), (comp, g)
        for iface in c["required"]:
            datum = ifs[iface][0][0]
            s = ops["set" + datum[0].upper() + datum[1:]]
            assert s[1] == "public" and s[3] == (("value", "int", "in"),) and s[4] == "void", (comp, s)


def test_headlamp_composite_and_profile(profile):
    pap = Model(model_files("headlamp")["papyrus"], "papyrus")
    comps = pap.components()
    top = comps["HeadlampAssembly"]
    assert len(top["parts"]) == 5 and len(top["connectors"]) == 6
    sts = pap.stereotypes(profile)
    activities = [s for s in sts if s[0] == "Activity"]
    assert len(activities) == 5
    for _, target, tags in activities:
        assert dict(tags)["period"] == "0.003" and dict(tags)["priority"] == "50" \
            and dict(tags)["scheduler"] == "RT", target
    mw = [s for s in sts if s[0] == "Middleware"]
    assert mw and dict(mw[0][2])["kind"] == "OROCOS"
    lib = [dict(s[2]) for s in sts if s[0] == "Library"]
    assert lib == [{"path": "atomic", "target": "headlamp_atomic", "includeDir": "include"}]
    cp = [s for s in sts if s[0] == "ConnectionPolicy"]
    assert len(cp) == 6 and all(dict(t)["type"] == "DATA" and dict(t)["size"] == "1"
                                and dict(t)["lockPolicy"] == "LOCK_FREE" for _, _, t in cp)


def test_meka_unprofiled_conventions():
    for dialect, path in model_files("meka").items():
        m = Model(path, dialect)
        root = m.doc.getroot()
        assert not list(root.iter("{%s}*" % ROBOMDA_NS)), "meka must not apply stereotypes"
        assert not root.findall(".//profileApplication")
        for name, c in m.classes().items():
            conv = {a[0]: a for a in c["attrs"]}
            assert conv["sample"][1:3] == ("double", "0.05"), name
            assert conv["priority"][1:3] == ("int", "50"), name
            assert conv["scheduler"][1:3] == ("std::string", "OTHER"), name
        pf = m.platform()
        assert list(pf["nodes"].values()) == [{"OROCOS": ["meka_atomic"]}]
        assert pf["artifacts"]["meka_atomic"]["fileName"] == "atomic"
        assert all(not c["connectors"] and not c["parts"] for c in m.components().values())


def test_papyrus_profile_application_resolves():
    pdoc = etree.parse(str(PROFILE))
    ids = {el.get("{%s}id" % XMI_NS["papyrus"]) for el in pdoc.iter() if isinstance(el.tag, str)}
    epkg = pdoc.find(".//contents")
    assert epkg.get("nsURI") == ROBOMDA_NS and epkg.get("nsPrefix") == "robomda"
    path = model_files("headlamp")["papyrus"]
    doc = etree.parse(str(path))
    app = doc.find(".//profileApplication")
    hrefs = [app.find("eAnnotations/references").get("href"), app.find("appliedProfile").get("href")]
    for href in hrefs:
        file_part, frag = href.split("#")
        assert (path.parent / file_part).resolve() == PROFILE.resolve()
        assert frag in ids, href
    assert hrefs[0].split("#")[1] == epkg.get("{%s}id" % XMI_NS["papyrus"])


def test_profile_matches_spec(profile):
    """Stereotypes, extended metaclasses and tags of docs/profile.md."""
    expected = {
        "Middleware": (["ExecutionEnvironment"], ["kind", "version", "managed"]),
        "Host": (["Node", "Device"], ["hostname", "address", "cores", "memory", "realTime"]),
        "Activity": (["Component", "Class", "Property"], ["period", "priority", "scheduler", "cpuAffinity"]),
        "ConnectionPolicy": (["Connector", "Interface", "Port"],
                             ["type", "size", "lockPolicy", "init", "pull", "topic"]),
        "Configurable": (["Property"], []),
        "OperationThread": (["Operation"], ["thread"]),
        "AtomicCode": (["Class"], ["header", "cppName"]),
        "Library": (["Artifact"], ["path", "target", "includeDir"]),
        "StartAfter": (["Dependency"], []),
        "Robot": (["Device"], ["dof", "urdf", "rootLink", "tipLink"]),
        "Thread": (["ExecutionEnvironment"], ["period", "priority", "scheduler", "cpuAffinity"]),
        "ComponentSet": (["Artifact"], []),
        "Bus": (["CommunicationPath"], ["kind", "bandwidth"]),
        # seed 004 (docs/substitution.md)
        "Category": (["Component"], ["kind"]),
        "Alternative": (["Component"], ["replaces"]),
        "Constant": (["Port", "Interface"], []),
        # seed 004 §4.3 (docs/jobs.md)
        "Job": (["InstanceSpecification"], ["configuration"]),  # a configuration of the product line (docs/jobs.md)
        "Subsystem": (["StateMachine"], []),
    }
    assert {k: (v["metas"], list(v["tags"])) for k, v in profile.items()} == expected
    assert profile["Category"]["tags"]["kind"] == "generic"  # as xslt/import/profile-defaults.xml
    assert profile["Activity"]["tags"]["scheduler"] == "OTHER"
    assert profile["ConnectionPolicy"]["tags"]["lockPolicy"] == "LOCK_FREE"
    # an unset dof is 0 (EMF's Integer default), which means "not given"
    assert profile["Robot"]["tags"]["dof"] == "0" and profile["Robot"]["tags"]["urdf"] is None
    # seed 002: a thread's activity tags default as Activity's; 0 = not given for cores, memory, bandwidth
    assert profile["Thread"]["tags"] == profile["Activity"]["tags"]
    assert profile["Host"]["tags"] == {"hostname": None, "address": None, "cores": "0", "memory": "0",
                                       "realTime": "false"}
    assert profile["Bus"]["tags"] == {"kind": "Ethernet", "bandwidth": "0.0"}
    assert profile["Middleware"]["tags"]["managed"] == "false"
    # the UML side of the profile declares the same stereotypes as its Ecore definition
    doc = etree.parse(str(PROFILE))
    uml_st = sorted(e.get("name") for e in doc.iter("packagedElement")
                    if e.get("{%s}type" % XMI_NS["papyrus"]) == "uml:Stereotype")
    assert uml_st == sorted(expected)


# ------------------------------------------------- C++ matches the model
SECTION = re.compile(r"^\s*(public|protected|private):\s*$")


def header_members(path: Path) -> dict:
    """{name: (visibility, declaration without spaces)} for one-line member declarations."""
    vis, out = "private", {}
    for line in path.read_text().splitlines():
        m = SECTION.match(line)
        if m:
            vis = m.group(1)
            continue
        line = line.split("//")[0].strip()
        m = re.match(r"^([\w:]+)\s+(\w+)(\(.*\))?(\s*const)?(\s*=.*)?;$", line)
        if m:
            out[m.group(2)] = (vis, line)
    return out


CPP_DEFAULT = {"int": "{}", "double": "{}", "bool": "{}", "std::string": '"{}"'}


@pytest.mark.parametrize("case", CASES)
def test_headers_match_uml_classes(case: str):
    m = Model(model_files(case)["papyrus"], "papyrus")
    inc = CASES_DIR / case / "atomic" / "include"
    for cname, c in m.classes().items():
        members = header_members(inc / f"{cname}.hpp")
        expected = set()
        for name, ctype, default, vis in c["attrs"]:
            expected.add(name)
            decl = f"{ctype} {name} = {CPP_DEFAULT[ctype].format(default)};"
            assert members.get(name) == (vis, decl), (cname, name, members.get(name), decl)
        for name, vis, query, params, ret in c["ops"]:
            expected.add(name)
            args = ", ".join(f"{t} {n}" for n, t, _ in params)
            decl = f"{ret} {name}({args}){' const' if query == 'true' else ''};"
            assert members.get(name) == (vis, decl), (cname, name, members.get(name), decl)
        assert set(members) == expected, (cname, set(members) ^ expected)


@pytest.mark.parametrize("case", CASES)
def test_library_target_is_artifact_name(case: str):
    cm = (CASES_DIR / case / "atomic" / "CMakeLists.txt").read_text()
    target = re.search(r"add_library\((\w+)\s+STATIC", cm).group(1)
    assert target == LIBRARY_TARGETS[case]
    for dialect, path in model_files(case).items():
        arts = Model(path, dialect).platform()["artifacts"]
        assert list(arts) == [target] and arts[target]["fileName"] == "atomic"
    assert "POSITION_INDEPENDENT_CODE ON" in cm and "CXX_STANDARD 14" in cm
    srcs = sorted(p.name for p in (CASES_DIR / case / "atomic" / "src").glob("*.cpp"))
    classes = Model(model_files(case)["papyrus"], "papyrus").classes()
    assert srcs == sorted(f"{c}.cpp" for c in classes)


# ------------------------------------------------------ real C++ builds
needs_cmake = pytest.mark.skipif(shutil.which("cmake") is None or shutil.which("make") is None
                                 or shutil.which("c++") is None and shutil.which("g++") is None,
                                 reason="cmake, make or a C++ compiler is not installed")

STRICT = "-Wall -Wextra -Werror"


def run(cmd: list[str], cwd: Path) -> str:
    p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       universal_newlines=True, timeout=300)
    assert p.returncode == 0, f"{' '.join(cmd)} failed in {cwd}:\n{p.stdout}"
    return p.stdout


@needs_cmake
@pytest.mark.parametrize("case", CASES)
def test_library_builds(case: str, tmp_path: Path):
    src = CASES_DIR / case / "atomic"
    run(["cmake", f"-DCMAKE_CXX_FLAGS={STRICT}", str(src)], tmp_path)
    run(["make"], tmp_path)
    lib = tmp_path / f"lib{LIBRARY_TARGETS[case]}.a"
    assert lib.is_file()
    if shutil.which("nm"):
        syms = run(["nm", "-C", str(lib)], tmp_path)
        for cname in Model(model_files(case)["papyrus"], "papyrus").classes():
            assert f"{cname}::configure()" in syms, cname
    assert not (src / "CMakeCache.txt").exists(), "build must stay out of the source tree"


SMOKE_HEADER = r"""
#include <cmath>
#include <iostream>
#include <string>
static int failures = 0;
#define CHECK(expr) do { if (!(expr)) { ++failures; \
    std::cerr << __LINE__ << ": CHECK failed: " #expr << std::endl; } } while (0)
#define CHECK_EQ(a, b) do { if (!((a) == (b))) { ++failures; \
    std::cerr << __LINE__ << ": " #a " == " << (a) << ", expected " << (b) << std::endl; } } while (0)
"""

SMOKE = {
    "headlamp": r"""
#include "GuppyF080C.hpp"
#include "ForceTorqueSensor.hpp"
#include "GumChannelDetector.hpp"
#include "ImpedanceControl.hpp"
#include "IndustrialArmDriver.hpp"

// Generated Orocos components derive from the atomic class (seed 000 Fig. 11):
// the tests do the same to reach the protected operations and properties.
struct Camera : GuppyF080C {
    using GuppyF080C::setWidth; using GuppyF080C::getWidth; using GuppyF080C::setGain;
    using GuppyF080C::getGain; using GuppyF080C::setShutter; using GuppyF080C::getShutter;
    using GuppyF080C::getHeight; using GuppyF080C::guid;
};
struct Sensor : ForceTorqueSensor { using ForceTorqueSensor::bias; using ForceTorqueSensor::offset; };
struct Vision : GumChannelDetector { using GumChannelDetector::reset; using GumChannelDetector::threshold; };
struct Controller : ImpedanceControl {
    using ImpedanceControl::setGains; using ImpedanceControl::getStiffness; using ImpedanceControl::getDamping;
};
struct Arm : IndustrialArmDriver {
    using IndustrialArmDriver::home; using IndustrialArmDriver::setSpeed; using IndustrialArmDriver::getSpeed;
    using IndustrialArmDriver::ip;
};

int main() {
    Camera cam;
    CHECK(cam.configure());
    CHECK_EQ(cam.guid, std::string("000A47010C0A3D12"));
    CHECK_EQ(cam.getWidth(), 1032); CHECK_EQ(cam.getHeight(), 778); CHECK_EQ(cam.getShutter(), 500);
    CHECK(cam.start());
    cam.setGain(7); CHECK_EQ(cam.getGain(), 7);
    cam.update(); cam.update(); cam.update();
    CHECK_EQ(cam.getVisionValue(), 3007);
    cam.setWidth(640); CHECK_EQ(cam.getWidth(), 640);
    cam.setShutter(250); CHECK_EQ(cam.getShutter(), 250);
    cam.stop(); cam.update();
    CHECK_EQ(cam.getVisionValue(), 3007);
    cam.cleanup();
    CHECK_EQ(cam.getVisionValue(), 7);

    Sensor fts;
    CHECK(fts.configure()); CHECK(fts.start());
    for (int i = 0; i < 4; ++i) fts.update();
    CHECK_EQ(fts.getWrench(), 28);
    fts.bias(); CHECK_EQ(fts.offset, 28); CHECK_EQ(fts.getWrench(), 0);
    fts.update(); CHECK_EQ(fts.getWrench(), 7);
    fts.stop(); fts.update(); CHECK_EQ(fts.getWrench(), 7);

    Vision vis;
    CHECK(vis.configure()); CHECK_EQ(vis.threshold, 100);
    vis.setVisionValue(3007); vis.setToolPose(150); vis.update();
    CHECK_EQ(vis.getChannelPosition(), 440);
    vis.reset(); CHECK_EQ(vis.getChannelPosition(), 0);

    Controller ctl;
    CHECK(ctl.configure()); CHECK(ctl.start());
    CHECK_EQ(ctl.getArmCommand(), 0);
    ctl.setChannelPosition(440); ctl.setWrench(28); ctl.setArmState(400); ctl.update();
    CHECK_EQ(ctl.getArmCommand(), 443);
    ctl.setGains(1000, 0); CHECK_EQ(ctl.getStiffness(), 1000); CHECK_EQ(ctl.getDamping(), 0);
    ctl.update(); CHECK_EQ(ctl.getArmCommand(), 438);
    ctl.stop(); CHECK_EQ(ctl.getArmCommand(), 400);

    Arm arm;
    CHECK(arm.configure()); CHECK_EQ(arm.ip, std::string("192.168.10.4")); CHECK(arm.start());
    arm.setArmCommand(25);
    arm.update(); CHECK_EQ(arm.getArmState(), 10);
    arm.update(); CHECK_EQ(arm.getArmState(), 20);
    arm.update(); CHECK_EQ(arm.getArmState(), 25);
    CHECK_EQ(arm.getToolPose(), 175);
    arm.home(); arm.update(); CHECK_EQ(arm.getArmState(), 15);
    arm.setSpeed(100); CHECK_EQ(arm.getSpeed(), 100);
    arm.update(); CHECK_EQ(arm.getArmState(), 0);
    arm.stop(); arm.cleanup(); CHECK_EQ(arm.getToolPose(), 150);

    // one deployment-like cycle over the six connections of the model
    Camera c2; Sensor s2; Vision v2; Controller k2; Arm a2;
    CHECK(c2.configure() && s2.configure() && v2.configure() && k2.configure() && a2.configure());
    CHECK(c2.start() && s2.start() && k2.start() && a2.start());
    for (int cycle = 0; cycle < 50; ++cycle) {
        c2.update(); s2.update(); a2.update();
        v2.setVisionValue(c2.getVisionValue());        // visionValueConn
        v2.setToolPose(a2.getToolPose());              // toolPoseConn
        v2.update();
        k2.setChannelPosition(v2.getChannelPosition()); // channelPositionConn
        k2.setWrench(s2.getWrench());                  // wrenchConn
        k2.setArmState(a2.getArmState());              // armStateConn
        k2.update();
        a2.setArmCommand(k2.getArmCommand());          // armCommandConn
    }
    CHECK(a2.getArmState() > 0);
    return failures == 0 ? 0 : 1;
}
""",
    "meka": r"""
#include "GX1050.hpp"
#include "ATIForceTorque.hpp"
#include "ScrewDetector.hpp"
#include "TrajectoryGenerator.hpp"
#include "ImpedanceControl.hpp"
#include "MekaArmDriver.hpp"

struct Camera : GX1050 {
    using GX1050::setGain; using GX1050::getGain; using GX1050::getWidth; using GX1050::getHeight;
    using GX1050::setShutter; using GX1050::getShutter; using GX1050::ip;
    using GX1050::sample; using GX1050::priority; using GX1050::scheduler;
};
struct Sensor : ATIForceTorque { using ATIForceTorque::bias; using ATIForceTorque::sample; };
struct Detector : ScrewDetector { using ScrewDetector::reset; using ScrewDetector::priority; };
struct Planner : TrajectoryGenerator {
    using TrajectoryGenerator::setStep; using TrajectoryGenerator::getStep; using TrajectoryGenerator::scheduler;
};
struct Controller : ImpedanceControl {
    using ImpedanceControl::setGains; using ImpedanceControl::getStiffness; using ImpedanceControl::getDamping;
};
struct Arm : MekaArmDriver {
    using MekaArmDriver::home; using MekaArmDriver::setSpeed; using MekaArmDriver::getSpeed;
    using MekaArmDriver::robotName;
};

int main() {
    Camera cam;
    CHECK(std::fabs(cam.sample - 0.05) < 1e-12); CHECK_EQ(cam.priority, 50);
    CHECK_EQ(cam.scheduler, std::string("OTHER")); CHECK_EQ(cam.ip, std::string("192.168.1.50"));
    CHECK(cam.configure()); CHECK(cam.start());
    CHECK_EQ(cam.getWidth(), 1024); CHECK_EQ(cam.getHeight(), 1024); CHECK_EQ(cam.getShutter(), 10000);
    cam.setGain(3); cam.update(); cam.update();
    CHECK_EQ(cam.getImage(), 2003);
    cam.setShutter(500); CHECK_EQ(cam.getShutter(), 500);
    cam.stop(); cam.update(); CHECK_EQ(cam.getImage(), 2003);
    cam.cleanup(); CHECK_EQ(cam.getImage(), 3);

    Sensor ati;
    CHECK(std::fabs(ati.sample - 0.05) < 1e-12);
    CHECK(ati.configure()); CHECK(ati.start());
    for (int i = 0; i < 5; ++i) ati.update();
    CHECK_EQ(ati.getForce(), 15);
    ati.bias(); CHECK_EQ(ati.getForce(), 0);
    ati.update(); CHECK_EQ(ati.getForce(), 3);
    ati.stop();

    Detector det;
    CHECK_EQ(det.priority, 50);
    CHECK(det.configure());
    det.setImage(2003); det.update(); CHECK_EQ(det.getScrewPosition(), 150);
    det.setImage(100); det.update(); CHECK_EQ(det.getScrewPosition(), 0);
    det.setImage(2003); det.update(); det.reset(); CHECK_EQ(det.getScrewPosition(), 0);

    Planner plan;
    CHECK_EQ(plan.scheduler, std::string("OTHER"));
    CHECK(plan.configure()); plan.setArmState(0); CHECK(plan.start());
    CHECK_EQ(plan.getTrajectory(), 0);
    plan.setScrewPosition(150); plan.update(); CHECK_EQ(plan.getTrajectory(), 5);
    plan.setArmState(148); plan.update(); CHECK_EQ(plan.getTrajectory(), 150);
    plan.setStep(50); CHECK_EQ(plan.getStep(), 50);
    plan.setArmState(0); plan.update(); CHECK_EQ(plan.getTrajectory(), 50);

    Controller ctl;
    CHECK(ctl.configure());
    ctl.setTrajectory(50); CHECK(ctl.start()); CHECK_EQ(ctl.getArmCommand(), 50);
    ctl.setForce(15); ctl.update(); CHECK_EQ(ctl.getArmCommand(), 46);
    ctl.setGains(100, 0); CHECK_EQ(ctl.getStiffness(), 100); CHECK_EQ(ctl.getDamping(), 0);
    ctl.update(); CHECK_EQ(ctl.getArmCommand(), 35);
    ctl.stop(); CHECK_EQ(ctl.getArmCommand(), 50);

    Arm arm;
    CHECK_EQ(arm.robotName, std::string("m3humanoid"));
    CHECK(arm.configure()); CHECK(arm.start());
    arm.setArmCommand(12);
    arm.update(); CHECK_EQ(arm.getArmState(), 5);
    arm.update(); CHECK_EQ(arm.getArmState(), 10);
    arm.update(); CHECK_EQ(arm.getArmState(), 12);
    arm.home(); arm.update(); CHECK_EQ(arm.getArmState(), 7);
    arm.setSpeed(20); CHECK_EQ(arm.getSpeed(), 20);
    arm.stop(); arm.cleanup(); CHECK_EQ(arm.getArmState(), 0);
    return failures == 0 ? 0 : 1;
}
""",
}


@needs_cmake
@pytest.mark.parametrize("case", CASES)
def test_smoke_program(case: str, tmp_path: Path):
    """A program linked against the library through its CMake target runs and checks values."""
    proj = tmp_path / "smoke"
    proj.mkdir()
    (proj / "main.cpp").write_text(SMOKE_HEADER + SMOKE[case])
    atomic = (CASES_DIR / case / "atomic").as_posix()
    (proj / "CMakeLists.txt").write_text(textwrap.dedent(f"""\
        cmake_minimum_required(VERSION 3.5)
        project(smoke_{case} CXX)
        add_subdirectory("{atomic}" atomic)
        add_executable(smoke main.cpp)
        set_target_properties(smoke PROPERTIES CXX_STANDARD 14 CXX_STANDARD_REQUIRED ON)
        target_link_libraries(smoke {LIBRARY_TARGETS[case]})
        """))
    build = tmp_path / "build"
    build.mkdir()
    run(["cmake", f"-DCMAKE_CXX_FLAGS={STRICT}", str(proj)], build)
    run(["make"], build)
    p = subprocess.run([str(build / "smoke")], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       universal_newlines=True, timeout=60)
    assert p.returncode == 0, p.stdout


@pytest.mark.parametrize("script", [CASES_DIR / "tuned" / "make.py", CASES_DIR / "undeployed" / "make.py",
                                    CASES_DIR / "structured" / "make.py",
                                    ROOT / "fixtures" / "ros" / "jointstate" / "make.py",
                                    ROOT / "fixtures" / "ros" / "managed" / "make.py",
                                    ROOT / "fixtures" / "ros" / "usercode" / "make.py",
                                    ROOT / "fixtures" / "ros" / "p4rlib" / "make.py",
                                    CASES_DIR / "pidswap" / "make.py"],
                         ids=["tuned", "undeployed", "structured", "jointstate", "managed", "usercode", "p4rlib",
                              "pidswap"])
def test_derived_fixture_is_what_its_make_py_writes(script: Path):
    """A derived fixture is its source model with the edits its make.py lists, and nothing else."""
    import importlib.util
    spec = importlib.util.spec_from_file_location(f"{script.parent.name}_make", script)
    make = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(make)
    for path, text in make.texts().items():
        assert path.read_text(encoding="utf-8") == text, f"{path} is stale: run python {script}"
