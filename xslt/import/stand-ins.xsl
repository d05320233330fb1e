<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/stand-ins.xsl - the services of a tool's library that is not
  shipped with the model, stood in from their references alone.

  Papyrus for Robotics types most ports by the service definitions of its
  ROS 2 library (pathmap://ROS2_LIB_BASE/services/sensor_msgs.servicedef.uml
  #svcdefs/P_Image): an Eclipse plug-in's file, never beside the model. The
  reference itself names the ROS package, the communication pattern (the
  name's prefix) and the message, so the import stands in the service
  definition instead of losing the port.

  Reads:   the original XMI (mode mp:normalise-extra, which the normalisation
           of xmi-common.xsl applies to every element with an href): a
           supplier or contract whose href a d:library-service rule of
           dialects.xml matches; then the normalised document.
  Writes:  on such a reference, x:idref (the stand-in's id,
           robomda.lib.<package>.<name>) and x:stand-in (a marker, so the
           references are found by key); fp:with-stand-ins:
           the normalised document unchanged when it has no such reference,
           else a copy with, inside the model element, a Package per
           library package (robomda.lib.<package>, named after it) holding
           an Interface per service named (named as in the library, its
           template binding's argument the rule's datum, an href into the
           library whose type primitive-types.xml names), and at the top
           the dialect's stereotype application that makes each one a
           service definition (so dialects.xsl reads its pattern as for a
           service definition of the model).
  Params:  none.  Keys: fp:stand-in (asked only when the model uses a
           dialect: fp:dialect-use of dialects.xsl).
  Errors:  none. What a target cannot do with a library message it says
           itself, located (ORO001; RTM001, a warning; RTM021).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:mp="urn:robomda:xslt:mode:private"
    xmlns:d="urn:robomda:dialects"
    xmlns:u="urn:robomda:import:uml"
    xmlns:x="urn:robomda:import:xmi"
    exclude-result-prefixes="#all">

  <!-- the rule whose href pattern reference $href matches -->
  <xsl:function name="fp:library-service" as="element(d:library-service)?">
    <xsl:param name="href" as="xs:string"/>
    <xsl:sequence select="$fp:dialects/d:library-service[matches($href, @href)][1]"/>
  </xsl:function>

  <!-- the stand-in's id for a reference $href that rule $rule matches -->
  <xsl:function name="fp:stand-in-id" as="xs:string">
    <xsl:param name="href" as="xs:string"/>
    <xsl:param name="rule" as="element(d:library-service)"/>
    <xsl:sequence select="'robomda.lib.' || replace($href, $rule/@href, $rule/@package) || '.'
                          || replace($href, $rule/@href, $rule/@name)"/>
  </xsl:function>

  <xsl:template match="*[local-name() = ('supplier', 'contract')][exists(fp:library-service(@href))]"
                mode="mp:normalise-extra" as="attribute()+">
    <xsl:attribute name="x:idref" select="fp:stand-in-id(@href, fp:library-service(@href))"/>
    <xsl:attribute name="x:stand-in" select="'true'"/>
  </xsl:template>

  <xsl:key name="fp:stand-in" match="*[@x:stand-in]" use="'any'"/>

  <!-- $norm with the stand-ins its references name (see the header) -->
  <xsl:function name="fp:with-stand-ins" as="document-node()">
    <xsl:param name="norm" as="document-node()"/>
    <!-- a model in no dialect (most) asks the key of its stereotype
         applications only, not a scan of every element -->
    <xsl:variable name="refs" as="element()*"
        select="if (empty(key('fp:dialect-use', 'any', $norm))) then () else key('fp:stand-in', 'any', $norm)"/>
    <xsl:choose>
      <xsl:when test="empty($refs)">
        <xsl:sequence select="$norm"/>
      </xsl:when>
      <xsl:otherwise>
        <!-- one stand-in per service, whichever file names it how often -->
        <xsl:variable name="services" as="map(*)*">
          <xsl:for-each-group select="$refs" group-by="string(@x:idref)">
            <xsl:sort select="current-grouping-key()"/>
            <xsl:variable name="href" as="xs:string" select="current-group()[1]/@href"/>
            <xsl:variable name="rule" as="element(d:library-service)" select="fp:library-service($href)"/>
            <xsl:sequence select="map { 'id': current-grouping-key(), 'rule': $rule,
                'package': replace($href, $rule/@href, $rule/@package),
                'name': replace($href, $rule/@href, $rule/@name),
                'datum': replace($href, $rule/@href, $rule/@datum) }"/>
          </xsl:for-each-group>
        </xsl:variable>
        <xsl:document>
          <xsl:apply-templates select="$norm/node()" mode="mp:stand-in">
            <xsl:with-param name="services" as="map(*)*" select="$services" tunnel="yes"/>
            <xsl:with-param name="model-el" as="element()" select="fp:model-el($norm)" tunnel="yes"/>
          </xsl:apply-templates>
        </xsl:document>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <xsl:mode name="mp:stand-in" on-no-match="shallow-copy"/>

  <!-- the stereotype applications, after the document's own -->
  <xsl:template match="/x:XMI" mode="mp:stand-in">
    <xsl:param name="services" as="map(*)*" tunnel="yes"/>
    <xsl:copy>
      <xsl:apply-templates select="@* | node()" mode="#current"/>
      <xsl:for-each select="$services">
        <xsl:variable name="rule" as="element(d:library-service)" select="?rule"/>
        <xsl:element name="{$rule/@prefix}:{$rule/@stereotype}" namespace="{$rule/@namespace}">
          <xsl:attribute name="x:id" select="?id || '.' || $rule/@stereotype"/>
          <xsl:attribute name="base_Interface" select="?id"/>
        </xsl:element>
      </xsl:for-each>
    </xsl:copy>
  </xsl:template>

  <!-- the library's packages, last in the model element -->
  <xsl:template match="u:Model | u:Package" mode="mp:stand-in">
    <xsl:param name="services" as="map(*)*" tunnel="yes"/>
    <xsl:param name="model-el" as="element()" tunnel="yes"/>
    <xsl:copy>
      <xsl:apply-templates select="@* | node()" mode="#current"/>
      <xsl:if test=". is $model-el">
        <xsl:for-each-group select="$services" group-by="?package">
          <packagedElement x:type="Package" x:id="robomda.lib.{current-grouping-key()}" name="{current-grouping-key()}">
            <xsl:for-each select="current-group()">
              <packagedElement x:type="Interface" x:id="{?id}" name="{?name}">
                <templateBinding x:id="{?id}.binding">
                  <parameterSubstitution x:id="{?id}.datum">
                    <actual x:type="DataType" href="{?datum}"/>
                  </parameterSubstitution>
                </templateBinding>
              </packagedElement>
            </xsl:for-each>
          </packagedElement>
        </xsl:for-each-group>
      </xsl:if>
    </xsl:copy>
  </xsl:template>
</xsl:stylesheet>
