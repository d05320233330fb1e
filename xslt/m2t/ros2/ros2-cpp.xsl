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
  subscriptions with the port's QoS (callbacks take the message as
  ConstSharedPtr), the services and the timer (period > 0) on the node's
  clock (simulated time under use_sim_time). Same call pattern as ROS 1
  (ros1-cpp.xsl).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:ros2-qos" as="xs:string">
    <xsl:param name="name" as="element(r:qos)"/>
    <xsl:sequence select="concat('rclcpp::QoS(rclcpp::KeepLast(', $name/@depth, '))',
         (if ($name/@reliability eq 'reliable') then '.reliable()' else '.best_effort()'),
         (if ($name/@durability eq 'transient_local') then '.transient_local()' else '.durability_volatile()'))"/>
  </xsl:function>

  <xsl:function name="fp:ros2-header" as="xs:string">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="class" as="xs:string" select="$node/@class"/>
    <xsl:variable name="package" as="xs:string" select="$node/@namespace"/>
    <xsl:sequence select="fp:lines((
        fp:ros-header-opening($node),
        '',
        fp:ros2-includes($node, (), ()),
        '',
        concat('namespace ', $package), '{',
        '',
        '/**',
        concat(' * ', fp:doc-of($node, concat('ROS 2 node of component ', $node/@name, '.'))),
        concat(' * Wraps the atomic code ', $node/r:realizing-class/@cpp-name, ' (seed 000, R1); a component'),
        concat(' * (rclcpp_components) named ', $node/@type-name, '.'),
        ' */',
        fp:class-line($class, 'rclcpp::Node', $node/r:realizing-class/@cpp-name),
        '{',
        'public:',
        concat('  explicit ', $class, '(const rclcpp::NodeOptions &amp; options = rclcpp::NodeOptions());'),
        concat('  ~', $class, '() override;'),
        fp:client-overrides($node),
        '',
        'private:',
        fp:ros2-members($node, 'rclcpp::Publisher'),
        '};',
        '',
        concat('}  // namespace ', $package),
        '',
        concat('#endif  // ', fp:guard($package, $class))))"/>
  </xsl:function>

  <!-- the includes of a node's header in cpplint's order: the standard
       library's (and $std, each "<name>"), then rclcpp's and the $others
       (paths), its messages and services, the realizing class, the message
       conversions -->
  <xsl:function name="fp:ros2-includes" as="xs:string*">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:param name="std" as="xs:string*"/>
    <xsl:param name="others" as="xs:string*"/>
    <xsl:variable name="package" as="xs:string" select="$node/@namespace"/>
    <xsl:sequence select="(
        '#include &lt;memory&gt;',
        if (fp:answers($node)) then '#include &lt;mutex&gt;' else (),
        '#include &lt;string&gt;',
        $std ! ('#include ' || .),
        '',
        '#include &quot;rclcpp/rclcpp.hpp&quot;',
        $others ! ('#include &quot;' || . || '&quot;'),
        distinct-values(($node/r:port/r:message/@msg ! (concat('#include &quot;', fp:ros2-type(., $package, 'msg')[1], '&quot;')),
                         ($node/r:service/@srv, $node/r:service-client/@srv) ! (concat('#include &quot;', fp:ros2-type(., $package, 'srv')[1], '&quot;')))),
        concat('#include &quot;', $node/r:realizing-class/@header, '&quot;'), fp:conversions-include($node))"/>
  </xsl:function>

  <!-- the clients of services of the package's own with a result whose
       node keeps the latest answer (fp:ros2-own-call) -->
  <xsl:function name="fp:answers" as="element(r:service-client)*">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:sequence select="$node/r:service-client[xs:boolean(@forward)][r:result]"/>
  </xsl:function>

  <!-- the private members of a node class: step(), the callbacks, the
       publishers ($publisher: their class template), subscriptions,
       services, clients and the timer -->
  <xsl:function name="fp:ros2-members" as="xs:string+">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:param name="publisher" as="xs:string"/>
    <xsl:variable name="package" as="xs:string" select="$node/@namespace"/>
    <xsl:sequence select="(
        '  void step();',
        $node/r:port[@direction eq 'in'] ! (concat('  void on_', @name, '(const ', fp:ros2-type(r:message/@msg, $package, 'msg')[2], '::ConstSharedPtr msg);')),
        $node/r:service ! ('  void on_' || @name || '(', fp:indent(2, fp:ros2-service-parameters(., ('request', 'response'), ');'))),
        '',
        $node/r:port[@direction eq 'out'] ! (concat('  ', $publisher, '&lt;', fp:ros2-type(r:message/@msg, $package, 'msg')[2], '&gt;::SharedPtr ', @member, ';')),
        $node/r:port[@direction eq 'in'] ! (concat('  rclcpp::Subscription&lt;', fp:ros2-type(r:message/@msg, $package, 'msg')[2], '&gt;::SharedPtr ', @member, ';')),
        $node/r:service ! (concat('  rclcpp::Service&lt;', fp:ros2-type(@srv, $package, 'srv')[2], '&gt;::SharedPtr ', @member, ';')),
        $node/r:service-client ! (concat('  rclcpp::Client&lt;', fp:ros2-type(@srv, $package, 'srv')[2], '&gt;::SharedPtr ', @member, ';')),
        fp:answers($node) ! ('  ' || r:result/r:message/@cpp-type || ' answer_' || @name || '_;'),
        if (fp:answers($node)) then '  std::mutex answers_mutex_;' else (),
        '  rclcpp::TimerBase::SharedPtr timer_;',
        '  double period_;',
        '  bool running_;')"/>
  </xsl:function>

  <xsl:function name="fp:ros2-source" as="xs:string">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="class" as="xs:string" select="$node/@class"/>
    <xsl:variable name="package" as="xs:string" select="$node/@namespace"/>
    <xsl:sequence select="fp:lines((
        fp:ros-source-opening($node),
        '',
        '#include &lt;chrono&gt;',
        '#include &lt;cstdint&gt;',
        '#include &lt;functional&gt;',
        '#include &lt;stdexcept&gt;',
        '',
        '#include &quot;rclcpp_components/register_node_macro.hpp&quot;',
        '',
        concat('namespace ', $package), '{',
        '',
        concat($class, '::', $class, '(const rclcpp::NodeOptions &amp; options)'),
        concat(': rclcpp::Node(', fp:cpp-string($node/@default-name), ', options),'),
        concat('  period_(', fp:double-literal($node/@period), '),'),
        '  running_(false)',
        '{',
        fp:ros2-constructor($node),
        '}',
        '',
        concat($class, '::~', $class, '()'),
        '{',
        '  if (running_) {',
        '    running_ = false;',
        '    if (timer_) {',
        '      timer_-&gt;cancel();',
        '    }',
        $node/r:hook[@name = ('stop', 'cleanup')][@call]
          ! concat('    ', $node/r:realizing-class/@cpp-name, '::', @call, '();'),
        '  }',
        '}',
        '',
        concat('void ', $class, '::step()'),
        '{',
        fp:ros-step($node, $node/r:port[@direction eq 'out'] ! fp:ros2-type(r:message/@msg, $package, 'msg')[2],
                    '-&gt;publish'),
        '}',
        fp:ros2-callbacks($node),
        '',
        concat('}  // namespace ', $package),
        '',
        concat('RCLCPP_COMPONENTS_REGISTER_NODE(', $node/@type-name, ')')))"/>
  </xsl:function>

  <!-- the parameters (R4), declared with their type and the model default
       into the realizing class's members, and update_period -->
  <xsl:function name="fp:ros2-parameters" as="xs:string+">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="realizing-class" as="xs:string" select="$node/r:realizing-class/@cpp-name"/>
    <xsl:sequence select="(
        '  // parameters (R4), declared with their type and the model default',
        for $p in $node/r:parameter return
        let $declare := 'this->declare_parameter&lt;' || $p/@param2 || '&gt;('
        , $arguments := fp:cpp-string($p/@name) || ', '
                          || (if ($p/@param2 eq 'std::string') then concat('std::string(', $p/@cpp-default, ')')
                              (: a braced list names its type: an empty brace alone also converts to a ParameterDescriptor :)
                              else if (starts-with($p/@cpp-default, '{')) then concat($p/@param2, $p/@cpp-default)
                              else $p/@cpp-default) || ')'
        , $member := $realizing-class || '::' || $p/@member || ' = '
        return if ($p/@kind = ('enum', 'sequence'))
          then ('  {', fp:fit(4, 'const ' || $p/@param2 || ' value = ' || $declare, $arguments || ';'),
                fp:parameter-assign($p, $p/@param2, 'RCLCPP_ERROR(this->get_logger(), ', 4), '  }')
          else if ($p/@param2 eq $p/@cpp-type) then fp:fit(2, $member || $declare, $arguments || ';')
          else fp:fit(2, $member || 'static_cast&lt;' || $p/@cpp-type || '&gt;(', $declare || $arguments || ');'),
        '  period_ = this->declare_parameter&lt;double&gt;(&quot;update_period&quot;, period_);')"/>
  </xsl:function>

  <!-- the calls of the realizing class's hooks $names (configure, start,
       stop, cleanup); one that returns false fails: a plain node throws, a
       lifecycle node ($lifecycle) logs and fails the transition -->
  <xsl:function name="fp:ros2-hook-calls" as="xs:string*">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:param name="names" as="xs:string+"/>
    <xsl:param name="lifecycle" as="xs:boolean"/>
    <xsl:variable name="realizing-class" as="xs:string" select="$node/r:realizing-class/@cpp-name"/>
    <xsl:sequence select="
        for $hook in $node/r:hook[@name = $names][@call] return
          if (xs:boolean($hook/@returns-bool))
          then (concat('  if (!', $realizing-class, '::', $hook/@call, '()) {'),
                if ($lifecycle)
                then (concat('    RCLCPP_ERROR(get_logger(), &quot;', $hook/@call, '() failed&quot;);'),
                      '    return CallbackReturn::FAILURE;')
                else concat('    throw std::runtime_error(&quot;', $node/@class, ': ', $hook/@call, '() failed&quot;);'),
                '  }')
          else concat('  ', $realizing-class, '::', $hook/@call, '();')"/>
  </xsl:function>

  <!-- the publishers, subscriptions (with the port's QoS), services and
       clients of a node -->
  <xsl:function name="fp:ros2-entities" as="xs:string*">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="class" as="xs:string" select="$node/@class"/>
    <xsl:variable name="package" as="xs:string" select="$node/@namespace"/>
    <xsl:sequence select="(
        $node/r:port[@direction eq 'out'] ! (
            concat('  ', @member, ' = this->create_publisher&lt;', fp:ros2-type(r:message/@msg, $package, 'msg')[2], '&gt;('),
            concat('    ', fp:cpp-string(@topic), ', ', fp:ros2-qos(r:qos), ');')),
        $node/r:port[@direction eq 'in'] ! (
            concat('  ', @member, ' = this->create_subscription&lt;', fp:ros2-type(r:message/@msg, $package, 'msg')[2], '&gt;('),
            concat('    ', fp:cpp-string(@topic), ', ', fp:ros2-qos(r:qos), ','),
            fp:fit(4, 'std::bind(', '&amp;' || $class || '::on_' || @name || ', this, std::placeholders::_1));')),
        $node/r:service ! (
            concat('  ', @member, ' = this->create_service&lt;', fp:ros2-type(@srv, $package, 'srv')[2], '&gt;('),
            concat('    ', fp:cpp-string(concat('~/', @name)), ','),
            fp:fit(4, 'std::bind(', '&amp;' || $class || '::on_' || @name || ', this, std::placeholders::_1, std::placeholders::_2));')),
        $node/r:service-client ! fp:fit(2, @member || ' = this->create_client&lt;' || fp:ros2-type(@srv, $package, 'srv')[2] || '&gt;(',
                                        fp:cpp-string(@name) || ');'))"/>
  </xsl:function>

  <!-- the timer that runs step(), when the node has a period: on the node's
       clock, so that it follows /clock when use_sim_time is set -->
  <xsl:function name="fp:ros2-timer" as="xs:string+">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:sequence select="
        '  if (period_ &gt; 0.0) {',
        '    timer_ = rclcpp::create_timer(this, this-&gt;get_clock(), rclcpp::Duration::from_seconds(period_),',
        concat('      std::bind(&amp;', $node/@class, '::step, this));'),
        '  }'"/>
  </xsl:function>

  <!-- the body of the constructor: parameters, configure() and start(),
       then the publishers, subscriptions, services and the timer -->
  <xsl:function name="fp:ros2-constructor" as="xs:string+">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:sequence select="(fp:ros2-parameters($node), fp:ros2-hook-calls($node, ('configure', 'start'), false()),
                           fp:ros2-entities($node),
                           fp:ros-publish-constants($node, $node/r:port[@direction eq 'out']
                                                    ! fp:ros2-type(r:message/@msg, $node/@namespace, 'msg')[2], '-&gt;publish'),
                           fp:ros2-timer($node), '  running_ = true;')"/>
  </xsl:function>
  <!-- the subscription and service callbacks, each after an empty line -->
  <xsl:function name="fp:ros2-callbacks" as="xs:string*">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="class" as="xs:string" select="$node/@class"/>
    <xsl:variable name="realizing-class" as="xs:string" select="$node/r:realizing-class/@cpp-name"/>
    <xsl:sequence select="(
        for $port in $node/r:port[@direction eq 'in'] return (
          '',
          concat('void ', $class, '::on_', $port/@name, '(const ',
                 fp:ros2-type($port/r:message/@msg, $node/@namespace, 'msg')[2], '::ConstSharedPtr msg)'),
          '{',
          fp:ros-on-input($port, $realizing-class),
          '}'),
        for $service in $node/r:service return (
          '',
          'void ' || $class || '::on_' || $service/@name || '(',
          fp:ros2-service-parameters($service, fp:service-callback-names($service)[not(starts-with(., '/*'))], ')'),
          '{',
          fp:service-body($service, $realizing-class, '-&gt;'),
          '}'),
        for $client in $node/r:service-client[xs:boolean(@forward)] return (
          '',
          fp:client-method($client, concat($class, '::')),
          '{',
          if (fp:is-own-service($client)) then fp:ros2-own-call($client, $node) else (
          '  // asynchronous: a node must not wait for a service inside its own callback; the call is sent',
          concat('  if (!', $client/@member, '-&gt;service_is_ready()) {'),
          fp:fit(4, 'RCLCPP_WARN(', 'get_logger(), &quot;service %s (' || $client/@service || ') is not available&quot;, '
                 || $client/@member || '-&gt;get_service_name());'),
          if (xs:boolean($client/@returns-bool)) then '    return false;' else '    return;',
          '  }',
          concat('  auto request = std::make_shared&lt;', fp:ros2-type($client/@srv, $node/@namespace, 'srv')[2], '::Request&gt;();'),
          $client/@argument ! concat('  request-&gt;data = ', ., ';'),
          concat('  ', $client/@member, '-&gt;async_send_request(request);'),
          if (xs:boolean($client/@returns-bool)) then '  return true;  // sent (the answer is not awaited)' else ()),
          '}'))"/>
  </xsl:function>

  <!-- the line that opens the declaration of node class $class, a $base
       and the realizing class $rc: both bases on it when it fits in 100
       columns, else the second on the next line -->
  <xsl:function name="fp:class-line" as="xs:string+">
    <xsl:param name="class" as="xs:string"/>
    <xsl:param name="base" as="xs:string"/>
    <xsl:param name="rc" as="xs:string"/>
    <xsl:variable name="line" as="xs:string" select="'class ' || $class || ' : public ' || $base || ', public ' || $rc"/>
    <xsl:sequence select="if (string-length($line) le 100) then $line
                          else ('class ' || $class || ' : public ' || $base || ',', '  public ' || $rc)"/>
  </xsl:function>

  <!-- the parameters of the callback of $service, a line each after the
       line that opens them, indented by 2: (request, response), each named
       when in $names (a callback names only those it uses), $end after -->
  <xsl:function name="fp:ros2-service-parameters" as="xs:string+">
    <xsl:param name="service" as="element(r:service)"/>
    <xsl:param name="names" as="xs:string*"/>
    <xsl:param name="end" as="xs:string"/>
    <xsl:variable name="srv" as="xs:string" select="fp:ros2-type($service/@srv, $service/../@namespace, 'srv')[2]"/>
    <xsl:sequence select="'  const std::shared_ptr&lt;' || $srv || '::Request&gt;' || ' request'[$names = 'request'] || ',',
                          '  std::shared_ptr&lt;' || $srv || '::Response&gt;' || ' response'[$names = 'response'] || $end"/>
  </xsl:function>

  <!-- the body of the method that calls $client, a service of the
       package's own: the request sent, never awaited (a node must not wait
       inside its own callback); the answer, when it comes, kept under the
       node's mutex: the method returns the latest answer received (the
       result type's default until the first) -->
  <xsl:function name="fp:ros2-own-call" as="xs:string+">
    <xsl:param name="client" as="element(r:service-client)"/>
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="srv" as="xs:string" select="fp:ros2-type($client/@srv, $node/@namespace, 'srv')[2]"/>
    <xsl:variable name="answer" as="xs:string" select="'answer_' || $client/@name || '_'"/>
    <xsl:variable name="send" as="xs:string+" select="
        '  auto request_msg = std::make_shared&lt;' || $srv || '::Request&gt;();',
        $client/r:argument ! fp:to-msg(r:message, 'request_msg-&gt;' || @field, @name) ! ('  ' || .),
        if ($client/r:result)
        then ('  ' || $client/@member || '-&gt;async_send_request(',
              '    request_msg, [this](rclcpp::Client&lt;' || $srv || '&gt;::SharedFuture future) {',
              '      std::lock_guard&lt;std::mutex&gt; lock(answers_mutex_);',
              '      ' || $answer || ' = ' || fp:from-msg($client/r:result/r:message, 'future.get()-&gt;' || $client/r:result/@field) || ';',
              '    });')
        else '  ' || $client/@member || '-&gt;async_send_request(request_msg);'"/>
    <xsl:variable name="unavailable" as="xs:string+"
        select="fp:fit(4, 'RCLCPP_WARN(', 'get_logger(), &quot;service %s (' || $client/@service || ') is not available&quot;, '
                || $client/@member || '-&gt;get_service_name());')"/>
    <xsl:sequence select="
        '  // asynchronous: a node must not wait for a service inside its own callback; the call is sent',
        $client/r:result ! '  // and the latest answer received is returned (the default until the first)',
        '  if (!' || $client/@member || '-&gt;service_is_ready()) {',
        $unavailable,
        if ($client/r:result)
        then ('  } else {', fp:indent(2, $send), '  }', '  std::lock_guard&lt;std::mutex&gt; lock(answers_mutex_);', '  return ' || $answer || ';')
        else ('    return;', '  }', $send)"/>
  </xsl:function>

  <xsl:function name="fp:ros2-main" as="xs:string">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:cpp-xsl, fp:what($node), false()),
        '#include &lt;memory&gt;',
        '',
        concat('#include &quot;', $node/@namespace, '/', $node/@class, '.hpp&quot;'),
        '',
        'int main(int argc, char ** argv)',
        '{',
        '  rclcpp::init(argc, argv);',
        concat('  rclcpp::spin(std::make_shared&lt;', $node/@type-name, '&gt;());'),
        '  rclcpp::shutdown();',
        '  return 0;',
        '}'))"/>
  </xsl:function>
</xsl:stylesheet>
