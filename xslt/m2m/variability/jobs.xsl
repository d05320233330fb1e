<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/variability/jobs.xsl - jobs given as configurations of a product
  line (seed 004's saved configurations as seed 002's variants; docs/jobs.md,
  "Jobs given as configurations"; docs/variability.md, "Variants as jobs").

  Reads:   the PIM configure.xsl reads (pim:job whose «Job» stereotype has the
           tag configuration: a FeatureIDE configuration's path relative to
           the model's folder), the configuration files, and the feature model
           and resolution model beside them; through the global variables of
           configure.xsl, which includes this module and only it: $pim,
           $features, $config-jobs, $job-mode, $job-files, $selections, $res,
           $gone, and its keys fp:qn, fp:id-any.
  Writes:  in mode mp:configure, each job given as a configuration with its
           members: a pim:member per part of the job's composite that the
           job's configuration keeps (the slot of the «Job» for it when there
           is one, else @at = the job), each with a pim:value per value the
           job's own features set (the features not every job selects: a `set`
           with part on that part, a `set` of an attribute the part's realizing
           class owns), after the slot's own values, which win.
  Params:  none (configure.xsl's model-uri, passed to fp:job-files).
  Public:  fp:job-configuration, fp:job-files, fp:job-file-errors,
           fp:job-errors, template fp:job-report (all for configure.xsl).
  Errors:  JOB100-JOB107, raised by configure.xsl (its header says each);
           JOB104 located at the action in the resolution file, the others on
           the «Job» or its slot.
  Info / warnings: JOB111, JOB110, JOB112 (configure.xsl's header).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:r="urn:robomda:resolution:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:mp="urn:robomda:xslt:mode:private"
    exclude-result-prefixes="#all">

  <!-- the configuration a «Job» names (its tag configuration), if any -->
  <xsl:function name="fp:job-configuration" as="xs:string?">
    <xsl:param name="job" as="element(pim:job)"/>
    <xsl:sequence select="($job/pim:stereotype[@name eq 'Job']/pim:tag[@name eq 'configuration']/@value[normalize-space()])[1]
                          ! normalize-space()"/>
  </xsl:function>

  <!-- the files of job $job: map { job, rel (as the tag says), cfg (its URI, "" when it cannot be
       one), inside (in the model's folder or below), fm, res (the feature model's and resolution
       model's URIs, when they exist) } -->
  <xsl:function name="fp:job-files" as="map(*)">
    <xsl:param name="job" as="element(pim:job)"/>
    <xsl:param name="model-uri" as="xs:string"/>
    <xsl:variable name="rel" as="xs:string" select="fp:job-configuration($job)"/>
    <xsl:variable name="folder" as="xs:string" select="replace($model-uri, '/[^/]*$', '/')"/>
    <xsl:variable name="cfg" as="xs:string">
      <xsl:try select="if ($model-uri eq '') then '' else string(resolve-uri(iri-to-uri(translate($rel, '\', '/')), $model-uri))">
        <xsl:catch select="''"/>
      </xsl:try>
    </xsl:variable>
    <!-- compared as paths: Saxon writes file:/x where the driver wrote file:///x -->
    <xsl:variable name="inside" as="xs:boolean" select="$cfg ne '' and starts-with(fp:path($cfg), fp:path($folder))"/>
    <xsl:variable name="fm" as="xs:string?"
        select="if ($inside and doc-available($cfg))
                then ((resolve-uri('model.xml', $cfg), resolve-uri('../model.xml', $cfg)) ! string())
                     [starts-with(fp:path(.), fp:path($folder))][doc-available(.)][1]
                else ()"/>
    <xsl:sequence select="map { 'job': $job, 'rel': $rel, 'cfg': $cfg, 'inside': $inside, 'fm': $fm,
                                'res': $fm ! string(resolve-uri('resolution.xml', .))[doc-available(.)] }"/>
  </xsl:function>

  <!-- a file URI as a path (file:/x, file:///x: /x), to compare -->
  <xsl:function name="fp:path" as="xs:string">
    <xsl:param name="uri" as="xs:string"/>
    <xsl:sequence select="replace($uri, '^file:/*', '/')"/>
  </xsl:function>

  <!-- JOB100-JOB103, JOB106, JOB107: what keeps the jobs' configurations from being read -->
  <xsl:function name="fp:job-file-errors" as="map(*)*">
    <xsl:if test="$features ne '' and exists($config-jobs)">
      <xsl:sequence select="map { 'code': 'JOB106', 'id': string($config-jobs[1]/@id), 'message': 'job '''
          || $config-jobs[1]/@name || ''' is a configuration of the product line (tag configuration): the jobs configure'
          || ' the template model, a configuration given with --features would configure it once more; generate without --features' }"/>
    </xsl:if>
    <xsl:for-each select="$job-files">
      <xsl:variable name="id" as="xs:string" select="string(?job/@id)"/>
      <xsl:variable name="says" as="xs:string" select="'job ''' || ?job/@name || ''' names configuration ''' || ?rel || ''''"/>
      <xsl:variable name="composite" as="element()?" select="key('fp:id-any', string(?job/@classifier), $pim)[1]"/>
      <xsl:choose>
        <xsl:when test="not(?inside)">
          <xsl:sequence select="map { 'code': 'JOB100', 'id': $id, 'message': $says || ', which is no file in the model''s folder or below it'
              || (if ($model-uri eq '') then ' (the model''s location is not known: run the chain through robomda)' else '') }"/>
        </xsl:when>
        <xsl:when test="not(doc-available(?cfg))">
          <xsl:sequence select="map { 'code': 'JOB100', 'id': $id, 'message': $says || ': '
              || (if (unparsed-text-available(?cfg)) then 'not well-formed XML' else 'no such file') || ' ('
              || replace(?cfg, '^file:(//)?', '') || ')' }"/>
        </xsl:when>
        <xsl:when test="empty(doc(?cfg)/configuration)">
          <xsl:sequence select="map { 'code': 'JOB103', 'id': $id, 'message': $says || ', which is no FeatureIDE configuration (its root is '''
              || name(doc(?cfg)/*) || ''', not ''configuration'')' }"/>
        </xsl:when>
        <xsl:when test="empty(?fm)">
          <xsl:sequence select="map { 'code': 'JOB101', 'id': $id, 'message': $says
              || ': no feature model (model.xml) in its folder or the folder above it' }"/>
        </xsl:when>
        <xsl:when test="empty(doc(?fm)/featureModel)">
          <xsl:sequence select="map { 'code': 'JOB103', 'id': $id, 'message': $says || ': its feature model '
              || replace(?fm, '^file:(//)?', '') || ' is no FeatureIDE feature model (its root is ''' || name(doc(?fm)/*) || ''')' }"/>
        </xsl:when>
        <xsl:when test="empty(?res)">
          <xsl:sequence select="map { 'code': 'JOB101', 'id': $id, 'message': $says || ': no resolution model (resolution.xml) beside its feature model '
              || replace(?fm, '^file:(//)?', '') }"/>
        </xsl:when>
        <xsl:when test="empty(doc(?res)/r:resolution)">
          <xsl:sequence select="map { 'code': 'JOB103', 'id': $id, 'message': $says || ': its resolution model '
              || replace(?res, '^file:(//)?', '') || ' is no robomda resolution model (its root is ''' || name(doc(?res)/*) || ''')' }"/>
        </xsl:when>
        <xsl:when test="empty($composite/self::pim:component[pim:part])">
          <xsl:sequence select="map { 'code': 'JOB107', 'id': $id, 'message': 'job ''' || ?job/@name
              || ''' is a configuration, so its members are the parts of its classifier that the configuration keeps: '
              || (if ($composite) then local-name($composite) || ' ''' || $composite/@name || ''' has no parts'
                  else 'it has no classifier') || '; classify it by the composite whose parts are the instances' }"/>
        </xsl:when>
      </xsl:choose>
    </xsl:for-each>
    <xsl:variable name="models" as="xs:string*" select="distinct-values($job-files?fm)"/>
    <xsl:if test="count($models) gt 1">
      <xsl:variable name="other" as="map(*)" select="$job-files[?fm = $models[2]][1]"/>
      <xsl:sequence select="map { 'code': 'JOB102', 'id': string($other?job/@id), 'message': 'job ''' || $other?job/@name
          || ''' is a configuration of feature model ' || replace($models[2], '^file:(//)?', '') || ', job '''
          || $job-files[1]?job/@name || ''' one of ' || replace($models[1], '^file:(//)?', '')
          || ': the jobs of a model configure one template, the variants of one product line' }"/>
    </xsl:if>
  </xsl:function>

  <!-- job id -> map { selection, gone (what its configuration removes), actions (those of its features
       that not every job selects: its own) } -->
  <xsl:variable name="job-plans" as="map(xs:string, map(*))" select="map:merge(
      for $s in $selections[exists(?job)] return map:entry(string($s?job/@id), map {
        'selection': $s,
        'gone': fp:gone(fp:absent($s)),
        'actions': $res/r:resolution/r:feature[@name = $s?selected][some $t in $selections satisfies not(@name = $t?selected)]/* }))"/>

  <!-- the actions some selections select and others do not -->
  <xsl:function name="fp:partial-actions" as="element()*">
    <xsl:sequence select="$res/r:resolution/r:feature[some $s in $selections satisfies @name = $s?selected]
                          [some $s in $selections satisfies not(@name = $s?selected)]/*"/>
  </xsl:function>

  <!-- the names of the jobs whose configuration selects feature $name (or not: $selects false) -->
  <xsl:function name="fp:jobs-selecting" as="xs:string">
    <xsl:param name="name" as="xs:string"/>
    <xsl:param name="selects" as="xs:boolean"/>
    <xsl:sequence select="string-join($selections[($name = ?selected) eq $selects] ! ('''' || ?job/@name || ''''), ', ')"/>
  </xsl:function>

  <!-- the parts of job $job's composite that its configuration keeps -->
  <xsl:function name="fp:job-parts" as="element(pim:part)*">
    <xsl:param name="job" as="element(pim:job)"/>
    <xsl:variable name="plan" as="map(*)" select="$job-plans(string($job/@id))"/>
    <xsl:sequence select="key('fp:id-any', string($job/@classifier), $pim)[1]/self::pim:component/pim:part
                          [not(map:contains($plan?gone, string(@id)))]"/>
  </xsl:function>

  <!-- the values job plan $plan's own features set on $part: maps { attribute (id), value, action };
       a `set` naming the part wins over one of the attribute -->
  <xsl:function name="fp:config-values" as="map(*)*">
    <xsl:param name="plan" as="map(*)"/>
    <xsl:param name="part" as="element(pim:part)"/>
    <xsl:variable name="classes" as="xs:string*" select="key('fp:id-any', string($part/@type), $pim)[1]/pim:realization/@classifier ! string()"/>
    <xsl:variable name="found" as="map(*)*" select="
        ($plan?actions/self::r:set[empty(@part)] ! (let $a := key('fp:qn', string(@attribute), $pim)[1] return
           if (string($a/../@id) = $classes) then map { 'attribute': string($a/@id), 'value': string(@value), 'action': . } else ()),
         $plan?actions/self::r:set[@part][key('fp:qn', string(@part), $pim)[1] is $part]
           ! map { 'attribute': string(key('fp:qn', string(@attribute), $pim)[1]/@id), 'value': string(@value), 'action': . })"/>
    <xsl:for-each-group select="$found" group-by="?attribute">
      <xsl:sequence select="current-group()[last()]"/>
    </xsl:for-each-group>
  </xsl:function>

  <!-- JOB104, JOB105: what the jobs' configurations ask that one system cannot hold -->
  <xsl:function name="fp:job-errors" as="map(*)*">
    <xsl:if test="$job-mode">
      <xsl:for-each select="fp:partial-actions()[self::r:realize or self::r:policy or self::r:deploy]">
        <xsl:sequence select="map { 'code': 'JOB104', 'id': f:where(.), 'message': 'feature ''' || ../@name || ''' '
            || (if (self::r:realize) then 'swaps the realizing class of ''' || @component || ''''
                else if (self::r:policy) then 'sets the policy of connector ''' || @connector || ''''
                else 'deploys ''' || @element || ''' on ''' || @on || '''')
            || ' in the configurations of jobs ' || fp:jobs-selecting(../@name, true()) || ' and not in those of '
            || fp:jobs-selecting(../@name, false()) || ': the jobs a subsystem switches between share one system, with one realizing'
            || ' class per component, one policy per connection and one place per element; select the feature in every job or in'
            || ' none, or model the alternative as parts with presence conditions' }"/>
      </xsl:for-each>
      <xsl:for-each select="$pim/pim:model/pim:coordination/pim:job">
        <xsl:variable name="job" as="element(pim:job)" select="."/>
        <xsl:variable name="plan" as="map(*)?" select="$job-plans(string(@id))"/>
        <xsl:variable name="removed" as="map(*)" select="if (exists($plan)) then $plan?gone else $gone"/>
        <xsl:for-each select="pim:member[map:contains($removed, string(@part))]">
          <xsl:sequence select="map { 'code': 'JOB105', 'id': string(@id), 'message': 'job ''' || $job/@name || ''' lists part '''
              || key('fp:id-any', string(@part), $pim)[1]/@name || ''', which '
              || (if (exists($plan)) then 'its configuration ''' || $plan?selection?name || ''' removes ('
                  else 'no job''s configuration keeps (') || $removed(string(@part))?why || ')' }"/>
        </xsl:for-each>
      </xsl:for-each>
    </xsl:if>
  </xsl:function>

  <!-- JOB111 per job given as a configuration; JOB110, JOB112 -->
  <xsl:template name="fp:job-report" as="empty-sequence()">
    <xsl:if test="$job-mode">
      <xsl:for-each select="$config-jobs">
        <xsl:variable name="job" as="element(pim:job)" select="."/>
        <xsl:variable name="plan" as="map(*)" select="$job-plans(string(@id))"/>
        <xsl:variable name="values" as="xs:string*" select="fp:job-parts(.) ! (let $p := . return
            ($job/pim:member[@part eq $p/@id]/pim:value[@value] ! (@attribute || '=' || @value),
             fp:config-values($plan, $p)[not(?attribute = $job/pim:member[@part eq $p/@id]/pim:value/@attribute)]
               ! (?attribute || '=' || ?value))
            ! ($p/@name || '.' || key('fp:id-any', substring-before(., '='), $pim)[1]/@name || ' = ' || substring-after(., '=')))"/>
        <xsl:message select="'JOB111: job ''' || @name || ''' is configuration ''' || $plan?selection?name || ''' (features '
            || string-join($plan?selection?selected, ', ') || '): members ' || string-join(fp:job-parts(.)/@name, ', ')
            || (if (exists($values)) then '; sets ' || string-join($values, ', ') else '') || ' [xmi:id=' || @id || ']'"/>
      </xsl:for-each>
      <xsl:for-each select="$res/r:resolution/r:present">
        <xsl:variable name="present" as="element(r:present)" select="."/>
        <xsl:variable name="connector" as="element(pim:connector)?" select="key('fp:qn', string(@element), $pim)[1]/self::pim:connector"/>
        <xsl:for-each select="$config-jobs[exists($connector) and not(map:contains($gone, string($connector/@id)))]">
          <xsl:variable name="plan" as="map(*)" select="$job-plans(string(@id))"/>
          <xsl:variable name="parts" as="xs:string*" select="fp:job-parts(.)/@id ! string()"/>
          <xsl:if test="not(fp:holds-in($present, $plan?selection)) and exists($connector/pim:end/@part)
                        and (every $p in $connector/pim:end/@part satisfies $p = $parts)">
            <xsl:sequence select="f:warn('JOB110', string($connector/@id), 'connector ''' || $connector/@name || ''' is not in configuration '''
                || $plan?selection?name || ''' of job ''' || @name || ''' (' || fp:condition-text($present) || ') but in another job''s:'
                || ' the system keeps it, and since the job runs the parts at both its ends, it carries data in job ''' || @name || ''' too')"/>
          </xsl:if>
        </xsl:for-each>
      </xsl:for-each>
      <xsl:for-each select="fp:partial-actions()/self::r:set[empty(@part)]">
        <xsl:variable name="action" as="element(r:set)" select="."/>
        <xsl:for-each select="$config-jobs">
          <xsl:variable name="plan" as="map(*)" select="$job-plans(string(@id))"/>
          <xsl:if test="exists($plan?actions intersect $action)
                        and empty(fp:job-parts(.)[some $v in fp:config-values($plan, .) satisfies $v?action is $action])">
            <xsl:sequence select="f:warn('JOB112', f:where($action), 'feature ''' || $action/../@name || ''' sets '''
                || $action/@attribute || ''' in the configuration of job ''' || @name || ''', whose members realize no class that owns it:'
                || ' a feature not every job selects sets the values of the job''s members, so this one sets nothing')"/>
          </xsl:if>
        </xsl:for-each>
      </xsl:for-each>
    </xsl:if>
  </xsl:template>

  <!-- a job given as a configuration, with the members and values it gives -->
  <xsl:template match="pim:job[map:contains($job-plans, string(@id))]" mode="mp:configure" as="element(pim:job)">
    <xsl:variable name="job" as="element(pim:job)" select="."/>
    <xsl:variable name="plan" as="map(*)" select="$job-plans(string(@id))"/>
    <xsl:variable name="parts" as="element(pim:part)*" select="fp:job-parts(.)"/>
    <xsl:copy>
      <xsl:copy-of select="@*"/>
      <xsl:apply-templates select="* except pim:member" mode="mp:configure"/>
      <xsl:for-each select="$parts">
        <xsl:variable name="part" as="element(pim:part)" select="."/>
        <xsl:variable name="slot" as="element(pim:member)?" select="$job/pim:member[@part eq $part/@id][1]"/>
        <pim:member id="{($slot/@id, $job/@id || '.' || @id)[1]}" part="{@id}">
          <xsl:if test="empty($slot)">
            <xsl:attribute name="at" select="$job/@id"/>
          </xsl:if>
          <xsl:copy-of select="$slot/pim:value"/>
          <xsl:for-each select="fp:config-values($plan, .)[not(?attribute = $slot/pim:value/@attribute)]">
            <pim:value id="{$job/@id}.{$part/@id}.{?attribute}" at="{$job/@id}" attribute="{?attribute}" value="{?value}"/>
          </xsl:for-each>
        </pim:member>
      </xsl:for-each>
      <!-- slots that name no part the configuration keeps, as the model has them: bind checks what
           they name (JOB001); one its configuration removes was refused (JOB105) -->
      <xsl:copy-of select="pim:member[not(@part = $parts/@id)]"/>
    </xsl:copy>
  </xsl:template>
</xsl:stylesheet>
