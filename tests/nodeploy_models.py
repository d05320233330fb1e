"""Builders of component models with no deployment yet (issue 30 item 1), in the dialects of
Eclipse UML2 / Papyrus and Enterprise Architect.

``component_model(dialect, ...)`` writes the first model a robot developer draws: two
components with ports typed by one interface (provided by the driver, required by the
planner), a top composite with a part of each and an assembly connector between them, and
no platform at all. Options add a platform piece by piece: a Node (``node``), an
ExecutionEnvironment in it (``environment``: its name), a second one named ``deploy``
holding the driver's part by a Deployment, an Artifact nested in the first environment
that manifests the planner's part (``nested_artifact``), a «Host» memory / «Bus» bandwidth / «Activity» period written with
units (``host_memory``, ``bandwidth``, ``period``).
"""

from __future__ import annotations

from pathlib import Path

__all__ = ["component_model", "write"]

_HEADS = {
    "eclipse": ('<xmi:XMI xmi:version="20131001" xmlns:xmi="http://www.omg.org/spec/XMI/20131001" '
                'xmlns:uml="http://www.eclipse.org/uml2/5.0.0/UML" xmlns:robomda="http://robomda.org/profile/robomda/1">\n'
                '  <uml:Model xmi:id="{p}M" name="rover">\n'),
    "ea": ('<xmi:XMI xmi:version="2.1" xmlns:uml="http://schema.omg.org/spec/UML/2.1" '
           'xmlns:xmi="http://schema.omg.org/spec/XMI/2.1" xmlns:robomda="http://robomda.org/profile/robomda/1">\n'
           '  <xmi:Documentation exporter="Enterprise Architect" exporterVersion="6.5"/>\n'
           '  <uml:Model xmi:type="uml:Model" xmi:id="{p}M" name="rover" visibility="public">\n'),
}
_REAL = {"eclipse": '<type xmi:type="uml:PrimitiveType" href="pathmap://UML_LIBRARIES/UMLPrimitiveTypes.library.uml#Real"/>',
         "ea": '<type xmi:idref="EAJava_double"/>'}


