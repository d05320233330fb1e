<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/bind/devices.xsl - bind (xslt/m2m/bind.xsl): the hardware
  platform's degrees of freedom (seed 001, the DoF-mismatch warning).

  Reads:   the PIM (urn:robomda:pim:1): pim:dependency kind "drives" (a part
           or a component drives a Device: the import reads a Dependency
           whose supplier is a Device so), the Device's degrees of freedom
           (fp:declared-dofs: its robomda Robot tag dof, else the movable
           joints of the kinematic chain the import counted in the URDF
           file its tag urdf names, pim:kinematic-chain, else the default
           of its attribute dof), the instances, bound components and
           connections of the binding being made.
  Writes:  nothing; warnings.
  Params:  none.  Keys: those of bind.xsl.
  Errors (f:fail-all, every robot Device at once):
    BND010  a Robot tag dof that is not a non-negative integer (located on
            the stereotype application).
  Warnings (f:warn):
    BND021  a fixed-size array (multiplicity [n..n], n > 1) that an
            instance driving a Device, or an instance connected to it,
            carries on a port (the datum, or an attribute of its data type
            at any depth) or holds in an attribute, whose size is not the
            Device's degrees of freedom: once on the element and once on
            the Device, each naming the other (and where the number comes
            from, unless it is the attribute dof).
    BND022  a Device some part drives that declares no degrees of freedom
            (no Robot tag dof or urdf, no attribute dof with an integer
            default): nothing is checked.
    BND023  a Device whose Robot tag dof, URDF chain and attribute dof
            (two or three of them) disagree: on the Robot stereotype
            application, naming every value and the one the checks use
            (the first of that order).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- ============================================ degrees of freedom -->
  <xsl:variable name="fp:dof-attribute" as="xs:string" select="'the attribute dof'"/>

  <!-- what $device declares as its degrees of freedom, the one that
       counts first: maps { 'dof': the number, 'source': where it is
       written } from its Robot tag dof, the movable joints of its URDF
       chain, the default of its attribute dof (each when given) -->
  <xsl:function name="fp:declared-dofs" as="map(*)*">
    <xsl:param name="device" as="element()"/>
    <xsl:variable name="tag" as="xs:string?" select="fp:dof-tag($device)"/>
    <xsl:variable name="attribute" as="xs:string?"
        select="(fp:attributes($device)[@name eq 'dof']/@default ! normalize-space(.))[. castable as xs:integer][1]"/>
    <xsl:sequence select="
        $tag[fp:is-dof(.)] ! map { 'dof': xs:integer(.), 'source': 'the Robot tag dof' },
        $device/pim:kinematic-chain ! map { 'dof': xs:integer(@dof), 'source': fp:chain-label(.) },
        $attribute ! map { 'dof': xs:integer(.), 'source': $fp:dof-attribute }"/>
  </xsl:function>

  <!-- "the movable joints of URDF file 'arm.urdf' from link 'base' to link 'tool'" -->
  <xsl:function name="fp:chain-label" as="xs:string">
    <xsl:param name="chain" as="element(pim:kinematic-chain)"/>
    <xsl:sequence select="string-join(('the movable joints of URDF file ''' || $chain/@urdf || '''',
                                       $chain/@root-link ! ('from link ''' || . || ''''),
                                       $chain/@tip-link ! ('to link ''' || . || '''')), ' ')"/>
  </xsl:function>

  <!-- the Robot tag dof of $device as written, () when not given -->
  <xsl:function name="fp:dof-tag" as="xs:string?">
    <xsl:param name="device" as="element()"/>
    <xsl:sequence select="fp:tag($device, 'Robot', 'dof') ! normalize-space(.)[. ne '']"/>
  </xsl:function>

  <xsl:function name="fp:is-dof" as="xs:boolean">
    <xsl:param name="value" as="xs:string"/>
    <xsl:sequence select="matches($value, '^\+?[0-9]+$')"/>
  </xsl:function>

  <!-- every robot Device (Robot stereotype): BND010 for each tag dof that
       is no number of degrees of freedom (all at once), then BND023 for
       each that declares different numbers -->
  <xsl:function name="fp:check-devices" as="empty-sequence()">
    <xsl:param name="root" as="document-node()"/>
    <xsl:variable name="robots" as="element(pim:node)*"
        select="$root/pim:model/pim:platform//pim:node[@kind eq 'device'][exists(f:stereotype(., 'Robot'))]"/>
    <xsl:sequence select="f:fail-all($robots[fp:dof-tag(.)[not(fp:is-dof(.))]] ! map { 'code': 'BND010',
        'id': string(f:stereotype(., 'Robot')/@id), 'message': 'the Robot tag dof of device ''' || @name || ''': '''
        || fp:dof-tag(.) || ''' is not a number of degrees of freedom (a non-negative integer)' })"/>
    <xsl:for-each select="$robots">
      <xsl:variable name="dofs" as="map(*)*" select="fp:declared-dofs(.)"/>
      <xsl:if test="count(distinct-values($dofs ! ?dof)) gt 1">
        <xsl:sequence select="f:warn('BND023', string(f:stereotype(., 'Robot')/@id), 'device ''' || @name
            || ''' declares its degrees of freedom ' || (if (count($dofs) eq 2) then 'twice' else 'three times')
            || ', differently: ' || string-join($dofs ! (?dof || ' (' || ?source || ')'), ', ')
            || '; robomda checks against ' || $dofs[1]?dof || ', ' || $dofs[1]?source)"/>
      </xsl:if>
    </xsl:for-each>
  </xsl:function>

  <!-- ================================================= DoF mismatch -->
  <xsl:function name="fp:warn-dof" as="empty-sequence()">
    <xsl:param name="root" as="document-node()"/>
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:param name="bound" as="element(pim:bound-component)*"/>
    <xsl:param name="connections" as="element(pim:connection)*"/>
    <xsl:for-each select="$root//pim:dependency[@kind eq 'drives']">
      <xsl:variable name="drives" as="element(pim:dependency)" select="."/>
      <xsl:for-each select="pim:supplier ! key('fp:id', @element, $root)">
        <xsl:variable name="device" as="element()" select="."/>
        <xsl:variable name="dof" as="map(*)?" select="fp:declared-dofs($device)[1]"/>
        <xsl:variable name="drivers" as="element(pim:instance)*"
            select="$instances[@xmi-id = $drives/pim:client/@element or @component = $drives/pim:client/@element]"/>
        <xsl:variable name="linked" as="element(pim:instance)*"
            select="$instances[@name = $connections[(pim:writer | pim:reader)/@instance = $drivers/@name]
                                                   /(pim:writer | pim:reader)/@instance]"/>
        <xsl:choose>
          <xsl:when test="empty($dof)">
            <xsl:sequence select="f:warn('BND022', string($device/@id), 'device ''' || $device/@name
                || ''' is driven by ' || string-join($drivers/@name, ', ')
                || ' but declares no degrees of freedom (a Robot tag dof or urdf, or an attribute dof with an integer default):'
                || ' nothing is checked')"/>
          </xsl:when>
          <xsl:otherwise>
            <xsl:sequence select="fp:dof-mismatches($root, $device, $dof, ($drivers | $linked), $bound,
                                                    string-join($drivers/@name, ', '))"/>
          </xsl:otherwise>
        </xsl:choose>
      </xsl:for-each>
    </xsl:for-each>
  </xsl:function>

  <!-- BND021 for each array of $instances' components whose fixed size is
       not the degrees of freedom $declared (of fp:declared-dofs): on the
       element, and on the device -->
  <xsl:function name="fp:dof-mismatches" as="empty-sequence()">
    <xsl:param name="root" as="document-node()"/>
    <xsl:param name="device" as="element()"/>
    <xsl:param name="declared" as="map(*)"/>
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:param name="bound" as="element(pim:bound-component)*"/>
    <xsl:param name="drivers" as="xs:string"/>
    <xsl:variable name="dof" as="xs:integer" select="$declared?dof"/>
    <!-- " has 6 degrees of freedom", with where the number comes from
         unless it is the attribute dof -->
    <xsl:variable name="has" as="xs:string" select="' has ' || $dof || ' degrees of freedom'
        || (if ($declared?source eq $fp:dof-attribute) then '' else ' (' || $declared?source || ')')"/>
    <xsl:variable name="components" as="element(pim:bound-component)*" select="$bound[@component = $instances/@component]"/>
    <xsl:variable name="arrays" as="element()*">
      <xsl:for-each select="$components">
        <xsl:variable name="users" as="xs:string" select="string-join($instances[@component eq current()/@component]/@name, ', ')"/>
        <xsl:for-each select="pim:data-port">
          <xsl:sequence select="fp:fixed-arrays(., 'port ''' || @port-name || ''' of ' || $users, @port, $root)"/>
        </xsl:for-each>
        <xsl:for-each select="fp:attributes(fp:feature-owner(key('fp:id', @component, $root)))[@visibility ne 'private']">
          <xsl:sequence select="fp:fixed-arrays(., 'attribute ''' || @name || ''' of ' || $users, @id, $root)"/>
        </xsl:for-each>
      </xsl:for-each>
    </xsl:variable>
    <!-- the arrays in the order they were made: current-group() ! ..., not
         a path, which would sort separately constructed nodes -->
    <xsl:for-each-group select="$arrays[xs:integer(@size) ne $dof]" group-by="@id">
      <xsl:variable name="what" as="xs:string"
          select="@what || ' holds ' || string-join(current-group() ! string(@label), ', ') || ' ('
                  || string-join(distinct-values(current-group() ! string(@size)), ', ') || ' values)'"/>
      <xsl:sequence select="f:warn('BND021', string(@id), $what || ', but device ''' || $device/@name || ''' (driven by '
                                   || $drivers || ')' || $has || ' (DoF mismatch)')"/>
      <xsl:sequence select="f:warn('BND021', string($device/@id), 'device ''' || $device/@name || ''' (driven by ' || $drivers
                                   || ')' || $has || ', but ' || $what || ' (DoF mismatch)')"/>
    </xsl:for-each-group>
  </xsl:function>

  <!-- the fixed-size arrays a typed element holds: itself, and the
       attributes of its data type at any depth; fp:array elements with
       @id (where to warn), @what, @label and @size -->
  <xsl:function name="fp:fixed-arrays" as="element()*">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:param name="root" as="document-node()"/>
    <xsl:variable name="own" as="xs:string*" select="fp:array($typed)"/>
    <xsl:if test="$own[1] eq 'fixed'">
      <fp:array id="{$id}" what="{$what}" label="{($typed/@type-name, $typed/@primitive)[1]}[{$own[2]}]" size="{$own[2]}"/>
    </xsl:if>
    <xsl:for-each select="fp:type-closure(key('fp:id', $typed/@type, $root)/self::pim:datatype)/self::pim:datatype">
      <xsl:variable name="type" as="element(pim:datatype)" select="."/>
      <xsl:for-each select="fp:attributes(.)">
        <xsl:variable name="array" as="xs:string*" select="fp:array(.)"/>
        <xsl:if test="$array[1] eq 'fixed'">
          <fp:array id="{$id}" what="{$what}" label="{$type/@name}.{@name}[{$array[2]}]" size="{$array[2]}"/>
        </xsl:if>
      </xsl:for-each>
    </xsl:for-each>
  </xsl:function>
</xsl:stylesheet>
