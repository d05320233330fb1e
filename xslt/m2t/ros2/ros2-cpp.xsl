<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros2/ros2-cpp.xsl - C++ of the ROS 2 (rclcpp) package.

  Reads:   r:node of urn:robomda:psm-ros:1 (ros-version 2).
  Writes:  strings (file contents), wrapped into fs:file by main.xsl.
  Params:  none.  Errors: none.

  Per node: an rclcpp::Node subclass deriving also from the realizing class
  (include/<pkg>/<Class>.hpp, src/<Class>.cpp, registered as a component
  with RCLCPP_COMPONENTS_REGISTER_NODE) and src/<executable>.cpp, a main().
  The constructor declares the parameters (declared type, model default)
  into the realizing class's members, calls configure() and start()
  (throws std::runtime_error when they fail), creates the publishers and
  subscriptions with the port's QoS, the services and the wall timer
  (period > 0). Same call pattern as ROS 1 (ros1-cpp.xsl).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- (header, C++ type) of "pkg/Name"; $kind msg or srv -->
  <xsl:function name="fp:ros2-type" as="xs:string+">
    <xsl:param name="type" as="xs:string"/>
    <xsl:param name="pkg" as="xs:string"/>
    <xsl:param name="kind" as="xs:string"/>
    <xsl:variable name="p" as="xs:string+" select="fp:msg-parts($type, $pkg)"/>
    <xsl:sequence select="concat($p[1], '/', $kind, '/', fp:ros-snake($p[2]), '.hpp'), concat($p[1], '::', $kind, '::', $p[2])"/>
  </xsl:function>

  <xsl:function name="fp:ros2-qos" as="xs:string">
    <xsl:param name="q" as="element(r:qos)"/>
    <xsl:sequence select="concat('rclcpp::QoS(rclcpp::KeepLast(', $q/@depth, '))',
         (if ($q/@reliability eq 'reliable') then '.reliable()' else '.best_effort()'),
         (if ($q/@durability eq 'transient_local') then '.transient_local()' else '.durability_volatile()'))"/>
  </xsl:function>

  <xsl:function name="fp:ros2-header" as="xs:string">
    <xsl:param name="n" as="element(r:node)"/>
    <xsl:variable name="cls" as="xs:string" select="$n/@class"/>
    <xsl:variable name="pkg" as="xs:string" select="$n/@namespace"/>
    <xsl:variable name="guard" as="xs:string" select="fp:guard($pkg, $cls)"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:cpp-xsl, fp:what($n), false()),
        concat('#ifndef ', $guard),
        concat('#define ', $guard),
        '',
        '#include &lt;rclcpp/rclcpp.hpp&gt;',
        distinct-values(($n/r:port/r:message/@msg ! (concat('#include &lt;', fp:ros2-type(., $pkg, 'msg')[1], '&gt;')),
                         $n/r:service/@srv ! (concat('#include &lt;', fp:ros2-type(., $pkg, 'srv')[1], '&gt;')))),
        '#include &lt;memory&gt;',
        '#include &lt;string&gt;',
        concat('#include &lt;', $n/r:realizing-class/@header, '&gt;'),
        '',
        concat('namespace ', $pkg, ' {'),
        '',
        '/**',
        concat(' * ', fp:doc-of($n, concat('ROS 2 node of component ', $n/@name, '.'))),
        concat(' * Wraps the atomic code ', $n/r:realizing-class/@cpp-name, ' (seed 000, R1); a component'),
        concat(' * (rclcpp_components) named ', $n/@type-name, '.'),
        ' */',
        concat('class ', $cls, ' : public rclcpp::Node, public ', $n/r:realizing-class/@cpp-name),
        '{',
        'public:',
        concat('  explicit ', $cls, '(const rclcpp::NodeOptions&amp; options = rclcpp::NodeOptions());'),
        concat('  ~', $cls, '() override;'),
        '',
        'private:',
        '  void step();',
        $n/r:port[@direction eq 'in'] ! (concat('  void on_', @name, '(const ', fp:ros2-type(r:message/@msg, $pkg, 'msg')[2], '::SharedPtr msg);')),
        $n/r:service ! (concat('  void on_', @name, '(const std::shared_ptr&lt;', fp:ros2-type(@srv, $pkg, 'srv')[2], '::Request&gt; request,'),
                        concat('    std::shared_ptr&lt;', fp:ros2-type(@srv, $pkg, 'srv')[2], '::Response&gt; response);')),
        '',
        $n/r:port[@direction eq 'out'] ! (concat('  rclcpp::Publisher&lt;', fp:ros2-type(r:message/@msg, $pkg, 'msg')[2], '&gt;::SharedPtr ', @member, ';')),
        $n/r:port[@direction eq 'in'] ! (concat('  rclcpp::Subscription&lt;', fp:ros2-type(r:message/@msg, $pkg, 'msg')[2], '&gt;::SharedPtr ', @member, ';')),
        $n/r:service ! (concat('  rclcpp::Service&lt;', fp:ros2-type(@srv, $pkg, 'srv')[2], '&gt;::SharedPtr ', @member, ';')),
        '  rclcpp::TimerBase::SharedPtr timer_;',
        '  double period_;',
        '  bool running_;',
        '};',
        '',
        concat('}  // namespace ', $pkg),
        '',
        concat('#endif  // ', $guard)))"/>
  </xsl:function>

  <xsl:function name="fp:ros2-source" as="xs:string">
    <xsl:param name="n" as="element(r:node)"/>
    <xsl:variable name="cls" as="xs:string" select="$n/@class"/>
    <xsl:variable name="pkg" as="xs:string" select="$n/@namespace"/>
    <xsl:variable name="rc" as="xs:string" select="$n/r:realizing-class/@cpp-name"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:cpp-xsl, fp:what($n), false()),
        concat('#include &lt;', $pkg, '/', $cls, '.hpp&gt;'),
        '',
        '#include &lt;chrono&gt;',
        '#include &lt;cstdint&gt;',
        '#include &lt;functional&gt;',
        '#include &lt;stdexcept&gt;',
        '#include &lt;rclcpp_components/register_node_macro.hpp&gt;',
        '',
        concat('namespace ', $pkg, ' {'),
        '',
        concat($cls, '::', $cls, '(const rclcpp::NodeOptions&amp; options)'),
        concat('  : rclcpp::Node(', fp:cpp-string($n/@default-name), ', options), period_(', fp:double-literal($n/@period), '), running_(false)'),
        '{',
        '  // parameters (R4), declared with their type and the model default',
        $n/r:parameter ! (concat('  ', $rc, '::', @member, ' = ',
             (if (@param2 eq @cpp-type) then '' else concat('static_cast&lt;', @cpp-type, '&gt;(')),
             'this->declare_parameter&lt;', @param2, '&gt;(', fp:cpp-string(@name), ', ',
             (if (@param2 eq 'std::string') then concat('std::string(', @cpp-default, ')') else @cpp-default), ')',
             (if (@param2 eq @cpp-type) then '' else ')'), ';')),
        '  period_ = this->declare_parameter&lt;double&gt;(&quot;update_period&quot;, period_);',
        for $h in $n/r:hook[@name = ('configure', 'start')][@call] return
          if (xs:boolean($h/@returns-bool))
          then (concat('  if (!', $rc, '::', $h/@call, '()) {'),
                concat('    throw std::runtime_error(&quot;', $cls, ': ', $h/@call, '() failed&quot;);'),
                '  }')
          else concat('  ', $rc, '::', $h/@call, '();'),
        $n/r:port[@direction eq 'out'] ! (concat('  ', @member, ' = this->create_publisher&lt;', fp:ros2-type(r:message/@msg, $pkg, 'msg')[2], '&gt;('),
            concat('    ', fp:cpp-string(@topic), ', ', fp:ros2-qos(r:qos), ');')),
        $n/r:port[@direction eq 'in'] ! (concat('  ', @member, ' = this->create_subscription&lt;', fp:ros2-type(r:message/@msg, $pkg, 'msg')[2], '&gt;('),
            concat('    ', fp:cpp-string(@topic), ', ', fp:ros2-qos(r:qos), ','),
            concat('    std::bind(&amp;', $cls, '::on_', @name, ', this, std::placeholders::_1));')),
        $n/r:service ! (concat('  ', @member, ' = this->create_service&lt;', fp:ros2-type(@srv, $pkg, 'srv')[2], '&gt;('),
            concat('    ', fp:cpp-string(concat('~/', @name)), ', std::bind(&amp;', $cls, '::on_', @name, ', this, std::placeholders::_1, std::placeholders::_2));')),
        '  if (period_ &gt; 0.0) {',
        concat('    timer_ = this->create_wall_timer(std::chrono::duration&lt;double&gt;(period_), std::bind(&amp;', $cls, '::step, this));'),
        '  }',
        '  running_ = true;',
        '}',
        '',
        concat($cls, '::~', $cls, '()'),
        '{',
        '  if (running_) {',
        '    running_ = false;',
        '    if (timer_) {',
        '      timer_-&gt;cancel();',
        '    }',
        $n/r:hook[@name = ('stop', 'cleanup')][@call] ! (concat('    ', $rc, '::', @call, '();')),
        '  }',
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
            concat('    ', fp:ros2-type($p/r:message/@msg, $pkg, 'msg')[2], ' msg;'),
            fp:indent(4, fp:to-msg($p/r:message, 'msg', concat($rc, '::', $p/@accessor, '()'))),
            concat('    ', $p/@member, '-&gt;publish(msg);'),
            '  }')
          else concat('  // ', $n/r:realizing-class/@name, ' declares no ', $p/@accessor, '(): ', $p/@name, ' is not published'),
        '}',
        for $p in $n/r:port[@direction eq 'in'] return (
          '',
          concat('void ', $cls, '::on_', $p/@name, '(const ', fp:ros2-type($p/r:message/@msg, $pkg, 'msg')[2], '::SharedPtr msg)'),
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
          concat('void ', $cls, '::on_', $s/@name, '(const std::shared_ptr&lt;', fp:ros2-type($s/@srv, $pkg, 'srv')[2], '::Request&gt; ',
               (if ($s/@srv eq 'std_srvs/SetBool') then 'request' else '/*request*/'), ','),
          concat('  std::shared_ptr&lt;', fp:ros2-type($s/@srv, $pkg, 'srv')[2], '::Response&gt; ',
               (if ($s/@srv eq 'std_srvs/Empty') then '/*response*/' else 'response'), ')'),
          '{',
          fp:service-body($s, $rc, '-&gt;'),
          '}'),
        '',
        concat('}  // namespace ', $pkg),
        '',
        concat('RCLCPP_COMPONENTS_REGISTER_NODE(', $n/@type-name, ')')))"/>
  </xsl:function>

  <xsl:function name="fp:ros2-main" as="xs:string">
    <xsl:param name="n" as="element(r:node)"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:cpp-xsl, fp:what($n), false()),
        concat('#include &lt;', $n/@namespace, '/', $n/@class, '.hpp&gt;'),
        '',
        '#include &lt;memory&gt;',
        '',
        'int main(int argc, char** argv)',
        '{',
        '  rclcpp::init(argc, argv);',
        concat('  rclcpp::spin(std::make_shared&lt;', $n/@type-name, '&gt;());'),
        '  rclcpp::shutdown();',
        '  return 0;',
        '}'))"/>
  </xsl:function>
</xsl:stylesheet>
