"""Builder of small component models for the user-code tests (issue 31 item 3): components with
no realizing class (each gets a generated base and a user class written once), their ports and
properties, and a top composite with one part of each (the instances).

A model is a tuple of :class:`Comp`; ids are the components' and ports' own (``key``), so that
a rename keeps the id (the model element is the same) and a removal drops it. ``rich`` gives
each component what else a user class implements or uses: protected operations of each
std_srvs shape (services), attributes of a data type, an enumeration, a string, an integer
(parameters), and a connector from each output to the next component's input of that name.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["Comp", "Port", "xmi", "write"]

_LIB = "pathmap://UML_LIBRARIES/UMLPrimitiveTypes.library.uml#"
_REAL = f'<type xmi:type="uml:PrimitiveType" href="{_LIB}Real"/>'
_RICH_TYPES = (
    '    <packagedElement xmi:type="uml:Enumeration" xmi:id="_uMode" name="Mode">\n'
    '      <ownedLiteral xmi:id="_uModeIdle" name="IDLE"/>\n      <ownedLiteral xmi:id="_uModeRun" name="RUN"/>\n'
    '    </packagedElement>\n'
    '    <packagedElement xmi:type="uml:DataType" xmi:id="_uGains" name="Gains">\n'
    f'      <ownedAttribute xmi:id="_uGainsKp" name="kp">{_REAL}<defaultValue xmi:type="uml:LiteralReal" '
    'xmi:id="_uGainsKpD" value="2.5"/></ownedAttribute>\n'
    f'      <ownedAttribute xmi:id="_uGainsKd" name="kd">{_REAL}</ownedAttribute>\n'
    '    </packagedElement>\n')


def _rich_members(key: str) -> str:
    """Protected operations of each std_srvs shape and parameters of each kind, for component ``key``."""
    bool_type = f'<type xmi:type="uml:PrimitiveType" href="{_LIB}Boolean"/>'
    return (f'      <ownedAttribute xmi:id="_u{key}Mode" name="mode" visibility="protected" type="_uMode"/>\n'
            f'      <ownedAttribute xmi:id="_u{key}Gains" name="gains" visibility="protected" type="_uGains"/>\n'
            f'      <ownedAttribute xmi:id="_u{key}Label" name="label" visibility="public"><type href="{_LIB}String"/>'
            f'<defaultValue xmi:type="uml:LiteralString" xmi:id="_u{key}LabelD" value="left"/></ownedAttribute>\n'
            f'      <ownedAttribute xmi:id="_u{key}Count" name="count" visibility="public"><type href="{_LIB}Integer"/>'
            f'<defaultValue xmi:type="uml:LiteralInteger" xmi:id="_u{key}CountD" value="3"/></ownedAttribute>\n'
            f'      <ownedOperation xmi:id="_u{key}Reset" name="reset" visibility="protected"/>\n'
            f'      <ownedOperation xmi:id="_u{key}Cal" name="calibrate" visibility="protected">\n'
            f'        <ownedParameter xmi:id="_u{key}CalR" name="result" direction="return">{bool_type}</ownedParameter>\n'
            f'      </ownedOperation>\n'
            f'      <ownedOperation xmi:id="_u{key}En" name="enable" visibility="protected">\n'
            f'        <ownedParameter xmi:id="_u{key}EnA" name="on" direction="in">{bool_type}</ownedParameter>\n'
            f'      </ownedOperation>\n')


@dataclass(frozen=True)
class Port:
    key: str        # stable id part
    name: str
    direction: str  # "in" or "out"


@dataclass(frozen=True)
class Comp:
    key: str
    name: str
    ports: tuple[Port, ...] = ()
    properties: tuple[tuple[str, str], ...] = field(default=())  # (key, name)


def _component(c: Comp, rich: bool) -> list[str]:
    lines = [f'    <packagedElement xmi:type="uml:Component" xmi:id="_u{c.key}" name="{c.name}">\n']
    if rich:
        lines.append(_rich_members(c.key))
    for p in c.ports:
        lines.append(f'      <ownedAttribute xmi:type="uml:Port" xmi:id="_u{c.key}P{p.key}" name="{p.name}" '
                     f'type="_u{c.key}I{p.key}" aggregation="composite"/>\n')
    for key, name in c.properties:
        lines.append(f'      <ownedAttribute xmi:type="uml:Property" xmi:id="_u{c.key}A{key}" name="{name}" visibility="public">'
                     f'{_REAL}<defaultValue xmi:type="uml:LiteralReal" xmi:id="_u{c.key}A{key}d" value="1.5"/></ownedAttribute>\n')
    for p in c.ports:
        if p.direction == "out":
            lines.append(f'      <interfaceRealization xmi:type="uml:InterfaceRealization" xmi:id="_u{c.key}R{p.key}" '
                         f'client="_u{c.key}" supplier="_u{c.key}I{p.key}" contract="_u{c.key}I{p.key}"/>\n')
    lines.append('    </packagedElement>\n')
    for p in c.ports:
        lines.append(f'    <packagedElement xmi:type="uml:Interface" xmi:id="_u{c.key}I{p.key}" name="I{c.name}{p.key}">\n'
                     f'      <ownedAttribute xmi:type="uml:Property" xmi:id="_u{c.key}I{p.key}d" name="{p.name}">{_REAL}'
                     f'</ownedAttribute>\n    </packagedElement>\n')
        if p.direction == "in":
            lines.append(f'    <packagedElement xmi:type="uml:Usage" xmi:id="_u{c.key}U{p.key}" client="_u{c.key}" '
                         f'supplier="_u{c.key}I{p.key}"/>\n')
    return lines


def xmi(comps: tuple[Comp, ...], name: str = "usercode", rich: bool = False) -> str:
    """The XMI text (Eclipse UML2) of the components and a top composite holding a part of each."""
    body = ([_RICH_TYPES] if rich else []) + [line for c in comps for line in _component(c, rich)]
    body.append('    <packagedElement xmi:type="uml:Component" xmi:id="_uTop" name="System">\n')
    body += [f'      <ownedAttribute xmi:type="uml:Property" xmi:id="_uPart{c.key}" name="{c.name[0].lower() + c.name[1:]}" '
             f'type="_u{c.key}" aggregation="composite"/>\n' for c in comps]
    body.append('    </packagedElement>\n')
    return ('<?xml version="1.0" encoding="UTF-8"?>\n'
            '<xmi:XMI xmi:version="20131001" xmlns:xmi="http://www.omg.org/spec/XMI/20131001" '
            'xmlns:uml="http://www.eclipse.org/uml2/5.0.0/UML">\n'
            f'  <uml:Model xmi:id="_uModel" name="{name}">\n' + "".join(body) + '  </uml:Model>\n</xmi:XMI>\n')


def write(path: Path, comps: tuple[Comp, ...], rich: bool = False) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(xmi(comps, rich=rich), encoding="utf-8")
    return path
