<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/configure.xsl - resolve a template PIM for one configuration of
  its feature model (seed 002: template system model + feature selection +
  resolution model -> configured system model).

  Reads:   a PIM, urn:robomda:pim:1 (schemas/pim/1/pim.xsd), as written by
           xslt/import/import.xsl (before bind); through doc() the files of
           its parameters.
  Writes:  the configured PIM (schemas/pim/1/pim.xsd), indented as f:indent
           (common/indent.xsl) indents it: the template without the elements
           whose presence condition is false and what depends on them, with
           the actions of the selected features applied. Nothing else
           changes: a configured model is the model a user would write
           without the removed parts (tests/test_variability.py).
  Params:  features       URI of a FeatureIDE configuration (required)
           feature-model  URI of its FeatureIDE feature model (required)
           resolution     URI of the resolution model
                          (schemas/variability/1/resolution.xsd; required)
           The pipeline runs this step only when `features` is given
           (pipelines/import.xml, step/@if).
  Modules: variability/features.xsl (configuration against feature model,
           formulas).
  Errors:  VAR010-VAR019 (variability/features.xsl): the configuration is
           invalid for its feature model, or the feature model unusable;
           VAR020 the resolution names a feature the feature model lacks;
           VAR021 it names a model element the PIM lacks; VAR022 the element
           is not of the kind the action needs; VAR023 a component to
           realize otherwise has no realizing class; VAR024 two selected
           features act on the same element the same way. All are stated
           before the run stops (f:fail-all), located in the configuration,
           feature model or resolution file.
  Info:    VAR030 an element removed by its presence condition (located at
           the element in the XMI, naming the condition); VAR031 an element
           removed with it (a part typed by a removed component, a connector
           or dependency with an end at a removed element, a deployment or
           manifestation of one), naming the element and condition that
           removed it.
  Warning: VAR032 a connector removed (by its condition, or with a part)
           leaves a port of a part
           that stays without any connection: names the feature condition
           that removed it, so a rule failing later on the configured model
           (an unconnected input) can be traced to the feature.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:r="urn:robomda:resolution:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:m="urn:robomda:xslt:mode"
    xmlns:mp="urn:robomda:xslt:mode:private"
    exclude-result-prefixes="#all">

  <xsl:include href="../common/errors.xsl"/>
  <xsl:include href="../common/indent.xsl"/>
  <xsl:include href="variability/features.xsl"/>

  <xsl:param name="features" as="xs:string" select="''">
    <!-- URI of the FeatureIDE configuration -->
  </xsl:param>
  <xsl:param name="feature-model" as="xs:string" select="''">
    <!-- URI of the FeatureIDE feature model the configuration configures -->
  </xsl:param>
  <xsl:param name="resolution" as="xs:string" select="''">
    <!-- URI of the resolution model (schemas/variability/1/resolution.xsd) -->
  </xsl:param>

  <xsl:global-context-item as="document-node(element(pim:model))" use="required"/>
  <xsl:output method="xml" indent="no" encoding="UTF-8"/>
  <xsl:mode on-no-match="fail"/>
  <xsl:mode name="mp:configure" on-no-match="shallow-copy"/>

  <xsl:key name="fp:qn" match="pim:*[@qualified-name]" use="@qualified-name"/>
  <xsl:key name="fp:part-by-type" match="pim:part" use="@type"/>
  <xsl:key name="fp:connector-by-end" match="pim:connector" use="pim:end/(@part, @role)"/>
  <xsl:key name="fp:dependency-by-end" match="pim:dependency" use="(pim:client, pim:supplier)/@element"/>
  <xsl:key name="fp:manifestation-by-element" match="pim:manifestation" use="@element"/>
  <xsl:key name="fp:deployment-by-deployed" match="pim:deployment" use="tokenize(@deployed)"/>
  <xsl:key name="fp:realization-by-classifier" match="pim:realization" use="@classifier"/>
  <xsl:key name="fp:feature-name" match="struct//*[@name]" use="@name"/>

  <xsl:variable name="pim" as="document-node()" select="/"/>
  <xsl:variable name="fm" as="document-node()" select="doc($feature-model)"/>
  <xsl:variable name="cfg" as="document-node()" select="doc($features)"/>
  <xsl:variable name="res" as="document-node()" select="doc($resolution)"/>
  <xsl:variable name="selected" as="xs:string*" select="f:selected($cfg)"/>
  <xsl:variable name="config-name" as="xs:string" select="replace(base-uri($cfg/*), '^.*/', '')"/>

  <!-- the presence conditions that are false, each with the element it removes -->
  <xsl:variable name="absent" as="map(*)*">
    <xsl:for-each select="$res/r:resolution/r:present">
      <xsl:variable name="condition" as="xs:boolean"
          select="if (@when) then string(@when) = $selected else f:holds(*[1], $selected)"/>
      <xsl:variable name="target" as="element()?" select="key('fp:qn', @element, $pim)[1]"/>
      <xsl:if test="not($condition) and exists($target)">
        <xsl:sequence select="map { 'element': $target, 'why': fp:condition-text(.) }"/>
      </xsl:if>
    </xsl:for-each>
  </xsl:variable>

  <!-- removed element id -> map { why, by (the element whose removal removed it, or empty) } -->
  <xsl:variable name="gone" as="map(xs:string, map(*))">
    <xsl:variable name="roots" as="map(xs:string, map(*))" select="map:merge(
        for $a in $absent, $e in $a?element/descendant-or-self::*[@id]
        return map:entry(string($e/@id), map { 'why': $a?why, 'by': () }),
        map { 'duplicates': 'use-first' })"/>
    <xsl:variable name="parts" as="map(xs:string, map(*))" select="map:merge((
        $roots,
        for $id in sort(map:keys($roots)), $p in key('fp:part-by-type', $id, $pim)
        return map:entry(string($p/@id), map { 'why': $roots($id)?why, 'by': key('fp:id-any', $id, $pim)[1] })),
        map { 'duplicates': 'use-first' })"/>
    <xsl:sequence select="map:merge((
        $parts,
        for $id in sort(map:keys($parts)),
            $d in (key('fp:connector-by-end', $id, $pim), key('fp:dependency-by-end', $id, $pim),
                   key('fp:manifestation-by-element', $id, $pim), key('fp:realization-by-classifier', $id, $pim),
                   key('fp:deployment-by-deployed', $id, $pim)[every $t in tokenize(@deployed) satisfies map:contains($parts, $t)])
        return map:entry(string($d/@id), map { 'why': $parts($id)?why, 'by': key('fp:id-any', $id, $pim)[1] })),
        map { 'duplicates': 'use-first' })"/>
  </xsl:variable>
  <xsl:key name="fp:id-any" match="*[@id]" use="@id"/>

  <!-- the selected features' actions, by the id of the element they act on -->
  <xsl:variable name="acting" as="element()*" select="$res/r:resolution/r:feature[@name = $selected]/*"/>
  <xsl:variable name="realize" as="map(*)" select="fp:by-target($acting/self::r:realize, 'component')"/>
  <xsl:variable name="set" as="map(*)" select="fp:by-target($acting/self::r:set[empty(@part)], 'attribute')"/>
  <!-- "part id|attribute id" -> the set action that gives that part's value of the attribute -->
  <xsl:variable name="set-value" as="map(*)" select="map:merge(
      for $a in $acting/self::r:set[@part], $p in key('fp:qn', string($a/@part), $pim)[1],
          $t in key('fp:qn', string($a/@attribute), $pim)[1]
      return map:entry($p/@id || '|' || $t/@id, $a), map { 'duplicates': 'use-first' })"/>
  <xsl:variable name="policy" as="map(*)" select="fp:by-target($acting/self::r:policy, 'connector')"/>
  <xsl:variable name="deploy" as="map(*)" select="fp:by-target($acting/self::r:deploy, 'element')"/>
  <!-- node id -> the deployments that move there -->
  <xsl:variable name="moved-to" as="map(*)" select="map:merge(
      for $id in map:keys($deploy), $d in key('fp:deployment-by-deployed', $id, $pim)
      return map:entry(string(key('fp:qn', $deploy($id)/@on, $pim)[1]/@id), $d),
      map { 'duplicates': 'combine' })"/>

  <xsl:function name="fp:by-target" as="map(*)">
    <xsl:param name="actions" as="element()*"/>
    <xsl:param name="attribute" as="xs:string"/>
    <xsl:sequence select="map:merge(
        for $a in $actions, $t in key('fp:qn', string($a/@*[local-name() eq $attribute]), $pim)[1]
        return map:entry(string($t/@id), $a), map { 'duplicates': 'use-first' })"/>
  </xsl:function>

  <xsl:function name="fp:condition-text" as="xs:string">
    <xsl:param name="present" as="element(r:present)"/>
    <xsl:sequence select="if ($present/@when) then 'feature ' || $present/@when || ' not selected'
                          else f:formula-text($present/*[1]) || ' is false'"/>
  </xsl:function>

  <xsl:template match="/" as="document-node()">
    <xsl:sequence select="f:fail-all((f:model-errors($fm), f:configuration-errors($fm, $cfg), fp:resolution-errors()))"/>
    <xsl:call-template name="fp:report"/>
    <xsl:variable name="configured" as="document-node()">
      <xsl:document>
        <xsl:apply-templates select="pim:model" mode="mp:configure"/>
      </xsl:document>
    </xsl:variable>
    <xsl:sequence select="f:indent($configured)"/>
  </xsl:template>

  <!-- ======================================================== the copy -->
  <xsl:template match="pim:*[@id][map:contains($gone, string(@id))]" mode="mp:configure" priority="2"/>

  <xsl:template match="pim:deployment[some $t in tokenize(@deployed) satisfies map:contains($deploy, $t)]"
                mode="mp:configure" priority="1"/>

  <xsl:template match="pim:deployment[some $t in tokenize(@deployed) satisfies map:contains($gone, $t)]"
                mode="mp:configure" as="element(pim:deployment)">
    <xsl:copy>
      <xsl:copy-of select="@* except @deployed"/>
      <xsl:attribute name="deployed" select="tokenize(@deployed)[not(map:contains($gone, .))]"/>
      <xsl:apply-templates mode="mp:configure"/>
    </xsl:copy>
  </xsl:template>

  <xsl:template match="pim:node[map:contains($moved-to, string(@id))]" mode="mp:configure" as="element(pim:node)">
    <xsl:variable name="node" as="element(pim:node)" select="."/>
    <xsl:copy>
      <xsl:copy-of select="@*"/>
      <xsl:apply-templates select="node() except pim:node" mode="mp:configure"/>
      <xsl:for-each select="$moved-to(string(@id))">
        <xsl:copy>
          <xsl:copy-of select="@*"/>
          <xsl:apply-templates mode="mp:configure"/>
        </xsl:copy>
      </xsl:for-each>
      <xsl:apply-templates select="pim:node" mode="mp:configure"/>
    </xsl:copy>
  </xsl:template>

  <xsl:template match="pim:realization[map:contains($realize, string(../@id))]" mode="mp:configure"
                as="element(pim:realization)">
    <xsl:copy>
      <xsl:copy-of select="@id"/>
      <xsl:attribute name="classifier" select="key('fp:qn', $realize(string(../@id))/@class, $pim)[1]/@id"/>
    </xsl:copy>
  </xsl:template>

  <xsl:template match="pim:attribute[map:contains($set, string(@id))]" mode="mp:configure" as="element(pim:attribute)">
    <xsl:variable name="value" as="xs:string" select="$set(string(@id))/@value"/>
    <xsl:copy>
      <xsl:for-each select="@*">
        <xsl:attribute name="{name()}" select="if (local-name() eq 'default') then $value else string(.)"/>
      </xsl:for-each>
      <xsl:if test="empty(@default)">
        <xsl:attribute name="default" select="$value"/>
      </xsl:if>
      <xsl:apply-templates mode="mp:configure"/>
    </xsl:copy>
  </xsl:template>

  <!-- a part whose value of an attribute a selected feature sets: that value replaced, or added last -->
  <xsl:template match="pim:part[some $k in map:keys($set-value) satisfies starts-with($k, @id || '|')]"
                mode="mp:configure" as="element(pim:part)">
    <xsl:variable name="part" as="element(pim:part)" select="."/>
    <xsl:copy>
      <xsl:copy-of select="@*"/>
      <xsl:for-each select="node()">
        <xsl:variable name="action" as="element(r:set)?" select="self::pim:value/$set-value($part/@id || '|' || @attribute)"/>
        <xsl:choose>
          <xsl:when test="exists($action)">
            <pim:value id="{@id}" attribute="{@attribute}" value="{$action/@value}"/>
          </xsl:when>
          <xsl:otherwise>
            <xsl:apply-templates select="." mode="mp:configure"/>
          </xsl:otherwise>
        </xsl:choose>
      </xsl:for-each>
      <xsl:for-each select="sort(map:keys($set-value)[starts-with(., $part/@id || '|')])">
        <xsl:variable name="attribute" as="xs:string" select="substring-after(., '|')"/>
        <xsl:if test="empty($part/pim:value[@attribute eq $attribute])">
          <pim:value id="{$part/@id}-{$attribute}" attribute="{$attribute}" value="{$set-value(.)/@value}"/>
        </xsl:if>
      </xsl:for-each>
    </xsl:copy>
  </xsl:template>

  <xsl:template match="pim:connector[map:contains($policy, string(@id))]" mode="mp:configure" as="element(pim:connector)">
    <xsl:variable name="action" as="element(r:policy)" select="$policy(string(@id))"/>
    <xsl:variable name="old" as="element(pim:stereotype)?" select="pim:stereotype[@name eq 'ConnectionPolicy']"/>
    <xsl:variable name="given" as="map(xs:string, xs:string)" select="map:merge((
        $action/@type ! map:entry('type', string(.)), $action/@size ! map:entry('size', string(.)),
        $action/@lock-policy ! map:entry('lockPolicy', string(.)), $action/@topic ! map:entry('topic', string(.))))"/>
    <xsl:copy>
      <xsl:copy-of select="@*"/>
      <xsl:apply-templates select="pim:stereotype except $old" mode="mp:configure"/>
      <pim:stereotype id="{if ($old) then $old/@id else @id || '-policy'}" name="ConnectionPolicy"
                      profile="robomda" profile-uri="http://robomda.org/profile/robomda/1">
        <xsl:for-each select="('type', 'size', 'lockPolicy', 'init', 'pull', 'topic')">
          <xsl:variable name="tag" as="xs:string" select="."/>
          <xsl:variable name="value" as="xs:string?" select="($given($tag), $old/pim:tag[@name eq $tag]/@value)[1]"/>
          <xsl:if test="exists($value)">
            <pim:tag name="{$tag}" value="{$value}"/>
          </xsl:if>
        </xsl:for-each>
      </pim:stereotype>
      <xsl:apply-templates select="node() except pim:stereotype" mode="mp:configure"/>
    </xsl:copy>
  </xsl:template>

  <!-- ================================================ what was removed -->
  <xsl:template name="fp:report" as="empty-sequence()">
    <xsl:for-each select="$absent">
      <xsl:message select="'VAR030: ' || fp:kind(?element) || ' ''' || ?element/@name || ''' removed in configuration '''
          || $config-name || ''': its presence condition (' || ?why || ') [xmi:id=' || ?element/@id || ']'"/>
    </xsl:for-each>
    <xsl:for-each select="map:keys($gone)[exists($gone(.)?by)]">
      <xsl:sort select="."/>
      <xsl:variable name="e" as="element()" select="key('fp:id-any', ., $pim)[1]"/>
      <xsl:message select="'VAR031: ' || fp:kind($e) || ' ''' || fp:name($e) || ''' removed with ' || fp:kind($gone(.)?by)
          || ' ''' || fp:name($gone(.)?by) || ''' (' || $gone(.)?why || ') [xmi:id=' || $e/@id || ']'"/>
    </xsl:for-each>
    <xsl:for-each select="map:keys($gone)">
      <xsl:sort select="."/>
      <xsl:variable name="c" as="element()" select="key('fp:id-any', ., $pim)[1]"/>
      <xsl:for-each select="$c/self::pim:connector/pim:end[@part][not(map:contains($gone, string(@part)))]">
        <xsl:variable name="end" as="element(pim:end)" select="."/>
        <xsl:if test="every $k in key('fp:connector-by-end', string($end/@role), $pim)[pim:end/@part = $end/@part]
                      satisfies map:contains($gone, string($k/@id))">
          <xsl:sequence select="f:warn('VAR032', string($c/@id), 'connector ''' || $c/@name || ''' is removed in configuration '''
              || $config-name || ''' (' || $gone(string($c/@id))?why || '), which leaves port '''
              || key('fp:id-any', $end/@role, $pim)[1]/@name || ''' of part ''' || key('fp:id-any', $end/@part, $pim)[1]/@name
              || ''' with no connection')"/>
        </xsl:if>
      </xsl:for-each>
    </xsl:for-each>
  </xsl:template>

  <xsl:function name="fp:kind" as="xs:string">
    <xsl:param name="e" as="element()"/>
    <xsl:sequence select="local-name($e)"/>
  </xsl:function>

  <xsl:function name="fp:name" as="xs:string">
    <xsl:param name="e" as="element()"/>
    <xsl:sequence select="string(($e/@name[. ne ''], $e/@id)[1])"/>
  </xsl:function>

  <!-- ======================================= the resolution, checked -->
  <xsl:function name="fp:resolution-errors" as="map(*)*">
    <xsl:for-each select="$res/r:resolution//(r:var, r:present/@when, r:feature/@name)">
      <xsl:if test="empty(key('fp:feature-name', normalize-space(), $fm))">
        <xsl:sequence select="map { 'code': 'VAR020', 'id': f:where((self::*, ..)[1]), 'message':
            'the resolution names feature ''' || normalize-space() || ''', which the feature model does not have' }"/>
      </xsl:if>
    </xsl:for-each>
    <xsl:for-each select="$res/r:resolution//(r:present/@element, r:realize/(@component, @class), r:set/(@attribute, @part),
                                               r:policy/@connector, r:deploy/(@element, @on))">
      <xsl:variable name="target" as="element()?" select="key('fp:qn', string(.), $pim)[1]"/>
      <xsl:variable name="kinds" as="xs:string*" select="fp:kinds-for(.)"/>
      <xsl:choose>
        <xsl:when test="empty($target)">
          <xsl:sequence select="map { 'code': 'VAR021', 'id': f:where(..), 'message':
              'the resolution names model element ''' || . || ''', which the model does not have' }"/>
        </xsl:when>
        <xsl:when test="exists($kinds) and not(local-name($target) = $kinds)">
          <xsl:sequence select="map { 'code': 'VAR022', 'id': f:where(..), 'message':
              local-name(..) || '/@' || local-name() || ' names ' || local-name($target) || ' ''' || . || ''', not a '
              || string-join($kinds, ' or ') }"/>
        </xsl:when>
        <xsl:when test="self::attribute(component)[parent::r:realize] and empty($target/pim:realization)">
          <xsl:sequence select="map { 'code': 'VAR023', 'id': f:where(..), 'message':
              'component ''' || . || ''' has no realizing class to swap' }"/>
        </xsl:when>
      </xsl:choose>
    </xsl:for-each>
    <xsl:for-each-group select="$acting" group-by="local-name() || '|' || string(@part) || '|' || string((@component, @attribute, @connector, @element)[1])">
      <xsl:if test="count(current-group()) gt 1">
        <xsl:sequence select="map { 'code': 'VAR024', 'id': f:where(current-group()[2]), 'message':
            'features ' || string-join(current-group()/../@name, ' and ') || ' both ' || local-name() || ' '''
            || (@component, @attribute, @connector, @element)[1] || ''' in this configuration' }"/>
      </xsl:if>
    </xsl:for-each-group>
  </xsl:function>

  <!-- the PIM element kinds an action's reference may name (empty: any) -->
  <xsl:function name="fp:kinds-for" as="xs:string*">
    <xsl:param name="ref" as="attribute()"/>
    <xsl:variable name="at" as="xs:string" select="local-name($ref/..) || '/@' || local-name($ref)"/>
    <xsl:sequence select="map {
        'realize/@component': 'component', 'realize/@class': 'class', 'set/@attribute': 'attribute', 'set/@part': 'part',
        'policy/@connector': 'connector', 'deploy/@element': ('artifact', 'part', 'component'), 'deploy/@on': 'node'
      }($at)"/>
  </xsl:function>
</xsl:stylesheet>
