<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/bind/devices.xsl - bind (xslt/m2m/bind.xsl): the hardware
  platform's degrees of freedom (seed 001, the DoF-mismatch warning).

  Reads:   the PIM (urn:robomda:pim:1): pim:dependency kind "drives" (a part
           or a component drives a Device: the import reads a Dependency
           whose supplier is a Device so), the Device's attribute dof (its
           default: the kinematic chain's degrees of freedom), the instances,
           bound components and connections of the binding being made.
  Writes:  nothing; warnings.
  Params:  none.  Keys: those of bind.xsl.
  Warnings (f:warn):
    BND021  a fixed-size array (multiplicity [n..n], n > 1) that an
            instance driving a Device, or an instance connected to it,
            carries on a port (the datum, or an attribute of its data type
            at any depth) or holds in an attribute, whose size is not the
            Device's degrees of freedom: once on the element and once on
            the Device, each naming the other.
    BND022  a Device some part drives that declares no degrees of freedom
            (no attribute dof with an integer default): nothing is checked.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:warn-dof" as="empty-sequence()">
    <xsl:param name="root" as="document-node()"/>
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:param name="bound" as="element(pim:bound-component)*"/>
    <xsl:param name="connections" as="element(pim:connection)*"/>
    <xsl:for-each select="$root//pim:dependency[@kind eq 'drives']">
      <xsl:variable name="drives" as="element(pim:dependency)" select="."/>
      <xsl:for-each select="pim:supplier ! key('fp:id', @element, $root)">
        <xsl:variable name="device" as="element()" select="."/>
        <xsl:variable name="dof" as="xs:string?"
            select="(fp:attributes($device)[@name eq 'dof']/@default ! normalize-space(.))[. castable as xs:integer][1]"/>
        <xsl:variable name="drivers" as="element(pim:instance)*"
            select="$instances[@xmi-id = $drives/pim:client/@element or @component = $drives/pim:client/@element]"/>
        <xsl:variable name="linked" as="element(pim:instance)*"
            select="$instances[@name = $connections[(pim:writer | pim:reader)/@instance = $drivers/@name]
                                                   /(pim:writer | pim:reader)/@instance]"/>
        <xsl:choose>
          <xsl:when test="empty($dof)">
            <xsl:sequence select="f:warn('BND022', string($device/@id), 'device ''' || $device/@name
                || ''' is driven by ' || string-join($drivers/@name, ', ')
                || ' but declares no degrees of freedom (an attribute dof with an integer default): nothing is checked')"/>
          </xsl:when>
          <xsl:otherwise>
            <xsl:sequence select="fp:dof-mismatches($root, $device, xs:integer($dof), ($drivers | $linked), $bound,
                                                    string-join($drivers/@name, ', '))"/>
          </xsl:otherwise>
        </xsl:choose>
      </xsl:for-each>
    </xsl:for-each>
  </xsl:function>

  <!-- BND021 for each array of $instances' components whose fixed size is
       not $dof: on the element, and on the device -->
  <xsl:function name="fp:dof-mismatches" as="empty-sequence()">
    <xsl:param name="root" as="document-node()"/>
    <xsl:param name="device" as="element()"/>
    <xsl:param name="dof" as="xs:integer"/>
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:param name="bound" as="element(pim:bound-component)*"/>
    <xsl:param name="drivers" as="xs:string"/>
    <xsl:variable name="components" as="element(pim:bound-component)*" select="$bound[@component = $instances/@component]"/>
    <xsl:variable name="arrays" as="element()*">
      <xsl:for-each select="$components">
        <xsl:variable name="users" as="xs:string" select="string-join($instances[@component eq current()/@component]/@name, ', ')"/>
        <xsl:for-each select="pim:data-port">
          <xsl:sequence select="fp:fixed-arrays(., 'port ''' || @port-name || ''' of ' || $users, @port, $root)"/>
        </xsl:for-each>
        <xsl:for-each select="fp:attributes(fp:feature-owner(key('fp:id', @component, $root)))[@visibility ne 'private']">
          <xsl:sequence select="fp:fixed-arrays(., 'attribute ''' || @name || ''' of ' || $users, @id, $root)"/>
        </xsl:for-each>
      </xsl:for-each>
    </xsl:variable>
    <xsl:for-each-group select="$arrays[xs:integer(@size) ne $dof]" group-by="@id">
      <xsl:variable name="what" as="xs:string"
          select="@what || ' holds ' || string-join(current-group()/@label, ', ') || ' (' || string-join(distinct-values(current-group()/@size), ', ')
                  || ' values)'"/>
      <xsl:sequence select="f:warn('BND021', string(@id), $what || ', but device ''' || $device/@name || ''' (driven by '
                                   || $drivers || ') has ' || $dof || ' degrees of freedom (DoF mismatch)')"/>
      <xsl:sequence select="f:warn('BND021', string($device/@id), 'device ''' || $device/@name || ''' (driven by ' || $drivers
                                   || ') has ' || $dof || ' degrees of freedom, but ' || $what || ' (DoF mismatch)')"/>
    </xsl:for-each-group>
  </xsl:function>

  <!-- the fixed-size arrays a typed element holds: itself, and the
       attributes of its data type at any depth; fp:array elements with
       @id (where to warn), @what, @label and @size -->
  <xsl:function name="fp:fixed-arrays" as="element()*">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:param name="root" as="document-node()"/>
    <xsl:variable name="own" as="xs:string*" select="fp:array($typed)"/>
    <xsl:if test="$own[1] eq 'fixed'">
      <fp:array id="{$id}" what="{$what}" label="{($typed/@type-name, $typed/@primitive)[1]}[{$own[2]}]" size="{$own[2]}"/>
    </xsl:if>
    <xsl:for-each select="fp:type-closure(key('fp:id', $typed/@type, $root)/self::pim:datatype)/self::pim:datatype">
      <xsl:variable name="type" as="element(pim:datatype)" select="."/>
      <xsl:for-each select="fp:attributes(.)">
        <xsl:variable name="array" as="xs:string*" select="fp:array(.)"/>
        <xsl:if test="$array[1] eq 'fixed'">
          <fp:array id="{$id}" what="{$what}" label="{$type/@name}.{@name}[{$array[2]}]" size="{$array[2]}"/>
        </xsl:if>
      </xsl:for-each>
    </xsl:for-each>
  </xsl:function>
</xsl:stylesheet>
