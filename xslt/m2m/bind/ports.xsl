<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/bind/ports.xsl - bind (xslt/m2m/bind.xsl): bound components and their data ports (seed 000 R2).

  Reads:   the PIM (urn:robomda:pim:1) and the working trees of fp:binding.
  Writes:  parts of pim:binding (schemas/pim/1/binding.xsd), or values.
  Params:  none.  Keys: those of bind.xsl.
  Provides: fp:bound-component, fp:component-name, fp:port-interfaces, fp:data-ports, fp:port-problems,
           fp:constant («Constant»: data-port/@constant), fp:provided-direction, fp:flip,
           fp:is-message-set.
  A port's data ports follow what its tool's profile says
  (xslt/import/dialects.xsl): a direction (inout: a writer and a reader),
  the flow properties of its type (SysML), a pattern whose provider reads
  (a Papyrus for Robotics Send, a UML-RT message set), a message set's
  messages, each a data port of its own.
  Errors:  BND002, BND005, BND030 (as data for f:fail-all), BND011.
  Warnings: BND004 a port whose interface has no datum and no operation,
           left out; BND029 an inout port or flow property generated as an
           output and an input. Note BND033: a port that is the runtime's
           service in its profile, not generated.
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

  <!-- ============================================ components and ports -->
  <xsl:function name="fp:bound-component" as="element(pim:bound-component)">
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:variable name="realization-item" as="element(pim:class)?" select="fp:realizing-class($component)"/>
    <xsl:variable name="host" as="xs:string?" select="fp:tag($realization-item, 'AtomicCode', 'header')[normalize-space(.)]"/>
    <xsl:variable name="name" as="xs:string?" select="fp:tag($realization-item, 'AtomicCode', 'cppName')[normalize-space(.)]"/>
    <xsl:variable name="cpp" as="xs:string?" select="($name, $realization-item/@name)[1]"/>
    <xsl:if test="$realization-item and not(normalize-space($cpp) and (every $part in tokenize(replace(string($cpp), '^::', ''), '::')
                             satisfies matches($part, '^[A-Za-z_][A-Za-z0-9_]*$')))">
      <xsl:sequence select="f:fail('BND011', string($realization-item/@id), 'the realizing class of component '''
          || $component/@name || ''' has no usable C++ name (''' || string($cpp)
          || '''): name the class, or give its AtomicCode stereotype a cppName')"/>
    </xsl:if>
    <pim:bound-component component="{$component/@id}" name="{fp:component-name($component)}">
      <xsl:if test="$realization-item">
        <xsl:attribute name="realization" select="$realization-item/@id"/>
        <xsl:attribute name="realization-name" select="$realization-item/@name"/>
        <xsl:attribute name="header" select="($host, $realization-item/@name || '.hpp')[1]"/>
        <xsl:attribute name="header-source" select="if (exists($host)) then 'stereotype' else 'default'"/>
        <xsl:attribute name="cpp-name" select="($name, $realization-item/@name)[1]"/>
        <xsl:attribute name="cpp-name-source" select="if (exists($name)) then 'stereotype' else 'name'"/>
      </xsl:if>
      <!-- a port that is the runtime's service in its tool's profile (a
           UML-RT SAP or SPP, a Log or Timing port) is no port of the
           generated system: a note says so -->
      <xsl:for-each select="$component/pim:port[@runtime]">
        <xsl:message select="'BND033: port ''' || @name || ''' of ' || $component/@name || ' is '
            || (if (@runtime eq 'unwired') then 'unwired (a UML-RT service access or provision point, which the runtime connects by name)'
                else 'typed by the protocol ''' || @type-name || ''' of its runtime library (its timers, log or frame service)')
            || ': no port of the generated component; the target''s own services stand for it [xmi:id=' || @id || ']'"/>
      </xsl:for-each>
      <xsl:for-each select="$component/pim:port[not(@runtime)]">
        <xsl:sequence select="fp:data-ports(., $component, $realization-item)"/>
      </xsl:for-each>
      <!-- operations provided and called (bind/services.xsl) -->
      <xsl:for-each select="$component/pim:port[not(@runtime)]">
        <xsl:sequence select="fp:service-ports(., $component, $realization-item)"/>
      </xsl:for-each>
    </pim:bound-component>
  </xsl:function>

  <!-- the name a component is bound by: its own, or, when components of
       one name are in different packages (legal UML), its qualified name
       below the model as an identifier (front::Camera: front_Camera), so
       that their classes and instances differ on every target -->
  <xsl:function name="fp:component-name" as="xs:string">
    <xsl:param name="component" as="element(pim:component)"/>
    <!-- (two of one qualified name, in one package, keep their name: that
         is no legal UML, and BND009 / APP020 say so) -->
    <xsl:variable name="same" as="element(pim:component)*"
        select="key('fp:component-of-name', string($component/@name), root($component))"/>
    <xsl:sequence select="if (count($same) gt 1 and count($same[@qualified-name eq $component/@qualified-name]) eq 1)
                          then f:cpp-identifier(replace(replace($component/@qualified-name, '^[^:]*::', ''), '::', '_'))
                          else string($component/@name)"/>
  </xsl:function>

  <!-- (interface id, direction) pairs of a port, flattened: id, dir, id, dir ... -->
  <xsl:function name="fp:port-interfaces" as="xs:string*">
    <xsl:param name="port" as="element(pim:port)"/>
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:param name="realization" as="element(pim:class)?"/>
    <xsl:variable name="root" as="document-node()" select="root($port[1])"/>
    <xsl:variable name="type" as="element()?" select="key('fp:id', $port/@type, $root)"/>
    <xsl:variable name="conj" as="xs:boolean" select="$port/@conjugated = ('true', '1')"/>
    <!-- the direction a dialect's port stereotype gives (RobotML
         DataFlowPort, SysML FlowPort: xslt/import/dialects.xml); inout
         is a writer and a reader (fp:data-ports names the two) -->
    <xsl:variable name="given" as="xs:string*"
        select="if ($port/@direction eq 'inout') then ('out', 'in') else $port/@direction ! string(.)"/>
    <xsl:sequence select="
        if (not($port/pim:provided or $port/pim:required) and exists($type/pim:attribute[@direction])) then
          (: a port typed by a SysML interface block or flow specification:
             each flow property in its direction, swapped when conjugated :)
          ($type/pim:attribute[@direction] ! (let $id := string(@id) return
              (if (@direction eq 'inout') then ('out', 'in') else string(@direction)) ! ($id, if ($conj) then fp:flip(.) else .)))
        else if (exists($given) and not($port/pim:provided or $port/pim:required)
            and ($type/self::pim:interface or fp:is-data-type($type) or (empty($type) and $port/@primitive))) then
          ($given ! (string(($type/@id, $port/@id)[1]), if ($conj) then fp:flip(.) else .))
        else if ($port/pim:provided or $port/pim:required) then
          ($port/pim:provided ! (string(@interface), fp:provided-direction(key('fp:id', @interface, $root))),
           $port/pim:required ! (string(@interface), fp:flip(fp:provided-direction(key('fp:id', @interface, $root)))))
        else if ($type/self::pim:interface) then
          (string($type/@id),
           if (($component, $realization)/pim:requires/@interface = $type/@id) then fp:flip(fp:provided-direction($type))
           else if (($component, $realization)/pim:provides/@interface = $type/@id) then fp:provided-direction($type)
           else if ($conj) then 'in' else 'out')
        else if ($type/self::pim:class) then
          ($type/pim:provides ! (string(@interface),
                                 let $d := fp:provided-direction(key('fp:id', @interface, $root)) return if ($conj) then fp:flip($d) else $d),
           $type/pim:requires ! (string(@interface),
                                 let $d := fp:flip(fp:provided-direction(key('fp:id', @interface, $root))) return if ($conj) then fp:flip($d) else $d))
        else if (fp:is-data-type($type)) then (string($type/@id), if ($conj) then 'in' else 'out')
        else if (empty($type) and $port/@primitive) then (string($port/@id), if ($conj) then 'in' else 'out')
        else ()"/>
  </xsl:function>

  <!-- the direction of the data at a port that provides interface $i:
       out (seed 000: the provider writes), or what the communication
       pattern it binds says (a Papyrus for Robotics Send: the provider
       receives; pim:interface/@provided-direction) -->
  <xsl:function name="fp:provided-direction" as="xs:string">
    <xsl:param name="interface" as="element()?"/>
    <xsl:sequence select="($interface/@provided-direction[. = ('in', 'out')], 'out')[1]"/>
  </xsl:function>

  <xsl:function name="fp:flip" as="xs:string">
    <xsl:param name="direction" as="xs:string"/>
    <xsl:sequence select="if ($direction eq 'in') then 'out' else 'in'"/>
  </xsl:function>

  <!-- true when port $p is typed by an interface that neither the
       component nor its realizing class provides or requires, and has no
       provided / required lists: fp:port-interfaces then guesses its
       direction from conjugation alone (rule APP006 says so) -->
  <xsl:function name="fp:direction-guessed" as="xs:boolean">
    <xsl:param name="port" as="element(pim:port)"/>
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:param name="realization" as="element(pim:class)?"/>
    <xsl:variable name="type" as="element()?" select="key('fp:id', $port/@type, root($port))"/>
    <xsl:sequence select="not($port/pim:provided or $port/pim:required) and exists($type/self::pim:interface)
                          and not(($component, $realization)/(pim:requires | pim:provides)/@interface = $type/@id)"/>
  </xsl:function>

  <!-- the problems of the data ports of port $p (BND002, BND005,
       BND030), as maps for f:fail-all -->
  <xsl:function name="fp:port-problems" as="map(*)*">
    <xsl:param name="port" as="element(pim:port)"/>
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:param name="realization" as="element(pim:class)?"/>
    <xsl:variable name="root" as="document-node()" select="root($port[1])"/>
    <xsl:variable name="pairs" as="xs:string*" select="fp:port-interfaces($port, $component, $realization)"/>
    <xsl:if test="$port/@direction-literal">
      <xsl:sequence select="map { 'code': 'BND030', 'id': string($port/@id), 'message': 'port ''' || $port/@name
          || ''' of ' || $component/@name || ' has direction ''' || $port/@direction-literal || ''' ('
          || $port/@dialect || '), which is none of in, out, inout: give it one of them' }"/>
    </xsl:if>
    <xsl:for-each select="1 to count($pairs) idiv 2">
      <xsl:variable name="instance" as="element()?" select="key('fp:id', $pairs[2 * current() - 1], $root)"/>
      <xsl:variable name="data" as="element(pim:attribute)*" select="$instance/pim:attribute"/>
      <xsl:choose>
        <xsl:when test="fp:is-data-type($instance) or fp:is-service-interface($instance)"/>
        <xsl:when test="$instance/self::pim:attribute[@direction]"/>
        <xsl:when test="not($instance/self::pim:interface)">
          <xsl:sequence select="map { 'code': 'BND002', 'id': string($port/@id), 'message': 'port ''' || $port/@name
              || ''' refers to ''' || $pairs[2 * current() - 1] || ''', which is not an interface' }"/>
        </xsl:when>
        <!-- an interface with no datum and no operation: the port is
             left out of the bound component, with warning BND004
             (fp:data-ports), not refused -->
        <xsl:when test="empty($data)"/>
        <xsl:when test="count($data) gt 1 and not(fp:is-message-set($instance))">
          <xsl:sequence select="map { 'code': 'BND005', 'id': string($instance/@id), 'message': 'interface ''' || $instance/@name
              || ''' (port ''' || $port/@name || ''') carries ' || count($data)
              || ' attributes (' || string-join($data/@name, ', ') || '): an interface carries exactly one datum' }"/>
        </xsl:when>
      </xsl:choose>
    </xsl:for-each>
  </xsl:function>

  <!-- constant="true" when the port, or the interface it carries, is
       stereotyped «Constant»: a configuration constant exchanged once at
       initialisation (seed 004 Fig. 5), not data of every cycle -->
  <xsl:function name="fp:constant" as="attribute(constant)?">
    <xsl:param name="port" as="element(pim:port)"/>
    <xsl:param name="interface" as="element()?"/>
    <xsl:if test="exists(($port, $interface[self::pim:interface]) ! f:stereotype(., 'Constant'))">
      <xsl:attribute name="constant" select="'true'"/>
    </xsl:if>
  </xsl:function>

  <!-- a UML-RT message set: an interface each of whose attributes is a
       message, a datum of its own (xslt/import/dialects.xsl) -->
  <xsl:function name="fp:is-message-set" as="xs:boolean">
    <xsl:param name="interface" as="element()?"/>
    <xsl:sequence select="exists($interface/self::pim:interface[@pattern eq 'Messages'])"/>
  </xsl:function>

  <!-- a port's own type that is its data (a data type, primitive or
       enumeration of the model; the port itself for a library primitive) -->
  <xsl:function name="fp:is-data-type" as="xs:boolean">
    <xsl:param name="type" as="element()?"/>
    <xsl:sequence select="exists($type/(self::pim:datatype | self::pim:primitive | self::pim:enumeration
                                     | self::pim:port[@primitive]))"/>
  </xsl:function>

  <!-- the name of the data or service port of $port for $interface, one of
       its $count interfaces: the port's name, with the interface's after it
       when there are several -->
  <xsl:function name="fp:sub-port-name" as="xs:string">
    <xsl:param name="port" as="element(pim:port)"/>
    <xsl:param name="interface" as="element()?"/>
    <xsl:param name="count" as="xs:integer"/>
    <xsl:sequence select="f:cpp-identifier(if ($count eq 1) then $port/@name else $port/@name || '_' || $interface/@name)"/>
  </xsl:function>

  <!-- the name of data port $n of the $count of $port going $direction:
       an inout port of a dialect is a writer and a reader, named
       <port>_out and <port>_in -->
  <xsl:function name="fp:data-port-name" as="xs:string">
    <xsl:param name="port" as="element(pim:port)"/>
    <xsl:param name="interface" as="element()?"/>
    <xsl:param name="count" as="xs:integer"/>
    <xsl:param name="direction" as="xs:string"/>
    <xsl:sequence select="if ($port/@direction eq 'inout' and not($port/pim:provided or $port/pim:required))
                          then f:cpp-identifier($port/@name || '_' || $direction)
                          else fp:sub-port-name($port, $interface, $count)"/>
  </xsl:function>

  <xsl:function name="fp:data-ports" as="element(pim:data-port)*">
    <xsl:param name="port" as="element(pim:port)"/>
    <xsl:param name="component" as="element(pim:component)"/>
    <xsl:param name="realization" as="element(pim:class)?"/>
    <xsl:variable name="root" as="document-node()" select="root($port[1])"/>
    <xsl:sequence select="f:fail-all(fp:port-problems($port, $component, $realization))"/>
    <xsl:variable name="pairs" as="xs:string*" select="fp:port-interfaces($port, $component, $realization)"/>
    <xsl:variable name="inout-flows" as="element(pim:attribute)*"
        select="key('fp:id', $port/@type, $root)/pim:attribute[@direction eq 'inout']"/>
    <xsl:if test="exists($inout-flows) and not($port/pim:provided or $port/pim:required)">
      <xsl:sequence select="f:warn('BND029', string($port/@id), 'port ''' || $port/@name || ''' of '
          || $component/@name || ' carries the inout flow propert' || (if (count($inout-flows) gt 1) then 'ies ''' else 'y ''')
          || string-join($inout-flows/@name, ''', ''') || ''': no target has a port that both writes and reads, so each is'
          || ' generated as an output and an input (' || string-join($inout-flows ! ($port/@name || '_' || @name || '_out'), ', ')
          || ' and the _in ones), each connected where the connector joins a port that reads or writes it')"/>
    </xsl:if>
    <xsl:if test="$port/@direction eq 'inout' and not($port/pim:provided or $port/pim:required) and exists($pairs)">
      <xsl:sequence select="f:warn('BND029', string($port/@id), 'port ''' || $port/@name || ''' of '
          || $component/@name || ' is inout (' || $port/@dialect || '): no target has a port that both writes and reads,'
          || ' so it is generated as an output ''' || $port/@name || '_out'' and an input ''' || $port/@name
          || '_in'', each connected where the connector joins a port that reads or writes the same data')"/>
    </xsl:if>
    <xsl:variable name="name" as="xs:integer" select="count($pairs) idiv 2"/>
    <xsl:for-each select="1 to $name">
      <xsl:variable name="instance" as="element()?" select="key('fp:id', $pairs[2 * current() - 1], $root)"/>
      <xsl:choose>
        <xsl:when test="fp:is-service-interface($instance)"/>
        <xsl:when test="fp:is-data-type($instance)">
          <!-- a port typed by a data type carries that data itself: the
               type stands for the interface, the port for the datum -->
          <pim:data-port port="{$port/@id}" name="{fp:data-port-name($port, $instance, 1, $pairs[2 * current()])}"
                         port-name="{$port/@name}" direction="{$pairs[2 * current()]}"
                         interface="{$instance/@id}" interface-name="{($instance/self::pim:port/@type-name, $instance/@name)[1]}"
                         datum="{$port/@id}" datum-name="{$port/@name}">
            <xsl:sequence select="$port/(@primitive, @type, @type-name, @lower, @upper), fp:constant($port, ())"/>
          </pim:data-port>
        </xsl:when>
        <xsl:when test="$instance/self::pim:interface and empty($instance/pim:attribute)">
          <xsl:sequence select="f:warn('BND004', string($port/@id), 'port ''' || $port/@name || ''' of '
              || $component/@name || ' carries interface ''' || $instance/@name
              || (if ($instance/@pattern eq 'Query')
                  then ''', a Query of ' || $instance/@dialect || ' whose request and answer robomda cannot read (its'
                       || ' template binding does not give both, or it is a service of a library the model does not ship):'
                       || ' the port is left out of the generated component and of its connections'
                  else if ($instance/@pattern)
                  then ''', a ' || $instance/@pattern || ' of ' || $instance/@dialect
                       || ' (action or event), which no target generates yet (Push and Send are data ports, a Query a'
                       || ' service port): the port is left out of the generated component and of its connections'
                  else ''', which has no attribute (its datum) and no operation: the port is left out of the generated '
                       || 'component and of its connections; give ''' || $instance/@name || ''' one attribute, the data it carries'
                       || ' (or operations, for calls)'))"/>
        </xsl:when>
        <xsl:when test="$instance/self::pim:attribute[@direction]">
          <!-- a SysML flow property of the port's type: a data port of its
               own, the property both its interface and its datum (two ports
               typed alike match by it) -->
          <pim:data-port port="{$port/@id}"
                         name="{f:cpp-identifier($port/@name || '_' || $instance/@name
                                                 || (if ($instance/@direction eq 'inout') then '_' || $pairs[2 * current()] else ''))}"
                         port-name="{$port/@name}" direction="{$pairs[2 * current()]}"
                         interface="{$instance/@id}" interface-name="{$instance/@name}"
                         datum="{$instance/@id}" datum-name="{$instance/@name}">
            <xsl:sequence select="$instance/(@primitive, @type, @type-name, @lower, @upper), fp:constant($port, ())"/>
          </pim:data-port>
        </xsl:when>
        <xsl:when test="fp:is-message-set($instance)">
          <!-- a UML-RT message set: a data port per message, named after
               the port and the message -->
          <xsl:variable name="direction" as="xs:string" select="$pairs[2 * current()]"/>
          <xsl:for-each select="$instance/pim:attribute">
            <pim:data-port port="{$port/@id}" name="{f:cpp-identifier($port/@name || '_' || @name)}"
                           port-name="{$port/@name}" direction="{$direction}"
                           interface="{$instance/@id}" interface-name="{$instance/@name}"
                           datum="{@id}" datum-name="{@name}">
              <xsl:sequence select="(@primitive, @type, @type-name, @lower, @upper), fp:constant($port, $instance)"/>
            </pim:data-port>
          </xsl:for-each>
        </xsl:when>
        <xsl:otherwise>
          <xsl:variable name="data" as="element(pim:attribute)*" select="$instance/pim:attribute"/>
          <pim:data-port port="{$port/@id}"
                         name="{fp:data-port-name($port, $instance, $name, $pairs[2 * current()])}"
                         port-name="{$port/@name}" direction="{$pairs[2 * current()]}"
                         interface="{$instance/@id}" interface-name="{$instance/@name}"
                         datum="{$data/@id}" datum-name="{$data/@name}">
            <xsl:if test="fp:direction-guessed($port, $component, $realization)">
              <xsl:attribute name="direction-source" select="'guessed'"/>
            </xsl:if>
            <xsl:sequence select="$data/(@primitive, @type, @type-name, @lower, @upper), fp:constant($port, $instance)"/>
          </pim:data-port>
        </xsl:otherwise>
      </xsl:choose>
    </xsl:for-each>
  </xsl:function>
</xsl:stylesheet>
