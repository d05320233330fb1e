<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/connector-ends.xsl - nested connector ends: the path of parts
  from the connector's classifier down to the part whose port a connector
  end joins.

  Reads:   the normalised XMI (see xmi-common.xsl).
  Writes:  nothing itself; fp:end-path (used by the connector rule of
           application.xsl and by report.xsl) and fp:path-start (used by
           fp:connector-owner).
  Params:  none.
  Errors:  none raised; a connector with an end whose path cannot be
           followed is not imported and report.xsl names it (IMP110, with
           the reason fp:end-path gives).

  Rules
  - A UML connector end joins a port (role) of a part (partWithPort) of
    the classifier that owns the connector. An end on a port of a part of
    a part needs the whole path, else it joins the wrong instance:
    SysML's NestedConnectorEnd stereotype (Papyrus, MagicDraw / Cameo: any
    namespace, base_ConnectorEnd) lists it in propertyPath (ids, or child
    elements with xmi:idref), from a part of the connector's classifier to
    the part typed by the role's owner, which MagicDraw also writes as
    partWithPort (a partWithPort that is not the path's last step is added
    to it); a path whose last step is the end's role itself (some
    exporters write the port too) is the path to the role's part. A tool
    without SysML may write only partWithPort, a part of a
    part: the path is then the one chain of parts from the connector's
    classifier down to it; none (a part a general owns, say) leaves the
    end as written, several is ambiguous.
  - The path is written to pim:end/@path (ids, outermost first) when it
    has more than one step; pim:end/@part is its last step. The bind step
    instantiates the end at that path (xslt/m2m/bind/composites.xsl).
  - A path that cannot be followed (a step not in the file or in another
    file, a step that is no part of the one before, a first step that is
    no part of the connector's classifier, several chains of parts to a
    partWithPort) refuses the connector: IMP110 names the end and why.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:x="urn:robomda:import:xmi"
    exclude-result-prefixes="#all">

  <!-- the SysML NestedConnectorEnd application on connector end $end, if any -->
  <xsl:function name="fp:nested-end" as="element()?">
    <xsl:param name="end" as="element()"/>
    <xsl:sequence select="key('fp:stereotype-by-base', fp:id($end), root($end))[local-name() eq 'NestedConnectorEnd'][1]"/>
  </xsl:function>

  <!-- the first step of $end's propertyPath, else its partWithPort: the
       part that tells which classifier a connector belongs to -->
  <xsl:function name="fp:path-start" as="element()?">
    <xsl:param name="end" as="element()"/>
    <xsl:sequence select="(fp:nested-end($end) ! fp:targets(., 'propertyPath'), fp:targets($end, 'partWithPort'))[1]"/>
  </xsl:function>

  <!-- map { 'steps': the parts from a part of $owner (the connector's
       classifier) down to the part whose port $end's role is, outermost
       first (one step: partWithPort; none: an end on $owner's own port or
       part), 'problem': why the path cannot be followed, if it cannot } -->
  <xsl:function name="fp:end-path" as="map(*)">
    <xsl:param name="end" as="element()"/>
    <xsl:param name="owner" as="element()?"/>
    <xsl:variable name="nested" as="element()?" select="fp:nested-end($end)"/>
    <xsl:variable name="pwp" as="element()?" select="fp:targets($end, 'partWithPort')[1]"/>
    <xsl:choose>
      <xsl:when test="exists($nested)">
        <xsl:variable name="written" as="xs:string*" select="fp:ref-ids($nested, 'propertyPath')"/>
        <!-- a path that ends in the role itself (some exporters write the
             port as its last step) is the path to the role's part: the
             role is not followed again -->
        <xsl:variable name="ids" as="xs:string*"
            select="if (count($written) gt 1 and $written[last()] = fp:ref-ids($end, 'role')) then $written[position() lt last()]
                    else $written"/>
        <xsl:variable name="steps" as="element()*" select="$ids ! fp:element($end, .)"/>
        <xsl:sequence select="
            if (exists($nested/propertyPath/@href))
            then fp:path-problem('its propertyPath runs through another model file')
            else if (count($steps) ne count($ids))
            then fp:path-problem('its propertyPath names ''' || string-join($ids[empty(fp:element($end, .))], ''', ''')
                                 || ''', which is not in the file')
            else fp:checked-path(($steps, $pwp[not(. is $steps[last()])]), $owner)"/>
      </xsl:when>
      <xsl:when test="exists($pwp) and exists($owner) and not($pwp/.. is $owner)">
        <xsl:variable name="chains" as="xs:string*" select="fp:chains-to($owner, $pwp, $owner)"/>
        <xsl:sequence select="
            if (count($chains) gt 1)
            then fp:path-problem('its partWithPort ' || fp:label($pwp) || ' is a part of a part that '
                                 || fp:label($owner) || ' holds ' || count($chains)
                                 || ' times: say which with a SysML NestedConnectorEnd (propertyPath)')
            else map { 'steps': if (exists($chains)) then tokenize($chains) ! fp:element($end, .) else $pwp }"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:sequence select="map { 'steps': $pwp }"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <xsl:function name="fp:path-problem" as="map(*)">
    <xsl:param name="problem" as="xs:string"/>
    <xsl:sequence select="map { 'steps': (), 'problem': $problem }"/>
  </xsl:function>

  <!-- $steps as an end path of a connector of $owner, or the problem:
       the first a part of $owner, each other one a part of the type of the
       one before -->
  <xsl:function name="fp:checked-path" as="map(*)">
    <xsl:param name="steps" as="element()*"/>
    <xsl:param name="owner" as="element()?"/>
    <xsl:variable name="broken" as="xs:integer?"
        select="(for $i in 1 to count($steps) return
                 $i[not($steps[$i]/.. is (if ($i eq 1) then $owner else fp:type-element($steps[$i - 1])))])[1]"/>
    <xsl:sequence select="
        if (empty($broken)) then map { 'steps': $steps }
        else fp:path-problem('its path ' || string-join($steps ! string(@name), '.') || ' is broken at '
            || fp:label($steps[$broken]) || ', which is no part of '
            || (if ($broken eq 1) then (if ($owner) then fp:label($owner) else 'the connector''s classifier')
                else 'the type of ' || fp:label($steps[$broken - 1])))"/>
  </xsl:function>

  <!-- the chains of parts (ids, space-separated) from classifier
       $classifier down to the part $target ($seen: the classifiers walked,
       so a model whose composition is a cycle ends) -->
  <xsl:function name="fp:chains-to" as="xs:string*">
    <xsl:param name="classifier" as="element()"/>
    <xsl:param name="target" as="element()"/>
    <xsl:param name="seen" as="element()*"/>
    <xsl:for-each select="$classifier/ownedAttribute[not(@x:type eq 'Port')]">
      <xsl:variable name="type" as="element()?" select="fp:type-element(.)[@x:type = ('Class', 'Component')]"/>
      <xsl:choose>
        <xsl:when test=". is $target">
          <xsl:sequence select="fp:id(.)"/>
        </xsl:when>
        <xsl:when test="exists($type) and not(some $s in $seen satisfies $s is $type)">
          <xsl:variable name="part" as="xs:string" select="fp:id(.)"/>
          <xsl:sequence select="fp:chains-to($type, $target, ($seen, $type)) ! ($part || ' ' || .)"/>
        </xsl:when>
      </xsl:choose>
    </xsl:for-each>
  </xsl:function>
</xsl:stylesheet>
