<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/urdf.xsl - the kinematic chain of a robot Device, read from
  the URDF file its Robot stereotype names (seed 001: the degrees of
  freedom of the hardware platform, for the DoF-mismatch check of
  xslt/m2m/bind/devices.xsl).

  Reads:   the normalised XMI: every Device with a robomda Robot stereotype
           application and its tags urdf, rootLink and tipLink (attributes
           of the application, or child elements as some tools write
           them); through doc(), the URDF file urdf names (a path relative
           to the model file that holds the Device; a URDF document is a
           robot element whose link and joint children are read, any
           namespace).
  Writes:  fp:urdf-chains: per Device with a Robot stereotype, a map
           { 'device': its id, 'items': its pim:kinematic-chain
           (schemas/pim/1/pim.xsd), else its problems (fp:problem: maps
           with severity error / warning, code, id, message) }.
           fp:check-urdf reports the problems; platform.xsl writes the
           chains into their pim:node.
  Params:  none; fp:urdf-chains takes the model file's URI and the
           sandbox (files.xsl: fp:sandbox).

  Counting (docs/profile.md, "The hardware platform's degrees of freedom"):
  the joints of the chain from link rootLink down to link tipLink (both
  given); of the subtree below rootLink (only rootLink); from the tree's
  root down to tipLink (only tipLink); of the whole file (neither).
  revolute, continuous and prismatic joints count 1 each, fixed joints 0,
  a joint with a mimic element 0 (its value follows another joint's); a
  floating or planar joint, or a type URDF does not have, is refused
  (IMP047): its coordinates are no values of a joint array.

  Errors (f:fail-all, located on the Robot stereotype application):
    IMP040  the urdf path names a file outside the model's sandbox (its
            folder, project, workspace projects and the model path:
            files.xsl), or is a URI of another scheme (package://, http:).
    IMP042  the URDF file is not there, or cannot be read (or the model
            was given without a file, so no path is relative to it).
    IMP043  the URDF file is not well-formed XML.
    IMP044  the URDF file is not a URDF robot description: its root
            element is not robot, or it uses xacro macros (unexpanded).
    IMP045  rootLink or tipLink names no link of the URDF file.
    IMP046  tipLink is not below rootLink (the message names both, and
            the links above tipLink).
    IMP047  a joint of the chain that robomda does not count: floating,
            planar, or a type URDF does not have.
  Warnings:
    IMP048  rootLink or tipLink without urdf: nothing to read them from.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:x="urn:robomda:import:xmi"
    xmlns:pim="urn:robomda:pim:1"
    exclude-result-prefixes="#all">

  <!-- URDF documents: the joints by the link they move (child) and by the
       link they hang from (parent) -->
  <xsl:key name="fp:urdf-joint-by-child" match="/*:robot/*:joint" use="*:child/@link"/>
  <xsl:key name="fp:urdf-joint-by-parent" match="/*:robot/*:joint" use="*:parent/@link"/>

  <!-- the joint types that count, and those robomda refuses to count -->
  <xsl:variable name="fp:urdf-counted" as="xs:string+" select="('revolute', 'continuous', 'prismatic')"/>
  <xsl:variable name="fp:urdf-types" as="xs:string+" select="($fp:urdf-counted, 'fixed', 'floating', 'planar')"/>

  <!-- the robomda Robot stereotype application of $device, if any -->
  <xsl:function name="fp:robot-application" as="element()?">
    <xsl:param name="device" as="element()"/>
    <xsl:sequence select="key('fp:stereotype-by-base', fp:id($device), root($device))[local-name() eq 'Robot']
        [f:is-robomda-profile(string(prefix-from-QName(node-name(.))), namespace-uri())][1]"/>
  </xsl:function>

  <!-- tag $name of stereotype application $app, () when it is not set or
       empty (EA writes unset tags as "") -->
  <xsl:function name="fp:application-tag" as="xs:string?">
    <xsl:param name="app" as="element()"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:sequence select="($app/@*[namespace-uri() eq ''][local-name() eq $name],
                           $app/*[namespace-uri() eq ''][local-name() eq $name])[1] ! normalize-space(.)[. ne '']"/>
  </xsl:function>

  <!-- ====================================================== entry -->
  <!-- per Device under $root with a Robot stereotype: map { 'device',
       'items' } (see the header); $model-uri the model file's URI ('' when
       the model was given without a file), $sandbox the sandbox
       (files.xsl, fp:sandbox; () without a file) -->
  <xsl:function name="fp:urdf-chains" as="map(*)*">
    <xsl:param name="root" as="element()"/>
    <xsl:param name="model-uri" as="xs:string"/>
    <xsl:param name="sandbox" as="map(*)?"/>
    <xsl:for-each select="$root/descendant-or-self::*[@x:type eq 'Device']">
      <xsl:variable name="app" as="element()?" select="fp:robot-application(.)"/>
      <xsl:if test="exists($app)">
        <xsl:sequence select="map { 'device': fp:id(.), 'items': fp:urdf-chain(., $app, $model-uri, $sandbox) }"/>
      </xsl:if>
    </xsl:for-each>
  </xsl:function>

  <!-- the warnings of $chains reported, every error raised (f:fail-all) -->
  <xsl:function name="fp:check-urdf" as="empty-sequence()">
    <xsl:param name="chains" as="map(*)*"/>
    <xsl:variable name="problems" as="map(*)*" select="$chains ! ?items[. instance of map(*)]"/>
    <xsl:for-each select="$problems[?severity eq 'warning']">
      <xsl:sequence select="f:warn(?code, ?id, ?message)"/>
    </xsl:for-each>
    <xsl:sequence select="f:fail-all($problems[?severity eq 'error'])"/>
  </xsl:function>

  <!-- a problem found in a URDF file, as f:fail-all takes it (with its
       severity): located on the Robot stereotype application $app -->
  <xsl:function name="fp:problem" as="map(*)">
    <xsl:param name="code" as="xs:string"/>
    <xsl:param name="app" as="element()"/>
    <xsl:param name="message" as="xs:string"/>
    <xsl:sequence select="map { 'severity': if ($code eq 'IMP048') then 'warning' else 'error', 'code': $code,
                                'id': fp:id($app), 'message': $message }"/>
  </xsl:function>

  <!-- ================================================ the file -->
  <!-- the chain of $device, whose Robot stereotype application is $app:
       its pim:kinematic-chain, else its problems (fp:problem); () when no urdf
       is given -->
  <xsl:function name="fp:urdf-chain" as="item()*">
    <xsl:param name="device" as="element()"/>
    <xsl:param name="app" as="element()"/>
    <xsl:param name="model-uri" as="xs:string"/>
    <xsl:param name="sandbox" as="map(*)?"/>
    <xsl:variable name="path" as="xs:string?" select="fp:application-tag($app, 'urdf')"/>
    <xsl:variable name="who" as="xs:string" select="'device ''' || $device/@name || ''''"/>
    <xsl:variable name="file" as="xs:string" select="'the URDF file ''' || $path || ''' of ' || $who"/>
    <!-- a Device of another model file: relative to that file -->
    <xsl:variable name="base" as="xs:string?"
        select="if ($model-uri eq '') then () else ($device/ancestor::*[@x:file][1]/@x:file ! string(resolve-uri(., $model-uri)), $model-uri)[1]"/>
    <xsl:variable name="uri" as="xs:string?" select="if (exists($path) and exists($base)) then fp:urdf-uri($path, $base) else ()"/>
    <xsl:choose>
      <xsl:when test="empty($path)">
        <xsl:if test="exists((fp:application-tag($app, 'rootLink'), fp:application-tag($app, 'tipLink')))">
          <xsl:sequence select="fp:problem('IMP048', $app, $who || ' names its chain by rootLink / tipLink but no URDF file '
              || '(the Robot tag urdf): they are not read; give urdf, or leave them out')"/>
        </xsl:if>
      </xsl:when>
      <xsl:when test="empty($base)">
        <xsl:sequence select="fp:problem('IMP042', $app, $file || ' cannot be read: the model was not read from a file, '
            || 'so no path is relative to it')"/>
      </xsl:when>
      <xsl:when test="empty($uri) or empty($sandbox) or not(fp:in-sandbox($uri, $sandbox))">
        <xsl:sequence select="fp:problem('IMP040', $app, $file || ' is not a file in the model''s folder, project or the model path: '
            || 'robomda reads only files there, never a package:// or network URI; give the path relative to the model file, '
            || 'or add its folder with --model-path DIR')"/>
      </xsl:when>
      <xsl:when test="not(doc-available($uri))">
        <xsl:sequence select="if (unparsed-text-available($uri))
            then fp:problem('IMP043', $app, $file || ' is not well-formed XML: robomda cannot read its joints '
                 || '(an XML parser names the line: xmllint --noout FILE)')
            else fp:problem('IMP042', $app, $file || ' is not there (or cannot be read): the path is relative to the model file; '
                 || 'put the file there or correct the tag urdf')"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:sequence select="fp:urdf-robot(doc($uri)/*, $path, $app, $file)"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <!-- $path (a file path, "\" or "/" separated, relative or absolute, or a
       file: URI) resolved against $base; () for a URI of another scheme
       or what no URI can be made of -->
  <xsl:function name="fp:urdf-uri" as="xs:string?">
    <xsl:param name="path" as="xs:string"/>
    <xsl:param name="base" as="xs:string"/>
    <xsl:variable name="slashed" as="xs:string" select="translate($path, '\', '/')"/>
    <xsl:if test="not(matches($slashed, '^[A-Za-z][A-Za-z0-9+.\-]*:') and not(starts-with(lower-case($slashed), 'file:')))">
      <xsl:try>
        <xsl:sequence select="string(resolve-uri(iri-to-uri($slashed), $base))"/>
        <xsl:catch/>
      </xsl:try>
    </xsl:if>
  </xsl:function>

  <!-- ============================================== the robot -->
  <!-- the chain of the URDF document element $robot that $app names
       (rootLink, tipLink), counted; else its problems (fp:problem) -->
  <xsl:function name="fp:urdf-robot" as="item()*">
    <xsl:param name="robot" as="element()"/>
    <xsl:param name="path" as="xs:string"/>
    <xsl:param name="app" as="element()"/>
    <xsl:param name="file" as="xs:string"/>
    <xsl:variable name="root-link" as="xs:string?" select="fp:application-tag($app, 'rootLink')"/>
    <xsl:variable name="tip-link" as="xs:string?" select="fp:application-tag($app, 'tipLink')"/>
    <xsl:variable name="links" as="xs:string*"
        select="distinct-values(($robot/*:link/@name, $robot/*:joint/(*:parent | *:child)/@link) ! string(.))"/>
    <xsl:variable name="xacro" as="element()?" select="$robot/descendant-or-self::*[contains(namespace-uri(), 'xacro')][1]"/>
    <xsl:choose>
      <xsl:when test="local-name($robot) ne 'robot'">
        <xsl:sequence select="fp:problem('IMP044', $app, $file || ' is not a URDF robot description: its root element is '
            || name($robot) || ', not robot')"/>
      </xsl:when>
      <xsl:when test="exists($xacro)">
        <xsl:sequence select="fp:problem('IMP044', $app, $file || ' uses xacro macros (' || name($xacro)
            || '): robomda reads URDF, not xacro; expand it (xacro FILE.urdf.xacro -o FILE.urdf) and name the expanded file')"/>
      </xsl:when>
      <xsl:when test="some $link in ($root-link, $tip-link) satisfies not($link = $links)">
        <xsl:for-each select="('rootLink', 'tipLink')">
          <xsl:variable name="link" as="xs:string?" select="if (. eq 'rootLink') then $root-link else $tip-link"/>
          <xsl:if test="exists($link) and not($link = $links)">
            <xsl:sequence select="fp:problem('IMP045', $app, $file || ' (robot ''' || $robot/@name || ''') has no link '''
                || $link || ''' (the Robot tag ' || . || '); its links: ' || fp:names($links))"/>
          </xsl:if>
        </xsl:for-each>
      </xsl:when>
      <xsl:otherwise>
        <xsl:sequence select="fp:urdf-counted($robot, $path, $app, $file, $root-link, $tip-link)"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <!-- "a, b, c" (the first 12 of $names, then "..."), or "none" -->
  <xsl:function name="fp:names" as="xs:string">
    <xsl:param name="names" as="xs:string*"/>
    <xsl:sequence select="if (empty($names)) then 'none'
        else string-join((subsequence($names, 1, 12), if (count($names) gt 12) then '...' else ()), ', ')"/>
  </xsl:function>

  <!-- the counted chain (pim:kinematic-chain), else problems (fp:problem):
       IMP046 when $tip-link is not below $root-link, IMP047 for each joint
       that cannot be counted. The joints are handled as their positions
       among the robot's joints: atomic values keep the chain's order, where
       a sequence of nodes may come back in document order (SaxonJS 2 sorts
       the nodes a conditional expression returns). -->
  <xsl:function name="fp:urdf-counted" as="item()*">
    <xsl:param name="robot" as="element()"/>
    <xsl:param name="path" as="xs:string"/>
    <xsl:param name="app" as="element()"/>
    <xsl:param name="file" as="xs:string"/>
    <xsl:param name="root-link" as="xs:string?"/>
    <xsl:param name="tip-link" as="xs:string?"/>
    <xsl:variable name="all" as="element()*" select="$robot/*:joint"/>
    <!-- each joint's position among them, by node identity (built once: a
         count of the preceding joints per joint was quadratic) -->
    <xsl:variable name="positions" as="map(xs:string, xs:integer)"
        select="map:merge(for $i in 1 to count($all) return map:entry(generate-id($all[$i]), $i))"/>
    <!-- from the tip up: the joints above it, tip first -->
    <xsl:variable name="up" as="xs:integer*" select="fp:urdf-up($robot, $positions, $tip-link, map{})"/>
    <!-- how many of them are on the chain: up to the one that hangs from
         the root link; () when none does (the tip is not below the root) -->
    <xsl:variable name="on-chain" as="xs:integer?"
        select="if (empty($tip-link) or $root-link = $tip-link) then 0
                else if (empty($root-link)) then count($up)
                else (for $i in 1 to count($up) return $i[string($all[$up[$i]]/*:parent/@link) eq $root-link])[1]"/>
    <xsl:variable name="chain" as="xs:integer*"
        select="if (exists($tip-link)) then reverse(subsequence($up, 1, ($on-chain, 0)[1]))
                else if (exists($root-link)) then (fp:urdf-below($robot, $root-link, map{})/.) ! $positions(generate-id(.))
                else 1 to count($all)"/>
    <xsl:variable name="wrong" as="xs:integer*"
        select="for $i in $chain return $i[not(fp:urdf-type($all[$i]) = $fp:urdf-types)
                                           or fp:urdf-type($all[$i]) = ('floating', 'planar')]"/>
    <xsl:variable name="moving" as="xs:integer*" select="for $i in $chain return $i[fp:urdf-type($all[$i]) = $fp:urdf-counted]"/>
    <xsl:choose>
      <xsl:when test="empty($on-chain)">
        <xsl:sequence select="fp:problem('IMP046', $app, $file || ' names the chain from link ''' || $root-link
            || ''' (rootLink) to link ''' || $tip-link || ''' (tipLink), but ''' || $tip-link || ''' is not below '''
            || $root-link || ''': the links above it are ' || fp:names(for $i in $up return string($all[$i]/*:parent/@link)))"/>
      </xsl:when>
      <xsl:when test="exists($wrong)">
        <xsl:sequence select="for $i in $wrong return fp:unknown-joint($all[$i], $app, $file)"/>
      </xsl:when>
      <xsl:otherwise>
        <pim:kinematic-chain urdf="{$path}" robot="{$robot/@name}" dof="{count(for $i in $moving return $i[empty($all[$i]/*:mimic)])}">
          <xsl:if test="exists($root-link)"><xsl:attribute name="root-link" select="$root-link"/></xsl:if>
          <xsl:if test="exists($tip-link)"><xsl:attribute name="tip-link" select="$tip-link"/></xsl:if>
          <xsl:for-each select="$moving">
            <xsl:variable name="joint" as="element()" select="$all[current()]"/>
            <pim:joint name="{$joint/@name}" type="{fp:urdf-type($joint)}">
              <xsl:for-each select="$joint/*:mimic[1]/@joint"><xsl:attribute name="mimics" select="."/></xsl:for-each>
            </pim:joint>
          </xsl:for-each>
        </pim:kinematic-chain>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <xsl:function name="fp:urdf-type" as="xs:string">
    <xsl:param name="joint" as="element()"/>
    <xsl:sequence select="normalize-space($joint/@type)"/>
  </xsl:function>

  <!-- IMP047 about $joint, a joint of the chain that robomda does not count -->
  <xsl:function name="fp:unknown-joint" as="map(*)">
    <xsl:param name="joint" as="element()"/>
    <xsl:param name="app" as="element()"/>
    <xsl:param name="file" as="xs:string"/>
    <xsl:sequence select="fp:problem('IMP047', $app, $file || ': the chain holds joint ''' || $joint/@name || ''' of type '''
        || $joint/@type || ''', which robomda does not count ('
        || (if (fp:urdf-type($joint) = ('floating', 'planar'))
            then 'a floating or planar joint moves a body in space or in a plane; its coordinates are no values of a joint array'
            else 'URDF joint types: ' || string-join($fp:urdf-types, ', '))
        || '); choose rootLink / tipLink so that the chain leaves it out')"/>
  </xsl:function>

  <!-- the joints from link $link up to the root of the tree, $link's own
       first, as their positions among the robot's joints ($positions:
       generate-id of a joint to its position; each link once, $seen the
       links passed as a set: a URDF with a cycle ends there) -->
  <xsl:function name="fp:urdf-up" as="xs:integer*">
    <xsl:param name="robot" as="element()"/>
    <xsl:param name="positions" as="map(xs:string, xs:integer)"/>
    <xsl:param name="link" as="xs:string?"/>
    <xsl:param name="seen" as="map(xs:string, xs:boolean)"/>
    <xsl:variable name="joint" as="element()?" select="key('fp:urdf-joint-by-child', $link, root($robot))[1]"/>
    <xsl:sequence select="if (empty($joint) or map:contains($seen, $link)) then ()
        else ($positions(generate-id($joint)),
              fp:urdf-up($robot, $positions, string($joint/*:parent/@link), map:put($seen, $link, true())))"/>
  </xsl:function>

  <!-- the joints below the links $links, at any depth (each link once;
       $seen: the links passed, as a set) -->
  <xsl:function name="fp:urdf-below" as="element()*">
    <xsl:param name="robot" as="element()"/>
    <xsl:param name="links" as="xs:string*"/>
    <xsl:param name="seen" as="map(xs:string, xs:boolean)"/>
    <xsl:variable name="joints" as="element()*" select="key('fp:urdf-joint-by-parent', $links, root($robot))"/>
    <xsl:variable name="passed" as="map(xs:string, xs:boolean)"
        select="map:merge(($seen, $links ! map:entry(., true())), map{'duplicates': 'use-first'})"/>
    <xsl:variable name="next" as="xs:string*"
        select="distinct-values($joints/*:child/@link ! string(.))[not(map:contains($passed, .))]"/>
    <xsl:sequence select="$joints, if (exists($next)) then fp:urdf-below($robot, $next, $passed) else ()"/>
  </xsl:function>
</xsl:stylesheet>
