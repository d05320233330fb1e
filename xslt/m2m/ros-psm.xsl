<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/ros-psm.xsl - bound PIM -> ROS PSM (ROS 1 roscpp / ROS 2 rclcpp).

  Reads:   a bound PIM, urn:robomda:pim:1 with pim:binding (xslt/m2m/bind.xsl).
  Writes:  urn:robomda:psm-ros:1 (schemas/psm-ros/1/psm-ros.xsd),
           indented as f:indent (common/indent.xsl) indents it, through its
           rules (t:indented-content) in the same pass.
  Data:    xslt/m2m/ros-types.xml (type -> C++ type, message, parameter type),
           overridden entry by entry by the map the type-map parameter names.
  Params:  ros-version ('1' or '2'), package-name, type-map (see below).

  Rules (docs/ros.md)
  N1  one node class per component type with an instance (all instances,
      whatever their middleware: see W100): class UpperCamel(component),
      executable snake(component)_node; kind "wrapper" with a realizing
      class (the node class derives from it, as the Orocos target does),
      else "base" (a generated <Class>Base and a user <Class>).
  N2  data ports: out -> publisher, in -> subscription whose callback calls
      set<Datum>; the topic in the code is the port name, remapped per
      instance in the launch files to the connection's topic. Message type
      from the type map; a data type of primitives that no entry maps gets a
      generated msg/<Type>.msg.
  N3  services: the protected operations of the realizing class (base: of
      the component), except the lifecycle names, where a std_srvs service
      fits: no argument and no result -> std_srvs/Empty; no argument and a
      Boolean result -> std_srvs/Trigger; one Boolean argument -> std_srvs/
      SetBool. Any other operation is left out with warning ROS101.
  N4  parameters: the attributes R4 of the Orocos target selects
      (Configurable, else public/protected non-static non-read-only ones not
      named sample/priority/scheduler/cpuAffinity), with declared type and
      the model's default; plus update_period (the instance's period).
  N5  period -> timer (update(), then publish the outputs); period 0 ->
      data-driven (each received message runs update() and publishes).
  N6  connection -> topic: the policy's topic tag, else the connection name;
      policy -> queue depth (DATA 1, BUFFER / CIRCULAR_BUFFER its size),
      latch / durability transient_local when init is true, reliability
      reliable, history keep_last(depth). A port's QoS is taken from the
      first connection it is in (ROS sets QoS per publisher, not per link).
  N7  deployment: one package per model; hosts -> ROS 1 machines, one launch
      file per host (component set) plus a top-level one; ROS 2: one launch
      file per host (warning ROS102: no machine tag).

  Errors (urn:robomda:error, f:fail):
    ROS001  a port, service or Configurable parameter has a type the type
            map cannot map (names the element)
    ROS002  a parameter default is not valid for its type
    ROS003  the input has no pim:binding (run xslt/m2m/bind.xsl first)
    ROS004  two component types map to the same C++ class name
    ROS005  a ConnectionPolicy topic is not a valid ROS graph name
    ROS006  parameter ros-version is neither '1' nor '2'
    ROS007  a component with an instance has no realizing class (the ROS
            targets do not generate a user base class yet)
    ROS008  nothing to generate: the model has no component instance
  Warnings (f:warn):
    ROS100  instances deployed on an execution environment of another
            middleware are generated for ROS anyway (once per model)
    ROS101  operations with no fitting std_srvs service are left out (one
            warning per component type, naming them)
    ROS102  ROS 2 launch has no machine tag: one launch file per host
    ROS103  a port is in several connections: only the first one's topic
            and policy are used
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:ty="urn:robomda:ros-types:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:m="urn:robomda:xslt:mode"
    xmlns:t="urn:robomda:xslt:template"
    exclude-result-prefixes="#all">

  <xsl:include href="../common/errors.xsl"/>
  <xsl:include href="../common/indent.xsl"/>
  <xsl:include href="../common/naming.xsl"/>
  <xsl:include href="../common/profile.xsl"/>

  <xsl:param name="ros-version" as="xs:string" select="'1'">
    <!-- '1' (catkin / roscpp) or '2' (ament / rclcpp) -->
  </xsl:param>
  <xsl:param name="package-name" as="xs:string" select="''">
    <!-- the ROS package; '' = lower snake-case of the model name -->
  </xsl:param>
  <xsl:param name="type-map" as="xs:string" select="''">
    <!-- URI of an extra type map (format of xslt/m2m/ros-types.xml): absolute, or relative to the input; its entries win; '' = none -->
  </xsl:param>

  <xsl:output method="xml" indent="no" encoding="UTF-8"/>
  <xsl:mode name="m:to-psm" on-no-match="fail"/>

  <xsl:key name="fp:id" match="*[@id]" use="@id"/>
  <xsl:key name="fp:type-by-primitive" match="ty:type[@primitive]" use="@primitive"/>
  <xsl:key name="fp:type-by-name" match="ty:type[@type-name]" use="@type-name"/>
  <xsl:key name="fp:instance-of" match="pim:instance" use="@component"/>
  <xsl:key name="fp:host" match="pim:host" use="@xmi-id"/>
  <xsl:key name="fp:connection-by-end" match="pim:connection"
      use="(pim:writer | pim:reader) ! (@instance || '/' || @data-port)"/>
  <xsl:key name="fp:node" match="r:node" use="@xmi-id"/>

  <xsl:variable name="fp:builtin-types" as="document-node()" select="doc('ros-types.xml')"/>
  <xsl:variable name="fp:user-types" as="document-node()?"
      select="if (normalize-space($type-map)) then doc(resolve-uri($type-map, base-uri(/))) else ()"/>
  <xsl:variable name="fp:lifecycle" as="xs:string+" select="('configure', 'start', 'update', 'stop', 'cleanup')"/>
  <xsl:variable name="fp:convention-names" as="xs:string+" select="('sample', 'priority', 'scheduler', 'cpuAffinity')"/>
  <xsl:variable name="fp:target-middleware" as="xs:string" select="if ($ros-version eq '2') then 'ROS2' else 'ROS'"/>

  <!-- ================================================================ entry -->
  <xsl:template match="/" as="document-node()">
    <xsl:if test="not($ros-version = ('1', '2'))">
      <xsl:sequence select="f:fail('ROS006', '', 'parameter ros-version is ''' || $ros-version || ''': use ''1'' or ''2''')"/>
    </xsl:if>
    <!-- indented as f:indent (common/indent.xsl) would indent it, in one
         pass: r:package puts its children through f:indent's rules
         (t:indented-content), so the nodes, made once in a tree of their own, are
         not copied into an unindented result first -->
    <xsl:document>
      <xsl:apply-templates select="pim:model" mode="m:to-psm"/>
    </xsl:document>
  </xsl:template>

  <xsl:template match="pim:model[empty(pim:binding)]" mode="m:to-psm" as="empty-sequence()">
    <xsl:sequence select="f:fail('ROS003', @id, 'the model has no platform binding: run xslt/m2m/bind.xsl first')"/>
  </xsl:template>

  <xsl:template match="pim:model" mode="m:to-psm" as="element(r:package)">
    <xsl:variable name="b" as="element(pim:binding)" select="pim:binding"/>
    <xsl:variable name="pkg" as="xs:string"
        select="if (normalize-space($package-name)) then f:snake-case($package-name) else f:snake-case(@name)"/>
    <xsl:variable name="components" as="element(pim:bound-component)*"
        select="$b/pim:bound-component[exists(key('fp:instance-of', @component))]"/>
    <xsl:for-each-group select="$components" group-by="f:upper-camel(@name)">
      <xsl:if test="count(current-group()) gt 1">
        <xsl:sequence select="f:fail('ROS004', current-group()[2]/@component, 'components '''
            || string-join(current-group()/@name, ''', ''') || ''' all map to C++ class ' || current-grouping-key())"/>
      </xsl:if>
    </xsl:for-each-group>
    <xsl:if test="empty($b/pim:instance)">
      <xsl:sequence select="f:fail('ROS008', @id, 'nothing to generate: model ''' || @name
          || ''' has no component instance (a component with ports or a realizing class)')"/>
    </xsl:if>
    <xsl:variable name="other" as="element(pim:instance)*" select="$b/pim:instance[@middleware ne $fp:target-middleware]"/>
    <xsl:if test="exists($other)">
      <xsl:sequence select="f:warn('ROS100', $other[1]/@execution-environment, 'the platform model deploys instance(s) '''
          || string-join($other/@name, ''', ''') || ''' on ' || string-join(distinct-values($other/@middleware), ', ')
          || ', not ' || $fp:target-middleware || ': generated for ROS ' || $ros-version || ' anyway')"/>
    </xsl:if>
    <!-- fp:host-key of each host the instances name, made once per host -->
    <xsl:variable name="host-keys" as="map(xs:string, xs:string)"
        select="map:merge(distinct-values($b/pim:instance ! string(@host)) ! map:entry(., fp:host-key(., root($b))))"/>
    <xsl:variable name="hosts" as="element(r:host)*">
      <xsl:for-each-group select="$b/pim:instance" group-by="$host-keys(string(@host))">
        <xsl:variable name="h" as="element(pim:host)?" select="key('fp:host', string(current-group()[1]/@host))"/>
        <r:host xmi-id="{($h/@xmi-id, current-group()[1]/@execution-environment)[1]}"
                name="{current-grouping-key()}" machine="{current-grouping-key()}"
                hostname="{($h/@hostname, 'localhost')[1]}" address="{($h/@address, 'localhost')[1]}"
                launch="{current-grouping-key()}"/>
      </xsl:for-each-group>
    </xsl:variable>
    <xsl:if test="$ros-version eq '2' and count($hosts) gt 1">
      <xsl:sequence select="f:warn('ROS102', $hosts[2]/@xmi-id, 'ROS 2 launch has no machine tag: one launch file per host ('
          || string-join($hosts/@launch, ', ') || '), each to be started on its host')"/>
    </xsl:if>
    <xsl:variable name="nodes" as="document-node()">
      <xsl:document>
        <xsl:sequence select="$components ! fp:node(., $pkg, $b)"/>
      </xsl:document>
    </xsl:variable>
    <r:package xmi-id="{@id}" model-name="{@name}" name="{$pkg}" namespace="{$pkg}" ros-version="{$ros-version}"
               deploy-name="{f:snake-case(@name)}" source="{@source}">
      <xsl:variable name="children" as="element()*">
        <xsl:for-each select="$b/pim:library">
          <r:library xmi-id="{@xmi-id}" name="{@name}" path="{@path}" absolute="{@absolute}"
                     target="{@target}" include-dir="{@include-dir}"
                     cmake-var="{upper-case($pkg) || '_' || upper-case(f:snake-case(@name)) || '_DIR'}"
                     build-dir="{f:snake-case(@name) || '-build'}"/>
        </xsl:for-each>
        <xsl:for-each-group select="$nodes//r:message[@generated eq 'true']" group-by="@msg">
          <r:message-file name="{current-grouping-key()}" xmi-id="{@type}">
            <xsl:sequence select="r:field"/>
          </r:message-file>
        </xsl:for-each-group>
        <xsl:sequence select="$nodes/r:node"/>
        <xsl:sequence select="$hosts"/>
        <xsl:for-each select="$b/pim:connection">
          <xsl:variable name="topic" as="xs:string" select="(pim:policy/@topic[normalize-space(.)], @name)[1]"/>
          <xsl:if test="not(matches($topic, '^[~/]?[A-Za-z][A-Za-z0-9_]*(/[A-Za-z][A-Za-z0-9_]*)*$'))">
            <xsl:sequence select="f:fail('ROS005', (pim:policy/@source-element, @xmi-id)[1],
                'topic ''' || $topic || ''' of connection ''' || @name || ''' is not a valid ROS graph name')"/>
          </xsl:if>
          <r:topic xmi-id="{@xmi-id}" connection="{@name}" name="{$topic}">
            <xsl:sequence select="fp:qos(pim:policy)"/>
            <xsl:for-each select="pim:writer">
              <r:writer instance="{@instance}" port="{@data-port}" xmi-id="{@port}"/>
            </xsl:for-each>
            <xsl:for-each select="pim:reader">
              <r:reader instance="{@instance}" port="{@data-port}" xmi-id="{@port}"/>
            </xsl:for-each>
          </r:topic>
        </xsl:for-each>
        <xsl:for-each select="$b/pim:instance">
          <xsl:sequence select="fp:ros-instance(., $nodes, $host-keys)"/>
        </xsl:for-each>
      </xsl:variable>
      <xsl:call-template name="t:indented-content">
        <xsl:with-param name="children" select="$children"/>
        <xsl:with-param name="margin" select="'&#10;'"/>
      </xsl:call-template>
    </r:package>
  </xsl:template>

  <xsl:function name="fp:host-key" as="xs:string">
    <xsl:param name="host" as="xs:string"/>
    <xsl:param name="root" as="document-node()"/>
    <xsl:variable name="h" as="element(pim:host)?" select="key('fp:host', $host, $root)"/>
    <xsl:sequence select="if ($h) then f:snake-case($h/@name) else 'local'"/>
  </xsl:function>

  <!-- queue depth and QoS of a connection policy (N6) -->
  <xsl:function name="fp:qos" as="element(r:qos)">
    <xsl:param name="p" as="element(pim:policy)?"/>
    <r:qos depth="{if ($p/@type = ('BUFFER', 'CIRCULAR_BUFFER')) then $p/@size else 1}"
           latch="{$p/@init = ('true', '1')}" reliability="reliable"
           durability="{if ($p/@init = ('true', '1')) then 'transient_local' else 'volatile'}" history="keep_last"/>
  </xsl:function>

  <!-- ============================================================ types -->
  <xsl:function name="fp:type" as="element(ty:type)?">
    <xsl:param name="typed" as="element()"/>
    <xsl:variable name="name" as="xs:string" select="string($typed/@type-name)"/>
    <xsl:variable name="p" as="xs:string" select="string($typed/@primitive)"/>
    <xsl:sequence select="if ($typed/@upper and not($typed/@upper = ('1', ''))) then ()
        else (if ($name ne '' and exists($fp:user-types)) then key('fp:type-by-name', $name, $fp:user-types) else (),
              if ($p ne '' and exists($fp:user-types)) then key('fp:type-by-primitive', $p, $fp:user-types) else (),
              if ($name ne '') then key('fp:type-by-name', $name, $fp:builtin-types) else (),
              if ($p ne '') then key('fp:type-by-primitive', $p, $fp:builtin-types) else ())[1]"/>
  </xsl:function>

  <xsl:function name="fp:required-type" as="element(ty:type)">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:variable name="t" as="element(ty:type)?" select="fp:type($typed)"/>
    <xsl:sequence select="if (exists($t) and $t/@cpp ne 'void') then $t
        else f:fail('ROS001', $id, $what || ' has type ''' || ($typed/@type-name, $typed/@primitive, '?')[1]
                     || (if ($typed/@upper and not($typed/@upper = ('1', ''))) then '[' || $typed/@upper || ']' else '')
                     || ''', which the ROS type map does not map (supported: '
                     || string-join($fp:builtin-types//ty:type[@cpp ne 'void']/@primitive, ', ')
                     || ', data types of those, and the entries of parameter type-map)')"/>
  </xsl:function>

  <!-- the message a data port carries: a mapped type, or a generated .msg
       for a data type whose attributes are all mapped primitives -->
  <xsl:function name="fp:message" as="element(r:message)">
    <xsl:param name="dp" as="element(pim:data-port)"/>
    <xsl:variable name="t" as="element(ty:type)?" select="fp:type($dp)"/>
    <xsl:variable name="dt" as="element()?" select="if ($dp/@type) then key('fp:id', $dp/@type, root($dp)) else ()"/>
    <xsl:variable name="what" as="xs:string"
        select="'port ''' || $dp/@port-name || ''' (datum ''' || $dp/@datum-name || ''' of interface ''' || $dp/@interface-name || ''')'"/>
    <xsl:choose>
      <xsl:when test="exists($t) and $t/@cpp ne 'void'">
        <r:message msg="{$t/@msg}" field="{$t/@field}" cpp-type="{$t/@cpp}" sample="{$t/@sample}" generated="false"/>
      </xsl:when>
      <xsl:when test="exists($dt) and empty($dp/@primitive) and exists($dt/pim:attribute)
                      and (every $a in $dt/pim:attribute satisfies exists(fp:type($a)[@msg-field ne '']))
                      and not($dp/@upper and not($dp/@upper = ('1', '')))">
        <xsl:variable name="n" as="xs:string" select="f:upper-camel($dt/@name)"/>
        <!-- the user's C++ type of the same name, in the global namespace
             (qualified: inside the package's namespace the bare name is the
             generated message) -->
        <r:message msg="{$n}" field="" cpp-type="{'::' || f:cpp-identifier($dt/@name)}" sample="{'::' || f:cpp-identifier($dt/@name) || '()'}"
                   generated="true" type="{$dt/@id}">
          <xsl:for-each select="$dt/pim:attribute">
            <r:field name="{f:snake-case(@name)}" member="{f:cpp-identifier(@name)}" msg-field="{fp:type(.)/@msg-field}"/>
          </xsl:for-each>
        </r:message>
      </xsl:when>
      <xsl:otherwise>
        <xsl:variable name="never" as="element(ty:type)" select="fp:required-type($dp, $dp/@port, $what)"/>
        <r:message msg="{$never/@msg}" field="" cpp-type="" sample="" generated="false"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <xsl:function name="fp:ros-doc" as="element(r:doc)?">
    <xsl:param name="e" as="element()?"/>
    <xsl:for-each select="$e/pim:doc[normalize-space(.)]">
      <r:doc><xsl:value-of select="normalize-space(.)"/></r:doc>
    </xsl:for-each>
  </xsl:function>

  <!-- ============================================================= node -->
  <xsl:function name="fp:node" as="element(r:node)">
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:param name="pkg" as="xs:string"/>
    <xsl:param name="b" as="element(pim:binding)"/>
    <xsl:variable name="c" as="element(pim:component)" select="key('fp:id', $bc/@component, root($bc))"/>
    <xsl:variable name="r" as="element(pim:class)?" select="key('fp:id', $bc/@realization, root($bc))"/>
    <xsl:variable name="class" as="xs:string" select="f:upper-camel($c/@name)"/>
    <xsl:variable name="owner" as="element()" select="($r, $c)[1]"/>
    <xsl:variable name="callable" as="element(pim:operation)*" select="$r/pim:operation[@visibility ne 'private']"/>
    <xsl:variable name="instances" as="element(pim:instance)*" select="key('fp:instance-of', $bc/@component, root($bc))"/>
    <xsl:if test="empty($r)">
      <xsl:sequence select="f:fail('ROS007', $c/@id, 'component ''' || $c/@name || ''' has no realizing class (ComponentRealization):'
          || ' the ROS targets wrap the atomic code and do not generate a user base class yet')"/>
    </xsl:if>
    <r:node xmi-id="{$c/@id}" name="{$c/@name}" class="{$class}" namespace="{$pkg}" type-name="{$pkg}::{$class}"
            kind="{if ($r) then 'wrapper' else 'base'}" generated-class="{if ($r) then $class else $class || 'Base'}"
            executable="{f:snake-case($c/@name)}_node" default-name="{f:snake-case($c/@name)}"
            period="{($instances/pim:activity/@period)[1]}">
      <xsl:sequence select="fp:ros-doc($c)"/>
      <xsl:if test="$r">
        <xsl:variable name="n" as="xs:string"
            select="string-join(tokenize($bc/@cpp-name, '::')[normalize-space(.)] ! f:cpp-identifier(.), '::')"/>
        <r:realizing-class xmi-id="{$r/@id}" name="{$r/@name}" cpp-name="::{$n}" header="{$bc/@header}"/>
      </xsl:if>
      <xsl:for-each select="$fp:lifecycle">
        <xsl:variable name="h" as="xs:string" select="."/>
        <xsl:variable name="op" as="element(pim:operation)?" select="$callable[@name eq $h][1]"/>
        <r:hook name="{$h}">
          <xsl:if test="$op">
            <xsl:attribute name="call" select="$h"/>
            <xsl:attribute name="returns-bool" select="$op/pim:parameter[@direction eq 'return']/@primitive = 'boolean'"/>
            <xsl:attribute name="xmi-id" select="$op/@id"/>
          </xsl:if>
        </r:hook>
      </xsl:for-each>
      <xsl:for-each select="$bc/pim:data-port">
        <xsl:variable name="dp" as="element(pim:data-port)" select="."/>
        <xsl:variable name="port" as="element(pim:port)" select="key('fp:id', @port, root($bc))"/>
        <xsl:variable name="acc" as="xs:string"
            select="(if (@direction eq 'out') then 'get' else 'set') || f:upper-first(f:cpp-identifier(@datum-name))"/>
        <xsl:variable name="links" as="element(pim:connection)*"
            select="$instances ! key('fp:connection-by-end', @name || '/' || $dp/@name, root($bc))"/>
        <r:port xmi-id="{@port}" direction="{@direction}" name="{@name}" topic="{@name}"
                member="{if (@direction eq 'out') then 'pub_' else 'sub_'}{@name}_"
                interface="{@interface-name}" datum="{@datum-name}"
                accessor="{$acc}" accessor-declared="{exists($callable[@name eq $acc])}">
          <xsl:sequence select="fp:ros-doc($port)"/>
          <xsl:sequence select="fp:message(.)"/>
          <xsl:sequence select="fp:qos($links[1]/pim:policy)"/>
        </r:port>
      </xsl:for-each>
      <xsl:variable name="ops" as="element(pim:operation)*"
          select="$owner/pim:operation[@visibility eq 'protected'][not(@static = ('true', '1'))][not(@name = $fp:lifecycle)]"/>
      <xsl:variable name="services" as="element(r:service)*" select="$ops ! fp:service(.)"/>
      <xsl:sequence select="$services"/>
      <xsl:variable name="left-out" as="element(pim:operation)*" select="$ops[not(@id = $services/@xmi-id)]"/>
      <xsl:if test="exists($left-out)">
        <xsl:sequence select="f:warn('ROS101', $left-out[1]/@id, 'operation(s) ''' || string-join($left-out/@name, ''', ''')
            || ''' of ''' || $owner/@name || ''' fit no std_srvs service (Empty: no argument, no result; Trigger: no argument,'
            || ' Boolean result; SetBool: one Boolean argument): not exposed as ROS services')"/>
      </xsl:if>
      <xsl:variable name="configurable" as="element(pim:attribute)*"
          select="$owner/pim:attribute[exists(f:stereotype(., 'Configurable'))]"/>
      <xsl:choose>
        <xsl:when test="exists($configurable)">
          <xsl:sequence select="$configurable ! fp:parameter(.)"/>
        </xsl:when>
        <xsl:otherwise>
          <xsl:sequence select="$owner/pim:attribute[@visibility = ('public', 'protected')]
                                  [not(@static = ('true', '1'))][not(@read-only = ('true', '1'))]
                                  [not(@name = $fp:convention-names)][exists(fp:type(.)[@cpp ne 'void'])]
                                ! fp:parameter(.)"/>
        </xsl:otherwise>
      </xsl:choose>
    </r:node>
  </xsl:function>

  <!-- N3: a std_srvs service, or nothing (the caller warns: ROS101) -->
  <xsl:function name="fp:service" as="element(r:service)?">
    <xsl:param name="op" as="element(pim:operation)"/>
    <xsl:variable name="ret" as="element(pim:parameter)?" select="$op/pim:parameter[@direction eq 'return'][1]"/>
    <xsl:variable name="args" as="element(pim:parameter)*" select="$op/pim:parameter[@direction ne 'return']"/>
    <xsl:variable name="void" as="xs:boolean" select="empty($ret) or $ret/@primitive eq 'void'"/>
    <xsl:variable name="bool-ret" as="xs:boolean" select="$ret/@primitive = 'boolean' and not($ret/@upper and not($ret/@upper = ('1', '')))"/>
    <xsl:variable name="srv" as="xs:string?" select="
        if (empty($args) and $void) then 'std_srvs/Empty'
        else if (empty($args) and $bool-ret) then 'std_srvs/Trigger'
        else if (count($args) eq 1 and $args/@direction eq 'in' and $args/@primitive eq 'boolean'
                 and not($args/@upper and not($args/@upper = ('1', ''))) and ($void or $bool-ret)) then 'std_srvs/SetBool'
        else ()"/>
    <xsl:choose>
      <xsl:when test="exists($srv)">
        <r:service xmi-id="{$op/@id}" name="{f:cpp-identifier($op/@name)}" srv="{$srv}"
                   returns-bool="{$bool-ret}" member="srv_{f:cpp-identifier($op/@name)}_">
          <xsl:sequence select="fp:ros-doc($op)"/>
        </r:service>
      </xsl:when>
    </xsl:choose>
  </xsl:function>

  <!-- ================================================ parameter values -->
  <xsl:function name="fp:quoted" as="xs:string">
    <xsl:param name="v" as="xs:string"/>
    <xsl:sequence select="'&quot;' || replace(replace(replace($v, '\\', '\\\\'), '&quot;', '\\&quot;'), '&#10;', '\\n') || '&quot;'"/>
  </xsl:function>

  <!-- (C++ literal, YAML literal) of a default value -->
  <xsl:function name="fp:values" as="xs:string+">
    <xsl:param name="v" as="xs:string"/>
    <xsl:param name="t" as="element(ty:type)"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:variable name="s" as="xs:string" select="f:unquote(normalize-space($v))"/>
    <xsl:variable name="num" as="xs:string" select="replace($s, '^([+\-]?[0-9.eE+\-]+)[fFdDlLuU]*$', '$1')"/>
    <xsl:variable name="p" as="xs:string" select="string($t/@primitive)"/>
    <xsl:sequence select="
      if ($t/@param1 eq 'std::string') then (fp:quoted($s), fp:quoted($s))
      else if ($p eq 'boolean') then
        (if (lower-case($s) = ('true', '1')) then ('true', 'true')
         else if (lower-case($s) = ('false', '0')) then ('false', 'false')
         else f:fail('ROS002', $id, 'default ''' || $v || ''' is not a boolean'))
      else if ($p eq 'char') then
        (if (string-length($s) eq 1) then (string(string-to-codepoints($s)), string(string-to-codepoints($s)))
         else f:fail('ROS002', $id, 'default ''' || $v || ''' is not a single character'))
      else if ($t/@param1 eq 'double') then
        (if ($num castable as xs:double and not(matches($num, 'nan|inf', 'i')))
         then (for $d in (if (contains($num, '.') or contains(lower-case($num), 'e')) then $num else $num || '.0')
               return ($d || (if ($p eq 'float32') then 'f' else ''), $d))
         else f:fail('ROS002', $id, 'default ''' || $v || ''' is not a number'))
      else if ($t/@param1 eq 'int') then
        (if ($num castable as xs:integer and (not(starts-with($p, 'u') or $p eq 'octet') or xs:integer($num) ge 0))
         then (string(xs:integer($num)), string(xs:integer($num)))
         else f:fail('ROS002', $id, 'default ''' || $v || ''' is not a valid ' || $p))
      else f:fail('ROS002', $id, 'a default value of type ''' || ($t/@type-name, $p)[1] || ''' cannot be written as a ROS parameter')"/>
  </xsl:function>

  <xsl:function name="fp:parameter" as="element(r:parameter)">
    <xsl:param name="a" as="element(pim:attribute)"/>
    <xsl:variable name="t" as="element(ty:type)"
        select="fp:required-type($a, $a/@id, 'parameter ''' || $a/@name || '''')"/>
    <xsl:if test="not($t/@param1 = ('int', 'double', 'bool', 'std::string'))">
      <xsl:sequence select="f:fail('ROS001', $a/@id, 'parameter ''' || $a/@name || ''' has type '''
          || ($a/@type-name, $a/@primitive)[1] || ''', which is not a ROS parameter type')"/>
    </xsl:if>
    <xsl:variable name="vals" as="xs:string+"
        select="if ($a/@default) then fp:values($a/@default, $t, $a/@id)
                else if ($t/@param1 eq 'std::string') then ('&quot;&quot;', '&quot;&quot;')
                else if ($t/@param1 eq 'bool') then ('false', 'false')
                else if ($t/@param1 eq 'double') then (if ($t/@primitive eq 'float32') then '0.0f' else '0.0', '0.0')
                else ('0', '0')"/>
    <r:parameter xmi-id="{$a/@id}" name="{f:cpp-identifier($a/@name)}" member="{f:cpp-identifier($a/@name)}"
                 cpp-type="{$t/@cpp}" param1="{$t/@param1}" param2="{$t/@param2}"
                 cpp-default="{$vals[1]}" yaml-default="{$vals[2]}">
      <xsl:sequence select="fp:ros-doc($a)"/>
    </r:parameter>
  </xsl:function>

  <!-- ========================================================= instance -->
  <xsl:function name="fp:ros-instance" as="element(r:instance)">
    <xsl:param name="i" as="element(pim:instance)"/>
    <xsl:param name="nodes" as="document-node()"/>
    <xsl:param name="host-keys" as="map(xs:string, xs:string)"/>
    <xsl:variable name="n" as="element(r:node)" select="key('fp:node', $i/@component, $nodes)"/>
    <xsl:variable name="a" as="element(pim:activity)" select="$i/pim:activity"/>
    <r:instance xmi-id="{$i/@xmi-id}" name="{$i/@name}" node="{$n/@class}" executable="{$n/@executable}"
                host="{$host-keys(string($i/@host))}" middleware="{$i/@middleware}"
                period="{$a/@period}" periodic="{number($a/@period) ne 0}">
      <xsl:for-each select="$n/r:port">
        <xsl:variable name="p" as="element(r:port)" select="."/>
        <xsl:variable name="links" as="element(pim:connection)*"
            select="key('fp:connection-by-end', $i/@name || '/' || $p/@name, root($i))"/>
        <xsl:if test="count($links) gt 1">
          <xsl:sequence select="f:warn('ROS103', $p/@xmi-id, 'port ''' || $p/@name || ''' of instance ''' || $i/@name
              || ''' is in connections ''' || string-join($links/@name, ''', ''') || ''': ROS remaps a port to one topic; '''
              || $links[1]/@name || ''' is used')"/>
        </xsl:if>
        <xsl:for-each select="$links[1]">
          <r:remap from="{$p/@topic}" to="{(pim:policy/@topic[normalize-space(.)], @name)[1]}"/>
        </xsl:for-each>
      </xsl:for-each>
      <r:parameter-value name="update_period" yaml="{fp:yaml-double($a/@period)}"/>
      <xsl:for-each select="$n/r:parameter">
        <r:parameter-value name="{@name}" yaml="{@yaml-default}"/>
      </xsl:for-each>
    </r:instance>
  </xsl:function>

  <xsl:function name="fp:yaml-double" as="xs:string">
    <xsl:param name="v" as="xs:string"/>
    <xsl:sequence select="if (contains($v, '.') or contains(lower-case($v), 'e')) then $v else $v || '.0'"/>
  </xsl:function>
</xsl:stylesheet>
