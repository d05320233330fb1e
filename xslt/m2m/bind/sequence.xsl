<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/bind/sequence.xsl - bind (xslt/m2m/bind.xsl): the deployment sequence (seed 002): StartAfter constraints and the start order.

  Reads:   the PIM (urn:robomda:pim:1) and the working trees of fp:binding.
  Writes:  parts of pim:binding (schemas/pim/1/binding.xsd), or values.
  Params:  none.  Keys: those of bind.xsl.
  Provides: fp:start-after-dependencies, fp:sequence (with fp:start-graph,
           fp:dependency-end, fp:start-order, fp:put-all).
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
    <xsl:variable name="graph" as="document-node()" select="fp:start-graph($model, $instances, $instance-tree)"/>
    <xsl:variable name="order" as="document-node()" select="fp:start-order($graph, count($instances))"/>
    <xsl:for-each select="$instances">
      <xsl:variable name="position" as="xs:integer" select="position()"/>
      <xsl:copy>
        <xsl:sequence select="@*"/>
        <xsl:for-each select="key('fp:placed', string($position), $order)">
          <xsl:attribute name="start-order" select="@start-order"/>
        </xsl:for-each>
        <xsl:sequence select="node()"/>
        <xsl:for-each select="key('fp:edge-to', string($position), $graph)">
          <pim:start-after instance="{@instance}" xmi-id="{@dependency}"/>
        </xsl:for-each>
      </xsl:copy>
    </xsl:for-each>
  </xsl:function>

  <!-- the constraints: one fp:edge per (supplier, client) pair of a
       StartAfter dependency, from the position (in $instances) of the
       earlier instance to the position of the later one -->
  <xsl:function name="fp:start-graph" as="document-node()">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:param name="instance-tree" as="document-node()"/>
    <!-- instance name (unique: BND009) -> position in document order -->
    <xsl:variable name="position" as="map(xs:string, xs:integer)"
        select="map:merge(for $k in 1 to count($instances) return map { string($instances[$k]/@name): $k })"/>
    <xsl:document>
      <xsl:for-each select="fp:start-after-dependencies($model)">
        <xsl:variable name="dependency" as="element(pim:dependency)" select="."/>
        <!-- clients first: a wrong client is reported before a wrong supplier -->
        <xsl:variable name="clients" as="element(pim:instance)*" select="pim:client ! fp:dependency-end(., $instance-tree)"/>
        <xsl:for-each select="pim:supplier ! fp:dependency-end(., $instance-tree)">
          <xsl:variable name="supplier" as="element(pim:instance)" select="."/>
          <xsl:for-each select="$clients">
            <fp:edge from="{$position($supplier/@name)}" to="{$position(@name)}"
                     instance="{$supplier/@name}" dependency="{$dependency/@id}"/>
          </xsl:for-each>
        </xsl:for-each>
      </xsl:for-each>
    </xsl:document>
  </xsl:function>

  <!-- the instance a client or supplier of a StartAfter dependency names;
       BND012 when it names something that is not one -->
  <xsl:function name="fp:dependency-end" as="element(pim:instance)+">
    <xsl:param name="end" as="element()"/>
    <xsl:param name="instance-tree" as="document-node()"/>
    <!-- a part inside a composite used twice is two instances; a composite
         part stands for every instance inside it -->
    <xsl:variable name="composites" as="element(pim:composite-instance)*"
        select="$instance-tree/pim:composite-instance[@xmi-id eq $end/@element]"/>
    <xsl:variable name="instance" as="element(pim:instance)*"
        select="key('fp:instance-by-part', $end/@element, $instance-tree)
                | (if (exists($composites))
                   then $instance-tree/pim:instance[some $c in $composites satisfies starts-with(@path, $c/@path || '.')]
                   else ())"/>
    <xsl:variable name="dependency" as="element(pim:dependency)" select="$end/.."/>
    <xsl:variable name="element" as="element()?" select="key('fp:id', $end/@element, root($end))"/>
    <xsl:sequence select="if (exists($instance)) then $instance
        else f:fail('BND012', $dependency/@id, 'StartAfter dependency ''' || $dependency/@name
                    || ''' has ' || local-name($end) || ' '
                    || (if (empty($element)) then '''' || $end/@element || ''', which is not in the model'
                        else local-name($element) || ' ''' || $element/@name || ''', which is not a component instance')
                    || ': client and supplier must be parts (or composite parts) that become instances'
                    || ' (or components, in a model without a composite component)')"/>
  </xsl:function>

  <!-- Kahn's algorithm on $graph over positions 1 to $count: one fp:placed
       per position that gets a start order. $free: the positions with no
       constraint, in order; $released: the positions whose constraints all
       started, sorted; each step starts the smallest position of the two.
       Positions on a cycle get none. -->
  <xsl:function name="fp:start-order" as="document-node()">
    <xsl:param name="graph" as="document-node()"/>
    <xsl:param name="count" as="xs:integer"/>
    <!-- how many constraints each constrained instance waits for -->
    <xsl:variable name="in-degree" as="map(xs:integer, xs:integer)">
      <xsl:map>
        <xsl:for-each-group select="$graph/fp:edge" group-by="xs:integer(@to)">
          <xsl:map-entry key="current-grouping-key()" select="count(current-group())"/>
        </xsl:for-each-group>
      </xsl:map>
    </xsl:variable>
    <xsl:document>
      <xsl:iterate select="1 to $count">
        <xsl:param name="free" as="xs:integer*" select="(1 to $count)[not(map:contains($in-degree, .))]"/>
        <xsl:param name="released" as="xs:integer*" select="()"/>
        <xsl:param name="waiting" as="map(xs:integer, xs:integer)" select="$in-degree"/>
        <xsl:variable name="next" as="xs:integer?" select="min(($free[1], $released[1]))"/>
        <xsl:choose>
          <xsl:when test="empty($next)">
            <xsl:break/>
          </xsl:when>
          <xsl:otherwise>
            <fp:placed position="{$next}" start-order="{.}"/>
            <!-- the waiting counts of the positions that wait for $next, less it -->
            <xsl:variable name="after" as="map(xs:integer, xs:integer)">
              <xsl:map>
                <xsl:for-each-group select="key('fp:edge-from', string($next), $graph)" group-by="xs:integer(@to)">
                  <xsl:map-entry key="current-grouping-key()"
                      select="$waiting(current-grouping-key()) - count(current-group())"/>
                </xsl:for-each-group>
              </xsl:map>
            </xsl:variable>
            <xsl:variable name="now-free" as="xs:integer*" select="map:keys($after)[$after(.) eq 0]"/>
            <xsl:variable name="rest" as="xs:integer*"
                select="if ($released[1] eq $next) then subsequence($released, 2) else $released"/>
            <xsl:next-iteration>
              <xsl:with-param name="free" select="if ($free[1] eq $next) then subsequence($free, 2) else $free"/>
              <xsl:with-param name="released" select="if (empty($now-free)) then $rest else sort(($rest, $now-free))"/>
              <xsl:with-param name="waiting" select="fp:put-all($waiting, $after)"/>
            </xsl:next-iteration>
          </xsl:otherwise>
        </xsl:choose>
      </xsl:iterate>
    </xsl:document>
  </xsl:function>

  <!-- $map with the entries of $changes put in, one map:put each (a
       persistent map: the cost grows with $changes, not with $map) -->
  <xsl:function name="fp:put-all" as="map(xs:integer, xs:integer)">
    <xsl:param name="map" as="map(xs:integer, xs:integer)"/>
    <xsl:param name="changes" as="map(xs:integer, xs:integer)"/>
    <xsl:iterate select="map:keys($changes)">
      <xsl:param name="result" as="map(xs:integer, xs:integer)" select="$map"/>
      <xsl:on-completion select="$result"/>
      <xsl:next-iteration>
        <xsl:with-param name="result" select="map:put($result, ., $changes(.))"/>
      </xsl:next-iteration>
    </xsl:iterate>
  </xsl:function>
</xsl:stylesheet>
