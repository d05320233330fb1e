<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros1/ros1-cpp.xsl - C++ of the ROS 1 (roscpp) package.

  Reads:   r:node of urn:robomda:psm-ros:1 (ros-version 1).
  Writes:  strings (file contents), wrapped into fs:file by main.xsl.
  Params:  none.  Errors: none.

  Per node: include/<pkg>/<Class>.hpp and src/<Class>.cpp, the node class
  deriving from the realizing class (seed 000 Fig. 11, as in the Orocos
  target); src/<executable>.cpp, its main(). setUp() reads the private
  parameters into the realizing class's members, calls configure() and
  start(), advertises the publishers, subscribes the inputs, advertises the
  services and starts the timer (period > 0); step() calls update() and
  publishes get<Datum>() of each output; each subscription callback calls
  set<Datum>() and, when the node is data-driven (period 0), step().
  tearDown() calls stop() and cleanup(). Calls are qualified with the
  realizing class's C++ name. Before configure(), setUp() reads each
  configuration constant («Constant» input, seed 004) once: the latched
  message, waited for up to 10 s (fp:ros1-read-constants). A node whose
  values a job switch changes while it runs (ros1-jobs.xsl) has the
  service ~reload_parameters (std_srvs/Empty), which reads the parameters
  into the atomic code again.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:ros1-includes" as="xs:string*">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="pkg" as="xs:string" select="$node/@namespace"/>
    <xsl:sequence select="'#include &lt;ros/ros.h&gt;',
        distinct-values(($node/r:port/r:message/@msg, $node/r:service/@srv, $node/r:service-client/@srv) ! (concat('#include &lt;', fp:ros1-type(., $pkg)[1], '&gt;'))),
        if (fp:ros-switched($node)) then '#include &lt;std_srvs/Empty.h&gt;' else (),
        if ($node/r:port[@direction eq 'in'][@constant = 'true']) then '#include &lt;ros/topic.h&gt;' else (),
        '#include &lt;string&gt;',
        concat('#include &lt;', $node/r:realizing-class/@header, '&gt;'), fp:conversions-include($node)"/>
  </xsl:function>

  <xsl:function name="fp:ros1-header" as="xs:string">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="package" as="xs:string" select="$node/@namespace"/>
    <xsl:variable name="class" as="xs:string" select="$node/@class"/>
    <xsl:sequence select="fp:lines((
        fp:ros-header-opening($node),
        '',
        fp:ros1-includes($node),
        '',
        concat('namespace ', $package, ' {'),
        '',
        '/**',
        concat(' * ', fp:doc-of($node, concat('ROS 1 node of component ', $node/@name, '.'))),
        concat(' * Wraps the atomic code ', $node/r:realizing-class/@cpp-name, ' (seed 000, R1).'),
        ' */',
        concat('class ', $class, ' : public ', $node/r:realizing-class/@cpp-name),
        '{',
        'public:',
        concat('  ', $class, '(const ros::NodeHandle&amp; nh, const ros::NodeHandle&amp; private_nh);'),
        concat('  virtual ~', $class, '();'),
        '',
        '  /// Reads the parameters, calls configure() and start(), opens the ports,',
        '  /// services and timer. False when configure() or start() fails.',
        '  bool setUp();',
        '  /// Stops the timer, calls stop() and cleanup().',
        '  void tearDown();',
        fp:client-overrides($node),
        '',
        'private:',
        '  void step();',
        '  void onTimer(const ros::TimerEvent&amp; event);',
        $node/r:port[@direction eq 'in'] ! (concat('  void on_', @name, '(const ', fp:ros1-type(r:message/@msg, $package)[2], '::ConstPtr&amp; msg);')),
        $node/r:service ! (concat('  bool on_', @name, '(', fp:ros1-type(@srv, $package)[2], '::Request&amp; request, ',
                         fp:ros1-type(@srv, $package)[2], '::Response&amp; response);')),
        if (fp:ros-switched($node)) then (
          '  /// ~reload_parameters: the parameters read again into the atomic code (a job switch set them)',
          '  bool on_reload_parameters(std_srvs::Empty::Request&amp; request, std_srvs::Empty::Response&amp; response);',
          '  ros::ServiceServer srv_reload_parameters_;') else (),
        '',
        '  ros::NodeHandle nh_;',
        '  ros::NodeHandle private_nh_;',
        $node/r:port[@direction eq 'out'] ! (concat('  ros::Publisher ', @member, ';')),
        $node/r:port[@direction eq 'in'] ! (concat('  ros::Subscriber ', @member, ';')),
        $node/r:service ! (concat('  ros::ServiceServer ', @member, ';')),
        $node/r:service-client ! (concat('  ros::ServiceClient ', @member, ';')),
        '  ros::Timer timer_;',
        '  double period_;',
        '  bool running_;',
        '};',
        '',
        concat('}  // namespace ', $package),
        '',
        concat('#endif  // ', fp:guard($package, $class))))"/>
  </xsl:function>

  <xsl:function name="fp:ros1-source" as="xs:string">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="class" as="xs:string" select="$node/@class"/>
    <xsl:variable name="package" as="xs:string" select="$node/@namespace"/>
    <xsl:sequence select="fp:lines((
        fp:ros-source-opening($node),
        '',
        concat('namespace ', $package, ' {'),
        '',
        if ($node/r:parameter[@kind eq 'items']) then fp:ros1-item-helpers() else (),
        concat($class, '::', $class, '(const ros::NodeHandle&amp; nh, const ros::NodeHandle&amp; private_nh)'),
        concat('  : nh_(nh), private_nh_(private_nh), period_(', fp:double-literal($node/@period), '), running_(false)'),
        '{',
        '}',
        '',
        concat($class, '::~', $class, '()'),
        '{',
        '  tearDown();',
        '}',
        '',
        concat('bool ', $class, '::setUp()'),
        '{',
        fp:ros1-set-up($node),
        '}',
        '',
        concat('void ', $class, '::tearDown()'),
        '{',
        '  if (!running_) {',
        '    return;',
        '  }',
        '  running_ = false;',
        '  timer_.stop();',
        $node/r:hook[@name = ('stop', 'cleanup')][@call]
          ! concat('  ', $node/r:realizing-class/@cpp-name, '::', @call, '();'),
        '}',
        '',
        concat('void ', $class, '::step()'),
        '{',
        fp:ros-step($node, $node/r:port[@direction eq 'out'] ! fp:ros1-type(r:message/@msg, $package)[2], '.publish'),
        '}',
        '',
        concat('void ', $class, '::onTimer(const ros::TimerEvent&amp; /*event*/)'),
        '{',
        '  step();',
        '}',
        fp:ros1-callbacks($node),
        if (fp:ros-switched($node)) then (
          '',
          concat('bool ', $class, '::on_reload_parameters(std_srvs::Empty::Request&amp; /*request*/, std_srvs::Empty::Response&amp; /*response*/)'),
          '{',
          fp:ros1-read-parameters($node),
          '  ROS_INFO(&quot;%s: parameters reloaded&quot;, ros::this_node::getName().c_str());',
          '  return true;',
          '}') else (),
        '',
        concat('}  // namespace ', $package)))"/>
  </xsl:function>

  <!-- the reading of the members of an item of a list-of-mappings
       parameter (issue 37): a value of each C++ type a member is read as;
       an absent key keeps the item's model value, one of another type
       rejects the parameter -->
  <xsl:function name="fp:ros1-item-helpers" as="xs:string+">
    <xsl:variable name="types" as="xs:string" select="'XmlRpc::XmlRpcValue::Type'"/>
    <xsl:sequence select="
        'namespace {', '',
        '// one member of an item of a list-of-mappings parameter: false when it has another type',
        'bool item_value(XmlRpc::XmlRpcValue&amp; v, double&amp; out)', '{',
        '  if (v.getType() == ' || $types || 'Double) {', '    out = static_cast&lt;double&amp;&gt;(v);', '    return true;', '  }',
        '  if (v.getType() == ' || $types || 'Int) {', '    out = static_cast&lt;int&amp;&gt;(v);', '    return true;', '  }',
        '  return false;', '}', '',
        (['int', 'Int'], ['bool', 'Boolean'], ['std::string', 'String']) ! (
          'bool item_value(XmlRpc::XmlRpcValue&amp; v, ' || ?1 || '&amp; out)', '{',
          '  if (v.getType() != ' || $types || ?2 || ') {', '    return false;', '  }',
          '  out = static_cast&lt;' || ?1 || '&amp;&gt;(v);', '  return true;', '}', ''),
        '// member key of item, read as Read: an absent key keeps out''s value',
        'template &lt;typename Read, typename Member&gt;',
        'bool item_member(XmlRpc::XmlRpcValue&amp; item, const char* key, Member&amp; out)', '{',
        '  if (!item.hasMember(key)) {', '    return true;', '  }',
        '  Read value;',
        '  if (!item_value(item[key], value)) {', '    return false;', '  }',
        '  out = static_cast&lt;Member&gt;(value);', '  return true;', '}', '',
        '}  // namespace', ''"/>
  </xsl:function>

  <!-- the block of setUp() that reads list-of-mappings parameter $parameter
       into the realizing class's member: the model's value when it is not
       set; logged, the member keeping its value, when it is no list of
       mappings (of the fixed size) or a member has another type -->
  <xsl:function name="fp:ros1-items-parameter" as="xs:string+">
    <xsl:param name="parameter" as="element(r:parameter)"/>
    <xsl:variable name="member" as="xs:string" select="$parameter/../r:realizing-class/@cpp-name || '::' || $parameter/@member"/>
    <xsl:variable name="name" as="xs:string" select="fp:cpp-string($parameter/@name)"/>
    <xsl:variable name="item-type" as="xs:string" select="$parameter/@item-type"/>
    <xsl:sequence select="
        '{', '  XmlRpc::XmlRpcValue value;',
        '  if (private_nh_.getParam(' || fp:cpp-string(translate($parameter/@name, '.', '/')) || ', value)) {',
        '    bool ok = value.getType() == XmlRpc::XmlRpcValue::TypeArray'
            || ($parameter/@size ! (' &amp;&amp; value.size() == ' || .)) || ';',
        '    ' || $parameter/@cpp-type || ' items(ok ? value.size() : 0, ' || $item-type || '());',
        '    for (int i = 0; ok &amp;&amp; i &lt; value.size(); ++i) {',
        '      XmlRpc::XmlRpcValue&amp; item = value[i];',
        '      ' || $item-type || '&amp; e = items[i];',
        '      ok = item.getType() == XmlRpc::XmlRpcValue::TypeStruct;',
        fp:indent(6, fp:ros1-item-reads($parameter/r:item, 'item', 'e', 1)),
        '    }',
        '    if (ok) {', '      ' || $member || ' = items;', '    } else {',
        '      ROS_ERROR(&quot;parameter %s: not a list of ' || ($parameter/@size, 'any number of')[1] || ' mappings of the members of '
            || replace($item-type, '^.*::', '') || ' (' || string-join($parameter/r:item/@name, ', ')
            || '), each of its type&quot;, ' || $name || ');',
        '    }',
        '  } else {', '    ' || $member || ' = ' || $parameter/@cpp-default || ';', '  }',
        '}'"/>
  </xsl:function>

  <xsl:function name="fp:ros1-item-reads" as="xs:string*">
    <xsl:param name="items" as="element(r:item)*"/>
    <xsl:param name="item" as="xs:string"/>
    <xsl:param name="e" as="xs:string"/>
    <xsl:param name="depth" as="xs:integer"/>
    <xsl:for-each select="$items">
      <xsl:variable name="key" as="xs:string" select="fp:cpp-string(@name)"/>
      <xsl:sequence select="
        if (@kind eq 'struct') then (
          'if (ok &amp;&amp; ' || $item || '.hasMember(' || $key || ')) {',
          '  XmlRpc::XmlRpcValue&amp; item' || $depth || ' = ' || $item || '[' || $key || '];',
          '  ' || @cpp-type || '&amp; e' || $depth || ' = ' || $e || '.' || @member || ';',
          '  ok = item' || $depth || '.getType() == XmlRpc::XmlRpcValue::TypeStruct;',
          fp:indent(2, fp:ros1-item-reads(r:item, 'item' || $depth, 'e' || $depth, $depth + 1)),
          '}')
        else if (@kind eq 'enum') then (
          'if (ok &amp;&amp; ' || $item || '.hasMember(' || $key || ')) {',
          '  std::string literal;',
          '  ok = item_value(' || $item || '[' || $key || '], literal);',
          r:choice ! ('  ' || (if (position() eq 1) then 'if' else '} else if') || ' (literal == ' || fp:cpp-string(@value) || ') {',
                      '    ' || $e || '.' || ../@member || ' = ' || @cpp || ';'),
          '  } else {', '    ok = false;', '  }',
          '}')
        else 'ok = ok &amp;&amp; item_member&lt;' || @param1 || '&gt;(' || $item || ', ' || $key || ', ' || $e || '.' || @member || ');'"/>
    </xsl:for-each>
  </xsl:function>

  <!-- the body of setUp(): parameters, configure() and start(), then the
       publishers, subscribers, services and the timer -->
  <xsl:function name="fp:ros1-set-up" as="xs:string+">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="class" as="xs:string" select="$node/@class"/>
    <xsl:variable name="package" as="xs:string" select="$node/@namespace"/>
    <xsl:variable name="realizing-class" as="xs:string" select="$node/r:realizing-class/@cpp-name"/>
    <xsl:sequence select="(
        fp:ros1-read-parameters($node),
        '  private_nh_.param&lt;double&gt;(&quot;update_period&quot;, period_, period_);',
        fp:ros1-read-constants($node),
        for $hook in $node/r:hook[@name = ('configure', 'start')][@call] return
          if (xs:boolean($hook/@returns-bool))
          then (concat('  if (!', $realizing-class, '::', $hook/@call, '()) {'),
                concat('    ROS_ERROR(&quot;', $class, ': ', $hook/@call, '() failed&quot;);'),
                '    return false;',
                '  }')
          else concat('  ', $realizing-class, '::', $hook/@call, '();'),
        $node/r:port[@direction eq 'out'] ! concat('  ', @member, ' = nh_.advertise&lt;',
             fp:ros1-type(r:message/@msg, $package)[2], '&gt;(', fp:cpp-string(@topic), ', ', r:qos/@depth, ', ',
             r:qos/@latch, ');'),
        $node/r:port[@direction eq 'in'] ! concat('  ', @member, ' = nh_.subscribe(', fp:cpp-string(@topic), ', ',
             r:qos/@depth, ', &amp;', $class, '::on_', @name, ', this);'),
        $node/r:service ! concat('  ', @member, ' = private_nh_.advertiseService(', fp:cpp-string(@name), ', &amp;',
             $class, '::on_', @name, ', this);'),
        fp:ros-publish-constants($node, $node/r:port[@direction eq 'out'] ! fp:ros1-type(r:message/@msg, $package)[2], '.publish'),
        if (fp:ros-switched($node)) then concat('  srv_reload_parameters_ = private_nh_.advertiseService(&quot;reload_parameters&quot;, &amp;',
                                                $class, '::on_reload_parameters, this);') else (),
        $node/r:service-client ! concat('  ', @member, ' = nh_.serviceClient&lt;', fp:ros1-type(@srv, $package)[2], '&gt;(',
             fp:cpp-string(@name), ');'),
        '  if (period_ &gt; 0.0) {',
        concat('    timer_ = nh_.createTimer(ros::Duration(period_), &amp;', $class, '::onTimer, this);'),
        '  }',
        '  running_ = true;',
        '  return true;')"/>
  </xsl:function>

  <!-- the private parameters (R4) read into the realizing class's members -->
  <xsl:function name="fp:ros1-read-parameters" as="xs:string+">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:sequence select="(
        '  // parameters (R4), private: ~name',
        for $parameter in $node/r:parameter return if ($parameter/@kind eq 'items') then fp:indent(2, fp:ros1-items-parameter($parameter)) else (
          '  {',
          concat('    ', $parameter/@param1, ' value;'),
          concat('    private_nh_.param&lt;', $parameter/@param1, '&gt;(', fp:cpp-string(translate($parameter/@name, '.', '/')), ', value, ',
               (if ($parameter/@param1 eq 'std::string') then concat('std::string(', $parameter/@cpp-default, ')')
                else $parameter/@cpp-default), ');'),
          fp:parameter-assign($parameter, $parameter/@param1, 'ROS_ERROR(', 4),
          '  }'))"/>
  </xsl:function>

  <!-- each configuration constant («Constant» input, seed 004) read once
       before configure(), as Orocos reads it in configureHook: the latched
       message of its writer, waited for up to 10 s; none fails setUp() -->
  <xsl:function name="fp:ros1-read-constants" as="xs:string*">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="rc" as="xs:string" select="$node/r:realizing-class/@cpp-name"/>
    <xsl:for-each select="$node/r:port[@direction eq 'in'][@constant = 'true']">
      <xsl:sequence select="
          concat('  {  // configuration constant ', @name, ': read before configure()'),
          concat('    const auto msg = ros::topic::waitForMessage&lt;', fp:ros1-type(r:message/@msg, $node/@namespace)[2], '&gt;(',
                 fp:cpp-string(@topic), ', nh_, ros::Duration(10.0));'),
          '    if (!msg) {',
          concat('      ROS_ERROR(&quot;', $node/@class, ': no configuration constant on %s&quot;, nh_.resolveName(', fp:cpp-string(@topic), ').c_str());'),
          '      return false;',
          '    }',
          if (xs:boolean(@accessor-declared))
          then concat('    ', $rc, '::', @accessor, '(', fp:from-msg(r:message, '(*msg)'), ');')
          else concat('    (void)msg;  // ', ../r:realizing-class/@name, ' declares no ', @accessor, '()'),
          '  }'"/>
    </xsl:for-each>
  </xsl:function>

  <!-- the subscription and service callbacks, each after an empty line -->
  <xsl:function name="fp:ros1-callbacks" as="xs:string*">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="class" as="xs:string" select="$node/@class"/>
    <xsl:variable name="realizing-class" as="xs:string" select="$node/r:realizing-class/@cpp-name"/>
    <xsl:sequence select="(
        for $port in $node/r:port[@direction eq 'in'] return (
          '',
          concat('void ', $class, '::on_', $port/@name, '(const ', fp:ros1-type($port/r:message/@msg, $node/@namespace)[2],
                 '::ConstPtr&amp; msg)'),
          '{',
          fp:ros-on-input($port, $realizing-class),
          '}'),
        for $service in $node/r:service return (
          '',
          concat('bool ', $class, '::on_', $service/@name, '(', fp:ros1-type($service/@srv, $node/@namespace)[2], '::Request&amp; ',
               fp:service-callback-names($service)[1], ', ',
               fp:ros1-type($service/@srv, $node/@namespace)[2], '::Response&amp; ',
               fp:service-callback-names($service)[2], ')'),
          '{',
          fp:service-body($service, $realizing-class, '.'),
          '  return true;',
          '}'),
        for $client in $node/r:service-client[xs:boolean(@forward)] return (
          '',
          fp:client-method($client, concat($class, '::')),
          '{',
          concat('  ', fp:ros1-type($client/@srv, $node/@namespace)[2], ' srv;'),
          $client/@argument ! concat('  srv.request.data = ', ., ';'),
          $client/r:argument ! fp:indent(2, fp:to-msg(r:message, 'srv.request.' || @field, @name)),
          concat('  if (!', $client/@member, '.call(srv)) {'),
          concat('    ROS_WARN_STREAM(ros::this_node::getName() &lt;&lt; &quot;: service &quot; &lt;&lt; ', $client/@member,
                 '.getService() &lt;&lt; &quot; (', $client/@service, ') did not answer&quot;);'),
          if (xs:boolean($client/@returns-bool)) then '    return false;'
          else if ($client/r:result) then '    return ' || $client/r:result/r:message/@sample || ';'
          else '    return;',
          '  }',
          if (xs:boolean($client/@returns-bool)) then '  return srv.response.success;' else (),
          $client/r:result ! ('  return ' || fp:from-msg(r:message, 'srv.response.' || @field) || ';'),
          '}'))"/>
  </xsl:function>

  <xsl:function name="fp:ros1-main" as="xs:string">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="pkg" as="xs:string" select="$node/@namespace"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:cpp-xsl, fp:what($node), false()),
        concat('#include &lt;', $pkg, '/', $node/@class, '.hpp&gt;'),
        '',
        'int main(int argc, char** argv)',
        '{',
        concat('  ros::init(argc, argv, ', fp:cpp-string($node/@default-name), ');'),
        '  ros::NodeHandle nh;',
        '  ros::NodeHandle private_nh(&quot;~&quot;);',
        concat('  ', $pkg, '::', $node/@class, ' node(nh, private_nh);'),
        '  if (!node.setUp()) {',
        '    return 1;',
        '  }',
        '  ros::spin();',
        '  node.tearDown();',
        '  return 0;',
        '}'))"/>
  </xsl:function>
</xsl:stylesheet>
