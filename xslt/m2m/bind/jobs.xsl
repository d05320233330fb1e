<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/bind/jobs.xsl - jobs and subsystems resolved (seed 004 §4.3, docs/jobs.md).
  Reads:   pim:coordination of the PIM (xslt/import/jobs.xsl; for jobs given
           as configurations, as xslt/m2m/configure.xsl completed it: a
           member or value with @at is located there, at the job) and the
           instances of fp:binding (sequenced: with @start-order).
  Writes:  pim:bound-job and pim:bound-subsystem (schemas/pim/1/binding.xsd);
           the instances of the initial jobs with the job's values
           (pim:property-value source="job").
  Params:  none.  Keys: those of bind.xsl, fp:job-instance (below).
  Provides: fp:job-problems, fp:bound-jobs, fp:with-initial-values,
           fp:job-mates (which instances may run together: BND008).
  Errors (f:fail-all, every one of the model at once):
    JOB001  a job's slot names no component instance: not a part of a top
            composite that became an instance (a composite part, a part of
            another classifier, an attribute)
    JOB002  a job's value names an attribute that is not one of the member
            instance's realizing class (nor inherited)
    JOB003  a state of a subsystem names no job (no «Job» of that name)
    JOB004  a subsystem without exactly one initial job: no initial
            pseudostate leading to a job state, or several
    JOB005  a transition of a subsystem from or to a state that is no job
            (other than the one from the initial pseudostate)
    JOB006  two transitions leave one job on the same event
    JOB007  two jobs, or two subsystems, get the same name
    JOB008  a job names one instance twice (two slots for one part)
    JOB009  an instance in jobs of two subsystems: two coordinators would
            switch it
    JOB012  a subsystem named like a component instance (its coordinator
            is a component named after the subsystem)
  Warnings: JOB030 a job that no subsystem runs (only checked, never
  switched to).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:key name="fp:job-instance" match="pim:instance" use="@xmi-id"/>
  <xsl:key name="fp:job-by-name" match="pim:job" use="string(@name)"/>
  <xsl:key name="fp:state-by-id" match="pim:subsystem/pim:state" use="@id"/>

  <!-- the instance a job member names (a part that became one instance), if any -->
  <xsl:function name="fp:member-instance" as="element(pim:instance)?">
    <xsl:param name="member" as="element(pim:member)"/>
    <xsl:param name="instances" as="document-node()"/>
    <xsl:variable name="found" as="element(pim:instance)*" select="key('fp:job-instance', $member/@part, $instances)"/>
    <xsl:sequence select="if (count($found) eq 1) then $found else ()"/>
  </xsl:function>

  <!-- the job a state runs -->
  <xsl:function name="fp:state-job" as="element(pim:job)?">
    <xsl:param name="state" as="element(pim:state)?"/>
    <xsl:sequence select="if ($state/@kind eq 'state') then key('fp:job-by-name', string($state/@name), root($state))[1] else ()"/>
  </xsl:function>

  <!-- the initial transitions of a subsystem: from an initial pseudostate to a job -->
  <xsl:function name="fp:initial-transitions" as="element(pim:transition)*">
    <xsl:param name="subsystem" as="element(pim:subsystem)"/>
    <xsl:sequence select="$subsystem/pim:transition[key('fp:state-by-id', @source, root($subsystem))/@kind eq 'initial']"/>
  </xsl:function>

  <!-- every problem of the jobs and subsystems (JOB001-JOB009) -->
  <xsl:function name="fp:job-problems" as="map(*)*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:param name="instances" as="document-node()"/>
    <xsl:variable name="root" as="document-node()" select="root($model)"/>
    <xsl:for-each select="$model/pim:coordination/pim:job">
      <xsl:variable name="job" as="element(pim:job)" select="."/>
      <xsl:for-each select="pim:member">
        <xsl:variable name="instance" as="element(pim:instance)?" select="fp:member-instance(., $instances)"/>
        <xsl:choose>
          <xsl:when test="empty($instance)">
            <xsl:sequence select="map { 'code': 'JOB001', 'id': string((@at, @id)[1]), 'message': 'job ''' || $job/@name
                || ''': its slot names ''' || (key('fp:id', @part, $root)/@name, @part)[1]
                || ''', which is no component instance (a part of the composite whose parts are the instances; a composite part: name its parts)' }"/>
          </xsl:when>
          <xsl:otherwise>
            <xsl:variable name="class" as="element()?" select="key('fp:id', $instance/@realization, $root)"/>
            <xsl:variable name="known" as="xs:string*" select="if ($class) then fp:attributes($class)/@id else ()"/>
            <xsl:for-each select="pim:value[not(@attribute = $known)]">
              <xsl:sequence select="map { 'code': 'JOB002', 'id': string((@at, @id)[1]), 'message': 'job ''' || $job/@name
                  || ''' sets ''' || (key('fp:id', @attribute, $root)/@name, @attribute)[1] || ''' on instance '''
                  || $instance/@name || ''', whose realizing class ''' || ($class/@name, '?')[1] || ''' has no such attribute' }"/>
            </xsl:for-each>
          </xsl:otherwise>
        </xsl:choose>
      </xsl:for-each>
      <xsl:for-each-group select="pim:member" group-by="@part">
        <xsl:if test="count(current-group()) gt 1">
          <xsl:sequence select="map { 'code': 'JOB008', 'id': string(current-group()[2]/(@at, @id)[1]), 'message': 'job '''
              || $job/@name || ''' names part ''' || (key('fp:id', current-grouping-key(), $root)/@name)[1] || ''' twice' }"/>
        </xsl:if>
      </xsl:for-each-group>
    </xsl:for-each>
    <xsl:for-each select="$model/pim:coordination/pim:subsystem">
      <xsl:variable name="subsystem" as="element(pim:subsystem)" select="."/>
      <xsl:for-each select="pim:state[@kind eq 'state'][empty(fp:state-job(.))]">
        <xsl:sequence select="map { 'code': 'JOB003', 'id': string(@id), 'message': 'state ''' || @name
            || ''' of subsystem ''' || $subsystem/@name || ''' names no job (a «Job» InstanceSpecification of that name)' }"/>
      </xsl:for-each>
      <xsl:variable name="initial" as="element(pim:transition)*" select="fp:initial-transitions(.)"/>
      <xsl:if test="count($initial) ne 1">
        <xsl:sequence select="map { 'code': 'JOB004', 'id': string(($initial[2]/@id, @id)[1]), 'message': 'subsystem '''
            || @name || ''' has ' || (if (empty($initial)) then 'no initial job: draw an initial pseudostate and a transition from it to the job that runs first'
                                     else count($initial) || ' initial transitions: one job runs first') }"/>
      </xsl:if>
      <xsl:for-each select="pim:transition except $initial">
        <xsl:variable name="ends" as="element(pim:state)*" select="key('fp:state-by-id', (@source, @target), root(.))"/>
        <xsl:if test="some $end in $ends satisfies empty(fp:state-job($end))">
          <xsl:sequence select="map { 'code': 'JOB005', 'id': string(@id), 'message': 'transition '
              || string-join($ends ! (if (@name ne '') then '''' || @name || '''' else @kind), ' -> ')
              || ' of subsystem ''' || $subsystem/@name || ''' leaves or reaches a state that is no job: a coordinator switches between jobs only' }"/>
        </xsl:if>
      </xsl:for-each>
      <xsl:for-each-group select="pim:transition except $initial" group-by="@source || '|' || (@event, 'next')[1]">
        <xsl:if test="count(current-group()) gt 1">
          <xsl:sequence select="map { 'code': 'JOB006', 'id': string(current-group()[2]/@id), 'message': 'subsystem '''
              || $subsystem/@name || ''': two transitions leave job ''' || key('fp:state-by-id', @source, root(.))/@name
              || ''' on event ''' || (@event, 'next')[1] || '''' }"/>
        </xsl:if>
      </xsl:for-each-group>
    </xsl:for-each>
    <xsl:for-each-group select="$model/pim:coordination/(pim:job | pim:subsystem)" group-by="local-name() || '|' || f:cpp-identifier(@name)">
      <xsl:if test="count(current-group()) gt 1">
        <xsl:sequence select="map { 'code': 'JOB007', 'id': string(current-group()[2]/@id), 'message': 'two '
            || local-name() || 's are named ''' || f:cpp-identifier(@name) || '''' }"/>
      </xsl:if>
    </xsl:for-each-group>
    <!-- a coordinator is a component named after its subsystem -->
    <xsl:for-each select="$model/pim:coordination/pim:subsystem[f:cpp-identifier(@name) = $instances//pim:instance/@name]">
      <xsl:sequence select="map { 'code': 'JOB012', 'id': string(@id), 'message': 'subsystem ''' || @name
          || ''' has the name of a component instance: its coordinator is a component of that name; rename one of them' }"/>
    </xsl:for-each>
    <!-- an instance switched by two subsystems -->
    <xsl:for-each-group select="$model/pim:coordination/pim:subsystem ! (let $s := . return
                                  distinct-values(pim:state ! fp:state-job(.)/pim:member/@part) ! map { 'part': ., 's': $s })"
        group-by="?part">
      <xsl:if test="count(distinct-values(current-group() ! ?s/@id)) gt 1">
        <xsl:sequence select="map { 'code': 'JOB009', 'id': string(current-group()[2]?s/@id), 'message': 'part '''
            || key('fp:id', current-grouping-key(), $root)/@name || ''' is in jobs of subsystems '''
            || string-join(distinct-values(current-group() ! string(?s/@name)), ''', ''') || ''': only one may switch it' }"/>
      </xsl:if>
    </xsl:for-each-group>
  </xsl:function>

  <!-- the values job $job gives instance $instance: a map attribute id ->
       map { name, value, holder? } over every attribute any job of the
       model sets on the instance (the job's own value, else the
       instance's value, else the attribute's default) -->
  <xsl:function name="fp:job-values" as="map(*)*">
    <xsl:param name="job" as="element(pim:job)?"/>
    <xsl:param name="instance" as="element(pim:instance)"/>
    <xsl:param name="base" as="element(pim:instance)"/>
    <xsl:variable name="root" as="document-node()" select="root($instance)"/>
    <xsl:variable name="all" as="element(pim:value)*"
        select="$job/../pim:job/pim:member[@part eq $instance/@xmi-id]/pim:value[@value]"/>
    <xsl:variable name="own" as="element(pim:value)*" select="$job/pim:member[@part eq $instance/@xmi-id]/pim:value[@value]"/>
    <xsl:for-each select="distinct-values($all/@attribute)">
      <xsl:variable name="attribute" as="xs:string" select="."/>
      <xsl:variable name="set" as="element(pim:value)?" select="$own[@attribute eq $attribute][1]"/>
      <xsl:variable name="declared" as="element()?" select="key('fp:id', $attribute, $job/root())"/>
      <xsl:sequence select="map:merge((
          map { 'attribute': $attribute, 'name': string($declared/@name),
                'value': string(($set/@value, $base/pim:property-value[@attribute eq $attribute][not(@source eq 'job')]/@value,
                                 $declared/@default, '')[1]) },
          $set ! map { 'holder': string((@at, @id)[1]) }))"/>
    </xsl:for-each>
  </xsl:function>

  <xsl:function name="fp:sets" as="element(pim:set)*">
    <xsl:param name="values" as="map(*)*"/>
    <xsl:for-each select="$values">
      <pim:set attribute="{?attribute}" name="{?name}" value="{?value}">
        <xsl:if test="map:contains(., 'holder')"><xsl:attribute name="holder" select="?holder"/></xsl:if>
      </pim:set>
    </xsl:for-each>
  </xsl:function>

  <!-- the members of $job as instances, in start order -->
  <xsl:function name="fp:job-instances" as="element(pim:instance)*">
    <xsl:param name="job" as="element(pim:job)?"/>
    <xsl:param name="instances" as="document-node()"/>
    <xsl:for-each select="$job/pim:member ! fp:member-instance(., $instances)">
      <xsl:sort select="xs:integer((@start-order, 0)[1])"/>
      <xsl:sequence select="."/>
    </xsl:for-each>
  </xsl:function>

  <!-- pim:bound-job and pim:bound-subsystem of the model; $instances the
       sequenced instances (in a document of their own) -->
  <xsl:function name="fp:bound-jobs" as="element()*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:param name="instances" as="document-node()"/>
    <xsl:variable name="coordination" as="element(pim:coordination)?" select="$model/pim:coordination"/>
    <xsl:for-each select="$coordination/pim:job">
      <xsl:variable name="job" as="element(pim:job)" select="."/>
      <xsl:if test="empty($coordination/pim:subsystem/pim:state[fp:state-job(.) is $job])">
        <xsl:sequence select="f:warn('JOB030', string(@id), 'job ''' || @name || ''' is run by no subsystem: it is checked as a configuration, but no coordinator switches to it')"/>
      </xsl:if>
      <pim:bound-job name="{f:cpp-identifier(@name)}" xmi-id="{@id}">
        <xsl:for-each select="fp:job-instances(., $instances)">
          <pim:member instance="{@name}" xmi-id="{$job/pim:member[@part eq current()/@xmi-id][1]/(@at, @id)[1]}">
            <xsl:sequence select="fp:sets(fp:job-values($job, ., .))"/>
          </pim:member>
        </xsl:for-each>
      </pim:bound-job>
    </xsl:for-each>
    <xsl:for-each select="$coordination/pim:subsystem">
      <xsl:variable name="initial" as="element(pim:job)?"
          select="fp:initial-transitions(.)[1] ! fp:state-job(key('fp:state-by-id', @target, root(.)))"/>
      <pim:bound-subsystem name="{f:cpp-identifier(@name)}" xmi-id="{@id}" initial-job="{f:cpp-identifier($initial/@name)}">
        <xsl:for-each select="pim:transition except fp:initial-transitions(.)">
          <xsl:variable name="from" as="element(pim:job)" select="fp:state-job(key('fp:state-by-id', @source, root(.)))"/>
          <xsl:variable name="to" as="element(pim:job)" select="fp:state-job(key('fp:state-by-id', @target, root(.)))"/>
          <xsl:sequence select="fp:bound-transition(., $from, $to, $instances)"/>
        </xsl:for-each>
      </pim:bound-subsystem>
    </xsl:for-each>
  </xsl:function>

  <xsl:function name="fp:bound-transition" as="element(pim:transition)">
    <xsl:param name="transition" as="element(pim:transition)"/>
    <xsl:param name="from" as="element(pim:job)"/>
    <xsl:param name="to" as="element(pim:job)"/>
    <xsl:param name="instances" as="document-node()"/>
    <xsl:variable name="before" as="element(pim:instance)*" select="fp:job-instances($from, $instances)"/>
    <xsl:variable name="after" as="element(pim:instance)*" select="fp:job-instances($to, $instances)"/>
    <pim:transition xmi-id="{$transition/@id}" from="{f:cpp-identifier($from/@name)}" to="{f:cpp-identifier($to/@name)}"
        event="{($transition/@event, 'next')[1]}">
      <xsl:for-each select="reverse($before[not(@xmi-id = $after/@xmi-id)])">
        <pim:stop instance="{@name}"/>
      </xsl:for-each>
      <xsl:variable name="stay" as="element(pim:instance)*" select="$after[@xmi-id = $before/@xmi-id]"/>
      <xsl:for-each select="$stay">
        <xsl:variable name="old" as="map(*)*" select="fp:job-values($from, ., .)"/>
        <xsl:variable name="changed" as="map(*)*"
            select="fp:job-values($to, ., .)[let $n := . return not(some $o in $old satisfies ($o?attribute eq $n?attribute and $o?value eq $n?value))]"/>
        <xsl:if test="exists($changed)">
          <pim:reconfigure instance="{@name}"><xsl:sequence select="fp:sets($changed)"/></pim:reconfigure>
        </xsl:if>
      </xsl:for-each>
      <xsl:for-each select="$after[not(@xmi-id = $before/@xmi-id)]">
        <pim:start instance="{@name}"><xsl:sequence select="fp:sets(fp:job-values($to, ., .))"/></pim:start>
      </xsl:for-each>
      <xsl:for-each select="$stay">
        <xsl:variable name="old" as="map(*)*" select="fp:job-values($from, ., .)"/>
        <xsl:if test="every $n in fp:job-values($to, ., .) satisfies (some $o in $old satisfies ($o?attribute eq $n?attribute and $o?value eq $n?value))">
          <pim:keep instance="{@name}"/>
        </xsl:if>
      </xsl:for-each>
    </pim:transition>
  </xsl:function>

  <!-- $instances with the values of the initial job of each subsystem
       (pim:property-value source="job", in place of the instance's own) -->
  <xsl:function name="fp:with-initial-values" as="element(pim:instance)*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:variable name="initials" as="element(pim:job)*"
        select="$model/pim:coordination/pim:subsystem ! (fp:initial-transitions(.)[1] ! fp:state-job(key('fp:state-by-id', @target, root(.))))"/>
    <xsl:variable name="root" as="document-node()" select="root($model)"/>
    <xsl:for-each select="$instances">
      <xsl:variable name="values" as="element(pim:value)*"
          select="$initials/pim:member[@part eq current()/@xmi-id]/pim:value[@value]"/>
      <xsl:choose>
        <xsl:when test="empty($values)"><xsl:sequence select="."/></xsl:when>
        <xsl:otherwise>
          <xsl:copy>
            <xsl:sequence select="@*, pim:activity"/>
            <xsl:sequence select="pim:property-value[not(@attribute = $values/@attribute)]"/>
            <xsl:for-each select="$values">
              <pim:property-value attribute="{@attribute}" name="{key('fp:id', @attribute, $root)/@name}" value="{@value}"
                  source="job" holder="{(@at, @id)[1]}"/>
            </xsl:for-each>
            <xsl:sequence select="* except (pim:activity | pim:property-value)"/>
          </xsl:copy>
        </xsl:otherwise>
      </xsl:choose>
    </xsl:for-each>
  </xsl:function>

  <!-- the ids of the jobs each instance (by name: a part of a top composite) is in: which
       writers may run together (BND008: an input fed by writers that no
       job runs together is no conflict) -->
  <xsl:function name="fp:job-mates" as="map(xs:string, xs:string*)">
    <xsl:param name="root" as="document-node()"/>
    <xsl:variable name="members" as="element(pim:member)*" select="$root/pim:model/pim:coordination/pim:job/pim:member"/>
    <xsl:sequence select="map:merge(for $p in distinct-values($members/@part) return
                          map:entry(f:cpp-identifier(string(key('fp:id', $p, $root)/@name)), distinct-values($members[@part eq $p]/../@id) ! string(.)))"/>
  </xsl:function>
</xsl:stylesheet>
