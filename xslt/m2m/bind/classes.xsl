<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/bind/classes.xsl - bind (xslt/m2m/bind.xsl): classes taken as
  components, and the implicit parts of components drawn in a tool's own
  profile.

  Reads:   a PIM (urn:robomda:pim:1), as import.xsl wrote it.
  Writes:  the same PIM, for the rest of bind to bind as it binds any
           model (fp:promoted-classes, fp:portless-components,
           fp:with-classes-as-components):
           - each class that is a component by the rule below written as a
             pim:component (same id, name, decoration, ports, parts,
             attributes, operations, connectors and nested classifiers;
             @drawn-as="class", @dialect kept); the attributes of its
             parameter blocks (pim:class/@parameters, a Papyrus for Robotics
             «Parameter») moved into it; its attributes typed by a class its
             profile says is no component (a Papyrus for Robotics
             «ActivityInstance»: the component's activity) and the
             connectors joining them left out; the operations of the
             interfaces it provides and does not declare copied as its own
             (ids robomda.op.<class>.<operation>: fp:provided-operations);
           - in a model that draws no system, each component that provides
             or requires interfaces with no port given a port per interface
             (pim:port/@implicit, id robomda.port.<the dependency's id>).
  Params:  none.  Keys: fp:part-by-type, fp:id (bind.xsl), fp:realized-by.
  Errors:  none. Warning BND032 (once, on the first such component):
           components with no port given ports and instances.

  The rule (docs/profile.md, "Components drawn as classes"): the robotics
  modelling tools draw components as classes with ports, in their own
  profiles. A class is a component when
  1. its tool's profile says so (pim:class/@component: RobotML's «System»
     family ..., xslt/import/dialects.xml), or
  2. it has ports and is the type of a part (it is used as a component),
  3. or one of its parts is typed by a component (by 1, 2, 3, or a
     uml:Component): a composite of components is a component;
  and it is not the realizing class of a component (that class is the
  component's atomic code, seed 000), nor a class its profile says is no
  component, nor a part of itself (a recursive pattern). A class with
  ports that none of these makes a component stays a class: ORO005 names
  it when nothing is left to generate (xslt/m2m/common/psm-kit.xsl).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:tp="urn:robomda:xslt:template:private"
    xmlns:mp="urn:robomda:xslt:mode:private"
    exclude-result-prefixes="#all">

  <xsl:key name="fp:realized-by" match="pim:component/pim:realization" use="@classifier"/>

  <!-- the classes of $model that the rule above makes components -->
  <xsl:function name="fp:promoted-classes" as="element(pim:class)*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:variable name="root" as="document-node()" select="root($model)"/>
    <!-- (not a class that is a part of itself: a recursive pattern, such as
         SysML's roll-up patterns, which no system can instantiate) -->
    <xsl:variable name="classes" as="element(pim:class)*"
        select="$model/pim:application//pim:class[empty(key('fp:realized-by', @id, $root))]
                                                  [not(@component = ('false', '0'))][not(pim:part/@type = @id)]"/>
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

  <!-- the components (and classes taken as components, $promoted) of
       $model that provide or require interfaces directly (a lollipop and
       a socket on the component), with no port, in a model that draws no
       system (no part is typed by a component): each gets a port per such
       interface (fp:implicit-ports) -->
  <xsl:function name="fp:portless-components" as="element()*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:param name="promoted" as="element(pim:class)*"/>
    <xsl:variable name="all" as="element()*" select="$model/pim:application//pim:component | $promoted"/>
    <xsl:sequence select="if (some $c in $all satisfies exists(key('fp:part-by-type', $c/@id, root($model)))) then ()
                          else $all[not(@abstract = ('true', '1'))][empty(pim:port)][pim:provides or pim:requires]"/>
  </xsl:function>

  <!-- the PIM with the classes $promoted written as components, and the
       components $portless given their implicit ports -->
  <xsl:function name="fp:with-classes-as-components" as="document-node()">
    <xsl:param name="doc" as="document-node()"/>
    <xsl:param name="promoted" as="element(pim:class)*"/>
    <xsl:param name="portless" as="element()*"/>
    <xsl:if test="exists($portless)">
      <xsl:sequence select="f:warn('BND032', string($portless[1]/@id), 'the model draws components that provide or require'
          || ' interfaces with no port and no system using them (''' || string-join($portless/@name, ''', ''')
          || '''): each gets a port per interface and one instance, and the instances are wired by interface (one'
          || ' provider to its users); to say which instance talks to which, draw a class or component whose parts are'
          || ' typed by these components and connectors between their ports (docs/profile.md, Components drawn as classes)')"/>
    </xsl:if>
    <xsl:document>
      <xsl:apply-templates select="$doc/node()" mode="mp:promote">
        <xsl:with-param name="ids" tunnel="yes"
            select="map:merge($promoted ! map:entry(generate-id(.), true()))"/>
        <xsl:with-param name="portless" tunnel="yes"
            select="map:merge($portless ! map:entry(generate-id(.), true()))"/>
      </xsl:apply-templates>
    </xsl:document>
  </xsl:function>

  <!-- a component with no port that provides or requires interfaces: its
       implicit ports, one per interface (named after it; with _in and _out
       when it both provides and requires it), after its attributes -->
  <xsl:template match="pim:component" mode="mp:promote" priority="1" as="element(pim:component)">
    <xsl:param name="portless" as="map(xs:string, xs:boolean)" tunnel="yes"/>
    <xsl:copy>
      <xsl:copy-of select="@*"/>
      <xsl:choose>
        <xsl:when test="map:contains($portless, generate-id(.))">
          <xsl:call-template name="tp:with-implicit-ports"/>
        </xsl:when>
        <xsl:otherwise>
          <xsl:apply-templates mode="mp:promote"/>
        </xsl:otherwise>
      </xsl:choose>
    </xsl:copy>
  </xsl:template>

  <!-- the content of the context component (or class taken as one), its
       implicit ports after its attributes -->
  <xsl:template name="tp:with-implicit-ports" as="node()*">
    <xsl:variable name="after" as="element()?"
        select="(pim:part | pim:operation | pim:connector | pim:attribute[last()]/following-sibling::*)[1]"/>
    <xsl:for-each select="node()">
      <xsl:if test=". is $after">
        <xsl:sequence select="fp:implicit-ports(..)"/>
      </xsl:if>
      <xsl:apply-templates select="." mode="mp:promote"/>
    </xsl:for-each>
    <xsl:if test="empty($after)">
      <xsl:sequence select="fp:implicit-ports(.)"/>
    </xsl:if>
  </xsl:template>

  <xsl:function name="fp:implicit-ports" as="element(pim:port)*">
    <xsl:param name="component" as="element()"/>
    <xsl:variable name="root" as="document-node()" select="root($component)"/>
    <xsl:variable name="both" as="xs:string*" select="$component/pim:provides/@interface[. = ../../pim:requires/@interface]"/>
    <xsl:for-each select="$component/(pim:provides | pim:requires)">
      <xsl:variable name="interface" as="element()?" select="key('fp:id', @interface, $root)"/>
      <xsl:variable name="kind" as="xs:string" select="if (self::pim:provides) then 'provided' else 'required'"/>
      <pim:port id="robomda.port.{@id}"
          name="{$interface/@name}{if (@interface = $both) then (if ($kind eq 'provided') then '_out' else '_in') else ''}"
          qualified-name="{$component/@qualified-name}::{$interface/@name}" type="{@interface}"
          type-name="{$interface/@name}" type-library="local" visibility="public" conjugated="false"
          service="true" behavior="false" implicit="true">
        <xsl:element name="pim:{$kind}" namespace="urn:robomda:pim:1">
          <xsl:attribute name="interface" select="@interface"/>
          <xsl:attribute name="via" select="@id"/>
        </xsl:element>
      </pim:port>
    </xsl:for-each>
  </xsl:function>

  <xsl:mode name="mp:promote" on-no-match="shallow-copy"/>

  <xsl:template match="pim:class" mode="mp:promote" priority="1" as="element()">
    <xsl:param name="ids" as="map(xs:string, xs:boolean)" tunnel="yes"/>
    <xsl:param name="portless" as="map(xs:string, xs:boolean)" tunnel="yes"/>
    <xsl:choose>
      <xsl:when test="map:contains($ids, generate-id(.)) and map:contains($portless, generate-id(.))">
        <!-- a class with no port taken as a component (its profile says so)
             that provides or requires interfaces: a component with its
             implicit ports, as for components (read from the class, in the
             model: its interfaces are looked up there) -->
        <pim:component>
          <xsl:copy-of select="@* except (@active, @component, @parameters)"/>
          <xsl:attribute name="drawn-as" select="'class'"/>
          <xsl:call-template name="tp:with-implicit-ports"/>
        </pim:component>
      </xsl:when>
      <xsl:when test="map:contains($ids, generate-id(.))">
        <pim:component>
          <xsl:copy-of select="@* except (@active, @component, @parameters)"/>
          <xsl:attribute name="drawn-as" select="'class'"/>
          <!-- the attributes of its parameter blocks are its own, after
               its own attributes -->
          <xsl:variable name="moved" as="element(pim:attribute)*" select="pim:class[@parameters = ('true', '1')]/pim:attribute"/>
          <xsl:variable name="after" as="element()?"
              select="(pim:port | pim:part | pim:operation | pim:connector | pim:attribute[last()]/following-sibling::*)[1]"/>
          <!-- the operations of the interfaces it provides that it does not
               declare: its own, for its user class to implement -->
          <xsl:variable name="provided" as="element(pim:operation)*" select="fp:provided-operations(.)"/>
          <xsl:variable name="ops-before" as="element()?"
              select="(pim:connector | pim:operation[last()]/following-sibling::* | pim:part[last()]/following-sibling::*
                       | pim:port[last()]/following-sibling::*)[not(self::pim:operation or self::pim:part or self::pim:port)][1]"/>
          <xsl:for-each select="node()">
            <xsl:if test=". is $after">
              <xsl:copy-of select="$moved"/>
            </xsl:if>
            <xsl:if test=". is $ops-before">
              <xsl:sequence select="$provided"/>
            </xsl:if>
            <xsl:apply-templates select="." mode="mp:promote">
              <xsl:with-param name="moved" tunnel="yes" select="$moved"/>
            </xsl:apply-templates>
          </xsl:for-each>
          <xsl:if test="empty($after)">
            <xsl:copy-of select="$moved"/>
          </xsl:if>
          <xsl:if test="empty($ops-before)">
            <xsl:sequence select="$provided"/>
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

  <!-- the operations of the service interfaces (operations, no datum)
       class $c provides (its pim:provides, its ports' explicit
       pim:provided: a RobotML service port; else the interfaces their
       types realize: a Papyrus for Robotics «ComponentService» that
       realizes a Query) that it declares under no name
       of its own, copied as its own: a class drawn as a component declares
       no operation of the interfaces its ports provide; its user class
       implements them (ids robomda.op.<class>.<operation>, and likewise
       for their parameters) -->
  <xsl:function name="fp:provided-operations" as="element(pim:operation)*">
    <xsl:param name="c" as="element(pim:class)"/>
    <xsl:variable name="root" as="document-node()" select="root($c)"/>
    <xsl:variable name="interfaces" as="element(pim:interface)*"
        select="key('fp:id', distinct-values(($c/pim:provides, $c/pim:port/pim:provided,
                                              $c/pim:port[not(pim:provided or pim:required)]
                                              ! key('fp:id', @type, $root)/self::pim:class/pim:provides)/@interface), $root)
                /self::pim:interface[pim:operation][empty(pim:attribute)]"/>
    <xsl:variable name="own" as="xs:string*" select="$c/pim:operation/@name ! string(.)"/>
    <xsl:for-each select="$interfaces/pim:operation[not(@name = $own)]">
      <xsl:variable name="prefix" as="xs:string" select="'robomda.op.' || $c/@id || '.'"/>
      <pim:operation id="{$prefix}{@id}">
        <xsl:copy-of select="@* except @id"/>
        <xsl:for-each select="pim:parameter">
          <pim:parameter id="{$prefix}{@id}">
            <xsl:copy-of select="@* except @id"/>
          </pim:parameter>
        </xsl:for-each>
      </pim:operation>
    </xsl:for-each>
  </xsl:function>

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

  <!-- nothing else changes but classes and components -->
  <xsl:template match="*[not(descendant::pim:class or descendant::pim:component)]" mode="mp:promote" as="element()">
    <xsl:copy-of select="."/>
  </xsl:template>
</xsl:stylesheet>
