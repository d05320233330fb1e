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
  realizing class's C++ name.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- (header, C++ type) of a message or service type "pkg/Name" -->
  <xsl:function name="fp:ros1-type" as="xs:string+">
    <xsl:param name="type" as="xs:string"/>
    <xsl:param name="pkg" as="xs:string"/>
    <xsl:variable name="p" as="xs:string+" select="fp:msg-parts($type, $pkg)"/>
    <xsl:sequence select="concat($p[1], '/', $p[2], '.h'), concat($p[1], '::', $p[2])"/>
  </xsl:function>

  <xsl:function name="fp:ros1-includes" as="xs:string*">
    <xsl:param name="n" as="element(r:node)"/>
    <xsl:variable name="pkg" as="xs:string" select="$n/@namespace"/>
    <xsl:sequence select="'#include &lt;ros/ros.h&gt;',
        distinct-values(($n/r:port/r:message/@msg, $n/r:service/@srv) ! (concat('#include &lt;', fp:ros1-type(., $pkg)[1], '&gt;'))),
        '#include &lt;string&gt;',
        concat('#include &lt;', $n/r:realizing-class/@header, '&gt;')"/>
  </xsl:function>

  <xsl:function name="fp:ros1-header" as="xs:string">
    <xsl:param name="n" as="element(r:node)"/>
    <xsl:variable name="cls" as="xs:string" select="$n/@class"/>
    <xsl:variable name="pkg" as="xs:string" select="$n/@namespace"/>
    <xsl:variable name="guard" as="xs:string" select="fp:guard($pkg, $cls)"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:cpp-xsl, fp:what($n), false()),
        concat('#ifndef ', $guard),
        concat('#define ', $guard),
        '',
        fp:ros1-includes($n),
        '',
        concat('namespace ', $pkg, ' {'),
        '',
        '/**',
        concat(' * ', fp:doc-of($n, concat('ROS 1 node of component ', $n/@name, '.'))),
        concat(' * Wraps the atomic code ', $n/r:realizing-class/@cpp-name, ' (seed 000, R1).'),
        ' */',
        concat('class ', $cls, ' : public ', $n/r:realizing-class/@cpp-name),
        '{',
        'public:',
        concat('  ', $cls, '(const ros::NodeHandle&amp; nh, const ros::NodeHandle&amp; private_nh);'),
        concat('  virtual ~', $cls, '();'),
        '',
        '  /// Reads the parameters, calls configure() and start(), opens the ports,',
        '  /// services and timer. False when configure() or start() fails.',
        '  bool setUp();',
        '  /// Stops the timer, calls stop() and cleanup().',
        '  void tearDown();',
        '',
        'private:',
        '  void step();',
        '  void onTimer(const ros::TimerEvent&amp; event);',
        $n/r:port[@direction eq 'in'] ! (concat('  void on_', @name, '(const ', fp:ros1-type(r:message/@msg, $pkg)[2], '::ConstPtr&amp; msg);')),
        $n/r:service ! (concat('  bool on_', @name, '(', fp:ros1-type(@srv, $pkg)[2], '::Request&amp; request, ',
                         fp:ros1-type(@srv, $pkg)[2], '::Response&amp; response);')),
        '',
        '  ros::NodeHandle nh_;',
        '  ros::NodeHandle private_nh_;',
        $n/r:port[@direction eq 'out'] ! (concat('  ros::Publisher ', @member, ';')),
        $n/r:port[@direction eq 'in'] ! (concat('  ros::Subscriber ', @member, ';')),
        $n/r:service ! (concat('  ros::ServiceServer ', @member, ';')),
        '  ros::Timer timer_;',
        '  double period_;',
        '  bool running_;',
        '};',
        '',
        concat('}  // namespace ', $pkg),
        '',
        concat('#endif  // ', $guard)))"/>
  </xsl:function>

  <xsl:function name="fp:ros1-source" as="xs:string">
    <xsl:param name="n" as="element(r:node)"/>
    <xsl:variable name="cls" as="xs:string" select="$n/@class"/>
    <xsl:variable name="pkg" as="xs:string" select="$n/@namespace"/>
    <xsl:variable name="rc" as="xs:string" select="$n/r:realizing-class/@cpp-name"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:cpp-xsl, fp:what($n), false()),
        concat('#include &lt;', $pkg, '/', $cls, '.hpp&gt;'),
        '',
        concat('namespace ', $pkg, ' {'),
        '',
        concat($cls, '::', $cls, '(const ros::NodeHandle&amp; nh, const ros::NodeHandle&amp; private_nh)'),
        concat('  : nh_(nh), private_nh_(private_nh), period_(', fp:double-literal($n/@period), '), running_(false)'),
        '{',
        '}',
        '',
        concat($cls, '::~', $cls, '()'),
        '{',
        '  tearDown();',
        '}',
        '',
        concat('bool ', $cls, '::setUp()'),
        '{',
        '  // parameters (R4), private: ~name',
        for $p in $n/r:parameter return (
          '  {',
          concat('    ', $p/@param1, ' value;'),
          concat('    private_nh_.param&lt;', $p/@param1, '&gt;(', fp:cpp-string($p/@name), ', value, ',
               (if ($p/@param1 eq 'std::string') then concat('std::string(', $p/@cpp-default, ')') else $p/@cpp-default), ');'),
          concat('    ', $rc, '::', $p/@member, ' = ', (if ($p/@param1 eq $p/@cpp-type) then 'value' else concat('static_cast&lt;', $p/@cpp-type, '&gt;(value)')), ';'),
          '  }'),
        '  private_nh_.param&lt;double&gt;(&quot;update_period&quot;, period_, period_);',
        for $h in $n/r:hook[@name = ('configure', 'start')][@call] return
          if (xs:boolean($h/@returns-bool))
          then (concat('  if (!', $rc, '::', $h/@call, '()) {'),
                concat('    ROS_ERROR(&quot;', $cls, ': ', $h/@call, '() failed&quot;);'),
                '    return false;',
                '  }')
          else concat('  ', $rc, '::', $h/@call, '();'),
        $n/r:port[@direction eq 'out'] ! (concat('  ', @member, ' = nh_.advertise&lt;', fp:ros1-type(r:message/@msg, $pkg)[2], '&gt;(',
             fp:cpp-string(@topic), ', ', r:qos/@depth, ', ', r:qos/@latch, ');')),
        $n/r:port[@direction eq 'in'] ! (concat('  ', @member, ' = nh_.subscribe(', fp:cpp-string(@topic), ', ', r:qos/@depth,
             ', &amp;', $cls, '::on_', @name, ', this);')),
        $n/r:service ! (concat('  ', @member, ' = private_nh_.advertiseService(', fp:cpp-string(@name), ', &amp;', $cls, '::on_', @name, ', this);')),
        '  if (period_ &gt; 0.0) {',
        concat('    timer_ = nh_.createTimer(ros::Duration(period_), &amp;', $cls, '::onTimer, this);'),
        '  }',
        '  running_ = true;',
        '  return true;',
        '}',
        '',
        concat('void ', $cls, '::tearDown()'),
        '{',
        '  if (!running_) {',
        '    return;',
        '  }',
        '  running_ = false;',
        '  timer_.stop();',
        $n/r:hook[@name = ('stop', 'cleanup')][@call] ! (concat('  ', $rc, '::', @call, '();')),
        '}',
        '',
        concat('void ', $cls, '::step()'),
        '{',
        '  if (!running_) {',
        '    return;',
        '  }',
        $n/r:hook[@name eq 'update'][@call] ! (concat('  ', $rc, '::update();')),
        for $p in $n/r:port[@direction eq 'out'] return
          if (xs:boolean($p/@accessor-declared)) then (
            '  {',
            concat('    ', fp:ros1-type($p/r:message/@msg, $pkg)[2], ' msg;'),
            fp:indent(4, fp:to-msg($p/r:message, 'msg', concat($rc, '::', $p/@accessor, '()'))),
            concat('    ', $p/@member, '.publish(msg);'),
            '  }')
          else concat('  // ', $n/r:realizing-class/@name, ' declares no ', $p/@accessor, '(): ', $p/@name, ' is not published'),
        '}',
        '',
        concat('void ', $cls, '::onTimer(const ros::TimerEvent&amp; /*event*/)'),
        '{',
        '  step();',
        '}',
        for $p in $n/r:port[@direction eq 'in'] return (
          '',
          concat('void ', $cls, '::on_', $p/@name, '(const ', fp:ros1-type($p/r:message/@msg, $pkg)[2], '::ConstPtr&amp; msg)'),
          '{',
          if (xs:boolean($p/@accessor-declared))
          then concat('  ', $rc, '::', $p/@accessor, '(', fp:from-msg($p/r:message, '(*msg)'), ');')
          else concat('  (void)msg;  // ', $n/r:realizing-class/@name, ' declares no ', $p/@accessor, '()'),
          '  if (period_ &lt;= 0.0) {',
          '    step();  // data-driven (period 0)',
          '  }',
          '}'),
        for $s in $n/r:service return (
          '',
          concat('bool ', $cls, '::on_', $s/@name, '(', fp:ros1-type($s/@srv, $pkg)[2], '::Request&amp; ',
               (if ($s/@srv eq 'std_srvs/SetBool') then 'request' else '/*request*/'), ', ',
               fp:ros1-type($s/@srv, $pkg)[2], '::Response&amp; ',
               (if ($s/@srv eq 'std_srvs/Empty') then '/*response*/' else 'response'), ')'),
          '{',
          fp:service-body($s, $rc, '.'),
          '  return true;',
          '}'),
        '',
        concat('}  // namespace ', $pkg)))"/>
  </xsl:function>

  <xsl:function name="fp:ros1-main" as="xs:string">
    <xsl:param name="n" as="element(r:node)"/>
    <xsl:variable name="pkg" as="xs:string" select="$n/@namespace"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:cpp-xsl, fp:what($n), false()),
        concat('#include &lt;', $pkg, '/', $n/@class, '.hpp&gt;'),
        '',
        'int main(int argc, char** argv)',
        '{',
        concat('  ros::init(argc, argv, ', fp:cpp-string($n/@default-name), ');'),
        '  ros::NodeHandle nh;',
        '  ros::NodeHandle private_nh(&quot;~&quot;);',
        concat('  ', $pkg, '::', $n/@class, ' node(nh, private_nh);'),
        '  if (!node.setUp()) {',
        '    return 1;',
        '  }',
        '  ros::spin();',
        '  node.tearDown();',
        '  return 0;',
        '}'))"/>
  </xsl:function>
</xsl:stylesheet>
