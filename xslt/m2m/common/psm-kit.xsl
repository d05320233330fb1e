<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/common/psm-kit.xsl - what every PSM stage makes the same way from
  a bound PIM: the component wrapper (realizing class, lifecycle hooks,
  accessors, which operations and attributes a component offers), type
  look-up helpers and the parsing of default values. Included by each
  target's xslt/m2m/<target>/psm.xsl; a target formats what the kit finds.

  Reads:   elements of a bound PIM (urn:robomda:pim:1, xslt/m2m/bind.xsl).
  Writes:  elements in the including PSM's namespace, named by its globals
           $fp:psm-namespace (the namespace URI) and $fp:psm-prefix (its
           prefix), e.g. 'urn:robomda:psm-orocos:1' and 'o'; strings.
  Params:  none (the globals above are the including stylesheet's).
  Errors:  through f:fail, with the code the caller passes:
           fp:check-class-names  two component types map to one C++ class
           fp:parse-default      a default value is not valid for its kind

  Functions
    fp:package-name($requested, $model)  the package name ('' = from model)
    fp:type-cpp-name($def, $package)  the C++ name of a model data type or enumeration
    fp:on-target($instance, $middleware)  whether the target takes the instance
    fp:check-targets($model, $instances, $middleware, $package, $codes)  nothing to generate,
                                 instances taken though deployed elsewhere, each one left out
    fp:classes-with-ports-note($model)  what "nothing to generate" says of the classes with ports
    fp:kept-connection($connection, $binding, $targets)  a connection with an end in the package
    fp:psm-host-resources($host)  real-time, cores, memory and buses of a host
    fp:check-class-names($components, $code)
    fp:is-array($typed)          multiplicity upper bound other than 1
    fp:type-label($typed)        'Type' or 'Type[*]', for messages
    fp:type-library($typed)      the library of its type (a data port: its datum's)
    fp:library-note($typed)      what a target that cannot carry a ROS library
                                 message says of one: ' (a message of ...)', else ''
    fp:realization($bc)          the realizing class of a bound component
    fp:owner($bc)                where operations and attributes are read
    fp:callable($bc)             the non-private operations of the realization
    fp:psm-realizing-class($bc)  <x:realizing-class> of a wrapper, or ()
    fp:psm-hooks($bc)            <x:hook> per lifecycle hook, with call if any
    fp:psm-library($library, $package)   <x:library> of a pim:library
    fp:psm-doc($e)               <x:doc> of a model element's comment
    fp:accessor($data-port)      get<Datum> (out) / set<Datum> (in)
    fp:accessor-declared($data-port)  the realizing class has that accessor
    fp:offered-operations($bc, $excluded)  protected, not static, not excluded, or of a
                                 provided interface; never one of a required interface
    fp:interface-operations($service-ports)  the operations of their interfaces
    fp:provided-interface-operation($bc, $operation)  the operation of a provided interface it implements, if any
    fp:provided-service($bc, $operation)  that interface's name
    fp:check-services($components, $code)  one port per interface and role, one required operation per name
    fp:check-calls($calls, $targets, $code)  no call crosses middlewares
    fp:warn-unbound-services($instances, $code)  required interfaces no call binds
    fp:calls-declared($bc, $service-port, $operation, $generated, $code)  the class declares a required operation
    fp:warn-unused-values($instance, $exposed, $code)  values set on properties the target does not expose
    fp:warn-skipped-attributes($skipped, $code, $what)  attributes the convention
                                 would expose that the target cannot carry
    fp:configurable-attributes($bc)  the attributes stereotyped Configurable
    fp:convention-attributes($bc)    without any: the convention's choice
    fp:parse-default($value, $kind, $primitive, $id, $code)  see below (integers
                                 within the model type's range, fp:in-range)
    fp:decimal($number)          a number text with a '.0' where it has none
  Data types, arrays and inherited features: data-types.xsl (included).
  A realizing class's operations and attributes include those it inherits.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:include href="data-types.xsl"/>

  <!-- the lifecycle hooks a component may implement, in calling order -->
  <xsl:variable name="fp:lifecycle" as="xs:string+" select="('configure', 'start', 'update', 'stop', 'cleanup')"/>
  <!-- attribute names that configure the deployment, not the component
       (the import reads them as activity settings) -->
  <xsl:variable name="fp:convention-names" as="xs:string+" select="('sample', 'priority', 'scheduler', 'cpuAffinity')"/>

  <!-- every PIM element by its id; the including PSMs look up with it too -->
  <xsl:key name="fp:id" match="*[@id]" use="@id"/>
  <!-- the instances of a component, its binding, the calls an instance
       makes, the instances on a middleware, the links (buses) of a host -->
  <xsl:key name="fp:instance-of" match="pim:instance" use="@component"/>
  <xsl:key name="fp:bound-component" match="pim:bound-component" use="@component"/>
  <xsl:key name="fp:call-by-caller" match="pim:call" use="pim:caller/@instance"/>
  <xsl:key name="fp:instance-by-middleware" match="pim:instance" use="@middleware"/>
  <xsl:key name="fp:link-by-host" match="pim:link" use="pim:link-end/@host"/>

  <!-- ====================================================== deployment -->
  <!-- true when $instance goes into the package of the target for
       $middleware (OROCOS, ROS, ROS2): it is deployed on that middleware,
       or no instance of the model is (the target then takes them all: the
       same model runs on another middleware, and the target says so; an
       instance of a model that draws no execution environment has no
       middleware, and every target takes it without a word: bind said so,
       BND028) -->
  <xsl:function name="fp:on-target" as="xs:boolean">
    <xsl:param name="instance" as="element(pim:instance)"/>
    <xsl:param name="middleware" as="xs:string"/>
    <xsl:sequence select="$instance/@middleware eq $middleware
                          or empty(key('fp:instance-by-middleware', $middleware, root($instance)))"/>
  </xsl:function>

  <!-- the package's instances ($instances, fp:on-target) against the
       model's, for the target of $middleware whose package $package names
       ('Orocos', 'ROS 1'): $codes[1] (an error) when there is nothing to
       generate, $codes[2] when the package takes instances deployed on
       other middlewares (none is on $middleware), $codes[3] for each
       instance it leaves to another middleware's target -->
  <xsl:function name="fp:check-targets" as="empty-sequence()">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:param name="middleware" as="xs:string"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:param name="codes" as="xs:string+"/>
    <xsl:if test="empty($instances)">
      <xsl:sequence select="f:fail($codes[1], $model/@id, 'nothing to generate: model ''' || $model/@name
          || ''' has no component instance (a component with ports or a realizing class)'
          || fp:classes-with-ports-note($model))"/>
    </xsl:if>
    <xsl:variable name="other" as="element(pim:instance)*" select="$instances[@middleware ne $middleware]"/>
    <xsl:if test="exists($other)">
      <xsl:sequence select="f:warn($codes[2], $other[1]/@execution-environment, 'no instance is deployed on '
          || $middleware || ': the platform model deploys ''' || string-join($other/@name, ''', ''') || ''' on '
          || string-join(distinct-values($other/@middleware), ', ') || '; all ' || count($other)
          || ' are generated for ' || $package || ' anyway')"/>
    </xsl:if>
    <xsl:for-each select="$model/pim:binding/pim:instance except $instances">
      <xsl:sequence select="f:warn($codes[3], string(@xmi-id), 'instance ''' || @name || ''' is deployed on '
          || @middleware || ', not ' || $middleware || ': it is not part of the ' || $package
          || ' package (the ' || @middleware || ' target generates it)')"/>
    </xsl:for-each>
  </xsl:function>

  <!-- what ORO005 / ROS008 / RTM005 add about the classes with ports the
       model has, which bind did not take as components
       (xslt/m2m/bind/classes.xsl): each named with what it lacks -->
  <xsl:function name="fp:classes-with-ports-note" as="xs:string">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:variable name="classes" as="element(pim:class)*" select="$model/pim:application//pim:class[pim:port]"/>
    <xsl:sequence select="if (empty($classes)) then ''
        else '; of its ' || count($classes) || ' class' || (if (count($classes) gt 1) then 'es' else '')
             || ' with ports, none is a component: '
             || string-join(for $c in $classes[position() le 5]
                            return '''' || $c/@name || ''' ('
                                   || (if (every $p in $c/pim:port satisfies empty($p/(@type, @type-name, @primitive, @direction,
                                                                                     pim:provided, pim:required)))
                                       then 'its ports have no type and no direction, and it is'
                                       else 'it is') || ' the type of no part and in no known profile)', ', ')
             || (if (count($classes) gt 5) then ' and ' || count($classes) - 5 || ' more' else '')
             || '; a class is a component when it is the type of a part (a property of a composite class), '
             || 'or stereotyped as a component in its tool''s profile (docs/profile.md, section Components drawn as classes)'"/>
  </xsl:function>

  <!-- a connection of $binding that a PSM keeps: one of its ends is an
       instance of the package ($targets: the names of the instances of
       $binding that are on the target, see fp:on-target), and it has ends
       on both sides; an end on another middleware is reached through a
       transport, or the target says why not -->
  <xsl:function name="fp:kept-connection" as="xs:boolean">
    <xsl:param name="connection" as="element(pim:connection)"/>
    <xsl:param name="binding" as="element(pim:binding)"/>
    <xsl:param name="targets" as="map(xs:string, xs:boolean)"/>
    <xsl:sequence select="$connection/.. is $binding
                          and exists($connection/pim:writer) and exists($connection/pim:reader)
                          and (some $n in ($connection/pim:writer | $connection/pim:reader)/@instance satisfies map:contains($targets, string($n)))"/>
  </xsl:function>

  <!-- what a PSM host carries of $host's computational resources (seed
       002): attributes real-time, cores, memory, and a <bus> per
       communication path with its kind, bandwidth and the nodes at its
       other ends -->
  <xsl:function name="fp:psm-host-resources" as="node()*">
    <xsl:param name="host" as="element(pim:host)"/>
    <xsl:attribute name="real-time" select="$host/@real-time"/>
    <xsl:sequence select="$host/(@cores, @memory)"/>
    <xsl:for-each select="key('fp:link-by-host', $host/@xmi-id, root($host))[.. is $host/..]">
      <xsl:element name="{$fp:psm-prefix}:bus" namespace="{$fp:psm-namespace}">
        <xsl:attribute name="name" select="@name"/>
        <xsl:attribute name="kind" select="@kind"/>
        <xsl:attribute name="to" select="string-join((pim:link-end[not(@host = $host/@xmi-id)]/@node ! key('fp:id', ., root($host))/@name), ', ')"/>
        <xsl:sequence select="@bandwidth"/>
      </xsl:element>
    </xsl:for-each>
  </xsl:function>

  <!-- ========================================================== package -->
  <xsl:function name="fp:package-name" as="xs:string">
    <xsl:param name="requested" as="xs:string"/>
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:sequence select="f:snake-case(if (normalize-space($requested)) then $requested else $model/@name)"/>
  </xsl:function>

  <!-- the C++ name of the model's data type or enumeration $def in package
       $package: ::<package>::types::<Name>. The package's namespace, as its
       RTT type name /<package>/<Name> and its ROS message <package>/<Name>
       are, so that two packages' JointState are two C++ types in one
       process; and below it "types", because ROS 1 declares the package's
       generated message as <package>::JointState (messages and components
       are UpperCamel, so no ROS 1 message or component is named "types";
       ROS 2's are in <package>::msg). docs/profile.md -->
  <xsl:function name="fp:type-cpp-name" as="xs:string">
    <xsl:param name="def" as="element()"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:sequence select="'::' || $package || '::types::' || f:cpp-identifier($def/@name)"/>
  </xsl:function>

  <!-- ================================================ operation calls -->
  <!-- seed 003's operation calls between components (service ports and
       pim:call, xslt/m2m/bind/services.xsl): a provider offers the
       operations of its provided interfaces, a caller calls those of its
       required ones -->
  <xsl:function name="fp:interface-operations" as="element(pim:operation)*">
    <xsl:param name="service-ports" as="element(pim:service-port)*"/>
    <xsl:sequence select="$service-ports ! key('fp:id', @interface, root(.))/pim:operation"/>
  </xsl:function>

  <!-- the operation (by name) of the first provided service port's
       interface that $operation implements, or () -->
  <xsl:function name="fp:provided-interface-operation" as="element(pim:operation)?">
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:param name="operation" as="element(pim:operation)"/>
    <xsl:sequence select="fp:interface-operations($bc/pim:service-port[@role eq 'provided'])[@name eq $operation/@name][1]"/>
  </xsl:function>

  <!-- the name of that operation's interface (the service port's
       interface-name), or () -->
  <xsl:function name="fp:provided-service" as="xs:string?">
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:param name="operation" as="element(pim:operation)"/>
    <xsl:sequence select="fp:provided-interface-operation($bc, $operation)/../@name"/>
  </xsl:function>

  <!-- fails with $code where a component of $components has two service
       ports of one interface and role (a middleware names the service after
       its interface), or requires two operations of one name (one method
       calls each) -->
  <xsl:function name="fp:check-services" as="empty-sequence()">
    <xsl:param name="components" as="element(pim:bound-component)*"/>
    <xsl:param name="code" as="xs:string"/>
    <xsl:variable name="problems" as="map(*)*">
      <xsl:for-each select="$components">
        <xsl:variable name="bc" as="element(pim:bound-component)" select="."/>
        <xsl:for-each-group select="pim:service-port" group-by="@role || ' ' || @interface">
          <xsl:if test="count(current-group()) gt 1">
            <xsl:sequence select="map { 'code': $code, 'id': string(current-group()[2]/@port), 'message': 'component '''
                || $bc/@name || ''' has ports ''' || string-join(current-group()/@port-name, ''', ''') || ''' that '
                || (if (@role eq 'provided') then 'provide' else 'require') || ' interface ''' || @interface-name
                || ''': a middleware names the service after its interface; use one port' }"/>
          </xsl:if>
        </xsl:for-each-group>
        <xsl:for-each-group select="fp:interface-operations(pim:service-port[@role eq 'required'])" group-by="@name">
          <xsl:if test="count(current-group()) gt 1">
            <xsl:sequence select="map { 'code': $code, 'id': string(current-group()[2]/@id), 'message': 'component '''
                || $bc/@name || ''' requires two operations named ''' || current-grouping-key()
                || ''' (interfaces ''' || string-join(current-group()/../@name, ''', ''') || '''): one method calls each; rename one' }"/>
          </xsl:if>
        </xsl:for-each-group>
      </xsl:for-each>
    </xsl:variable>
    <xsl:sequence select="f:fail-all($problems)"/>
  </xsl:function>

  <!-- fails with $code for each call of $calls with one end in the package
       ($targets: the names of its instances) and the other on another
       middleware: a call does not cross middlewares -->
  <xsl:function name="fp:check-calls" as="empty-sequence()">
    <xsl:param name="calls" as="element(pim:call)*"/>
    <xsl:param name="targets" as="map(xs:string, xs:boolean)"/>
    <xsl:param name="code" as="xs:string"/>
    <xsl:sequence select="f:fail-all($calls[count((pim:caller, pim:provider)[map:contains($targets, string(@instance))]) eq 1]
        ! map { 'code': $code, 'id': string(@xmi-id), 'message': 'instance ''' || pim:caller/@instance
                || ''' calls the operations of interface ''' || key('fp:id', @interface, root(.))/@name || ''' on instance '''
                || pim:provider/@instance || ''', which is deployed on another middleware: operation calls do not cross'
                || ' middlewares; deploy both on one, or exchange the data through data ports' })"/>
  </xsl:function>

  <!-- a warning $code for each required service port of $instances that no
       call binds: its calls fail at run time -->
  <xsl:function name="fp:warn-unbound-services" as="empty-sequence()">
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:param name="code" as="xs:string"/>
    <xsl:for-each select="$instances">
      <xsl:variable name="instance" as="element(pim:instance)" select="."/>
      <xsl:for-each select="key('fp:bound-component', @component, root(.))/pim:service-port[@role eq 'required']
                            [not(@name = key('fp:call-by-caller', $instance/@name, root(.))/pim:caller/@service-port)]">
        <xsl:sequence select="f:warn($code, @port, 'instance ''' || $instance/@name || ''' requires interface '''
            || @interface-name || ''' (port ''' || @port-name || ''') but no connector binds it to a provider:'
            || ' the component will not configure; draw the connector to the component that provides it')"/>
      </xsl:for-each>
    </xsl:for-each>
  </xsl:function>

  <!-- whether the class of $bc declares $operation of its required
       interface ($service-port), so that the generated class can override
       it to make the call (a component without a class: the generated base
       defines it); else a warning $code naming $generated, the caller the
       target generates anyway -->
  <xsl:function name="fp:calls-declared" as="xs:boolean">
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:param name="service-port" as="element(pim:service-port)"/>
    <xsl:param name="operation" as="element(pim:operation)"/>
    <xsl:param name="generated" as="xs:string"/>
    <xsl:param name="code" as="xs:string"/>
    <xsl:variable name="declared" as="xs:boolean"
        select="empty(fp:realization($bc)) or $operation/@name = fp:callable($bc)/@name"/>
    <xsl:if test="not($declared)">
      <xsl:sequence select="f:warn($code, $service-port/@port, 'component ''' || $bc/@name || ''' requires operation '''
          || $operation/@name || ''' of interface ''' || $service-port/@interface-name || ''', but its class '''
          || $bc/@realization-name || ''' does not declare it: the generated ' || $generated
          || ' is there, but the class cannot call it; declare the operation (abstract) in the class')"/>
    </xsl:if>
    <xsl:sequence select="$declared"/>
  </xsl:function>

  <!-- fails with $code when two of $components map to one C++ class -->
  <xsl:function name="fp:check-class-names" as="empty-sequence()">
    <xsl:param name="components" as="element(pim:bound-component)*"/>
    <xsl:param name="code" as="xs:string"/>
    <xsl:for-each-group select="$components" group-by="f:upper-camel(@name)">
      <xsl:if test="count(current-group()) gt 1">
        <xsl:sequence select="f:fail($code, current-group()[2]/@component, 'components '''
            || string-join(current-group()/@name, ''', ''') || ''' all map to C++ class ' || current-grouping-key())"/>
      </xsl:if>
    </xsl:for-each-group>
  </xsl:function>

  <!-- ============================================================ types -->
  <xsl:function name="fp:is-array" as="xs:boolean">
    <xsl:param name="typed" as="element()"/>
    <xsl:sequence select="exists($typed/@upper) and not($typed/@upper = ('1', ''))"/>
  </xsl:function>

  <xsl:function name="fp:type-label" as="xs:string">
    <xsl:param name="typed" as="element()"/>
    <xsl:sequence select="($typed/@type-name, $typed/@primitive, '?')[1]
                          || (if (fp:is-array($typed)) then '[' || $typed/@upper || ']' else '')"/>
  </xsl:function>

  <xsl:function name="fp:type-library" as="xs:string?">
    <xsl:param name="typed" as="element()"/>
    <xsl:sequence select="($typed/@type-library, $typed/self::pim:data-port/key('fp:id', @datum, root(.))/@type-library)[1]"/>
  </xsl:function>

  <xsl:function name="fp:library-note" as="xs:string">
    <xsl:param name="typed" as="element()"/>
    <xsl:sequence select="if (fp:type-library($typed) eq 'ros-message')
        then ' (a message of the ROS library the model names, which the ros1 and ros2 targets carry)' else ''"/>
  </xsl:function>

  <!-- ================================================ component wrapper -->

  <xsl:function name="fp:realization" as="element(pim:class)?">
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:sequence select="key('fp:id', $bc/@realization, root($bc))"/>
  </xsl:function>

  <!-- the realizing class, else the component itself (a "base" component) -->
  <xsl:function name="fp:owner" as="element()">
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:sequence select="(fp:realization($bc), key('fp:id', $bc/@component, root($bc)))[1]"/>
  </xsl:function>

  <xsl:function name="fp:callable" as="element(pim:operation)*">
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:sequence select="fp:realization($bc) ! fp:operations(.)[@visibility ne 'private']"/>
  </xsl:function>

  <xsl:function name="fp:psm-realizing-class" as="element()?">
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:for-each select="fp:realization($bc)">
      <xsl:element name="{$fp:psm-prefix}:realizing-class" namespace="{$fp:psm-namespace}">
        <xsl:attribute name="xmi-id" select="@id"/>
        <xsl:attribute name="name" select="@name"/>
        <xsl:attribute name="cpp-name"
            select="'::' || string-join(tokenize($bc/@cpp-name, '::')[normalize-space(.)] ! f:cpp-identifier(.), '::')"/>
        <xsl:attribute name="header" select="$bc/@header"/>
      </xsl:element>
    </xsl:for-each>
  </xsl:function>

  <!-- one hook per lifecycle name; call / returns-bool / xmi-id where the
       realizing class implements it -->
  <xsl:function name="fp:psm-hooks" as="element()+">
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:variable name="callable" as="element(pim:operation)*" select="fp:callable($bc)"/>
    <xsl:for-each select="$fp:lifecycle">
      <xsl:variable name="hook" as="xs:string" select="."/>
      <xsl:variable name="operation" as="element(pim:operation)?" select="$callable[@name eq $hook][1]"/>
      <xsl:element name="{$fp:psm-prefix}:hook" namespace="{$fp:psm-namespace}">
        <xsl:attribute name="name" select="$hook"/>
        <xsl:if test="$operation">
          <xsl:attribute name="call" select="$hook"/>
          <xsl:attribute name="returns-bool" select="$operation/pim:parameter[@direction eq 'return']/@primitive = 'boolean'"/>
          <xsl:attribute name="xmi-id" select="$operation/@id"/>
        </xsl:if>
      </xsl:element>
    </xsl:for-each>
  </xsl:function>

  <xsl:function name="fp:psm-library" as="element()">
    <xsl:param name="library" as="element(pim:library)"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:element name="{$fp:psm-prefix}:library" namespace="{$fp:psm-namespace}">
      <xsl:sequence select="$library/@xmi-id, $library/@name, $library/@path, $library/@absolute,
                            $library/@target, $library/@include-dir"/>
      <xsl:attribute name="cmake-var" select="upper-case($package) || '_' || upper-case(f:snake-case($library/@name)) || '_DIR'"/>
      <xsl:attribute name="build-dir" select="f:snake-case($library/@name) || '-build'"/>
    </xsl:element>
  </xsl:function>

  <xsl:function name="fp:psm-doc" as="element()?">
    <xsl:param name="element" as="element()?"/>
    <xsl:for-each select="$element/pim:doc[normalize-space(.)]">
      <xsl:element name="{$fp:psm-prefix}:doc" namespace="{$fp:psm-namespace}">
        <xsl:value-of select="normalize-space(.)"/>
      </xsl:element>
    </xsl:for-each>
  </xsl:function>

  <xsl:function name="fp:accessor" as="xs:string">
    <xsl:param name="data-port" as="element(pim:data-port)"/>
    <xsl:sequence select="(if ($data-port/@direction eq 'out') then 'get' else 'set')
                          || f:upper-first(f:cpp-identifier($data-port/@datum-name))"/>
  </xsl:function>

  <xsl:function name="fp:accessor-declared" as="xs:boolean">
    <xsl:param name="data-port" as="element(pim:data-port)"/>
    <xsl:variable name="accessor" as="xs:string" select="fp:accessor($data-port)"/>
    <xsl:sequence select="exists(fp:callable($data-port/..)[@name eq $accessor])"/>
  </xsl:function>

  <!-- the operations a component offers: the protected, non-static
       operations of its owner (fp:owner) not named in $excluded -->
  <xsl:function name="fp:offered-operations" as="element(pim:operation)*">
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:param name="excluded" as="xs:string*"/>
    <xsl:variable name="operations" as="element(pim:operation)*" select="fp:operations(fp:owner($bc))"/>
    <xsl:sequence select="($operations[@visibility eq 'protected'][not(@static = ('true', '1'))][not(@name = $excluded)]
                           | $operations[@visibility ne 'private'][@name = fp:interface-operations($bc/pim:service-port[@role eq 'provided'])/@name])
                          [not(@name = fp:interface-operations($bc/pim:service-port[@role eq 'required'])/@name)]"/>
  </xsl:function>

  <!-- a warning $code for each value the model sets on a property of
       $instance beyond its default (pim:property-value: a part's slot or a
       composite's promoted property, seed 003) that the target does not
       use: $exposed, the ids of the attributes it makes properties or
       parameters, does not hold it -->
  <xsl:function name="fp:warn-unused-values" as="empty-sequence()">
    <xsl:param name="instance" as="element(pim:instance)"/>
    <xsl:param name="exposed" as="xs:string*"/>
    <xsl:param name="code" as="xs:string"/>
    <xsl:for-each select="$instance/pim:property-value[not(@attribute = $exposed)]">
      <xsl:sequence select="f:warn($code, string(@holder), 'the value ''' || @value || ''' the model sets on '''
          || @name || ''' of instance ''' || $instance/@name || ''' is not used: that attribute is no property of the'
          || ' component (mark it Configurable, or, without any Configurable, make it public or protected)')"/>
    </xsl:for-each>
  </xsl:function>

  <!-- a warning $code for each attribute the convention would expose that
       the target has no type for ($what: 'Orocos property', ...): never
       left out silently -->
  <xsl:function name="fp:warn-skipped-attributes" as="empty-sequence()">
    <xsl:param name="skipped" as="element(pim:attribute)*"/>
    <xsl:param name="code" as="xs:string"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:for-each select="$skipped">
      <xsl:sequence select="f:warn($code, string(@id), 'attribute ''' || @name || ''' of type ''' || fp:type-label(.)
          || ''' is no ' || $what || ': the target cannot carry that type (stereotype it Configurable to make'
          || ' this an error, or make it private)')"/>
    </xsl:for-each>
  </xsl:function>

  <xsl:function name="fp:configurable-attributes" as="element(pim:attribute)*">
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:sequence select="fp:attributes(fp:owner($bc))[exists(f:stereotype(., 'Configurable'))]"/>
  </xsl:function>

  <!-- the attributes a component without Configurable ones exposes: public
       and protected, not static, not read-only, not a convention name (the
       caller keeps those its target has a type for) -->
  <xsl:function name="fp:convention-attributes" as="element(pim:attribute)*">
    <xsl:param name="bc" as="element(pim:bound-component)"/>
    <xsl:sequence select="fp:attributes(fp:owner($bc))[@visibility = ('public', 'protected')]
                            [not(@static = ('true', '1'))][not(@read-only = ('true', '1'))]
                            [not(@name = $fp:convention-names)]"/>
  </xsl:function>

  <!-- ==================================================== default values -->
  <!-- A model's default value, checked against the kind of value its type
       holds, as a canonical text each target formats in its own languages:
         string   the text, unquoted ('x' or "x" in the model)
         boolean  'true' or 'false' (from true / false / 1 / 0, any case)
         char     the one character (the caller decides which it accepts)
         real     the number as written, without a C++ suffix (f, d, L ...)
         integer  the canonical integer; not negative for an unsigned
                  $primitive ('u...' or 'octet')
       Fails with $code, naming $value, when it does not fit. -->
  <xsl:function name="fp:parse-default" as="xs:string">
    <xsl:param name="value" as="xs:string"/>
    <xsl:param name="kind" as="xs:string"/>
    <xsl:param name="primitive" as="xs:string"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:param name="code" as="xs:string"/>
    <xsl:variable name="text" as="xs:string" select="f:unquote(normalize-space($value))"/>
    <xsl:variable name="number" as="xs:string" select="replace($text, '^([+\-]?[0-9.eE+\-]+)[fFdDlLuU]*$', '$1')"/>
    <xsl:sequence select="
      if ($kind eq 'string') then $text
      else if ($kind eq 'boolean') then
        (if (lower-case($text) = ('true', '1')) then 'true'
         else if (lower-case($text) = ('false', '0')) then 'false'
         else f:fail($code, $id, 'default ''' || $value || ''' is not a boolean'))
      else if ($kind eq 'char') then $text
      else if ($kind eq 'real') then
        (if ($number castable as xs:double and not(matches($number, 'nan|inf', 'i'))) then $number
         else f:fail($code, $id, 'default ''' || $value || ''' is not a number'))
      else
        (if ($number castable as xs:integer and fp:in-range(xs:integer($number), $primitive))
         then string(xs:integer($number))
         else f:fail($code, $id, 'default ''' || $value || ''' is not a valid ' || $primitive
                     || (if ($number castable as xs:integer)
                         then ' (' || string-join(map:get($fp:integer-range, $primitive) ! string(.), ' to ') || ')' else '')))"/>
  </xsl:function>

  <!-- the least and the greatest value of each integer kind -->
  <xsl:variable name="fp:integer-range" as="map(xs:string, xs:integer+)" select="map {
      'octet': (0, 255), 'int16': (-32768, 32767), 'uint16': (0, 65535),
      'int32': (-2147483648, 2147483647), 'uint32': (0, 4294967295),
      'int64': (-9223372036854775808, 9223372036854775807), 'uint64': (0, 18446744073709551615) }"/>

  <xsl:function name="fp:in-range" as="xs:boolean">
    <xsl:param name="number" as="xs:integer"/>
    <xsl:param name="primitive" as="xs:string"/>
    <xsl:variable name="range" as="xs:integer*" select="map:get($fp:integer-range, $primitive)"/>
    <xsl:sequence select="empty($range) or ($number ge $range[1] and $number le $range[2])"/>
  </xsl:function>

  <xsl:function name="fp:decimal" as="xs:string">
    <xsl:param name="number" as="xs:string"/>
    <xsl:sequence select="if (contains($number, '.') or contains(lower-case($number), 'e')) then $number else $number || '.0'"/>
  </xsl:function>
</xsl:stylesheet>
