"""Synthetic UML models for the benchmark, in the shapes users draw.

Every shape has N components. Component i is realized by class Drv<i>,
provides interface I<i> on port out and requires I<i-1> on port in, so the
data goes round a ring of N connections. The shapes differ in how the model
says so (issue 35):

- ``ring``: ball-and-socket only (no composite, no connector), one artifact
  manifesting every component on one execution environment.
- ``composite``: one system component with a part per component, joined by
  N assembly connectors (as Papyrus, Enterprise Architect and the seed case
  studies draw them), deployed on one execution environment.
- ``nested``: the system holds N/10 sub-assemblies, each a composite of 10
  parts joined inside it, promoting its first part's in port and its last
  part's out port through delegation connectors and its first part's gain
  as a property of its own, which the system's part sets through a slot.
- ``datatypes``: ``composite`` with a structured data type on every
  interface (a DataType of its own per interface, holding a shared header
  DataType, a bounded array and a scalar).
- ``deployment``: ``composite`` deployed on N/100 hosts (a ring of
  communication paths), each with 2 processes of 5 threads and one component
  set per process; every part deployed on a thread.
- ``calls``: ``composite`` plus an operation call per part: part i provides
  a service interface S<i> (one operation), part i+1 calls it through a
  required port joined by a connector.

The XMI is written in the Eclipse UML2 / Papyrus dialect.

    python bench/synth.py 1000 [shape [middleware]] > /tmp/synth-1000.xmi
"""

from __future__ import annotations

import sys
from pathlib import Path

__all__ = ["SHAPES", "synth_model", "write_model"]

SHAPES = ("ring", "composite", "nested", "datatypes", "deployment", "calls")

_HEAD = """<?xml version="1.0" encoding="UTF-8"?>
<xmi:XMI xmi:version="20131001" xmlns:xmi="http://www.omg.org/spec/XMI/20131001" xmlns:uml="http://www.eclipse.org/uml2/5.0.0/UML" xmlns:robomda="http://robomda.org/profile/robomda/1">
  <uml:Model xmi:id="_model" name="Synth{n}">
    <packagedElement xmi:type="uml:Package" xmi:id="_app" name="app">
"""
_PRIM = "pathmap://UML_LIBRARIES/UMLPrimitiveTypes.library.uml#{0}"
_GROUP = 10  # parts per sub-assembly (nested)
_HOST = 100  # components per host (deployment)
_THREADS = 5  # threads per process (deployment)


def _data_type(i: int) -> str:
    """The structured data type of interface I<i> (shape datatypes)."""
    real = _PRIM.format("Real")
    return f"""      <packagedElement xmi:type="uml:DataType" xmi:id="_T{i}" name="Msg{i}">
        <ownedAttribute xmi:id="_T{i}_h" name="header" visibility="public"><type xmi:type="uml:DataType" xmi:idref="_Hdr"/></ownedAttribute>
        <ownedAttribute xmi:id="_T{i}_p" name="position" visibility="public"><type xmi:type="uml:PrimitiveType" href="{real}"/>
          <lowerValue xmi:type="uml:LiteralInteger" xmi:id="_T{i}_pl" value="3"/><upperValue xmi:type="uml:LiteralUnlimitedNatural" xmi:id="_T{i}_pu" value="3"/></ownedAttribute>
        <ownedAttribute xmi:id="_T{i}_g" name="gain{i}" visibility="public"><type xmi:type="uml:PrimitiveType" href="{real}"/></ownedAttribute>
      </packagedElement>
"""


def _header_type() -> str:
    integer, string = _PRIM.format("Integer"), _PRIM.format("String")
    return f"""      <packagedElement xmi:type="uml:DataType" xmi:id="_Hdr" name="Header">
        <ownedAttribute xmi:id="_Hdr_s" name="seq" visibility="public"><type xmi:type="uml:PrimitiveType" href="{integer}"/></ownedAttribute>
        <ownedAttribute xmi:id="_Hdr_f" name="frame" visibility="public"><type xmi:type="uml:PrimitiveType" href="{string}"/></ownedAttribute>
      </packagedElement>
"""


