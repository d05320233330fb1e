<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/orocos/orocos-cpp.xsl - C++ of the Orocos component package.

  Reads:   o:task-context / o:deployment of urn:robomda:psm-orocos:1.
  Writes:  strings (file contents), wrapped into fs:file by main.xsl.
  Params:  none.  Errors: none.

  kind="wrapper" (seed 000 Fig. 11): class <Class> derives from
  RTT::TaskContext and from the realizing class; its constructor adds ports
  (input ports of components with a non-periodic instance as event ports,
  so that data arriving runs updateHook), properties bound to the realizing class's
  members and operations bound to its protected methods; the hooks call
  configure / start / update / stop / cleanup of the realizing class when it
  declares them (docs/profile.md, atomic-code conventions). Calls to the
  realizing class are qualified with its C++ name because RTT::TaskContext
  has methods with the same names (configure, start, stop, update, cleanup).
  Real time (issue 37): updateHook reads an input of a data type, array or
  string into a member sample made once with the model's sizes (no heap
  allocation per cycle); configureHook gives an output of a data type or an
  unbounded array the class's configured value as data sample.
  kind="base": generated <Class>Base (ports, properties, pure virtual
  operations) plus a user class <Class> written once, with empty hooks.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:o="urn:robomda:psm-orocos:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:signature" as="xs:string">
    <xsl:param name="op" as="element()"/><!-- o:operation or o:operation-caller -->
    <xsl:param name="with-names" as="xs:boolean"/>
    <xsl:sequence select="concat('(', string-join($op/o:parameter !
        (concat(@decl-type, ' ', (if ($with-names) then @name else concat('/*', @name, '*/')))), ', '), ')')"/>
  </xsl:function>

  <xsl:function name="fp:includes" as="xs:string*">
    <xsl:param name="tc" as="element(o:task-context)"/>
    <!-- every type definition of the deployment (o:types) -->
    <xsl:param name="definitions" as="element()*"/>
    <xsl:sequence select="'#include &lt;rtt/TaskContext.hpp&gt;',
        if ($tc/o:port[@direction eq 'in']) then '#include &lt;rtt/InputPort.hpp&gt;' else (),
        if ($tc/o:port[@direction eq 'out']) then '#include &lt;rtt/OutputPort.hpp&gt;' else (),
        if ($tc/o:required-service) then ('#include &lt;rtt/Logger.hpp&gt;', '#include &lt;rtt/OperationCaller.hpp&gt;') else (),
        '#include &lt;string&gt;',
        if ($tc//*[@type-kind eq 'sequence']) then '#include &lt;vector&gt;' else (),
        distinct-values(fp:definitions-of($tc//@type-ref, $definitions)/@header) ! ('#include &quot;' || . || '&quot;')"/>
  </xsl:function>

  <xsl:function name="fp:member-decls" as="xs:string*">
    <xsl:param name="tc" as="element(o:task-context)"/>
    <xsl:sequence select="
        if ($tc/o:port) then ('', '// data ports (R2)', $tc/o:port ! (concat(@rtt-class, ' ', @member, ';'))) else (),
        if (fp:read-samples($tc))
        then ('', '// what updateHook() reads the inputs into: made once, of the model''s sizes, so that a read',
              '// copies into storage that is already there (no heap allocation in a real-time cycle)',
              fp:read-samples($tc) ! concat(@cpp-type, ' ', @member, '_sample;')) else (),
        if ($tc/@kind eq 'base' and $tc/o:property)
        then ('', '// properties (R4)', $tc/o:property ! (concat(@cpp-type, ' ', @member, ';'))) else (),
        $tc/o:required-service ! (
          '', concat('// required interface ', @name, ' (port ', @port, '): its operations, called through the provider'),
          o:operation-caller ! concat('RTT::OperationCaller&lt;', @return-type, '(',
                                      string-join(o:parameter/@decl-type, ', '), ')&gt; ', @member, ';'),
          o:operation-caller[xs:boolean(@forward)] ! concat(@return-type, ' ', @name, fp:signature(., true()),
                                      if ($tc/@kind eq 'wrapper') then ' override;' else ';')),
        if ($tc/o:required-service)
        then ('', '// connects the required interfaces (script: connectServices; XML: from the Peers)',
              'bool connectRequiredServices();') else ()"/>
  </xsl:function>

  <!-- the generated methods of required interfaces: the connection from
       the peers where the deployment did not make it, and one method per
       operation that calls it -->
  <xsl:function name="fp:required-service-methods" as="xs:string*">
    <xsl:param name="tc" as="element(o:task-context)"/>
    <xsl:variable name="cls" as="xs:string" select="$tc/@generated-class"/>
    <xsl:if test="$tc/o:required-service">
      <xsl:sequence select="'', concat('bool ', $cls, '::connectRequiredServices()'), '{',
          concat('  if (', string-join($tc/o:required-service ! concat('!this-&gt;requires(', fp:cpp-string(@name), ')-&gt;ready()'),
                                       ' || '), ') {'),
          '    for (const std::string&amp; peer : this-&gt;getPeerList())',
          '      this-&gt;connectServices(this-&gt;getPeer(peer));',
          '  }',
          '  bool ready = true;',
          $tc/o:required-service ! (
            concat('  if (!this-&gt;requires(', fp:cpp-string(@name), ')-&gt;ready()) {'),
            concat('    RTT::log(RTT::Error) &lt;&lt; getName() &lt;&lt; ', fp:cpp-string(': required interface ' || @name
                   || ' (port ' || @port || ') is not connected to a component that provides it'), ' &lt;&lt; RTT::endlog();'),
            '    ready = false;',
            '  }'),
          '  return ready;', '}'"/>
      <xsl:for-each select="$tc/o:required-service/o:operation-caller[xs:boolean(@forward)]">
        <xsl:sequence select="'', concat(@return-type, ' ', $cls, '::', @name, fp:signature(., true())), '{',
            concat('  ', if (@return-type ne 'void') then 'return ' else '', @member, '(',
                   string-join(o:parameter/@name, ', '), ');'), '}'"/>
      </xsl:for-each>
    </xsl:if>
  </xsl:function>

  <!-- constructor body: ports, properties, operations -->
  <xsl:function name="fp:constructor-body" as="xs:string*">
    <xsl:param name="tc" as="element(o:task-context)"/>
    <xsl:variable name="owner" as="xs:string"
        select="if ($tc/@kind eq 'wrapper') then concat($tc/o:realizing-class/@cpp-name, '::') else ''"/>
    <xsl:for-each select="$tc/o:port">
      <xsl:sequence select="concat('this->ports()->', (if (@event eq 'true') then 'addEventPort' else 'addPort'),
           '(', @member, ').doc(', fp:cpp-string(fp:doc-of(., concat(@interface, '::', @datum))), ');')"/>
      <xsl:if test="@direction eq 'out'">
        <xsl:sequence select="concat(@member, '.setDataSample(', @sample, ');')"/>
      </xsl:if>
    </xsl:for-each>
    <xsl:for-each select="$tc/o:property">
      <xsl:sequence select="concat('this->addProperty(', fp:cpp-string(@name), ', ', $owner, @member,
           ').doc(', fp:cpp-string(fp:doc-of(., @name)), ');')"/>
    </xsl:for-each>
    <xsl:for-each select="$tc/o:operation">
      <xsl:sequence select="concat('this->', (@service ! concat('provides(', fp:cpp-string(.), ')->')),
           'addOperation(', fp:cpp-string(@name), ', &amp;', $tc/@generated-class,
           '::', @name, ', this, ', @thread, ')'),
          concat('    .doc(', fp:cpp-string(fp:doc-of(., @name)), ')',
           string-join(o:parameter ! (concat('.arg(', fp:cpp-string(@name), ', ', fp:cpp-string(fp:doc-of(., concat(@direction, ' ', @cpp-type))), ')')), ''),
           ';')"/>
    </xsl:for-each>
    <xsl:for-each select="$tc/o:required-service/o:operation-caller">
      <xsl:sequence select="concat('this->requires(', fp:cpp-string(../@name), ')->addOperationCaller(', @member, ');')"/>
    </xsl:for-each>
  </xsl:function>

  <xsl:function name="fp:initialisers" as="xs:string">
    <xsl:param name="tc" as="element(o:task-context)"/>
    <xsl:variable name="inits" as="xs:string*" select="
        'RTT::TaskContext(name, PreOperational)',
        $tc/o:port ! (concat(@member, '(', fp:cpp-string(@name), ')')),
        fp:read-samples($tc) ! concat(@member, '_sample(', @sample, ')'),
        $tc/o:required-service/o:operation-caller ! (concat(@member, '(', fp:cpp-string(@name), ')')),
        if ($tc/@kind eq 'base') then $tc/o:property ! (concat(@member, '(', @cpp-default, ')')) else ()"/>
    <xsl:sequence select="string-join($inits, ',&#10;    ')"/>
  </xsl:function>

  <!-- ================================================ generated header -->
  <xsl:function name="fp:cpp-header" as="xs:string">
    <xsl:param name="tc" as="element(o:task-context)"/>
    <!-- every type definition of the deployment (o:types), for the
         headers the component includes -->
    <xsl:param name="definitions" as="element()*"/>
    <xsl:variable name="cls" as="xs:string" select="$tc/@generated-class"/>
    <xsl:variable name="guard" as="xs:string" select="fp:guard($tc/@namespace, $cls)"/>
    <xsl:variable name="wrapper" as="xs:boolean" select="$tc/@kind eq 'wrapper'"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:cpp-xsl, fp:what($tc), false()),
        concat('#ifndef ', $guard),
        concat('#define ', $guard),
        '',
        fp:includes($tc, $definitions),
        if ($wrapper) then concat('#include &quot;', $tc/o:realizing-class/@header, '&quot;') else (),
        '',
        concat('namespace ', $tc/@namespace, ' {'),
        '',
        '/**',
        concat(' * ', fp:doc-of($tc, concat('Orocos TaskContext of component ', $tc/@name, '.'))),
        if ($wrapper) then concat(' * Wraps the atomic code ', $tc/o:realizing-class/@cpp-name, ' (seed 000, R1).')
        else concat(' * Generated base: derive ', $tc/@class, ' from it (user file).'),
        ' */',
        concat('class ', $cls, ' : public RTT::TaskContext',
           (if ($wrapper) then concat(', public ', $tc/o:realizing-class/@cpp-name) else '')),
        '{',
        'public:',
        concat('  explicit ', $cls, '(const std::string&amp; name);'),
        concat('  virtual ~', $cls, '();'),
        if ($wrapper) then (
          '',
          '  bool configureHook() override;',
          '  bool startHook() override;',
          '  void updateHook() override;',
          '  void stopHook() override;',
          '  void cleanupHook() override;')
        else (),
        if (not($wrapper) and $tc/o:operation) then (
          '',
          'protected:',
          concat('  // operations (R3): implemented by ', $tc/@class),
          $tc/o:operation ! (concat('  virtual ', @return-type, ' ', @name, fp:signature(., true()), ' = 0;')))
        else (),
        if (not($wrapper) and $tc/o:required-service) then ('', '  bool configureHook() override;') else (),
        if ($tc/o:port or (not($wrapper) and $tc/o:property) or $tc/o:required-service) then ('', 'protected:') else (),
        fp:indent(2, fp:member-decls($tc)[position() gt 1]),
        '};',
        '',
        concat('}  // namespace ', $tc/@namespace),
        '',
        concat('#endif  // ', $guard)))"/>
  </xsl:function>

  <!-- ================================================ generated source -->
  <xsl:function name="fp:cpp-source" as="xs:string">
    <xsl:param name="tc" as="element(o:task-context)"/>
    <xsl:variable name="cls" as="xs:string" select="$tc/@generated-class"/>
    <xsl:variable name="wrapper" as="xs:boolean" select="$tc/@kind eq 'wrapper'"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:cpp-xsl, fp:what($tc), false()),
        concat('#include &lt;', $tc/@namespace, '/', $cls, '.hpp&gt;'),
        '',
        concat('namespace ', $tc/@namespace, ' {'),
        '',
        concat($cls, '::', $cls, '(const std::string&amp; name)'),
        concat('  : ', fp:initialisers($tc)),
        '{',
        fp:indent(2, fp:constructor-body($tc)),
        '}',
        '',
        concat($cls, '::~', $cls, '()'),
        '{',
        '}',
        if ($wrapper) then fp:wrapper-hooks($tc)
        else if ($tc/o:required-service) then ('', concat('bool ', $cls, '::configureHook()'), '{', '  return connectRequiredServices();', '}')
        else (),
        fp:required-service-methods($tc),
        '',
        concat('}  // namespace ', $tc/@namespace)))"/>
  </xsl:function>

  <!-- the input ports a wrapper's updateHook() reads whose type may hold
       heap storage (a data type, an array, a string): each gets a member
       sample of the type's model sizes (a fixed [n] array has n elements),
       so reading a sample of those sizes allocates nothing; an unbounded
       array grows on its first larger sample only (std::vector keeps its
       capacity) -->
  <xsl:function name="fp:read-samples" as="element(o:port)*">
    <xsl:param name="tc" as="element(o:task-context)"/>
    <xsl:sequence select="if ($tc/@kind eq 'wrapper' and $tc/o:hook[@name eq 'update'])
                          then $tc/o:port[@direction eq 'in'][@type-kind or @primitive eq 'string'] else ()"/>
  </xsl:function>

  <xsl:function name="fp:wrapper-hooks" as="xs:string*">
    <xsl:param name="tc" as="element(o:task-context)"/>
    <xsl:variable name="cls" as="xs:string" select="$tc/@generated-class"/>
    <xsl:variable name="rc" as="xs:string" select="$tc/o:realizing-class/@cpp-name"/>
    <xsl:for-each select="$tc/o:hook">
      <xsl:variable name="host" as="element(o:hook)" select="."/>
      <xsl:variable name="bool" as="xs:boolean" select="@name = ('configure', 'start')"/>
      <xsl:sequence select="'', concat((if ($bool) then 'bool ' else 'void '), $cls, '::', @name, 'Hook()'), '{'"/>
      <xsl:if test="@name eq 'configure' and $tc/o:required-service">
        <xsl:sequence select="'  if (!connectRequiredServices())', '    return false;'"/>
      </xsl:if>
      <xsl:if test="@name eq 'configure'">
        <xsl:sequence select="fp:read-constants($tc)"/>
      </xsl:if>
      <xsl:if test="@name eq 'update'">
        <xsl:for-each select="$tc/o:port[@direction eq 'in'][not(@constant = 'true')]">
          <xsl:variable name="member" as="xs:boolean" select="exists(. intersect fp:read-samples($tc))"/>
          <xsl:variable name="value" as="xs:string" select="if ($member) then concat(@member, '_sample') else concat(@name, '_sample')"/>
          <xsl:sequence select="
              (if ($member) then () else concat('  ', @cpp-type, ' ', $value, ' = ', @sample, ';')),
              if (xs:boolean(@accessor-declared))
              then (concat('  if (', @member, '.read(', $value, ') == RTT::NewData) {'),
                    concat('    ', $rc, '::', @accessor, '(', $value, ');'),
                    '  }')
              else (concat('  ', @member, '.read(', $value, ');  // ', $tc/o:realizing-class/@name,
                     ' declares no ', @accessor, '(): the sample is not passed on'))"/>
        </xsl:for-each>
      </xsl:if>
      <!-- configure: outputs whose size the model does not fix (an unbounded
           array, a data type that may hold one) take the class's own value,
           once configured, as their data sample (setDataSample sizes the
           connections' buffers, so a write in a cycle copies without
           allocating) -->
      <xsl:variable name="sized" as="element(o:port)*"
          select="if (@name eq 'configure') then $tc/o:port[@direction eq 'out'][xs:boolean(@accessor-declared)]
                     [@type-kind eq 'struct' or (@type-kind eq 'sequence' and @sample eq @cpp-type || '()')] else ()"/>
      <xsl:variable name="samples" as="xs:string*"
          select="$sized ! concat('  ', @member, '.setDataSample(', $rc, '::', @accessor, '());  // the sizes the class gives')"/>
      <xsl:variable name="writes" as="xs:string*" select="if (@name eq 'configure') then fp:write-constants($tc) else ()"/>
      <xsl:choose>
        <xsl:when test="@call and $bool and xs:boolean(@returns-bool) and exists(($samples, $writes))">
          <xsl:sequence select="concat('  if (!', $rc, '::', @call, '())'), '    return false;', $samples, $writes, '  return true;'"/>
        </xsl:when>
        <xsl:when test="@call and $bool and xs:boolean(@returns-bool)">
          <xsl:sequence select="concat('  return ', $rc, '::', @call, '();')"/>
        </xsl:when>
        <xsl:when test="@call">
          <xsl:sequence select="concat('  ', $rc, '::', @call, '();')"/>
        </xsl:when>
        <xsl:otherwise>
          <xsl:sequence select="concat('  // ', $tc/o:realizing-class/@name, ' declares no ', @name, '()')"/>
        </xsl:otherwise>
      </xsl:choose>
      <xsl:if test="@name eq 'configure' and not(@call and $bool and xs:boolean(@returns-bool))">
        <xsl:sequence select="$writes"/>
      </xsl:if>
      <xsl:if test="@name eq 'update'">
        <xsl:for-each select="$tc/o:port[@direction eq 'out'][not(@constant = 'true')]">
          <xsl:sequence select="if (xs:boolean(@accessor-declared))
              then concat('  ', @member, '.write(', $rc, '::', @accessor, '());')
              else concat('  // ', $tc/o:realizing-class/@name, ' declares no ', @accessor, '(): ', @member, ' is not written')"/>
        </xsl:for-each>
      </xsl:if>
      <xsl:if test="$bool and not(@call and xs:boolean(@returns-bool))">
        <xsl:sequence select="$samples, '  return true;'"/>
      </xsl:if>
      <xsl:sequence select="'}'"/>
    </xsl:for-each>
  </xsl:function>

  <!-- configuration constants (seed 004 Fig. 5, «Constant»): read once in
       configureHook, before the class configures (the deployer connects
       the ports before it configures the components, and configures the
       writer first when the reader starts after it); configure fails while
       nothing was written -->
  <xsl:function name="fp:read-constants" as="xs:string*">
    <xsl:param name="tc" as="element(o:task-context)"/>
    <xsl:for-each select="$tc/o:port[@direction eq 'in'][@constant = 'true']">
      <xsl:variable name="value" as="xs:string" select="concat(@name, '_constant')"/>
      <xsl:sequence select="concat('  ', @cpp-type, ' ', $value, ' = ', @sample, ';'),
          concat('  if (', @member, '.read(', $value, ') == RTT::NoData)'),
          concat('    return false;  // configuration constant ', @name, ' not written yet: configure its writer first'),
          if (xs:boolean(@accessor-declared))
          then concat('  ', $tc/o:realizing-class/@cpp-name, '::', @accessor, '(', $value, ');')
          else concat('  // ', $tc/o:realizing-class/@name, ' declares no ', @accessor, '(): the constant is not passed on')"/>
    </xsl:for-each>
  </xsl:function>

  <!-- configuration constants written once, once the class is configured -->
  <xsl:function name="fp:write-constants" as="xs:string*">
    <xsl:param name="tc" as="element(o:task-context)"/>
    <xsl:for-each select="$tc/o:port[@direction eq 'out'][@constant = 'true']">
      <xsl:sequence select="if (xs:boolean(@accessor-declared))
          then concat('  ', @member, '.write(', $tc/o:realizing-class/@cpp-name, '::', @accessor, '());  // configuration constant, written once')
          else concat('  // ', $tc/o:realizing-class/@name, ' declares no ', @accessor, '(): configuration constant ', @member, ' is not written')"/>
    </xsl:for-each>
  </xsl:function>

  <!-- ===================================================== user class -->
  <xsl:function name="fp:user-header" as="xs:string">
    <xsl:param name="tc" as="element(o:task-context)"/>
    <xsl:sequence select="fp:user-class-header($fp:cpp-xsl, $tc, $tc/@namespace, $tc/@class, $tc/@generated-class, (
        'public:',
        concat('  explicit ', $tc/@class, '(const std::string&amp; name);'),
        '',
        '  bool configureHook() override;',
        '  bool startHook() override;',
        '  void updateHook() override;',
        '  void stopHook() override;',
        '  void cleanupHook() override;',
        if ($tc/o:operation) then (
          '',
          'protected:',
          $tc/o:operation ! (concat('  ', @return-type, ' ', @name, fp:signature(., true()), ' override;')))
        else ()), '.hpp', ())"/>
  </xsl:function>

  <xsl:function name="fp:user-source" as="xs:string">
    <xsl:param name="tc" as="element(o:task-context)"/>
    <xsl:variable name="cls" as="xs:string" select="$tc/@class"/>
    <xsl:sequence select="fp:user-class-source($fp:cpp-xsl, $tc, $tc/@namespace, $cls, (
        concat($cls, '::', $cls, '(const std::string&amp; name)'),
        concat('  : ', $tc/@generated-class, '(name)'),
        '{',
        '}',
        '',
        fp:definition(concat('bool ', $cls, '::configureHook()'),
          if ($tc/o:required-service) then concat('  return ', $tc/@generated-class, '::configureHook();  // connects the required interfaces')
          else '  return true;'),
        '',
        fp:definition(concat('bool ', $cls, '::startHook()'), '  return true;'),
        '',
        fp:definition(concat('void ', $cls, '::updateHook()'), (
          if ($tc/o:port[@direction eq 'in'])
          then concat('  // read: ', string-join($tc/o:port[@direction eq 'in'] ! (concat(@member, '.read(sample)')), ', ')) else (),
          if ($tc/o:port[@direction eq 'out'])
          then concat('  // write: ', string-join($tc/o:port[@direction eq 'out'] ! (concat(@member, '.write(value)')), ', ')) else ())),
        '',
        fp:definition(concat('void ', $cls, '::stopHook()'), ()),
        '',
        fp:definition(concat('void ', $cls, '::cleanupHook()'), ()),
        $tc/o:operation ! (
          '',
          fp:definition(concat(@return-type, ' ', $cls, '::', @name, fp:signature(., false())),
            if (@return-type ne 'void') then concat('  return ', @return-sample, ';') else ()))), '.hpp', ())"/>
  </xsl:function>

  <!-- ============================================== component library -->
  <xsl:function name="fp:components-cpp" as="xs:string">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:cpp-xsl, concat('the component library of model ''', $deployment/@model-name, ''''), false()),
        '#include &lt;rtt/Component.hpp&gt;',
        $deployment/o:task-context ! (concat('#include &lt;', @namespace, '/', @class, '.hpp&gt;')),
        '',
        'ORO_CREATE_COMPONENT_LIBRARY()',
        $deployment/o:task-context ! (concat('ORO_LIST_COMPONENT_TYPE(', @type-name, ')'))))"/>
  </xsl:function>
  <!-- ============================================== the shared thread -->
  <!-- SharedThread (task context of kind thread, seed 002): a component
       whose activity is the thread; its members (property members, names
       of peers, in order) have SlaveActivities it executes in updateHook -->
  <xsl:function name="fp:thread-header" as="xs:string">
    <xsl:param name="tc" as="element(o:task-context)"/>
    <xsl:variable name="guard" as="xs:string" select="fp:guard($tc/@namespace, $tc/@class)"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:cpp-xsl, 'the shared thread of the deployment (seed 002)', false()),
        concat('#ifndef ', $guard),
        concat('#define ', $guard),
        '',
        '#include &lt;string&gt;',
        '#include &lt;vector&gt;',
        '#include &lt;rtt/TaskContext.hpp&gt;',
        '',
        concat('namespace ', $tc/@namespace, ' {'),
        '',
        '/**',
        concat(' * ', $tc/o:doc),
        ' * The deployment gives each member a SlaveActivity whose master is this',
        ' * component''s activity and makes it a peer; configure() finds the members,',
        ' * start() requires each to have its SlaveActivity (the XML deployer sets',
        ' * activities while it configures, after this component), updateHook()',
        ' * executes them one after the other in this thread.',
        ' */',
        'class SharedThread : public RTT::TaskContext',
        '{',
        'public:',
        '  explicit SharedThread(const std::string&amp; name);',
        '',
        'protected:',
        '  bool configureHook() override;',
        '  bool startHook() override;',
        '  void updateHook() override;',
        '  void cleanupHook() override;',
        '',
        '  /** the members, peer names separated by spaces, in execution order */',
        '  std::string members_;',
        '',
        'private:',
        '  std::vector&lt;RTT::TaskContext*&gt; peers_;',
        '};',
        '',
        concat('}  // namespace ', $tc/@namespace),
        '',
        concat('#endif  // ', $guard)))"/>
  </xsl:function>

  <xsl:function name="fp:thread-source" as="xs:string">
    <xsl:param name="tc" as="element(o:task-context)"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:cpp-xsl, 'the shared thread of the deployment (seed 002)', false()),
        concat('#include &lt;', $tc/@namespace, '/SharedThread.hpp&gt;'),
        '',
        '#include &lt;sstream&gt;',
        '#include &lt;rtt/Logger.hpp&gt;',
        '#include &lt;rtt/extras/SlaveActivity.hpp&gt;',
        '',
        concat('namespace ', $tc/@namespace, ' {'),
        '',
        'SharedThread::SharedThread(const std::string&amp; name)',
        '  : RTT::TaskContext(name, PreOperational)',
        '{',
        '  addProperty(&quot;members&quot;, members_)',
        '      .doc(&quot;The components this thread runs, peer names separated by spaces, in execution order.&quot;);',
        '}',
        '',
        'bool SharedThread::configureHook()',
        '{',
        '  peers_.clear();',
        '  std::istringstream names(members_);',
        '  std::string name;',
        '  while (names &gt;&gt; name) {',
        '    RTT::TaskContext* member = getPeer(name);',
        '    if (member == 0) {',
        '      RTT::log(RTT::Error) &lt;&lt; getName() &lt;&lt; &quot;: member &quot; &lt;&lt; name &lt;&lt; &quot; is no peer&quot; &lt;&lt; RTT::endlog();',
        '      return false;',
        '    }',
        '    peers_.push_back(member);',
        '  }',
        '  return true;',
        '}',
        '',
        'bool SharedThread::startHook()',
        '{',
        '  for (std::size_t i = 0; i &lt; peers_.size(); ++i) {',
        '    if (dynamic_cast&lt;RTT::extras::SlaveActivity*&gt;(peers_[i]-&gt;getActivity()) == 0) {',
        '      RTT::log(RTT::Error) &lt;&lt; getName() &lt;&lt; &quot;: member &quot; &lt;&lt; peers_[i]-&gt;getName()',
        '                           &lt;&lt; &quot; has no SlaveActivity: it would not run in this thread&quot; &lt;&lt; RTT::endlog();',
        '      return false;',
        '    }',
        '  }',
        '  return true;',
        '}',
        '',
        'void SharedThread::updateHook()',
        '{',
        '  // the activity, not a copy of the pointer: a deployer may replace it until start',
        '  for (std::size_t i = 0; i &lt; peers_.size(); ++i) {',
        '    peers_[i]-&gt;getActivity()-&gt;execute();',
        '  }',
        '}',
        '',
        'void SharedThread::cleanupHook()',
        '{',
        '  peers_.clear();',
        '}',
        '',
        concat('}  // namespace ', $tc/@namespace)))"/>
  </xsl:function>
</xsl:stylesheet>
