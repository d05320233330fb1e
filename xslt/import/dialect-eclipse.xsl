<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/dialect-eclipse.xsl - Eclipse UML2 serialisations: Papyrus,
  plain Eclipse UML2 (.uml), Modelio (Objing), RobotML.

  Reads:   the original XMI (tool signatures) and the normalised XMI.
  Writes:  nothing itself; functions used by import.xsl.
  Params:  none.
  Errors:  none.

  Rules
  - The file may be a bare <uml:Model> (or <uml:Package>) without the
    xmi:XMI wrapper; then it holds no stereotype applications.
  - xmi:type is omitted when it equals the declared type of the feature
    (ownedAttribute = Property, realization = ComponentRealization ...):
    the defaults are in xmi-common.xsl ($default-metas).
  - Library types are hrefs pathmap://UML_LIBRARIES/UMLPrimitiveTypes.
    library.uml#Integer, pathmap://UML_METAMODELS/Ecore.metamodel.uml#EInt,
    pathmap://PapyrusC_Cpp_LIBRARIES/AnsiCLibrary.uml#<id> ...: the library
    patterns are data in xslt/common/primitive-types.xml.
  - Dependencies (a deployment-sequence StartAfter between parts) are
    packagedElements of the package Papyrus creates them in, client and
    supplier as id attributes; the stereotype application is a top-level
    robomda:StartAfter with base_Dependency (application.xsl reads both).
  - EMF reads xsi:type as well as xmi:type, and some exporters
    (GenMyModel) write only xsi:type: the normalisation reads it as
    xmi:type (xmi-common.xsl). UML Designer writes a relationship with
    several clients as one id list (client="class port component"):
    application.xsl imports each pair (fp:pair-id).
  - Papyrus' SysML NestedConnectorEnd (propertyPath as an id list) gives
    the path of a connector end on a port of a part of a part
    (connector-ends.xsl).
  - Template signatures: the placeholders Papyrus writes for template
    parameters (ownedParameteredElement "TemplateParameter1") are no
    classes (xmi-common.xsl; IMP118, report.xsl).
  - Empty default values are written <defaultValue xmi:type=
    "uml:LiteralString"><value xsi:nil="true"/></defaultValue>: no default.
  - Tool: Papyrus when a namespace, href or exporter names Papyrus (its
    profiles live under http://www.eclipse.org/papyrus/ or
    http://Papyrus/...); Modelio when exported by Modelio or carrying its
    "Objing" eAnnotation; otherwise eclipse-uml2 for an Eclipse UML2
    namespace.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:is-modelio" as="xs:boolean">
    <xsl:param name="doc" as="document-node()"/>
    <xsl:param name="exporter" as="xs:string"/>
    <xsl:sequence select="matches($exporter, 'modelio|objing', 'i')
        or (not($exporter) and exists(($doc/*/(self::*, *)/*[local-name() eq 'eAnnotations']
                                       [matches(@source, 'objing|modelio', 'i')])[1]))"/>
  </xsl:function>

  <xsl:function name="fp:is-papyrus" as="xs:boolean">
    <xsl:param name="doc" as="document-node()"/>
    <xsl:param name="exporter" as="xs:string"/>
    <xsl:sequence select="contains(lower-case($exporter), 'papyrus')
        or (not($exporter) and (
              (some $ns in $doc/*/namespace::* satisfies contains(lower-case($ns), 'papyrus'))
              or exists(distinct-values($doc//@href)[contains(lower-case(.), 'papyrus')][1])))"/>
  </xsl:function>

  <xsl:function name="fp:is-eclipse-uml2" as="xs:boolean">
    <xsl:param name="uml-ns" as="xs:string"/>
    <xsl:sequence select="contains($uml-ns, 'eclipse.org/uml2')"/>
  </xsl:function>
</xsl:stylesheet>
