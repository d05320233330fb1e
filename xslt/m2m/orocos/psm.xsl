<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/orocos/psm.xsl - bound PIM -> Orocos RTT 2.x PSM (seed 000 R1-R5).

  Reads:   a bound PIM, urn:robomda:pim:1 with pim:binding (xslt/m2m/bind.xsl).
  Writes:  urn:robomda:psm-orocos:1 (schemas/psm-orocos/1/psm-orocos.xsd),
           indented as f:indent (common/indent.xsl) indents it, through its
           rules (t:indented-content) in the same pass.
  Data:    xslt/m2m/orocos/types.xml (primitive kind -> C++ / cpf XML type, sample).
  Types:   xslt/m2m/orocos/types.xsl (data types, enumerations, arrays, the
           typekit's o:types, structured property values).
  Uses:    xslt/m2m/common/psm-kit.xsl (wrapper, hooks, default values).
  Params:  package-name (see below).

  Rules
  R1  one TaskContext per component type with an OROCOS instance: class =
      UpperCamel(component name), namespace = package name, type name
      namespace::class. kind "wrapper" when the component has a realizing
      class (the TaskContext derives from it, seed 000 Fig. 11), else "base"
      (a generated <class>Base plus a user class <class>).
  R2  one port per bound data port: out -> RTT::OutputPort<T>, in ->
      RTT::InputPort<T>; member port_<name>; accessor get<Datum> / set<Datum>.
  R3  operations: the protected operations of the realizing class (base kind:
      of the component), except the lifecycle names and the names RTT's
      TaskContext already defines. Thread: OperationThread tag, else
      ClientThread for a query, else OwnThread. in parameters by value
      (const T& for strings), out / inout by reference.
  R4  properties: the attributes stereotyped Configurable of the realizing
      class (base kind: of the component); without any, the public and
      protected attributes that are not static, not read-only and not named
      sample / priority / scheduler / cpuAffinity. Convention-selected
      attributes of a type RTT cannot marshal are skipped; a Configurable one
      is an error.
  R5  activity: deployer type "Activity" for all instances (own thread;
      Period 0 = non-periodic, else periodic); PeriodicActivity is not used
      because it shares one thread among components with equal period and
      priority. Scheduler always explicit.
  Deployment: instances with middleware OROCOS (all instances when none is
  on OROCOS, see ORO006); connections whose ends are all such instances
  (ends on other middlewares are dropped, a connection
  left without writer or reader is dropped: a name used by one port would
  need a transport). Peers: a reader instance gets the writer instances of a
  connection whose interface declares operations (it may call them); data
  flow alone needs no peers. Operation calls (pim:call, seed 003): the
  caller gets the provider as a peer and an o:call (the text stage connects
  the services); the provider's operations of a provided interface carry
  o:operation/@service, the caller an o:required-service of callers.
  Deployment sequence (seed 002): the o:instance elements are written in
  the binding's start order (pim:instance/@start-order; instances without
  one, on a cycle of the constraints, come last in binding order), so the
  text stage loads, configures and starts them in that order; each keeps
  its constraints on other Orocos instances as o:start-after.

  Jobs (seed 004 §4.3, jobs.xsl): an o:coordinator per subsystem; an
  instance of a job that is not the initial one is idle (configured, not
  started: the coordinator starts it on a switch).
  Errors (urn:robomda:error, f:fail):
    ORO001  a port, operation parameter or Configurable property has a type
            robomda cannot map to C++ / cpf XML (names the element)
    ORO002  a property default value is not valid for its type
    ORO003  the input has no pim:binding (run xslt/m2m/bind.xsl first)
    ORO004  two component types map to the same C++ class name
    ORO005  nothing to generate: the model has no component instance
    ORO009  an operation call Orocos cannot make (two ports of one interface
            and role, two required operations of one name, a call to or
            from another middleware)
    ORO012  a data type that contains itself (types.xsl)
  Warnings (f:warn):
    ORO006  no instance is deployed on OROCOS: all instances are generated
            for Orocos anyway (the same model on another middleware)
    ORO007  an instance deployed on another middleware is left out (the model
            deploys some components on OROCOS and others elsewhere)
    ORO010  a required interface no connector binds to a provider
    ORO011  a required operation the realizing class does not declare
    ORO013  an attribute the convention would make a property that has a
            type Orocos cannot carry (it is no property)
    ORO120  a StartAfter pair whose earlier instance is deployed on another
            middleware: the start scripts cannot wait for it (named, not kept)
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:o="urn:robomda:psm-orocos:1"
    xmlns:ty="urn:robomda:orocos-types:1"
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
  <xsl:include href="../../common/sequence.xsl"/>
  <xsl:include href="../common/psm-kit.xsl"/>
  <xsl:include href="types.xsl"/>
  <xsl:include href="processes.xsl"/>
  <xsl:include href="jobs.xsl"/>

  <xsl:param name="package-name" as="xs:string" select="''">
    <!-- the component package (CMake project, deployer Import); '' = lower snake-case of the model name -->
  </xsl:param>

  <xsl:output method="xml" indent="no" encoding="UTF-8"/>
  <xsl:mode name="m:to-psm" on-no-match="fail"/>

  <!-- the elements the kit (../common/psm-kit.xsl) makes -->
  <xsl:variable name="fp:psm-namespace" as="xs:string" select="'urn:robomda:psm-orocos:1'"/>
  <xsl:variable name="fp:psm-prefix" as="xs:string" select="'o'"/>

  <xsl:key name="fp:type" match="ty:type" use="@primitive"/>
  <xsl:key name="fp:connection-by-instance" match="pim:connection" use="(pim:writer | pim:reader)/@instance"/>
  <xsl:key name="fp:host" match="pim:host" use="@xmi-id"/>
  <xsl:key name="fp:data-port" match="pim:data-port" use="@port"/>
  <!-- on the temporary tree of task contexts -->
  <xsl:key name="fp:task-context" match="o:task-context" use="@xmi-id"/>

  <xsl:variable name="fp:types" as="document-node()" select="doc('types.xml')"/>
  <xsl:variable name="fp:reserved-operations" as="xs:string+" select="(
      $fp:lifecycle, 'trigger', 'error', 'recover',
      'activate', 'isRunning', 'isActive', 'isConfigured', 'inFatalError', 'inException',
      'inRunTimeError', 'getPeriod', 'setPeriod', 'getCpuAffinity', 'setCpuAffinity',
      'loadService', 'getName', 'getState')"/>

  <!-- ================================================================ entry -->
  <!-- the result is indented as f:indent (common/indent.xsl) would indent
       it, in one pass: o:deployment puts its children through f:indent's
       rules (t:indented-content), so the task contexts, made once in a tree of
       their own, are not copied into an unindented result first -->
  <xsl:template match="/" as="document-node()">
    <xsl:document>
      <xsl:apply-templates select="pim:model" mode="m:to-psm"/>
    </xsl:document>
  </xsl:template>

  <xsl:template match="pim:model[empty(pim:binding)]" mode="m:to-psm" as="empty-sequence()">
    <xsl:sequence select="f:fail('ORO003', @id, 'the model has no platform binding: run xslt/m2m/bind.xsl first')"/>
  </xsl:template>

  <xsl:template match="pim:model" mode="m:to-psm" as="element(o:deployment)">
    <xsl:variable name="binding" as="element(pim:binding)" select="pim:binding"/>
    <xsl:variable name="package" as="xs:string" select="fp:package-name($package-name, .)"/>
    <xsl:variable name="instances" as="element(pim:instance)*" select="$binding/pim:instance[fp:on-target(., 'OROCOS')]"/>
    <xsl:sequence select="fp:check-targets(., $instances, 'OROCOS', 'Orocos', ('ORO005', 'ORO006', 'ORO007'))"/>
    <!-- the names and the component ids of $instances, as sets: whether an
         instance / component is in the package is one look-up -->
    <xsl:variable name="targets" as="map(xs:string, xs:boolean)"
        select="map:merge(distinct-values($instances/@name ! string(.)) ! map:entry(., true()))"/>
    <xsl:variable name="target-components" as="map(xs:string, xs:boolean)"
        select="map:merge(distinct-values($instances/@component ! string(.)) ! map:entry(., true()))"/>
    <xsl:variable name="components" as="element(pim:bound-component)*"
        select="$binding/pim:bound-component[@component ! map:contains($target-components, string(.))]"/>
    <xsl:sequence select="fp:check-class-names($components, 'ORO004')"/>
    <xsl:sequence select="fp:check-services($components, 'ORO009'), fp:check-calls($binding/pim:call, $targets, 'ORO009'),
                          fp:warn-unbound-services($instances, 'ORO010')"/>
    <!-- each task context is made once: listed here, and looked up (key
         fp:task-context) by the instances for their property values -->
    <xsl:variable name="task-contexts" as="document-node()">
      <xsl:document>
        <xsl:sequence select="$components ! fp:task-context(., $package)"/>
      </xsl:document>
    </xsl:variable>
    <!-- the runtime architecture (processes.xsl): processes in start order,
         and each kept connection's transports -->
    <xsl:sequence select="fp:oro-process-problems($instances, $targets, $binding/pim:call)"/>
    <xsl:variable name="order" as="element(pim:process)*" select="fp:oro-process-order($instances)"/>
    <!-- once: it reads every instance -->
    <xsl:variable name="single" as="xs:boolean" select="fp:oro-single-process($instances)"/>
    <xsl:variable name="files" as="map(xs:string, xs:string)"
        select="map:merge($order ! map:entry(string(@xmi-id),
                  if ($single) then f:snake-case(root(.)/pim:model/@name) else fp:oro-process-file(.)))"/>
    <!-- each process id's place in start order (the first, as index-of
         gave: a later duplicate id does not move it) -->
    <xsl:variable name="places" as="map(xs:string, xs:integer)"
        select="map:merge(for $i in 1 to count($order) return map:entry(string($order[$i]/@xmi-id), $i),
                          map{'duplicates': 'use-first'})"/>
    <xsl:variable name="connections" as="element(o:connection)*"
        select="$binding/pim:connection[fp:kept-connection(., $binding, $targets)]
                ! fp:oro-connection(., $targets, $places, $files, $package)"/>
    <xsl:variable name="corba" as="xs:boolean" select="exists($connections/o:remote) or not($single)"/>
    <!-- the deployment files that stream over ROS, as a set (a look-up per process) -->
    <xsl:variable name="ros-files" as="map(xs:string, xs:boolean)"
        select="map:merge(distinct-values($connections/o:stream[@transport eq 'ros']/@process ! string(.)) ! map:entry(., true()))"/>
    <xsl:variable name="processes" as="element(o:process)*"
        select="fp:oro-processes($instances, $corba, $order[map:contains($ros-files, map:get($files, string(@xmi-id)))]/@name)"/>
    <o:deployment xmi-id="{@id}" model-name="{@name}" deploy-name="{f:snake-case(@name)}"
                  package="{$package}" namespace="{$package}" source="{@source}">
      <xsl:variable name="parts" as="element()*">
        <xsl:sequence select="$binding/pim:library ! fp:psm-library(., $package)"/>
        <xsl:sequence select="fp:oro-types($task-contexts/o:task-context, $package, root(.))"/>
        <xsl:sequence select="$task-contexts/o:task-context, fp:oro-thread-task-context($processes, $package)"/>
        <xsl:sequence select="$binding/pim:host ! fp:oro-host(.)"/>
        <xsl:sequence select="$processes, $connections"/>
        <xsl:variable name="process-by-id" as="map(xs:string, element(o:process))"
            select="map:merge($processes ! map:entry(string(@xmi-id), .))"/>
        <xsl:for-each select="fp:in-start-order($instances)">
          <xsl:variable name="process" as="element(o:process)" select="$process-by-id(string(@execution-environment))"/>
          <xsl:variable name="thread" as="element(o:thread)?" select="$process/o:thread[@xmi-id eq current()/@thread]"/>
          <!-- a thread starts just before its first member -->
          <xsl:if test="$thread and tokenize($thread/@members)[1] eq @name">
            <xsl:sequence select="fp:oro-thread-instance($thread, key('fp:process', @execution-environment, root(.))/pim:thread[@xmi-id eq current()/@thread]/pim:activity, $package, $corba)"/>
          </xsl:if>
          <xsl:sequence select="fp:oro-instance(., $package, $binding, $task-contexts, $targets, $process, $thread, $corba)"/>
        </xsl:for-each>
      </xsl:variable>
      <!-- the job coordinators (jobs.xsl, docs/jobs.md) -->
      <xsl:variable name="children" as="element()*"
          select="$parts, fp:oro-coordinators($binding, $parts/self::o:instance, f:snake-case(@name))"/>
      <xsl:call-template name="t:indented-content">
        <xsl:with-param name="children" select="$children"/>
        <xsl:with-param name="margin" select="'&#10;'"/>
      </xsl:call-template>
    </o:deployment>
  </xsl:template>

  <!-- a kept connection: its policy, its Orocos ends in their processes
       ($files: process id -> deployment file), their transports -->
  <xsl:function name="fp:oro-connection" as="element(o:connection)">
    <xsl:param name="connection" as="element(pim:connection)"/>
    <xsl:param name="targets" as="map(xs:string, xs:boolean)"/>
    <xsl:param name="order" as="map(xs:string, xs:integer)"/>
    <xsl:param name="files" as="map(xs:string, xs:string)"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:variable name="policy" as="element(pim:policy)?" select="$connection/pim:policy"/>
    <xsl:variable name="datum" as="element(pim:data-port)?"
        select="key('fp:data-port', $connection/pim:writer[1]/@port, root($connection))[1]"/>
    <o:connection xmi-id="{$connection/@xmi-id}" name="{$connection/@name}" type="{$policy/@type}"
                  type-code="{index-of(('DATA', 'BUFFER', 'CIRCULAR_BUFFER'), $policy/@type) - 1}"
                  size="{$policy/@size}" lock-policy="{$policy/@lock-policy}"
                  lock-policy-code="{index-of(('UNSYNC', 'LOCKED', 'LOCK_FREE'), $policy/@lock-policy) - 1}"
                  init="{$policy/@init}" pull="{$policy/@pull}" topic="{$policy/@topic}">
      <xsl:for-each select="$connection/(pim:writer | pim:reader)[@instance ! map:contains($targets, string(.))]">
        <xsl:element name="o:{local-name()}">
          <xsl:attribute name="instance" select="@instance"/>
          <xsl:attribute name="port" select="@data-port"/>
          <xsl:attribute name="xmi-id" select="@port"/>
          <xsl:attribute name="process" select="map:get($files, string(key('fp:instance-by-name', @instance, root(.))/@execution-environment))"/>
        </xsl:element>
      </xsl:for-each>
      <!-- numbers, booleans and strings have RTT's MQueue, CORBA and ROS transports -->
      <xsl:for-each select="fp:oro-legs($connection, $targets, $order, $package,
                                        exists($datum/@primitive) and string($datum/@upper) = ('', '1') and empty($datum/@type))">
        <xsl:copy>
          <xsl:sequence select="@*"/>
          <xsl:for-each select="@process"><xsl:attribute name="process" select="map:get($files, string(.))"/></xsl:for-each>
        </xsl:copy>
      </xsl:for-each>
    </o:connection>
  </xsl:function>

  <!-- ===================================================== task context -->
  <xsl:function name="fp:task-context" as="element(o:task-context)">
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:variable name="component" as="element(pim:component)" select="key('fp:id', $bc/@component, root($bc))"/>
    <xsl:variable name="wrapper" as="xs:boolean" select="exists(fp:realization($bc))"/>
    <!-- named as bound: components of one name in different packages by their qualified names -->
    <xsl:variable name="class" as="xs:string" select="f:upper-camel($bc/@name)"/>
    <o:task-context xmi-id="{$component/@id}" name="{$bc/@name}" class="{$class}" namespace="{$package}"
                    type-name="{$package}::{$class}" kind="{if ($wrapper) then 'wrapper' else 'base'}"
                    generated-class="{if ($wrapper) then $class else $class || 'Base'}">
      <xsl:sequence select="fp:psm-doc($component)"/>
      <xsl:sequence select="fp:psm-realizing-class($bc)"/>
      <xsl:sequence select="fp:psm-hooks($bc)"/>
      <!-- some instance of the component is non-periodic (see o:port/@event) -->
      <xsl:variable name="non-periodic" as="xs:boolean"
          select="some $a in key('fp:instance-of', $bc/@component, root($bc))/pim:activity
                  satisfies number($a/@period) eq 0"/>
      <xsl:sequence select="$bc/pim:data-port ! fp:oro-port(., $non-periodic)"/>
      <xsl:sequence select="fp:offered-operations($bc, $fp:reserved-operations) ! fp:operation(., fp:provided-service($bc, .))"/>
      <xsl:sequence select="$bc/pim:service-port[@role eq 'required'] ! fp:required-service(., $bc)"/>
      <xsl:variable name="configurable" as="element(pim:attribute)*" select="fp:configurable-attributes($bc)"/>
      <xsl:variable name="convention" as="element(pim:attribute)*"
          select="if (exists($configurable)) then () else fp:convention-attributes($bc)"/>
      <xsl:variable name="typed" as="element(pim:attribute)*" select="$convention[exists(fp:oro-type(.))][not(@primitive = 'void')]"/>
      <xsl:sequence select="fp:warn-skipped-attributes($convention except $typed, 'ORO013', 'Orocos property')"/>
      <xsl:sequence select="($configurable, $typed) ! fp:property(.)"/>
    </o:task-context>
  </xsl:function>

  <!-- an input port triggers updateHook (event port) only where some
       instance of the component is non-periodic ($non-periodic): a periodic
       activity already runs updateHook on its own clock -->
  <xsl:function name="fp:oro-port" as="element(o:port)">
    <xsl:param name="data-port" as="element(pim:data-port)"/>
    <xsl:param name="non-periodic" as="xs:boolean"/>
    <xsl:for-each select="$data-port">
      <xsl:variable name="type" as="element(ty:type)"
          select="fp:oro-required-type(., @port, 'port ''' || @port-name || ''' (datum ''' || @datum-name || ''' of interface ''' || @interface-name || ''')')"/>
      <xsl:variable name="accessor" as="xs:string" select="fp:accessor(.)"/>
      <o:port xmi-id="{@port}" direction="{@direction}"
              event="{@direction eq 'in' and $non-periodic and not(@constant = ('true', '1'))}"
              rtt-class="{if (@direction eq 'out') then 'RTT::OutputPort' else 'RTT::InputPort'}&lt;{$type/@cpp}&gt;"
              name="{@name}" member="port_{@name}" interface="{@interface-name}" datum="{@datum-name}"
              accessor="{$accessor}" accessor-declared="{fp:accessor-declared(.)}" sample="{$type/@sample}">
        <xsl:if test="@constant = ('true', '1')"><xsl:attribute name="constant" select="'true'"/></xsl:if>
        <xsl:sequence select="fp:oro-typed($type)"/>
        <xsl:sequence select="fp:psm-doc(key('fp:id', @port, root(.)))"/>
      </o:port>
    </xsl:for-each>
  </xsl:function>

  <xsl:function name="fp:operation" as="element(o:operation)">
    <xsl:param name="operation" as="element(pim:operation)"/>
    <xsl:param name="service" as="xs:string?"/>
    <xsl:variable name="tag" as="xs:string?"
        select="f:stereotype($operation, 'OperationThread')/pim:tag[@name eq 'thread'][1]/@value"/>
    <xsl:variable name="thread" as="xs:string"
        select="if (exists($tag)) then (if (matches($tag, 'CLIENT', 'i')) then 'RTT::ClientThread' else 'RTT::OwnThread')
                else if ($operation/@query = ('true', '1')) then 'RTT::ClientThread' else 'RTT::OwnThread'"/>
    <xsl:variable name="result" as="element(pim:parameter)?" select="$operation/pim:parameter[@direction eq 'return'][1]"/>
    <xsl:variable name="result-type" as="element(ty:type)"
        select="if ($result) then fp:oro-required-type($result, $operation/@id, 'result of operation ''' || $operation/@name || '''')
                else key('fp:type', 'void', $fp:types)"/>
    <o:operation xmi-id="{$operation/@id}" name="{f:cpp-identifier($operation/@name)}" thread="{$thread}"
                 return-type="{$result-type/@cpp}" return-primitive="{$result-type/@primitive}"
                 return-sample="{$result-type/@sample}">
      <xsl:if test="exists($service)"><xsl:attribute name="service" select="$service"/></xsl:if>
      <xsl:sequence select="fp:psm-doc($operation)"/>
      <xsl:for-each select="$operation/pim:parameter[@direction ne 'return']">
        <xsl:variable name="type" as="element(ty:type)"
            select="fp:oro-required-type(., @id, 'parameter ''' || @name || ''' of operation ''' || $operation/@name || '''')"/>
        <o:parameter xmi-id="{@id}" name="{f:cpp-identifier((@name[normalize-space(.)], 'arg' || position())[1])}"
                     direction="{@direction}"
                     decl-type="{if (@direction = ('out', 'inout')) then $type/@cpp || '&amp;'
                                 else if ($type/@pass eq 'cref') then 'const ' || $type/@cpp || '&amp;' else $type/@cpp}">
          <xsl:sequence select="fp:oro-typed($type)"/>
          <xsl:sequence select="fp:psm-doc(.)"/>
        </o:parameter>
      </xsl:for-each>
      <!-- a result of a type of the model: the header it needs, the
           typekit's type (types.xsl reads every typed element) -->
      <xsl:if test="$result-type/@type-ref">
        <o:result xmi-id="{$result/@id}">
          <xsl:sequence select="fp:oro-typed($result-type)"/>
        </o:result>
      </xsl:if>
    </o:operation>
  </xsl:function>

  <!-- a required interface (seed 003): an RTT::OperationCaller per
       operation, in the service requester named after the interface; the
       component's code calls the operation by its name where the generated
       class defines it (base kind; wrapper kind: where the realizing class
       declares it, virtual, for the wrapper to override; else ORO011) -->
  <xsl:function name="fp:required-service" as="element(o:required-service)">
    <xsl:param name="service-port" as="element(pim:service-port)"/>
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <o:required-service xmi-id="{$service-port/@port}" name="{$service-port/@interface-name}" port="{$service-port/@port-name}">
      <xsl:for-each select="fp:interface-operations($service-port)">
        <xsl:variable name="operation" as="element(o:operation)" select="fp:operation(., ())"/>
        <o:operation-caller member="caller_{$operation/@name}"
            forward="{fp:calls-declared($bc, $service-port, ., 'caller caller_' || $operation/@name, 'ORO011')}">
          <xsl:sequence select="$operation/@*, $operation/node()"/>
        </o:operation-caller>
      </xsl:for-each>
    </o:required-service>
  </xsl:function>

  <!-- (xml value, script literal, C++ literal) of a default value -->
  <xsl:function name="fp:oro-values" as="xs:string+">
    <xsl:param name="value" as="xs:string"/>
    <xsl:param name="type" as="element(ty:type)"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:variable name="primitive" as="xs:string" select="$type/@primitive"/>
    <xsl:variable name="kind" as="xs:string"
        select="if ($primitive = ('string', 'boolean', 'char')) then $primitive
                else if ($primitive = ('float32', 'float64')) then 'real' else 'integer'"/>
    <xsl:variable name="parsed" as="xs:string" select="fp:parse-default($value, $kind, $primitive, $id, 'ORO002')"/>
    <xsl:sequence select="
      if ($kind eq 'string') then ($parsed, fp:cpp-string($parsed), fp:cpp-string($parsed))
      else if ($kind eq 'boolean') then (if ($parsed eq 'true') then '1' else '0', $parsed, $parsed)
      else if ($kind eq 'char') then
        (if (string-length($parsed) eq 1 and matches($parsed, '[A-Za-z0-9 _.,;:+\-*/=!?]'))
         then ($parsed, '''' || $parsed || '''', '''' || $parsed || '''')
         else f:fail('ORO002', $id, 'default ''' || $value || ''' is not a single plain character'))
      else if ($kind eq 'real') then
        ($parsed, fp:decimal($parsed), fp:decimal($parsed) || (if ($primitive eq 'float32') then 'f' else ''))
      else ($parsed, $parsed, $parsed)"/>
  </xsl:function>

  <xsl:function name="fp:property" as="element(o:property)">
    <xsl:param name="attribute" as="element(pim:attribute)"/>
    <xsl:variable name="type" as="element(ty:type)"
        select="fp:oro-required-type($attribute, $attribute/@id, 'property ''' || $attribute/@name || '''')"/>
    <!-- a structured value: the whole tree, always (its leaves without a
         model value hold the type's zero); of a data type, or an array of
         one, only once fp:type-depth found no data type that contains
         itself (it fails with ORO012: the tree would have no end) -->
    <xsl:variable name="tree" as="element(o:value)?"
        select="if (empty($type/@kind)) then ()
                else if (exists($type/@type-ref) and fp:type-depth(key('fp:id', $type/@type-ref, root($attribute)), (), 'ORO012') lt 0) then ()
                else fp:oro-value($attribute, $type, $attribute/@name, '')"/>
    <xsl:variable name="values" as="xs:string*"
        select="if ($attribute/@default and empty($tree)) then fp:oro-values($attribute/@default, $type, $attribute/@id) else ()"/>
    <o:property xmi-id="{$attribute/@id}" name="{f:cpp-identifier($attribute/@name)}"
                member="{f:cpp-identifier($attribute/@name)}"
                cpp-default="{($tree/@cpp-value, $values[3], $type/@sample)[1]}">
      <xsl:sequence select="fp:oro-typed($type)"/>
      <xsl:if test="exists($values)">
        <xsl:attribute name="xml-default" select="$values[1]"/>
        <xsl:attribute name="script-default" select="$values[2]"/>
      </xsl:if>
      <xsl:sequence select="fp:psm-doc($attribute)"/>
      <xsl:sequence select="$tree"/>
    </o:property>
  </xsl:function>

  <!-- a host, with its computational resources and buses (seed 002) -->
  <xsl:function name="fp:oro-host" as="element(o:host)">
    <xsl:param name="host" as="element(pim:host)"/>
    <o:host xmi-id="{$host/@xmi-id}" name="{$host/@name}" hostname="{$host/@hostname}" address="{$host/@address}">
      <xsl:sequence select="fp:psm-host-resources($host)"/>
    </o:host>
  </xsl:function>

  <!-- ========================================================= instance -->
  <xsl:function name="fp:oro-instance" as="element(o:instance)">
    <xsl:param name="instance" as="element(pim:instance)"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:param name="binding" as="element(pim:binding)"/>
    <xsl:param name="task-contexts" as="document-node()"/>
    <xsl:param name="targets" as="map(xs:string, xs:boolean)"/>
    <xsl:param name="process" as="element(o:process)"/>
    <xsl:param name="thread" as="element(o:thread)?"/>
    <!-- a CORBA server: the deployment uses CORBA (every instance can be reached) -->
    <xsl:param name="server" as="xs:boolean"/>
    <xsl:variable name="task-context" as="element(o:task-context)"
        select="key('fp:task-context', $instance/@component, $task-contexts)"/>
    <!-- f:upper-camel of the component's name, made once by fp:task-context -->
    <xsl:variable name="class" as="xs:string" select="$task-context/@class"/>
    <xsl:variable name="activity" as="element(pim:activity)" select="$instance/pim:activity"/>
    <xsl:variable name="connections" as="element(pim:connection)*"
        select="key('fp:connection-by-instance', $instance/@name, root($instance))
                [fp:kept-connection(., $binding, $targets)]"/>
    <o:instance xmi-id="{$instance/@xmi-id}" name="{$instance/@name}" task-context="{$class}"
                type-name="{$package}::{$class}" process="{$process/@file}" server="{$server}">
      <!-- in a job, not in the initial one: configured at deployment, started by a switch (jobs.xsl) -->
      <xsl:if test="fp:oro-idle($instance)"><xsl:attribute name="idle" select="'true'"/></xsl:if>
      <xsl:for-each select="key('fp:id', $instance/@host, root($instance))">
        <xsl:attribute name="host" select="(key('fp:host', @id, root($instance))/@hostname, @name)[1]"/>
      </xsl:for-each>
      <xsl:sequence select="fp:oro-activity($activity, $thread/@name)"/>
      <xsl:variable name="calls" as="element(pim:call)*" select="key('fp:call-by-caller', $instance/@name, root($instance))"/>
      <xsl:for-each select="distinct-values(($connections[pim:reader/@instance = $instance/@name]
                              [exists(key('fp:id', @interface, root($instance))/pim:operation)]
                              /pim:writer/@instance[. ne $instance/@name], $calls/pim:provider/@instance))">
        <o:peer instance="{.}"/>
      </xsl:for-each>
      <xsl:for-each select="$calls">
        <o:call xmi-id="{@xmi-id}" name="{@name}" service="{key('fp:id', @interface, root(.))/@name}"
                provider="{pim:provider/@instance}"/>
      </xsl:for-each>
      <xsl:for-each select="$connections">
        <xsl:variable name="connection" as="element(pim:connection)" select="."/>
        <xsl:for-each select="distinct-values((pim:writer | pim:reader)[@instance eq $instance/@name]/@data-port)">
          <o:port-connection port="{.}" connection="{$connection/@name}"/>
        </xsl:for-each>
      </xsl:for-each>
      <!-- the model's value: one set by the enclosing parts and composites
           (seed 003), else the default -->
      <xsl:sequence select="fp:warn-unused-values($instance, $task-context/o:property/@xmi-id, 'ORO008')"/>
      <xsl:for-each select="$task-context/o:property">
        <xsl:variable name="set" as="element(pim:property-value)?" select="$instance/pim:property-value[@attribute eq current()/@xmi-id]"/>
        <xsl:variable name="values" as="xs:string*"
            select="if ($set and empty(o:value)) then fp:oro-values($set/@value, fp:oro-required-type(key('fp:id', @xmi-id, root($instance)), @xmi-id, 'property ''' || @name || ''''), $set/@holder)
                    else (@xml-default, @script-default)"/>
        <xsl:choose>
          <xsl:when test="o:value">
            <o:property-value name="{@name}" xml-type="{@xml-type}">
              <xsl:sequence select="if (empty($set)) then o:value
                  else if (@type-kind eq 'enum') then fp:oro-leaf($set/@value, fp:oro-required-type(key('fp:id', @xmi-id, root($instance)),
                                                      @xmi-id, 'property ''' || @name || ''''), $set, @name, '')
                  else f:fail('ORO002', $set/@holder, 'the value ''' || $set/@value || ''' set on property ''' || @name
                              || ''' of instance ''' || $instance/@name || ''': the value of a data type or an array comes from'
                              || ' the defaults of its attributes, not from a part''s slot')"/>
            </o:property-value>
          </xsl:when>
          <xsl:when test="exists($values)">
            <o:property-value name="{@name}" xml-type="{@xml-type}" value="{$values[1]}" script-value="{$values[2]}"/>
          </xsl:when>
        </xsl:choose>
      </xsl:for-each>
      <xsl:for-each select="$instance/pim:start-after[@instance ! map:contains($targets, string(.))]">
        <o:start-after instance="{@instance}" xmi-id="{@xmi-id}"/>
      </xsl:for-each>
      <!-- an earlier instance on another middleware: no start script of this package can wait for it -->
      <xsl:for-each select="$instance/pim:start-after[not(map:contains($targets, string(@instance)))]">
        <xsl:sequence select="f:warn('ORO120', @xmi-id, 'instance ''' || $instance/@name || ''' starts after '''
            || @instance || ''' (StartAfter), which is not deployed on Orocos: the Orocos start scripts cannot wait'
            || ' for it; start it (with its own target''s files) before the process of ''' || $instance/@name || '''')"/>
      </xsl:for-each>
    </o:instance>
  </xsl:function>
</xsl:stylesheet>
