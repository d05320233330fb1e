<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/bind/sequence.xsl - bind (xslt/m2m/bind.xsl): the deployment sequence (seed 002): StartAfter constraints and the start order.

  Reads:   the PIM (urn:robomda:pim:1) and the working trees of fp:binding.
  Writes:  parts of pim:binding (schemas/pim/1/binding.xsd), or values.
  Params:  none.  Keys: those of bind.xsl.
  Provides: fp:start-after-dependencies, fp:sequence.
  Errors:  BND012 a StartAfter dependency between elements that are not parts.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:m="urn:robomda:xslt:mode"
    xmlns:t="urn:robomda:xslt:template"
    xmlns:mp="urn:robomda:xslt:mode:private"
    xmlns:err="http://www.w3.org/2005/xqt-errors"
    exclude-result-prefixes="#all">

  <!-- ============================================ deployment sequence -->
  <!-- the deployment-sequence dependencies of the model -->
  <xsl:function name="fp:start-after-dependencies" as="element(pim:dependency)*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:sequence select="$model/pim:application//pim:dependency
        [exists(f:stereotype(., 'StartAfter')) or lower-case(normalize-space(@name)) eq 'startafter']"/>
  </xsl:function>

  <!-- $instances (in document order) with their pim:start-after children
       and @start-order (see the header) -->
  <xsl:function name="fp:sequence" as="element(pim:instance)*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:param name="instance-tree" as="document-node()"/>
    <xsl:variable name="root" as="document-node()" select="root($model)"/>
    <xsl:variable name="deps" as="element(pim:dependency)*" select="fp:start-after-dependencies($model)"/>
    <!-- instance xmi-id -> position in document order -->
    <xsl:variable name="position" as="map(xs:string, xs:integer)"
        select="map:merge(for $k in 1 to count($instances) return map { string($instances[$k]/@xmi-id): $k })"/>
    <!-- the constraints: one fp:edge per (supplier, client) pair of a
         dependency, from the position of the earlier instance to the
         position of the later one -->
    <xsl:variable name="graph" as="document-node()">
      <xsl:document>
        <xsl:for-each select="$deps">
          <xsl:variable name="d" as="element(pim:dependency)" select="."/>
          <xsl:variable name="ends" as="element(pim:instance)*">
            <xsl:for-each select="pim:client, pim:supplier">
              <xsl:variable name="i" as="element(pim:instance)?"
                  select="key('fp:instance-by-part', @element, $instance-tree)"/>
              <xsl:if test="empty($i)">
                <xsl:variable name="e" as="element()?" select="key('fp:id', @element, $root)"/>
                <xsl:sequence select="f:fail('BND012', $d/@id, 'StartAfter dependency ''' || $d/@name
                    || ''' has ' || local-name() || ' '
                    || (if (empty($e)) then '''' || @element || ''', which is not in the model'
                        else local-name($e) || ' ''' || $e/@name || ''', which is not a component instance')
                    || ': client and supplier must be parts that become instances'
                    || ' (or components, in a model without a composite component)')"/>
              </xsl:if>
              <xsl:sequence select="$i"/>
            </xsl:for-each>
          </xsl:variable>
          <xsl:variable name="clients" as="element(pim:instance)*" select="$ends[position() le count($d/pim:client)]"/>
          <xsl:for-each select="$ends[position() gt count($d/pim:client)]">
            <xsl:variable name="s" as="element(pim:instance)" select="."/>
            <xsl:for-each select="$clients">
              <fp:edge from="{$position($s/@xmi-id)}" to="{$position(@xmi-id)}" instance="{$s/@name}" dependency="{$d/@id}"/>
            </xsl:for-each>
          </xsl:for-each>
        </xsl:for-each>
      </xsl:document>
    </xsl:variable>
    <xsl:variable name="edges" as="element(fp:edge)*" select="$graph/fp:edge"/>
    <!-- how many constraints each constrained instance waits for -->
    <xsl:variable name="in-degree" as="map(xs:integer, xs:integer)">
      <xsl:map>
        <xsl:for-each-group select="$edges" group-by="xs:integer(@to)">
          <xsl:map-entry key="current-grouping-key()" select="count(current-group())"/>
        </xsl:for-each-group>
      </xsl:map>
    </xsl:variable>
    <xsl:variable name="n" as="xs:integer" select="count($instances)"/>
    <!-- Kahn's algorithm; $free: the positions with no constraint, in
         order; $released: the positions whose constraints all started,
         sorted; each step starts the smallest position of the two -->
    <xsl:variable name="order" as="document-node()">
      <xsl:document>
        <xsl:iterate select="1 to $n">
          <xsl:param name="free" as="xs:integer*"
              select="(1 to $n)[not(map:contains($in-degree, .))]"/>
          <xsl:param name="released" as="xs:integer*" select="()"/>
          <xsl:param name="waiting" as="map(xs:integer, xs:integer)" select="$in-degree"/>
          <xsl:variable name="next" as="xs:integer?" select="min(($free[1], $released[1]))"/>
          <xsl:choose>
            <xsl:when test="empty($next)">
              <xsl:break/>
            </xsl:when>
            <xsl:otherwise>
              <fp:placed position="{$next}" start-order="{.}"/>
              <xsl:variable name="after" as="map(xs:integer, xs:integer)">
                <xsl:map>
                  <xsl:for-each-group select="key('fp:edge-from', string($next), $graph)" group-by="xs:integer(@to)">
                    <xsl:map-entry key="current-grouping-key()"
                        select="$waiting(current-grouping-key()) - count(current-group())"/>
                  </xsl:for-each-group>
                </xsl:map>
              </xsl:variable>
              <xsl:variable name="now-free" as="xs:integer*"
                  select="map:keys($after)[$after(.) eq 0]"/>
              <xsl:next-iteration>
                <xsl:with-param name="free" select="if ($free[1] eq $next) then subsequence($free, 2) else $free"/>
                <xsl:with-param name="released"
                    select="let $rest := (if ($released[1] eq $next) then subsequence($released, 2) else $released)
                            return if (empty($now-free)) then $rest else sort(($rest, $now-free))"/>
                <xsl:with-param name="waiting" as="map(xs:integer, xs:integer)">
                  <xsl:iterate select="map:keys($after)">
                    <xsl:param name="m" as="map(xs:integer, xs:integer)" select="$waiting"/>
                    <xsl:on-completion select="$m"/>
                    <xsl:next-iteration>
                      <xsl:with-param name="m" select="map:put($m, ., $after(.))"/>
                    </xsl:next-iteration>
                  </xsl:iterate>
                </xsl:with-param>
              </xsl:next-iteration>
            </xsl:otherwise>
          </xsl:choose>
        </xsl:iterate>
      </xsl:document>
    </xsl:variable>
    <xsl:for-each select="$instances">
      <xsl:variable name="p" as="xs:integer" select="position()"/>
      <xsl:copy>
        <xsl:sequence select="@*"/>
        <xsl:for-each select="key('fp:placed', string($p), $order)">
          <xsl:attribute name="start-order" select="@start-order"/>
        </xsl:for-each>
        <xsl:sequence select="node()"/>
        <xsl:for-each select="key('fp:edge-to', string($p), $graph)">
          <pim:start-after instance="{@instance}" xmi-id="{@dependency}"/>
        </xsl:for-each>
      </xsl:copy>
    </xsl:for-each>
  </xsl:function>
</xsl:stylesheet>
