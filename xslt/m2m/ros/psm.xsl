<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/ros/psm.xsl - bound PIM -> ROS PSM (ROS 1 roscpp / ROS 2 rclcpp).

  Reads:   a bound PIM, urn:robomda:pim:1 with pim:binding (xslt/m2m/bind.xsl).
  Writes:  urn:robomda:psm-ros:1 (schemas/psm-ros/1/psm-ros.xsd),
           indented as f:indent (common/indent.xsl) indents it, through its
           rules (t:indented-content) in the same pass.
  Data:    xslt/m2m/ros/types.xml (type -> C++ type, message, parameter type),
           overridden entry by entry by the map the type-map parameter names.
  Uses:    xslt/m2m/common/psm-kit.xsl (wrapper, hooks, default values).
  Params:  ros-version ('1' or '2'), package-name, type-map (see below).

  Rules (docs/ros.md)
  N1  one node class per component type with an instance (all instances,
      whatever their middleware: see W100): class UpperCamel(component),
      executable snake(component)_node; kind "wrapper" with a realizing
      class (the node class derives from it, as the Orocos target does),
      else "base" (a generated <Class>Base and a user <Class>).
  N2  data ports: out -> publisher, in -> subscription whose callback calls
      set<Datum>; the topic in the code is the port name, remapped per
      instance in the launch files to the connection's topic (for a node
      in a namespace named from the root, r:remap/@from-root, as a service
      client's provider is: ROS 2 launch puts the pushed namespace before
      it). Message type
      from the type map; a data type or an enumeration no entry maps: its
      generated msg/<Type>.msg (types.xsl); an array of numbers: the
      std_msgs multi-array message.
  N3  services: the protected operations of the realizing class (base: of
      the component), except the lifecycle names, where a std_srvs service
      fits: no argument and no result -> std_srvs/Empty; no argument and a
      Boolean result -> std_srvs/Trigger; one Boolean argument -> std_srvs/
      SetBool. An operation of a provided or required interface that fits
      none: a service of the package's own (r:service-type, srv/<Op>.srv:
      a request field per argument, a response field for the result, each
      the message that carries the parameter's type; fp:own-service); one
      that can have none (an out / inout parameter, a type no message
      carries): ROS009. Any other operation is left out with warning ROS101.
  N4  parameters: the attributes R4 of the Orocos target selects
      (Configurable, else public/protected non-static non-read-only ones not
      named sample/priority/scheduler/cpuAffinity), with declared type and
      the model's default (an enumeration: a literal's name; an array: a
      list; a data type: one parameter per attribute at any depth, named
      by its path gains.stiffness); plus update_period (the instance's
      period).
  N5  period -> timer (update(), then publish the outputs); period 0 ->
      data-driven (each received message runs update() and publishes).
  N6  connection -> topic: the policy's topic tag, else the connection name;
      policy -> queue depth (DATA 1, BUFFER / CIRCULAR_BUFFER its size),
      latch / durability transient_local when init is true, reliability
      reliable, history keep_last(depth). A port's QoS is taken from the
      first connection it is in (ROS sets QoS per publisher, not per link).
  N7  deployment (seed 002, docs/deployment.md): one package per model with
      the instances deployed on the target's middleware (ROS / ROS2), all
      when none is (ROS100); each other instance is its own target's
      (ROS110). Hosts -> ROS 1 machines, one launch file per host plus a
      top-level one; ROS 2: one launch file per host (warning ROS102: no
      machine tag). Processes -> r:process: ROS 2 component containers
      (multi-threaded where the model has threads in one); ROS 1 runs one
      node per component (ROS111, ROS112). Component sets -> r:set, a
      launch file each, included by its host's. A connection to an
      instance on Orocos is a ROS 1 topic named from the root (/topic, as
      the Orocos target's rtt_roscomm stream names it); any other
      connection across middlewares is ROS011.
  N8  managed lifecycle (ROS 2): an instance in a process whose middleware
      is managed is a lifecycle node: its node class gets a lifecycle twin
      (@lifecycle-type-name, <pkg>::lifecycle::<Class>), the instance
      @managed, and its host a lifecycle manager node (@lifecycle-manager)
      that configures the host's managed nodes, then activates them, in the
      deployment sequence. ROS 1 has no node lifecycle (ROS113).
  N9  a component without a realizing class (kind "base"): the user's
      class <Class>Impl, written once, stands where the realizing class
      would (r:realizing-class user="true"); its hooks are the five
      lifecycle calls, set<Datum> / get<Datum> of each port, each service's
      operation; the generated <Class>Base declares them (pure virtual) and
      holds the parameters' members (r:member), so a hook the model no
      longer has fails to compile where the user's class overrides it.
  N10 jobs (seed 004, docs/jobs.md; jobs.xsl): an instance in the jobs of
      a subsystem is switched by the subsystem's coordinator (r:coordinator,
      r:instance/@job; @idle when it is in no initial job, so no launch file
      starts it); on ROS 2 it is a lifecycle node (@managed) that the
      coordinator, not the host's lifecycle manager, configures and
      activates. Warnings JOB050-JOB052 (jobs.xsl).

  Errors (urn:robomda:error, f:fail):
    ROS001  a port, service or Configurable parameter has a type the type
            map cannot map (names the element)
    ROS002  a parameter default is not valid for its type
    ROS003  the input has no pim:binding (run xslt/m2m/bind.xsl first)
    ROS004  two component types map to the same C++ class name
    ROS005  a ConnectionPolicy topic is not a valid ROS graph name
    ROS006  parameter ros-version is neither '1' nor '2'
    ROS030  a class a component without a realizing class brings
            (<Class>Base, <Class>Impl) is the class of another component
    ROS008  nothing to generate: the model has no component instance
    ROS010  a data type that contains itself (types.xsl)
    ROS011  a connection between an instance of the package and one on a
            middleware no transport reaches from it (names both ends)
    ROS009  an operation call ROS cannot make (an operation of a provided
            or required interface that fits no std_srvs service and can have
            no service of its own, two ports of one interface and role, two
            required operations of one name)
  Warnings (f:warn):
    ROS100  no instance is deployed on the target's middleware: the
            instances of the others are generated for ROS anyway (once)
    ROS110  an instance deployed on another middleware is left to its target
    ROS111  ROS 1: a process of several components runs them as nodes of
            their own
    ROS112  ROS 1: the components of a thread each run in their own
    ROS113  ROS 1: a managed (lifecycle) process; ROS 1 has no node lifecycle
    ROS101  operations with no fitting std_srvs service are left out (one
            warning per component type, naming them)
    ROS102  ROS 2 launch has no machine tag: one launch file per host
    ROS103  a port is in several connections: only the first one's topic
            and policy are used
    ROS104  a value set on an instance's property that is no parameter
    ROS105  a required interface no connector binds to a provider
    ROS106  a required operation the realizing class does not declare
    ROS107  an attribute the convention would make a parameter that has a
            type the ROS type map cannot carry (it is no parameter): an
            array of a data type on ROS 2 (ROS 1 reads a list of mappings)
    ROS108  a bounded array in a ROS 1 message (types.xsl)
    ROS109  a data type no port carries that cannot be declared (types.xsl)
    JOB050, JOB051, JOB052  the job coordinators (jobs.xsl)
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

  <xsl:include href="../../common/errors.xsl"/>
  <xsl:include href="../../common/literals.xsl"/>
  <xsl:include href="../../common/indent.xsl"/>
  <xsl:include href="../../common/naming.xsl"/>
  <xsl:include href="../../common/profile.xsl"/>
  <xsl:include href="../common/psm-kit.xsl"/>
  <xsl:include href="types.xsl"/>
  <xsl:include href="jobs.xsl"/>

  <xsl:param name="ros-version" as="xs:string" select="'1'">
    <!-- '1' (catkin / roscpp) or '2' (ament / rclcpp) -->
  </xsl:param>
  <xsl:param name="package-name" as="xs:string" select="''">
    <!-- the ROS package; '' = lower snake-case of the model name -->
  </xsl:param>
  <xsl:param name="type-map" as="xs:string" select="''">
    <!-- URI of an extra type map (format of xslt/m2m/ros/types.xml): absolute, or relative to the input; its entries win; '' = none -->
  </xsl:param>

  <xsl:output method="xml" indent="no" encoding="UTF-8"/>
  <xsl:mode name="m:to-psm" on-no-match="fail"/>

  <!-- the elements the kit (../common/psm-kit.xsl) makes -->
  <xsl:variable name="fp:psm-namespace" as="xs:string" select="'urn:robomda:psm-ros:1'"/>
  <xsl:variable name="fp:psm-prefix" as="xs:string" select="'r'"/>

  <xsl:key name="fp:type-by-primitive" match="ty:type[@primitive]" use="@primitive"/>
  <xsl:key name="fp:type-by-name" match="ty:type[@type-name]" use="@type-name"/>
  <xsl:key name="fp:host" match="pim:host" use="@xmi-id"/>
  <xsl:key name="fp:connection-by-end" match="pim:connection"
      use="(pim:writer | pim:reader) ! (@instance || '/' || @data-port)"/>
  <xsl:key name="fp:node" match="r:node" use="@xmi-id"/>
  <!-- N3: the interfaces' operations and the model's types by the name a
       service of its own would have (fp:srv-name) -->
  <xsl:key name="fp:operation-by-srv" match="pim:interface/pim:operation" use="f:upper-camel(@name)"/>
  <xsl:key name="fp:type-by-srv" match="pim:datatype | pim:enumeration" use="f:upper-camel(@name)"/>
  <xsl:key name="fp:instance-by-name" match="pim:binding/pim:instance" use="@name"/>
  <xsl:key name="fp:process" match="pim:process" use="@xmi-id"/>
  <xsl:key name="fp:thread" match="pim:thread" use="@xmi-id"/>
  <xsl:key name="fp:component-set" match="pim:component-set" use="@xmi-id"/>

  <xsl:variable name="fp:builtin-types" as="document-node()" select="doc('types.xml')"/>
  <xsl:variable name="fp:user-types" as="document-node()?"
      select="if (normalize-space($type-map)) then doc(resolve-uri($type-map, base-uri(/))) else ()"/>
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
    <xsl:variable name="binding" as="element(pim:binding)" select="pim:binding"/>
    <xsl:variable name="package" as="xs:string" select="fp:package-name($package-name, .)"/>
    <!-- the instances of this package (N7): those deployed on the target's
         middleware, all when none is -->
    <xsl:variable name="instances" as="element(pim:instance)*"
        select="$binding/pim:instance[fp:on-target(., $fp:target-middleware)]"/>
    <xsl:variable name="targets" as="map(xs:string, xs:boolean)"
        select="map:merge($instances ! map:entry(string(@name), true()))"/>
    <xsl:variable name="components" as="element(pim:bound-component)*"
        select="$binding/pim:bound-component[some $i in key('fp:instance-of', @component) satisfies map:contains($targets, string($i/@name))]"/>
    <xsl:sequence select="fp:check-class-names($components, 'ROS004')"/>
    <xsl:sequence select="fp:check-services($components, 'ROS009'), fp:check-calls($binding/pim:call, $targets, 'ROS009'),
                          fp:warn-unbound-services($instances, 'ROS105')"/>
    <xsl:sequence select="fp:check-targets(., $instances, $fp:target-middleware, 'ROS ' || $ros-version,
                                           ('ROS008', 'ROS100', 'ROS110'))"/>
    <xsl:variable name="connections" as="element(pim:connection)*"
        select="$binding/pim:connection[fp:kept-connection(., $binding, $targets)]"/>
    <xsl:sequence select="f:fail-all(for $c in $connections, $end in fp:foreign-ends($c, $targets)[not(fp:reachable(@middleware))]
                                     return fp:no-transport($c, $end))"/>
    <!-- fp:host-key of each host the instances name, made once per host -->
    <xsl:variable name="host-keys" as="map(xs:string, xs:string)"
        select="map:merge(distinct-values($instances ! string(@host))
                          ! map:entry(., fp:host-key(., root($binding))))"/>
    <xsl:variable name="hosts" as="element(r:host)*" select="fp:ros-hosts($instances, $host-keys)"/>
    <xsl:if test="$ros-version eq '2' and count($hosts) gt 1">
      <xsl:sequence select="f:warn('ROS102', $hosts[2]/@xmi-id, 'ROS 2 launch has no machine tag: one launch file per host ('
          || string-join($hosts/@launch, ', ') || '), each to be started on its host')"/>
    </xsl:if>
    <xsl:variable name="nodes" as="document-node()">
      <xsl:document>
        <xsl:sequence select="$components ! fp:node(., $package,
            some $i in key('fp:instance-of', @component)[map:contains($targets, string(@name))] satisfies fp:managed($i))"/>
      </xsl:document>
    </xsl:variable>
    <xsl:sequence select="fp:check-user-classes($nodes/r:node)"/>
    <r:package xmi-id="{@id}" model-name="{@name}" name="{$package}" namespace="{$package}" ros-version="{$ros-version}"
               deploy-name="{f:snake-case(@name)}" source="{@source}">
      <xsl:variable name="children" as="element()*">
        <xsl:sequence select="$binding/pim:library ! fp:psm-library(., $package)"/>
        <xsl:sequence select="fp:ros-types($components, $nodes/r:node/(r:port, r:service, r:service-client)//r:message, root(.))"/>
        <xsl:sequence select="fp:service-types($nodes/r:node)"/>
        <xsl:sequence select="$nodes/r:node"/>
        <xsl:sequence select="$hosts"/>
        <xsl:sequence select="fp:ros-processes($instances, $host-keys)"/>
        <xsl:sequence select="fp:ros-sets($instances, $host-keys)"/>
        <xsl:sequence select="$connections ! fp:topic(., $targets)"/>
        <xsl:sequence select="$instances ! fp:ros-instance(., $nodes, $host-keys, $targets)"/>
        <xsl:sequence select="fp:ros-coordinators($binding, $instances, $nodes, $host-keys)"/>
      </xsl:variable>
      <xsl:call-template name="t:indented-content">
        <xsl:with-param name="children" select="$children"/>
        <xsl:with-param name="margin" select="'&#10;'"/>
      </xsl:call-template>
    </r:package>
  </xsl:template>

  <!-- instance $instance is a ROS 2 managed (lifecycle) node: its process
       asks for it (Middleware managed, N8), or a subsystem's coordinator
       switches it (N10) -->
  <xsl:function name="fp:managed" as="xs:boolean">
    <xsl:param name="instance" as="element(pim:instance)"/>
    <xsl:sequence select="$ros-version eq '2'
        and (key('fp:process', string($instance/@execution-environment), root($instance))/@managed = 'true'
             or exists(fp:ros-job-of($instance)))"/>
  </xsl:function>

  <xsl:function name="fp:host-key" as="xs:string">
    <xsl:param name="host" as="xs:string"/>
    <xsl:param name="root" as="document-node()"/>
    <xsl:variable name="pim-host" as="element(pim:host)?" select="key('fp:host', $host, $root)"/>
    <xsl:sequence select="if ($pim-host) then f:snake-case($pim-host/@name) else 'local'"/>
  </xsl:function>

  <!-- one r:host per host key of the package's instances (N7), with the
       host's resources and buses -->
  <xsl:function name="fp:ros-hosts" as="element(r:host)*">
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:param name="host-keys" as="map(xs:string, xs:string)"/>
    <xsl:for-each-group select="$instances" group-by="$host-keys(string(@host))">
      <xsl:variable name="pim-host" as="element(pim:host)?"
          select="key('fp:host', string(current-group()[1]/@host), root(current-group()[1]))"/>
      <r:host xmi-id="{($pim-host/@xmi-id, current-group()[1]/@execution-environment)[1]}"
              name="{current-grouping-key()}" machine="{current-grouping-key()}"
              hostname="{($pim-host/@hostname, 'localhost')[1]}" address="{($pim-host/@address, 'localhost')[1]}"
              launch="{current-grouping-key()}">
        <!-- the lifecycle manager: the managed nodes no coordinator switches -->
        <xsl:if test="some $i in current-group() satisfies (fp:managed($i) and empty(fp:ros-job-of($i)))">
          <xsl:attribute name="lifecycle-manager" select="current-grouping-key() || '_lifecycle_manager'"/>
        </xsl:if>
        <xsl:sequence select="$pim-host ! fp:psm-host-resources(.)"/>
      </r:host>
    </xsl:for-each-group>
  </xsl:function>

  <!-- ===================================================== deployment -->
  <!-- the processes of the package's instances: a ROS 2 component
       container each (multi-threaded where the model has threads in it);
       ROS 1 runs one node per component: ROS111 per process of several,
       ROS112 per thread -->
  <xsl:function name="fp:ros-processes" as="element(r:process)*">
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:param name="host-keys" as="map(xs:string, xs:string)"/>
    <xsl:for-each-group select="$instances[@execution-environment]" group-by="@execution-environment">
      <xsl:variable name="process" as="element(pim:process)?"
          select="key('fp:process', current-grouping-key(), root(current-group()[1]))"/>
      <xsl:variable name="members" as="element(pim:instance)*" select="current-group()"/>
      <xsl:if test="exists($process)">
        <!-- thread id -> its members (one pass, not a scan of the members per thread) -->
        <xsl:variable name="by-thread" as="map(xs:string, element(pim:instance)+)">
          <xsl:map>
            <xsl:for-each-group select="$members[@thread]" group-by="string(@thread)">
              <xsl:map-entry key="current-grouping-key()" select="current-group()"/>
            </xsl:for-each-group>
          </xsl:map>
        </xsl:variable>
        <xsl:variable name="threads" as="element(pim:thread)*" select="$process/pim:thread[map:contains($by-thread, string(@xmi-id))]"/>
        <!-- an execution environment named after its middleware (the
             unprofiled convention) stands for the middleware, not a process -->
        <xsl:if test="$ros-version eq '1' and count($members) gt 1 and upper-case($process/@name) ne $process/@middleware">
          <xsl:sequence select="f:warn('ROS111', $process/@xmi-id, 'process ''' || $process/@name || ''' holds '''
              || string-join($members/@name, ''', ''') || ''': ROS 1 runs each component as a node of its own (no nodelet manager is generated)')"/>
        </xsl:if>
        <xsl:for-each select="$threads[$ros-version eq '1']">
          <xsl:variable name="thread" as="element(pim:thread)" select="."/>
          <xsl:sequence select="f:warn('ROS112', @xmi-id, 'thread ''' || @name || ''' of process ''' || $process/@name
              || ''': ROS 1 nodes cannot share a thread; ''' || string-join($by-thread(string($thread/@xmi-id))/@name, ''', ''')
              || ''' each run in their own, with the thread''s period')"/>
        </xsl:for-each>
        <xsl:if test="$ros-version eq '1' and $process/@managed = 'true'">
          <xsl:sequence select="f:warn('ROS113', $process/@xmi-id, 'process ''' || $process/@name || ''' asks for managed'
              || ' (lifecycle) nodes: ROS 1 has no node lifecycle; '''
              || string-join($members/@name, ''', ''') || ''' start active, in no managed sequence')"/>
        </xsl:if>
        <!-- a process all of whose components are in one set belongs to it -->
        <xsl:variable name="sets" as="xs:string*" select="distinct-values($members ! string(@set))"/>
        <r:process xmi-id="{$process/@xmi-id}" name="{$process/@name}" container="{f:snake-case($process/@name)}"
                   host="{$host-keys(string($members[1]/@host))}" executor="{if (exists($threads)) then 'multi' else 'single'}"
                   managed="{$process/@managed = 'true'}">
          <xsl:if test="count($sets) eq 1 and $sets ne ''">
            <xsl:attribute name="set" select="f:snake-case(key('fp:component-set', $sets, root($process))/@name)"/>
          </xsl:if>
          <xsl:if test="exists($threads)">
            <xsl:attribute name="threads" select="string-join($threads/@name, ' ')"/>
          </xsl:if>
        </r:process>
      </xsl:if>
    </xsl:for-each-group>
  </xsl:function>

  <!-- the component sets of the package's instances: a launch file each,
       on the host the set is deployed on (else its first member's) -->
  <xsl:function name="fp:ros-sets" as="element(r:set)*">
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:param name="host-keys" as="map(xs:string, xs:string)"/>
    <xsl:for-each-group select="$instances[@set]" group-by="@set">
      <xsl:variable name="set" as="element(pim:component-set)"
          select="key('fp:component-set', current-grouping-key(), root(current-group()[1]))"/>
      <xsl:variable name="host" as="xs:string"
          select="(string($set/pim:on[map:contains($host-keys, string(@host))][1]/@host), string(current-group()[1]/@host))[. ne ''][1]"/>
      <r:set xmi-id="{$set/@xmi-id}" name="{$set/@name}" launch="{f:snake-case($set/@name)}" host="{$host-keys($host)}"/>
    </xsl:for-each-group>
  </xsl:function>

  <!-- the ends of $connection on instances another target generates -->
  <xsl:function name="fp:foreign-ends" as="element(pim:instance)*">
    <xsl:param name="connection" as="element(pim:connection)"/>
    <xsl:param name="targets" as="map(xs:string, xs:boolean)"/>
    <xsl:sequence select="($connection/pim:writer | $connection/pim:reader)[not(map:contains($targets, string(@instance)))]
        ! key('fp:instance-by-name', string(@instance), root($connection))"/>
  </xsl:function>

  <!-- whether this target meets an instance on $middleware on a topic:
       Orocos RTT reaches ROS 1 through rtt_roscomm (the agreed topic) -->
  <xsl:function name="fp:reachable" as="xs:boolean">
    <xsl:param name="middleware" as="xs:string"/>
    <xsl:sequence select="$ros-version eq '1' and $middleware eq 'OROCOS'"/>
  </xsl:function>

  <!-- ROS011 for $connection, one of whose ends ($end) no transport from
       this target reaches -->
  <xsl:function name="fp:no-transport" as="map(*)">
    <xsl:param name="connection" as="element(pim:connection)"/>
    <xsl:param name="end" as="element(pim:instance)"/>
    <xsl:sequence select="map { 'code': 'ROS011', 'id': string($connection/@xmi-id), 'message': 'connection '''
        || $connection/@name || ''' joins ' || string-join(($connection/pim:writer | $connection/pim:reader)
           ! ('''' || @instance || ''' (' || key('fp:instance-by-name', string(@instance), root($end))/@middleware || ')'), ' and ')
        || ': no transport joins ' || $fp:target-middleware || ' and ' || $end/@middleware
        || (if ($end/@middleware eq 'OROCOS') then ' (Orocos RTT reaches ROS 1 only, through rtt_roscomm)' else '')
        || '; deploy both ends on one middleware, or exchange the data through a ROS 1 component' }"/>
  </xsl:function>

  <!-- the topic of a connection (N6): the policy's topic, else the
       connection's name; from the root (/name) when it crosses to another
       middleware, whose side names it so too -->
  <xsl:function name="fp:topic-name" as="xs:string">
    <xsl:param name="connection" as="element(pim:connection)"/>
    <xsl:param name="targets" as="map(xs:string, xs:boolean)"/>
    <xsl:variable name="topic" as="xs:string" select="($connection/pim:policy/@topic[normalize-space(.)], $connection/@name)[1]"/>
    <xsl:sequence select="if (exists(fp:foreign-ends($connection, $targets)) and not(starts-with($topic, '/')))
                          then '/' || $topic else $topic"/>
  </xsl:function>

  <!-- a connection as a topic (N6); ROS005 when its name is not a graph
       name; an end on another middleware is marked with it -->
  <xsl:function name="fp:topic" as="element(r:topic)">
    <xsl:param name="connection" as="element(pim:connection)"/>
    <xsl:param name="targets" as="map(xs:string, xs:boolean)"/>
    <xsl:for-each select="$connection">
      <xsl:variable name="topic" as="xs:string" select="fp:topic-name(., $targets)"/>
      <xsl:if test="not(matches($topic, '^[~/]?[A-Za-z][A-Za-z0-9_]*(/[A-Za-z][A-Za-z0-9_]*)*$'))">
        <xsl:sequence select="f:fail('ROS005', (pim:policy/@source-element, @xmi-id)[1],
            'topic ''' || $topic || ''' of connection ''' || @name || ''' is not a valid ROS graph name')"/>
      </xsl:if>
      <r:topic xmi-id="{@xmi-id}" connection="{@name}" name="{$topic}">
        <xsl:sequence select="fp:qos(pim:policy)"/>
        <xsl:for-each select="pim:writer | pim:reader">
          <xsl:element name="r:{local-name()}">
            <xsl:attribute name="instance" select="@instance"/>
            <xsl:attribute name="port" select="@data-port"/>
            <xsl:attribute name="xmi-id" select="@port"/>
            <xsl:if test="not(map:contains($targets, string(@instance)))">
              <xsl:attribute name="middleware" select="key('fp:instance-by-name', string(@instance), root(.))/@middleware"/>
            </xsl:if>
          </xsl:element>
        </xsl:for-each>
      </r:topic>
    </xsl:for-each>
  </xsl:function>

  <!-- queue depth and QoS of a connection policy (N6) -->
  <xsl:function name="fp:qos" as="element(r:qos)">
    <xsl:param name="policy" as="element(pim:policy)?"/>
    <r:qos depth="{if ($policy/@type = ('BUFFER', 'CIRCULAR_BUFFER')) then $policy/@size else 1}"
           latch="{$policy/@init = ('true', '1')}" reliability="reliable"
           durability="{if ($policy/@init = ('true', '1')) then 'transient_local' else 'volatile'}" history="keep_last"/>
  </xsl:function>

  <!-- ============================================================ types -->
  <xsl:function name="fp:required-type" as="element(ty:type)">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:variable name="type" as="element(ty:type)?" select="fp:type($typed)"/>
    <xsl:sequence select="if (exists($type) and $type/@cpp ne 'void') then $type
        else f:fail('ROS001', $id, $what || ' has type ''' || fp:type-label($typed)
                     || ''', which the ROS type map does not map (supported: '
                     || string-join($fp:builtin-types//ty:type[@cpp ne 'void']/@primitive, ', ')
                     || ', the model''s data types and enumerations with a literal, arrays of these,'
                     || ' and the entries of parameter type-map)')"/>
  </xsl:function>

  <!-- the message a data port carries: a mapped type; a generated message
       for a data type or an enumeration (types.xsl); the standard multi-array
       message of an array of numbers -->
  <xsl:function name="fp:message" as="element(r:message)">
    <xsl:param name="data-port" as="element(pim:data-port)"/>
    <xsl:variable name="what" as="xs:string" select="'port ''' || $data-port/@port-name || ''' (datum '''
        || $data-port/@datum-name || ''' of interface ''' || $data-port/@interface-name || ''')'"/>
    <xsl:variable name="type" as="element(ty:type)" select="fp:required-type($data-port, $data-port/@port, $what)"/>
    <xsl:variable name="message" as="element(r:message)?" select="fp:message-of($data-port, $type)"/>
    <xsl:sequence select="if (exists($message)) then $message
        else f:fail('ROS001', $data-port/@port, $what || ' carries ''' || fp:type-label($data-port)
               || ''': no standard message carries an array of that type (std_msgs has multi-array messages of numbers);'
               || ' make the array an attribute of a data type, whose generated message carries it')"/>
  </xsl:function>

  <!-- the message that carries typed element $typed of ROS type $type;
       () for an array no standard message carries -->
  <xsl:function name="fp:message-of" as="element(r:message)?">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="type" as="element(ty:type)"/>
    <xsl:choose>
      <xsl:when test="$type/@kind = ('struct', 'enum')">
        <r:message msg="{$type/@msg}" field="" cpp-type="{$type/@cpp}" sample="{$type/@sample}" generated="true"
                   type="{$type/@type-ref}">
          <xsl:if test="fp:stamped(fp:type-def($typed))"><xsl:attribute name="stamped" select="'true'"/></xsl:if>
        </r:message>
      </xsl:when>
      <xsl:when test="$type/@kind eq 'sequence' and $type/@msg ne ''">
        <r:message msg="{$type/@msg}" field="data" cpp-type="{$type/@cpp}" sample="{$type/@sample}" generated="false"
                   sequence="true"/>
      </xsl:when>
      <xsl:when test="$type/@kind eq 'sequence'"/>
      <xsl:otherwise>
        <r:message msg="{$type/@msg}" field="{$type/@field}" cpp-type="{$type/@cpp}" sample="{$type/@sample}" generated="false"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <!-- ============================================================= node -->
  <xsl:function name="fp:node" as="element(r:node)">
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:param name="package" as="xs:string"/>
    <!-- an instance of it is a managed (lifecycle) node (N8) -->
    <xsl:param name="managed" as="xs:boolean"/>
    <xsl:variable name="component" as="element(pim:component)" select="key('fp:id', $bc/@component, root($bc))"/>
    <xsl:variable name="wrapper" as="xs:boolean" select="exists(fp:realization($bc))"/>
    <!-- named as bound: components of one name in different packages by their qualified names -->
    <xsl:variable name="class" as="xs:string" select="f:upper-camel($bc/@name)"/>
    <xsl:variable name="instances" as="element(pim:instance)*" select="key('fp:instance-of', $bc/@component, root($bc))"/>
    <r:node xmi-id="{$component/@id}" name="{$bc/@name}" class="{$class}" namespace="{$package}"
            type-name="{$package}::{$class}" kind="{if ($wrapper) then 'wrapper' else 'base'}"
            generated-class="{if ($wrapper) then $class else $class || 'Base'}"
            executable="{f:snake-case($bc/@name)}_node" default-name="{f:snake-case($bc/@name)}"
            period="{($instances/pim:activity/@period)[1]}">
      <xsl:if test="$managed">
        <xsl:attribute name="lifecycle-type-name" select="$package || '::lifecycle::' || $class"/>
      </xsl:if>
      <xsl:sequence select="fp:psm-doc($component)"/>
      <!-- N9: without a realizing class, the user's class written once
           (<Class>Impl) stands where the realizing class would, and
           implements every hook the generated <Class>Base declares -->
      <xsl:sequence select="if ($wrapper) then (fp:psm-realizing-class($bc), fp:psm-hooks($bc))
                            else fp:user-class($component, $package, $class)"/>
      <xsl:sequence select="$bc/pim:data-port ! fp:ros-port(., $instances)"/>
      <xsl:sequence select="fp:services($bc)"/>
      <xsl:sequence select="$bc/pim:service-port[@role eq 'required'] ! fp:service-clients(., $bc)"/>
      <xsl:variable name="configurable" as="element(pim:attribute)*" select="fp:configurable-attributes($bc)"/>
      <xsl:variable name="convention" as="element(pim:attribute)*"
          select="if (exists($configurable)) then () else fp:convention-attributes($bc)"/>
      <xsl:variable name="typed" as="element(pim:attribute)*"
          select="$convention[fp:param-able(., fp:type(.)) or fp:item-list-able(., fp:type(.))]"/>
      <xsl:sequence select="fp:warn-skipped-attributes($convention except $typed, 'ROS107', 'ROS parameter')"/>
      <xsl:variable name="parameters" as="element(r:parameter)*"
          select="($configurable, $typed) ! fp:parameters(., f:cpp-identifier(@name))"/>
      <xsl:sequence select="$parameters"/>
      <xsl:if test="not($wrapper)">
        <xsl:sequence select="($configurable, $typed) ! fp:base-member(., $parameters)"/>
      </xsl:if>
    </r:node>
  </xsl:function>

  <!-- ROS030 when a class a base node brings (N9: <Class>Base, <Class>Impl)
       is the class of another node, or one it brings -->
  <xsl:function name="fp:check-user-classes" as="empty-sequence()">
    <xsl:param name="nodes" as="element(r:node)*"/>
    <xsl:variable name="classes" as="map(*)*"
        select="$nodes ! (map { 'class': string(@class), 'node': . },
                          .[@kind eq 'base'] ! (map { 'class': @class || 'Base', 'node': . }, map { 'class': @class || 'Impl', 'node': . }))"/>
    <xsl:for-each-group select="$classes" group-by="?class">
      <xsl:variable name="nodes" as="element(r:node)+" select="current-group() ! ?node"/>
      <xsl:if test="count($nodes) gt 1">
        <xsl:variable name="base" as="element(r:node)" select="($nodes[@kind eq 'base'], $nodes)[1]"/>
        <xsl:sequence select="f:fail('ROS030', $base/@xmi-id, 'components ''' || string-join($nodes/@name, ''', ''')
            || ''' both need C++ class ' || current-grouping-key() || ': component ''' || $base/@name
            || ''' has no realizing class, so its node ' || $base/@class || ' gets a generated ' || $base/@class
            || 'Base and your ' || $base/@class || 'Impl; rename one of the components')"/>
      </xsl:if>
    </xsl:for-each-group>
  </xsl:function>

  <!-- N9: the user's class of a component without a realizing class,
       <Class>Impl, written once, in the place of a realizing class (the
       node derives from it and calls it), and the five hooks, which the
       generated <Class>Base declares and the user class implements -->
  <xsl:function name="fp:user-class" as="element()+">
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:param name="class" as="xs:string"/>
    <r:realizing-class xmi-id="{$component/@id}" name="{$class}Impl" cpp-name="::{$package}::{$class}Impl"
                       header="{$package}/{$class}Impl.hpp" user="true"/>
    <xsl:for-each select="$fp:lifecycle">
      <r:hook name="{.}" call="{.}" returns-bool="{. = ('configure', 'start')}"/>
    </xsl:for-each>
  </xsl:function>

  <!-- N9: the member of <Class>Base behind attribute $attribute, whose
       parameters are $parameters (a data type's: one per attribute of it),
       initialised to the model's default -->
  <xsl:function name="fp:base-member" as="element(r:member)">
    <xsl:param name="attribute" as="element(pim:attribute)"/>
    <xsl:param name="parameters" as="element(r:parameter)*"/>
    <xsl:variable name="type" as="element(ty:type)" select="fp:type($attribute)"/>
    <xsl:variable name="parameter" as="element(r:parameter)?" select="$parameters[@xmi-id eq $attribute/@id]"/>
    <r:member name="{f:cpp-identifier($attribute/@name)}" cpp-type="{$type/@cpp}"
              init="{if ($type/@kind eq 'struct') then ''
                     else if ($type/@kind eq 'enum') then $parameter/r:choice[fp:yaml-quoted(@value) eq $parameter/@yaml-default]/@cpp
                     else $parameter/@cpp-default}">
      <xsl:if test="$type/@kind = ('struct', 'enum')">
        <xsl:attribute name="type" select="$type/@type-ref"/>
      </xsl:if>
    </r:member>
  </xsl:function>

  <!-- N2: a data port of a node; its QoS from the first connection one of
       the component's $instances makes through it -->
  <xsl:function name="fp:ros-port" as="element(r:port)">
    <xsl:param name="data-port" as="element(pim:data-port)"/>
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:for-each select="$data-port">
      <xsl:variable name="accessor" as="xs:string" select="fp:accessor(.)"/>
      <xsl:variable name="connections" as="element(pim:connection)*"
          select="$instances ! key('fp:connection-by-end', @name || '/' || $data-port/@name, root($data-port))"/>
      <r:port xmi-id="{@port}" direction="{@direction}" name="{@name}" topic="{@name}"
              member="{if (@direction eq 'out') then 'pub_' else 'sub_'}{@name}_"
              interface="{@interface-name}" datum="{@datum-name}"
              accessor="{$accessor}" accessor-declared="{empty(fp:realization(..)) or fp:accessor-declared(.)}">
        <xsl:if test="@constant = ('true', '1')"><xsl:attribute name="constant" select="'true'"/></xsl:if>
        <xsl:sequence select="fp:psm-doc(key('fp:id', @port, root(.)))"/>
        <xsl:sequence select="fp:message(.)"/>
        <xsl:sequence select="fp:qos($connections[1]/pim:policy)"/>
      </r:port>
    </xsl:for-each>
  </xsl:function>

  <!-- N3: the services of a node: a std_srvs service, else, for an
       operation of a provided interface, a service of its own
       (fp:own-service; ROS009 when it can have none); ROS101 names the
       other operations no std_srvs service fits -->
  <xsl:function name="fp:services" as="element(r:service)*">
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:variable name="operations" as="element(pim:operation)*" select="fp:offered-operations($bc, $fp:lifecycle)"/>
    <xsl:variable name="services" as="element(r:service)*">
      <xsl:for-each select="$operations">
        <xsl:variable name="service" as="element(r:service)?" select="fp:service(.)"/>
        <xsl:variable name="interface-op" as="element(pim:operation)?"
            select="if (exists($service)) then () else fp:provided-interface-operation($bc, .)"/>
        <xsl:sequence select="if (exists($service) or empty($interface-op)) then $service
                              else fp:own-service-of(., $interface-op, 'provides')"/>
      </xsl:for-each>
    </xsl:variable>
    <xsl:sequence select="$services"/>
    <xsl:variable name="left-out" as="element(pim:operation)*" select="$operations[not(@id = $services/@xmi-id)]"/>
    <xsl:if test="exists($left-out)">
      <xsl:sequence select="f:warn('ROS101', $left-out[1]/@id, 'operation(s) ''' || string-join($left-out/@name, ''', ''')
          || ''' of ''' || fp:owner($bc)/@name || ''' fit no std_srvs service (Empty: no argument, no result; Trigger: no argument,'
          || ' Boolean result; SetBool: one Boolean argument): not exposed as ROS services')"/>
    </xsl:if>
  </xsl:function>



  <!-- N3: the r:service of $operation, which is or implements operation
       $interface-op of an interface, through a service of its own
       (fp:own-service); ROS009 when it can have none (the component
       $role: provides, requires) -->
  <xsl:function name="fp:own-service-of" as="element(r:service)">
    <xsl:param name="operation" as="element(pim:operation)"/>
    <xsl:param name="interface-op" as="element(pim:operation)"/>
    <xsl:param name="role" as="xs:string"/>
    <xsl:variable name="own" as="map(*)" select="fp:own-service($interface-op)"/>
    <xsl:sequence select="f:fail-all($own?problem ! fp:no-srv($interface-op, $role, .))"/>
    <r:service xmi-id="{$operation/@id}" name="{f:cpp-identifier($operation/@name)}" srv="{$own?srv}"
               returns-bool="false" member="srv_{f:cpp-identifier($operation/@name)}_">
      <xsl:sequence select="fp:psm-doc($operation), $own?parts"/>
    </r:service>
  </xsl:function>

  <!-- N3: a service of its own for interface operation $operation
       (srv/<Name>.srv, fp:service-types): its request one field per
       argument (in), its response one field for the result, each field the
       message that carries the parameter's type. A map: srv (the name,
       fp:srv-name), parts (r:argument*, r:result?), problem (why it can be
       none: an out or inout parameter, a type no message carries) -->
  <xsl:function name="fp:own-service" as="map(*)">
    <xsl:param name="operation" as="element(pim:operation)"/>
    <xsl:variable name="parts" as="element()*">
      <xsl:for-each select="$operation/pim:parameter[@direction = ('in', 'return')]">
        <xsl:variable name="type" as="element(ty:type)?" select="fp:type(.)[@cpp ne 'void']"/>
        <xsl:variable name="field" as="xs:string"
            select="if (normalize-space(@name)) then f:snake-case(@name) else if (@direction eq 'return') then 'result' else 'argument'"/>
        <xsl:element name="{if (@direction eq 'return') then 'r:result' else 'r:argument'}" namespace="urn:robomda:psm-ros:1">
          <xsl:attribute name="name" select="f:cpp-identifier(if (normalize-space(@name)) then @name else $field)"/>
          <xsl:attribute name="field" select="$field"/>
          <xsl:attribute name="parameter" select="@id"/>
          <xsl:sequence select="$type ! fp:message-of(current(), .)"/>
        </xsl:element>
      </xsl:for-each>
    </xsl:variable>
    <xsl:variable name="unmapped" as="element(pim:parameter)*"
        select="$operation/pim:parameter[@id = $parts[empty(r:message)]/@parameter]"/>
    <xsl:variable name="outs" as="element(pim:parameter)*" select="$operation/pim:parameter[@direction = ('out', 'inout')]"/>
    <xsl:sequence select="map {
        'srv': fp:srv-name($operation),
        'parts': $parts,
        'problem': if (exists($outs))
                   then 'its parameter ''' || $outs[1]/@name || ''' is ' || $outs[1]/@direction
                        || ': a ROS service answers with its response only; make it the result'
                   else if (exists($unmapped))
                   then 'its parameter ''' || $unmapped[1]/@name || ''' has type ''' || fp:type-label($unmapped[1])
                        || ''', which no ROS message carries'
                   else () }"/>
  </xsl:function>

  <!-- the name of operation $operation's service of its own: the
       operation's name in UpperCamel, after its interface's where another
       interface has an operation of that name, or a data type of the model
       has it (or it with Request / Response: ROS 1 writes headers of those
       names beside the messages') -->
  <xsl:function name="fp:srv-name" as="xs:string">
    <xsl:param name="operation" as="element(pim:operation)"/>
    <xsl:variable name="name" as="xs:string" select="f:upper-camel($operation/@name)"/>
    <xsl:variable name="root" as="document-node()" select="root($operation)"/>
    <xsl:sequence select="if (count(distinct-values(key('fp:operation-by-srv', $name, $root)/../@id)) gt 1
                              or exists(($name, $name || 'Request', $name || 'Response') ! key('fp:type-by-srv', ., $root)))
                          then f:upper-camel($operation/../@name) || $name else $name"/>
  </xsl:function>

  <!-- ROS009 for operation $operation of an interface that a component
       provides or requires ($role), which no service can carry ($why) -->
  <xsl:function name="fp:no-srv" as="map(*)">
    <xsl:param name="operation" as="element(pim:operation)"/>
    <xsl:param name="role" as="xs:string"/>
    <xsl:param name="why" as="xs:string"/>
    <xsl:sequence select="map { 'code': 'ROS009', 'id': string($operation/@id), 'message': 'operation '''
        || $operation/@name || ''' of interface ''' || $operation/../@name || ''', which a component ' || $role
        || ', fits no std_srvs service and can have no service of its own: ' || $why }"/>
  </xsl:function>

  <!-- N3: the types of the package's own services (srv/<Name>.srv), each
       once, from the first node's service or client of it -->
  <xsl:function name="fp:service-types" as="element(r:service-type)*">
    <xsl:param name="nodes" as="element(r:node)*"/>
    <xsl:for-each-group select="$nodes/(r:service, r:service-client)[r:argument or r:result]" group-by="@srv">
      <r:service-type name="{current-grouping-key()}">
        <xsl:for-each select="r:argument, r:result">
          <xsl:element name="{if (self::r:result) then 'r:response' else 'r:request'}" namespace="urn:robomda:psm-ros:1">
            <xsl:attribute name="field" select="@field"/>
            <xsl:attribute name="msg" select="r:message/@msg"/>
          </xsl:element>
        </xsl:for-each>
      </r:service-type>
    </xsl:for-each-group>
  </xsl:function>

  <!-- a required interface (seed 003): a service client per operation,
       remapped per instance to the provider's service; the realizing class
       calls the operation by its name where it declares it (virtual, for the
       node to override; else ROS106) -->
  <xsl:function name="fp:service-clients" as="element(r:service-client)*">
    <xsl:param name="service-port" as="element(pim:service-port)"/>
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:for-each select="fp:interface-operations($service-port)">
      <xsl:variable name="std" as="element(r:service)?" select="fp:service(.)"/>
      <xsl:variable name="service" as="element(r:service)"
          select="if (exists($std)) then $std else fp:own-service-of(., ., 'requires')"/>
      <r:service-client xmi-id="{@id}" name="{$service/@name}" srv="{$service/@srv}" returns-bool="{$service/@returns-bool}"
          member="client_{$service/@name}_" service="{$service-port/@interface-name}"
          forward="{fp:calls-declared($bc, $service-port, ., 'client client_' || $service/@name || '_', 'ROS106')}">
        <xsl:if test="$service/@srv eq 'std_srvs/SetBool'">
          <xsl:attribute name="argument" select="f:cpp-identifier((pim:parameter[@direction ne 'return']/@name[normalize-space(.)], 'data')[1])"/>
        </xsl:if>
        <xsl:sequence select="$service/(r:argument, r:result)"/>
      </r:service-client>
    </xsl:for-each>
  </xsl:function>

  <!-- N3: a std_srvs service, or nothing (the caller warns: ROS101) -->
  <xsl:function name="fp:service" as="element(r:service)?">
    <xsl:param name="operation" as="element(pim:operation)"/>
    <xsl:variable name="result" as="element(pim:parameter)?" select="$operation/pim:parameter[@direction eq 'return'][1]"/>
    <xsl:variable name="arguments" as="element(pim:parameter)*" select="$operation/pim:parameter[@direction ne 'return']"/>
    <xsl:variable name="void" as="xs:boolean" select="empty($result) or $result/@primitive eq 'void'"/>
    <xsl:variable name="bool-result" as="xs:boolean" select="$result/@primitive = 'boolean' and not(fp:is-array($result))"/>
    <xsl:variable name="srv" as="xs:string?" select="
        if (empty($arguments) and $void) then 'std_srvs/Empty'
        else if (empty($arguments) and $bool-result) then 'std_srvs/Trigger'
        else if (count($arguments) eq 1 and $arguments/@direction eq 'in' and $arguments/@primitive eq 'boolean'
                 and not(fp:is-array($arguments)) and ($void or $bool-result)) then 'std_srvs/SetBool'
        else ()"/>
    <xsl:if test="exists($srv)">
      <r:service xmi-id="{$operation/@id}" name="{f:cpp-identifier($operation/@name)}" srv="{$srv}"
                 returns-bool="{$bool-result}" member="srv_{f:cpp-identifier($operation/@name)}_">
        <xsl:sequence select="fp:psm-doc($operation)"/>
      </r:service>
    </xsl:if>
  </xsl:function>

  <!-- ================================================ parameter values -->
  <!-- (C++ literal, YAML literal) of a default value -->
  <xsl:function name="fp:values" as="xs:string+">
    <xsl:param name="value" as="xs:string"/>
    <xsl:param name="type" as="element(ty:type)"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:variable name="primitive" as="xs:string" select="string($type/@primitive)"/>
    <xsl:variable name="kind" as="xs:string?"
        select="if ($type/@param1 eq 'std::string') then 'string'
                else if ($primitive = ('boolean', 'char')) then $primitive
                else if ($type/@param1 eq 'double') then 'real'
                else if ($type/@param1 eq 'int') then 'integer' else ()"/>
    <xsl:variable name="parsed" as="xs:string"
        select="if (exists($kind)) then fp:parse-default($value, $kind, $primitive, $id, 'ROS002')
                else f:fail('ROS002', $id, 'a default value of type ''' || ($type/@type-name, $primitive)[1]
                            || ''' cannot be written as a ROS parameter')"/>
    <xsl:sequence select="
      if ($kind eq 'string') then (fp:cpp-string($parsed), fp:cpp-string($parsed))
      else if ($kind eq 'char') then
        (if (string-length($parsed) eq 1) then (string(string-to-codepoints($parsed)), string(string-to-codepoints($parsed)))
         else f:fail('ROS002', $id, 'default ''' || $value || ''' is not a single character'))
      else if ($kind eq 'real') then
        (fp:decimal($parsed) || (if ($primitive eq 'float32') then 'f' else ''), fp:decimal($parsed))
      else ($parsed, $parsed)"/>
  </xsl:function>

  <!-- (C++ literal, YAML literal) of a parameter's value $value (() = the
       type's zero) of $typed: a primitive, an enumeration literal (the
       parameter is its name), an array of primitives (a list) -->
  <xsl:function name="fp:param-values" as="xs:string+">
    <xsl:param name="value" as="xs:string?"/>
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="type" as="element(ty:type)"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:choose>
      <xsl:when test="$type/@kind eq 'enum'">
        <xsl:variable name="literal" as="xs:string"
            select="if (exists($value)) then fp:enum-literal($value, key('fp:id', $type/@type-ref, root($typed)), $id, 'ROS002')/@name
                    else key('fp:id', $type/@type-ref, root($typed))/pim:literal[1]/@name"/>
        <xsl:sequence select="fp:cpp-string($literal), fp:yaml-quoted($literal)"/>
      </xsl:when>
      <xsl:when test="$type/@kind eq 'sequence'">
        <xsl:variable name="items" as="xs:string*"
            select="if (exists($value)) then fp:default-items($value, $typed, $id, 'ROS002')
                    else if ($type/@array eq 'fixed') then (1 to xs:integer($type/@size)) ! '' else ()"/>
        <xsl:variable name="pairs" as="xs:string*" select="$items ! fp:param-values(.[. ne ''], $typed, $type/ty:type, $id)"/>
        <xsl:sequence select="'{' || string-join($pairs[position() mod 2 eq 1], ', ') || '}',
                              '[' || string-join($pairs[position() mod 2 eq 0], ', ') || ']'"/>
      </xsl:when>
      <xsl:when test="exists($value)">
        <xsl:sequence select="fp:values($value, $type, $id)"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:sequence select="if ($type/@param1 eq 'std::string') then ('&quot;&quot;', '&quot;&quot;')
            else if ($type/@param1 eq 'bool') then ('false', 'false')
            else if ($type/@param1 eq 'double') then (if ($type/@primitive eq 'float32') then '0.0f' else '0.0', '0.0')
            else ('0', '0')"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <xsl:function name="fp:yaml-quoted" as="xs:string">
    <xsl:param name="text" as="xs:string"/>
    <xsl:sequence select="'&quot;' || $text || '&quot;'"/>
  </xsl:function>

  <!-- (ROS 1 type, ROS 2 type) a parameter of $type is read as, or () when
       none: a primitive's; an enumeration's literal name (std::string); a
       std::vector of a primitive's -->
  <xsl:function name="fp:param-type" as="xs:string*">
    <xsl:param name="type" as="element(ty:type)?"/>
    <xsl:sequence select="
      if ($type/@param1 = ('int', 'double', 'bool', 'std::string')) then ($type/@param1, $type/@param2)
      else if ($type/@kind eq 'enum') then ('std::string', 'std::string')
      else if ($type/@kind eq 'sequence' and $type/ty:type/@param1 = ('int', 'double', 'bool', 'std::string'))
      then $type/ty:type ! ('std::vector&lt;' || @param1 || '&gt;', 'std::vector&lt;' || @param2 || '&gt;')
      else ()"/>
  </xsl:function>

  <!-- whether an attribute of type $type can be a parameter: a type
       fp:param-type reads, or a data type all of whose attributes can -->
  <xsl:function name="fp:param-able" as="xs:boolean">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="type" as="element(ty:type)?"/>
    <!-- if, not and / or: a data type that contains itself must fail
         (ROS010) before the recursion, whatever order an engine picks -->
    <xsl:sequence select="
        if (exists(fp:param-type($type))) then true()
        else if (not($type/@kind eq 'struct')) then false()
        else if (fp:type-depth(key('fp:id', $type/@type-ref, root($typed)), (), 'ROS010') lt 0) then false()
        else every $a in fp:attributes(key('fp:id', $type/@type-ref, root($typed))) satisfies fp:param-able($a, fp:type($a))"/>
  </xsl:function>

  <!-- ROS 1: whether an attribute of type $type can be a parameter that
       is a list of mappings (XmlRpc array of structs): an array of a data
       type whose attributes are, at any depth, single numbers, Booleans,
       strings, enumerations or data types of these (ROS 2 parameters hold
       no list of mappings) -->
  <xsl:function name="fp:item-list-able" as="xs:boolean">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="type" as="element(ty:type)?"/>
    <xsl:sequence select="$ros-version eq '1' and $type/@kind eq 'sequence' and $type/ty:type/@kind eq 'struct'
                          and fp:item-able($typed, $type/ty:type)"/>
  </xsl:function>

  <xsl:function name="fp:item-able" as="xs:boolean">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="type" as="element(ty:type)?"/>
    <xsl:sequence select="
        if ($type/@param1 = ('int', 'double', 'bool', 'std::string') or $type/@kind eq 'enum') then true()
        else if (not($type/@kind eq 'struct')) then false()
        else if (fp:type-depth(key('fp:id', $type/@type-ref, root($typed)), (), 'ROS010') lt 0) then false()
        else every $a in fp:attributes(key('fp:id', $type/@type-ref, root($typed))) satisfies fp:item-able($a, fp:type($a))"/>
  </xsl:function>

  <!-- the members of one item of a list-of-mappings parameter (data type
       $def): r:item per attribute, read as param1 (a number, Boolean or
       string), an enumeration's literal name (r:choice), or a mapping (its
       r:item children) -->
  <xsl:function name="fp:param-items" as="element(r:item)*">
    <xsl:param name="def" as="element()"/>
    <xsl:for-each select="fp:attributes($def)">
      <xsl:variable name="type" as="element(ty:type)" select="fp:type(.)"/>
      <r:item name="{@name}" member="{f:cpp-identifier(@name)}" cpp-type="{$type/@cpp}"
              kind="{($type/@kind, 'primitive')[1]}" param1="{fp:param-type($type)[1]}"
              yaml="{if ($type/@kind eq 'struct') then fp:yaml-item(key('fp:id', $type/@type-ref, root(.)))
                     else fp:param-values(@default[normalize-space(.)], ., $type, @id)[2]}">
        <xsl:for-each select="$type[@kind eq 'enum']/key('fp:id', @type-ref, root(current()))/pim:literal">
          <r:choice value="{@name}" cpp="{$type/@cpp}::{f:cpp-identifier(@name)}"/>
        </xsl:for-each>
        <xsl:sequence select="$type[@kind eq 'struct'] ! fp:param-items(key('fp:id', @type-ref, root(current())))"/>
      </r:item>
    </xsl:for-each>
  </xsl:function>

  <!-- the YAML flow mapping of data type $def's model value -->
  <xsl:function name="fp:yaml-item" as="xs:string">
    <xsl:param name="def" as="element()"/>
    <xsl:sequence select="'{' || string-join(fp:param-items($def) ! (@name || ': ' || @yaml), ', ') || '}'"/>
  </xsl:function>

  <!-- the parameters of an attribute: one, or one per attribute of its data
       type at any depth (name and member gains.stiffness); ROS001 when one
       cannot be a parameter -->
  <xsl:function name="fp:parameters" as="element(r:parameter)*">
    <xsl:param name="attribute" as="element(pim:attribute)"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:variable name="what" as="xs:string" select="'parameter ''' || $name || ''''"/>
    <xsl:variable name="type" as="element(ty:type)" select="fp:required-type($attribute, $attribute/@id, $what)"/>
    <xsl:variable name="param-type" as="xs:string*" select="fp:param-type($type)"/>
    <xsl:choose>
      <xsl:when test="$type/@kind eq 'struct' and fp:param-able($attribute, $type)">
        <xsl:if test="$attribute/@default[normalize-space(.)]">
          <xsl:sequence select="f:fail('ROS002', $attribute/@id, 'default ''' || $attribute/@default || ''' of data type '''
              || $attribute/@type-name || ''': the data type''s attributes give its value')"/>
        </xsl:if>
        <xsl:sequence select="fp:attributes(key('fp:id', $type/@type-ref, root($attribute)))
                              ! fp:parameters(., $name || '.' || f:cpp-identifier(@name))"/>
      </xsl:when>
      <xsl:when test="fp:item-list-able($attribute, $type)">
        <xsl:if test="$attribute/@default[normalize-space(.)]">
          <xsl:sequence select="f:fail('ROS002', $attribute/@id, 'default ''' || $attribute/@default || ''' of an array of data type '''
              || $attribute/@type-name || ''': the data type''s attributes give its value')"/>
        </xsl:if>
        <xsl:variable name="def" as="element()" select="key('fp:id', $type/ty:type/@type-ref, root($attribute))"/>
        <!-- ROS 1: a list of mappings, one per item; a fixed array has its
             size of the type's model values, an unbounded one none -->
        <r:parameter xmi-id="{$attribute/@id}" name="{$name}" member="{$name}" kind="items"
                     cpp-type="{$type/@cpp}" param1="XmlRpc::XmlRpcValue" param2=""
                     cpp-default="{$type/@sample}"
                     yaml-default="{'[' || string-join((1 to xs:integer(($type[@array eq 'fixed']/@size, 0)[1])) ! fp:yaml-item($def), ', ') || ']'}"
                     item-type="{$type/ty:type/@cpp}">
          <xsl:if test="$type/@array eq 'fixed'"><xsl:attribute name="size" select="$type/@size"/></xsl:if>
          <xsl:sequence select="fp:psm-doc($attribute)"/>
          <xsl:sequence select="fp:param-items($def)"/>
        </r:parameter>
      </xsl:when>
      <xsl:when test="empty($param-type)">
        <xsl:sequence select="f:fail('ROS001', $attribute/@id, $what || ' has type ''' || fp:type-label($attribute)
            || ''', which is not a ROS parameter type (numbers, Boolean, strings, enumerations, arrays of numbers,'
            || ' Booleans or strings, and data types of these)')"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:variable name="values" as="xs:string+" select="fp:param-values($attribute/@default[normalize-space(.)], $attribute, $type, $attribute/@id)"/>
        <r:parameter xmi-id="{$attribute/@id}" name="{$name}" member="{$name}" kind="{($type/@kind, 'primitive')[1]}"
                     cpp-type="{$type/@cpp}" param1="{$param-type[1]}" param2="{$param-type[2]}"
                     cpp-default="{$values[1]}" yaml-default="{$values[2]}">
          <xsl:if test="$type/@array eq 'fixed'"><xsl:attribute name="size" select="$type/@size"/></xsl:if>
          <xsl:sequence select="fp:psm-doc($attribute)"/>
          <xsl:for-each select="$type[@kind eq 'enum']/key('fp:id', @type-ref, root($attribute))/pim:literal">
            <r:choice value="{@name}" cpp="{$type/@cpp}::{f:cpp-identifier(@name)}"/>
          </xsl:for-each>
        </r:parameter>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <!-- ========================================================= instance -->
  <xsl:function name="fp:ros-instance" as="element(r:instance)">
    <xsl:param name="instance" as="element(pim:instance)"/>
    <xsl:param name="nodes" as="document-node()"/>
    <xsl:param name="host-keys" as="map(xs:string, xs:string)"/>
    <xsl:param name="targets" as="map(xs:string, xs:boolean)"/>
    <xsl:variable name="node" as="element(r:node)" select="key('fp:node', $instance/@component, $nodes)"/>
    <xsl:variable name="activity" as="element(pim:activity)" select="$instance/pim:activity"/>
    <r:instance xmi-id="{$instance/@xmi-id}" name="{$instance/@name}" node="{$node/@class}">
      <!-- inside a composite part: a node in the namespace of its path -->
      <xsl:if test="$instance/@parent">
        <xsl:attribute name="node-name" select="substring-after($instance/@path, $instance/@parent || '.')"/>
        <xsl:attribute name="namespace" select="translate($instance/@parent, '.', '/')"/>
      </xsl:if>
      <xsl:attribute name="executable" select="$node/@executable"/>
      <xsl:attribute name="host" select="$host-keys(string($instance/@host))"/>
      <!-- an instance of the default process (the model draws none) runs
           on the target's middleware -->
      <xsl:attribute name="middleware" select="($instance/@middleware, $fp:target-middleware)[1]"/>
      <!-- its process (a container), component set and thread, by name -->
      <xsl:for-each select="key('fp:process', string($instance/@execution-environment), root($instance))">
        <xsl:attribute name="process" select="@name"/>
        <xsl:for-each select="key('fp:thread', string($instance/@thread), root($instance))[.. is current()]">
          <xsl:attribute name="thread" select="@name"/>
        </xsl:for-each>
      </xsl:for-each>
      <xsl:for-each select="key('fp:component-set', string($instance/@set), root($instance))">
        <xsl:attribute name="set" select="f:snake-case(@name)"/>
      </xsl:for-each>
      <xsl:sequence select="$instance/@start-order"/>
      <xsl:if test="fp:managed($instance)">
        <xsl:attribute name="managed" select="true()"/>
      </xsl:if>
      <!-- switched by the coordinator of its subsystem (N10); idle: in no
           initial job, started by a switch only -->
      <xsl:for-each select="fp:ros-job-of($instance)">
        <xsl:attribute name="job" select="."/>
        <xsl:if test="fp:ros-job-idle($instance)">
          <xsl:attribute name="idle" select="true()"/>
        </xsl:if>
      </xsl:for-each>
      <xsl:attribute name="period" select="$activity/@period"/>
      <xsl:attribute name="periodic" select="number($activity/@period) ne 0"/>
      <xsl:for-each select="$node/r:port">
        <xsl:variable name="port" as="element(r:port)" select="."/>
        <xsl:variable name="connections" as="element(pim:connection)*"
            select="key('fp:connection-by-end', $instance/@name || '/' || $port/@name, root($instance))"/>
        <!-- writers a coordinator switches share their reader's topic (jobs.xsl) -->
        <xsl:if test="count(distinct-values($connections ! fp:ros-alternatives(.)/@name)) gt 1">
          <xsl:sequence select="f:warn('ROS103', $port/@xmi-id, 'port ''' || $port/@name || ''' of instance '''
              || $instance/@name || ''' is in connections ''' || string-join($connections/@name, ''', ''')
              || ''': ROS remaps a port to one topic; ''' || $connections[1]/@name || ''' is used')"/>
        </xsl:if>
        <xsl:for-each select="$connections[1] ! fp:ros-alternatives(.)">
          <!-- a node in a namespace resolves a relative name in it: the
               topic is named from the root so that all ends meet (from-root:
               the launch's root, which a pushed namespace moves) -->
          <xsl:variable name="topic" as="xs:string" select="fp:topic-name(., $targets)"/>
          <r:remap from="{$port/@topic}"
                   to="{if ($instance/@parent and not(starts-with($topic, '/'))) then '/' || $topic else $topic}">
            <xsl:if test="$instance/@parent and not(starts-with($topic, '/'))">
              <xsl:attribute name="from-root" select="true()"/>
            </xsl:if>
          </r:remap>
        </xsl:for-each>
      </xsl:for-each>
      <!-- operation calls (seed 003): each client to the provider's
           private service, named from the root -->
      <xsl:for-each select="key('fp:call-by-caller', $instance/@name, root($instance))">
        <xsl:variable name="provider" as="element(pim:instance)" select="key('fp:instance-by-name', string(pim:provider/@instance), root(.))"/>
        <xsl:variable name="node-path" as="xs:string" select="translate(($provider/@path, $provider/@name)[1], '.', '/')"/>
        <xsl:for-each select="$node/r:service-client[@service eq key('fp:id', current()/@interface, root($instance))/@name]">
          <r:remap from="{@name}" to="/{$node-path}/{@name}" from-root="true"/>
        </xsl:for-each>
      </xsl:for-each>
      <r:parameter-value name="update_period" yaml="{fp:decimal($activity/@period)}"/>
      <!-- the model's value: one set by the enclosing parts and composites
           (seed 003), else the default -->
      <xsl:sequence select="fp:warn-unused-values($instance, $node/r:parameter/@xmi-id, 'ROS104')"/>
      <xsl:for-each select="$node/r:parameter">
        <xsl:variable name="set" as="element(pim:property-value)?" select="$instance/pim:property-value[@attribute eq current()/@xmi-id]"/>
        <r:parameter-value name="{@name}"
            yaml="{if ($set) then fp:param-values($set/@value, key('fp:id', @xmi-id, root($instance)),
                                      fp:required-type(key('fp:id', @xmi-id, root($instance)), @xmi-id, 'parameter ''' || @name || ''''),
                                      $set/@holder)[2]
                   else @yaml-default}"/>
      </xsl:for-each>
    </r:instance>
  </xsl:function>
</xsl:stylesheet>
