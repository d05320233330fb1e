<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/check/substitute.xsl - check the component swaps a model or a user
  asks for (seed 004 §4.2): robomda check MODEL with option replace OLD=NEW, and
  every component stereotyped «Alternative» (its tag replaces: the
  components it may take the place of). The rule itself is
  xslt/check/substitution.xsl (f:substitution-problems); this stage finds
  the swaps and the bound view of each component, and raises every
  violation of every swap at once (f:fail-all).

  Reads:   a bound PIM, urn:robomda:pim:1 (schemas/pim/1, xslt/m2m/bind.xsl).
  Writes:  the same PIM, unchanged (the check pipeline's last model).
  Params:  replace (xs:string) the swaps asked for, "OLD=NEW" pairs apart by
           spaces; a side names a component by its name, or by its
           qualified name when several share the name. '' = none.
  Imports: xslt/m2m/bind.xsl, for the bound view of a component that has no
           instance (fp:bound-component), its activity values and its keys.
  Errors (namespace urn:robomda:error, with f:fail-all):
    SUB001-SUB008  see xslt/check/substitution.xsl
    SUB009  the replace option names no component of the model, several, or is not
            OLD=NEW
    SUB010  an «Alternative» replaces tag names no component, or its own
    SUB011  a «Category» kind that is no category of seed 004
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:import href="../m2m/bind.xsl"/>
  <xsl:include href="substitution.xsl"/>

  <xsl:param name="replace" as="xs:string" select="''">
    <!-- the swaps asked for: "OLD=NEW" pairs apart by spaces ('' = none) -->
  </xsl:param>

  <xsl:output method="xml" indent="no" encoding="UTF-8"/>

  <xsl:key name="fp:component-by-name" match="pim:component" use="@name, @qualified-name"/>
  <xsl:key name="fp:instances-of" match="pim:binding/pim:instance" use="@component"/>
  <xsl:key name="fp:alternatives" match="pim:component[pim:stereotype[@name eq 'Alternative']]" use="'all'"/>

  <xsl:template match="/" as="document-node()">
    <xsl:variable name="model" as="element(pim:model)" select="pim:model"/>
    <xsl:variable name="asked" as="map(*)*" select="tokenize($replace) ! fp:asked-swap(., root($model))"/>
    <xsl:variable name="declared" as="map(*)*"
        select="key('fp:alternatives', 'all') ! fp:declared-swaps(.)"/>
    <xsl:variable name="categories" as="map(*)*"
        select="//pim:component ! f:stereotype(., 'Category')[pim:tag[@name eq 'kind'][not(@value = map:keys($f:component-categories))]]
                ! map { 'code': 'SUB011', 'id': string(@id), 'message': 'component ''' || ../@name || ''': «Category» kind '''
                        || pim:tag[@name eq 'kind']/@value || ''' is no component category (one of '
                        || string-join(sort(map:keys($f:component-categories)), ', ') || ')' }"/>
    <xsl:sequence select="f:fail-all(($categories, $asked[?code], $declared[?code]))"/>
    <xsl:sequence select="f:fail-all(($asked, $declared)[empty(?code)] ! fp:check-swap(., $model/pim:binding))"/>
    <xsl:sequence select="."/>
  </xsl:template>

  <!-- "OLD=NEW" as a swap (map old, new, why), or an SUB009 problem -->
  <xsl:function name="fp:asked-swap" as="map(*)">
    <xsl:param name="pair" as="xs:string"/>
    <xsl:param name="root" as="document-node()"/>
    <xsl:variable name="sides" as="xs:string*" select="tokenize($pair, '=')"/>
    <xsl:variable name="found" as="element(pim:component)*" select="$sides ! (key('fp:component-by-name', ., $root)[1])"/>
    <xsl:variable name="wrong" as="xs:string*"
        select="$sides[count(distinct-values(key('fp:component-by-name', ., $root)/@id)) ne 1]"/>
    <xsl:sequence select="
        if (count($sides) ne 2 or $sides = '') then
          map { 'code': 'SUB009', 'id': '', 'message': '--replace ''' || $pair || ''': write OLD=NEW, two component names' }
        else if (exists($wrong)) then
          map { 'code': 'SUB009', 'id': '', 'message': '--replace ''' || $pair || ''': ''' || $wrong[1] || ''' names '
                || (if (empty(key('fp:component-by-name', $wrong[1], $root))) then 'no component of the model'
                    else 'several components (' || string-join(key('fp:component-by-name', $wrong[1], $root)/@qualified-name, ', ')
                         || '): give the qualified name') }
        else if ($found[1] is $found[2]) then
          map { 'code': 'SUB009', 'id': '', 'message': '--replace ''' || $pair || ''': a component replacing itself' }
        else map { 'old': $found[1], 'new': $found[2], 'why': '--replace ' || $pair }"/>
  </xsl:function>

  <!-- the swaps an «Alternative» component declares, or SUB010 problems -->
  <xsl:function name="fp:declared-swaps" as="map(*)*">
    <xsl:param name="new" as="element(pim:component)"/>
    <xsl:variable name="stereotype" as="element(pim:stereotype)?" select="f:stereotype($new, 'Alternative')"/>
    <xsl:for-each select="$stereotype/pim:tag[@name eq 'replaces']">
      <xsl:variable name="old" as="element()?" select="key('fp:id', @value, root($new))"/>
      <xsl:sequence select="
          if (empty($old/self::pim:component) or $old is $new) then
            map { 'code': 'SUB010', 'id': string($stereotype/@id), 'message': 'component ''' || $new/@name
                  || ''': «Alternative» replaces ''' || ($old/@name, @value)[1] || ''', which is '
                  || (if ($old is $new) then 'itself' else 'no component') }
          else map { 'old': $old, 'new': $new, 'why': 'its «Alternative» stereotype' }"/>
    </xsl:for-each>
    <xsl:if test="exists($stereotype) and empty($stereotype/pim:tag[@name eq 'replaces'])">
      <xsl:sequence select="map { 'code': 'SUB010', 'id': string($stereotype/@id), 'message': 'component '''
          || $new/@name || ''': «Alternative» names no component it replaces (tag replaces)' }"/>
    </xsl:if>
  </xsl:function>

  <!-- the rule's verdict on one swap, with the bound view of both sides -->
  <xsl:function name="fp:check-swap" as="map(*)*">
    <xsl:param name="swap" as="map(*)"/>
    <xsl:param name="binding" as="element(pim:binding)"/>
    <xsl:variable name="instances" as="element(pim:instance)*" select="key('fp:instances-of', $swap?old/@id, root($binding))"/>
    <xsl:sequence select="f:substitution-problems(map:merge(($swap, map {
        'old-bound': fp:bound-view($swap?old, $binding), 'new-bound': fp:bound-view($swap?new, $binding),
        'old-properties': fp:sub-properties($swap?old), 'new-properties': fp:sub-properties($swap?new),
        'instances': $instances, 'new-periods': $instances ! fp:period-in-place(., $swap?new),
        'period-holder': fp:own-period($swap?new)[3][. ne ''],
        'binding': $binding })))"/>
  </xsl:function>

  <!-- a component's bound view: the binding's, else made as bind makes it -->
  <xsl:function name="fp:bound-view" as="element(pim:bound-component)">
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:param name="binding" as="element(pim:binding)"/>
    <xsl:sequence select="(key('fp:bc', $component/@id, root($binding)), fp:bound-component($component))[1]"/>
  </xsl:function>

  <!-- the configuration constants a component accepts: the attributes of
       its realizing class (or composite) stereotyped Configurable, else
       those a target exposes as properties (public or protected, not
       static, not read-only, not an activity convention) -->
  <xsl:function name="fp:sub-properties" as="element(pim:attribute)*">
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:variable name="all" as="element(pim:attribute)*" select="fp:attributes(fp:feature-owner($component))"/>
    <xsl:variable name="marked" as="element(pim:attribute)*" select="$all[exists(f:stereotype(., 'Configurable'))]"/>
    <xsl:sequence select="if (exists($marked)) then $marked
        else $all[@visibility = ('public', 'protected')][not(@static = ('true', '1'))][not(@read-only = ('true', '1'))]
                 [not(@name = ('sample', 'priority', 'scheduler', 'cpuAffinity'))]"/>
  </xsl:function>

  <!-- (period, source, holder id) of component $new by itself: its
       «Activity», else its class's, else its class's attribute sample -->
  <xsl:function name="fp:own-period" as="xs:string+">
    <xsl:param name="new" as="element(pim:component)"/>
    <xsl:variable name="class" as="element(pim:class)?" select="fp:realizing-class($new)"/>
    <xsl:sequence select="fp:activity-value(($new, $class)[exists(f:stereotype(., 'Activity'))], 'period', $class, (), 'sample', '0')"/>
  </xsl:function>

  <!-- the period component $new would run at in $instance's place: the
       instance's own when a part's «Activity» or a thread sets it (they
       stay), else $new's (its «Activity», else its class's, else its
       class's attribute sample; 0 = none) -->
  <xsl:function name="fp:period-in-place" as="xs:double">
    <xsl:param name="instance" as="element(pim:instance)"/>
    <xsl:param name="new" as="element(pim:component)"/>
    <xsl:variable name="part" as="element(pim:part)?" select="key('fp:id', $instance/@xmi-id, root($instance))/self::pim:part"/>
    <xsl:variable name="own" as="xs:string+" select="fp:own-period($new)"/>
    <xsl:sequence select="if (exists($instance/@thread) or exists(fp:tag($part, 'Activity', 'period')))
                          then xs:double($instance/pim:activity/@period)
                          else fp:quantity($own[1], 'period', 'period', fp:holder($own, string($new/@id)))"/>
  </xsl:function>
</xsl:stylesheet>
