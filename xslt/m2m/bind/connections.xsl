<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/bind/connections.xsl - bind (xslt/m2m/bind.xsl): connection points from assembly connectors or shared interfaces, with their policies.

  Reads:   the PIM (urn:robomda:pim:1) and the working trees of fp:binding.
  Writes:  parts of pim:binding (schemas/pim/1/binding.xsd), or values.
  Params:  none.  Keys: those of bind.xsl.
  Provides: fp:policy, fp:policy-of, fp:connection-name, fp:connections-from-interfaces,
           fp:connections-from-connectors.
  Warnings: BND031 a connector joining a port that carries nothing robomda generates, left out.
  Errors:  BND007 a connector that joins nothing, BND008 an input fed twice (raised together;
           not by writers no job runs together: bind/jobs.xsl, fp:job-mates).
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

  <!-- ==================================================== connections -->
  <!-- the policy of a connection that no ConnectionPolicy stereotype
       configures; its attributes are also the value of each tag a
       stereotype leaves out -->
  <xsl:variable name="fp:default-policy" as="element(pim:policy)">
    <pim:policy type="DATA" size="1" lock-policy="LOCK_FREE" init="false" pull="false" topic="" source="default"/>
  </xsl:variable>

  <xsl:function name="fp:policy" as="element(pim:policy)">
    <xsl:param name="candidates" as="element()*"/>
    <xsl:variable name="element" as="element()?"
        select="$candidates[exists(f:stereotype(., 'ConnectionPolicy')) or self::pim:port[@buffer]][1]"/>
    <xsl:sequence select="if ($element/self::pim:port[@buffer] and empty(f:stereotype($element, 'ConnectionPolicy')))
                          then fp:dialect-buffer-policy($element)
                          else if (exists($element)) then fp:policy-of($element)
                          else if (exists($candidates[exists(f:stereotype(., 'Constant'))])) then $fp:constant-policy
                          else if (exists($candidates[fp:is-message-set(.)])) then fp:message-policy($candidates[fp:is-message-set(.)][1])
                          else $fp:default-policy"/>
  </xsl:function>

  <!-- the policy of a connection of UML-RT messages that no
       ConnectionPolicy configures: a queue, since a message must not be
       dropped (its size: the dialect's, xslt/import/dialects.xml) -->
  <xsl:function name="fp:message-policy" as="element(pim:policy)">
    <xsl:param name="interface" as="element(pim:interface)"/>
    <pim:policy type="BUFFER" size="{$fp:message-queue}" lock-policy="LOCK_FREE" init="false" pull="false" topic=""
        source="interface" source-element="{$interface/@id}" holder="{$interface/@id}"/>
  </xsl:function>
  <xsl:variable name="fp:message-queue" as="xs:integer"
      select="xs:integer((doc('../../import/dialects.xml')//*:messages/@size)[1])"/>

  <!-- the policy of a port whose tool's profile gives it a buffer size
       (RobotML DataFlowPort bufferSize, pim:port/@buffer): a queue of that
       size; 1 is the default policy's one sample -->
  <xsl:function name="fp:dialect-buffer-policy" as="element(pim:policy)">
    <xsl:param name="port" as="element(pim:port)"/>
    <xsl:variable name="size" as="xs:integer"
        select="fp:integer($port/@buffer, 'bufferSize of port ''' || $port/@name || '''', $port/@id)"/>
    <pim:policy type="{if ($size gt 1) then 'BUFFER' else 'DATA'}" size="{max((1, $size))}"
        lock-policy="{$fp:default-policy/@lock-policy}" init="false" pull="false" topic=""
        source="port" source-element="{$port/@id}" holder="{$port/@id}"/>
  </xsl:function>

  <!-- the policy of a connection that carries a configuration constant
       («Constant» on a port or the interface, seed 004) and that no
       ConnectionPolicy configures: init, so that a reader connected after
       the one write still gets it (Orocos ConnPolicy init, a latched ROS 1
       topic, transient-local ROS 2 durability) -->
  <xsl:variable name="fp:constant-policy" as="element(pim:policy)">
    <pim:policy type="DATA" size="1" lock-policy="LOCK_FREE" init="true" pull="false" topic="" source="constant"/>
  </xsl:variable>

  <!-- the policy given by the ConnectionPolicy stereotype of $e -->
  <xsl:function name="fp:policy-of" as="element(pim:policy)">
    <xsl:param name="element" as="element()"/>
    <!-- the stereotype application holds the values: errors point at it -->
    <xsl:variable name="id" as="xs:string?" select="(f:stereotype($element, 'ConnectionPolicy')/@id, $element/@id)[1]"/>
    <xsl:variable name="default" as="element(pim:policy)" select="$fp:default-policy"/>
    <xsl:variable name="type" as="xs:string"
        select="fp:enum((fp:tag($element, 'ConnectionPolicy', 'type')[normalize-space(.)], $default/@type)[1],
                        ('DATA', 'BUFFER', 'CIRCULAR_BUFFER'), 'connection type', $id)"/>
    <pim:policy type="{$type}"
        size="{let $s := fp:tag($element, 'ConnectionPolicy', 'size')[normalize-space(.)]
               return if (exists($s)) then fp:integer($s, 'size', $id) else $default/@size}"
        lock-policy="{fp:enum((fp:tag($element, 'ConnectionPolicy', 'lockPolicy')[normalize-space(.)], $default/@lock-policy)[1],
                             ('UNSYNC', 'LOCKED', 'LOCK_FREE'), 'lock policy', $id)}"
        init="{fp:boolean((fp:tag($element, 'ConnectionPolicy', 'init')[normalize-space(.)], $default/@init)[1], 'init', $id)}"
        pull="{fp:boolean((fp:tag($element, 'ConnectionPolicy', 'pull')[normalize-space(.)], $default/@pull)[1], 'pull', $id)}"
        topic="{fp:tag($element, 'ConnectionPolicy', 'topic')}"
        source="{if ($element/self::pim:connector) then 'connector'
                 else if ($element/self::pim:port) then 'port' else 'interface'}"
        source-element="{$element/@id}" holder="{$id}"/>
  </xsl:function>

  <xsl:function name="fp:connection-name" as="xs:string">
    <xsl:param name="connector" as="element(pim:connector)?"/>
    <xsl:param name="interface" as="element()"/>
    <xsl:sequence select="if (normalize-space($connector/@name)) then f:cpp-identifier($connector/@name)
                          else f:cpp-identifier($interface/@name || 'Conn')"/>
  </xsl:function>

  <!-- ball-and-socket: one connection point per interface -->
  <xsl:function name="fp:connections-from-interfaces" as="element(pim:connection)*">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:param name="work" as="document-node()"/>
    <xsl:variable name="root" as="document-node()" select="root($model[1])"/>
    <xsl:for-each select="$model/pim:application//pim:interface">
      <xsl:variable name="interface" as="element(pim:interface)" select="."/>
      <!-- a UML-RT message set: one connection point per message; a
           service port's point is a call's (services.xsl), never data -->
      <xsl:for-each-group select="key('fp:ip-by-interface', @id, $work)[not(@kind eq 'service')]" group-by="string(@message)">
        <xsl:variable name="writer" as="element(fp:ip)*" select="current-group()[@direction eq 'out']"/>
        <xsl:variable name="realization" as="element(fp:ip)*" select="current-group()[@direction eq 'in']"/>
        <xsl:if test="exists($writer) and exists($realization)">
          <xsl:variable name="message" as="element()?" select="key('fp:id', current-grouping-key(), $root)"/>
          <pim:connection name="{if ($message) then f:cpp-identifier($interface/@name || '_' || $message/@name)
                                 else fp:connection-name((), $interface)}"
              xmi-id="{($message/@id, $interface/@id)[1]}" interface="{$interface/@id}">
            <xsl:sequence select="fp:policy((key('fp:id', ($writer, $realization)/@port, $root), $interface))"/>
            <xsl:for-each select="$writer"><pim:writer instance="{@instance}" port="{@port}" data-port="{@data-port}"/></xsl:for-each>
            <xsl:for-each select="$realization"><pim:reader instance="{@instance}" port="{@port}" data-port="{@data-port}"/></xsl:for-each>
          </pim:connection>
        </xsl:if>
      </xsl:for-each-group>
    </xsl:for-each>
  </xsl:function>

  <!-- connector mode: writer->reader pairs grouped by writer port. $uses:
       each assembly connector with the path of the composite it is drawn
       in (bind/composites.xsl); its ends resolve through delegations -->
  <xsl:function name="fp:connections-from-connectors" as="element(pim:connection)*">
    <xsl:param name="root" as="document-node()"/>
    <xsl:param name="uses" as="element(fp:use)*"/>
    <!-- fp:connector-pairs of $uses -->
    <xsl:param name="resolved" as="element()*"/>
    <xsl:variable name="pairs" as="element(fp:pair)*" select="$resolved/self::fp:pair"/>
    <xsl:variable name="mates" as="map(xs:string, xs:string*)" select="fp:job-mates($root)"/>
    <!-- the connectors that join something, as a set (one look-up per connector) -->
    <xsl:variable name="joining" as="map(xs:string, xs:boolean)"
        select="map:merge(distinct-values(($pairs, $resolved/(self::fp:unresolved | self::fp:call-pair))/@connector ! string(.))
                          ! map:entry(., true()))"/>
    <!-- the connectors that join a port carrying nothing robomda
         generates: left out with warning BND031, never BND007 -->
    <xsl:variable name="left-out" as="map(xs:string, xs:string)"
        select="map:merge($resolved/self::fp:left-out[not(map:contains($joining, string(@connector)))]
                          ! map:entry(string(@connector), string(@port)), map { 'duplicates': 'use-first' })"/>
    <xsl:for-each select="map:keys($left-out) ! key('fp:id', ., $root)">
      <xsl:sort select="@id"/>
      <xsl:variable name="port" as="element()?" select="key('fp:id', $left-out(string(current()/@id)), $root)"/>
      <xsl:sequence select="f:warn('BND031', string(@id), 'connector ''' || @name || ''' is left out: it joins port '''
          || $port/@name || ''' of ' || $port/../@name || ', which carries nothing robomda generates ('
          || string-join(pim:end ! fp:end-data($root, .), ', ') || '); the warnings about that port say what to add')"/>
    </xsl:for-each>
    <!-- every promoted port delegated to nothing, every connector that
         joins nothing and every input fed twice, at once -->
    <xsl:variable name="problems" as="map(*)*">
      <xsl:for-each-group select="$resolved/self::fp:unresolved" group-by="@message">
        <xsl:sequence select="map { 'code': 'BND014', 'id': string(@connector), 'message': string(@message) }"/>
      </xsl:for-each-group>
      <xsl:for-each select="key('fp:id', distinct-values($uses/@connector), $root)
                            [not(map:contains($joining, string(@id)))]
                            [not(map:contains($left-out, string(@id)))]">
        <xsl:sequence select="map { 'code': 'BND007', 'id': string(@id), 'message': 'connector ''' || @name
            || ''' joins no output port to an input port of the same data type ('
            || string-join(pim:end ! fp:end-data($root, .), ', ') || ')' }"/>
      </xsl:for-each>
      <xsl:for-each-group select="$pairs" group-by="@r-instance || '.' || @r-dp">
        <!-- writers no job runs together (seed 004's swap of a source between jobs) are no conflict -->
        <xsl:variable name="writers" as="xs:string*" select="distinct-values(current-group()/@w-instance)"/>
        <xsl:if test="count(distinct-values(current-group()/(@w-instance || '.' || @w-dp))) gt 1
                      and (some $a in $writers, $b in $writers[. ne $a] satisfies
                           (empty($mates($a)) or empty($mates($b)) or $mates($a) = $mates($b)))">
          <xsl:sequence select="map { 'code': 'BND008', 'id': string(current-group()[1]/@r-port),
              'message': 'input port ' || current-grouping-key() || ' is fed by several output ports ('
              || string-join(distinct-values(current-group()/(@w-instance || '.' || @w-dp)), ', ') || ')' }"/>
        </xsl:if>
      </xsl:for-each-group>
    </xsl:variable>
    <xsl:sequence select="f:fail-all($problems)"/>
    <xsl:for-each-group select="$pairs" group-by="@w-instance || '.' || @w-dp">
      <xsl:variable name="group" as="element(fp:pair)+" select="current-group()"/>
      <xsl:variable name="ks" as="element(pim:connector)*"
          select="key('fp:id', distinct-values($group/@connector), $root)"/>
      <!-- an interface, or the data type (the port, for a library primitive) a port is typed by -->
      <xsl:variable name="iface" as="element()" select="key('fp:id', $group[1]/@interface, $root)"/>
      <!-- a connector inside a composite part: named after the part's path too -->
      <xsl:variable name="prefix" as="xs:string" select="$group[@connector eq $ks[1]/@id][1]/@prefix"/>
      <pim:connection name="{if ($prefix eq '') then fp:connection-name($ks[1], $iface)
                             else f:cpp-identifier($prefix || '_' || fp:connection-name($ks[1], $iface))}"
                      xmi-id="{$ks[1]/@id}" interface="{$iface/@id}" connectors="{$ks/@id}">
        <xsl:sequence select="fp:policy(($ks, key('fp:id', ($group[1]/@w-port, $group/@r-port), $root), $iface))"/>
        <pim:writer instance="{$group[1]/@w-instance}" port="{$group[1]/@w-port}" data-port="{$group[1]/@w-dp}"/>
        <xsl:for-each-group select="$group" group-by="@r-instance || '.' || @r-dp">
          <pim:reader instance="{@r-instance}" port="{@r-port}" data-port="{@r-dp}"/>
        </xsl:for-each-group>
      </pim:connection>
    </xsl:for-each-group>
  </xsl:function>

  <!-- "part.port: Type[7]" for a connector end, the data its port carries
       (the datum of each interface it is typed by, or its own type), for
       BND007 -->
  <xsl:function name="fp:end-data" as="xs:string">
    <xsl:param name="root" as="document-node()"/>
    <xsl:param name="end" as="element()"/>
    <xsl:variable name="port" as="element()?" select="key('fp:id', $end/@role, $root)"/>
    <xsl:variable name="interfaces" as="element()*"
        select="($port/@type, $port/(pim:provided | pim:required)/@interface) ! key('fp:id', ., $root)/self::pim:interface"/>
    <xsl:variable name="data" as="element()*" select="if (exists($interfaces)) then $interfaces/pim:attribute else $port"/>
    <xsl:variable name="labels" as="xs:string*"
        select="distinct-values($data ! (string((@type-name, @primitive, '?')[1]) || fp:multiplicity-label(.)))"/>
    <xsl:sequence select="string-join(((if ($end/@path) then tokenize($end/@path) else $end/@part) ! key('fp:id', ., $root)/@name,
                                       $port/@name), '.') || ': '
        || (if (empty($labels)) then 'no data' else string-join($labels, ' / '))"/>
  </xsl:function>

  <!-- the writer -> reader pairs (fp:pair) of each use of an assembly
       connector, and an fp:unresolved for each end on a promoted port that
       is delegated to nothing -->
  <xsl:function name="fp:connector-pairs" as="element()*">
    <xsl:param name="root" as="document-node()"/>
    <xsl:param name="uses" as="element(fp:use)*"/>
    <xsl:param name="work" as="document-node()"/>
    <xsl:for-each select="$uses">
      <xsl:variable name="use" as="element(fp:use)" select="."/>
      <xsl:variable name="prefix" as="xs:string" select="translate(@path, '.', '_')"/>
      <xsl:variable name="connection" as="element(pim:connector)" select="key('fp:id', @connector, $root)"/>
      <xsl:variable name="targets" as="element()*"
          select="$connection/pim:end[@part] ! fp:end-targets(., tokenize($use/@path, '\.'))"/>
      <xsl:sequence select="$targets/self::fp:unresolved"/>
      <xsl:variable name="ips" as="element(fp:ip)*"
          select="$targets/self::fp:target ! key('fp:ip-by-end', @instance || '|' || @port, $work)"/>
      <!-- an end on a port that carries nothing robomda generates (no data
           port, no service port: its interface has no datum, BND004, or is
           not in the model) leaves the connector out, with a warning -->
      <xsl:for-each select="$targets/self::fp:target[empty(key('fp:ip-by-end', @instance || '|' || @port, $work))][1]">
        <fp:left-out connector="{$connection/@id}" port="{@port}"/>
      </xsl:for-each>
      <xsl:sequence select="fp:call-pairs($connection, $prefix, $ips)"/>
      <xsl:for-each select="$ips[not(@kind)][@direction eq 'out']">
        <xsl:variable name="wr" as="element(fp:ip)" select="."/>
        <xsl:for-each select="$ips[not(@kind)][@direction eq 'in'][@instance ne $wr/@instance or @port ne $wr/@port]
                                  [if (@message or $wr/@message) then @message eq $wr/@message
                                   else (@interface eq $wr/@interface or @type-key eq $wr/@type-key)]">
          <fp:pair connector="{$connection/@id}" prefix="{$prefix}" interface="{$wr/@interface}"
                   w-instance="{$wr/@instance}" w-port="{$wr/@port}" w-dp="{$wr/@data-port}"
                   r-instance="{@instance}" r-port="{@port}" r-dp="{@data-port}"/>
        </xsl:for-each>
      </xsl:for-each>
    </xsl:for-each>
  </xsl:function>
</xsl:stylesheet>
