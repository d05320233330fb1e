<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/platform.xsl - the platform part of the PIM (deployment
  diagram, seed 000 Table 3).

  Reads:   the normalised XMI: every deployment element anywhere
           under the model root, whatever package or classifier owns it.
  Writes:  pim:platform with pim:node (nested), pim:artifact and
           pim:communication-path (schemas/pim/1/pim.xsd).
  Params:  none; tunnel parameters set by import.xsl: root (the model
           root: where the deployment elements are looked for, and where
           qualified names start), href-types (fp:href-types of the
           normalised XMI, for the mp:feature rules) and chains (the
           pim:kinematic-chain of each robot Device by its id, counted in
           its URDF file by urdf.xsl).
  Errors:  none raised here: check.xsl has reported dangling references.
  Warnings: IMP117 a deployment owned by one node whose client is another.

  Rules
  - Node, Device, ExecutionEnvironment -> pim:node kind node / device /
    execution-environment. A node owned by another node (nestedNode,
    packagedElement, nestedClassifier or ownedMember of a node) is a child
    node; every other node is a top-level pim:node.
  - A Device with a robomda Robot stereotype whose tag urdf names a URDF
    file: pim:kinematic-chain (the file, the chain's links, its movable
    joints and their count), before the attributes.
  - Node attributes: its owned Properties (not ports).
  - Deployment (owned by the node, or anywhere with client = the node):
    deployed = deployedArtifact, plus supplier, local ids only, in order,
    without duplicates. One owned by a node whose client is another node
    deploys on its client, once (warning IMP117 names both); one whose
    client is no node is not imported (IMP113, report.xsl).
  - A dialect's «Allocate» to the node (SysML: dialects.xsl,
    fp:node-allocations): a pim:deployment of what it allocates, as a
    Deployment; one to what is no node is IMP124 (fp:node-allocation-warnings).
  - A tool's deployment plan (RobotML): its middleware instances as
    execution environments (fp:allocation-nodes).
  - Artifact and DeploymentSpecification (nested artifacts too) ->
    top-level pim:artifact; @file-name = fileName; @node = the Node,
    Device or ExecutionEnvironment that owns it, if any (bind deploys what
    it manifests there). Manifestation (owned by
    the artifact, or anywhere with client = the artifact): element =
    utilizedElement, else supplier.
  - CommunicationPath -> pim:communication-path; its ends are the types of
    its memberEnd properties (ownedEnd, or ends owned by the nodes), or of
    its ownedEnds when memberEnd is not written. A path with fewer than two
    node ends is not written (IMP114, report.xsl).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:x="urn:robomda:import:xmi"
    xmlns:mp="urn:robomda:xslt:mode:private"
    xmlns:tp="urn:robomda:xslt:template:private"
    xmlns:pim="urn:robomda:pim:1"
    exclude-result-prefixes="#all">

  <xsl:mode name="mp:platform" on-no-match="deep-skip"/>

  <xsl:template name="tp:platform" as="element(pim:platform)">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <xsl:variable name="all" as="element()*" select="$root/descendant-or-self::*[@x:type = $platform-metas]"/>
    <!-- rival deployment plans (dialects.xsl), found once for every node -->
    <xsl:variable name="rival-plans" as="element()*" select="fp:rival-plans($root)"/>
    <pim:platform>
      <xsl:apply-templates select="$all[@x:type = $node-metas][not(../@x:type = $node-metas)]" mode="mp:platform">
        <xsl:with-param name="rival-plans" as="element()*" select="$rival-plans" tunnel="yes"/>
      </xsl:apply-templates>
      <!-- the execution environments of a tool's deployment plans (RobotML:
           dialects.xsl) -->
      <xsl:sequence select="fp:allocation-nodes($root), fp:node-allocation-warnings($root, $rival-plans)"/>
      <xsl:apply-templates select="$all[@x:type = $artifact-metas]" mode="mp:platform"/>
      <xsl:apply-templates select="$all[@x:type eq 'CommunicationPath']" mode="mp:platform"/>
    </pim:platform>
  </xsl:template>

  <xsl:template match="*" mode="mp:platform" priority="-1" as="empty-sequence()"/>

  <xsl:template match="*[@x:type = $node-metas]" mode="mp:platform" as="element(pim:node)">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <xsl:param name="chains" as="map(*)" tunnel="yes" select="map { }"/>
    <xsl:param name="rival-plans" as="element()*" tunnel="yes" select="()"/>
    <xsl:variable name="meta" as="xs:string" select="fp:meta(.)"/>
    <pim:node id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}"
        kind="{if ($meta eq 'Device') then 'device'
               else if ($meta eq 'ExecutionEnvironment') then 'execution-environment'
               else 'node'}">
      <xsl:call-template name="tp:decoration">
        <xsl:with-param name="e" select="."/>
      </xsl:call-template>
      <!-- a robot Device's kinematic chain, counted in its URDF file (urdf.xsl) -->
      <xsl:sequence select="$chains(fp:id(.))"/>
      <xsl:apply-templates select="ownedAttribute[not(@x:type = 'Port')]" mode="mp:feature"/>
      <!-- a deployment owned here whose client is another element is that
           one's (IMP117 when it is a node: imported there, once) -->
      <xsl:variable name="node" as="element()" select="."/>
      <xsl:variable name="elsewhere" as="element()*"
          select="deployment[@x:type eq 'Deployment'][exists(fp:targets(., 'client') except $node)]"/>
      <xsl:for-each select="$elsewhere">
        <xsl:variable name="client" as="element()*" select="fp:targets(., 'client')[@x:type = $node-metas]"/>
        <xsl:if test="exists($client)">
          <xsl:sequence select="f:warn('IMP117', fp:id(.), fp:label(.) || ' is owned by ' || fp:label($node) || ' but its client is '
              || string-join($client ! fp:label(.), ', ') || ': it deploys there (its client), not on its owner')"/>
        </xsl:if>
      </xsl:for-each>
      <xsl:for-each select="(deployment[@x:type eq 'Deployment'] except $elsewhere)
                            | key('fp:dep-by-client', fp:id(.))[@x:type eq 'Deployment']">
        <xsl:variable name="deployed" as="xs:string*"
            select="distinct-values((fp:targets(., 'deployedArtifact'), fp:targets(., 'supplier')) ! fp:id(.))"/>
        <xsl:if test="exists($deployed)">
          <pim:deployment id="{fp:id(.)}" name="{@name}" deployed="{$deployed}">
            <xsl:call-template name="tp:decoration">
              <xsl:with-param name="e" select="."/>
            </xsl:call-template>
          </pim:deployment>
        </xsl:if>
      </xsl:for-each>
      <!-- what a dialect's «Allocate» puts here (SysML: dialects.xsl) -->
      <xsl:sequence select="fp:node-allocations(., $rival-plans)"/>
      <xsl:apply-templates select="*[@x:type = $node-metas]" mode="mp:platform"/>
    </pim:node>
  </xsl:template>

  <xsl:template match="*[@x:type = $artifact-metas]" mode="mp:platform" as="element(pim:artifact)">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <pim:artifact id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}">
      <xsl:if test="@fileName">
        <xsl:attribute name="file-name" select="@fileName"/>
      </xsl:if>
      <!-- owned by a node: what it manifests runs there (bind) -->
      <xsl:for-each select="ancestor::*[@x:type = $node-metas][1]">
        <xsl:attribute name="node" select="fp:id(.)"/>
      </xsl:for-each>
      <xsl:call-template name="tp:decoration">
        <xsl:with-param name="e" select="."/>
      </xsl:call-template>
      <xsl:apply-templates select="ownedAttribute[not(@x:type = 'Port')]" mode="mp:feature"/>
      <xsl:for-each select="manifestation | key('fp:dep-by-client', fp:id(.))[@x:type eq 'Manifestation']">
        <xsl:variable name="member" as="element()" select="."/>
        <xsl:variable name="elements" as="element()*"
            select="if (exists(fp:ref-ids(., 'utilizedElement'))) then fp:targets(., 'utilizedElement')
                    else fp:targets(., 'supplier')"/>
        <xsl:for-each select="$elements">
          <pim:manifestation id="{fp:nth-id($member, position())}" name="{$member/@name}" element="{fp:id(.)}"/>
        </xsl:for-each>
      </xsl:for-each>
    </pim:artifact>
  </xsl:template>

  <xsl:template match="*[@x:type eq 'CommunicationPath']" mode="mp:platform"
                as="element(pim:communication-path)?">
    <xsl:param name="root" as="element()" tunnel="yes"/>
    <xsl:variable name="member-ends" as="element()*" select="fp:targets(., 'memberEnd')"/>
    <xsl:variable name="ends" as="element()*"
        select="if (exists($member-ends)) then $member-ends else ownedEnd"/>
    <xsl:variable name="nodes" as="element()*"
        select="$ends ! fp:type-element(.)[@x:type = $node-metas]"/>
    <xsl:choose>
      <xsl:when test="count($nodes) ge 2">
        <pim:communication-path id="{fp:id(.)}" name="{@name}" qualified-name="{fp:qname(., $root)}">
          <xsl:call-template name="tp:decoration">
            <xsl:with-param name="e" select="."/>
          </xsl:call-template>
          <xsl:for-each select="$nodes">
            <pim:end node="{fp:id(.)}"/>
          </xsl:for-each>
        </pim:communication-path>
      </xsl:when>
      <!-- otherwise not imported: report.xsl says so (IMP114) -->
    </xsl:choose>
  </xsl:template>
</xsl:stylesheet>
