<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/openrtm/openrtm-cpp.xsl - the C++ of each RT-Component and the
  package's CMakeLists.txt (part of xslt/m2t/openrtm/main.xsl).

  Reads:   r:component, r:library, r:system of the OpenRTM PSM.
  Writes:  strings: a header, a source (RTC::DataFlowComponentBase; its
           actions onInitialize / onActivated / onExecute / onDeactivated /
           onFinalize call the realizing class's configure / start / update /
           stop / cleanup, seed 000; onExecute logs, at INFO, each input
           port's first sample: "input port <instance>.<port>: first sample
           received"; with configuration-constant inputs, «Constant»,
           configure runs on the first activation, once they arrived), its
           configuration parameters (bindParameter, with the conversion of
           <pkg>_conf.h for a structured one, and a listener that logs a
           warning for a value that does not parse), the user class of a
           component without
           one, its service ports (RTC::CorbaPort: a servant calling the
           component's operation, or a consumer its override calls), the IDL
           of each interface, and CMakeLists.txt (omniidl for the IDL, one
           module <Class>.so per component, with the <Class>Init entry rtcd2 loads).
  Params:  none (main.xsl's).
  Errors:  none.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-openrtm:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- the system's data types (one r:data-types), looked up by every
       component and data port: from a component, ../r:data-types scanned
       every component and instance of the system (issue 35) -->
  <xsl:key name="fp:rtm-data-types" match="r:system/r:data-types" use="'data-types'"/>

  <!-- the actions, each with the lifecycle operation it calls -->
  <xsl:variable name="fp:rtm-actions" as="map(xs:string, xs:string)"
      select="map { 'configure': 'onInitialize', 'start': 'onActivated', 'update': 'onExecute',
                    'stop': 'onDeactivated', 'cleanup': 'onFinalize' }"/>

  <xsl:function name="fp:rtm-action-signature" as="xs:string">
    <xsl:param name="hook" as="xs:string"/>
    <xsl:sequence select="'RTC::ReturnCode_t ' || $fp:rtm-actions($hook)
                          || (if ($hook = ('configure', 'cleanup')) then '()' else '(RTC::UniqueId ec_id)')"/>
  </xsl:function>

  <xsl:function name="fp:rtm-header" as="xs:string">
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:variable name="pkg" as="xs:string" select="$c/@category"/>
    <xsl:variable name="rc" as="element(r:realizing-class)?" select="$c/r:realizing-class"/>
    <xsl:sequence select="fp:lines((
      fp:banner('// ', $fp:cpp-xsl, fp:what($c), false()),
      '#ifndef ' || fp:guard($pkg, $c/@generated-class),
      '#define ' || fp:guard($pkg, $c/@generated-class),
      '',
      '// the IDL types first: OpenRTM''s port templates find their CORBA::Any operators only if declared before',
      '#include &lt;rtm/idl/BasicDataTypeSkel.h&gt;',
      if ($c/r:data-port[@convert ne 'primitive']) then '#include &lt;' || $pkg || '/' || key('fp:rtm-data-types', 'data-types', root($c))/@idl || '.h&gt;' else (),
      if ($c/r:parameter[@kind]) then '#include &lt;' || $pkg || '/' || $pkg || '_conf.h&gt;' else (),
      distinct-values($c/r:service-port/@interface) ! ('#include &quot;' || . || '.hh&quot;'),
      '#include &lt;rtm/DataFlowComponentBase.h&gt;',
      '#include &lt;rtm/Manager.h&gt;',
      '#include &lt;rtm/InPort.h&gt;',
      '#include &lt;rtm/OutPort.h&gt;',
      if ($c/r:service-port) then ('#include &lt;rtm/CorbaPort.h&gt;', '#include &lt;rtm/CorbaConsumer.h&gt;') else (),
      '#include &lt;string&gt;',
      if (exists(fp:rtm-constants($c))) then ('#include &lt;chrono&gt;', '#include &lt;thread&gt;') else (),
      $rc ! ('#include &quot;' || @header || '&quot;'),
      '',
      'namespace ' || $pkg || ' {',
      '',
      '/**',
      ' * RT-Component ' || $c/@name || ' (OpenRTM-aist 2.0, DataFlowComponentBase).',
      if ($rc) then ' * Wraps the atomic code ' || $rc/@cpp-name || ' (seed 000): its actions call the class''s lifecycle.'
      else ' * Generated base: the user class ' || $c/@class || ' (include/' || $pkg || '/' || $c/@class || '.h) implements the actions.',
      ' */',
      'class ' || $c/@generated-class || ' : public RTC::DataFlowComponentBase' || $rc ! (', public ' || @cpp-name),
      '{',
      'public:',
      '  explicit ' || $c/@generated-class || '(RTC::Manager* manager);',
      '  ~' || $c/@generated-class || '() override;',
      '',
      '  RTC::ReturnCode_t onInitialize() override;',
      if ($rc) then $c/r:hook[@name ne 'configure'] ! ('  ' || fp:rtm-action-signature(@name) || ' override;') else (),
      '',
      'protected:',
      '  // data ports: the datum and its port (R2)',
      $c/r:data-port ! (
        '  ' || @timed || ' ' || @member || ';',
        '  RTC::' || (if (@direction eq 'out') then 'OutPort' else 'InPort') || '&lt;' || @timed || '&gt; ' || @port-member || ';',
        if ($rc and @direction eq 'in') then '  bool ' || @port-member || 'Received = false;  // its first sample is logged' else ()),
      fp:rtm-service-members($c),
      if ($c/@kind eq 'base' and $c/r:parameter) then ('  // configuration parameters (R3)', $c/r:parameter ! ('  ' || @type || ' m_' || @name || ';')) else (),
      if ($c/r:parameter) then ('  // logs a configuration value that does not parse (OpenRTM then sets the default)',
                                '  void reportConfiguration(const char* name, const char* value);') else (),
      if (exists(fp:rtm-constants($c))) then ('  // configure() has run (on the first activation, after the configuration constants)', '  bool m_configured = false;') else (),
      '};',
      '',
      '}  // namespace ' || $pkg,
      '',
      if ($rc) then fp:rtm-init-decl($c) else (),
      '',
      '#endif  // ' || fp:guard($pkg, $c/@generated-class)))"/>
  </xsl:function>

  <!-- ====================================================== service ports -->
  <xsl:function name="fp:rtm-servant-class" as="xs:string">
    <xsl:param name="sp" as="element(r:service-port)"/>
    <xsl:sequence select="upper-case(substring($sp/@name, 1, 1)) || substring($sp/@name, 2) || 'Servant'"/>
  </xsl:function>

  <xsl:function name="fp:rtm-corba-signature" as="xs:string">
    <xsl:param name="op" as="element(r:operation)"/>
    <xsl:param name="scope" as="xs:string"/>
    <xsl:sequence select="$op/@return-corba || ' ' || $scope || $op/@name || '('
                          || string-join($op/r:parameter ! (@corba || ' ' || @name), ', ') || ')'"/>
  </xsl:function>

  <xsl:function name="fp:rtm-cpp-signature" as="xs:string">
    <xsl:param name="op" as="element(r:operation)"/>
    <xsl:param name="scope" as="xs:string"/>
    <xsl:sequence select="$op/@return-cpp || ' ' || $scope || $op/@name || '('
                          || string-join($op/r:parameter ! (@decl-type || ' ' || @name), ', ') || ')'"/>
  </xsl:function>

  <!-- the header lines of a component's service ports: ports, consumers, servant classes, overrides -->
  <xsl:function name="fp:rtm-service-members" as="xs:string*">
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:for-each select="$c/r:service-port">
      <xsl:sequence select="'  // service port ' || @name || ' (' || @role || ' interface ' || @interface || ', R5b)',
                            '  RTC::CorbaPort ' || @port-member || ';'"/>
      <xsl:choose>
        <xsl:when test="@role eq 'required'">
          <xsl:sequence select="'  RTC::CorbaConsumer&lt;' || @idl-type || '&gt; ' || @member || ';',
                                r:operation[xs:boolean(@forward)] ! ('  ' || fp:rtm-cpp-signature(., '') || ' override;')"/>
        </xsl:when>
        <xsl:otherwise>
          <xsl:variable name="servant" as="xs:string" select="fp:rtm-servant-class(.)"/>
          <xsl:sequence select="(
            '  class ' || $servant || ' : public virtual POA_' || @idl-type,
            '  {',
            '  public:',
            '    explicit ' || $servant || '(' || $c/@generated-class || '&amp; owner) : m_owner(owner) {}',
            r:operation ! ('    ' || fp:rtm-corba-signature(., '') || ' override;'),
            '  private:',
            '    ' || $c/@generated-class || '&amp; m_owner;',
            '  };',
            '  ' || $servant || ' ' || @member || ';',
            if ($c/@kind eq 'base') then r:operation ! ('  virtual ' || fp:rtm-cpp-signature(., '') || ' = 0;') else ())"/>
        </xsl:otherwise>
      </xsl:choose>
    </xsl:for-each>
  </xsl:function>

  <!-- the source lines: servant operations call the component's, overrides call the consumer -->
  <xsl:function name="fp:rtm-service-definitions" as="xs:string*">
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:variable name="class" as="xs:string" select="$c/@generated-class"/>
    <xsl:for-each select="$c/r:service-port[@role eq 'provided']/r:operation">
      <xsl:variable name="call" as="xs:string"
          select="'m_owner.' || @name || '(' || string-join(r:parameter ! (if (@primitive eq 'string') then 'std::string(' || @name || ')' else @name), ', ') || ')'"/>
      <xsl:sequence select="'', fp:rtm-corba-signature(., $class || '::' || fp:rtm-servant-class(..) || '::'), '{',
          if (@return-primitive eq 'void') then '  ' || $call || ';'
          else if (@return-primitive eq 'string') then '  return CORBA::string_dup(' || $call || '.c_str());'
          else '  return ' || $call || ';', '}'"/>
    </xsl:for-each>
    <xsl:for-each select="$c/r:service-port[@role eq 'required']/r:operation[xs:boolean(@forward)]">
      <xsl:variable name="call" as="xs:string"
          select="../@member || '-&gt;' || @name || '(' || string-join(r:parameter ! (if (@primitive eq 'string') then @name || '.c_str()' else @name), ', ') || ')'"/>
      <!-- OpenRTM serves a provided interface only while its component is Active (CorbaPort
           activates it with the component): a call before that, or after, raises a CORBA system
           exception; the override logs it and returns the result type's zero -->
      <xsl:sequence select="'', fp:rtm-cpp-signature(., $class || '::'), '{', '  try {',
          if (@return-primitive eq 'void') then '    ' || $call || ';'
          else if (@return-primitive eq 'string') then ('    CORBA::String_var result = ' || $call || ';', '    return std::string(result.in());')
          else '    return ' || $call || ';',
          '  } catch (const CORBA::SystemException&amp; e) {',
          '    RTC_WARN((&quot;' || ../@name || ': ' || @name || '() not served (%s): the provider is not active&quot;, e._name()));',
          if (@return-primitive eq 'void') then () else '    return ' || @return-sample || ';',
          '  }', '}'"/>
    </xsl:for-each>
  </xsl:function>

  <!-- onInitialize: each service port's interface registered, the port added -->
  <xsl:function name="fp:rtm-service-registration" as="xs:string*">
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:for-each select="$c/r:service-port">
      <xsl:sequence select="'  ' || @port-member || (if (@role eq 'provided') then '.registerProvider(' else '.registerConsumer(')
                              || '&quot;' || @interface || '&quot;, &quot;' || @interface || '&quot;, ' || @member || ');',
                            '  addPort(' || @port-member || ');'"/>
    </xsl:for-each>
  </xsl:function>

  <!-- idl/<Interface>.idl -->
  <xsl:function name="fp:rtm-idl" as="xs:string">
    <xsl:param name="i" as="element(r:interface)"/>
    <xsl:variable name="guard" as="xs:string" select="upper-case($i/@module || '_' || $i/@name) || '_IDL'"/>
    <xsl:sequence select="fp:lines((
      fp:banner('// ', $fp:cpp-xsl, 'interface ''' || $i/@name || ''' of model ''' || $i/../@model-name || '''', false()),
      '#ifndef ' || $guard, '#define ' || $guard, '',
      'module ' || $i/@module, '{',
      '  interface ' || $i/@name, '  {',
      $i/r:operation ! ('    ' || @return-idl || ' ' || @name || '(' || string-join(r:parameter ! ('in ' || @idl || ' ' || @name), ', ') || ');'),
      '  };', '};', '', '#endif'))"/>
  </xsl:function>

  <!-- CMake lines: omniidl compiles each IDL, one static library of their stubs and skeletons -->
  <xsl:function name="fp:rtm-idl-cmake" as="xs:string*">
    <xsl:param name="system" as="element(r:system)"/>
    <xsl:variable name="pkg" as="xs:string" select="$system/@package"/>
    <xsl:variable name="types" as="xs:string*" select="$system/r:data-types[(r:enum | r:struct)[xs:boolean(@idl)]]/@idl"/>
    <xsl:if test="$system/r:interface or exists($types)">
      <xsl:sequence select="(
        if (empty($types)) then '# the service ports'' interfaces: omniidl (Debian omniidl) writes their C++ stubs and skeletons'
        else ('# the ' || (if ($system/r:interface) then 'service ports'' interfaces and the ' else '')
              || 'data ports'' types: omniidl (Debian omniidl) writes their C++',
              '# stubs and skeletons; the types also their CORBA::Any operators and type codes (-Wba), which OpenRTM''s',
              '# data ports use, with OpenRTM''s IDL folder (BasicDataType.idl) on the include path'),
        'find_program(OMNIIDL omniidl)',
        'if(NOT OMNIIDL)',
        '  message(FATAL_ERROR &quot;omniidl not found (Debian package omniidl)&quot;)',
        'endif()',
        'set(IDL_OUT ${CMAKE_CURRENT_BINARY_DIR}/idl)',
        'file(MAKE_DIRECTORY ${IDL_OUT})',
        $system/r:interface ! (
          'add_custom_command(OUTPUT ${IDL_OUT}/' || @name || '.hh ${IDL_OUT}/' || @name || 'SK.cc',
          '  COMMAND ${OMNIIDL} -bcxx -Wbh=.hh -Wbs=SK.cc -C ${IDL_OUT} ${CMAKE_CURRENT_SOURCE_DIR}/idl/' || @name || '.idl',
          '  DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/idl/' || @name || '.idl)'),
        $types ! (
          'add_custom_command(OUTPUT ${IDL_OUT}/' || . || '.hh ${IDL_OUT}/' || . || 'SK.cc ${IDL_OUT}/' || . || 'DynSK.cc',
          '  COMMAND ${OMNIIDL} -bcxx -Wba -Wbuse_quotes -Wbh=.hh -Wbs=SK.cc -Wbd=DynSK.cc -I${OPENRTM_INCLUDE_DIR}/rtm/idl -C ${IDL_OUT} ${CMAKE_CURRENT_SOURCE_DIR}/idl/' || . || '.idl',
          '  DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/idl/' || . || '.idl)'),
        'add_library(' || $pkg || '_idl STATIC' || string-join(($types ! (' ${IDL_OUT}/' || . || 'SK.cc ${IDL_OUT}/' || . || 'DynSK.cc'),
                                                              $system/r:interface ! (' ${IDL_OUT}/' || @name || 'SK.cc'))) || ')',
        'set_target_properties(' || $pkg || '_idl PROPERTIES POSITION_INDEPENDENT_CODE ON)',
        'include_directories(${IDL_OUT})',
        '')"/>
    </xsl:if>
  </xsl:function>

  <!-- the entry rtcd2 calls when it loads the module <Class>.so -->
  <xsl:function name="fp:rtm-init-decl" as="xs:string+">
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:sequence select="('extern &quot;C&quot;', '{', '  void ' || $c/@class || 'Init(RTC::Manager* manager);', '}')"/>
  </xsl:function>

  <!-- the component's specification: the profile and the configuration set "default" -->
  <xsl:function name="fp:rtm-spec" as="xs:string+">
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:variable name="pairs" as="xs:string+" select="(
        'implementation_id', $c/@type-name, 'type_name', $c/@type-name,
        'description', 'robomda component ' || $c/@name, 'version', '1.0.0', 'vendor', 'robomda',
        'category', $c/@category, 'activity_type', 'PERIODIC', 'kind', 'DataFlowComponent',
        'max_instance', '0', 'language', 'C++', 'lang_type', 'compile',
        $c/r:parameter ! ('conf.default.' || @name, string(@default)))"/>
    <xsl:sequence select="('const char* const spec[] =', '{',
        for $i in 1 to count($pairs) idiv 2
        return '  ' || fp:cpp-string($pairs[2 * $i - 1]) || ', ' || fp:cpp-string($pairs[2 * $i]) || ',',
        '  &quot;&quot;', '};')"/>
  </xsl:function>

  <!-- the conversion of a parameter's text: coil::stringTo for a single
       primitive (bindParameter's default), else the package's <pkg>_conf.h -->
  <xsl:function name="fp:rtm-conf-parser" as="xs:string">
    <xsl:param name="p" as="element(r:parameter)"/>
    <xsl:variable name="scope" as="xs:string" select="'::' || $p/../@category || '::conf::'"/>
    <xsl:sequence select="
      if (empty($p/@kind)) then 'coil::stringTo'
      else if ($p/@kind eq 'sequence')
      then $scope || 'parseList&lt;' || $p/@element || ', ' || string-join(fp:rtm-conf-limits($p, $scope), ', ') || '&gt;'
      else $scope || 'parse&lt;' || $p/@type || '&gt;'"/>
  </xsl:function>

  <!-- the listener of the configuration set: OpenRTM's ConfigAdmin sets a
       parameter whose value does not parse to its default, silently; the
       component parses the value again and logs a warning that names it -->
  <xsl:function name="fp:rtm-report-configuration" as="xs:string*">
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:if test="$c/r:parameter">
      <xsl:sequence select="'',
        '// a value of the configuration set that does not parse: OpenRTM sets the parameter to its default',
        'void ' || $c/@generated-class || '::reportConfiguration(const char* name, const char* value)',
        '{',
        '  const std::string param(name);',
        '  bool parses = true;',
        $c/r:parameter ! ('  ' || (if (position() eq 1) then 'if' else 'else if') || ' (param == &quot;' || @name || '&quot;) { '
                          || @type || ' v; parses = ' || fp:rtm-conf-parser(.) || '(v, value); }'),
        '  if (!parses) {',
        '    RTC_WARN((&quot;configuration parameter %s of %s: value ''%s'' does not parse, the parameter has its default&quot;, name,',
        '              RTC::RTObject_impl::getInstanceName(), value));',
        '  }',
        '}'"/>
    </xsl:if>
  </xsl:function>

  <!-- a datum to the atomic code's type -->
  <xsl:function name="fp:rtm-from-datum" as="xs:string">
    <xsl:param name="port" as="element(r:data-port)"/>
    <xsl:sequence select="if ($port/@primitive eq 'string') then 'std::string(' || $port/@member || '.data)'
                          else 'static_cast&lt;' || $port/@cpp || '&gt;(' || $port/@member || '.data)'"/>
  </xsl:function>

  <xsl:function name="fp:rtm-source" as="xs:string">
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:variable name="pkg" as="xs:string" select="$c/@category"/>
    <xsl:variable name="rc" as="element(r:realizing-class)?" select="$c/r:realizing-class"/>
    <xsl:variable name="class" as="xs:string" select="$c/@generated-class"/>
    <xsl:sequence select="fp:lines((
      fp:banner('// ', $fp:cpp-xsl, fp:what($c), false()),
      '#include &lt;' || $pkg || '/' || $class || '.h&gt;',
      '',
      'namespace ' || $pkg || ' {',
      '',
      if ($rc) then (fp:rtm-spec($c), '') else (),
      $class || '::' || $class || '(RTC::Manager* manager)',
      '  : RTC::DataFlowComponentBase(manager)' || (if ($c/r:data-port or $c/r:service-port) then ',' else ''),
      fp:indent(4, fp:rtm-initializers($c)),
      '{',
      '}',
      '',
      $class || '::~' || $class || '()',
      '{',
      '}',
      '',
      'RTC::ReturnCode_t ' || $class || '::onInitialize()',
      '{',
      $c/r:data-port ! ('  ' || (if (@direction eq 'out') then 'addOutPort' else 'addInPort') || '(&quot;' || @name || '&quot;, ' || @port-member || ');'),
      fp:rtm-service-registration($c),
      if ($c/r:parameter) then ('  addConfigurationParamListener(RTC::ConfigurationParamListenerType::ON_UPDATE_CONFIG_PARAM, *this,',
                                '                                &amp;' || $class || '::reportConfiguration);') else (),
      $c/r:parameter ! ('  bindParameter(&quot;' || @name || '&quot;, '
                        || (if ($rc) then $rc/@cpp-name || '::' || @name else 'm_' || @name) || ', ' || fp:cpp-string(@default)
                        || (if (@kind) then ', &amp;' || fp:rtm-conf-parser(.) else '') || ');'),
      if (exists(fp:rtm-constants($c))) then ('  // configure() runs on the first activation, after the configuration constants (onActivated)', '  return RTC::RTC_OK;')
      else if ($rc) then fp:rtm-call($c, 'configure') else '  return RTC::RTC_OK;',
      '}',
      if ($rc) then $c/r:hook[@name ne 'configure'] ! ('', fp:rtm-action(., $c)) else (),
      fp:rtm-service-definitions($c),
      fp:rtm-report-configuration($c),
      '',
      '}  // namespace ' || $pkg,
      if ($rc) then ('', fp:rtm-init($c)) else ()))"/>
  </xsl:function>

  <!-- the constructor's member initialisers, in declaration order -->
  <xsl:function name="fp:rtm-initializers" as="xs:string*">
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:variable name="items" as="xs:string*" select="(
        $c/r:data-port ! (@port-member || '(&quot;' || @name || '&quot;, ' || @member || ')'),
        $c/r:service-port ! (@port-member || '(&quot;' || @name || '&quot;)', if (@role eq 'provided') then @member || '(*this)' else ()))"/>
    <xsl:sequence select="for $i in 1 to count($items) return $items[$i] || (if ($i lt count($items)) then ',' else '')"/>
  </xsl:function>

  <!-- the lines of an action that calls the realizing class's lifecycle operation $hook, if it has one -->
  <xsl:function name="fp:rtm-call" as="xs:string+">
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:param name="hook" as="xs:string"/>
    <xsl:variable name="h" as="element(r:hook)" select="$c/r:hook[@name eq $hook]"/>
    <xsl:variable name="rc" as="xs:string" select="$c/r:realizing-class/@cpp-name"/>
    <xsl:sequence select="
      if (empty($h/@call)) then ('  // ' || $c/r:realizing-class/@name || ' declares no ' || $hook || '()', '  return RTC::RTC_OK;')
      else if (xs:boolean($h/@returns-bool)) then '  return ' || $rc || '::' || $h/@call || '() ? RTC::RTC_OK : RTC::RTC_ERROR;'
      else ('  ' || $rc || '::' || $h/@call || '();', '  return RTC::RTC_OK;')"/>
  </xsl:function>

  <xsl:function name="fp:rtm-action" as="xs:string+">
    <xsl:param name="hook" as="element(r:hook)"/>
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:variable name="rc" as="xs:string" select="$c/r:realizing-class/@cpp-name"/>
    <xsl:variable name="rc-name" as="xs:string" select="$c/r:realizing-class/@name"/>
    <xsl:sequence select="(
      replace(fp:rtm-action-signature($hook/@name), '^(RTC::ReturnCode_t )', '$1' || $c/@generated-class || '::'),
      '{',
      if ($hook/@name eq 'update') then (
        $c/r:data-port[@direction eq 'in'] ! ('  if (' || @port-member || '.isNew()) {', fp:rtm-take(., $c), '  }'),
        if (empty($hook/@call)) then '  // ' || $rc-name || ' declares no update()' else '  ' || $rc || '::' || $hook/@call || '();',
        $c/r:data-port[@direction eq 'out'] ! (
          if (xs:boolean(@accessor-declared)) then (
            if (@convert eq 'primitive')
            then '  ' || @member || '.data = ' || $rc || '::' || @accessor || '()' || (if (@primitive eq 'string') then '.c_str()' else '') || ';'
            else '  toIdl' || (if (@convert eq 'sequence') then 'Seq' else '') || '(' || $rc || '::' || @accessor || '(), ' || @member || '.data);',
            '  setTimestamp(' || @member || ');',
            '  ' || @port-member || '.write();')
          else '  // ' || $rc-name || ' declares no ' || @accessor || '(): ' || @name || ' is not written'),
        '  return RTC::RTC_OK;')
      else if ($hook/@name eq 'start') then (fp:rtm-constants-first($c), fp:rtm-call($c, 'start'))
      else fp:rtm-call($c, $hook/@name),
      '}')"/>
  </xsl:function>

  <!-- the lines that read an input port's sample and hand it to the realizing class -->
  <xsl:function name="fp:rtm-take" as="xs:string+">
    <xsl:param name="port" as="element(r:data-port)"/>
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:variable name="rc" as="xs:string" select="$c/r:realizing-class/@cpp-name"/>
    <xsl:for-each select="$port">
      <xsl:sequence select="(
          '    ' || @port-member || '.read();',
          if ($c/r:realizing-class) then (
            '    if (!' || @port-member || 'Received) {',
            '      ' || @port-member || 'Received = true;',
            '      RTC_INFO((&quot;input port %s.' || @name || ': first sample received&quot;, RTC::RTObject_impl::getInstanceName()));',
            '    }') else (),
          if (not(xs:boolean(@accessor-declared))) then ()
          else if (@convert eq 'primitive') then '    ' || $rc || '::' || @accessor || '(' || fp:rtm-from-datum(.) || ');'
          else ('    ' || @cpp || ' value;', '    fromIdl' || (if (@convert eq 'sequence') then 'Seq' else '') || '(' || @member || '.data, value);',
                '    ' || $rc || '::' || @accessor || '(value);'),
          if (xs:boolean(@accessor-declared)) then () else '    // ' || $c/r:realizing-class/@name || ' declares no ' || @accessor || '()')"/>
    </xsl:for-each>
  </xsl:function>

  <!-- a wrapper's configuration-constant inputs (seed 004, «Constant»): its configure() runs
       on the first activation, once each constant has arrived (its writer, activated
       before it, writes it), not in onInitialize, where no connection is made yet -->
  <xsl:function name="fp:rtm-constants" as="element(r:data-port)*">
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:sequence select="$c[r:realizing-class]/r:data-port[@direction eq 'in'][@constant eq 'true']"/>
  </xsl:function>

  <xsl:function name="fp:rtm-constants-first" as="xs:string*">
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:variable name="ports" as="element(r:data-port)*" select="fp:rtm-constants($c)"/>
    <xsl:variable name="configure" as="element(r:hook)" select="$c/r:hook[@name eq 'configure']"/>
    <xsl:if test="exists($ports)">
      <xsl:sequence select="(
        '  if (!m_configured) {',
        '    // the configuration constants first (seed 004), waited for up to 10 s, then configure()',
        '    for (int i = 0; i &lt; 1000 &amp;&amp; !(' || string-join($ports ! (@port-member || '.isNew()'), ' &amp;&amp; ') || '); ++i) {',
        '      std::this_thread::sleep_for(std::chrono::milliseconds(10));',
        '    }',
        $ports ! (
          '    if (!' || @port-member || '.isNew()) {',
          '      RTC_ERROR((&quot;' || @name || ': no configuration constant after 10 s: not configured&quot;));',
          '      return RTC::RTC_ERROR;',
          '    }',
          fp:rtm-take(., $c)),
        if (empty($configure/@call)) then '    // ' || $c/r:realizing-class/@name || ' declares no configure()'
        else if (xs:boolean($configure/@returns-bool))
        then ('    if (!' || $c/r:realizing-class/@cpp-name || '::' || $configure/@call || '()) {', '      return RTC::RTC_ERROR;', '    }')
        else '    ' || $c/r:realizing-class/@cpp-name || '::' || $configure/@call || '();',
        '    m_configured = true;',
        '  }')"/>
    </xsl:if>
  </xsl:function>

  <!-- the factory registration rtcd2 calls when it loads the module -->
  <xsl:function name="fp:rtm-init" as="xs:string+">
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:variable name="type" as="xs:string" select="$c/@category || '::' || $c/@class"/>
    <xsl:sequence select="(
      'extern &quot;C&quot;',
      '{',
      '  void ' || $c/@class || 'Init(RTC::Manager* manager)',
      '  {',
      '    coil::Properties profile(' || $c/@category || '::spec);',
      '    manager-&gt;registerFactory(profile, RTC::Create&lt;' || $type || '&gt;, RTC::Delete&lt;' || $type || '&gt;);',
      '  }',
      '}')"/>
  </xsl:function>

  <!-- the user class of a component without realizing class: written once,
       in the shared frames (m2t/common/user-class.xsl) with OpenRTM's .h
       headers and the module entry <Class>Init after the namespace -->
  <xsl:function name="fp:rtm-user-header" as="xs:string">
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:sequence select="fp:user-class-header($fp:cpp-xsl, $c, $c/@category, $c/@class, $c/@generated-class, (
      'public:',
      '  explicit ' || $c/@class || '(RTC::Manager* manager) : ' || $c/@generated-class || '(manager) {}',
      '  RTC::ReturnCode_t onInitialize() override;',
      $c/r:hook[@name ne 'configure'] ! ('  ' || fp:rtm-action-signature(@name) || ' override;')), '.h', fp:rtm-init-decl($c))"/>
  </xsl:function>

  <xsl:function name="fp:rtm-user-source" as="xs:string">
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:sequence select="fp:user-class-source($fp:cpp-xsl, $c, $c/@category, $c/@class, (
      fp:rtm-spec($c), '',
      fp:definition('RTC::ReturnCode_t ' || $c/@class || '::onInitialize()',
        ('  RTC::ReturnCode_t ret = ' || $c/@generated-class || '::onInitialize();', '  // your initialisation', '  return ret;')),
      $c/r:hook[@name ne 'configure'] ! ('', fp:definition(replace(fp:rtm-action-signature(@name), '^(RTC::ReturnCode_t )', '$1' || $c/@class || '::'),
        '  return RTC::RTC_OK;'))), '.h', fp:rtm-init($c))"/>
  </xsl:function>

  <!-- CMakeLists.txt: OpenRTM-aist found by its CMake package, one module per component -->
  <xsl:function name="fp:rtm-cmakelists" as="xs:string">
    <xsl:param name="system" as="element(r:system)"/>
    <xsl:param name="version" as="xs:string"/>
    <xsl:variable name="pkg" as="xs:string" select="$system/@package"/>
    <!-- what every component's module links, said once: tested per
         component, it scanned the system's children per component -->
    <xsl:variable name="links" as="xs:string"
        select="(if ($system/r:interface or $system/r:data-types[(r:enum | r:struct)[xs:boolean(@idl)]]) then ' ' || $pkg || '_idl' else '')
                || ' ${OPENRTM_LIBRARIES}' || string-join($system/r:library ! (' ' || @target))"/>
    <xsl:sequence select="fp:lines((
      fp:banner('# ', $fp:cpp-xsl, 'model ''' || $system/@model-name || '''', false()),
      'cmake_minimum_required(VERSION 3.5)',
      'project(' || $pkg || ' LANGUAGES CXX)',
      '',
      'if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)',
      '  set(CMAKE_BUILD_TYPE Release CACHE STRING &quot;Build type (Release unless set)&quot; FORCE)',
      'endif()',
      'set(CMAKE_CXX_STANDARD 14)',
      'set(CMAKE_CXX_STANDARD_REQUIRED ON)',
      fp:cmake-warnings(),
      '',
      '# OpenRTM-aist 2.0, by its OpenRTMConfig.cmake (OPENRTM_INCLUDE_DIRS, OPENRTM_LIBRARIES, OPENRTM_CFLAGS)',
      'find_package(OpenRTM REQUIRED)',
      'include_directories(${CMAKE_CURRENT_SOURCE_DIR}/include ${OPENRTM_INCLUDE_DIRS})',
      'add_definitions(${OPENRTM_CFLAGS})',
      'link_directories(${OPENRTM_LIBRARY_DIRS})',
      '',
      $system/r:library ! fp:rtm-library-lines(.),
      fp:rtm-idl-cmake($system),
      '# one module per RT-Component: rtcd2 loads &lt;Class&gt;.so and calls &lt;Class&gt;Init',
      $system/r:component ! (
        'add_library(' || @class || ' MODULE src/' || @generated-class || '.cpp'
          || (if (@kind eq 'base') then ' src/' || @class || '.cpp' else '') || ')',
        'set_target_properties(' || @class || ' PROPERTIES PREFIX &quot;&quot;)',
        'target_link_libraries(' || @class || $links || ')',
        'install(TARGETS ' || @class || ' LIBRARY DESTINATION lib/' || $pkg || ')'),
      $system/r:coordinator ! fp:rtm-coordinator-cmake(.),
      'install(DIRECTORY conf deploy rtc DESTINATION share/' || $pkg || ')'))"/>
  </xsl:function>

  <xsl:function name="fp:rtm-library-lines" as="xs:string+">
    <xsl:param name="lib" as="element(r:library)"/>
    <xsl:sequence select="(
      '# atomic-code library ''' || $lib/@name || ''', built from its own CMakeLists.txt, position-independent (linked into modules)',
      'set(CMAKE_POSITION_INDEPENDENT_CODE ON)',
      'set(' || $lib/@cmake-var || ' &quot;' || fp:library-dir($lib) || '&quot; CACHE PATH &quot;Directory of the atomic-code library ' || $lib/@name || '&quot;)',
      'if(NOT TARGET ' || $lib/@target || ')',
      '  add_subdirectory(&quot;${' || $lib/@cmake-var || '}&quot; ' || $lib/@build-dir || ')',
      'endif()',
      'include_directories(&quot;${' || $lib/@cmake-var || '}/' || ($lib/@include-dir[. ne ''], 'include')[1] || '&quot; &quot;${' || $lib/@cmake-var || '}&quot;)',
      '')"/>
  </xsl:function>
</xsl:stylesheet>
