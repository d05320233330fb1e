<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/orocos-psm.xsl - bound PIM -> Orocos RTT 2.x PSM (seed 000 R1-R5).

  Reads:   a bound PIM, urn:robomda:pim:1 with pim:binding (xslt/m2m/bind.xsl).
  Writes:  urn:robomda:psm-orocos:1 (schemas/psm-orocos/1/psm-orocos.xsd),
           indented as f:indent (common/indent.xsl) indents it, through its
           rules (t:indented-content) in the same pass.
  Data:    xslt/m2m/orocos-types.xml (primitive kind -> C++ / cpf XML type, sample).
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
  flow alone needs no peers.
  Deployment sequence (seed 002): the o:instance elements are written in
  the binding's start order (pim:instance/@start-order; instances without
  one, on a cycle of the constraints, come last in binding order), so the
  text stage loads, configures and starts them in that order; each keeps
  its constraints on other Orocos instances as o:start-after.

  Errors (urn:robomda:error, f:fail):
    ORO001  a port, operation parameter or Configurable property has a type
            robomda cannot map to C++ / cpf XML (names the element)
    ORO002  a property default value is not valid for its type
    ORO003  the input has no pim:binding (run xslt/m2m/bind.xsl first)
    ORO004  two component types map to the same C++ class name
    ORO005  nothing to generate: the model has no component instance
  Warnings (f:warn):
    ORO006  no instance is deployed on OROCOS: all instances are generated
            for Orocos anyway (the same model on another middleware)
    ORO007  an instance deployed on another middleware is left out (the model
            deploys some components on OROCOS and others elsewhere)
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

  <xsl:include href="../common/errors.xsl"/>
  <xsl:include href="../common/literals.xsl"/>
  <xsl:include href="../common/indent.xsl"/>
  <xsl:include href="../common/naming.xsl"/>
  <xsl:include href="../common/profile.xsl"/>

  <xsl:param name="package-name" as="xs:string" select="''">
    <!-- the component package (CMake project, deployer Import); '' = lower snake-case of the model name -->
  </xsl:param>

  <xsl:output method="xml" indent="no" encoding="UTF-8"/>
  <xsl:mode name="m:to-psm" on-no-match="fail"/>

  <xsl:key name="fp:id" match="*[@id]" use="@id"/>
  <xsl:key name="fp:type" match="ty:type" use="@primitive"/>
  <xsl:key name="fp:bc" match="pim:bound-component" use="@component"/>
  <xsl:key name="fp:instance-of" match="pim:instance" use="@component"/>
  <xsl:key name="fp:instance-by-middleware" match="pim:instance" use="@middleware"/>
  <xsl:key name="fp:connection-by-instance" match="pim:connection" use="(pim:writer | pim:reader)/@instance"/>
  <xsl:key name="fp:host" match="pim:host" use="@xmi-id"/>
  <!-- on the temporary tree of task contexts -->
  <xsl:key name="fp:task-context" match="o:task-context" use="@xmi-id"/>

  <xsl:variable name="fp:types" as="document-node()" select="doc('orocos-types.xml')"/>
  <xsl:variable name="fp:reserved-operations" as="xs:string+" select="(
      'configure', 'start', 'update', 'stop', 'cleanup', 'trigger', 'error', 'recover',
      'activate', 'isRunning', 'isActive', 'isConfigured', 'inFatalError', 'inException',
      'inRunTimeError', 'getPeriod', 'setPeriod', 'getCpuAffinity', 'setCpuAffinity',
      'loadService', 'getName', 'getState')"/>
  <xsl:variable name="fp:convention-names" as="xs:string+" select="('sample', 'priority', 'scheduler', 'cpuAffinity')"/>

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
    <xsl:variable name="b" as="element(pim:binding)" select="pim:binding"/>
    <xsl:variable name="pkg" as="xs:string"
        select="if (normalize-space($package-name)) then f:snake-case($package-name) else f:snake-case(@name)"/>
    <xsl:variable name="instances" as="element(pim:instance)*" select="$b/pim:instance[fp:on-target(.)]"/>
    <xsl:if test="empty($instances)">
      <xsl:sequence select="f:fail('ORO005', @id, 'nothing to generate: model ''' || @name
          || ''' has no component instance (a component with ports or a realizing class)')"/>
    </xsl:if>
    <xsl:if test="empty($b/pim:instance[@middleware eq 'OROCOS'])">
      <xsl:sequence select="f:warn('ORO006', ($instances/@execution-environment)[1],
          'no component is deployed on OROCOS (the platform says '
          || string-join(distinct-values($instances/@middleware), ', ')
          || '): generating all ' || count($instances) || ' instances for Orocos')"/>
    </xsl:if>
    <xsl:for-each select="$b/pim:instance except $instances">
      <xsl:sequence select="f:warn('ORO007', string(@xmi-id), 'instance ''' || @name || ''' is deployed on '
          || @middleware || ', not OROCOS: it is not part of the Orocos package')"/>
    </xsl:for-each>
    <!-- the names and the component ids of $instances, as sets: whether an
         instance / component is in the package is one look-up -->
    <xsl:variable name="targets" as="map(xs:string, xs:boolean)"
        select="map:merge(distinct-values($instances/@name ! string(.)) ! map:entry(., true()))"/>
    <xsl:variable name="target-components" as="map(xs:string, xs:boolean)"
        select="map:merge(distinct-values($instances/@component ! string(.)) ! map:entry(., true()))"/>
    <xsl:variable name="components" as="element(pim:bound-component)*"
        select="$b/pim:bound-component[@component ! map:contains($target-components, string(.))]"/>
    <xsl:for-each-group select="$components" group-by="f:upper-camel(@name)">
      <xsl:if test="count(current-group()) gt 1">
        <xsl:sequence select="f:fail('ORO004', current-group()[2]/@component, 'components '''
            || string-join(current-group()/@name, ''', ''') || ''' all map to C++ class ' || current-grouping-key())"/>
      </xsl:if>
    </xsl:for-each-group>
    <xsl:variable name="connections" as="element(pim:connection)*"
        select="$b/pim:connection[fp:kept-connection(., $b, $targets)]"/>
    <!-- each task context is made once: listed here, and looked up (key
         fp:task-context) by the instances for their property values -->
    <xsl:variable name="task-contexts" as="document-node()">
      <xsl:document>
        <xsl:sequence select="$components ! fp:task-context(., $pkg)"/>
      </xsl:document>
    </xsl:variable>
    <o:deployment xmi-id="{@id}" model-name="{@name}" deploy-name="{f:snake-case(@name)}"
                  package="{$pkg}" namespace="{$pkg}" source="{@source}">
      <xsl:variable name="children" as="element()*">
        <xsl:for-each select="$b/pim:library">
          <o:library xmi-id="{@xmi-id}" name="{@name}" path="{@path}" absolute="{@absolute}"
                     target="{@target}" include-dir="{@include-dir}"
                     cmake-var="{upper-case($pkg) || '_' || upper-case(f:snake-case(@name)) || '_DIR'}"
                     build-dir="{f:snake-case(@name) || '-build'}"/>
        </xsl:for-each>
        <xsl:sequence select="$task-contexts/o:task-context"/>
        <xsl:for-each select="$b/pim:host">
          <o:host xmi-id="{@xmi-id}" name="{@name}" hostname="{@hostname}" address="{@address}"/>
        </xsl:for-each>
        <xsl:for-each select="$connections">
          <o:connection xmi-id="{@xmi-id}" name="{@name}" type="{pim:policy/@type}"
                        type-code="{index-of(('DATA', 'BUFFER', 'CIRCULAR_BUFFER'), pim:policy/@type) - 1}"
                        size="{pim:policy/@size}" lock-policy="{pim:policy/@lock-policy}"
                        lock-policy-code="{index-of(('UNSYNC', 'LOCKED', 'LOCK_FREE'), pim:policy/@lock-policy) - 1}"
                        init="{pim:policy/@init}" pull="{pim:policy/@pull}" topic="{pim:policy/@topic}">
            <xsl:for-each select="pim:writer[@instance ! map:contains($targets, string(.))]">
              <o:writer instance="{@instance}" port="{@data-port}" xmi-id="{@port}"/>
            </xsl:for-each>
            <xsl:for-each select="pim:reader[@instance ! map:contains($targets, string(.))]">
              <o:reader instance="{@instance}" port="{@data-port}" xmi-id="{@port}"/>
            </xsl:for-each>
          </o:connection>
        </xsl:for-each>
        <xsl:variable name="in-start-order" as="element(pim:instance)*">
          <xsl:perform-sort select="$instances">
            <xsl:sort select="empty(@start-order)"/>
            <xsl:sort select="xs:integer((@start-order, 0)[1])"/>
          </xsl:perform-sort>
        </xsl:variable>
        <xsl:for-each select="$in-start-order">
          <xsl:sequence select="fp:oro-instance(., $pkg, $b, $task-contexts, $targets)"/>
        </xsl:for-each>
      </xsl:variable>
      <xsl:call-template name="t:indented-content">
        <xsl:with-param name="children" select="$children"/>
        <xsl:with-param name="margin" select="'&#10;'"/>
      </xsl:call-template>
    </o:deployment>
  </xsl:template>

  <!-- true when instance $i goes into the Orocos package: it is deployed on
       OROCOS, or no instance of the model is (the target then takes them all:
       the same model runs on another middleware, ORO006 says so) -->
  <xsl:function name="fp:on-target" as="xs:boolean">
    <xsl:param name="i" as="element(pim:instance)"/>
    <xsl:sequence select="$i/@middleware eq 'OROCOS'
                          or empty(key('fp:instance-by-middleware', 'OROCOS', root($i)))"/>
  </xsl:function>

  <!-- a connection of the binding $b that the PSM keeps: one of its writers
       and one of its readers are OROCOS instances ($targets: the names of
       the instances of $b that are on the target, see fp:on-target) -->
  <xsl:function name="fp:kept-connection" as="xs:boolean">
    <xsl:param name="k" as="element(pim:connection)"/>
    <xsl:param name="b" as="element(pim:binding)"/>
    <xsl:param name="targets" as="map(xs:string, xs:boolean)"/>
    <xsl:sequence select="$k/.. is $b
                          and (some $n in $k/pim:writer/@instance satisfies map:contains($targets, string($n)))
                          and (some $n in $k/pim:reader/@instance satisfies map:contains($targets, string($n)))"/>
  </xsl:function>

  <!-- ============================================================ types -->
  <xsl:function name="fp:oro-type" as="element(ty:type)?">
    <xsl:param name="typed" as="element()"/>
    <xsl:sequence select="if ($typed/@upper and not($typed/@upper = ('1', '')))
                          then () else key('fp:type', string($typed/@primitive), $fp:types)"/>
  </xsl:function>

  <xsl:function name="fp:oro-required-type" as="element(ty:type)">
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:variable name="t" as="element(ty:type)?" select="fp:oro-type($typed)"/>
    <xsl:sequence select="if (exists($t) and ($t/@primitive ne 'void' or $what eq 'result'))
        then $t
        else f:fail('ORO001', $id, $what || ' has type ''' || ($typed/@type-name, $typed/@primitive, '?')[1]
                     || (if ($typed/@upper and not($typed/@upper = ('1', ''))) then '[' || $typed/@upper || ']' else '')
                     || ''', which robomda cannot map to an Orocos C++ / XML type (supported: '
                     || string-join($fp:types//ty:type[@primitive ne 'void']/@primitive, ', ') || ')')"/>
  </xsl:function>

  <xsl:function name="fp:oro-doc" as="element(o:doc)?">
    <xsl:param name="e" as="element()?"/>
    <xsl:for-each select="$e/pim:doc[normalize-space(.)]">
      <o:doc><xsl:value-of select="normalize-space(.)"/></o:doc>
    </xsl:for-each>
  </xsl:function>

  <!-- ===================================================== task context -->
  <xsl:function name="fp:task-context" as="element(o:task-context)">
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:param name="pkg" as="xs:string"/>
    <xsl:variable name="c" as="element(pim:component)" select="key('fp:id', $bc/@component, root($bc))"/>
    <xsl:variable name="r" as="element(pim:class)?" select="key('fp:id', $bc/@realization, root($bc))"/>
    <xsl:variable name="class" as="xs:string" select="f:upper-camel($c/@name)"/>
    <xsl:variable name="owner" as="element()" select="($r, $c)[1]"/>
    <xsl:variable name="callable" as="element(pim:operation)*" select="$r/pim:operation[@visibility ne 'private']"/>
    <o:task-context xmi-id="{$c/@id}" name="{$c/@name}" class="{$class}" namespace="{$pkg}"
                    type-name="{$pkg}::{$class}" kind="{if ($r) then 'wrapper' else 'base'}"
                    generated-class="{if ($r) then $class else $class || 'Base'}">
      <xsl:sequence select="fp:oro-doc($c)"/>
      <xsl:if test="$r">
        <xsl:variable name="n" as="xs:string"
            select="string-join(tokenize($bc/@cpp-name, '::')[normalize-space(.)] ! f:cpp-identifier(.), '::')"/>
        <o:realizing-class xmi-id="{$r/@id}" name="{$r/@name}" cpp-name="::{$n}" header="{$bc/@header}"/>
      </xsl:if>
      <xsl:for-each select="('configure', 'start', 'update', 'stop', 'cleanup')">
        <xsl:variable name="h" as="xs:string" select="."/>
        <xsl:variable name="op" as="element(pim:operation)?" select="$callable[@name eq $h][1]"/>
        <o:hook name="{$h}">
          <xsl:if test="$op">
            <xsl:attribute name="call" select="$h"/>
            <xsl:attribute name="returns-bool" select="$op/pim:parameter[@direction eq 'return']/@primitive = 'boolean'"/>
            <xsl:attribute name="xmi-id" select="$op/@id"/>
          </xsl:if>
        </o:hook>
      </xsl:for-each>
      <!-- some instance of the component is non-periodic (see o:port/@event) -->
      <xsl:variable name="non-periodic" as="xs:boolean"
          select="some $a in key('fp:instance-of', $bc/@component, root($bc))/pim:activity
                  satisfies number($a/@period) eq 0"/>
      <xsl:for-each select="$bc/pim:data-port">
        <xsl:variable name="port" as="element(pim:port)" select="key('fp:id', @port, root($bc))"/>
        <xsl:variable name="t" as="element(ty:type)"
            select="fp:oro-required-type(., @port, 'port ''' || @port-name || ''' (datum ''' || @datum-name || ''' of interface ''' || @interface-name || ''')')"/>
        <xsl:variable name="acc" as="xs:string"
            select="(if (@direction eq 'out') then 'get' else 'set') || f:upper-first(f:cpp-identifier(@datum-name))"/>
        <!-- an input port triggers updateHook (event port) only where some
             instance of the component is non-periodic: a periodic activity
             already runs updateHook on its own clock -->
        <o:port xmi-id="{@port}" direction="{@direction}"
                event="{@direction eq 'in' and $non-periodic}"
                rtt-class="{if (@direction eq 'out') then 'RTT::OutputPort' else 'RTT::InputPort'}&lt;{$t/@cpp}&gt;"
                name="{@name}" member="port_{@name}" interface="{@interface-name}" datum="{@datum-name}"
                accessor="{$acc}" accessor-declared="{exists($callable[@name eq $acc])}"
                primitive="{$t/@primitive}" cpp-type="{$t/@cpp}" xml-type="{$t/@xml}" sample="{$t/@sample}">
          <xsl:sequence select="fp:oro-doc($port)"/>
        </o:port>
      </xsl:for-each>
      <xsl:for-each select="$owner/pim:operation[@visibility eq 'protected'][not(@static = ('true', '1'))]
                                                [not(@name = $fp:reserved-operations)]">
        <xsl:sequence select="fp:operation(.)"/>
      </xsl:for-each>
      <xsl:variable name="configurable" as="element(pim:attribute)*"
          select="$owner/pim:attribute[exists(f:stereotype(., 'Configurable'))]"/>
      <xsl:choose>
        <xsl:when test="exists($configurable)">
          <xsl:sequence select="$configurable ! fp:property(., true())"/>
        </xsl:when>
        <xsl:otherwise>
          <xsl:sequence select="$owner/pim:attribute[@visibility = ('public', 'protected')]
                                  [not(@static = ('true', '1'))][not(@read-only = ('true', '1'))]
                                  [not(@name = $fp:convention-names)][exists(fp:oro-type(.))][@primitive ne 'void']
                                ! fp:property(., false())"/>
        </xsl:otherwise>
      </xsl:choose>
    </o:task-context>
  </xsl:function>

  <xsl:function name="fp:operation" as="element(o:operation)">
    <xsl:param name="op" as="element(pim:operation)"/>
    <xsl:variable name="tag" as="xs:string?"
        select="f:stereotype($op, 'OperationThread')/pim:tag[@name eq 'thread'][1]/@value"/>
    <xsl:variable name="thread" as="xs:string"
        select="if (exists($tag)) then (if (matches($tag, 'CLIENT', 'i')) then 'RTT::ClientThread' else 'RTT::OwnThread')
                else if ($op/@query = ('true', '1')) then 'RTT::ClientThread' else 'RTT::OwnThread'"/>
    <xsl:variable name="ret" as="element(pim:parameter)?" select="$op/pim:parameter[@direction eq 'return'][1]"/>
    <xsl:variable name="rt" as="element(ty:type)"
        select="if ($ret) then fp:oro-required-type($ret, $op/@id, 'result of operation ''' || $op/@name || '''')
                else key('fp:type', 'void', $fp:types)"/>
    <o:operation xmi-id="{$op/@id}" name="{f:cpp-identifier($op/@name)}" thread="{$thread}"
                 return-type="{$rt/@cpp}" return-primitive="{$rt/@primitive}" return-sample="{$rt/@sample}">
      <xsl:sequence select="fp:oro-doc($op)"/>
      <xsl:for-each select="$op/pim:parameter[@direction ne 'return']">
        <xsl:variable name="t" as="element(ty:type)"
            select="fp:oro-required-type(., @id, 'parameter ''' || @name || ''' of operation ''' || $op/@name || '''')"/>
        <o:parameter xmi-id="{@id}" name="{f:cpp-identifier((@name[normalize-space(.)], 'arg' || position())[1])}"
                     direction="{@direction}" primitive="{$t/@primitive}" cpp-type="{$t/@cpp}" xml-type="{$t/@xml}"
                     decl-type="{if (@direction = ('out', 'inout')) then $t/@cpp || '&amp;'
                                 else if ($t/@pass eq 'cref') then 'const ' || $t/@cpp || '&amp;' else $t/@cpp}">
          <xsl:sequence select="fp:oro-doc(.)"/>
        </o:parameter>
      </xsl:for-each>
    </o:operation>
  </xsl:function>

  <!-- (xml value, script literal, C++ literal) of a default value -->
  <xsl:function name="fp:oro-values" as="xs:string+">
    <xsl:param name="v" as="xs:string"/>
    <xsl:param name="t" as="element(ty:type)"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:variable name="s" as="xs:string" select="f:unquote(normalize-space($v))"/>
    <xsl:variable name="num" as="xs:string" select="replace($s, '^([+\-]?[0-9.eE+\-]+)[fFdDlLuU]*$', '$1')"/>
    <xsl:variable name="p" as="xs:string" select="$t/@primitive"/>
    <xsl:sequence select="
      if ($p eq 'string') then ($s, fp:cpp-string($s), fp:cpp-string($s))
      else if ($p eq 'boolean') then
        (if (lower-case($s) = ('true', '1')) then ('1', 'true', 'true')
         else if (lower-case($s) = ('false', '0')) then ('0', 'false', 'false')
         else f:fail('ORO002', $id, 'default ''' || $v || ''' is not a boolean'))
      else if ($p eq 'char') then
        (if (string-length($s) eq 1 and matches($s, '[A-Za-z0-9 _.,;:+\-*/=!?]'))
         then ($s, '''' || $s || '''', '''' || $s || '''')
         else f:fail('ORO002', $id, 'default ''' || $v || ''' is not a single plain character'))
      else if ($p = ('float32', 'float64')) then
        (if ($num castable as xs:double and not(matches($num, 'nan|inf', 'i')))
         then ($num, if (contains($num, '.') or contains(lower-case($num), 'e')) then $num else $num || '.0',
               (if (contains($num, '.') or contains(lower-case($num), 'e')) then $num else $num || '.0')
               || (if ($p eq 'float32') then 'f' else ''))
         else f:fail('ORO002', $id, 'default ''' || $v || ''' is not a number'))
      else
        (if ($num castable as xs:integer and (not(starts-with($p, 'u') or $p eq 'octet') or xs:integer($num) ge 0))
         then (string(xs:integer($num)), string(xs:integer($num)), string(xs:integer($num)))
         else f:fail('ORO002', $id, 'default ''' || $v || ''' is not a valid ' || $p))"/>
  </xsl:function>

  <xsl:function name="fp:property" as="element(o:property)">
    <xsl:param name="a" as="element(pim:attribute)"/>
    <xsl:param name="explicit" as="xs:boolean"/>
    <xsl:variable name="t" as="element(ty:type)"
        select="fp:oro-required-type($a, $a/@id, 'property ''' || $a/@name || '''')"/>
    <xsl:variable name="vals" as="xs:string*"
        select="if ($a/@default) then fp:oro-values($a/@default, $t, $a/@id) else ()"/>
    <o:property xmi-id="{$a/@id}" name="{f:cpp-identifier($a/@name)}" member="{f:cpp-identifier($a/@name)}"
                primitive="{$t/@primitive}" cpp-type="{$t/@cpp}" xml-type="{$t/@xml}"
                cpp-default="{($vals[3], $t/@sample)[1]}">
      <xsl:if test="exists($vals)">
        <xsl:attribute name="xml-default" select="$vals[1]"/>
        <xsl:attribute name="script-default" select="$vals[2]"/>
      </xsl:if>
      <xsl:sequence select="fp:oro-doc($a)"/>
    </o:property>
  </xsl:function>

  <!-- ========================================================= instance -->
  <xsl:function name="fp:oro-instance" as="element(o:instance)">
    <xsl:param name="i" as="element(pim:instance)"/>
    <xsl:param name="pkg" as="xs:string"/>
    <xsl:param name="b" as="element(pim:binding)"/>
    <xsl:param name="task-contexts" as="document-node()"/>
    <xsl:param name="targets" as="map(xs:string, xs:boolean)"/>
    <xsl:variable name="tc" as="element(o:task-context)"
        select="key('fp:task-context', $i/@component, $task-contexts)"/>
    <!-- f:upper-camel of the component's name, made once by fp:task-context -->
    <xsl:variable name="class" as="xs:string" select="$tc/@class"/>
    <xsl:variable name="a" as="element(pim:activity)" select="$i/pim:activity"/>
    <xsl:variable name="mine" as="element(pim:connection)*"
        select="key('fp:connection-by-instance', $i/@name, root($i))[fp:kept-connection(., $b, $targets)]"/>
    <o:instance xmi-id="{$i/@xmi-id}" name="{$i/@name}" task-context="{$class}" type-name="{$pkg}::{$class}">
      <xsl:for-each select="key('fp:id', $i/@host, root($i))">
        <xsl:attribute name="host" select="(key('fp:host', @id, root($i))/@hostname, @name)[1]"/>
      </xsl:for-each>
      <o:activity type="Activity" periodic="{number($a/@period) ne 0}" period="{$a/@period}"
                  priority="{$a/@priority}" scheduler="ORO_SCHED_{$a/@scheduler}" cpu-affinity="{$a/@cpu-affinity}"/>
      <xsl:for-each select="distinct-values($mine[pim:reader/@instance = $i/@name]
                              [exists(key('fp:id', @interface, root($i))/pim:operation)]
                              /pim:writer/@instance[. ne $i/@name])">
        <o:peer instance="{.}"/>
      </xsl:for-each>
      <xsl:for-each select="$mine">
        <xsl:variable name="k" as="element(pim:connection)" select="."/>
        <xsl:for-each select="distinct-values((pim:writer | pim:reader)[@instance eq $i/@name]/@data-port)">
          <o:port-connection port="{.}" connection="{$k/@name}"/>
        </xsl:for-each>
      </xsl:for-each>
      <xsl:for-each select="$tc/o:property[@xml-default]">
        <o:property-value name="{@name}" xml-type="{@xml-type}" value="{@xml-default}" script-value="{@script-default}"/>
      </xsl:for-each>
      <xsl:for-each select="$i/pim:start-after[@instance ! map:contains($targets, string(.))]">
        <o:start-after instance="{@instance}" xmi-id="{@xmi-id}"/>
      </xsl:for-each>
    </o:instance>
  </xsl:function>
</xsl:stylesheet>
