"""Builder of small component models for the user-code tests (issue 31 item 3): components with
no realizing class (each gets a generated base and a user class written once), their ports and
properties, and a top composite with one part of each (the instances).

A model is a tuple of :class:`Comp`; ids are the components' and ports' own (``key``), so that
a rename keeps the id (the model element is the same) and a removal drops it.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["Comp", "Port", "xmi", "write"]

_REAL = '<type xmi:type="uml:PrimitiveType" href="pathmap://UML_LIBRARIES/UMLPrimitiveTypes.library.uml#Real"/>'


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


def _component(c: Comp) -> list[str]:
    lines = [f'    <packagedElement xmi:type="uml:Component" xmi:id="_u{c.key}" name="{c.name}">\n']
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


def xmi(comps: tuple[Comp, ...], name: str = "usercode") -> str:
    """The XMI text (Eclipse UML2) of the components and a top composite holding a part of each."""
    body = [line for c in comps for line in _component(c)]
    body.append('    <packagedElement xmi:type="uml:Component" xmi:id="_uTop" name="System">\n')
    body += [f'      <ownedAttribute xmi:type="uml:Property" xmi:id="_uPart{c.key}" name="{c.name[0].lower() + c.name[1:]}" '
             f'type="_u{c.key}" aggregation="composite"/>\n' for c in comps]
    body.append('    </packagedElement>\n')
    return ('<?xml version="1.0" encoding="UTF-8"?>\n'
            '<xmi:XMI xmi:version="20131001" xmlns:xmi="http://www.omg.org/spec/XMI/20131001" '
            'xmlns:uml="http://www.eclipse.org/uml2/5.0.0/UML">\n'
            f'  <uml:Model xmi:id="_uModel" name="{name}">\n' + "".join(body) + '  </uml:Model>\n</xmi:XMI>\n')


def write(path: Path, comps: tuple[Comp, ...]) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(xmi(comps), encoding="utf-8")
    return path
