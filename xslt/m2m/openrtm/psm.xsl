<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/openrtm/psm.xsl - bound PIM -> OpenRTM-aist 2.0 PSM (seed 000,
  Table 5: data ports, service ports, configuration, component states).

  Reads:   a bound PIM, urn:robomda:pim:1 with pim:binding (xslt/m2m/bind.xsl).
  Writes:  urn:robomda:psm-openrtm:1 (schemas/psm-openrtm/1/psm-openrtm.xsd),
           indented as f:indent (common/indent.xsl) indents it.
  Data:    xslt/m2m/openrtm/types.xml (primitive kind -> TimedXxx, C++,
           configuration type).
  Uses:    xslt/m2m/openrtm/types.xsl (port types, r:data-types; RTM021, RTM022).
  Uses:    xslt/m2m/common/psm-kit.xsl (wrapper, hooks, attributes, defaults).
  Uses:    xslt/m2m/openrtm/jobs.xsl (the job coordinators, R7).
  Params:  package-name (the CMake project; '' = lower snake case of the model name).

  Rules (docs/openrtm.md)
  R1  one RT-Component type per component with an OPENRTM instance
      (RTC::DataFlowComponentBase), class UpperCamel(component name), type
      name the same, category the package. kind "wrapper" when the component
      has a realizing class (the RTC derives from it and its actions call the
      class's lifecycle operations), else "base" (a generated <class>Base and
      a user class <class>, written once).
  R2  one data port per bound data port: out -> RTC::OutPort<T>, in ->
      RTC::InPort<T>, T the TimedXxx of BasicDataType.idl for a single
      primitive (types.xml), RTC::TimedXxxSeq for an array of one, else a
      Timed type of the package's generated IDL (types.xsl); member
      m_<name>Out / m_<name>In, datum m_<name>. The package's data types
      get C++ headers (include/<Name>.hpp) and, those the ports carry, IDL.
  R3  configuration: the Configurable attributes of the realizing class (base
      kind: of the component), without any the convention's choice (public,
      protected, not static, not read-only): one parameter of
      configuration set "default" with the model default; the value an
      instance's part sets goes into the instance's .conf. A single
      primitive as coil::stringTo reads it; a data type, an enumeration or
      an array (@kind struct / enum / sequence, @array, @size, @element) in
      the text form of types.xsl fp:rtm-conf-text, which the generated
      <pkg>_conf.h reads.
  R4  execution context: PeriodicExecutionContext at rate 1 / period (Hz),
      one per instance (exec_cxt.periodic.rate in the instance's .conf); a
      CPU affinity mask other than 0 as the list of its CPU numbers,
      counted from 1 (RTM023 for a mask OpenRTM 2.0 cannot pin).
  R5  connections: dataflow push (pull when the policy pulls), subscription
      flush, buffer length = policy size, full policy overwrite for DATA and
      CIRCULAR_BUFFER, do_nothing (drop the new sample) for BUFFER.
  R5b operations: a service port per provided / required interface
      (RTC::CorbaPort), its interface in a generated IDL (module = package;
      in parameters and results of single primitive types); an operation
      call between two instances of the package, a service-port connection.
  R6  processes: one manager (rtcd2) per pim:process holding OpenRTM
      instances, in the order of their first instance's start order; each
      creates, connects and activates its instances in start order
      (rtc.conf precreate / preconnect / preactivation); a connection whose
      ends are in two processes is made by the later one through the
      naming service.
  R7  jobs (docs/jobs.md): per subsystem with a member here an RT-Component
      <Subsystem>Coordinator (r:coordinator, jobs.xsl) in the manager of its
      initial job's first member; an instance of a job other than the
      initial one is created, not activated (r:instance idle="true").
  Deployment: instances with middleware OpenRTM (all instances when none is
  on OPENRTM, RTM006); connections with ends on both sides.

  Errors (urn:robomda:error, f:fail):
    RTM002  a configuration default or value not valid for its type
    RTM003  the input has no pim:binding (run xslt/m2m/bind.xsl first)
    RTM004  two component types map to the same C++ class name
    RTM005  nothing to generate: the model has no component instance
    RTM021, RTM022  (types.xsl) a data type that cannot be declared; a bad default of its attribute
  Warnings (f:warn):
    JOB041, JOB042  the job coordinators (jobs.xsl): a member of a subsystem's jobs on
            another middleware; a value a job sets on no configuration parameter
    RTM001  a data port whose datum has no OpenRTM data type (an
            enumeration without a literal): no port
    RTM006  no instance is deployed on OpenRTM: all are generated anyway
    RTM007  an instance deployed on another middleware is left out
    RTM008  a value a part sets on an attribute that is no parameter
    RTM009  a service port whose interface has an operation with an out /
            inout parameter or a type other than a single primitive: no port
    RTM010  priority or real-time scheduler of an activity: OpenRTM's
            PeriodicExecutionContext has neither setting
    RTM011  a non-periodic activity: the execution context runs at 1000 Hz
    RTM012  a connection end on another middleware: the connection is left out
    RTM013  an attribute that would be a configuration parameter whose type
            OpenRTM has none for (an enumeration without a literal, or an
            array of one): it is no parameter
    RTM014  a connection policy setting OpenRTM has no counterpart for
            (init: the last sample on connecting)
    RTM015  a required operation the realizing class does not declare (no
            override is generated; the class cannot call it)
    RTM023  a CPU affinity mask other than CPUs 0 to n-1: OpenRTM-aist
            2.0 pins the execution context's thread to the first n CPUs
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:math="http://www.w3.org/2005/xpath-functions/math"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:r="urn:robomda:psm-openrtm:1"
    xmlns:ty="urn:robomda:openrtm-types:1"
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
  <xsl:include href="jobs.xsl"/>

  <xsl:param name="package-name" as="xs:string" select="''"/>

  <xsl:output method="xml" indent="no" encoding="UTF-8"/>
  <xsl:mode name="m:to-psm" on-no-match="fail"/>

  <xsl:variable name="fp:psm-namespace" as="xs:string" select="'urn:robomda:psm-openrtm:1'"/>
  <xsl:variable name="fp:psm-prefix" as="xs:string" select="'r'"/>

  <xsl:key name="fp:type" match="ty:type" use="@primitive"/>
  <xsl:key name="fp:host" match="pim:host" use="@xmi-id"/>
  <xsl:key name="fp:process" match="pim:process" use="@xmi-id"/>
  <xsl:key name="fp:instance-by-name" match="pim:instance" use="@name"/>
  <xsl:key name="fp:data-port" match="pim:data-port" use="@port"/>
  <xsl:key name="fp:rtc" match="r:component" use="@xmi-id"/>
  <!-- a generated service port by its id (the ends of an operation call):
       a look-up per end, not a scan of every component's ports (issue 35) -->
  <xsl:key name="fp:service-port" match="r:service-port" use="@xmi-id"/>

  <xsl:variable name="fp:types" as="document-node()" select="doc('types.xml')"/>

  <xsl:template match="/" as="document-node()">
    <xsl:document>
      <xsl:apply-templates select="pim:model" mode="m:to-psm"/>
    </xsl:document>
  </xsl:template>

  <xsl:template match="pim:model[empty(pim:binding)]" mode="m:to-psm" as="empty-sequence()">
    <xsl:sequence select="f:fail('RTM003', @id, 'the model has no platform binding: run xslt/m2m/bind.xsl first')"/>
  </xsl:template>

  <xsl:template match="pim:model" mode="m:to-psm" as="element(r:system)">
    <xsl:variable name="binding" as="element(pim:binding)" select="pim:binding"/>
    <xsl:variable name="package" as="xs:string" select="fp:package-name($package-name, .)"/>
    <xsl:variable name="instances" as="element(pim:instance)*" select="$binding/pim:instance[fp:on-target(., 'OpenRTM')]"/>
    <xsl:sequence select="fp:check-targets(., $instances, 'OpenRTM', 'OpenRTM', ('RTM005', 'RTM006', 'RTM007'))"/>
    <!-- the names of the package's instances, as a set; its components, by key -->
    <xsl:variable name="targets" as="map(xs:string, xs:boolean)"
        select="map:merge($instances ! map:entry(string(@name), true()), map { 'duplicates': 'use-first' })"/>
    <xsl:variable name="components" as="element(pim:bound-component)*"
        select="key('fp:bound-component', distinct-values($instances/@component ! string(.)), root($binding))"/>
    <xsl:sequence select="fp:check-class-names($components, 'RTM004')"/>
    <xsl:variable name="rtcs" as="document-node()">
      <xsl:document>
        <xsl:sequence select="$components ! fp:rtm-component(., $package)"/>
      </xsl:document>
    </xsl:variable>
    <xsl:variable name="ordered" as="element(pim:instance)*" select="fp:in-start-order($instances)"/>
    <xsl:variable name="processes" as="element(pim:process)*"
        select="distinct-values($ordered/@execution-environment ! string(.)) ! key('fp:process', ., root($binding))"/>
    <xsl:variable name="single" as="xs:boolean" select="count($processes) le 1"/>
    <xsl:variable name="files" as="map(xs:string, xs:string)"
        select="map:merge($processes ! map:entry(string(@xmi-id), if ($single) then f:snake-case(root(.)/pim:model/@name) else fp:rtm-process-file(.)))"/>
    <r:system xmi-id="{@id}" model-name="{@name}" deploy-name="{f:snake-case(@name)}" package="{$package}" source="{@source}">
      <xsl:variable name="children" as="element()*">
        <xsl:sequence select="$binding/pim:library ! fp:psm-library(., $package)"/>
        <xsl:sequence select="fp:rtm-data-types($components, $rtcs/r:component/r:data-port, $package, root($binding))"/>
        <!-- one IDL interface per interface a service port carries -->
        <xsl:for-each-group select="$rtcs/r:component/r:service-port" group-by="string(@interface)">
          <r:interface name="{current-grouping-key()}" module="{$package}">
            <xsl:sequence select="current-group()[1]/r:operation ! fp:rtm-idl-operation(.)"/>
          </r:interface>
        </xsl:for-each-group>
        <xsl:sequence select="$rtcs/r:component"/>
        <xsl:for-each select="$binding/pim:host">
          <r:host xmi-id="{@xmi-id}" name="{@name}" hostname="{@hostname}" address="{@address}"/>
        </xsl:for-each>
        <xsl:for-each select="$processes">
          <xsl:variable name="members" as="element(pim:instance)*" select="$ordered[@execution-environment eq current()/@xmi-id]"/>
          <r:process xmi-id="{@xmi-id}" name="{@name}" file="{map:get($files, string(@xmi-id))}"
                     host="{(key('fp:host', @host, root(.))/@hostname, 'localhost')[1]}"
                     host-name="{(key('fp:host', @host, root(.))/@name, 'localhost')[1]}" members="{$members ! string(@name)}"/>
        </xsl:for-each>
        <xsl:sequence select="$binding/pim:connection[fp:kept-connection(., $binding, $targets)] ! fp:rtm-connection(., $targets, $files)"/>
        <xsl:sequence select="$binding/pim:call ! fp:rtm-service-connection(., $targets, $rtcs)"/>
        <xsl:sequence select="$ordered ! fp:rtm-instance(., $rtcs, $targets, $files)"/>
        <xsl:sequence select="fp:rtm-coordinators($binding, $ordered, $rtcs, $files)"/>
      </xsl:variable>
      <xsl:call-template name="t:indented-content">
        <xsl:with-param name="children" select="$children"/>
        <xsl:with-param name="margin" select="'&#10;'"/>
      </xsl:call-template>
    </r:system>
  </xsl:template>

  <xsl:function name="fp:rtm-process-file" as="xs:string">
    <xsl:param name="process" as="element(pim:process)"/>
    <xsl:variable name="host" as="element(pim:host)?" select="key('fp:host', $process/@host, root($process))"/>
    <xsl:sequence select="string-join(($host/@name, $process/@name) ! f:snake-case(.), '_')"/>
  </xsl:function>

  <!-- ========================================================= component -->
  <xsl:function name="fp:rtm-component" as="element(r:component)">
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:variable name="component" as="element()" select="key('fp:id', $bc/@component, root($bc))"/>
    <xsl:variable name="wrapper" as="xs:boolean" select="exists(fp:realization($bc))"/>
    <!-- named as bound: components of one name in different packages by their qualified names -->
    <xsl:variable name="class" as="xs:string" select="f:upper-camel($bc/@name)"/>
    <r:component xmi-id="{$component/@id}" name="{$bc/@name}" class="{$class}" type-name="{$class}"
                 category="{$package}" kind="{if ($wrapper) then 'wrapper' else 'base'}"
                 generated-class="{if ($wrapper) then $class else $class || 'Base'}">
      <xsl:sequence select="fp:psm-doc($component)"/>
      <xsl:sequence select="fp:psm-realizing-class($bc)"/>
      <xsl:sequence select="fp:psm-hooks($bc)"/>
      <xsl:for-each select="$bc/pim:data-port">
        <xsl:variable name="type" as="attribute()*" select="fp:rtm-port-type(., $package)"/>
        <xsl:choose>
          <xsl:when test="empty($type)">
            <xsl:sequence select="f:warn('RTM001', string(@port), 'port ''' || @port-name || ''' of component ''' || $bc/@name
                || ''' carries ' || fp:type-label(.) || fp:library-note(.) || ', which has no OpenRTM
 data type (an enumeration needs a literal):'
                || ' the RT-Component has no such port')"/>
          </xsl:when>
          <xsl:otherwise>
            <r:data-port xmi-id="{@port}" name="{@name}" direction="{@direction}">
              <xsl:sequence select="$type"/>
              <xsl:attribute name="interface" select="@interface-name"/>
              <xsl:attribute name="datum" select="@datum-name"/>
              <xsl:attribute name="member" select="'m_' || @name"/>
              <xsl:attribute name="port-member" select="'m_' || @name || (if (@direction eq 'out') then 'Out' else 'In')"/>
              <xsl:attribute name="accessor" select="fp:accessor(.)"/>
              <xsl:attribute name="accessor-declared" select="fp:accessor-declared(.)"/>
              <xsl:if test="@constant = ('true', '1')">
                <!-- a configuration constant (seed 004, «Constant»): an input is read before configure() -->
                <xsl:attribute name="constant" select="'true'"/>
              </xsl:if>
              <xsl:sequence select="fp:psm-doc(key('fp:id', @port, root(.)))"/>
            </r:data-port>
          </xsl:otherwise>
        </xsl:choose>
      </xsl:for-each>
      <xsl:sequence select="$bc/pim:service-port ! fp:rtm-service-port(., $bc, $package)"/>
      <xsl:variable name="configurable" as="element(pim:attribute)*" select="fp:configurable-attributes($bc)"/>
      <xsl:variable name="convention" as="element(pim:attribute)*"
          select="if (exists($configurable)) then () else fp:convention-attributes($bc)"/>
      <xsl:variable name="typed" as="element(pim:attribute)*" select="$convention[exists(fp:rtm-conf-type(., $package))]"/>
      <xsl:sequence select="fp:warn-skipped-attributes($convention except $typed, 'RTM013', 'OpenRTM configuration parameter')"/>
      <xsl:for-each select="$configurable[empty(fp:rtm-conf-type(., $package))]">
        <xsl:sequence select="f:warn('RTM013', string(@id), 'attribute ''' || @name || ''' (Configurable) has type '
            || fp:type-label(.) || ', which has no OpenRTM type (an enumeration needs a literal): it is no parameter')"/>
      </xsl:for-each>
      <xsl:for-each select="($configurable, $typed)[exists(fp:rtm-conf-type(., $package))]">
        <xsl:variable name="type" as="element(ty:type)" select="fp:rtm-conf-type(., $package)"/>
        <xsl:choose>
          <xsl:when test="$type/@conf">
            <r:parameter xmi-id="{@id}" name="{f:cpp-identifier(@name)}" type="{$type/@conf}" primitive="{$type/@primitive}"
                         default="{if (@default) then fp:rtm-value(@default, $type, @id) else fp:rtm-zero($type)}">
              <xsl:sequence select="fp:psm-doc(.)"/>
            </r:parameter>
          </xsl:when>
          <xsl:otherwise>
            <!-- a structured parameter: its value in the text form <pkg>_conf.h reads (types.xsl) -->
            <r:parameter xmi-id="{@id}" name="{f:cpp-identifier(@name)}" type="{$type/@cpp}" primitive="" kind="{$type/@kind}"
                         default="{fp:rtm-conf-text(., $type, @default[normalize-space(.)], @id, 'RTM002')}">
              <xsl:sequence select="fp:rtm-conf-bounds($type)"/>
              <xsl:sequence select="fp:psm-doc(.)"/>
            </r:parameter>
          </xsl:otherwise>
        </xsl:choose>
      </xsl:for-each>
    </r:component>
  </xsl:function>

  <!-- a service port (seed 000 Table 5: methods): an RTC::CorbaPort with
       the interface of a generated IDL (module = package); provided: a
       servant calling the component's operation, required: a consumer the
       generated override of the realizing class's declared operation
       calls. An operation with an out / inout parameter or a type other
       than a single primitive leaves the port out (RTM009) -->
  <xsl:function name="fp:rtm-service-port" as="element(r:service-port)?">
    <xsl:param name="sp" as="element(pim:service-port)"/>
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:variable name="operations" as="element(pim:operation)*" select="fp:interface-operations($sp)"/>
    <xsl:variable name="bad" as="element()*"
        select="$operations/pim:parameter[@direction = ('out', 'inout') or exists(fp:type-def(.)) or exists(fp:array(.))
                                          or empty(key('fp:type', string(@primitive), $fp:types))
                                          or (@primitive eq 'void' and @direction ne 'return')]"/>
    <xsl:choose>
      <xsl:when test="exists($bad)">
        <xsl:sequence select="f:warn('RTM009', string($sp/@port), 'service port ''' || $sp/@port-name || ''' (' || $sp/@role || ' interface '''
            || $sp/@interface-name || ''') of component ''' || $bc/@name || ''': parameter ''' || $bad[1]/@name || ''' of operation '''
            || $bad[1]/../@name || ''' is ' || (if ($bad[1]/@direction = ('out', 'inout')) then $bad[1]/@direction else fp:type-label($bad[1]))
            || ', which the generated IDL does not carry (in parameters and results of single primitive types only): no such port')"/>
      </xsl:when>
      <xsl:otherwise>
        <r:service-port xmi-id="{$sp/@port}" name="{$sp/@port-name}" role="{$sp/@role}" interface="{$sp/@interface-name}"
                        idl-type="{$package}::{$sp/@interface-name}" port-member="m_{$sp/@port-name}Port"
                        member="m_{$sp/@port-name}{if ($sp/@role eq 'provided') then 'Servant' else ''}">
          <xsl:for-each select="$operations">
            <xsl:variable name="result" as="element(ty:type)"
                select="key('fp:type', string((pim:parameter[@direction eq 'return']/@primitive, 'void')[1]), $fp:types)"/>
            <r:operation xmi-id="{@id}" name="{f:cpp-identifier(@name)}" return-primitive="{$result/@primitive}"
                         return-cpp="{$result/@cpp}" return-idl="{$result/@idl}" return-corba="{$result/@corba}" return-sample="{$result/@sample}">
              <xsl:if test="$sp/@role eq 'required'">
                <xsl:attribute name="forward" select="fp:calls-declared($bc, $sp, ., 'override of ' || @name, 'RTM015')"/>
              </xsl:if>
              <xsl:for-each select="pim:parameter[@direction ne 'return']">
                <xsl:variable name="type" as="element(ty:type)" select="key('fp:type', string(@primitive), $fp:types)"/>
                <r:parameter name="{f:cpp-identifier((@name[normalize-space(.)], 'arg' || position())[1])}" primitive="{$type/@primitive}"
                             idl="{$type/@idl}" corba="{if ($type/@primitive eq 'string') then 'const char*' else $type/@corba}"
                             decl-type="{if ($type/@primitive eq 'string') then 'const std::string&amp;' else $type/@cpp}"/>
              </xsl:for-each>
            </r:operation>
          </xsl:for-each>
        </r:service-port>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <!-- the type of a configuration parameter: a single primitive other than
       void (coil::stringTo reads it), else any type OpenRTM has for it (a
       data type, an enumeration with a literal, an array of these or of
       primitives: the generated <pkg>_conf.h reads it) -->
  <xsl:function name="fp:rtm-conf-type" as="element(ty:type)?">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:sequence select="if (exists(fp:type-def($typed)) or exists(fp:array($typed))) then fp:rtm-type($typed, $package)
                          else key('fp:type', string($typed/@primitive), $fp:types)[@conf]"/>
  </xsl:function>

  <!-- a value in the text form of a .conf file (coil::stringTo reads it) -->
  <xsl:function name="fp:rtm-value" as="xs:string">
    <xsl:param name="value" as="xs:string"/>
    <xsl:param name="type" as="element(ty:type)"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:variable name="kind" as="xs:string" select="$type/@kind"/>
    <xsl:variable name="parsed" as="xs:string" select="fp:parse-default($value, $kind, string($type/@primitive), $id, 'RTM002')"/>
    <xsl:sequence select="
      if ($kind eq 'char' and string-length($parsed) ne 1)
      then f:fail('RTM002', $id, 'default ''' || $value || ''' is not a single character')
      else if ($kind eq 'string' and matches($parsed, '[&#10;&#13;\\]'))
      then f:fail('RTM002', $id, 'default ''' || $value || ''' has a line break or backslash, which a .conf value cannot hold')
      else if ($kind eq 'real') then fp:decimal($parsed) else $parsed"/>
  </xsl:function>

  <xsl:function name="fp:rtm-zero" as="xs:string">
    <xsl:param name="type" as="element(ty:type)"/>
    <xsl:sequence select="if ($type/@primitive eq 'boolean') then 'false' else if ($type/@primitive = ('string', 'char')) then ''
                          else if ($type/@primitive = ('float32', 'float64')) then '0.0' else '0'"/>
  </xsl:function>

  <!-- ======================================================== connection -->
  <xsl:function name="fp:rtm-connection" as="element(r:connection)?">
    <xsl:param name="connection" as="element(pim:connection)"/>
    <xsl:param name="targets" as="map(xs:string, xs:boolean)"/>
    <xsl:param name="files" as="map(xs:string, xs:string)"/>
    <xsl:variable name="policy" as="element(pim:policy)?" select="$connection/pim:policy"/>
    <xsl:variable name="ends" as="element()*" select="$connection/(pim:writer | pim:reader)"/>
    <xsl:variable name="away" as="element()*" select="$ends[not(@instance ! map:contains($targets, string(.)))]"/>
    <xsl:variable name="datum" as="element(pim:data-port)?" select="key('fp:data-port', $connection/pim:writer[1]/@port, root($connection))[1]"/>
    <xsl:choose>
      <xsl:when test="exists($away)">
        <xsl:sequence select="f:warn('RTM012', string($connection/@xmi-id), 'connection ''' || $connection/@name || ''' has ends on '
            || 'instances the OpenRTM package does not hold (''' || string-join(distinct-values($away/@instance), ''', ''')
            || '''): OpenRTM reaches no other middleware, the connection is left out')"/>
      </xsl:when>
      <xsl:when test="empty($datum) or empty(fp:rtm-type($datum, ''))">
        <xsl:sequence select="f:warn('RTM001', string($connection/@xmi-id), 'connection ''' || $connection/@name || ''' carries '
            || (if ($datum) then fp:type-label($datum) else 'no datum') || ', which has no OpenRTM data type: its ports are not generated,'
            || ' the connection is left out')"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:if test="$policy/@init = ('true', '1')">
          <xsl:sequence select="f:warn('RTM014', string(($policy/@holder, $connection/@xmi-id)[1]), 'connection ''' || $connection/@name
              || ''' asks for the last sample on connecting (init): an OpenRTM connector has no such setting; a reader gets only'
              || ' what is written after the connection is made')"/>
        </xsl:if>
        <r:connection xmi-id="{$connection/@xmi-id}" name="{$connection/@name}"
                      dataflow-type="{if ($policy/@pull = ('true', '1')) then 'pull' else 'push'}"
                      subscription-type="flush" interface-type="corba_cdr"
                      buffer-length="{($policy/@size[. ne ''], '1')[1]}"
                      full-policy="{if ($policy/@type eq 'BUFFER') then 'do_nothing' else 'overwrite'}"
                      policy="{$policy/@type}">
          <xsl:for-each select="$connection/pim:writer, $connection/pim:reader">
            <xsl:element name="r:{local-name()}">
              <xsl:attribute name="instance" select="@instance"/>
              <xsl:attribute name="port" select="@data-port"/>
              <xsl:attribute name="xmi-id" select="@port"/>
              <xsl:attribute name="process" select="map:get($files, string(key('fp:instance-by-name', @instance, root(.))/@execution-environment))"/>
            </xsl:element>
          </xsl:for-each>
        </r:connection>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <xsl:function name="fp:rtm-idl-operation" as="element(r:operation)">
    <xsl:param name="operation" as="element(r:operation)"/>
    <r:operation name="{$operation/@name}" return-idl="{$operation/@return-idl}">
      <xsl:for-each select="$operation/r:parameter">
        <r:parameter name="{@name}" idl="{@idl}"/>
      </xsl:for-each>
    </r:operation>
  </xsl:function>

  <!-- an operation call (seed 003) between two instances of the package whose
       service ports are generated: a service-port connection; a call with
       one end on another middleware is left out (RTM012) -->
  <xsl:function name="fp:rtm-service-connection" as="element(r:service-connection)?">
    <xsl:param name="call" as="element(pim:call)"/>
    <xsl:param name="targets" as="map(xs:string, xs:boolean)"/>
    <xsl:param name="rtcs" as="document-node()"/>
    <xsl:variable name="ends" as="element()+" select="$call/pim:caller, $call/pim:provider"/>
    <xsl:variable name="here" as="element()*" select="$ends[@instance ! map:contains($targets, string(.))]"/>
    <xsl:choose>
      <xsl:when test="empty($here)"/>
      <xsl:when test="count($here) lt 2">
        <xsl:sequence select="f:warn('RTM012', string($call/@xmi-id), 'operation call ''' || $call/@name || ''' joins '''
            || string-join($ends/@instance, ''' and ''') || ''', one of which the OpenRTM package does not hold: the call is left out')"/>
      </xsl:when>
      <xsl:when test="every $e in $ends satisfies exists(key('fp:service-port', string($e/@port), $rtcs))">
        <r:service-connection xmi-id="{$call/@xmi-id}" name="{$call/@name}"
            caller="{$call/pim:caller/@instance}" caller-port="{$call/pim:caller/@service-port}"
            provider="{$call/pim:provider/@instance}" provider-port="{$call/pim:provider/@service-port}"/>
      </xsl:when>
    </xsl:choose>
  </xsl:function>

  <!-- ========================================================== instance -->
  <xsl:function name="fp:rtm-instance" as="element(r:instance)">
    <xsl:param name="instance" as="element(pim:instance)"/>
    <xsl:param name="rtcs" as="document-node()"/>
    <xsl:param name="targets" as="map(xs:string, xs:boolean)"/>
    <xsl:param name="files" as="map(xs:string, xs:string)"/>
    <xsl:variable name="rtc" as="element(r:component)" select="key('fp:rtc', $instance/@component, $rtcs)"/>
    <xsl:variable name="activity" as="element(pim:activity)" select="$instance/pim:activity"/>
    <xsl:variable name="period" as="xs:double" select="number(($activity/@period, 0)[1])"/>
    <xsl:if test="not($period gt 0)">
      <xsl:sequence select="f:warn('RTM011', string(($activity/@period-holder, $instance/@xmi-id)[1]), 'instance ''' || $instance/@name
          || ''' is non-periodic: OpenRTM''s PeriodicExecutionContext has no data-triggered mode here; it runs at the default 1000 Hz')"/>
    </xsl:if>
    <xsl:if test="number($activity/@priority) ne 0 or $activity/@scheduler eq 'RT'">
      <xsl:sequence select="f:warn('RTM010', string(($activity/@priority-holder, $activity/@period-holder, $instance/@xmi-id)[1]),
          'instance ''' || $instance/@name || ''' asks for priority ' || $activity/@priority || ' with scheduler ' || $activity/@scheduler
          || ': OpenRTM-aist 2.0''s PeriodicExecutionContext sets neither; its thread runs with the default policy and priority')"/>
    </xsl:if>
    <r:instance xmi-id="{$instance/@xmi-id}" name="{$instance/@name}" component="{$rtc/@class}" category="{$rtc/@category}"
                process="{map:get($files, string($instance/@execution-environment))}"
                rate="{if ($period gt 0) then fp:decimal(string(round(1 div $period * 1000000) div 1000000)) else '1000.0'}"
                period="{$activity/@period}">
      <xsl:if test="fp:rtm-job-idle($instance)">
        <!-- in a job other than the initial one: created, activated by a switch (R7) -->
        <xsl:attribute name="idle" select="'true'"/>
      </xsl:if>
      <!-- the model's CPU bit mask as OpenRTM-aist 2.0's list of CPU numbers, counted from 1 as
           its PeriodicExecutionContext checks them (mask 3: "1,2"); it pins the thread to the
           first n CPUs of the machine for a list of n, so a mask that is not 0..n-1 is RTM023 -->
      <xsl:variable name="mask" as="xs:integer" select="if ($activity/@cpu-affinity castable as xs:integer) then xs:integer($activity/@cpu-affinity) else 0"/>
      <xsl:variable name="cpus" as="xs:integer*" select="(0 to 63)[($mask idiv xs:integer(math:pow(2, .))) mod 2 eq 1]"/>
      <xsl:if test="exists($cpus)">
        <xsl:attribute name="cpu-affinity" select="string-join($cpus ! string(. + 1), ',')"/>
      </xsl:if>
      <xsl:if test="exists($cpus) and not(deep-equal($cpus, 0 to count($cpus) - 1))">
        <xsl:sequence select="f:warn('RTM023', string(($activity/@period-holder, $instance/@xmi-id)[1]), 'instance ''' || $instance/@name
            || ''' asks for CPUs ' || string-join($cpus ! string(.), ', ') || ' (mask ' || $mask || '): OpenRTM-aist 2.0''s'
            || ' PeriodicExecutionContext pins its thread to the first ' || count($cpus) || ' CPU(s) of the machine (0 to '
            || count($cpus) - 1 || '), whichever it is given, and logs an error that they differ')"/>
      </xsl:if>
      <xsl:sequence select="fp:warn-unused-values($instance, $rtc/r:parameter/@xmi-id, 'RTM008')"/>
      <xsl:for-each select="$rtc/r:parameter">
        <xsl:variable name="set" as="element(pim:property-value)?" select="$instance/pim:property-value[@attribute eq current()/@xmi-id]"/>
        <xsl:variable name="attribute" as="element()" select="key('fp:id', @xmi-id, root($instance))"/>
        <r:parameter-value name="{@name}"
            value="{if (empty($set)) then @default
                    else if (@kind) then fp:rtm-conf-text($attribute, fp:rtm-type($attribute, $rtc/@category), $set/@value, $set/@holder, 'RTM002')
                    else fp:rtm-value($set/@value, key('fp:type', @primitive, $fp:types), $set/@holder)}"/>
      </xsl:for-each>
      <xsl:for-each select="$instance/pim:start-after[@instance ! map:contains($targets, string(.))]">
        <r:start-after instance="{@instance}" xmi-id="{@xmi-id}"/>
      </xsl:for-each>
    </r:instance>
  </xsl:function>
</xsl:stylesheet>
