<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/bind/lookups.xsl - bind (xslt/m2m/bind.xsl): look-ups in the PIM: realizing classes, middlewares, hosts.

  Reads:   the PIM (urn:robomda:pim:1) and the working trees of fp:binding.
  Writes:  parts of pim:binding (schemas/pim/1/binding.xsd), or values.
  Params:  none.  Keys: those of bind.xsl.
  Provides: the functions of the model look-ups section.
  Errors:  BND003 unknown middleware name.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:m="urn:robomda:xslt:mode"
    xmlns:t="urn:robomda:xslt:template"
    xmlns:mp="urn:robomda:xslt:mode:private"
    xmlns:err="http://www.w3.org/2005/xqt-errors"
    exclude-result-prefixes="#all">

  <!-- ================================================ model look-ups -->
  <xsl:function name="fp:realizing-class" as="element(pim:class)?">
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:variable name="root" as="document-node()" select="root($component[1])"/>
    <xsl:sequence select="(for $r in $component/pim:realization
                           return key('fp:id', $r/@classifier, $root)/self::pim:class)[1]"/>
  </xsl:function>

  <xsl:function name="fp:execution-environments" as="element(pim:node)*">
    <xsl:param name="root" as="document-node()"/>
    <xsl:sequence select="$root/pim:model/pim:platform//pim:node[@kind eq 'execution-environment']"/>
  </xsl:function>

  <xsl:function name="fp:hosts" as="element(pim:node)*">
    <xsl:param name="root" as="document-node()"/>
    <xsl:sequence select="$root/pim:model/pim:platform//pim:node[fp:is-host(.)]"/>
  </xsl:function>

  <!-- true when $node, a node of the model's platform, is one of fp:hosts
       (a test of the node itself: no scan of every host) -->
  <xsl:function name="fp:is-host" as="xs:boolean">
    <xsl:param name="node" as="element()"/>
    <xsl:sequence select="exists($node/self::pim:node[@kind eq 'node' or exists(f:stereotype(., 'Host'))]
                                 [ancestor::pim:platform[parent::pim:model[parent::document-node()]]])"/>
  </xsl:function>

  <!-- the default values of the robomda profile's tags (what a tool that
       leaves out a tag equal to its default means; the import drops such
       tags too, so that every tool gives the same PIM) -->
  <xsl:variable name="fp:profile-defaults" as="document-node()" select="doc('../../import/profile-defaults.xml')"/>

  <xsl:function name="fp:tag-default" as="xs:string?">
    <xsl:param name="stereo" as="xs:string"/>
    <xsl:param name="tag" as="xs:string"/>
    <xsl:sequence select="$fp:profile-defaults/*/*/*[@stereotype eq $stereo][@name eq $tag][1]/@default/string()"/>
  </xsl:function>

  <!-- what names the middleware of an execution environment: its Middleware
       kind; a Middleware stereotype that leaves kind out means the profile
       default (OROCOS); without the stereotype, the environment's name -->
  <xsl:function name="fp:middleware-name" as="xs:string">
    <xsl:param name="ee" as="element(pim:node)"/>
    <!-- (a middleware its tool's profile gives, pim:node/@middleware: a
         RobotML «RoboticMiddleware» that a deployment plan allocates to) -->
    <xsl:variable name="tag" as="xs:string?"
        select="($ee/@middleware ! string(.), fp:tag($ee, 'Middleware', 'kind')[normalize-space(.)],
                 if (exists(f:stereotype($ee, 'Middleware'))) then fp:tag-default('Middleware', 'kind') else ())[1]"/>
    <xsl:sequence select="if (normalize-space($tag)) then fp:literal($tag) else string($ee/@name)"/>
  </xsl:function>

  <!-- the middleware fp:middleware-name means, () when it is unknown -->
  <xsl:function name="fp:known-middleware" as="xs:string?">
    <xsl:param name="ee" as="element(pim:node)"/>
    <xsl:variable name="key" as="xs:string" select="upper-case(replace(fp:middleware-name($ee), '[^A-Za-z0-9]', ''))"/>
    <xsl:sequence select="
        if ($key = ('OROCOS', 'OROCOSRTT', 'RTT', 'OROCOSRTT2')) then 'OROCOS'
        else if ($key = ('ROS', 'ROS1')) then 'ROS'
        else if ($key eq 'ROS2') then 'ROS2'
        else if ($key = ('OPENRTM', 'OPENRTMAIST')) then 'OpenRTM'
        else ()"/>
  </xsl:function>

  <!-- the middleware of an execution environment; BND003 when unknown -->
  <xsl:function name="fp:middleware" as="xs:string">
    <xsl:param name="ee" as="element(pim:node)"/>
    <xsl:sequence select="(fp:known-middleware($ee), f:fail-all(fp:middleware-problems($ee)))[1]"/>
  </xsl:function>

  <!-- BND003 about $ee, if its middleware is unknown (fp:middleware) -->
  <xsl:function name="fp:middleware-problems" as="map(*)?">
    <xsl:param name="ee" as="element(pim:node)"/>
    <xsl:sequence select="if (exists(fp:known-middleware($ee))) then () else
        map { 'code': 'BND003', 'id': string($ee/@id), 'message': 'unknown middleware ''' || fp:middleware-name($ee)
              || ''' of execution environment ''' || $ee/@name || ''' (expected OROCOS, ROS, ROS2 or OpenRTM)' }"/>
  </xsl:function>
</xsl:stylesheet>
