<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/configure.xsl - resolve a template PIM for one configuration of
  its feature model (seed 002: template system model + feature selection +
  resolution model -> configured system model), or for the configurations
  the model's jobs name (a «Job» with tag configuration: docs/jobs.md,
  "Jobs given as configurations").

  Reads:   a PIM, urn:robomda:pim:1 (schemas/pim/1/pim.xsd), as written by
           xslt/import/import.xsl (before bind); through doc() the files of
           its parameters, or those the jobs' configuration tags name.
  Writes:  the configured PIM (schemas/pim/1/pim.xsd), indented as f:indent
           (common/indent.xsl) indents it: the template without the elements
           whose presence condition is false and what depends on them, with
           the actions of the selected features applied. Nothing else
           changes: a configured model is the model a user would write
           without the removed parts (tests/test_variability.py).
           For jobs given as configurations ("job mode": no `features`,
           and some pim:job whose «Job» has a tag configuration): an element
           is removed when its condition is false in every job's
           configuration, the actions of the features every job selects are
           applied as above, and each such job gets a pim:member per part
           of its composite that its configuration keeps, with a pim:value
           per value its configuration's other features set (pim:member /
           pim:value @at: the job, where a diagnostic about them points);
           the slots the «Job» lists itself are kept and win.
  Params:  features       URI of a FeatureIDE configuration ("" = job mode
                          when the model has jobs given as configurations)
           feature-model  URI of its FeatureIDE feature model
           resolution     URI of the resolution model
                          (schemas/variability/1/resolution.xsd)
           model-uri      URI of the XMI model: a job's configuration tag is
                          a path relative to its folder
           The pipeline runs this step only when `features` is given or the
           model has jobs given as configurations (pipelines/import.xml,
           step/@if "features job-configurations").
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
           Job mode (located on the «Job», else in the resolution file):
           JOB100 a job's configuration cannot be read: no such file, not
           well-formed XML, outside the model's folder; JOB101 no feature
           model (model.xml) in its folder or the one above, or no
           resolution.xml beside it; JOB102 the jobs' configurations belong
           to different feature models; JOB103 a file that is no FeatureIDE
           configuration / feature model / robomda resolution (its root
           element); JOB104 a swap (realize), policy or deploy action that
           some jobs' configurations select and others do not: the jobs share
           one system; JOB105 a slot of a «Job» names a part that its
           configuration (or, for a job of slots only, every job's
           configuration) removes; JOB106 `features` given for a model whose
           jobs are configurations; JOB107 a job given as a configuration
           whose classifier is no composite component with parts.
  Info:    VAR030 an element removed by its presence condition (located at
           the element in the XMI, naming the condition); VAR031 an element
           removed with it (a part typed by a removed component, a connector
           or dependency with an end at a removed element, a deployment or
           manifestation of one), naming the element and condition that
           removed it. JOB111 (job mode) per job given as a configuration:
           its features, members and values.
  Warning: VAR032 a connector removed (by its condition, or with a part)
           leaves a port of a part
           that stays without any connection: names the feature condition
           that removed it, so a rule failing later on the configured model
           (an unconnected input) can be traced to the feature.
           JOB110 (job mode) a connector whose condition is false in a job's
           configuration that keeps the parts at both its ends: kept for the
           jobs that have it, it carries data in that job too. JOB112 (job
           mode) a `set` of an attribute default that some jobs' features
           select: it becomes a value of the job's members whose realizing
           class owns the attribute, and reaches no member of that job.
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
  <xsl:include href="variability/jobs.xsl"/>

  <xsl:param name="features" as="xs:string" select="''">
    <!-- URI of the FeatureIDE configuration ("": the jobs' configurations, if any) -->
  </xsl:param>
  <xsl:param name="feature-model" as="xs:string" select="''">
    <!-- URI of the FeatureIDE feature model the configuration configures -->
  </xsl:param>
  <xsl:param name="resolution" as="xs:string" select="''">
    <!-- URI of the resolution model (schemas/variability/1/resolution.xsd) -->
  </xsl:param>
  <xsl:param name="model-uri" as="xs:string" select="''">
    <!-- URI of the XMI model, against which a job's configuration tag resolves -->
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
  <!-- job mode: no configuration given, and jobs given as configurations (variability/jobs.xsl) -->
  <xsl:variable name="config-jobs" as="element(pim:job)*"
      select="/pim:model/pim:coordination/pim:job[exists(fp:job-configuration(.))]"/>
  <xsl:variable name="job-mode" as="xs:boolean" select="$features eq '' and exists($config-jobs)"/>
  <xsl:variable name="job-files" as="map(*)*" select="if ($job-mode) then $config-jobs ! fp:job-files(., $model-uri) else ()"/>
  <xsl:variable name="fm" as="document-node()" select="doc(if ($job-mode) then $job-files[1]?fm else $feature-model)"/>
  <xsl:variable name="res" as="document-node()" select="doc(if ($job-mode) then $job-files[1]?res else $resolution)"/>
  <xsl:variable name="config-name" as="xs:string" select="replace($features, '^.*/', '')"/>
  <!-- the selections resolved: the configuration given, or one per job given as a configuration -->
  <xsl:variable name="selections" as="map(*)*" select="
      if ($job-mode) then $job-files ! (let $cfg := doc(?cfg) return
        map { 'job': ?job, 'cfg': $cfg, 'name': replace(?cfg, '^.*/', ''), 'selected': f:selected($cfg) })
      else (let $cfg := doc($features) return map { 'cfg': $cfg, 'name': $config-name, 'selected': f:selected($cfg) })"/>
  <!-- how the removals and the configuration are named in the messages -->
  <xsl:variable name="config-label" as="xs:string" select="
      if ($job-mode) then 'the configuration of every job (''' || string-join($selections ! ?name, ''', ''') || ''')'
      else 'configuration ''' || $config-name || ''''"/>

  <!-- the presence conditions false in every selection, each with the element it removes -->
  <xsl:variable name="absent" as="map(*)*" select="fp:absent($selections)"/>
  <xsl:function name="fp:absent" as="map(*)*">
    <xsl:param name="selections" as="map(*)*"/>
    <xsl:for-each select="$res/r:resolution/r:present">
      <xsl:variable name="present" as="element(r:present)" select="."/>
      <xsl:variable name="target" as="element()?" select="key('fp:qn', @element, $pim)[1]"/>
      <xsl:if test="exists($target) and (every $s in $selections satisfies not(fp:holds-in($present, $s)))">
        <xsl:sequence select="map { 'element': $target, 'why': fp:condition-text(.) }"/>
      </xsl:if>
    </xsl:for-each>
  </xsl:function>

  <xsl:function name="fp:holds-in" as="xs:boolean">
    <xsl:param name="present" as="element(r:present)"/>
    <xsl:param name="selection" as="map(*)"/>
    <xsl:sequence select="if ($present/@when) then string($present/@when) = $selection?selected
                          else f:holds($present/*[1], $selection?selected)"/>
  </xsl:function>

  <!-- removed element id -> map { why, by (the element whose removal removed it, or empty) } -->
  <xsl:variable name="gone" as="map(xs:string, map(*))" select="fp:gone($absent)"/>
  <xsl:function name="fp:gone" as="map(xs:string, map(*))">
    <xsl:param name="absent" as="map(*)*"/>
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
  </xsl:function>
  <xsl:key name="fp:id-any" match="*[@id]" use="@id"/>

  <!-- the actions of the features every selection selects, by the id of the element they act on -->
  <xsl:variable name="acting" as="element()*"
      select="$res/r:resolution/r:feature[every $s in $selections satisfies @name = $s?selected]/*"/>
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
    <!-- the files the jobs name first: nothing else can be read without them (variability/jobs.xsl) -->
    <xsl:sequence select="f:fail-all(fp:job-file-errors())"/>
    <xsl:sequence select="f:fail-all((f:model-errors($fm), $selections ! f:configuration-errors($fm, ?cfg),
                                      fp:resolution-errors(), fp:job-errors()))"/>
    <xsl:call-template name="fp:report"/>
    <xsl:call-template name="fp:job-report"/>
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
      <xsl:message select="'VAR030: ' || fp:kind(?element) || ' ''' || ?element/@name || ''' removed in '
          || $config-label || ': its presence condition (' || ?why || ') [xmi:id=' || ?element/@id || ']'"/>
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
          <xsl:sequence select="f:warn('VAR032', string($c/@id), 'connector ''' || $c/@name || ''' is removed in '
              || $config-label || ' (' || $gone(string($c/@id))?why || '), which leaves port '''
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
    <!-- per selection (each job's configuration in job mode), each clash once -->
    <xsl:variable name="clashes" as="map(*)*">
      <xsl:for-each select="$selections">
        <xsl:variable name="selected" as="xs:string*" select="?selected"/>
        <xsl:for-each-group select="$res/r:resolution/r:feature[@name = $selected]/*"
            group-by="local-name() || '|' || string(@part) || '|' || string((@component, @attribute, @connector, @element)[1])">
          <xsl:if test="count(current-group()) gt 1">
            <xsl:sequence select="map { 'code': 'VAR024', 'id': f:where(current-group()[2]), 'message':
                'features ' || string-join(current-group()/../@name, ' and ') || ' both ' || local-name() || ' '''
                || (@component, @attribute, @connector, @element)[1] || ''' in this configuration' }"/>
          </xsl:if>
        </xsl:for-each-group>
      </xsl:for-each>
    </xsl:variable>
    <xsl:for-each-group select="$clashes" group-by="?id">
      <xsl:sequence select="current-group()[1]"/>
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
