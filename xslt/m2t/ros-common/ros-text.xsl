<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros-common/ros-text.xsl - text helpers shared by the ROS 1 and
  ROS 2 text stages (included by xslt/m2t/ros1/main.xsl and ros2/main.xsl).

  Reads:   r:package of urn:robomda:psm-ros:1 (some helpers).
  Writes:  strings.  Params: none (model-dir-from-output: ../common/text.xsl).
  Errors:  none. The target-neutral helpers (lines, banners, literals,
  guards, library paths) are in ../common/text.xsl.
    fp:double-literal($v)  a C++ / YAML floating literal of a number
    fp:service-body($s, $rc, $acc)  the statements of a std_srvs callback
    fp:client-method($c, $qualifier)  the signature of a method calling a required operation
    fp:client-overrides($node)   their declarations in the node class
    fp:from-msg / fp:to-msg  datum <-> message conversion (ROS 1 and 2 alike)
    fp:ros-step($node, $types, $publish)  the body of a node's step()
    fp:ros-header-opening / fp:ros-source-opening($node)  banner and guard /
                           banner and include of a node's C++ files
    fp:ros-package-xml-opening($package)  package.xml up to its name
    fp:ros-on-input($port, $rc)  the body of a subscription callback
    fp:msg-parts($msg, $pkg)  (package, Name) of a message: a generated
                           message (no "/") lives in package $pkg
    fp:ros-snake($name)    rosidl's file-name form of a type name (UInt8 -> u_int8)
    fp:library-external-project / fp:library-vars / fp:library-depends  CMake lines
                           finding, linking and building first the atomic-code
                           library (cache variable as in the Orocos target)
    fp:yaml-string($s)     a YAML double-quoted scalar
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

  <!-- the entry of both ROS text stages: their r:package template (mode
       m:emit-files) makes the file set. It comes out as f:indent (common/indent.xsl) would indent
       it (one fs:file a line; their text as it is), written so directly with
       t:indented-content: f:indent would copy all the text once more -->
  <xsl:template match="/" as="document-node()">
    <xsl:document>
      <xsl:apply-templates select="r:package" mode="m:emit-files"/>
    </xsl:document>
  </xsl:template>

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
    <xsl:sequence select="fp:lines((
        fp:banner('# ', $stylesheet, $what, true()),
        concat('# The launch files load it after ', $generated, ': a parameter set here wins over the'),
        '# generated value, so tuning on the robot never means editing a generated file. Write',
        '# the same keys as there, in place of the empty mapping below.',
        '{}'))"/>
  </xsl:function>

  <xsl:function name="fp:msg-parts" as="xs:string+">
    <xsl:param name="msg" as="xs:string"/>
    <xsl:param name="pkg" as="xs:string"/>
    <xsl:sequence select="if (contains($msg, '/')) then (substring-before($msg, '/'), substring-after($msg, '/')) else ($pkg, $msg)"/>
  </xsl:function>

  <xsl:function name="fp:ros-snake" as="xs:string">
    <xsl:param name="name" as="xs:string"/>
    <xsl:sequence select="lower-case(string-join(f:words($name), '_'))"/>
  </xsl:function>

  <xsl:function name="fp:double-literal" as="xs:string">
    <xsl:param name="value" as="xs:string"/>
    <xsl:sequence select="if (contains($value, '.') or contains(lower-case($value), 'e')) then $value else concat($value, '.0')"/>
  </xsl:function>

  <!-- the method that calls operation $client of a required interface:
       "bool name(bool argument)"; $qualifier is '' or 'Class::' -->
  <xsl:function name="fp:client-method" as="xs:string">
    <xsl:param name="client" as="element(r:service-client)"/>
    <xsl:param name="qualifier" as="xs:string"/>
    <xsl:sequence select="concat(if (xs:boolean($client/@returns-bool)) then 'bool ' else 'void ', $qualifier, $client/@name,
                                 '(', $client/@argument ! concat('bool ', .), ')')"/>
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

  <!-- body of a std_srvs service callback; $acc is "." (ROS 1) or "->" (ROS 2) -->
  <xsl:function name="fp:service-body" as="xs:string*">
    <xsl:param name="service" as="element(r:service)"/>
    <xsl:param name="rc" as="xs:string"/>
    <xsl:param name="acc" as="xs:string"/>
    <xsl:variable name="call" as="xs:string"
        select="concat($rc, '::', $service/@name, '(', (if ($service/@srv eq 'std_srvs/SetBool') then concat('request', $acc, 'data') else ''), ')')"/>
    <xsl:sequence select="
        if ($service/@srv eq 'std_srvs/Empty') then concat('  ', $call, ';')
        else if (xs:boolean($service/@returns-bool)) then concat('  response', $acc, 'success = ', $call, ';')
        else (concat('  ', $call, ';'), concat('  response', $acc, 'success = true;'))"/>
  </xsl:function>

  <!-- the statements converting message expression $m to the datum, or the datum to message $var -->
  <xsl:function name="fp:from-msg" as="xs:string">
    <xsl:param name="msg" as="element(r:message)"/>
    <xsl:param name="model" as="xs:string"/>
    <xsl:sequence select="if ($msg/@generated eq 'true')
        then concat($msg/@cpp-type, '{', string-join($msg/r:field ! (concat($model, '.', @name)), ', '), '}')
        else if ($msg/@field ne '') then concat($model, '.', $msg/@field) else $model"/>
  </xsl:function>

  <xsl:function name="fp:to-msg" as="xs:string*">
    <xsl:param name="msg" as="element(r:message)"/>
    <xsl:param name="var" as="xs:string"/>
    <xsl:param name="value" as="xs:string"/>
    <xsl:sequence select="if ($msg/@generated eq 'true')
        then (concat('const ', $msg/@cpp-type, ' value = ', $value, ';'), $msg/r:field ! (concat($var, '.', @name, ' = value.', @member, ';')))
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
          if (xs:boolean($port/@accessor-declared)) then (
            '  {',
            concat('    ', $types[$k], ' msg;'),
            fp:indent(4, fp:to-msg($port/r:message, 'msg', concat($realizing-class, '::', $port/@accessor, '()'))),
            concat('    ', $port/@member, $publish, '(msg);'),
            '  }')
          else concat('  // ', $node/r:realizing-class/@name, ' declares no ', $port/@accessor, '(): ', $port/@name,
                      ' is not published'))"/>
  </xsl:function>

  <!-- the body of the callback of input port $port: the datum handed to
       the realizing class, then step() when the node is data-driven -->
  <xsl:function name="fp:ros-on-input" as="xs:string+">
    <xsl:param name="port" as="element(r:port)"/>
    <xsl:param name="realizing-class" as="xs:string"/>
    <xsl:sequence select="(
        if (xs:boolean($port/@accessor-declared))
        then concat('  ', $realizing-class, '::', $port/@accessor, '(', fp:from-msg($port/r:message, '(*msg)'), ');')
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
                           concat('#include &lt;', $node/@namespace, '/', $node/@class, '.hpp&gt;'))"/>
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
        concat('set(', $lib/@cmake-var, ' &quot;', fp:library-dir($lib), '&quot; CACHE PATH'),
        concat('    &quot;Directory of the atomic-code library ', $lib/@name, '&quot;)'),
        concat('if(NOT IS_DIRECTORY &quot;', $value, '&quot;)'),
        concat('  message(FATAL_ERROR &quot;atomic-code library ', $lib/@name, ': no directory ', $value,
               '; give its place with -D', $lib/@cmake-var, '=DIR&quot;)'),
        'endif()',
        concat('if(EXISTS &quot;', $value, '/CMakeLists.txt&quot;)'),
        '  include(ExternalProject)',
        concat('  set(', $var, '_LIBRARY'),
        concat('      &quot;', $bin, '/${CMAKE_STATIC_LIBRARY_PREFIX}', $lib/@target, '${CMAKE_STATIC_LIBRARY_SUFFIX}&quot;)'),
        concat('  ExternalProject_Add(${PROJECT_NAME}_', $lib/@build-dir),
        concat('    SOURCE_DIR &quot;', $value, '&quot;'),
        concat('    BINARY_DIR &quot;', $bin, '&quot;'),
        '    CMAKE_ARGS -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE} -DCMAKE_POSITION_INDEPENDENT_CODE=ON',
        '    INSTALL_COMMAND &quot;&quot;',
        concat('    BUILD_BYPRODUCTS &quot;${', $var, '_LIBRARY}&quot;)'),
        concat('  set(', $var, '_DEPENDS ${PROJECT_NAME}_', $lib/@build-dir, ')'),
        'else()',
        concat('  find_library(', $var, '_LIBRARY NAMES ', $lib/@target),
        concat('    PATHS &quot;', $value, '&quot; &quot;', $value, '/lib&quot; &quot;', $value, '/build&quot; NO_DEFAULT_PATH)'),
        concat('  set(', $var, '_DEPENDS &quot;&quot;)'),
        concat('  if(NOT ', $var, '_LIBRARY)'),
        concat('    message(FATAL_ERROR &quot;atomic-code library ', $lib/@name, ': neither a CMakeLists.txt nor a built library ',
               $lib/@target, ' in ', $value, '; give its place with -D', $lib/@cmake-var, '=DIR&quot;)'),
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

  <!-- the link items and the build dependencies of the libraries -->
  <xsl:function name="fp:library-vars" as="xs:string*">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="$package/r:library ! fp:library-target(.)"/>
  </xsl:function>

  <xsl:function name="fp:library-depends" as="xs:string*">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="target" as="xs:string"/>
    <xsl:sequence select="$package/r:library ! (
        concat('if(', replace(@cmake-var, '_DIR$', '_DEPENDS'), ')'),
        concat('  add_dependencies(', $target, ' ${', replace(@cmake-var, '_DIR$', '_DEPENDS'), '})'),
        'endif()')"/>
  </xsl:function>

  <!-- a generated .msg file: one field per attribute of the data type -->
  <xsl:function name="fp:msg-file" as="xs:string">
    <xsl:param name="model" as="element(r:message-file)"/>
    <xsl:param name="stylesheet" as="xs:string"/>
    <xsl:sequence select="fp:lines((
        fp:banner('# ', $stylesheet, concat('data type ''', $model/@name, ''' of model ''', $model/../@model-name, ''''), false()),
        $model/r:field ! (concat(@msg-field, ' ', @name))))"/>
  </xsl:function>

</xsl:stylesheet>
