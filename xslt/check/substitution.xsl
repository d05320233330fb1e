<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/check/substitution.xsl - the substitutability rule of seed 004 (§4.2):
  may component NEW take the place of component OLD in a system?

  Reads:   elements of a bound PIM (urn:robomda:pim:1, xslt/m2m/bind.xsl):
           the two components, their bound views (pim:bound-component:
           data and service ports), OLD's instances and the binding's
           connections and bound components.
  Writes:  nothing: a function module. The caller (xslt/check/substitute.xsl
           for `check the replace option` and «Alternative»; later a job's swap or a
           variability alternative) raises the maps it returns with
           f:fail-all, so every violation of every swap is reported at once.
  Params:  none.  Keys: fp:sub-writers (a binding's connections by interface),
           fp:sub-providers (its provided service ports by interface).

  Function
    f:substitution-problems($swap)  maps (code, id, message) for f:fail-all,
        one per violation; empty when NEW may replace OLD. $swap is a map:
          old, new            element(pim:component)
          old-bound, new-bound  element(pim:bound-component) (fp:bound-component
                              of an uninstantiated one)
          old-properties, new-properties  element(pim:attribute)*: the
                              configuration constants each accepts
          instances           element(pim:instance)*: OLD's instances
          new-periods         xs:double*: the period NEW would run at in each
                              instance's place, in the order of instances
          period-holder       xs:string?: the id of what gives NEW its period
                              (where SUB007 points; else the instance)
          binding             element(pim:binding)
          why                 xs:string: how the swap was asked ('the replace option',
                              'its «Alternative» stereotype' ...)
  The rule (docs/substitution.md): NEW provides every output data port and
  every provided interface of OLD, by port name and with the same data type
  (multiplicity and constant / per-cycle kind included); NEW needs no input
  OLD did not need, unless a connection of the model carries that interface
  from another instance; NEW accepts every configuration constant of OLD
  (its properties, by name and type); NEW runs at least as often as OLD
  (a period no longer than each instance's, and periodic when it is).
  Messages name both components with their seed 004 category («Category»).

  Errors (as maps): SUB001 an output of OLD that NEW lacks; SUB002 an output
  NEW carries with another data type; SUB003 an input NEW needs that nothing
  feeds; SUB004 an input NEW reads with another data type than OLD; SUB005 a
  configuration constant of OLD that NEW lacks; SUB006 one NEW holds with
  another type; SUB007 NEW runs less often than OLD; SUB008 a provided
  interface (operations) of OLD that NEW lacks.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:key name="fp:sub-writers" match="pim:binding/pim:connection" use="@interface"/>
  <xsl:key name="fp:sub-providers" match="pim:binding/pim:bound-component/pim:service-port[@role eq 'provided']" use="@interface"/>

  <!-- seed 004's component categories: the «Category» kind literal and
       the words the messages use -->
  <xsl:variable name="f:component-categories" as="map(xs:string, xs:string)"
      select="map { 'generic': 'generic', 'hardwareInterface': 'hardware-dependent interface',
                    'hardwareComputational': 'hardware-dependent computational', 'application': 'application',
                    'integration': 'integration' }"/>

  <!-- 'NAME' (category) as messages name a component -->
  <xsl:function name="f:component-label" as="xs:string">
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:variable name="category" as="element(pim:stereotype)?" select="f:stereotype($component, 'Category')"/>
    <xsl:variable name="kind" as="xs:string" select="string(($category/pim:tag[@name eq 'kind']/@value, 'generic')[1])"/>
    <xsl:sequence select="'''' || $component/@name || ''''
        || (if (exists($category)) then ' (' || (map:get($f:component-categories, $kind), $kind)[1] || ')' else '')"/>
  </xsl:function>

  <!-- what must agree between two typed elements (a data port, an
       attribute): the type, the multiplicity, constant or per cycle -->
  <xsl:function name="fp:sub-type-key" as="xs:string">
    <xsl:param name="typed" as="element()"/>
    <xsl:sequence select="string(($typed/@primitive, $typed/@type, $typed/@type-name)[1]) || fp:multiplicity-label($typed)
                          || (if ($typed/@constant = ('true', '1')) then ' constant' else '')"/>
  </xsl:function>

  <xsl:function name="fp:sub-type-label" as="xs:string">
    <xsl:param name="typed" as="element()"/>
    <xsl:sequence select="string($typed/@type-name) || fp:multiplicity-label($typed)
                          || (if ($typed/@constant = ('true', '1')) then ', a configuration constant' else '')"/>
  </xsl:function>

  <xsl:function name="f:substitution-problems" as="map(*)*">
    <xsl:param name="swap" as="map(*)"/>
    <xsl:variable name="head" as="xs:string"
        select="'component ' || f:component-label($swap?new) || ' cannot replace ' || f:component-label($swap?old)
                || ' (' || $swap?why || '): '"/>
    <xsl:sequence select="fp:output-problems($swap, $head), fp:input-problems($swap, $head),
                          fp:property-problems($swap, $head), fp:period-problems($swap, $head)"/>
  </xsl:function>

  <!-- SUB001, SUB002, SUB008: what OLD gives that NEW must give too -->
  <xsl:function name="fp:output-problems" as="map(*)*">
    <xsl:param name="swap" as="map(*)"/>
    <xsl:param name="head" as="xs:string"/>
    <xsl:variable name="new" as="element(pim:bound-component)" select="$swap?new-bound"/>
    <xsl:for-each select="$swap?old-bound/pim:data-port[@direction eq 'out']">
      <xsl:variable name="same" as="element(pim:data-port)?" select="$new/pim:data-port[@direction eq 'out'][@name eq current()/@name][1]"/>
      <xsl:choose>
        <xsl:when test="empty($same)">
          <xsl:sequence select="map { 'code': 'SUB001', 'id': string(@port), 'message': $head || 'it has no output port '''
              || @name || ''' (' || fp:sub-type-label(.) || ') that ''' || $swap?old/@name || ''' provides' }"/>
        </xsl:when>
        <xsl:when test="fp:sub-type-key($same) ne fp:sub-type-key(.)">
          <xsl:sequence select="map { 'code': 'SUB002', 'id': string($same/@port), 'message': $head || 'its output port '''
              || @name || ''' carries ' || fp:sub-type-label($same) || ', where that of ''' || $swap?old/@name || ''' carries '
              || fp:sub-type-label(.) }"/>
        </xsl:when>
      </xsl:choose>
    </xsl:for-each>
    <xsl:for-each select="$swap?old-bound/pim:service-port[@role eq 'provided'][not(@interface = $new/pim:service-port[@role eq 'provided']/@interface)]">
      <xsl:sequence select="map { 'code': 'SUB008', 'id': string(@port), 'message': $head || 'it does not provide interface '''
          || @interface-name || ''' (port ''' || @port-name || ''' of ''' || $swap?old/@name || '''), whose operations its peers call' }"/>
    </xsl:for-each>
  </xsl:function>

  <!-- SUB003, SUB004: what NEW needs beyond what OLD needed -->
  <xsl:function name="fp:input-problems" as="map(*)*">
    <xsl:param name="swap" as="map(*)"/>
    <xsl:param name="head" as="xs:string"/>
    <xsl:variable name="old" as="element(pim:bound-component)" select="$swap?old-bound"/>
    <xsl:variable name="binding" as="element(pim:binding)?" select="$swap?binding"/>
    <xsl:variable name="names" as="xs:string*" select="$swap?instances/@name"/>
    <xsl:for-each select="$swap?new-bound/pim:data-port[@direction eq 'in']">
      <xsl:variable name="same" as="element(pim:data-port)?" select="$old/pim:data-port[@direction eq 'in'][@name eq current()/@name][1]"/>
      <xsl:choose>
        <xsl:when test="exists($same) and fp:sub-type-key($same) ne fp:sub-type-key(.)">
          <xsl:sequence select="map { 'code': 'SUB004', 'id': string(@port), 'message': $head || 'its input port '''
              || @name || ''' reads ' || fp:sub-type-label(.) || ', where that of ''' || $swap?old/@name || ''' reads '
              || fp:sub-type-label($same) || ': what feeds it now does not fit' }"/>
        </xsl:when>
        <xsl:when test="exists($same)"/>
        <xsl:when test="exists(key('fp:sub-writers', @interface, root($binding))[pim:writer[not(@instance = $names)]])"/>
        <xsl:otherwise>
          <xsl:sequence select="map { 'code': 'SUB003', 'id': string(@port), 'message': $head || 'it needs input port '''
              || @name || ''' (' || fp:sub-type-label(.) || '), which ''' || $swap?old/@name
              || ''' does not need and no connection of the model feeds (no other instance writes interface '''
              || @interface-name || ''')' }"/>
        </xsl:otherwise>
      </xsl:choose>
    </xsl:for-each>
    <xsl:for-each select="$swap?new-bound/pim:service-port[@role eq 'required']
                            [not(@interface = $old/pim:service-port[@role eq 'required']/@interface)]
                            [empty(key('fp:sub-providers', @interface, root($binding))[not(../@component eq $swap?old/@id)])]">
      <xsl:sequence select="map { 'code': 'SUB003', 'id': string(@port), 'message': $head || 'it calls interface '''
          || @interface-name || ''' (port ''' || @port-name || '''), which ''' || $swap?old/@name
          || ''' does not call and no other component of the model provides' }"/>
    </xsl:for-each>
  </xsl:function>

  <!-- SUB005, SUB006: OLD's configuration constants (properties) -->
  <xsl:function name="fp:property-problems" as="map(*)*">
    <xsl:param name="swap" as="map(*)"/>
    <xsl:param name="head" as="xs:string"/>
    <xsl:variable name="new" as="element(pim:attribute)*" select="$swap?new-properties"/>
    <xsl:for-each select="$swap?old-properties">
      <xsl:variable name="same" as="element(pim:attribute)?" select="$new[@name eq current()/@name][1]"/>
      <xsl:choose>
        <xsl:when test="empty($same)">
          <xsl:sequence select="map { 'code': 'SUB005', 'id': string(@id), 'message': $head || 'it has no property '''
              || @name || ''' (' || fp:sub-type-label(.) || '): the configuration constant ''' || $swap?old/@name
              || ''' accepts would be lost' }"/>
        </xsl:when>
        <xsl:when test="fp:sub-type-key($same) ne fp:sub-type-key(.)">
          <xsl:sequence select="map { 'code': 'SUB006', 'id': string($same/@id), 'message': $head || 'its property '''
              || @name || ''' is of type ' || fp:sub-type-label($same) || ', where that of ''' || $swap?old/@name || ''' is '
              || fp:sub-type-label(.) }"/>
        </xsl:when>
      </xsl:choose>
    </xsl:for-each>
  </xsl:function>

  <!-- SUB007: NEW runs at least as often as each instance of OLD -->
  <xsl:function name="fp:period-problems" as="map(*)*">
    <xsl:param name="swap" as="map(*)"/>
    <xsl:param name="head" as="xs:string"/>
    <xsl:variable name="periods" as="xs:double*" select="$swap?new-periods"/>
    <xsl:for-each select="$swap?instances">
      <xsl:variable name="old" as="xs:double" select="xs:double(pim:activity/@period)"/>
      <xsl:variable name="position" as="xs:integer" select="position()"/>
      <xsl:variable name="period" as="xs:double" select="($periods[$position], $old)[1]"/>
      <xsl:if test="$old gt 0 and ($period eq 0 or $period gt $old)">
        <xsl:sequence select="map { 'code': 'SUB007', 'id': ($swap?period-holder, string(@xmi-id))[1], 'message': $head || 'in instance '''
            || @name || ''' it would run ' || (if ($period eq 0) then 'non-periodically (it declares no period)'
                                               else 'every ' || $period || ' s')
            || ', where ''' || $swap?old/@name || ''' runs every ' || $old || ' s: its readers would see its outputs less often' }"/>
      </xsl:if>
    </xsl:for-each>
  </xsl:function>
</xsl:stylesheet>
