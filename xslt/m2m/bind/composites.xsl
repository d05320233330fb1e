<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/bind/composites.xsl - bind (xslt/m2m/bind.xsl): composites of any
  depth flattened to instances, and connector ends resolved through the
  delegations (promoted ports) of the composites they reach.

  Reads:   the PIM (urn:robomda:pim:1).
  Writes:  the working tree of the expansion (fp:composite and fp:unit
           elements, below), fp:target / fp:unresolved elements, or maps for
           f:fail-all.
  Params:  none.  Keys: those of bind.xsl.
  Provides: fp:is-composite, fp:is-delegation, fp:is-assembly, fp:expansion,
           fp:end-targets, fp:connector-uses, fp:composition-cycles,
           fp:delegation-problems, fp:promotion-problems, fp:property-values.

  The expansion: a depth-first walk of the parts of the top composites. A
  part typed by a composite (a component with parts typed by components)
  gives an fp:composite and the walk goes on into the parts of its type; a
  part typed by any other component gives an fp:unit, which becomes an
  instance. Both carry:
    @path     the part names from the top composite down, each made a C++
              identifier (an unnamed part takes its type's name), joined by
              '.': "atf.driver.fri". The top composite is not in the path,
              so the parts of a model without nesting keep their names.
    @name     the path's names joined by '_', made a C++ identifier: the
              instance name every middleware starts from.
    @parent   the path of the enclosing fp:composite (absent at the top).
    @around   the ids of the top composite and of each enclosing composite
              part and its type, outermost first (a deployment of any of
              them places the instance).
  A composite that is a part of itself at any depth is refused before the
  walk (BND013), so the walk ends.

  Nested ends: an end with @path (the import's SysML NestedConnectorEnd
  propertyPath) joins the port of the part at that path below the
  connector's composite: "a.b" of a connector drawn in the composite at
  path "top" is the instance "top.a.b".

  Delegation: a connector of a composite with kind delegation, or with an
  end on a port of the composite itself (no partWithPort), promotes the
  inner ports it joins: a connector end on port q of a part typed by a
  composite stands for the ports its delegations from q reach, through
  any depth of composites (fp:end-targets).

  Promoted properties: a property (attribute) of a composite promotes the
  property of the same name of exactly one of its parts (at any depth: a
  composite part's own properties are the ones it promotes). A part sets
  values on the properties of its type with UML's construct: its default
  value is an InstanceValue whose InstanceSpecification has a Slot per
  property (pim:part/pim:value). Per instance, the outermost value wins
  (fp:property-values): the part's slot, then the default of the composite
  property that promotes it, then the slot of the enclosing part, and so on.

  Errors (codes of bind.xsl): BND013 composition cycle; BND014 a connector
  reaches a promoted port that is delegated to no inner port; BND015 a
  delegation joins ports of another direction or data type; BND035 a
  connector joins the composite's own behaviour port (isBehavior: a UML-RT
  capsule's state machine) to a part, no delegation; BND017 a
  composite property that promotes the property of several parts; BND018 a
  slot on a property the part's type does not have. Warning BND016: a
  composite property that promotes none.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- ================================================ what is what -->
  <!-- the component type of part $part, if it is a component -->
  <xsl:function name="fp:part-component" as="element(pim:component)?">
    <xsl:param name="part" as="element(pim:part)"/>
    <xsl:sequence select="key('fp:id', $part/@type, root($part))[self::pim:component]"/>
  </xsl:function>

  <xsl:function name="fp:is-composite" as="xs:boolean">
    <xsl:param name="component" as="element(pim:component)?"/>
    <xsl:sequence select="exists($component/pim:part[exists(fp:part-component(.))])"/>
  </xsl:function>

  <!-- a delegation: so marked, or with an end on a port of its own composite -->
  <xsl:function name="fp:is-delegation" as="xs:boolean">
    <xsl:param name="connector" as="element(pim:connector)"/>
    <xsl:sequence select="$connector/@kind eq 'delegation'
        or exists($connector/pim:end[not(@part)][key('fp:id', @role, root($connector))/self::pim:port/.. is $connector/..])"/>
  </xsl:function>

  <!-- an assembly connector between ports of two parts or more -->
  <xsl:function name="fp:is-assembly" as="xs:boolean">
    <xsl:param name="connector" as="element(pim:connector)"/>
    <xsl:sequence select="not(fp:is-delegation($connector)) and count($connector/pim:end[@part]) ge 2"/>
  </xsl:function>

  <!-- the path segment of a part: its name (else its type's) as an identifier -->
  <xsl:function name="fp:segment" as="xs:string">
    <xsl:param name="part" as="element(pim:part)"/>
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:sequence select="f:cpp-identifier(($part/@name[normalize-space(.)], $component/@name)[1])"/>
  </xsl:function>

  <!-- the instance name of a path: its segments joined by '_' -->
  <xsl:function name="fp:path-name" as="xs:string">
    <xsl:param name="segments" as="xs:string+"/>
    <xsl:sequence select="f:cpp-identifier(string-join($segments, '_'))"/>
  </xsl:function>

  <!-- ================================================== cycles -->
  <!-- BND013 for each composite that is a part of itself at any depth -->
  <xsl:function name="fp:composition-cycles" as="map(*)*">
    <xsl:param name="components" as="element(pim:component)*"/>
    <xsl:for-each select="$components[fp:is-composite(.)]">
      <xsl:variable name="chain" as="element(pim:component)*" select="fp:cycle-from(., .,  ())"/>
      <xsl:if test="exists($chain)">
        <xsl:sequence select="map { 'code': 'BND013', 'id': string(@id), 'message': 'composite ''' || @name
            || ''' is a part of itself (' || string-join((., $chain) ! string(@name), ' contains ')
            || '): a composite cannot contain itself at any depth' }"/>
      </xsl:if>
    </xsl:for-each>
  </xsl:function>

  <!-- the chain of composite types from $from that leads back to $start
       (ending with $start), else (); $seen: the composites walked so far -->
  <xsl:function name="fp:cycle-from" as="element(pim:component)*">
    <xsl:param name="start" as="element(pim:component)"/>
    <xsl:param name="from" as="element(pim:component)"/>
    <xsl:param name="seen" as="element(pim:component)*"/>
    <!-- each part type once ("/." removes the repeats) -->
    <xsl:iterate select="($from/pim:part ! fp:part-component(.))/.">
      <xsl:variable name="type" as="element(pim:component)" select="."/>
      <xsl:choose>
        <xsl:when test="$type is $start">
          <xsl:break select="$type"/>
        </xsl:when>
        <xsl:when test="fp:is-composite($type) and not(some $walked in $seen satisfies $walked is $type)">
          <xsl:variable name="rest" as="element(pim:component)*" select="fp:cycle-from($start, $type, ($seen, $from))"/>
          <xsl:if test="exists($rest)">
            <xsl:break select="$type, $rest"/>
          </xsl:if>
        </xsl:when>
      </xsl:choose>
    </xsl:iterate>
  </xsl:function>

  <!-- ================================================ expansion -->
  <xsl:function name="fp:expansion" as="document-node()">
    <xsl:param name="tops" as="element(pim:component)*"/>
    <xsl:document>
      <xsl:for-each select="$tops">
        <xsl:sequence select="fp:expand(., ., string(@id), ())"/>
      </xsl:for-each>
    </xsl:document>
  </xsl:function>

  <!-- the fp:composite and fp:unit elements of the parts of $composite,
       reached at path $segments from $top through the elements $around -->
  <xsl:function name="fp:expand" as="element()*">
    <xsl:param name="composite" as="element(pim:component)"/>
    <xsl:param name="top" as="element(pim:component)"/>
    <xsl:param name="around" as="xs:string"/>
    <xsl:param name="segments" as="xs:string*"/>
    <xsl:for-each select="$composite/pim:part[exists(fp:part-component(.))]">
      <xsl:variable name="type" as="element(pim:component)" select="fp:part-component(.)"/>
      <xsl:variable name="path" as="xs:string+" select="$segments, fp:segment(., $type)"/>
      <xsl:element name="{if (fp:is-composite($type)) then 'fp:composite' else 'fp:unit'}">
        <xsl:attribute name="part" select="@id"/>
        <xsl:attribute name="component" select="$type/@id"/>
        <xsl:attribute name="top" select="$top/@id"/>
        <xsl:attribute name="path" select="string-join($path, '.')"/>
        <xsl:attribute name="name" select="fp:path-name($path)"/>
        <xsl:if test="exists($segments)">
          <xsl:attribute name="parent" select="string-join($segments, '.')"/>
        </xsl:if>
        <xsl:attribute name="around" select="$around"/>
      </xsl:element>
      <xsl:if test="fp:is-composite($type)">
        <xsl:sequence select="fp:expand($type, $top, $around || ' ' || @id || ' ' || $type/@id, $path)"/>
      </xsl:if>
    </xsl:for-each>
  </xsl:function>

  <!-- ======================================== connector resolution -->
  <!-- one fp:use per assembly connector and composite it is drawn in:
       the top composites' own (@path ''), then those of each composite
       part, in the order of the walk -->
  <xsl:function name="fp:connector-uses" as="element(fp:use)*">
    <xsl:param name="tops" as="element(pim:component)*"/>
    <xsl:param name="expansion" as="document-node()"/>
    <xsl:variable name="root" as="document-node()?" select="root($tops[1])"/>
    <xsl:for-each select="$tops/pim:connector[fp:is-assembly(.)]">
      <fp:use connector="{@id}" path=""/>
    </xsl:for-each>
    <xsl:for-each select="$expansion/fp:composite">
      <xsl:variable name="path" as="xs:string" select="@path"/>
      <xsl:for-each select="key('fp:id', @component, $root)/pim:connector[fp:is-assembly(.)]">
        <fp:use connector="{@id}" path="{$path}"/>
      </xsl:for-each>
    </xsl:for-each>
  </xsl:function>

  <!-- the instance ports connector end $end stands for, drawn in the
       composite at path $segments: the port of the part's instance (of
       the part at the end's @path, for a nested end), or,
       for a part typed by a composite, the inner ports that the
       composite's delegations from the end's port reach (any depth); an
       fp:unresolved for a promoted port delegated to nothing -->
  <xsl:function name="fp:end-targets" as="element()*">
    <xsl:param name="end" as="element()"/>
    <xsl:param name="segments" as="xs:string*"/>
    <xsl:variable name="root" as="document-node()" select="root($end)"/>
    <xsl:variable name="part" as="element(pim:part)?" select="key('fp:id', $end/@part, $root)[self::pim:part]"/>
    <!-- a nested end (@path): the parts above @part, each typed by a composite -->
    <xsl:variable name="outer" as="element(pim:part)*"
        select="tokenize($end/@path)[position() lt last()] ! key('fp:id', ., $root)[self::pim:part]"/>
    <xsl:variable name="type" as="element(pim:component)?"
        select="if (count($outer) ne max((count(tokenize($end/@path)) - 1, 0))
                    or (some $o in $outer satisfies not(fp:is-composite(fp:part-component($o))))) then ()
                else $part ! fp:part-component(.)"/>
    <xsl:variable name="path" as="xs:string*"
        select="$type ! ($segments, $outer ! fp:segment(., fp:part-component(.)), fp:segment($part, .))"/>
    <xsl:choose>
      <xsl:when test="empty($type)"/>
      <xsl:when test="fp:is-composite($type)">
        <xsl:variable name="inner" as="element()*"
            select="key('fp:connector-by-own-port', $end/@role, $root)[.. is $type][fp:is-delegation(.)]
                    /pim:end[@part] ! fp:end-targets(., $path)"/>
        <xsl:sequence select="if (exists($inner)) then $inner
            else fp:unresolved($end, $part, $type)"/>
      </xsl:when>
      <xsl:otherwise>
        <fp:target instance="{fp:path-name($path)}" port="{$end/@role}"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <xsl:function name="fp:unresolved" as="element(fp:unresolved)">
    <xsl:param name="end" as="element()"/>
    <xsl:param name="part" as="element(pim:part)"/>
    <xsl:param name="type" as="element(pim:component)"/>
    <xsl:variable name="port" as="element()?" select="key('fp:id', $end/@role, root($end))"/>
    <fp:unresolved connector="{$end/../@id}"
        message="connector '{$end/../@name}' joins port '{($port/@name, $end/@role)[1]}' of part '{$part/@name}', but its type, composite '{$type/@name}', delegates that port to no port inside it: draw the delegation connector, or connect an inner part directly"/>
  </xsl:function>

  <!-- ================================================ delegations -->
  <!-- what a port carries, for comparing two ends of a delegation: its
       (direction, data) pairs, sorted; the data by id, or by name for a
       message ($readable) -->
  <xsl:function name="fp:port-signature" as="xs:string">
    <xsl:param name="port" as="element(pim:port)"/>
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:param name="readable" as="xs:boolean"/>
    <xsl:variable name="root" as="document-node()" select="root($port)"/>
    <xsl:variable name="pairs" as="xs:string*" select="fp:port-interfaces($port, $component, fp:realizing-class($component))"/>
    <xsl:sequence select="string-join(sort(for $k in 1 to count($pairs) idiv 2
        return $pairs[2 * $k] || ' ' || fp:data-key(key('fp:id', $pairs[2 * $k - 1], $root), $pairs[2 * $k - 1], $readable)), ', ')"/>
  </xsl:function>

  <!-- a port's data in a signature: a library primitive by its kind, any
       other by id (or name) -->
  <xsl:function name="fp:data-key" as="xs:string">
    <xsl:param name="data" as="element()?"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:param name="readable" as="xs:boolean"/>
    <xsl:sequence select="string(($data/self::pim:port/@primitive, if ($readable) then $data/@name else (), $id)[1])"/>
  </xsl:function>

  <!-- every delegation and promotion problem of the composites in use -->
  <xsl:function name="fp:composite-problems" as="map(*)*">
    <xsl:param name="composites" as="element(pim:component)*"/>
    <xsl:sequence select="if (empty($composites)) then ()
                          else (fp:delegation-problems($composites), fp:promotion-problems($composites))"/>
  </xsl:function>

  <!-- BND015 for each delegation of $composites that joins ports that do
       not carry the same data in the same direction -->
  <xsl:function name="fp:delegation-problems" as="map(*)*">
    <xsl:param name="composites" as="element(pim:component)*"/>
    <xsl:variable name="root" as="document-node()?" select="root($composites[1])"/>
    <xsl:for-each select="$composites/pim:connector[fp:is-delegation(.)]">
      <xsl:variable name="connector" as="element(pim:connector)" select="."/>
      <xsl:variable name="outer" as="element(pim:port)?" select="key('fp:id', pim:end[not(@part)][1]/@role, $root)[self::pim:port]"/>
      <xsl:for-each select="pim:end[@part]">
        <xsl:variable name="type" as="element(pim:component)?" select="key('fp:id', @part, $root)/self::pim:part ! fp:part-component(.)"/>
        <xsl:variable name="inner" as="element(pim:port)?" select="key('fp:id', @role, $root)[self::pim:port]"/>
        <xsl:if test="$outer and $type and $inner">
          <xsl:if test="$outer/@behavior eq 'true'">
            <!-- no delegation: the composite's own behaviour (a UML-RT
                 capsule's state machine) talks to its part -->
            <xsl:sequence select="map { 'code': 'BND035', 'id': string($connector/@id), 'message': 'connector '''
                || $connector/@name || ''' joins behaviour port ''' || $outer/@name || ''' of ''' || $connector/../@name
                || ''' (isBehavior: the composite''s own behaviour, a capsule''s state machine, talks through it) to port '''
                || $inner/@name || ''' of its part ''' || key('fp:id', @part, $root)/@name
                || ''': robomda generates a composite as its parts and their connections only, so that behaviour has no'
                || ' component to run in; move it into a component of its own, a part of ''' || $connector/../@name
                || ''', and connect that part''s port to ''' || $inner/@name || ''' instead' }"/>
          </xsl:if>
          <xsl:if test="not($outer/@behavior eq 'true')
                        and fp:port-signature($outer, $connector/.., false()) ne fp:port-signature($inner, $type, false())">
            <xsl:sequence select="map { 'code': 'BND015', 'id': string($connector/@id), 'message': 'delegation '''
                || $connector/@name || ''' joins port ''' || $outer/@name || ''' of composite ''' || $connector/../@name
                || ''' (' || fp:signature-text(fp:port-signature($outer, $connector/.., true())) || ') to port ''' || $inner/@name || ''' of part '''
                || key('fp:id', @part, $root)/@name || ''' (' || fp:signature-text(fp:port-signature($inner, $type, true()))
                || '): a promoted port carries the same data in the same direction as the port it promotes' }"/>
          </xsl:if>
        </xsl:if>
      </xsl:for-each>
    </xsl:for-each>
  </xsl:function>

  <xsl:function name="fp:signature-text" as="xs:string">
    <xsl:param name="signature" as="xs:string"/>
    <xsl:sequence select="if ($signature eq '') then 'no data' else $signature"/>
  </xsl:function>

  <!-- ============================================ promoted properties -->
  <!-- the element whose attributes and operations are those of component
       $component: a composite itself (its attributes are its promoted
       properties), else its realizing class, else the component -->
  <xsl:function name="fp:feature-owner" as="element()">
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:sequence select="if (fp:is-composite($component)) then $component
                          else (fp:realizing-class($component), $component)[1]"/>
  </xsl:function>

  <!-- the parts of composite $composite whose type offers a property named
       like $attribute (one of $composite's): exactly one is the part whose
       property it promotes -->
  <xsl:function name="fp:promoting-parts" as="element(pim:part)*">
    <xsl:param name="attribute" as="element(pim:attribute)"/>
    <xsl:param name="composite" as="element(pim:component)"/>
    <xsl:sequence select="$composite/pim:part[exists(fp:part-component(.))]
                          [fp:attributes(fp:feature-owner(fp:part-component(.)))/@name = $attribute/@name]"/>
  </xsl:function>

  <!-- BND017 for a property of a composite that promotes the property of
       several parts, BND018 for a value a part sets on a property its type
       does not have; warning BND016 for a property that promotes none (it
       has no effect: a composite runs no code) -->
  <xsl:function name="fp:promotion-problems" as="map(*)*">
    <xsl:param name="composites" as="element(pim:component)*"/>
    <xsl:variable name="root" as="document-node()?" select="root($composites[1])"/>
    <xsl:for-each select="$composites/pim:attribute">
      <xsl:variable name="parts" as="element(pim:part)*" select="fp:promoting-parts(., ..)"/>
      <xsl:choose>
        <xsl:when test="empty($parts)">
          <xsl:sequence select="f:warn('BND016', string(@id), 'property ''' || @name || ''' of composite ''' || ../@name
              || ''' promotes no property of its parts, so it has no effect: a composite runs no code of its own;'
              || ' name it like the property of the part it stands for')"/>
        </xsl:when>
        <xsl:when test="count($parts) gt 1">
          <xsl:sequence select="map { 'code': 'BND017', 'id': string(@id), 'message': 'property ''' || @name
              || ''' of composite ''' || ../@name || ''' promotes property ''' || @name || ''' of ' || count($parts)
              || ' parts (' || string-join($parts/@name, ', ') || '): a promoted property is the property of exactly one part; rename one' }"/>
        </xsl:when>
      </xsl:choose>
    </xsl:for-each>
    <xsl:for-each select="$composites/pim:part[exists(fp:part-component(.))]/pim:value">
      <xsl:variable name="type" as="element(pim:component)" select="fp:part-component(..)"/>
      <xsl:if test="not(@attribute = fp:attributes(fp:feature-owner($type))/@id)">
        <xsl:variable name="attribute" as="element()?" select="key('fp:id', @attribute, $root)"/>
        <xsl:sequence select="map { 'code': 'BND018', 'id': string(@id), 'message': 'part ''' || ../@name
            || ''' sets ''' || ($attribute/@name, @attribute)[1] || ''', which is no property of its type '''
            || $type/@name || '''' || (if (fp:is-composite($type)) then ' (a composite: a property it promotes)' else '') }"/>
      </xsl:if>
    </xsl:for-each>
  </xsl:function>

  <!-- the values that parts and composites set on the properties of the
       instance of $part ($around: the ids of the top composite, then of
       each enclosing composite part and its type, outermost first; $owner:
       the element whose attributes are the instance's properties): for
       each property, the outermost value wins -->
  <xsl:function name="fp:property-values" as="element(pim:property-value)*">
    <xsl:param name="part" as="element(pim:part)?"/>
    <xsl:param name="around" as="xs:string*"/>
    <xsl:param name="owner" as="element()"/>
    <xsl:variable name="root" as="document-node()" select="root($owner)"/>
    <xsl:variable name="parts" as="element(pim:part)*"
        select="($around[position() mod 2 eq 0] ! key('fp:id', ., $root), $part)"/>
    <xsl:variable name="composites" as="element(pim:component)*"
        select="$around[position() mod 2 eq 1] ! key('fp:id', ., $root)"/>
    <xsl:for-each select="if (exists($part)) then fp:attributes($owner) else ()">
      <xsl:variable name="holder" as="element()?" select="fp:outermost-value(., count($parts), $parts, $composites, ())"/>
      <xsl:if test="exists($holder)">
        <pim:property-value attribute="{@id}" name="{@name}" value="{($holder/@value, $holder/@default)[1]}"
            source="{if ($holder/self::pim:value) then 'part' else 'composite'}" holder="{$holder/@id}"/>
      </xsl:if>
    </xsl:for-each>
  </xsl:function>

  <!-- walk up from part $level of $parts: the value its part sets on
       $property, then the default of the property of the enclosing
       composite that promotes it, and so on up; the last found wins -->
  <xsl:function name="fp:outermost-value" as="element()?">
    <xsl:param name="property" as="element(pim:attribute)"/>
    <xsl:param name="level" as="xs:integer"/>
    <xsl:param name="parts" as="element(pim:part)*"/>
    <xsl:param name="composites" as="element(pim:component)*"/>
    <xsl:param name="found" as="element()?"/>
    <xsl:variable name="set" as="element(pim:value)?" select="$parts[$level]/pim:value[@attribute eq $property/@id][@value][1]"/>
    <xsl:variable name="promoted" as="element(pim:attribute)?"
        select="$composites[$level] ! fp:own-features(., 'attribute')[@name eq $property/@name]
                [fp:promoting-parts(., $composites[$level])[1] is $parts[$level]][1]"/>
    <xsl:variable name="here" as="element()?" select="($promoted[@default], $set, $found)[1]"/>
    <xsl:sequence select="if ($level gt 1 and exists($promoted))
                          then fp:outermost-value($promoted, $level - 1, $parts, $composites, $here)
                          else $here"/>
  </xsl:function>
</xsl:stylesheet>
