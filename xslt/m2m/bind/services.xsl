<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/bind/services.xsl - bind (xslt/m2m/bind.xsl): operation calls
  between components (seed 003: operations and operation callers joined by
  peer connections).

  Reads:   the PIM (urn:robomda:pim:1) and the working trees of fp:binding.
  Writes:  pim:service-port (in pim:bound-component), pim:call (in
           pim:binding; schemas/pim/1/binding.xsd), or maps for f:fail-all.
  Params:  none.  Keys: those of bind.xsl.
  Provides: fp:is-service-interface, fp:service-ports, fp:operation-signature,
           fp:conformance-problems, fp:call-pairs, fp:calls-from-pairs,
           fp:calls-from-interfaces.

  A service interface carries operations and no datum. A port typed by one
  (or providing / requiring one) is a service port: provided where the
  component provides the interface (InterfaceRealization), required where
  it requires it (Usage), by the rules of data ports (fp:port-interfaces).
  The provider implements each operation of the interface (its realizing
  class, else the component, has an operation of the same name and
  signature); the caller calls them. An assembly connector (resolved
  through delegations, bind/composites.xsl) from a required to a provided
  service port of the same interface is a call: the caller's operations
  are bound to the provider's. Without connectors, a required service port
  is bound to the one instance that provides the interface.

  Errors (codes of bind.xsl): BND019 a required service port bound to
  several providers; BND020 a provider that does not implement an
  operation of its interface, or a caller that declares one with another
  signature.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:is-service-interface" as="xs:boolean">
    <xsl:param name="interface" as="element()?"/>
    <xsl:sequence select="exists($interface/self::pim:interface/pim:operation) and empty($interface/pim:attribute)"/>
  </xsl:function>

  <!-- the service ports of port $port: one per service interface it
       provides or requires -->
  <xsl:function name="fp:service-ports" as="element(pim:service-port)*">
    <xsl:param name="port" as="element(pim:port)"/>
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:param name="realization" as="element(pim:class)?"/>
    <xsl:variable name="root" as="document-node()" select="root($port)"/>
    <xsl:variable name="pairs" as="xs:string*" select="fp:port-interfaces($port, $component, $realization)"/>
    <xsl:for-each select="1 to count($pairs) idiv 2">
      <xsl:variable name="interface" as="element()?" select="key('fp:id', $pairs[2 * current() - 1], $root)"/>
      <xsl:if test="fp:is-service-interface($interface)">
        <pim:service-port port="{$port/@id}"
            name="{fp:sub-port-name($port, $interface, count($pairs) idiv 2)}"
            port-name="{$port/@name}" interface="{$interface/@id}" interface-name="{$interface/@name}"
            role="{if ($pairs[2 * current()] eq 'out') then 'provided' else 'required'}"/>
      </xsl:if>
    </xsl:for-each>
  </xsl:function>

  <!-- an operation's name and signature: name(direction type, ...) result -->
  <xsl:function name="fp:operation-signature" as="xs:string">
    <xsl:param name="operation" as="element(pim:operation)"/>
    <xsl:sequence select="$operation/@name || '(' || string-join($operation/pim:parameter[@direction ne 'return']
                            ! (@direction || ' ' || fp:type-key(.)), ', ') || ') '
                          || (($operation/pim:parameter[@direction eq 'return'])[1] ! fp:type-key(.), 'void')[1]"/>
  </xsl:function>

  <xsl:function name="fp:type-key" as="xs:string">
    <xsl:param name="typed" as="element()"/>
    <xsl:sequence select="string(($typed/@primitive, $typed/@type-name, $typed/@type, '?')[1])"/>
  </xsl:function>

  <!-- BND020 for each operation of a service interface that a provider
       does not implement with its signature, or that a caller declares
       with another one -->
  <xsl:function name="fp:conformance-problems" as="map(*)*">
    <xsl:param name="model-root" as="document-node()"/>
    <xsl:param name="bound" as="element(pim:bound-component)*"/>
    <xsl:for-each select="$bound/pim:service-port">
      <xsl:variable name="service" as="element(pim:service-port)" select="."/>
      <xsl:variable name="component" as="element(pim:component)" select="key('fp:id', ../@component, $model-root)"/>
      <xsl:variable name="owner" as="element()" select="fp:feature-owner($component)"/>
      <xsl:for-each select="key('fp:id', @interface, $model-root)/pim:operation">
        <xsl:variable name="want" as="xs:string" select="fp:operation-signature(.)"/>
        <xsl:variable name="have" as="element(pim:operation)*" select="fp:operations($owner)[@name eq current()/@name]"/>
        <xsl:if test="if ($service/@role eq 'provided') then not($have ! fp:operation-signature(.) = $want)
                      else exists($have) and not($have ! fp:operation-signature(.) = $want)">
          <xsl:sequence select="map { 'code': 'BND020', 'id': string(($have/@id, $service/@port)[1]), 'message':
              'component ''' || $component/@name || ''' ' || (if ($service/@role eq 'provided') then 'provides' else 'requires')
              || ' interface ''' || $service/@interface-name
              || ''' (port ''' || $service/@port-name || '''), whose operation is ' || $want || ', but '
              || local-name($owner) || ' ''' || $owner/@name || ''' '
              || (if (empty($have)) then 'has no operation ' || @name
                  else 'declares ' || string-join($have ! fp:operation-signature(.), ' and '))
              || ': a provider implements the operations of its interface, a caller calls them, with one signature' }"/>
        </xsl:if>
      </xsl:for-each>
    </xsl:for-each>
  </xsl:function>

  <!-- the calls one use of an assembly connector makes: each required
       service port it reaches with each provided one of the same interface
       ($ips: the ports the connector's ends resolve to) -->
  <xsl:function name="fp:call-pairs" as="element(fp:call-pair)*">
    <xsl:param name="connector" as="element(pim:connector)"/>
    <xsl:param name="prefix" as="xs:string"/>
    <xsl:param name="ips" as="element(fp:ip)*"/>
    <xsl:for-each select="$ips[@kind eq 'service'][@direction eq 'in']">
      <xsl:variable name="caller" as="element(fp:ip)" select="."/>
      <xsl:for-each select="$ips[@kind eq 'service'][@direction eq 'out'][@interface eq $caller/@interface]">
        <fp:call-pair connector="{$connector/@id}" prefix="{$prefix}" interface="{@interface}"
            c-instance="{$caller/@instance}" c-port="{$caller/@port}" c-sp="{$caller/@data-port}"
            p-instance="{@instance}" p-port="{@port}" p-sp="{@data-port}"/>
      </xsl:for-each>
    </xsl:for-each>
  </xsl:function>

  <!-- one pim:call per required service port of an instance that the
       pairs bind; BND019 for one bound to several providers -->
  <xsl:function name="fp:calls-from-pairs" as="element(pim:call)*">
    <xsl:param name="root" as="document-node()"/>
    <xsl:param name="pairs" as="element(fp:call-pair)*"/>
    <xsl:variable name="groups" as="element(fp:call-pair)*">
      <xsl:for-each-group select="$pairs" group-by="@c-instance || '.' || @c-sp">
        <fp:call-pair>
          <xsl:sequence select="@*, current-group()"/>
        </fp:call-pair>
      </xsl:for-each-group>
    </xsl:variable>
    <xsl:sequence select="f:fail-all($groups[count(distinct-values(fp:call-pair/(@p-instance || '.' || @p-sp))) gt 1]
        ! map { 'code': 'BND019', 'id': string(@c-port), 'message': 'required interface ' || @c-instance || '.' || @c-sp
                || ' is bound to several providers (' || string-join(distinct-values(fp:call-pair/(@p-instance || '.' || @p-sp)), ', ')
                || '): a caller calls one provider' })"/>
    <xsl:for-each select="$groups">
      <xsl:variable name="connectors" as="element(pim:connector)*" select="key('fp:id', distinct-values(fp:call-pair/@connector), $root)"/>
      <xsl:sequence select="fp:call(@prefix, $connectors, key('fp:id', @interface, $root), .)"/>
    </xsl:for-each>
  </xsl:function>

  <!-- without connectors: each required service port bound to the one
       instance that provides its interface (none: unbound; several: BND019) -->
  <xsl:function name="fp:calls-from-interfaces" as="element(pim:call)*">
    <xsl:param name="root" as="document-node()"/>
    <xsl:param name="work" as="document-node()"/>
    <xsl:variable name="groups" as="element(fp:call-pair)*">
      <xsl:for-each select="$work//fp:ip[@kind eq 'service'][@direction eq 'in']">
        <xsl:variable name="caller" as="element(fp:ip)" select="."/>
        <xsl:variable name="providers" as="element(fp:ip)*"
            select="key('fp:ip-by-interface', @interface, $work)[@kind eq 'service'][@direction eq 'out']"/>
        <xsl:if test="exists($providers)">
          <fp:call-pair prefix="" interface="{@interface}" c-instance="{@instance}" c-port="{@port}" c-sp="{@data-port}">
            <xsl:for-each select="$providers">
              <fp:call-pair p-instance="{@instance}" p-port="{@port}" p-sp="{@data-port}"/>
            </xsl:for-each>
          </fp:call-pair>
        </xsl:if>
      </xsl:for-each>
    </xsl:variable>
    <xsl:sequence select="f:fail-all($groups[count(fp:call-pair) gt 1]
        ! map { 'code': 'BND019', 'id': string(@c-port), 'message': 'required interface ' || @c-instance || '.' || @c-sp
                || ' can be bound to several providers of ''' || key('fp:id', @interface, $root)/@name || ''' ('
                || string-join(fp:call-pair/(@p-instance || '.' || @p-sp), ', ') || '): draw the connector to the one it calls' })"/>
    <xsl:for-each select="$groups">
      <xsl:sequence select="fp:call('', (), key('fp:id', @interface, $root), .)"/>
    </xsl:for-each>
  </xsl:function>

  <xsl:function name="fp:call" as="element(pim:call)">
    <xsl:param name="prefix" as="xs:string"/>
    <xsl:param name="connectors" as="element(pim:connector)*"/>
    <xsl:param name="interface" as="element(pim:interface)"/>
    <xsl:param name="group" as="element(fp:call-pair)"/>
    <xsl:variable name="name" as="xs:string"
        select="if (normalize-space($connectors[1]/@name)) then f:cpp-identifier($connectors[1]/@name)
                else f:cpp-identifier($interface/@name || 'Call')"/>
    <xsl:variable name="provider" as="element(fp:call-pair)" select="$group/fp:call-pair[1]"/>
    <pim:call name="{if ($prefix eq '') then $name else f:cpp-identifier($prefix || '_' || $name)}"
              xmi-id="{($connectors[1]/@id, $interface/@id)[1]}" interface="{$interface/@id}">
      <xsl:if test="exists($connectors)"><xsl:attribute name="connectors" select="$connectors/@id"/></xsl:if>
      <pim:caller instance="{$group/@c-instance}" port="{$group/@c-port}" service-port="{$group/@c-sp}"/>
      <pim:provider instance="{$provider/@p-instance}" port="{$provider/@p-port}" service-port="{$provider/@p-sp}"/>
    </pim:call>
  </xsl:function>
</xsl:stylesheet>
