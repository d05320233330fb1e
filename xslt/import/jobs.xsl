<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/jobs.xsl - jobs and subsystems of seed 004 (docs/jobs.md).
  Reads:   the normalised XMI (xmi-common.xsl): InstanceSpecifications
           stereotyped robomda Job (their slots, and the slots of the
           InstanceSpecification each slot's InstanceValue names), and
           StateMachines stereotyped robomda Subsystem, or one of whose
           States is named after a job (their regions' states, pseudostates
           and transitions, with the triggers' events).
  Writes:  pim:coordination (schemas/pim/1/pim.xsd): pim:job (a pim:member
           per slot whose definingFeature is in the model, with a pim:value
           per slot of its value's instance), pim:subsystem (pim:state,
           pim:transition); nothing for a model without jobs.
  Params:  none (tunnel parameter root: the model root, for qualified names).
  Errors:  none raised here: bind checks what the members and states name
           (JOB001-JOB049, docs/errors.md).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:tp="urn:robomda:xslt:template:private"
    xmlns:mp="urn:robomda:xslt:mode:private"
    xmlns:x="urn:robomda:import:xmi"
    xmlns:pim="urn:robomda:pim:1"
    exclude-result-prefixes="#all">

  <!-- the robomda stereotype $name applied to $e, in the XMI -->
  <xsl:function name="fp:applies" as="xs:boolean">
    <xsl:param name="e" as="element()"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:sequence select="exists(key('fp:stereotype-by-base', fp:id($e), root($e))
        [local-name() eq $name][f:is-robomda-profile(string(prefix-from-QName(node-name(.))), namespace-uri())])"/>
  </xsl:function>

  <xsl:template name="tp:coordination" as="element(pim:coordination)?">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <xsl:variable name="jobs" as="element()*"
        select="$root/descendant-or-self::*[@x:type eq 'InstanceSpecification'][fp:applies(., 'Job')]"/>
    <xsl:variable name="job-names" as="xs:string*" select="$jobs/@name ! string()"/>
    <xsl:variable name="machines" as="element()*"
        select="$root/descendant-or-self::*[@x:type eq 'StateMachine']
                [fp:applies(., 'Subsystem') or region/subvertex[@x:type eq 'State'][@name = $job-names]]"/>
    <xsl:if test="exists($jobs) or exists($machines)">
      <pim:coordination>
        <xsl:apply-templates select="$jobs" mode="mp:job"/>
        <xsl:apply-templates select="$machines" mode="mp:subsystem"/>
      </pim:coordination>
    </xsl:if>
  </xsl:template>

  <xsl:mode name="mp:job" on-no-match="fail"/>
  <xsl:mode name="mp:subsystem" on-no-match="fail"/>

  <xsl:template match="*" mode="mp:job" as="element(pim:job)">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <pim:job id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}">
      <xsl:for-each select="fp:targets(., 'classifier')[1]">
        <xsl:attribute name="classifier" select="fp:id(.)"/>
      </xsl:for-each>
      <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
      <xsl:for-each select="slot[exists(fp:targets(., 'definingFeature'))]">
        <pim:member id="{fp:id(.)}" part="{fp:id(fp:targets(., 'definingFeature')[1])}">
          <xsl:for-each select="value[fp:meta(.) eq 'InstanceValue'] ! fp:targets(., 'instance')
                                /slot[exists(fp:targets(., 'definingFeature'))]">
            <xsl:variable name="value" as="xs:string?" select="fp:value(value[1])"/>
            <pim:value id="{fp:id(.)}" attribute="{fp:id(fp:targets(., 'definingFeature')[1])}">
              <xsl:if test="exists($value)"><xsl:attribute name="value" select="$value"/></xsl:if>
            </pim:value>
          </xsl:for-each>
        </pim:member>
      </xsl:for-each>
    </pim:job>
  </xsl:template>

  <xsl:template match="*" mode="mp:subsystem" as="element(pim:subsystem)">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <pim:subsystem id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}">
      <xsl:call-template name="tp:decoration"><xsl:with-param name="e" select="."/></xsl:call-template>
      <xsl:for-each select="region/subvertex">
        <pim:state id="{fp:id(.)}" name="{@name}"
            kind="{if (@x:type eq 'State') then 'state' else if (@x:type eq 'FinalState') then 'final'
                   else if (@x:type eq 'Pseudostate' and (empty(@kind) or @kind eq 'initial')) then 'initial'
                   else 'pseudostate'}"/>
      </xsl:for-each>
      <xsl:for-each select="region/transition[exists(fp:targets(., 'source')) and exists(fp:targets(., 'target'))]">
        <xsl:variable name="trigger" as="element()?" select="trigger[1]"/>
        <xsl:variable name="event" as="xs:string?"
            select="($trigger ! fp:targets(., 'event')[1]/@name[normalize-space()], $trigger/@name[normalize-space()])[1]"/>
        <pim:transition id="{fp:id(.)}" source="{fp:id(fp:targets(., 'source')[1])}" target="{fp:id(fp:targets(., 'target')[1])}">
          <xsl:if test="@name"><xsl:attribute name="name" select="@name"/></xsl:if>
          <xsl:if test="exists($event)"><xsl:attribute name="event" select="$event"/></xsl:if>
          <xsl:if test="exists($trigger)"><xsl:attribute name="trigger" select="fp:id($trigger)"/></xsl:if>
        </pim:transition>
      </xsl:for-each>
    </pim:subsystem>
  </xsl:template>
</xsl:stylesheet>
