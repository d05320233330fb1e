"""Synthetic UML models for the benchmark: N components in a ring.

Component i is realized by class Drv<i>, provides interface I<i> on port out
and requires I<i-1> on port in (ball-and-socket: no connectors), so the model
has N components, N classes, N interfaces, 2N ports and N connections, plus a
deployment: one node with an Orocos execution environment and one artifact.
The XMI is written in the Eclipse UML2 / Papyrus dialect.

    python bench/synth.py 1000 > /tmp/synth-1000.xmi
"""

from __future__ import annotations

import sys
from pathlib import Path

__all__ = ["synth_model", "write_model"]

_HEAD = """<?xml version="1.0" encoding="UTF-8"?>
<xmi:XMI xmi:version="20131001" xmlns:xmi="http://www.omg.org/spec/XMI/20131001" xmlns:uml="http://www.eclipse.org/uml2/5.0.0/UML">
  <uml:Model xmi:id="_model" name="Synth{n}">
    <packagedElement xmi:type="uml:Package" xmi:id="_app" name="app">
"""
_PRIM = "pathmap://UML_LIBRARIES/UMLPrimitiveTypes.library.uml#{0}"


def _component(i: int, n: int) -> str:
    prev = (i - 1) % n
    integer, real = _PRIM.format("Integer"), _PRIM.format("Real")
    return f"""      <packagedElement xmi:type="uml:Interface" xmi:id="_I{i}" name="I{i}">
        <ownedAttribute xmi:id="_I{i}_d" name="value{i}"><type xmi:type="uml:PrimitiveType" href="{integer}"/></ownedAttribute>
      </packagedElement>
      <packagedElement xmi:type="uml:Class" xmi:id="_D{i}" name="Drv{i}">
        <ownedAttribute xmi:id="_D{i}_s" name="sample" visibility="public"><type xmi:type="uml:PrimitiveType" href="{real}"/>
          <defaultValue xmi:type="uml:LiteralReal" xmi:id="_D{i}_sv" value="0.01"/></ownedAttribute>
        <ownedAttribute xmi:id="_D{i}_g" name="gain" visibility="public"><type xmi:type="uml:PrimitiveType" href="{real}"/>
          <defaultValue xmi:type="uml:LiteralReal" xmi:id="_D{i}_gv" value="1.5"/></ownedAttribute>
        <ownedOperation xmi:id="_D{i}_c" name="configure" visibility="public">
          <ownedParameter xmi:id="_D{i}_cr" direction="return"><type xmi:type="uml:PrimitiveType" href="{_PRIM.format('Boolean')}"/></ownedParameter>
        </ownedOperation>
        <ownedOperation xmi:id="_D{i}_u" name="update" visibility="public"/>
        <ownedOperation xmi:id="_D{i}_get" name="getValue{i}" visibility="public">
          <ownedParameter xmi:id="_D{i}_getr" direction="return"><type xmi:type="uml:PrimitiveType" href="{integer}"/></ownedParameter>
        </ownedOperation>
        <ownedOperation xmi:id="_D{i}_set" name="setValue{prev}" visibility="public">
          <ownedParameter xmi:id="_D{i}_setp" name="v"><type xmi:type="uml:PrimitiveType" href="{integer}"/></ownedParameter>
        </ownedOperation>
        <ownedOperation xmi:id="_D{i}_k" name="setGain" visibility="protected">
          <ownedParameter xmi:id="_D{i}_kp" name="gain"><type xmi:type="uml:PrimitiveType" href="{real}"/></ownedParameter>
        </ownedOperation>
      </packagedElement>
      <packagedElement xmi:type="uml:Component" xmi:id="_C{i}" name="Comp{i}">
        <ownedAttribute xmi:type="uml:Port" xmi:id="_C{i}_out" name="out" type="_I{i}" aggregation="composite"/>
        <ownedAttribute xmi:type="uml:Port" xmi:id="_C{i}_in" name="in" type="_I{prev}" aggregation="composite"/>
        <interfaceRealization xmi:id="_C{i}_ir" client="_C{i}" supplier="_I{i}" contract="_I{i}"/>
        <realization xmi:type="uml:ComponentRealization" xmi:id="_C{i}_cr" client="_D{i}" supplier="_C{i}" realizingClassifier="_D{i}" abstraction="_C{i}"/>
      </packagedElement>
      <packagedElement xmi:type="uml:Usage" xmi:id="_U{i}" client="_C{i}" supplier="_I{prev}"/>
"""


def _platform(n: int) -> str:
    manifests = "\n".join(
        f'        <manifestation xmi:id="_M{i}" client="_lib" supplier="_C{i}" utilizedElement="_C{i}"/>'
        for i in range(n))
    return f"""    </packagedElement>
    <packagedElement xmi:type="uml:Package" xmi:id="_platform" name="platform">
      <packagedElement xmi:type="uml:Node" xmi:id="_pc" name="pc">
        <nestedNode xmi:type="uml:ExecutionEnvironment" xmi:id="_ee" name="OROCOS">
          <deployment xmi:id="_dep" client="_ee" supplier="_lib" deployedArtifact="_lib"/>
        </nestedNode>
      </packagedElement>
      <packagedElement xmi:type="uml:Artifact" xmi:id="_lib" name="synth_atomic" fileName="atomic">
{manifests}
      </packagedElement>
    </packagedElement>
  </uml:Model>
</xmi:XMI>
"""


def synth_model(n: int) -> str:
    """The XMI text of a ring of ``n`` components."""
    return _HEAD.format(n=n) + "".join(_component(i, n) for i in range(n)) + _platform(n)


def write_model(n: int, path: Path) -> Path:
    path.write_text(synth_model(n), encoding="utf-8")
    return path


if __name__ == "__main__":
    sys.stdout.write(synth_model(int(sys.argv[1]) if len(sys.argv) > 1 else 100))
