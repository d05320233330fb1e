"""The "nothing dropped in silence" invariant of the import, checked by xmi:id.

Every element of a kind robomda understands (components, classes, interfaces,
ports, properties, operations, connectors, dependencies, nodes, devices,
execution environments, artifacts, deployments, communication paths,
stereotype applications) either reaches the PIM (an ``id`` or a ``via``
attribute of a PIM element carries its xmi:id) or is named (``[xmi:id=ID]``)
by a warning of the import. Shared by tests/test_import_invariant.py and
tests/test_import_generative.py.
"""

from __future__ import annotations

import re
from pathlib import Path

from lxml import etree

__all__ = ["KINDS", "understood_ids", "pim_ids", "dropped", "import_run"]

# the metaclasses robomda understands (issue 11, "Nothing dropped in silence")
CLASSIFIERS = {"Component", "Class", "Interface", "Node", "Device", "ExecutionEnvironment",
               "Artifact", "DeploymentSpecification"}
DEPENDENCIES = {"Dependency", "Usage", "Realization", "InterfaceRealization", "ComponentRealization",
                "Abstraction", "Deployment", "Manifestation"}
KINDS = CLASSIFIERS | DEPENDENCIES | {"Port", "Property", "Operation", "Connector", "CommunicationPath"}
# the owners whose Properties and Operations are features robomda reads
FEATURE_OWNERS = CLASSIFIERS | {"DataType", "Signal", "Collaboration"}
# Enterprise Architect's exposed interfaces: <provided> / <required> of these
EXPOSING = {"Component", "Class", "Port"}

# what XMI lets a tool leave out: the declared type of the feature
_DEFAULT_META = {
    "ownedAttribute": "Property", "ownedOperation": "Operation", "ownedPort": "Port",
    "interfaceRealization": "InterfaceRealization", "realization": "ComponentRealization",
    "deployment": "Deployment", "manifestation": "Manifestation", "ownedConnector": "Connector",
    "nestedNode": "Node", "nestedArtifact": "Artifact", "ownedEnd": "Property",
}


# tool annotations, and the placeholders of template parameters (no element
# of the user's model: a templated classifier is named by IMP118 instead)
_NOT_THE_MODEL = {"eAnnotations", "ownedParameteredElement", "ownedDefault", "ownedActual"}


def _is_xmi(uri: str | None) -> bool:
    return bool(uri) and re.search(r"omg\.org/(spec/)?XMI", uri, re.I) is not None


def _is_uml(uri: str | None) -> bool:
    return bool(uri) and re.search(r"(eclipse\.org/uml2/[0-9.]+/UML|omg\.org/(spec/)?UML)(/[0-9.]+)?/?$",
                                   uri, re.I) is not None


def _xmi_attr(el: etree._Element, name: str) -> str | None:
    for key, value in el.attrib.items():
        if key.startswith("{") and key.endswith("}" + name) and _is_xmi(key[1:key.index("}")]):
            return value
    return None


def meta(el: etree._Element) -> str:
    """The UML metaclass of an XMI element ('' when unknown)."""
    t = _xmi_attr(el, "type") or el.get("{http://www.w3.org/2001/XMLSchema-instance}type")
    if t:
        return t.split(":")[-1]
    q = etree.QName(el)
    if _is_uml(q.namespace):
        return q.localname
    if q.namespace is None:
        return _DEFAULT_META.get(q.localname, "")
    return ""


def understood_ids(xmi: Path) -> dict[str, str]:
    """xmi:id -> metaclass of every element of a kind robomda understands."""
    parser = etree.XMLParser(huge_tree=True, resolve_entities=False, no_network=True, load_dtd=False)
    root = etree.parse(str(xmi), parser).getroot()
    found: dict[str, str] = {}

    def skip(el: etree._Element) -> bool:
        q = etree.QName(el)
        return (q.localname == "Extension" and _is_xmi(q.namespace)) or q.localname in _NOT_THE_MODEL \
            or meta(el) in ("Profile", "Stereotype")

    def walk(el: etree._Element, owner_meta: str) -> None:
        for child in el.iterchildren(etree.Element):
            if skip(child):
                continue
            m = meta(child)
            xid = _xmi_attr(child, "id")
            if xid and child.tag in ("provided", "required") and owner_meta in EXPOSING:
                found.setdefault(xid, "exposed " + child.tag)
            elif xid and m in KINDS and child.get("href") is None and _xmi_attr(child, "idref") is None:
                if m not in ("Property", "Operation") or owner_meta in FEATURE_OWNERS:
                    # a Property / Operation counts as a feature of a classifier
                    if not (m == "Property" and etree.QName(child).localname == "ownedEnd"):
                        found.setdefault(xid, m)
            walk(child, m or owner_meta)

    q = etree.QName(root)
    if q.localname == "XMI" and _is_xmi(q.namespace):
        for child in root.iterchildren(etree.Element):
            cq = etree.QName(child)
            if _is_uml(cq.namespace):
                if meta(child) not in ("Profile",):
                    walk(child, meta(child))
            elif not _is_xmi(cq.namespace) and any(k.startswith("base_") for k in child.attrib):
                xid = _xmi_attr(child, "id")
                if xid:
                    found.setdefault(xid, "stereotype application")
    else:
        walk(root, meta(root))
    return found


def pim_ids(pim: etree._Element) -> set[str]:
    """Every xmi:id the PIM records (``id``, ``via``)."""
    ids: set[str] = set()
    for el in pim.iter(etree.Element):
        if el.get("id"):
            ids.add(el.get("id"))
            # a pair of a relationship with several clients: robomda.<ID>.<n>
            pair = _PAIR.match(el.get("id"))
            if pair:
                ids.add(pair.group(1))
        if el.get("via"):
            ids.update(el.get("via").split())
    return ids


_PAIR = re.compile(r"^robomda\.(.+)\.[0-9]+$")
_NAMED = re.compile(r"\[xmi:id=([^\]]*)\]")


def dropped(xmi: Path, pim_text: str | None, messages: list[str]) -> dict[str, str]:
    """The understood elements neither in the PIM nor named by a warning (id -> metaclass)."""
    named = {xid for m in messages for xid in _NAMED.findall(m)}
    named |= {i for m in messages for ids in re.findall(r"\bxmi:ids=([^\s\]\)]+)", m) for i in ids.split(",")}
    in_pim = pim_ids(etree.fromstring(pim_text.encode("utf-8"))) if pim_text else set()
    # an xmi:id other files of the model use too is "FILE#id" (xslt/import/files.xsl): the model file's own
    own = {i.rsplit("#", 1)[1] for i in in_pim | named if i.startswith(f"{xmi.name}#")}
    return {xid: m for xid, m in understood_ids(xmi).items() if xid not in in_pim | named | own}


def import_run(model: Path) -> tuple[int, str | None, list[str]]:
    """Run the import step through the driver: (exit code, PIM text or None, warning texts).

    A warning text is ``CODE: message [xmi:id=ID]`` (one per diagnostic).
    """
    from robomda import api, pipeline
    from robomda.diagnostics import EXIT_OK, RobomdaError
    from robomda.resources import pipeline_path

    chain = pipeline.load(pipeline_path("import"))
    try:
        result = api._run(chain, model, {"model-file-name": model.name}, steps=1)
    except RobomdaError as exc:
        return exc.exit_code, None, [f"{d.code}: {d.message} [xmi:id={d.xmi_id or ''}]" for d in exc.diagnostics]
    return EXIT_OK, result.output, [f"{d.code}: {d.message} [xmi:id={d.xmi_id or ''}]" for d in result.warnings]
