<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/ros/jobs.xsl - the job coordinators of the ROS PSM (seed 004 §4.3,
  docs/jobs.md, docs/ros.md "Jobs").

  Reads:   pim:bound-subsystem and pim:bound-job of the bound PIM
           (xslt/m2m/bind/jobs.xsl), the package's pim:instances and the
           r:node elements psm.xsl made (their r:parameter, by attribute id).
  Writes:  r:coordinator (schemas/psm-ros/1/psm-ros.xsd): one per subsystem
           with a member in the package, on the host of the first member (in
           start order) of its initial job: its jobs (the members in the
           package) and per transition the instances to stop, reconfigure
           (with the values), start (with the values) and keep, each value a
           node parameter with its C++ and YAML literals (r:value).
           fp:ros-job-of says which subsystem's coordinator switches an
           instance; fp:ros-job-idle which ones the deployment does not run
           at first (in a job, not in the initial one).
  Params:  ros-version (psm.xsl).  Included by psm.xsl (fp:param-values,
           fp:required-type, key fp:node).
  Warnings:
    JOB050  ROS 1 has no node lifecycle: a node that leaves a job is shut
            down (its process ends), one that comes is started anew (a new
            process: configure() and start() run again, its state is new),
            one that stays gets its new values through its
            reload_parameters service (configure() does not run again)
    JOB051  a value a job sets on an attribute that is no parameter of the
            ROS node: no switch sets it
    JOB052  a member of a subsystem's jobs that is not in this package (an
            instance on another middleware): this coordinator does not
            switch it
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:include href="../../common/sequence.xsl"/>

  <xsl:key name="fp:ros-bound-job" match="pim:bound-job" use="@name"/>
  <!-- the subsystems whose jobs an instance is in -->
  <xsl:key name="fp:ros-subsystem-of" match="pim:bound-subsystem"
      use="key('fp:ros-bound-job', distinct-values((@initial-job, pim:transition/(@from, @to))))/pim:member/@instance"/>

  <!-- the name of the subsystem whose coordinator switches $instance, or ()
       (an instance in no job runs from start to end, as without jobs) -->
  <xsl:function name="fp:ros-job-of" as="xs:string?">
    <xsl:param name="instance" as="element(pim:instance)"/>
    <xsl:sequence select="key('fp:ros-subsystem-of', string($instance/@name), root($instance))[1]/@name"/>
  </xsl:function>

  <!-- true when $instance is in a job of a subsystem but not in its initial
       job: the deployment loads it (ROS 2: configured by the coordinator),
       a switch starts it -->
  <xsl:function name="fp:ros-job-idle" as="xs:boolean">
    <xsl:param name="instance" as="element(pim:instance)"/>
    <xsl:variable name="subsystem" as="element(pim:bound-subsystem)?"
        select="key('fp:ros-subsystem-of', string($instance/@name), root($instance))[1]"/>
    <xsl:sequence select="exists($subsystem) and not($instance/@name
        = key('fp:ros-bound-job', string($subsystem/@initial-job), root($instance))/pim:member/@instance)"/>
  </xsl:function>

  <!-- the connection whose topic $connection's ends use: the first one of
       its reader's port when that port is fed by several writers all of
       which a coordinator switches (alternatives that no job runs together,
       seed 004's trajectory sources): every one of them publishes on that
       topic; else $connection itself -->
  <xsl:function name="fp:ros-alternatives" as="element(pim:connection)">
    <xsl:param name="connection" as="element(pim:connection)"/>
    <xsl:variable name="root" as="document-node()" select="root($connection)"/>
    <xsl:variable name="all" as="element(pim:connection)*"
        select="$connection/pim:reader[1] ! key('fp:connection-by-end', @instance || '/' || @data-port, $root)"/>
    <xsl:sequence select="if (count($all) gt 1 and (every $w in $all/pim:writer/@instance
                                 satisfies exists(key('fp:instance-by-name', string($w), $root) ! fp:ros-job-of(.))))
                          then $all[1] else $connection"/>
  </xsl:function>

  <xsl:function name="fp:ros-coordinators" as="element(r:coordinator)*">
    <xsl:param name="binding" as="element(pim:binding)"/>
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:param name="nodes" as="document-node()"/>
    <xsl:param name="host-keys" as="map(xs:string, xs:string)"/>
    <xsl:variable name="root" as="document-node()" select="root($binding)"/>
    <xsl:variable name="here" as="map(xs:string, element(pim:instance))"
        select="map:merge($instances ! map:entry(string(@name), .))"/>
    <xsl:for-each select="$binding/pim:bound-subsystem">
      <xsl:variable name="subsystem" as="element(pim:bound-subsystem)" select="."/>
      <xsl:variable name="jobs" as="element(pim:bound-job)*"
          select="key('fp:ros-bound-job', distinct-values((@initial-job, pim:transition/(@from, @to))), $root)"/>
      <xsl:variable name="members" as="element(pim:instance)*"
          select="fp:in-start-order(distinct-values($jobs/pim:member/@instance)[map:contains($here, .)] ! $here(.))"/>
      <xsl:variable name="initial" as="element(pim:instance)*"
          select="$members[@name = key('fp:ros-bound-job', string($subsystem/@initial-job), $root)/pim:member/@instance]"/>
      <xsl:if test="exists($members)">
        <xsl:for-each select="distinct-values($jobs/pim:member/@instance)[not(map:contains($here, .))]">
          <xsl:sequence select="f:warn('JOB052', string(($jobs/pim:member[@instance eq current()])[1]/@xmi-id),
              'instance ''' || . || ''' of the jobs of subsystem ''' || $subsystem/@name || ''' is not in the ROS ' || $ros-version
              || ' package (deployed on another middleware): the ROS coordinator does not switch it; its own target does')"/>
        </xsl:for-each>
        <xsl:if test="$ros-version eq '1'">
          <xsl:sequence select="f:warn('JOB050', string($subsystem/@xmi-id), 'subsystem ''' || $subsystem/@name
              || ''': ROS 1 has no node lifecycle; a switch shuts down the nodes that leave (their process ends) and starts'
              || ' the ones that come as new processes (configure() and start() run again, their state is new); a node'
              || ' that stays gets its new values through its reload_parameters service (configure() does not run again)')"/>
        </xsl:if>
        <r:coordinator name="{@name}" xmi-id="{@xmi-id}" node="{@name}_coordinator" executable="{@name}_coordinator"
                       host="{$host-keys(string(($initial, $members)[1]/@host))}" initial-job="{@initial-job}">
          <xsl:for-each select="$jobs">
            <r:job name="{@name}" xmi-id="{@xmi-id}">
              <xsl:for-each select="fp:in-start-order($members[@name = current()/pim:member/@instance])">
                <r:member instance="{@name}"/>
              </xsl:for-each>
            </r:job>
          </xsl:for-each>
          <xsl:for-each select="pim:transition">
            <r:transition xmi-id="{@xmi-id}" from="{@from}" to="{@to}" event="{@event}">
              <xsl:for-each select="(pim:stop, pim:reconfigure, pim:start, pim:keep)[map:contains($here, string(@instance))]">
                <xsl:element name="r:{local-name()}">
                  <xsl:attribute name="instance" select="@instance"/>
                  <xsl:sequence select="pim:set ! fp:ros-job-set(., $here(string(../@instance)), $nodes)"/>
                </xsl:element>
              </xsl:for-each>
            </r:transition>
          </xsl:for-each>
        </r:coordinator>
      </xsl:if>
    </xsl:for-each>
  </xsl:function>

  <!-- a value a switch sets: the node parameter of its attribute, with its
       C++ and YAML literals; JOB051 when the attribute is no parameter -->
  <xsl:function name="fp:ros-job-set" as="element(r:value)?">
    <xsl:param name="set" as="element(pim:set)"/>
    <xsl:param name="instance" as="element(pim:instance)"/>
    <xsl:param name="nodes" as="document-node()"/>
    <xsl:variable name="parameter" as="element(r:parameter)?"
        select="key('fp:node', string($instance/@component), $nodes)/r:parameter[@xmi-id eq $set/@attribute]"/>
    <xsl:choose>
      <xsl:when test="empty($parameter)">
        <xsl:sequence select="f:warn('JOB051', string(($set/@holder, $set/../@xmi-id, $set/@attribute)[1]), 'value '''
            || $set/@value || ''' of ''' || $set/@name || ''' of instance ''' || $instance/@name || ''' (a job of transition '''
            || $set/../../@event || '''): ''' || $set/@name || ''' is no parameter of the ROS node, no switch sets it')"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:variable name="attribute" as="element()" select="key('fp:id', string($set/@attribute), root($set))"/>
        <xsl:variable name="values" as="xs:string+"
            select="fp:param-values($set/@value, $attribute,
                                    fp:required-type($attribute, $attribute/@id, 'parameter ''' || $parameter/@name || ''''),
                                    string(($set/@holder, $set/@attribute)[1]))"/>
        <r:value name="{$parameter/@name}" param1="{$parameter/@param1}" param2="{$parameter/@param2}"
               cpp="{$values[1]}" yaml="{$values[2]}"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>
</xsl:stylesheet>
