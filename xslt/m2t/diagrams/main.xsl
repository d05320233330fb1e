<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/diagrams/main.xsl - bound PIM -> file set of PlantUML diagrams.

  Reads:   the bound PIM, urn:robomda:pim:1 (schemas/pim/1/pim.xsd with its
           binding, schemas/pim/1/binding.xsd), from xslt/m2m/bind.xsl.
  Writes:  urn:robomda:fileset:1 (schemas/fileset/1/fileset.xsd), target
           "diagrams", two generated files:
             diagrams/<model>-components.puml  the component view
                                                (diagrams-components.xsl)
             diagrams/<model>-deployment.puml  the deployment view
                                                (diagrams-deployment.xsl)
           <model>: the model's name, each character other than a letter,
           digit, '-', '.' or '_' written '_' ("model" when it has none).
           The driver (src/robomda/diagrams.py) renders them to SVG with
           PlantUML where it is installed; pipelines/diagrams.xml.
  Params:  model-dir-from-output (from ../common/text.xsl; unused here).
  Errors:  none (the bound PIM is valid; every element is drawn).
  Modules: ../common/text.xsl, diagrams-text.xsl, diagrams-components.xsl,
           diagrams-deployment.xsl.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:fs="urn:robomda:fileset:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:t="urn:robomda:xslt:template"
    exclude-result-prefixes="#all">

  <xsl:include href="../../common/indent.xsl"/>
  <xsl:include href="../common/text.xsl"/>
  <xsl:include href="diagrams-text.xsl"/>
  <xsl:include href="diagrams-components.xsl"/>
  <xsl:include href="diagrams-deployment.xsl"/>

  <xsl:output method="xml" indent="no" encoding="UTF-8" cdata-section-elements="fs:file"/>
  <xsl:global-context-item as="document-node(element(pim:model))" use="required"/>

  <xsl:key name="fp:id" match="pim:application//*[@id] | pim:platform//*[@id]" use="@id"/>
  <xsl:key name="fp:part-by-type" match="pim:part" use="@type"/>
  <xsl:key name="fp:bc" match="pim:bound-component" use="@component"/>
  <xsl:key name="fp:instance-by-name" match="pim:binding/pim:instance" use="@name"/>
  <xsl:key name="fp:instance-by-ee" match="pim:binding/pim:instance" use="@execution-environment"/>
  <xsl:key name="fp:instance-by-thread" match="pim:binding/pim:instance" use="@thread"/>
  <xsl:key name="fp:instance-by-set" match="pim:binding/pim:instance" use="@set"/>
  <xsl:key name="fp:process" match="pim:binding/pim:process" use="@xmi-id"/>
  <xsl:key name="fp:process-by-host" match="pim:binding/pim:process" use="string(@host)"/>
  <xsl:key name="fp:host" match="pim:binding/pim:host" use="@xmi-id"/>
  <xsl:key name="fp:set-by-host" match="pim:binding/pim:component-set" use="string(pim:on[@host][1]/@host)"/>

  <xsl:variable name="fp:components-xsl" as="xs:string" select="'m2t/diagrams/diagrams-components.xsl'"/>
  <xsl:variable name="fp:deployment-xsl" as="xs:string" select="'m2t/diagrams/diagrams-deployment.xsl'"/>

  <xsl:template match="/" as="document-node()">
    <xsl:variable name="model" as="element(pim:model)" select="pim:model"/>
    <xsl:variable name="stem" as="xs:string"
        select="(replace(normalize-space($model/@name), '[^A-Za-z0-9._\-]', '_')[. ne ''][not(starts-with(., '.'))], 'model')[1]"/>
    <xsl:document>
      <fs:files target="diagrams">
        <xsl:call-template name="t:indented-content">
          <xsl:with-param name="children" select="(
              fp:file('diagrams/' || $stem || '-components.puml', 'generated', $fp:components-xsl, fp:component-view($model)),
              fp:file('diagrams/' || $stem || '-deployment.puml', 'generated', $fp:deployment-xsl, fp:deployment-view($model)))"/>
          <xsl:with-param name="margin" select="'&#10;'"/>
        </xsl:call-template>
      </fs:files>
    </xsl:document>
  </xsl:template>
</xsl:stylesheet>