def _interface(i: int, shape: str) -> str:
    data = (f'<type xmi:type="uml:DataType" xmi:idref="_T{i}"/>' if shape == "datatypes"
            else f'<type xmi:type="uml:PrimitiveType" href="{_PRIM.format("Integer")}"/>')
    text = f"""      <packagedElement xmi:type="uml:Interface" xmi:id="_I{i}" name="I{i}">
        <ownedAttribute xmi:id="_I{i}_d" name="value{i}">{data}</ownedAttribute>
      </packagedElement>
"""
    if shape == "datatypes":
        text = _data_type(i) + text
    if shape == "calls":
        boolean, integer = _PRIM.format("Boolean"), _PRIM.format("Integer")
        text += f"""      <packagedElement xmi:type="uml:Interface" xmi:id="_S{i}" name="S{i}">
        <ownedOperation xmi:id="_S{i}_o" name="apply{i}">
          <ownedParameter xmi:id="_S{i}_op" name="v"><type xmi:type="uml:PrimitiveType" href="{integer}"/></ownedParameter>
          <ownedParameter xmi:id="_S{i}_or" direction="return"><type xmi:type="uml:PrimitiveType" href="{boolean}"/></ownedParameter>
        </ownedOperation>
      </packagedElement>
"""
    return text


def _calls_operations(i: int, n: int) -> str:
    """Drv<i> implements S<i>'s operation and declares S<i-1>'s, which it calls (shape calls)."""
    boolean, integer = _PRIM.format("Boolean"), _PRIM.format("Integer")
    prev = (i - 1) % n
    return "".join(f"""        <ownedOperation xmi:id="_D{i}_a{k}" name="apply{k}" visibility="public"{abstract}>
          <ownedParameter xmi:id="_D{i}_a{k}p" name="v"><type xmi:type="uml:PrimitiveType" href="{integer}"/></ownedParameter>
          <ownedParameter xmi:id="_D{i}_a{k}r" direction="return"><type xmi:type="uml:PrimitiveType" href="{boolean}"/></ownedParameter>
        </ownedOperation>
""" for k, abstract in ((i, ""), (prev, ' isAbstract="true"')))


def _component(i: int, n: int, shape: str) -> str:
    prev = (i - 1) % n
    integer, real = _PRIM.format("Integer"), _PRIM.format("Real")
    gain = f"gain{i % _GROUP}" if shape == "nested" else "gain"
    calls = _calls_operations(i, n) if shape == "calls" else ""
    # the accessors carry the ports' data (CMP020): the structured type of each interface on shape datatypes
    datum = (lambda k: f'<type xmi:type="uml:DataType" xmi:idref="_T{k}"/>') if shape == "datatypes" else (
        lambda k: f'<type xmi:type="uml:PrimitiveType" href="{integer}"/>')
    ports = ""
    if shape == "calls":
        ports = f"""        <ownedAttribute xmi:type="uml:Port" xmi:id="_C{i}_srv" name="srv" type="_S{i}" aggregation="composite"/>
        <ownedAttribute xmi:type="uml:Port" xmi:id="_C{i}_cli" name="cli" type="_S{prev}" aggregation="composite"/>
        <interfaceRealization xmi:id="_C{i}_sr" client="_C{i}" supplier="_S{i}" contract="_S{i}"/>
"""
    usage = (f'      <packagedElement xmi:type="uml:Usage" xmi:id="_US{i}" client="_C{i}" supplier="_S{prev}"/>\n'
             if shape == "calls" else "")
    return _interface(i, shape) + f"""      <packagedElement xmi:type="uml:Class" xmi:id="_D{i}" name="Drv{i}">
        <ownedAttribute xmi:id="_D{i}_s" name="sample" visibility="public"><type xmi:type="uml:PrimitiveType" href="{real}"/>
          <defaultValue xmi:type="uml:LiteralReal" xmi:id="_D{i}_sv" value="0.01"/></ownedAttribute>
        <ownedAttribute xmi:id="_D{i}_g" name="{gain}" visibility="public"><type xmi:type="uml:PrimitiveType" href="{real}"/>
          <defaultValue xmi:type="uml:LiteralReal" xmi:id="_D{i}_gv" value="1.5"/></ownedAttribute>
        <ownedOperation xmi:id="_D{i}_c" name="configure" visibility="public">
          <ownedParameter xmi:id="_D{i}_cr" direction="return"><type xmi:type="uml:PrimitiveType" href="{_PRIM.format('Boolean')}"/></ownedParameter>
        </ownedOperation>
        <ownedOperation xmi:id="_D{i}_u" name="update" visibility="public"/>
        <ownedOperation xmi:id="_D{i}_get" name="getValue{i}" visibility="public">
          <ownedParameter xmi:id="_D{i}_getr" direction="return">{datum(i)}</ownedParameter>
        </ownedOperation>
        <ownedOperation xmi:id="_D{i}_set" name="setValue{prev}" visibility="public">
          <ownedParameter xmi:id="_D{i}_setp" name="v">{datum(prev)}</ownedParameter>
        </ownedOperation>
        <ownedOperation xmi:id="_D{i}_k" name="setGain" visibility="protected">
          <ownedParameter xmi:id="_D{i}_kp" name="gain"><type xmi:type="uml:PrimitiveType" href="{real}"/></ownedParameter>
        </ownedOperation>
{calls}      </packagedElement>
      <packagedElement xmi:type="uml:Component" xmi:id="_C{i}" name="Comp{i}">
        <ownedAttribute xmi:type="uml:Port" xmi:id="_C{i}_out" name="out" type="_I{i}" aggregation="composite"/>
        <ownedAttribute xmi:type="uml:Port" xmi:id="_C{i}_in" name="in" type="_I{prev}" aggregation="composite"/>
{ports}        <interfaceRealization xmi:id="_C{i}_ir" client="_C{i}" supplier="_I{i}" contract="_I{i}"/>
        <realization xmi:type="uml:ComponentRealization" xmi:id="_C{i}_cr" client="_D{i}" supplier="_C{i}" realizingClassifier="_D{i}" abstraction="_C{i}"/>
      </packagedElement>
      <packagedElement xmi:type="uml:Usage" xmi:id="_U{i}" client="_C{i}" supplier="_I{prev}"/>
{usage}"""


