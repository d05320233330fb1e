<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/bind/classes.xsl - bind (xslt/m2m/bind.xsl): classes taken as
  components.

  Reads:   a PIM (urn:robomda:pim:1), as import.xsl wrote it.
  Writes:  the same PIM with each class that is a component by the rule
           below written as a pim:component (same id, name, decoration,
           ports, parts, attributes, operations, connectors and nested
           classifiers; @drawn-as="class", @dialect kept), for the rest of
           bind to bind as any component (fp:promoted-classes,
           fp:with-classes-as-components).
  Params:  none.  Keys: fp:part-by-type (bind.xsl), fp:realized-by.
  Errors:  none.

  The rule (docs/profile.md, "Components drawn as classes"): the robotics
  modelling tools draw components as classes with ports, in their own
  profiles. A class is a component when
  1. its tool's profile says so (pim:class/@component: RobotML's «System»
     family ..., xslt/import/dialects.xml), or
  2. it has ports and is the type of a part (it is used as a component),
  3. or one of its parts is typed by a component (by 1, 2, 3, or a
     uml:Component): a composite of components is a component;
  and it is not the realizing class of a component (that class is the
  component's atomic code, seed 000). A class with ports that none of
  these makes a component stays a class: ORO005 names it when nothing is
  left to generate (xslt/m2m/common/psm-kit.xsl).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:mp="urn:robomda:xslt:mode:private"
    exclude-result-prefixes="#all">

  <xsl:key name="fp:realized-by" match="pim:component/pim:realization" use="@classifier"/>

  <!-- the classes of $model that the rule above makes components -->
  <xsl:function name="fp:promoted-classes" as="element(pim:class)*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:variable name="root" as="document-node()" select="root($model)"/>
    <xsl:variable name="classes" as="element(pim:class)*"
        select="$model/pim:application//pim:class[empty(key('fp:realized-by', @id, $root))]
                                                  [not(@component = ('false', '0'))]"/>
    <xsl:variable name="seeds" as="element(pim:class)*"
        select="$classes[@component = ('true', '1') or (pim:port and exists(key('fp:part-by-type', @id, $root)))]"/>
    <xsl:variable name="components" as="map(xs:string, xs:boolean)"
        select="map:merge(($model/pim:application//pim:component, $seeds) ! map:entry(string(@id), true()))"/>
    <xsl:sequence select="fp:composites-of($classes except $seeds, $components, $seeds)"/>
  </xsl:function>

  <!-- $found, and the classes of $rest whose parts are typed by a
       component ($components: ids), repeated until none is added (one
       round per level of nesting) -->
  <xsl:function name="fp:composites-of" as="element(pim:class)*">
    <xsl:param name="rest" as="element(pim:class)*"/>
    <xsl:param name="components" as="map(xs:string, xs:boolean)"/>
    <xsl:param name="found" as="element(pim:class)*"/>
    <xsl:variable name="new" as="element(pim:class)*"
        select="$rest[some $t in pim:part/@type satisfies map:contains($components, $t)]"/>
    <xsl:sequence select="if (empty($new)) then $found
        else fp:composites-of($rest except $new,
                              map:merge(($components, map:merge($new ! map:entry(string(@id), true())))),
                              $found | $new)"/>
  </xsl:function>

  <!-- the PIM with the classes $promoted written as components -->
  <xsl:function name="fp:with-classes-as-components" as="document-node()">
    <xsl:param name="doc" as="document-node()"/>
    <xsl:param name="promoted" as="element(pim:class)*"/>
    <xsl:document>
      <xsl:apply-templates select="$doc/node()" mode="mp:promote">
        <xsl:with-param name="ids" tunnel="yes"
            select="map:merge($promoted ! map:entry(generate-id(.), true()))"/>
      </xsl:apply-templates>
    </xsl:document>
  </xsl:function>

  <xsl:mode name="mp:promote" on-no-match="shallow-copy"/>

  <xsl:template match="pim:class" mode="mp:promote" priority="1" as="element()">
    <xsl:param name="ids" as="map(xs:string, xs:boolean)" tunnel="yes"/>
    <xsl:choose>
      <xsl:when test="map:contains($ids, generate-id(.))">
        <pim:component>
          <xsl:copy-of select="@* except (@active, @component, @parameters)"/>
          <xsl:attribute name="drawn-as" select="'class'"/>
          <!-- the attributes of its parameter blocks are its own, after
               its own attributes -->
          <xsl:variable name="moved" as="element(pim:attribute)*" select="pim:class[@parameters = ('true', '1')]/pim:attribute"/>
          <xsl:variable name="after" as="element()?"
              select="(pim:port | pim:part | pim:operation | pim:connector | pim:attribute[last()]/following-sibling::*)[1]"/>
          <xsl:for-each select="node()">
            <xsl:if test=". is $after">
              <xsl:copy-of select="$moved"/>
            </xsl:if>
            <xsl:apply-templates select="." mode="mp:promote">
              <xsl:with-param name="moved" tunnel="yes" select="$moved"/>
            </xsl:apply-templates>
          </xsl:for-each>
          <xsl:if test="empty($after)">
            <xsl:copy-of select="$moved"/>
          </xsl:if>
        </pim:component>
      </xsl:when>
      <xsl:otherwise>
        <xsl:copy>
          <xsl:copy-of select="@*"/>
          <xsl:apply-templates mode="mp:promote"/>
        </xsl:copy>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:template>

  <!-- a parameter block's attributes moved to its component ($moved) -->
  <xsl:template match="pim:class/pim:attribute" mode="mp:promote" priority="2" as="element()?">
    <xsl:param name="moved" as="element(pim:attribute)*" tunnel="yes" select="()"/>
    <xsl:if test="not(some $m in $moved satisfies $m is current())">
      <xsl:copy-of select="."/>
    </xsl:if>
  </xsl:template>

  <!-- an attribute of a class taken as a component that is typed by a
       class its tool's profile says is no component (a Papyrus for
       Robotics «ActivityInstance»: the component's activity, which the
       binding gives every instance) is no property of the component: the
       import's PIM keeps it -->
  <xsl:template match="pim:class/pim:attribute[fp:is-activity-instance(.)]
                       | pim:class/pim:connector[pim:end/@part ! key('fp:id', .)[self::pim:attribute][fp:is-activity-instance(.)]]"
      mode="mp:promote" priority="3" as="element()?">
    <xsl:param name="ids" as="map(xs:string, xs:boolean)" tunnel="yes"/>
    <!-- dropped only from a class taken as a component; with them go the
         connectors inside the component that join the activity to the
         component's ports (the activity's side of them) -->
    <xsl:if test="not(map:contains($ids, generate-id(..)))">
      <xsl:copy-of select="."/>
    </xsl:if>
  </xsl:template>

  <xsl:function name="fp:is-activity-instance" as="xs:boolean">
    <xsl:param name="attribute" as="element(pim:attribute)"/>
    <xsl:sequence select="exists(key('fp:id', $attribute/@type, root($attribute))
                                 /self::pim:class[@component = ('false', '0')][not(@parameters = ('true', '1'))])"/>
  </xsl:function>

  <!-- below a class nothing else changes but nested classes -->
  <xsl:template match="*[not(descendant::pim:class)]" mode="mp:promote" as="element()">
    <xsl:copy-of select="."/>
  </xsl:template>
</xsl:stylesheet>
