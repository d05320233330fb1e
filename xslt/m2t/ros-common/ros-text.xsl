<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros-common/ros-text.xsl - text helpers shared by the ROS 1 and
  ROS 2 text stages (included by xslt/m2t/ros1/main.xsl and ros2/main.xsl).

  Reads:   r:package of urn:robomda:psm-ros:1 (some helpers).
  Writes:  strings.  Params: none (model-dir-from-output: ../common/text.xsl).
  Errors:  none. The target-neutral helpers (lines, banners, literals,
  guards, library paths) are in ../common/text.xsl.
    fp:double-literal($v)  a C++ / YAML floating literal of a number
    fp:service-body($s, $rc, $acc)  the statements of a service callback
    fp:client-method($c, $qualifier)  the signature of a method calling a required operation
    fp:is-own-service($s), fp:own-signature($s, $qualifier, $names)  a service of
                           the package's own (srv/<Name>.srv), its operation's C++ signature
    fp:service-callback-names($s)  the callback's (request, response) names
    fp:srv-file($t)        the text of srv/<Name>.srv
    fp:client-overrides($node)   their declarations in the node class
    fp:from-msg / fp:to-msg  datum <-> message conversion (ROS 1 and 2 alike)
    fp:ros-step($node, $types, $publish)  the body of a node's step()
    fp:ros-publish-constants($node, $types, $publish)  «Constant» outputs, published once
    fp:ros-header-opening / fp:ros-source-opening($node)  banner and guard /
                           banner and include of a node's C++ files
    fp:ros-package-xml-opening($package)  package.xml up to its name
    fp:ros-on-input($port, $rc)  the body of a subscription callback
    fp:ros-fqn($i)         the full name of an instance's node
    fp:msg-parts($msg, $pkg)  (package, Name) of a message: a generated
                           message (no "/") lives in package $pkg
    fp:library-external-project / fp:library-vars / fp:library-depends  CMake lines
                           finding, linking and building first the atomic-code
                           library (cache variable as in the Orocos target)
    fp:yaml-string($s)     a YAML double-quoted scalar
    fp:yaml-mapping($values, $prefix)  parameter values as (nested) YAML lines
    fp:parameter-assign($p, $type, $error, $indent)  a parameter's value into its member
    fp:conversions-include($node)  the include of the message conversions, if used
    fp:ros-type-files($package)  include/<Type>.hpp, msg/<Type>.msg and
                           include/<pkg>/msg_conversions.hpp of the model's types
    fp:msg-file / fp:ros-conversions  their texts
    fp:ros1-type / fp:ros2-type  (header, C++ type) of a message or service
    fp:ros-children($key, $package, $values)  the instances (sets) of a host,
                           the members of a set, the hosts and processes by
                           name, a host's and a set's processes, the nodes by
                           class: through keys fp:ros-on-host,
                           fp:ros-set-on-host, fp:ros-in-set, fp:ros-host,
                           fp:ros-process, fp:ros-process-on-host,
                           fp:ros-process-in-set and fp:ros-node, so that a
                           launch file does not scan every instance, host,
                           process or node
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:fs="urn:robomda:fileset:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:m="urn:robomda:xslt:mode"
    exclude-result-prefixes="#all">

  <!-- the instances and component sets of a host, the members of a set;
       hosts and processes by name, the processes of a host and of a set -->
  <xsl:key name="fp:ros-on-host" match="r:package/r:instance" use="@host"/>
  <xsl:key name="fp:ros-set-on-host" match="r:package/r:set" use="@host"/>
  <xsl:key name="fp:ros-in-set" match="r:package/r:instance" use="@set"/>
  <xsl:key name="fp:ros-host" match="r:package/r:host" use="@name"/>
  <xsl:key name="fp:ros-process" match="r:package/r:process" use="@name"/>
  <xsl:key name="fp:ros-process-on-host" match="r:package/r:process" use="@host"/>
  <xsl:key name="fp:ros-process-in-set" match="r:package/r:process" use="@set"/>
  <xsl:key name="fp:ros-node" match="r:package/r:node" use="@class"/>

  <!-- the children of $package that key $key finds for any of $values, in
       document order: as $package/r:instance[@host = $values] (fp:ros-on-host),
       r:set[@host = $values] (fp:ros-set-on-host), r:instance[@set = $values]
       (fp:ros-in-set), r:host[@name = $values] (fp:ros-host),
       r:process[@name = $values] (fp:ros-process), r:process[@host = $values]
       (fp:ros-process-on-host), r:process[@set = $values] (fp:ros-process-in-set)
       or r:node[@class = $values] (fp:ros-node) -->
  <xsl:function name="fp:ros-children" as="element()*">
    <xsl:param name="key" as="xs:string"/>
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="values" as="xs:string*"/>
    <xsl:sequence select="if (root($package) instance of document-node())
                          then key($key, $values, root($package))[.. is $package]
                          else if ($key eq 'fp:ros-on-host') then $package/r:instance[@host = $values]
                          else if ($key eq 'fp:ros-set-on-host') then $package/r:set[@host = $values]
                          else if ($key eq 'fp:ros-in-set') then $package/r:instance[@set = $values]
                          else if ($key eq 'fp:ros-host') then $package/r:host[@name = $values]
                          else if ($key eq 'fp:ros-process') then $package/r:process[@name = $values]
                          else if ($key eq 'fp:ros-process-on-host') then $package/r:process[@host = $values]
                          else if ($key eq 'fp:ros-node') then $package/r:node[@class = $values]
                          else $package/r:process[@set = $values]"/>
  </xsl:function>

  <!-- the entry of both ROS text stages: their r:package template (mode
       m:emit-files) makes the file set. It comes out as f:indent (common/indent.xsl) would indent
       it (one fs:file a line; their text as it is), written so directly with
       t:indented-content: f:indent would copy all the text once more -->
  <xsl:template match="/" as="document-node()">
    <xsl:document>
      <xsl:apply-templates select="r:package" mode="m:emit-files"/>
    </xsl:document>
  </xsl:template>

  <!-- the full name of the node of instance $i, relative to the namespace
       its launch file runs in: /name, or /namespace/name for a part of a
       composite (seed 003) -->
  <xsl:function name="fp:ros-fqn" as="xs:string">
    <xsl:param name="i" as="element(r:instance)"/>
    <xsl:sequence select="if ($i/@namespace) then concat('/', $i/@namespace, '/', $i/@node-name) else concat('/', $i/@name)"/>
  </xsl:function>

  <!-- the name attributes of a launch file's node: name="..." and, for a
       node inside a composite part (seed 003), its namespace in the
       attribute $namespace-attribute (ROS 1 ns, ROS 2 namespace), relative
       to the launch file's namespace -->
  <xsl:function name="fp:node-name-attributes" as="xs:string">
    <xsl:param name="instance" as="element(r:instance)"/>
    <xsl:param name="namespace-attribute" as="xs:string"/>
    <xsl:sequence select="concat('name=&quot;', ($instance/@node-name, $instance/@name)[1], '&quot;',
        $instance/@namespace ! concat(' ', $namespace-attribute, '=&quot;', ., '&quot;'))"/>
  </xsl:function>

  <!-- parameter values as YAML mapping lines: a path gains.stiffness nests
       (gains: then stiffness: one level in), which both rosparam (ROS 1:
       ~gains/stiffness) and ROS 2 (gains.stiffness) read so. An empty list
       is left out (ROS 2 cannot type it): the node's default applies. -->
  <xsl:function name="fp:yaml-mapping" as="xs:string*">
    <xsl:param name="values" as="element(r:parameter-value)*"/>
    <xsl:param name="prefix" as="xs:string"/>
    <xsl:for-each-group select="$values[@yaml ne '[]']" group-by="tokenize(substring(@name, string-length($prefix) + 1), '\.')[1]">
      <xsl:variable name="key" as="xs:string" select="current-grouping-key()"/>
      <xsl:variable name="leaf" as="element(r:parameter-value)?" select="current-group()[@name eq $prefix || $key][1]"/>
      <xsl:sequence select="if ($leaf) then $key || ': ' || $leaf/@yaml
          else ($key || ':', fp:indent(2, fp:yaml-mapping(current-group(), $prefix || $key || '.')))"/>
    </xsl:for-each-group>
  </xsl:function>

  <xsl:function name="fp:yaml-string" as="xs:string">
    <xsl:param name="text" as="xs:string?"/>
    <xsl:sequence select="fp:cpp-string($text)"/>
  </xsl:function>

  <!-- a user-owned parameter file, loaded after the generated one: the place
       for the values tuned on the robot (it starts empty; its values win) -->
  <xsl:function name="fp:user-params-yaml" as="xs:string">
    <xsl:param name="what" as="xs:string"/>
    <xsl:param name="generated" as="xs:string"/>
    <xsl:param name="stylesheet" as="xs:string"/>
    <xsl:param name="empty" as="xs:string+"/>
    <xsl:sequence select="fp:lines((
        fp:banner('# ', $stylesheet, $what, true()),
        concat('# The launch files load it after ', $generated, ': a parameter set here wins over the'),
        '# generated value, so tuning on the robot never means editing a generated file. Write',
        '# the same keys as there, in place of the empty mapping below.',
        $empty))"/>
  </xsl:function>

  <xsl:function name="fp:msg-parts" as="xs:string+">
    <xsl:param name="msg" as="xs:string"/>
    <xsl:param name="pkg" as="xs:string"/>
    <xsl:sequence select="if (contains($msg, '/')) then (substring-before($msg, '/'), substring-after($msg, '/')) else ($pkg, $msg)"/>
  </xsl:function>

  <xsl:function name="fp:double-literal" as="xs:string">
    <xsl:param name="value" as="xs:string"/>
    <xsl:sequence select="if (contains($value, '.') or contains(lower-case($value), 'e')) then $value else concat($value, '.0')"/>
  </xsl:function>

  <!-- the method that calls operation $client of a required interface:
       "bool name(bool argument)" (std_srvs), else its own signature
       (fp:own-signature); $qualifier is '' or 'Class::' -->
  <xsl:function name="fp:client-method" as="xs:string">
    <xsl:param name="client" as="element(r:service-client)"/>
    <xsl:param name="qualifier" as="xs:string"/>
    <xsl:sequence select="if (fp:is-own-service($client)) then fp:own-signature($client, $qualifier, true())
                          else concat(if (xs:boolean($client/@returns-bool)) then 'bool ' else 'void ', $qualifier, $client/@name,
                                      '(', $client/@argument ! concat('bool ', .), ')')"/>
  </xsl:function>

  <!-- true for a service or client $s of a service of the package's own
       (its arguments and result: r:argument, r:result) -->
  <xsl:function name="fp:is-own-service" as="xs:boolean">
    <xsl:param name="s" as="element()"/>
    <xsl:sequence select="exists($s/(r:argument, r:result))"/>
  </xsl:function>

  <!-- the C++ signature of the operation of service or client $s of the
       package's own: "Result name(const Argument& argument)", the result
       and arguments the C++ types of their data, a built-in type (no
       namespace: double, int32_t) passed by value ($names false: the
       argument names commented out, for a skeleton that uses none) -->
  <xsl:function name="fp:own-signature" as="xs:string">
    <xsl:param name="s" as="element()"/>
    <xsl:param name="qualifier" as="xs:string"/>
    <xsl:param name="names" as="xs:boolean"/>
    <xsl:sequence select="($s/r:result/r:message/@cpp-type, 'void')[1] || ' ' || $qualifier || $s/@name || '('
        || string-join($s/r:argument ! ((if (matches(r:message/@cpp-type, '^[a-z][a-z0-9_ ]*$')) then r:message/@cpp-type || ' '
                                         else 'const ' || r:message/@cpp-type || ' &amp; ')
                                        || (if ($names) then @name else '/*' || @name || '*/')), ', ')
        || ')'"/>
  </xsl:function>

  <!-- the parameter names of the callback of service $service: (request,
       response), each commented out where the callback does not use it -->
  <xsl:function name="fp:service-callback-names" as="xs:string+">
    <xsl:param name="service" as="element(r:service)"/>
    <xsl:sequence select="(if ($service/@srv eq 'std_srvs/SetBool' or $service/r:argument) then 'request' else '/*request*/'),
                          (if ($service/@srv eq 'std_srvs/Empty' or (fp:is-own-service($service) and empty($service/r:result)))
                           then '/*response*/' else 'response')"/>
  </xsl:function>

  <!-- the declarations a node class adds for its required interfaces:
       the overrides that call (protected, as the realizing class declares
       them) -->
  <xsl:function name="fp:client-overrides" as="xs:string*">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:if test="$node/r:service-client[xs:boolean(@forward)]">
      <xsl:sequence select="'', 'protected:', '  // required interfaces (seed 003): each operation calls the provider''s service',
          $node/r:service-client[xs:boolean(@forward)] ! concat('  ', fp:client-method(., ''), ' override;')"/>
    </xsl:if>
  </xsl:function>

  <!-- body of a service callback; $acc is "." (ROS 1) or "->" (ROS 2): a
       service of the package's own hands the request's fields to the
       operation and its result to the response's field -->
  <xsl:function name="fp:service-body" as="xs:string*">
    <xsl:param name="service" as="element(r:service)"/>
    <xsl:param name="rc" as="xs:string"/>
    <xsl:param name="acc" as="xs:string"/>
    <xsl:variable name="call" as="xs:string"
        select="if (fp:is-own-service($service))
                then $rc || '::' || $service/@name || '('
                     || string-join($service/r:argument ! fp:from-msg(r:message, 'request' || $acc || @field), ', ') || ')'
                else concat($rc, '::', $service/@name, '(', (if ($service/@srv eq 'std_srvs/SetBool') then concat('request', $acc, 'data') else ''), ')')"/>
    <xsl:sequence select="
        if ($service/r:result) then fp:indent(2, fp:to-msg($service/r:result/r:message, 'response' || $acc || $service/r:result/@field, $call))
        else if ($service/@srv eq 'std_srvs/Empty' or fp:is-own-service($service)) then concat('  ', $call, ';')
        else if (xs:boolean($service/@returns-bool)) then concat('  response', $acc, 'success = ', $call, ';')
        else (concat('  ', $call, ';'), concat('  response', $acc, 'success = true;'))"/>
  </xsl:function>

  <!-- the expression converting message expression $m to the datum: a
       generated message through its conversion (fp:ros-conversions), a
       multi-array's data copied, else the datum field or the message -->
  <xsl:function name="fp:from-msg" as="xs:string">
    <xsl:param name="msg" as="element(r:message)"/>
    <xsl:param name="model" as="xs:string"/>
    <xsl:sequence select="if ($msg/@generated eq 'true') then 'from_msg_value&lt;' || $msg/@cpp-type || '&gt;(' || replace($model, '^\((.*)\)$', '$1') || ')'
        else if ($msg/@sequence eq 'true') then $msg/@cpp-type || '(' || $model || '.data.begin(), ' || $model || '.data.end())'
        else if ($msg/@field ne '') then concat($model, '.', $msg/@field) else $model"/>
  </xsl:function>

  <!-- the statements setting message $var to the datum $value -->
  <xsl:function name="fp:to-msg" as="xs:string*">
    <xsl:param name="msg" as="element(r:message)"/>
    <xsl:param name="var" as="xs:string"/>
    <xsl:param name="value" as="xs:string"/>
    <xsl:sequence select="if ($msg/@generated eq 'true') then fp:fit(6, 'to_msg(', $value || ', ' || $var || ');') ! substring(., 7)
        else if ($msg/@sequence eq 'true')
        then ('const ' || $msg/@cpp-type || ' value = ' || $value || ';', $var || '.data.assign(value.begin(), value.end());',
              (: its layout: one dimension, named after the port, of the sample's size (issue 37: not empty) :)
              $var || '.layout.dim.resize(1);',
              $var || '.layout.dim[0].label = &quot;' || $msg/../@name || '&quot;;',
              $var || '.layout.dim[0].size = static_cast&lt;unsigned int&gt;(value.size());',
              $var || '.layout.dim[0].stride = static_cast&lt;unsigned int&gt;(value.size());',
              $var || '.layout.data_offset = 0;')
        else if ($msg/@field ne '') then concat($var, '.', $msg/@field, ' = ', $value, ';')
        else concat($var, ' = ', $value, ';')"/>
  </xsl:function>

  <!-- the body of step(): update(), then each output port published;
       $types: the C++ message type of each output port, in order;
       $publish: '.publish' (ROS 1) or '-&gt;publish' (ROS 2) -->
  <xsl:function name="fp:ros-step" as="xs:string*">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:param name="types" as="xs:string*"/>
    <xsl:param name="publish" as="xs:string"/>
    <xsl:variable name="realizing-class" as="xs:string" select="$node/r:realizing-class/@cpp-name"/>
    <xsl:variable name="outputs" as="element(r:port)*" select="$node/r:port[@direction eq 'out']"/>
    <xsl:sequence select="(
        '  if (!running_) {',
        '    return;',
        '  }',
        $node/r:hook[@name eq 'update'][@call] ! concat('  ', $realizing-class, '::update();'),
        for $k in 1 to count($outputs) return
          let $port := $outputs[$k] return
          if ($port/@constant = 'true') then ()  (: published once: fp:ros-publish-constants :)
          else if (xs:boolean($port/@accessor-declared)) then (
            '  {',
            concat('    ', $types[$k], ' msg;'),
            fp:indent(4, fp:to-msg($port/r:message, 'msg', concat($realizing-class, '::', $port/@accessor, '()'))),
            fp:indent(4, fp:stamp-now($port)),
            concat('    ', $port/@member, $publish, '(msg);'),
            '  }')
          else concat('  // ', $node/r:realizing-class/@name, ' declares no ', $port/@accessor, '(): ', $port/@name,
                      ' is not published'))"/>
  </xsl:function>

  <!-- a stamped message whose datum has no stamp (0) is stamped with the
       time of publishing, the node's clock -->
  <xsl:function name="fp:stamp-now" as="xs:string*">
    <xsl:param name="port" as="element(r:port)"/>
    <xsl:sequence select="if (not($port/r:message/@stamped eq 'true')) then ()
        else if ($port/ancestor::r:package/@ros-version eq '1')
        then ('if (msg.header.stamp.isZero()) {', '  msg.header.stamp = ros::Time::now();', '}')
        else ('if (msg.header.stamp.sec == 0 &amp;&amp; msg.header.stamp.nanosec == 0) {', '  msg.header.stamp = this->now();', '}')"/>
  </xsl:function>

  <!-- the configuration constants («Constant», seed 004) a node writes,
       published once, once it is configured and its publishers exist: the
       connection is latched (ROS 1) or transient-local (ROS 2), so a
       subscriber that comes later still receives them; $types and $publish
       as for fp:ros-step -->
  <xsl:function name="fp:ros-publish-constants" as="xs:string*">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:param name="types" as="xs:string*"/>
    <xsl:param name="publish" as="xs:string"/>
    <xsl:variable name="realizing-class" as="xs:string" select="$node/r:realizing-class/@cpp-name"/>
    <xsl:variable name="outputs" as="element(r:port)*" select="$node/r:port[@direction eq 'out']"/>
    <xsl:for-each select="for $k in 1 to count($outputs) return $k[$outputs[$k]/@constant = 'true']">
      <xsl:variable name="k" as="xs:integer" select="."/>
      <xsl:variable name="port" as="element(r:port)" select="$outputs[$k]"/>
      <xsl:sequence select="if (xs:boolean($port/@accessor-declared)) then (
            concat('  {  // configuration constant ', $port/@name, ': published once'),
            concat('    ', $types[$k], ' msg;'),
            fp:indent(4, fp:to-msg($port/r:message, 'msg', concat($realizing-class, '::', $port/@accessor, '()'))),
            concat('    ', $port/@member, $publish, '(msg);'),
            '  }')
          else concat('  // ', $node/r:realizing-class/@name, ' declares no ', $port/@accessor, '(): configuration constant ',
                      $port/@name, ' is not published')"/>
    </xsl:for-each>
  </xsl:function>

  <!-- the body of the callback of input port $port: the datum handed to
       the realizing class, then step() when the node is data-driven -->
  <xsl:function name="fp:ros-on-input" as="xs:string+">
    <xsl:param name="port" as="element(r:port)"/>
    <xsl:param name="realizing-class" as="xs:string"/>
    <xsl:sequence select="(
        if (xs:boolean($port/@accessor-declared))
        then fp:fit(2, $realizing-class || '::' || $port/@accessor || '(', fp:from-msg($port/r:message, '(*msg)') || ');')
        else concat('  (void)msg;  // ', $port/../r:realizing-class/@name, ' declares no ', $port/@accessor, '()'),
        '  if (period_ &lt;= 0.0) {',
        '    step();  // data-driven (period 0)',
        '  }')"/>
  </xsl:function>

  <!-- the first lines of a node's header: banner, include guard -->
  <xsl:function name="fp:ros-header-opening" as="xs:string+">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="guard" as="xs:string" select="fp:guard($node/@namespace, $node/@class)"/>
    <xsl:sequence select="(fp:banner('// ', $fp:cpp-xsl, fp:what($node), false()),
                           concat('#ifndef ', $guard), concat('#define ', $guard))"/>
  </xsl:function>

  <!-- the first lines of a node's source: banner, its own header -->
  <xsl:function name="fp:ros-source-opening" as="xs:string+">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:sequence select="(fp:banner('// ', $fp:cpp-xsl, fp:what($node), false()),
                           concat('#include &quot;', $node/@namespace, '/', $node/@class, '.hpp&quot;'))"/>
  </xsl:function>

  <!-- package.xml up to the package's name (format 3) -->
  <xsl:function name="fp:ros-package-xml-opening" as="xs:string+">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="(
        '&lt;?xml version=&quot;1.0&quot;?&gt;',
        '&lt;!--',
        fp:indent(2, fp:banner('', $fp:build-xsl, concat('model ''', fp:xml-text($package/@model-name), ''''), false())),
        '--&gt;',
        '&lt;package format=&quot;3&quot;&gt;',
        concat('  &lt;name&gt;', $package/@name, '&lt;/name&gt;'))"/>
  </xsl:function>

  <xsl:function name="fp:library-external-project" as="xs:string*">
    <xsl:param name="lib" as="element(r:library)"/>
    <xsl:variable name="value" as="xs:string" select="concat('${', $lib/@cmake-var, '}')"/>
    <xsl:variable name="var" as="xs:string" select="replace($lib/@cmake-var, '_DIR$', '')"/>
    <xsl:variable name="bin" as="xs:string" select="concat('${CMAKE_CURRENT_BINARY_DIR}/', $lib/@build-dir)"/>
    <xsl:sequence select="
        '',
        concat('# atomic-code library ''', $lib/@name, ''' (artifact path ''', $lib/@path, ''', CMake target ', $lib/@target, ')'),
        '# A folder with a CMakeLists.txt is built as an external project (a catkin / ament',
        '# package must not add_subdirectory() a folder outside itself); else a prebuilt',
        '# library is searched in the folder, its lib/ and build/.',
        concat('set(', $lib/@cmake-var),
        concat('    &quot;', fp:library-dir($lib), '&quot; CACHE PATH'),
        concat('    &quot;Directory of the atomic-code library ', $lib/@name, '&quot;)'),
        concat('if(NOT IS_DIRECTORY &quot;', $value, '&quot;)'),
        concat('  message(FATAL_ERROR &quot;atomic-code library ', $lib/@name, ': no directory ', $value, '&quot;'),
        concat('    &quot;; give its place with -D', $lib/@cmake-var, '=DIR&quot;)'),
        'endif()',
        concat('if(EXISTS &quot;', $value, '/CMakeLists.txt&quot;)'),
        '  include(ExternalProject)',
        concat('  set(', $var, '_LIBRARY'),
        concat('      &quot;', $bin, '/${CMAKE_STATIC_LIBRARY_PREFIX}', $lib/@target, '${CMAKE_STATIC_LIBRARY_SUFFIX}&quot;)'),
        concat('  externalproject_add(${PROJECT_NAME}_', $lib/@build-dir),
        concat('    SOURCE_DIR &quot;', $value, '&quot;'),
        concat('    BINARY_DIR &quot;', $bin, '&quot;'),
        '    CMAKE_ARGS -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE} -DCMAKE_POSITION_INDEPENDENT_CODE=ON',
        (: the model's data type headers (include/TYPE.hpp), which the atomic code includes by name :)
        if ($lib/../r:types) then '    &quot;-DCMAKE_CXX_FLAGS=${CMAKE_CXX_FLAGS} -I${CMAKE_CURRENT_SOURCE_DIR}/include&quot;' else (),
        '    INSTALL_COMMAND &quot;&quot;',
        concat('    BUILD_BYPRODUCTS &quot;${', $var, '_LIBRARY}&quot;)'),
        concat('  set(', $var, '_DEPENDS ${PROJECT_NAME}_', $lib/@build-dir, ')'),
        'else()',
        concat('  find_library(', $var, '_LIBRARY NAMES ', $lib/@target),
        concat('    PATHS &quot;', $value, '&quot; &quot;', $value, '/lib&quot;'),
        concat('    &quot;', $value, '/build&quot; NO_DEFAULT_PATH)'),
        concat('  set(', $var, '_DEPENDS &quot;&quot;)'),
        concat('  if(NOT ', $var, '_LIBRARY)'),
        concat('    message(FATAL_ERROR &quot;atomic-code library ', $lib/@name, ': neither a CMakeLists.txt&quot;'),
        concat('      &quot; nor a built library ', $lib/@target, ' in ', $value, '&quot;'),
        concat('      &quot;; give its place with -D', $lib/@cmake-var, '=DIR&quot;)'),
        '  endif()',
        'endif()',
        '# an imported target: the library and its include folders travel with the link,',
        '# and no include folder outside the package is added to the package itself',
        concat('set(', $var, '_INCLUDE_DIRS &quot;&quot;)'),
        concat('foreach(dir &quot;', $value, '/', $lib/@include-dir, '&quot; &quot;', $value, '&quot;)'),
        '  if(IS_DIRECTORY &quot;${dir}&quot;)',
        concat('    list(APPEND ', $var, '_INCLUDE_DIRS &quot;${dir}&quot;)'),
        '  endif()',
        'endforeach()',
        concat('add_library(', fp:library-target($lib), ' INTERFACE IMPORTED)'),
        concat('set_target_properties(', fp:library-target($lib), ' PROPERTIES'),
        concat('  INTERFACE_INCLUDE_DIRECTORIES &quot;${', $var, '_INCLUDE_DIRS}&quot;'),
        concat('  INTERFACE_LINK_LIBRARIES &quot;${', $var, '_LIBRARY}&quot;)')"/>
  </xsl:function>

  <!-- the imported CMake target of an atomic-code library -->
  <xsl:function name="fp:library-target" as="xs:string">
    <xsl:param name="lib" as="element(r:library)"/>
    <xsl:sequence select="concat('${PROJECT_NAME}::', $lib/@target)"/>
  </xsl:function>

  <!-- the link items and the build dependencies of the libraries (the
       package's r:library elements, found once by the caller: a node's
       lines asked the package for them, a scan of its nodes and instances
       per node) -->
  <xsl:function name="fp:library-vars" as="xs:string*">
    <xsl:param name="libraries" as="element(r:library)*"/>
    <xsl:sequence select="$libraries ! fp:library-target(.)"/>
  </xsl:function>

  <xsl:function name="fp:library-depends" as="xs:string*">
    <xsl:param name="libraries" as="element(r:library)*"/>
    <xsl:param name="target" as="xs:string"/>
    <xsl:sequence select="$libraries ! (
        concat('if(', replace(@cmake-var, '_DIR$', '_DEPENDS'), ')'),
        concat('  add_dependencies(', $target, ' ${', replace(@cmake-var, '_DIR$', '_DEPENDS'), '})'),
        'endif()')"/>
  </xsl:function>

  <!-- the files of the model's data types: include/<Type>.hpp each, and
       for those a port carries msg/<Type>.msg and the conversions -->
  <xsl:function name="fp:ros-type-files" as="element(fs:file)*">
    <xsl:param name="package" as="element(r:package)"/>
    <!-- the definitions, once: not a new sequence of them all for each type -->
    <xsl:variable name="definitions" as="element()*" select="$package/r:types/(r:struct | r:enum)"/>
    <xsl:for-each select="$definitions">
      <xsl:sequence select="fp:file('include/' || @header, 'generated', 'm2t/common/data-types.xsl',
                                    fp:type-header(., $definitions, $package/@model-name))"/>
      <xsl:if test="@message">
        <xsl:sequence select="fp:file('msg/' || @message || '.msg', 'generated', $fp:build-xsl, fp:msg-file(., $fp:build-xsl))"/>
      </xsl:if>
    </xsl:for-each>
    <xsl:if test="$package/r:types/*[@message]">
      <xsl:sequence select="fp:file('include/' || $package/@name || '/msg_conversions.hpp', 'generated', $fp:cpp-xsl,
                                    fp:ros-conversions($package, $fp:cpp-xsl))"/>
    </xsl:if>
    <xsl:for-each select="$package/r:service-type">
      <xsl:sequence select="fp:file('srv/' || @name || '.srv', 'generated', $fp:build-xsl, fp:srv-file(., $fp:build-xsl))"/>
    </xsl:for-each>
  </xsl:function>

  <!-- a generated .srv file of a service of the package's own: its
       request's fields (one message each), its response's -->
  <xsl:function name="fp:srv-file" as="xs:string">
    <xsl:param name="service" as="element(r:service-type)"/>
    <xsl:param name="stylesheet" as="xs:string"/>
    <xsl:sequence select="fp:lines((
        fp:banner('# ', $stylesheet, 'service ''' || $service/@name || ''' of model ''' || $service/../@model-name || '''', false()),
        $service/r:request ! (@msg || ' ' || @field),
        '---',
        $service/r:response ! (@msg || ' ' || @field)))"/>
  </xsl:function>

  <!-- a generated .msg file: a data type's fields (one per attribute; a
       stamped one's std_msgs/Header first, in place of its stamp and
       frameId), or an enumeration's constants (one per literal) and its
       field value -->
  <xsl:function name="fp:msg-file" as="xs:string">
    <xsl:param name="type" as="element()"/>
    <xsl:param name="stylesheet" as="xs:string"/>
    <xsl:variable name="enum" as="xs:boolean" select="exists($type/self::r:enum)"/>
    <xsl:sequence select="fp:lines((
        fp:banner('# ', $stylesheet, (if ($enum) then 'enumeration ''' else 'data type ''') || $type/@name
                  || ''' of model ''' || $type/../../@model-name || '''', false()),
        if ($type/@stamped eq 'true') then 'std_msgs/Header header' else (),
        $type/r:field[empty(@header)] ! (@msg-field || ' ' || @name),
        $type/r:literal ! ('int32 ' || @constant || '=' || @value),
        if ($enum) then 'int32 value' else ()))"/>
  </xsl:function>

  <!-- the statements setting the realizing class's member from parameter
       $parameter, read into "value" as $param-type: a cast, an enumeration's
       literal by its name, an array's values (a fixed array: exactly its
       size); a value that does not fit is logged with $error ("ROS_ERROR(")
       and the member keeps its value; the lines indented by $indent, a
       log statement broken where it would pass 100 columns -->
  <xsl:function name="fp:parameter-assign" as="xs:string+">
    <xsl:param name="parameter" as="element(r:parameter)"/>
    <xsl:param name="param-type" as="xs:string"/>
    <xsl:param name="error" as="xs:string"/>
    <xsl:param name="indent" as="xs:integer"/>
    <xsl:variable name="member" as="xs:string" select="$parameter/../r:realizing-class/@cpp-name || '::' || $parameter/@member"/>
    <xsl:variable name="log" as="xs:string" select="substring-before($error, '(') || '('"/>
    <xsl:variable name="logger" as="xs:string" select="substring-after($error, '(')"/>
    <xsl:variable name="name" as="xs:string" select="fp:cpp-string($parameter/@name)"/>
    <xsl:sequence select="fp:indent($indent,
      if ($parameter/@kind eq 'enum') then (
        $parameter/r:choice ! ((if (position() eq 1) then 'if' else '} else if') || ' (value == ' || fp:cpp-string(@value) || ') {',
                               '  ' || $member || ' = ' || @cpp || ';'),
        '} else {',
        fp:fit($indent + 2, $log, $logger || '&quot;parameter %s: \&quot;%s\&quot; is none of '
                                  || string-join($parameter/r:choice/@value, ', ') || '&quot;, ' || $name || ', value.c_str());')
          ! substring(., $indent + 1),
        '}')
      else if ($parameter/@kind eq 'sequence') then (
        let $assign := if ($param-type eq $parameter/@cpp-type) then $member || ' = value;'
                       else $member || '.assign(value.begin(), value.end());'
        return if (empty($parameter/@size)) then $assign
        else ('if (value.size() == ' || $parameter/@size || ') {', '  ' || $assign, '} else {',
              fp:fit($indent + 2, $log, $logger || '&quot;parameter %s: %zu values, ' || $parameter/@size || ' expected&quot;, '
                                        || $name || ', value.size());') ! substring(., $indent + 1),
              '}'))
      else $member || ' = ' || (if ($param-type eq $parameter/@cpp-type) then 'value' else 'static_cast&lt;' || $parameter/@cpp-type || '&gt;(value)') || ';')"/>
  </xsl:function>

  <!-- the include of the conversions a node with a port of a generated
       message uses, or () -->
  <xsl:function name="fp:conversions-include" as="xs:string?">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:sequence select="if ($node/(r:port, r:service, r:service-client)//r:message[@generated eq 'true'])
                          then '#include &quot;' || $node/@namespace || '/msg_conversions.hpp&quot;' else ()"/>
  </xsl:function>

  <!-- (header, C++ type) of a message or service type "pkg/Name" -->
  <xsl:function name="fp:ros1-type" as="xs:string+">
    <xsl:param name="type" as="xs:string"/>
    <xsl:param name="pkg" as="xs:string"/>
    <xsl:variable name="item" as="xs:string+" select="fp:msg-parts($type, $pkg)"/>
    <xsl:sequence select="f:ros-header($item[1], $item[2], 'msg', '1'), concat($item[1], '::', $item[2])"/>
  </xsl:function>

  <!-- (header, C++ type) of "pkg/Name"; $kind msg or srv -->
  <xsl:function name="fp:ros2-type" as="xs:string+">
    <xsl:param name="type" as="xs:string"/>
    <xsl:param name="pkg" as="xs:string"/>
    <xsl:param name="kind" as="xs:string"/>
    <xsl:variable name="item" as="xs:string+" select="fp:msg-parts($type, $pkg)"/>
    <xsl:sequence select="f:ros-header($item[1], $item[2], $kind, '2'), concat($item[1], '::', $kind, '::', $item[2])"/>
  </xsl:function>

  <!-- the packages whose messages the generated messages use: std_msgs for
       a stamped one's Header, a ROS library message's package for a field
       of that type; sorted -->
  <xsl:function name="fp:message-dependencies" as="xs:string*">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="sort(distinct-values((
        $package/r:types/*[@stamped eq 'true'][1] ! 'std_msgs',
        $package/r:types/*/r:field[@element-kind eq 'message']/@msg-field ! substring-before(., '/'),
        $package/r:service-type/*/@msg[contains(., '/')] ! substring-before(., '/'))))"/>
  </xsl:function>

  <!-- the header of message "pkg/Name" in package $package, on its ROS version -->

  <xsl:function name="fp:message-header" as="xs:string">
    <xsl:param name="msg" as="xs:string"/>
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="if ($package/@ros-version eq '1') then fp:ros1-type($msg, $package/@name)[1]
                          else fp:ros2-type($msg, $package/@name, 'msg')[1]"/>
  </xsl:function>

  <!-- (header, C++ type) of the generated message of $type -->
  <xsl:function name="fp:generated-msg" as="xs:string+">
    <xsl:param name="type" as="element()"/>
    <xsl:sequence select="if ($type/../../@ros-version eq '1') then fp:ros1-type($type/@message, $type/../../@name)
                          else fp:ros2-type($type/@message, $type/../../@name, 'msg')"/>
  </xsl:function>

  <!-- include/<pkg>/msg_conversions.hpp: from_msg / to_msg between each
       generated message and its C++ type, field by field (arrays item by
       item: a fixed array has its size in both), and from_msg_value -->
  <xsl:function name="fp:ros-conversions" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="stylesheet" as="xs:string"/>
    <xsl:variable name="types" as="element()*" select="$package/r:types/*[@message]"/>
    <xsl:variable name="guard" as="xs:string" select="fp:guard($package/@name, 'msg_conversions')"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $stylesheet, 'model ''' || $package/@model-name || '''', false()),
        '#ifndef ' || $guard, '#define ' || $guard, '',
        '#include &lt;cstddef&gt;', '#include &lt;cstdint&gt;',
        if ($types[@stamped eq 'true'] and $package/@ros-version ne '1') then '#include &lt;cmath&gt;' else (),
        $types ! ('#include &lt;' || @header || '&gt;'),
        $types ! ('#include &lt;' || fp:generated-msg(.)[1] || '&gt;'),
        '', 'namespace ' || $package/@name, '{', '',
        '// The model''s data types and enumerations (include/&lt;Type&gt;.hpp) to and from',
        '// their generated messages.',
        $types ! fp:conversion-functions(.),
        '',
        '/// The value of type Value that message m carries.',
        'template&lt;typename Value, typename Message&gt;',
        'Value from_msg_value(const Message &amp; m)',
        '{', '  Value v;', '  from_msg(m, v);', '  return v;', '}', '',
        '}  // namespace ' || $package/@name, '', '#endif  // ' || $guard))"/>
  </xsl:function>

  <xsl:function name="fp:conversion-functions" as="xs:string+">
    <xsl:param name="type" as="element()"/>
    <xsl:variable name="msg" as="xs:string" select="fp:generated-msg($type)[2]"/>
    <xsl:variable name="empty" as="xs:string*" select="if ($type/self::r:struct[empty(r:field)]) then '  (void)m;' else ()"/>
    <xsl:sequence select="'',
        'inline void from_msg(const ' || $msg || ' &amp; m, ' || $type/@cpp-name || ' &amp; v)', '{',
        if ($type/self::r:enum) then '  v = static_cast&lt;' || $type/@cpp-name || '&gt;(m.value);'
        else ($empty, '  (void)v;'[exists($empty)], $type/r:field ! fp:field-conversion(., 'm', 'v', 'from_msg')),
        '}', '',
        'inline void to_msg(const ' || $type/@cpp-name || ' &amp; v, ' || $msg || ' &amp; m)', '{',
        if ($type/self::r:enum) then '  m.value = static_cast&lt;std::int32_t&gt;(v);'
        else ($empty, '  (void)v;'[exists($empty)], $type/r:field ! fp:field-conversion(., 'v', 'm', 'to_msg')),
        '}'"/>
  </xsl:function>

  <!-- the statements copying field $field from $from to $to ($function:
       from_msg or to_msg, which converts a data type or an enumeration) -->
  <xsl:function name="fp:field-conversion" as="xs:string+">
    <xsl:param name="field" as="element(r:field)"/>
    <xsl:param name="from" as="xs:string"/>
    <xsl:param name="to" as="xs:string"/>
    <xsl:param name="function" as="xs:string"/>
    <xsl:sequence select="if ($field/@header) then fp:header-conversion($field, $from, $to) else fp:plain-conversion($field, $from, $to, $function)"/>
  </xsl:function>

  <!-- a stamped type's stamp (seconds) or frameId to or from the message's
       std_msgs/Header: ROS 1 ros::Time, ROS 2 builtin_interfaces/Time -->
  <xsl:function name="fp:header-conversion" as="xs:string+">
    <xsl:param name="field" as="element(r:field)"/>
    <xsl:param name="from" as="xs:string"/>
    <xsl:param name="to" as="xs:string"/>
    <xsl:variable name="member" as="xs:string" select="($to[. ne 'm'], $from)[1] || '.' || $field/@member"/>
    <xsl:variable name="ros1" as="xs:boolean" select="$field/ancestor::r:package/@ros-version eq '1'"/>
    <xsl:sequence select="
      if ($field/@header eq 'frame_id') then
        '  ' || (if ($to eq 'm') then 'm.header.frame_id = ' || $member else $member || ' = m.header.frame_id') || ';'
      else if ($to ne 'm') then
        '  ' || $member || ' = ' || (if ($ros1) then 'm.header.stamp.toSec();'
                                   else 'static_cast&lt;double&gt;(m.header.stamp.sec) + 1e-9 * m.header.stamp.nanosec;')
      else if ($ros1) then '  m.header.stamp = ros::Time(' || $member || ');'
      else ('  m.header.stamp.sec = static_cast&lt;std::int32_t&gt;(std::floor(' || $member || '));',
            '  m.header.stamp.nanosec = static_cast&lt;std::uint32_t&gt;((' || $member || ' - std::floor(' || $member || ')) * 1e9);')"/>
  </xsl:function>

  <xsl:function name="fp:plain-conversion" as="xs:string+">
    <xsl:param name="field" as="element(r:field)"/>
    <xsl:param name="from" as="xs:string"/>
    <xsl:param name="to" as="xs:string"/>
    <xsl:param name="function" as="xs:string"/>
    <xsl:variable name="source" as="xs:string" select="$from || '.' || (if ($from eq 'm') then $field/@name else $field/@member)"/>
    <xsl:variable name="target" as="xs:string" select="$to || '.' || (if ($to eq 'm') then $field/@name else $field/@member)"/>
    <xsl:variable name="copy" as="xs:string" select="
        if ($field/@element-kind = ('primitive', 'message')) then '{1} = {0};' else $function || '({0}, {1});'"/>
    <xsl:sequence select="
      if (empty($field/@array)) then '  ' || replace(replace($copy, '\{0\}', $source), '\{1\}', $target)
      else (
        if ($field/@array eq 'fixed' and $to eq 'm') then () else '  ' || $target || '.resize(' || $source || '.size());',
        '  for (std::size_t i = 0; i &lt; ' || $source || '.size() &amp;&amp; i &lt; ' || $target || '.size(); ++i) {',
        '    ' || replace(replace($copy, '\{0\}', $source || '[i]'), '\{1\}', $target || '[i]'),
        '  }')"/>
  </xsl:function>

</xsl:stylesheet>