def _connector(cid: str, part_a: str, port_a: str, part_b: str, port_b: str) -> str:
    """An assembly connector from port_a of part_a to port_b of part_b (no part: the owner's own port)."""
    def end(suffix: str, part: str, port: str) -> str:
        with_port = f' partWithPort="{part}"' if part else ""
        return f'<end xmi:type="uml:ConnectorEnd" xmi:id="{cid}_{suffix}"{with_port} role="{port}"/>'
    kind = "" if part_a and part_b else ' kind="delegation"'
    return (f'        <ownedConnector xmi:type="uml:Connector" xmi:id="{cid}" name="{cid[1:]}"{kind}>'
            f'{end("a", part_a, port_a)}{end("b", part_b, port_b)}</ownedConnector>\n')


def _flat_system(n: int, shape: str) -> str:
    """The system component: a part per component, joined in a ring (shapes composite, datatypes, deployment,
    calls)."""
    parts = "".join(f'        <ownedAttribute xmi:type="uml:Property" xmi:id="_P{i}" name="p{i}" type="_C{i}" '
                    f'aggregation="composite"/>\n' for i in range(n))
    connectors = "".join(_connector(f"_K{i}", f"_P{i}", f"_C{i}_out", f"_P{(i + 1) % n}", f"_C{(i + 1) % n}_in")
                         for i in range(n))
    if shape == "calls":
        connectors += "".join(_connector(f"_L{i}", f"_P{(i + 1) % n}", f"_C{(i + 1) % n}_cli", f"_P{i}",
                                         f"_C{i}_srv") for i in range(n))
    return (f'      <packagedElement xmi:type="uml:Component" xmi:id="_sys" name="System">\n{parts}{connectors}'
            f'      </packagedElement>\n')


