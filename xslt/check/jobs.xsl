<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/check/jobs.xsl - every job a configuration of its own, and what each
  switch does (seed 004 §4.3, docs/jobs.md).
  Reads:   a bound PIM, urn:robomda:pim:1 (schemas/pim/1, xslt/m2m/bind.xsl),
           with pim:bound-job and pim:bound-subsystem (bind/jobs.xsl).
  Writes:  the same PIM, unchanged (the check pipeline's last model); the
           report of every transition as info messages (JOB020).
  Params:  none (the replace of substitute.xsl, imported, is not used here).
  Imports: substitute.xsl (fp:check-swap: the substitutability rule of
           xslt/check/substitution.xsl on a pair of components).
  What is checked, per job (the model's own rules ran on the whole system:
  what differs in a job is which instances run):
    JOB010  an input data port of a member instance that no writer of the
            job feeds (a writer is a member of the job, or an instance in
            no job, which always runs); located on the job's slot
    JOB011  two writers of the job feed one input port (the instance reads
            one of them at random)
  and, per transition, a swap: an instance the switch stops and one it
  starts that feed the same input port (the one takes the other's role,
  seed 004's trackball and ctraj) must pass the substitutability rule
  (SUB001-SUB004, SUB007, SUB008, named "job switch FROM -> TO on EVENT"):
  not SUB005 / SUB006, since the job switched to sets the values of its
  own members, the stopped one's properties need not carry over.
  Info: JOB020 per transition, the instances it stops, reconfigures (with
  the values set), starts and keeps.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">
  <xsl:import href="substitute.xsl"/>
  <xsl:output method="xml" indent="no" encoding="UTF-8"/>

  <xsl:key name="fp:jc-instance" match="pim:binding/pim:instance" use="@name"/>
  <xsl:key name="fp:jc-reader" match="pim:binding/pim:connection" use="pim:reader/(@instance || '.' || @data-port)"/>
  <xsl:key name="fp:jc-job" match="pim:binding/pim:bound-job" use="@name"/>
  <xsl:key name="fp:jc-in-job" match="pim:bound-job/pim:member" use="@instance"/>

  <xsl:template match="/" as="document-node()">
    <xsl:variable name="binding" as="element(pim:binding)?" select="pim:model/pim:binding"/>
    <xsl:sequence select="f:fail-all($binding/pim:bound-job ! fp:configuration-problems(., $binding))"/>
    <xsl:sequence select="f:fail-all($binding/pim:bound-subsystem/pim:transition ! fp:swap-problems(., $binding))"/>
    <xsl:for-each select="$binding/pim:bound-subsystem/pim:transition">
      <xsl:message select="'JOB020: ' || fp:transition-report(.) || ' [xmi:id=' || @xmi-id || ']'"/>
    </xsl:for-each>
    <xsl:sequence select="."/>
  </xsl:template>

  <!-- the writers of an input port of $instance that run in $job -->
  <xsl:function name="fp:job-writers" as="xs:string*">
    <xsl:param name="job" as="element(pim:bound-job)"/>
    <xsl:param name="instance" as="xs:string"/>
    <xsl:param name="port" as="xs:string"/>
    <xsl:sequence select="distinct-values(key('fp:jc-reader', $instance || '.' || $port, root($job))/pim:writer/@instance
                          [. = $job/pim:member/@instance or empty(key('fp:jc-in-job', ., root($job)))])"/>
  </xsl:function>

  <xsl:function name="fp:configuration-problems" as="map(*)*">
    <xsl:param name="job" as="element(pim:bound-job)"/>
    <xsl:param name="binding" as="element(pim:binding)"/>
    <xsl:for-each select="$job/pim:member">
      <xsl:variable name="member" as="element(pim:member)" select="."/>
      <xsl:variable name="instance" as="element(pim:instance)?" select="key('fp:jc-instance', @instance, root($binding))"/>
      <xsl:for-each select="key('fp:bc', $instance/@component, root($binding))/pim:data-port[@direction eq 'in']">
        <xsl:variable name="writers" as="xs:string*" select="fp:job-writers($job, $member/@instance, @name)"/>
        <xsl:choose>
          <xsl:when test="empty($writers)">
            <xsl:sequence select="map { 'code': 'JOB010', 'id': string($member/@xmi-id), 'message': 'job ''' || $job/@name
                || ''': input port ''' || @name || ''' of instance ''' || $member/@instance || ''' is fed by no instance of the job'
                || (let $all := distinct-values(key('fp:jc-reader', $member/@instance || '.' || @name, root($binding))/pim:writer/@instance)
                    return if (exists($all)) then ' (only by ''' || string-join($all, ''', ''') || ''', not in it)' else '') }"/>
          </xsl:when>
          <xsl:when test="count($writers) gt 1">
            <xsl:sequence select="map { 'code': 'JOB011', 'id': string($member/@xmi-id), 'message': 'job ''' || $job/@name
                || ''': input port ''' || @name || ''' of instance ''' || $member/@instance || ''' is fed by '''
                || string-join($writers, ''' and ''') || ''' at once' }"/>
          </xsl:when>
        </xsl:choose>
      </xsl:for-each>
    </xsl:for-each>
  </xsl:function>

  <!-- the substitutability of each instance a transition starts in place
       of one it stops (both feed one input port) -->
  <xsl:function name="fp:swap-problems" as="map(*)*">
    <xsl:param name="transition" as="element(pim:transition)"/>
    <xsl:param name="binding" as="element(pim:binding)"/>
    <xsl:variable name="root" as="document-node()" select="root($binding)"/>
    <xsl:for-each select="$transition/pim:stop">
      <xsl:variable name="old" as="element(pim:instance)" select="key('fp:jc-instance', @instance, $root)"/>
      <xsl:for-each select="$transition/pim:start[fp:fed-ports($binding, @instance) = fp:fed-ports($binding, $old/@name)]">
        <xsl:variable name="new" as="element(pim:instance)" select="key('fp:jc-instance', @instance, $root)"/>
        <xsl:if test="$old/@component ne $new/@component">
          <xsl:sequence select="fp:check-swap(map { 'old': key('fp:id', $old/@component, $root), 'new': key('fp:id', $new/@component, $root),
              'why': 'job switch ' || $transition/@from || ' -> ' || $transition/@to || ' on ''' || $transition/@event
                     || ''', instance ''' || $new/@name || ''' in place of ''' || $old/@name || '''' }, $binding)
              [not(?code = ('SUB005', 'SUB006'))]"/>
        </xsl:if>
      </xsl:for-each>
    </xsl:for-each>
  </xsl:function>

  <!-- the input ports ("instance.port") instance $name writes to -->
  <xsl:key name="fp:jc-writer" match="pim:binding/pim:connection" use="pim:writer/@instance"/>
  <xsl:function name="fp:fed-ports" as="xs:string*">
    <xsl:param name="binding" as="element(pim:binding)"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:sequence select="key('fp:jc-writer', $name, root($binding))/pim:reader/(@instance || '.' || @data-port)"/>
  </xsl:function>

  <!-- "subsystem S, FROM -> TO on EVENT: stops a; reconfigures b (x = 1); starts c (y = 2); keeps d" -->
  <xsl:function name="fp:transition-report" as="xs:string">
    <xsl:param name="transition" as="element(pim:transition)"/>
    <xsl:variable name="parts" as="xs:string*" select="
        ('stop', 'reconfigure', 'start', 'keep') ! (let $kind := . return
          let $steps := $transition/*[local-name() eq $kind] return
          if (empty($steps)) then () else
            (if ($kind eq 'stop') then 'stops ' else if ($kind eq 'keep') then 'keeps ' else $kind || 's ')
            || string-join($steps ! (@instance || (if (pim:set) then ' (' || string-join(pim:set ! (@name || ' = ' || @value), ', ') || ')' else '')), ', '))"/>
    <xsl:sequence select="'subsystem ''' || $transition/../@name || ''', ' || $transition/@from || ' -> ' || $transition/@to
        || ' on ''' || $transition/@event || ''': ' || (if (empty($parts)) then 'changes nothing' else string-join($parts, '; '))"/>
  </xsl:function>
</xsl:stylesheet>