def component_model(dialect: str = "eclipse", *, node: bool = False, environment: str = "", deploy: str = "",
                    nested_artifact: bool = False, host_memory: str = "", bandwidth: str = "", period: str = "") -> str:
    """The XMI text of the rover model (see the module's doc)."""
    p = "EAID_" if dialect == "ea" else "_nd"
    real = _REAL[dialect]
    body = [
        f'    <packagedElement xmi:type="uml:Interface" xmi:id="{p}IOdom" name="IOdometry">\n'
        f'      <ownedAttribute xmi:type="uml:Property" xmi:id="{p}IOdomPose" name="pose">{real}</ownedAttribute>\n'
        f'    </packagedElement>\n',
        f'    <packagedElement xmi:type="uml:Component" xmi:id="{p}Wheel" name="WheelDriver">\n'
        f'      <ownedAttribute xmi:type="uml:Port" xmi:id="{p}WheelOut" name="odometry" type="{p}IOdom" aggregation="composite"/>\n'
        f'      <interfaceRealization xmi:type="uml:InterfaceRealization" xmi:id="{p}WheelReal" client="{p}Wheel" '
        f'supplier="{p}IOdom" contract="{p}IOdom"/>\n'
        f'    </packagedElement>\n',
        f'    <packagedElement xmi:type="uml:Component" xmi:id="{p}Plan" name="Planner">\n'
        f'      <ownedAttribute xmi:type="uml:Port" xmi:id="{p}PlanIn" name="odometry" type="{p}IOdom" aggregation="composite"/>\n'
        f'    </packagedElement>\n',
        f'    <packagedElement xmi:type="uml:Usage" xmi:id="{p}PlanUse" client="{p}Plan" supplier="{p}IOdom"/>\n',
        f'    <packagedElement xmi:type="uml:Component" xmi:id="{p}Rover" name="Rover">\n'
        f'      <ownedAttribute xmi:type="uml:Property" xmi:id="{p}PartW" name="wheels" type="{p}Wheel" aggregation="composite"/>\n'
        f'      <ownedAttribute xmi:type="uml:Property" xmi:id="{p}PartP" name="planner" type="{p}Plan" aggregation="composite"/>\n'
        f'      <ownedConnector xmi:type="uml:Connector" xmi:id="{p}Conn" name="odom">\n'
        f'        <end xmi:type="uml:ConnectorEnd" xmi:id="{p}ConnA" role="{p}WheelOut" partWithPort="{p}PartW"/>\n'
        f'        <end xmi:type="uml:ConnectorEnd" xmi:id="{p}ConnB" role="{p}PlanIn" partWithPort="{p}PartP"/>\n'
        f'      </ownedConnector>\n'
        f'    </packagedElement>\n',
    ]
    if node:
        inner = ""
        if environment:
            nested = (f'        <nestedClassifier xmi:type="uml:Artifact" xmi:id="{p}Art" name="planner_set">\n'
                      f'          <manifestation xmi:type="uml:Manifestation" xmi:id="{p}Man" client="{p}Art" '
                      f'supplier="{p}PartP" utilizedElement="{p}PartP"/>\n'
                      f'        </nestedClassifier>\n') if nested_artifact else ""
            inner = (f'      <nestedNode xmi:type="uml:ExecutionEnvironment" xmi:id="{p}EE" name="{environment}">\n'
                     f'{nested}      </nestedNode>\n')
            if deploy:
                inner += (f'      <nestedNode xmi:type="uml:ExecutionEnvironment" xmi:id="{p}EE2" name="{deploy}">\n'
                          f'        <deployment xmi:type="uml:Deployment" xmi:id="{p}Dep" client="{p}EE2" '
                          f'supplier="{p}PartW" deployedArtifact="{p}PartW"/>\n'
                          f'      </nestedNode>\n')
        body.append(f'    <packagedElement xmi:type="uml:Node" xmi:id="{p}PC" name="robotPC">\n{inner}    </packagedElement>\n')
        if bandwidth:
            body.append(f'    <packagedElement xmi:type="uml:Node" xmi:id="{p}PC2" name="otherPC"/>\n'
                        f'    <packagedElement xmi:type="uml:CommunicationPath" xmi:id="{p}Lan" name="lan">\n'
                        f'      <ownedEnd xmi:type="uml:Property" xmi:id="{p}Lan1" type="{p}PC" association="{p}Lan"/>\n'
                        f'      <ownedEnd xmi:type="uml:Property" xmi:id="{p}Lan2" type="{p}PC2" association="{p}Lan"/>\n'
                        f'      <memberEnd xmi:idref="{p}Lan1"/>\n      <memberEnd xmi:idref="{p}Lan2"/>\n'
                        f'    </packagedElement>\n')
    apps = []
    if host_memory:
        apps.append(f'  <robomda:Host xmi:id="{p}HostApp" base_Node="{p}PC" cores="2" memory="{host_memory}"/>\n')
    if bandwidth:
        apps.append(f'  <robomda:Bus xmi:id="{p}BusApp" base_CommunicationPath="{p}Lan" bandwidth="{bandwidth}"/>\n')
    if period:
        apps.append(f'  <robomda:Activity xmi:id="{p}ActApp" base_Component="{p}Wheel" period="{period}"/>\n')
    tail = "  </uml:Model>\n" + "".join(apps)
    if dialect == "ea":
        tail += ('  <xmi:Extension extender="Enterprise Architect" extenderID="6.5">\n'
                 f'    <elements><element xmi:idref="{p}Wheel" name="WheelDriver"/></elements>\n'
                 '  </xmi:Extension>\n')
    return ('<?xml version="1.0" encoding="UTF-8"?>\n' + _HEADS[dialect].format(p=p) + "".join(body) + tail
            + "</xmi:XMI>\n")


def write(path: Path, dialect: str = "eclipse", **options: object) -> Path:
    """Write :func:`component_model` to ``path`` and return it."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(component_model(dialect, **options), encoding="utf-8")  # type: ignore[arg-type]
    return path
