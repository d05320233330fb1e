<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/openrtm/jobs.xsl - the job coordinators of the OpenRTM PSM (seed
  004 §4.3, docs/jobs.md "On OpenRTM").

  Reads:   pim:bound-subsystem and pim:bound-job of the bound PIM
           (xslt/m2m/bind/jobs.xsl), the package's pim:instances and the
           r:component elements psm.xsl made (their r:parameter, by
           attribute id).
  Writes:  r:coordinator (schemas/psm-openrtm/1/psm-openrtm.xsd): one per
           subsystem with a member in the package: an RT-Component
           <Subsystem>Coordinator, instance named after the subsystem, in
           the manager of the first member (in start order) of its initial
           job; its jobs (the members in the package, in start order) and
           per transition the instances to stop, reconfigure (with the
           values), start (with the values) and keep; a value in the text
           form of a configuration parameter (fp:rtm-value).
           fp:rtm-job-idle says which instances the managers create but do
           not activate (in a job, not in the initial one).
  Params:  none.  Included by psm.xsl (fp:rtm-value, key fp:type, $fp:types).
  Warnings:
    JOB041  a member of a subsystem's jobs that is not in the OpenRTM
            package (deployed on another middleware): the coordinator does
            not switch it
    JOB042  a value a job sets on an attribute that is no configuration
            parameter of the RT-Component: no switch sets it
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:r="urn:robomda:psm-openrtm:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:key name="fp:rtm-bound-job" match="pim:bound-job" use="@name"/>
  <!-- the subsystems whose jobs an instance is in -->
  <xsl:key name="fp:rtm-subsystem-of" match="pim:bound-subsystem"
      use="key('fp:rtm-bound-job', distinct-values((@initial-job, pim:transition/(@from, @to))))/pim:member/@instance"/>

  <!-- true when $instance is in a job of a subsystem but not in its initial
       job: its manager creates it, a switch activates it -->
  <xsl:function name="fp:rtm-job-idle" as="xs:boolean">
    <xsl:param name="instance" as="element(pim:instance)"/>
    <xsl:variable name="subsystem" as="element(pim:bound-subsystem)?"
        select="key('fp:rtm-subsystem-of', string($instance/@name), root($instance))[1]"/>
    <xsl:sequence select="exists($subsystem) and not($instance/@name
        = key('fp:rtm-bound-job', string($subsystem/@initial-job), root($instance))/pim:member/@instance)"/>
  </xsl:function>

  <xsl:function name="fp:rtm-coordinators" as="element(r:coordinator)*">
    <xsl:param name="binding" as="element(pim:binding)"/>
    <xsl:param name="ordered" as="element(pim:instance)*"/>
    <xsl:param name="rtcs" as="document-node()"/>
    <xsl:param name="files" as="map(xs:string, xs:string)"/>
    <xsl:variable name="root" as="document-node()" select="root($binding)"/>
    <xsl:variable name="here" as="map(xs:string, element(pim:instance))"
        select="map:merge($ordered ! map:entry(string(@name), .), map { 'duplicates': 'use-first' })"/>
    <xsl:for-each select="$binding/pim:bound-subsystem">
      <xsl:variable name="subsystem" as="element(pim:bound-subsystem)" select="."/>
      <xsl:variable name="jobs" as="element(pim:bound-job)*"
          select="key('fp:rtm-bound-job', distinct-values((@initial-job, pim:transition/(@from, @to))), $root)"/>
      <xsl:variable name="names" as="xs:string*" select="distinct-values($jobs/pim:member/@instance)"/>
      <xsl:variable name="members" as="element(pim:instance)*" select="$ordered[@name = $names]"/>
      <xsl:variable name="first" as="element(pim:instance)?"
          select="($members[@name = key('fp:rtm-bound-job', string($subsystem/@initial-job), $root)/pim:member/@instance], $members)[1]"/>
      <xsl:if test="exists($first)">
        <xsl:for-each select="$names[not(map:contains($here, .))]">
          <xsl:sequence select="f:warn('JOB041', string(($jobs/pim:member[@instance eq current()])[1]/@xmi-id),
              'instance ''' || . || ''' of the jobs of subsystem ''' || $subsystem/@name || ''' is not in the OpenRTM'
              || ' package (deployed on another middleware): the OpenRTM coordinator does not switch it; its own target does')"/>
        </xsl:for-each>
        <r:coordinator name="{@name}" xmi-id="{@xmi-id}" class="{f:upper-camel(@name)}Coordinator"
                       process="{map:get($files, string($first/@execution-environment))}" initial-job="{@initial-job}">
          <xsl:for-each select="$jobs">
            <r:job name="{@name}" xmi-id="{@xmi-id}">
              <xsl:for-each select="$members[@name = current()/pim:member/@instance]">
                <r:member instance="{@name}"/>
              </xsl:for-each>
            </r:job>
          </xsl:for-each>
          <xsl:for-each select="pim:transition">
            <r:transition xmi-id="{@xmi-id}" from="{@from}" to="{@to}" event="{@event}">
              <xsl:sequence select="(pim:stop, pim:reconfigure, pim:start, pim:keep)[map:contains($here, string(@instance))]
                                    ! fp:rtm-switched(., $here(string(@instance)), $rtcs)"/>
            </r:transition>
          </xsl:for-each>
        </r:coordinator>
      </xsl:if>
    </xsl:for-each>
  </xsl:function>

  <!-- what a switch does to one instance (r:stop, r:reconfigure, r:start,
       r:keep, as the bound transition says), with the values it sets -->
  <xsl:function name="fp:rtm-switched" as="element()">
    <xsl:param name="switched" as="element()"/>
    <xsl:param name="instance" as="element(pim:instance)"/>
    <xsl:param name="rtcs" as="document-node()"/>
    <xsl:element name="r:{local-name($switched)}">
      <xsl:attribute name="instance" select="$instance/@name"/>
      <xsl:sequence select="$switched/pim:set ! fp:rtm-job-set(., $instance, $rtcs)"/>
    </xsl:element>
  </xsl:function>

  <!-- a value a switch sets: the configuration parameter of its attribute,
       in the text form of a .conf; JOB042 when the attribute is none -->
  <xsl:function name="fp:rtm-job-set" as="element(r:value)?">
    <xsl:param name="set" as="element(pim:set)"/>
    <xsl:param name="instance" as="element(pim:instance)"/>
    <xsl:param name="rtcs" as="document-node()"/>
    <xsl:variable name="parameter" as="element(r:parameter)?"
        select="key('fp:rtc', string($instance/@component), $rtcs)/r:parameter[@xmi-id eq $set/@attribute]"/>
    <xsl:choose>
      <xsl:when test="empty($parameter)">
        <xsl:sequence select="f:warn('JOB042', string(($set/@holder, $set/../@xmi-id, $set/@attribute)[1]), 'value '''
            || $set/@value || ''' of ''' || $set/@name || ''' of instance ''' || $instance/@name || ''' (a job of transition '''
            || $set/../../@event || '''): ''' || $set/@name || ''' is no configuration parameter of the RT-Component, no switch sets it')"/>
      </xsl:when>
      <xsl:otherwise>
        <r:value name="{$parameter/@name}"
                 value="{fp:rtm-value($set/@value, key('fp:type', string($parameter/@primitive), $fp:types), string(($set/@holder, $set/@attribute)[1]))}"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>
</xsl:stylesheet>