def _nested_system(n: int) -> str:
    """Sub-assemblies of _GROUP parts each, promoting their ends and a gain; the system joins them."""
    groups = -(-n // _GROUP)
    real = _PRIM.format("Real")
    text = []
    for g in range(groups):
        members = range(g * _GROUP, min(n, (g + 1) * _GROUP))
        first, last = members[0], members[-1]
        parts = "".join(f'        <ownedAttribute xmi:type="uml:Property" xmi:id="_P{i}" name="p{i}" type="_C{i}" '
                        f'aggregation="composite"/>\n' for i in members)
        inner = "".join(_connector(f"_K{i}", f"_P{i}", f"_C{i}_out", f"_P{i + 1}", f"_C{i + 1}_in")
                        for i in members[:-1])
        text.append(f"""      <packagedElement xmi:type="uml:Component" xmi:id="_G{g}" name="Group{g}">
        <ownedAttribute xmi:type="uml:Port" xmi:id="_G{g}_in" name="in" type="_I{(first - 1) % n}" aggregation="composite"/>
        <ownedAttribute xmi:type="uml:Port" xmi:id="_G{g}_out" name="out" type="_I{last}" aggregation="composite"/>
        <interfaceRealization xmi:id="_G{g}_ir" client="_G{g}" supplier="_I{last}" contract="_I{last}"/>
        <ownedAttribute xmi:id="_G{g}_g" name="gain{first % _GROUP}" visibility="public"><type xmi:type="uml:PrimitiveType" href="{real}"/>
          <defaultValue xmi:type="uml:LiteralReal" xmi:id="_G{g}_gv" value="2.5"/></ownedAttribute>
{parts}{inner}{_connector(f"_Gi{g}", "", f"_G{g}_in", f"_P{first}", f"_C{first}_in")}{_connector(f"_Go{g}", f"_P{last}", f"_C{last}_out", "", f"_G{g}_out")}      </packagedElement>
      <packagedElement xmi:type="uml:Usage" xmi:id="_GU{g}" client="_G{g}" supplier="_I{(first - 1) % n}"/>
      <packagedElement xmi:type="uml:InstanceSpecification" xmi:id="_V{g}" name="group{g}_settings">
        <slot xmi:type="uml:Slot" xmi:id="_V{g}_s" definingFeature="_G{g}_g"><value xmi:type="uml:LiteralReal" xmi:id="_V{g}_sv" value="{g % 7}.5"/></slot>
      </packagedElement>
""")
    parts = "".join(f"""        <ownedAttribute xmi:type="uml:Property" xmi:id="_Q{g}" name="g{g}" type="_G{g}" aggregation="composite">
          <defaultValue xmi:type="uml:InstanceValue" xmi:id="_Q{g}_dv" instance="_V{g}"/></ownedAttribute>
""" for g in range(groups))
    connectors = "".join(_connector(f"_J{g}", f"_Q{g}", f"_G{g}_out", f"_Q{(g + 1) % groups}",
                                    f"_G{(g + 1) % groups}_in") for g in range(groups))
    text.append(f'      <packagedElement xmi:type="uml:Component" xmi:id="_sys" name="System">\n{parts}{connectors}'
                f'      </packagedElement>\n')
    return "".join(text)


_ARTIFACT = """      <packagedElement xmi:type="uml:Artifact" xmi:id="_lib" name="synth_atomic" fileName="atomic">
{manifests}
      </packagedElement>
"""


def _one_environment(n: int, shape: str, middleware: str) -> str:
    """One node, one Orocos execution environment: the artifact of every class, and the system (or, for the
    ring, the artifact of every component) deployed on it."""
    manifests = "\n".join(f'        <manifestation xmi:id="_M{i}" client="_lib" supplier="_C{i}" utilizedElement="_C{i}"/>'
                          for i in range(n))
    deployed = "_lib" if shape == "ring" else "_sys"
    return f"""      <packagedElement xmi:type="uml:Node" xmi:id="_pc" name="pc">
        <nestedNode xmi:type="uml:ExecutionEnvironment" xmi:id="_ee" name="{middleware}">
          <deployment xmi:id="_dep" client="_ee" supplier="{deployed}" deployedArtifact="{deployed}"/>
        </nestedNode>
      </packagedElement>
""" + _ARTIFACT.format(manifests=manifests)


def _hosts(n: int, middleware: str) -> tuple[str, str]:
    """N/100 hosts, 2 processes each, 5 threads a process, a component set per process (shape deployment):
    the platform's elements and their stereotype applications."""
    hosts = max(1, -(-n // _HOST))
    per_process = -(-_HOST // 2)
    nodes, stereo = [], []
    for h in range(hosts):
        envs, deps = [], []
        for p in range(2):
            members = range(h * _HOST + p * per_process, min(n, h * _HOST + (p + 1) * per_process))
            if not members:
                continue
            threads = []
            for t in range(_THREADS):
                on = [i for i in members if i % _THREADS == t]
                lines = "".join(f'            <deployment xmi:id="_d{i}" client="_h{h}p{p}t{t}" supplier="_P{i}" '
                                f'deployedArtifact="_P{i}"/>\n' for i in on)
                threads.append(f'          <nestedNode xmi:type="uml:ExecutionEnvironment" xmi:id="_h{h}p{p}t{t}" '
                               f'name="h{h}p{p}t{t}">\n{lines}          </nestedNode>\n')
                stereo.append(f'  <robomda:Thread xmi:id="_h{h}p{p}t{t}_st" base_ExecutionEnvironment="_h{h}p{p}t{t}" '
                              f'period="0.01" priority="{10 + t}" scheduler="RT"/>\n')
            envs.append(f'        <nestedNode xmi:type="uml:ExecutionEnvironment" xmi:id="_h{h}p{p}" name="h{h}p{p}">\n'
                        f'{"".join(threads)}        </nestedNode>\n')
            stereo.append(f'  <robomda:Middleware xmi:id="_h{h}p{p}_st" base_ExecutionEnvironment="_h{h}p{p}" '
                          f'kind="{middleware}"/>\n')
            manifests = "".join(f'        <manifestation xmi:id="_m{i}" client="_s{h}p{p}" supplier="_P{i}" '
                                f'utilizedElement="_P{i}"/>\n' for i in members)
            deps.append(f'        <deployment xmi:id="_s{h}p{p}_d" client="_h{h}" supplier="_s{h}p{p}" '
                        f'deployedArtifact="_s{h}p{p}"/>\n')
            nodes.append(f'      <packagedElement xmi:type="uml:Artifact" xmi:id="_s{h}p{p}" name="set{h}p{p}">\n'
                         f'{manifests}      </packagedElement>\n')
            stereo.append(f'  <robomda:ComponentSet xmi:id="_s{h}p{p}_st" base_Artifact="_s{h}p{p}"/>\n')
        nodes.append(f'      <packagedElement xmi:type="uml:Node" xmi:id="_h{h}" name="host{h}">\n{"".join(deps)}'
                     f'{"".join(envs)}      </packagedElement>\n')
        stereo.append(f'  <robomda:Host xmi:id="_h{h}_st" base_Node="_h{h}" hostname="host{h}" address="10.0.0.{h % 250 + 1}" cores="8" memory="16384" realTime="true"/>\n')
    for h in range(hosts if hosts > 1 else 0):
        if hosts == 2 and h == 1:
            break
        other = (h + 1) % hosts
        nodes.append(f"""      <packagedElement xmi:type="uml:CommunicationPath" xmi:id="_lan{h}" name="lan{h}" memberEnd="_lan{h}a _lan{h}b">
        <ownedEnd xmi:type="uml:Property" xmi:id="_lan{h}a" name="host{h}" type="_h{h}" association="_lan{h}"/>
        <ownedEnd xmi:type="uml:Property" xmi:id="_lan{h}b" name="host{other}" type="_h{other}" association="_lan{h}"/>
      </packagedElement>
""")
    return "".join(nodes), "".join(stereo)


def _platform(n: int, shape: str, middleware: str) -> tuple[str, str]:
    """The platform package and the stereotype applications after the model."""
    if shape == "deployment":
        nodes, stereo = _hosts(n, middleware)
        manifests = "\n".join(f'        <manifestation xmi:id="_M{i}" client="_lib" supplier="_D{i}" '
                              f'utilizedElement="_D{i}"/>' for i in range(n))
        nodes += _ARTIFACT.format(manifests=manifests)
    else:
        nodes, stereo = _one_environment(n, shape, middleware), ""
    return (f"""    </packagedElement>
    <packagedElement xmi:type="uml:Package" xmi:id="_platform" name="platform">
{nodes}    </packagedElement>
  </uml:Model>
""", stereo)


def synth_model(n: int, shape: str = "ring", middleware: str = "OROCOS") -> str:
    """The XMI text of ``n`` components in ``shape`` (one of SHAPES), deployed on ``middleware`` (OROCOS, ROS or
    ROS2)."""
    if shape not in SHAPES:
        raise ValueError(f"unknown shape {shape!r}: one of {', '.join(SHAPES)}")
    body = [_HEAD.format(n=n)]
    if shape == "datatypes":
        body.append(_header_type())
    body.extend(_component(i, n, shape) for i in range(n))
    if shape == "nested":
        body.append(_nested_system(n))
    elif shape != "ring":
        body.append(_flat_system(n, shape))
    platform, stereotypes = _platform(n, shape, middleware)
    return "".join(body) + platform + stereotypes + "</xmi:XMI>\n"


def write_model(n: int, path: Path, shape: str = "ring", middleware: str = "OROCOS") -> Path:
    path.write_text(synth_model(n, shape, middleware), encoding="utf-8")
    return path


if __name__ == "__main__":
    sys.stdout.write(synth_model(int(sys.argv[1]) if len(sys.argv) > 1 else 100,
                                 sys.argv[2] if len(sys.argv) > 2 else "ring",
                                 sys.argv[3] if len(sys.argv) > 3 else "OROCOS"))
