<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/orocos/jobs.xsl - the job coordinators of the Orocos PSM (seed 004 §4.3, docs/jobs.md).
  Reads:   pim:bound-subsystem and pim:bound-job of the bound PIM
           (xslt/m2m/bind/jobs.xsl) and the o:instance elements psm.xsl made.
  Writes:  o:coordinator (schemas/psm-orocos/1/psm-orocos.xsd): one per
           subsystem with an Orocos instance, in the process of the first
           Orocos member of its initial job: its jobs (the members of that
           process), and per transition the instances to stop, reconfigure
           (with the values, as the deployment writes them), start and keep.
           fp:oro-idle says which instances the deployment configures but
           does not start (in a job, not in the initial one).
  Params:  none.  Included by psm.xsl (fp:oro-values, fp:oro-required-type).
  Warnings: JOB031 a member of a subsystem's jobs in another Orocos process
           than its coordinator: the coordinator cannot reach it (peers are
           local), it is neither stopped nor started by the switch.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:o="urn:robomda:psm-orocos:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:key name="fp:oro-bound-job" match="pim:bound-job" use="@name"/>
  <!-- the jobs an instance is a member of, and a binding's subsystems: looked
       up per instance, where a scan of the binding's children (every
       instance, connection and call of the model) made the PSM quadratic
       (issue 35: 1.1 of 8.9 s at 10,000 nested components, Saxon-HE -TP) -->
  <xsl:key name="fp:oro-member-job" match="pim:binding/pim:bound-job" use="pim:member/@instance"/>
  <xsl:key name="fp:oro-subsystem" match="pim:binding/pim:bound-subsystem" use="'subsystem'"/>

  <!-- true when $instance is in a job of a subsystem but not in its
       initial job: deployed and configured, started by a switch only -->
  <xsl:function name="fp:oro-idle" as="xs:boolean">
    <xsl:param name="instance" as="element(pim:instance)"/>
    <xsl:variable name="binding" as="element(pim:binding)" select="$instance/.."/>
    <xsl:variable name="jobs" as="element(pim:bound-job)*"
        select="key('fp:oro-member-job', $instance/@name, $binding)"/>
    <!-- an instance in no job (most of them) is not idle: the subsystems'
         transitions and initial jobs are looked up only for the others -->
    <xsl:sequence select="exists($jobs) and (some $s in key('fp:oro-subsystem', 'subsystem', $binding) satisfies
        (exists(key('fp:oro-bound-job', $s/pim:transition/(@from, @to), root($binding)) intersect $jobs)
         and not($instance/@name = key('fp:oro-bound-job', $s/@initial-job, root($binding))/pim:member/@instance)))"/>
  </xsl:function>

  <xsl:function name="fp:oro-coordinators" as="element(o:coordinator)*">
    <xsl:param name="binding" as="element(pim:binding)"/>
    <xsl:param name="instances" as="element(o:instance)*"/>
    <xsl:param name="deploy-name" as="xs:string"/>
    <xsl:variable name="root" as="document-node()" select="root($binding)"/>
    <xsl:for-each select="$binding/pim:bound-subsystem">
      <xsl:variable name="subsystem" as="element(pim:bound-subsystem)" select="."/>
      <xsl:variable name="jobs" as="element(pim:bound-job)*"
          select="key('fp:oro-bound-job', distinct-values((@initial-job, pim:transition/(@from, @to))), $root)"/>
      <xsl:variable name="members" as="element(o:instance)*" select="$instances[@name = $jobs/pim:member/@instance]"/>
      <xsl:variable name="first" as="element(o:instance)?"
          select="($members[@name = key('fp:oro-bound-job', $subsystem/@initial-job, $root)/pim:member/@instance], $members)[1]"/>
      <xsl:if test="exists($first)">
        <xsl:variable name="local" as="xs:string*" select="$members[@process eq $first/@process]/@name"/>
        <xsl:for-each select="$members[@process ne $first/@process]">
          <xsl:sequence select="f:warn('JOB031', string(@xmi-id), 'instance ''' || @name || ''' of the jobs of subsystem '''
              || $subsystem/@name || ''' runs in process ''' || @process || ''', its coordinator in ''' || $first/@process
              || ''': the coordinator reaches the components of its own process only, so no switch stops or starts it')"/>
        </xsl:for-each>
        <o:coordinator name="{@name}" xmi-id="{@xmi-id}" process="{$first/@process}" initial-job="{@initial-job}"
            script="{$deploy-name}_{@name}.lua">
          <xsl:for-each select="$jobs">
            <o:job name="{@name}" xmi-id="{@xmi-id}">
              <xsl:for-each select="pim:member[@instance = $local]">
                <o:member instance="{@instance}"/>
              </xsl:for-each>
            </o:job>
          </xsl:for-each>
          <xsl:for-each select="pim:transition">
            <o:transition xmi-id="{@xmi-id}" from="{@from}" to="{@to}" event="{@event}">
              <xsl:for-each select="(pim:stop, pim:reconfigure, pim:start, pim:keep)[@instance = $local]">
                <xsl:element name="o:{local-name()}">
                  <xsl:attribute name="instance" select="@instance"/>
                  <xsl:for-each select="pim:set">
                    <xsl:variable name="values" as="xs:string+"
                        select="fp:oro-values(@value, fp:oro-required-type(key('fp:id', @attribute, $root), @attribute,
                                'property ''' || @name || ''''), (@holder, @attribute)[1])"/>
                    <o:set name="{@name}" value="{$values[1]}" script-value="{$values[2]}"/>
                  </xsl:for-each>
                </xsl:element>
              </xsl:for-each>
            </o:transition>
          </xsl:for-each>
        </o:coordinator>
      </xsl:if>
    </xsl:for-each>
  </xsl:function>
</xsl:stylesheet>
