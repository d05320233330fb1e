<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros2/ros2-lifecycle.xsl - C++ of the managed (lifecycle) nodes of
  the ROS 2 package and of the lifecycle manager that drives them.

  Reads:   r:package / r:node of urn:robomda:psm-ros:1 (ros-version 2):
           r:node/@lifecycle-type-name, r:instance/@managed,
           r:host/@lifecycle-manager (xslt/m2m/ros/psm.xsl, N8).
  Writes:  strings (file contents), wrapped into fs:file by main.xsl.
  Params:  none.  Errors: none.
  Uses:    ros2-cpp.xsl (includes, members, parameters, hook calls,
           entities, timer, callbacks: shared with the plain node class).

  Per node with a managed instance: include/<pkg>/lifecycle/<Class>.hpp and
  src/lifecycle/<Class>.cpp, class <pkg>::lifecycle::<Class> deriving from
  rclcpp_lifecycle::LifecycleNode and the realizing class, registered as a
  component. The realizing class's hooks follow the managed lifecycle
  (design.ros2.org "Managed nodes"), as the Orocos target's TaskContext
  states do:
    constructor   parameters declared (the model default, the YAML value)
    on_configure  configure(); publishers, subscriptions, services, clients
    on_activate   publishers activated; start(); the timer
    on_deactivate the timer cancelled; stop(); publishers deactivated
    on_cleanup    cleanup(); every entity released
    on_shutdown   stop() if active, cleanup() if configured
    destructor    the shutdown transition if not finalized and the
                  context is still valid (rclcpp after Jazzy warns of a
                  lifecycle node destroyed unfinalized; after Ctrl-C the
                  context is gone and a transition would log errors), then
                  stop() / cleanup() if that transition could not run
  A hook that returns false fails its transition (the node stays where it
  was). on_configure first reads each configuration constant («Constant»
  input) once (fp:ros2-read-constants). A node whose values a job switch
  sets (ros2-jobs.xsl) writes each parameter set into the atomic code at
  once (a post-set parameters callback). step() runs only while active (running_), so nothing is published
  and update() is not called otherwise.

  src/lifecycle_manager.cpp (when an instance is managed): a node that takes
  the fully qualified names of managed nodes (parameter node_names, in the
  deployment sequence), waits for each one's change_state service, then
  configures them all and activates them in that order through
  lifecycle_msgs/srv/ChangeState; it exits 0 when all are active and 1
  naming the node and transition that failed or timed out (parameter
  timeout, seconds). Each host's launch file starts one (ros2-launch.xsl).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:ros2-lifecycle-header" as="xs:string">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="class" as="xs:string" select="$node/@class"/>
    <xsl:variable name="package" as="xs:string" select="$node/@namespace"/>
    <xsl:variable name="guard" as="xs:string" select="fp:guard($package || '/lifecycle', $class)"/>
    <xsl:variable name="rc" as="xs:string" select="$node/r:realizing-class/@cpp-name"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:lifecycle-xsl, fp:what($node), false()),
        concat('#ifndef ', $guard), concat('#define ', $guard),
        '',
        fp:ros2-includes($node, '&lt;vector&gt;'[fp:ros-switched($node)],
                         ('rclcpp_lifecycle/lifecycle_node.hpp', 'rclcpp_lifecycle/lifecycle_publisher.hpp')),
        '',
        concat('namespace ', $package), '{',
        'namespace lifecycle', '{',
        '',
        '/**',
        concat(' * ', fp:doc-of($node, concat('ROS 2 node of component ', $node/@name, '.'))),
        concat(' * Managed (lifecycle) node wrapping the atomic code ', $rc, ' (seed 000, R1):'),
        ' * configure() when configured, start() when activated, stop() when deactivated,',
        ' * cleanup() when cleaned up; it publishes and runs update() only while active.',
        concat(' * A component (rclcpp_components) named ', $node/@lifecycle-type-name, '.'),
        ' */',
        fp:class-line($class, 'rclcpp_lifecycle::LifecycleNode', $rc),
        '{',
        'public:',
        '  using CallbackReturn = rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn;',
        '',
        concat('  explicit ', $class, '(const rclcpp::NodeOptions &amp; options = rclcpp::NodeOptions());'),
        concat('  ~', $class, '() override;'),
        '',
        ('configure', 'activate', 'deactivate', 'cleanup', 'shutdown')
          ! concat('  CallbackReturn on_', ., '(const rclcpp_lifecycle::State &amp; previous_state) override;'),
        fp:client-overrides($node),
        '',
        'private:',
        fp:ros2-members($node, 'rclcpp_lifecycle::LifecyclePublisher'),
        '  bool configured_;',
        if (fp:ros-switched($node))
        then ('  void on_parameters_set(const std::vector&lt;rclcpp::Parameter&gt; &amp; parameters);',
              '  rclcpp::node_interfaces::PostSetParametersCallbackHandle::SharedPtr post_set_parameters_;') else (),
        '};',
        '',
        '}  // namespace lifecycle',
        concat('}  // namespace ', $package),
        '',
        concat('#endif  // ', $guard)))"/>
  </xsl:function>

  <xsl:function name="fp:ros2-lifecycle-source" as="xs:string">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="class" as="xs:string" select="$node/@class"/>
    <xsl:variable name="package" as="xs:string" select="$node/@namespace"/>
    <xsl:variable name="publishers" as="element(r:port)*" select="$node/r:port[@direction eq 'out']"/>
    <xsl:variable name="rc" as="xs:string" select="$node/r:realizing-class/@cpp-name"/>
    <!-- stop() and cleanup() where a transition cannot fail: their result is not read -->
    <xsl:variable name="stop" as="xs:string*" select="$node/r:hook[@name eq 'stop'][@call] ! concat('    ', $rc, '::', @call, '();')"/>
    <xsl:variable name="cleanup" as="xs:string*" select="$node/r:hook[@name eq 'cleanup'][@call] ! concat('    ', $rc, '::', @call, '();')"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:lifecycle-xsl, fp:what($node), false()),
        concat('#include &lt;', $package, '/lifecycle/', $class, '.hpp&gt;'),
        '',
        '#include &lt;chrono&gt;',
        '#include &lt;cstdint&gt;',
        '#include &lt;functional&gt;',
        '#include &lt;lifecycle_msgs/msg/state.hpp&gt;',
        '#include &lt;rclcpp_components/register_node_macro.hpp&gt;',
        '',
        concat('namespace ', $package), '{',
        'namespace lifecycle', '{',
        '',
        concat($class, '::', $class, '(const rclcpp::NodeOptions &amp; options)'),
        concat(': rclcpp_lifecycle::LifecycleNode(', fp:cpp-string($node/@default-name), ', options),'),
        concat('  period_(', fp:double-literal($node/@period), '),'),
        '  running_(false),',
        '  configured_(false)',
        '{',
        fp:ros2-parameters($node),
        if (fp:ros-switched($node))
        then ('  // values a job switch sets (docs/jobs.md): into the atomic code at once, active or not',
              '  post_set_parameters_ = add_post_set_parameters_callback(',
              fp:fit(4, 'std::bind(', '&amp;' || $class || '::on_parameters_set, this, std::placeholders::_1));')) else (),
        '}',
        '',
        concat($class, '::~', $class, '()'),
        '{',
        '  // finalized before it goes (its container stopping): on_shutdown winds the atomic code down;',
        '  // not once the context has shut down (Ctrl-C): the transition could not publish its event',
        '  if (get_node_base_interface()-&gt;get_context()-&gt;is_valid() &amp;&amp;',
        '    get_current_state().id() != lifecycle_msgs::msg::State::PRIMARY_STATE_FINALIZED)',
        '  {',
        '    shutdown();',
        '  }',
        '  // and so here, where that transition could not run (the context already shut down)',
        fp:ros2-wind-down($stop, $cleanup),
        '}',
        fp:ros2-transition($class, 'configure', (fp:ros2-read-constants($node), fp:ros2-hook-calls($node, 'configure', true()), fp:ros2-entities($node),
                                                 '  configured_ = true;')),
        fp:ros2-transition($class, 'activate', ($publishers ! concat('  ', @member, '-&gt;on_activate();'),
                                                fp:ros2-hook-calls($node, 'start', true()),
                                                fp:ros-publish-constants($node, $publishers ! fp:ros2-type(r:message/@msg, $package, 'msg')[2],
                                                                         '-&gt;publish'),
                                                fp:ros2-timer($node), '  running_ = true;')),
        fp:ros2-transition($class, 'deactivate', ('  running_ = false;', '  if (timer_) {', '    timer_-&gt;cancel();', '  }',
                                                  fp:ros2-hook-calls($node, 'stop', true()),
                                                  $publishers ! concat('  ', @member, '-&gt;on_deactivate();'))),
        fp:ros2-transition($class, 'cleanup', (fp:ros2-hook-calls($node, 'cleanup', true()), fp:ros2-release($node),
                                               '  configured_ = false;')),
        fp:ros2-transition($class, 'shutdown', (fp:ros2-wind-down($stop, $cleanup), fp:ros2-release($node))),
        '',
        concat('void ', $class, '::step()'),
        '{',
        fp:ros-step($node, $publishers ! fp:ros2-type(r:message/@msg, $package, 'msg')[2], '-&gt;publish'),
        '}',
        fp:ros2-callbacks($node),
        if (fp:ros-switched($node)) then fp:ros2-post-set-parameters($node) else (),
        '',
        '}  // namespace lifecycle',
        concat('}  // namespace ', $package),
        '',
        concat('RCLCPP_COMPONENTS_REGISTER_NODE(', $node/@lifecycle-type-name, ')')))"/>
  </xsl:function>

  <!-- the parameter callback (a method) of a node whose values a job
       switch sets: each new value goes into the atomic code's member at
       once -->
  <xsl:function name="fp:ros2-post-set-parameters" as="xs:string+">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:sequence select="
        '',
        'void ' || $node/@class || '::on_parameters_set(const std::vector&lt;rclcpp::Parameter&gt; &amp; parameters)',
        '{',
        '  for (const auto &amp; parameter : parameters) {',
        for $k in 1 to count($node/r:parameter) return let $p := $node/r:parameter[$k] return (
          concat('    ', if ($k eq 1) then '' else '} else ', 'if (parameter.get_name() == ', fp:cpp-string($p/@name), ') {'),
          concat('      const auto value = parameter.get_value&lt;', $p/@param2, '&gt;();'),
          fp:parameter-assign($p, $p/@param2, 'RCLCPP_ERROR(get_logger(), ', 6)),
        if ($node/r:parameter) then '    }' else (),
        '  }',
        '}'"/>
  </xsl:function>

  <!-- on_configure: each configuration constant («Constant» input, seed
       004) read once before configure(), as Orocos reads it in
       configureHook: the latched (transient local) sample its writer
       published when it was activated, waited for up to 10 s on a
       subscription of its own outside the executor; none fails the
       transition -->
  <xsl:function name="fp:ros2-read-constants" as="xs:string*">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="rc" as="xs:string" select="$node/r:realizing-class/@cpp-name"/>
    <xsl:for-each select="$node/r:port[@direction eq 'in'][@constant = 'true']">
      <xsl:variable name="type" as="xs:string" select="fp:ros2-type(r:message/@msg, $node/@namespace, 'msg')[2]"/>
      <xsl:sequence select="
          concat('  {  // configuration constant ', @name, ': read before configure()'),
          '    rclcpp::SubscriptionOptions options;',
          '    options.callback_group = create_callback_group(',
          '      rclcpp::CallbackGroupType::MutuallyExclusive, false);',
          concat('    auto constant = create_subscription&lt;', $type, '&gt;('),
          concat('      ', fp:cpp-string(@topic), ', ', fp:ros2-qos(r:qos), ','),
          concat('      [](', $type, '::ConstSharedPtr) {}, options);'),
          '    rclcpp::WaitSet wait_set;',
          '    wait_set.add_subscription(constant);',
          concat('    auto msg = std::make_shared&lt;', $type, '&gt;();'),
          '    rclcpp::MessageInfo info;',
          '    if (wait_set.wait(std::chrono::seconds(10)).kind() != rclcpp::WaitResultKind::Ready ||',
          '      !constant-&gt;take(*msg, info))',
          '    {',
          '      RCLCPP_ERROR(get_logger(), &quot;no configuration constant on %s&quot;, constant-&gt;get_topic_name());',
          '      return CallbackReturn::FAILURE;',
          '    }',
          '    wait_set.remove_subscription(constant);',
          if (xs:boolean(@accessor-declared))
          then concat('    ', $rc, '::', @accessor, '(', fp:from-msg(r:message, '(*msg)'), ');')
          else concat('    (void)msg;  // ', ../r:realizing-class/@name, ' declares no ', @accessor, '()'),
          '  }'"/>
    </xsl:for-each>
  </xsl:function>

  <!-- a transition callback of class $class running $body, then succeeding -->
  <xsl:function name="fp:ros2-transition" as="xs:string+">
    <xsl:param name="class" as="xs:string"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:param name="body" as="xs:string*"/>
    <xsl:sequence select="'', fp:fit(0, $class || '::CallbackReturn ' || $class || '::on_' || $name || '(',
                                     'const rclcpp_lifecycle::State &amp;)'),
                          '{', $body, '  return CallbackReturn::SUCCESS;', '}'"/>
  </xsl:function>

  <!-- the timer stopped and stop() called if active, cleanup() if
       configured: destructor and shutdown, which cannot fail -->
  <xsl:function name="fp:ros2-wind-down" as="xs:string+">
    <xsl:param name="stop" as="xs:string*"/>
    <xsl:param name="cleanup" as="xs:string*"/>
    <xsl:sequence select="'  if (running_) {', '    running_ = false;', '    if (timer_) {', '      timer_-&gt;cancel();', '    }',
                          $stop, '  }', '  if (configured_) {', '    configured_ = false;', $cleanup, '  }'"/>
  </xsl:function>

  <!-- the lines that release a node's timer and entities -->
  <xsl:function name="fp:ros2-release" as="xs:string+">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:sequence select="'  timer_.reset();',
        ($node/r:port, $node/r:service, $node/r:service-client) ! concat('  ', @member, '.reset();')"/>
  </xsl:function>

  <xsl:function name="fp:ros2-lifecycle-manager" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:lifecycle-xsl, concat('the managed nodes of model ''', $package/@model-name, ''''), false()),
        '//',
        '// The lifecycle manager: configures the nodes named by parameter node_names,',
        '// then activates them, in that order (the deployment sequence), through their',
        '// change_state services; exits 0 when all are active, 1 when one fails.',
        '',
        '#include &lt;chrono&gt;',
        '#include &lt;cstdint&gt;',
        '#include &lt;memory&gt;',
        '#include &lt;string&gt;',
        '#include &lt;vector&gt;',
        '',
        '#include &lt;lifecycle_msgs/msg/transition.hpp&gt;',
        '#include &lt;lifecycle_msgs/srv/change_state.hpp&gt;',
        '#include &lt;rclcpp/rclcpp.hpp&gt;',
        '',
        fp:ros2-change-state(),
        '',
        'int main(int argc, char ** argv)',
        '{',
        '  rclcpp::init(argc, argv);',
        '  auto node = std::make_shared&lt;rclcpp::Node&gt;(&quot;lifecycle_manager&quot;);',
        '  const auto names = node-&gt;declare_parameter&lt;std::vector&lt;std::string&gt;&gt;(',
        '    &quot;node_names&quot;, std::vector&lt;std::string&gt;{});',
        '  const std::chrono::seconds timeout(node-&gt;declare_parameter&lt;std::int64_t&gt;(&quot;timeout&quot;, 30));',
        '  bool ok = true;',
        '  for (const auto &amp; name : names) {',
        '    ok = ok &amp;&amp; change_state(node, name, Transition::TRANSITION_CONFIGURE, &quot;configure&quot;, timeout);',
        '  }',
        '  for (const auto &amp; name : names) {',
        '    ok = ok &amp;&amp; change_state(node, name, Transition::TRANSITION_ACTIVATE, &quot;activate&quot;, timeout);',
        '  }',
        '  if (ok) {',
        '    RCLCPP_INFO(node-&gt;get_logger(), &quot;%zu managed nodes active&quot;, names.size());',
        '  }',
        '  rclcpp::shutdown();',
        '  return ok ? 0 : 1;',
        '}'))"/>
  </xsl:function>

  <!-- the manager's change_state(): one transition of one node, through its
       change_state service, waited for -->
  <xsl:function name="fp:ros2-change-state" as="xs:string+">
    <xsl:sequence select="
        'namespace',
        '{',
        'using lifecycle_msgs::msg::Transition;',
        'using lifecycle_msgs::srv::ChangeState;',
        '',
        '// asks node `target` (fully qualified) for `transition`; false when it refuses or does not answer',
        'bool change_state(',
        '  const rclcpp::Node::SharedPtr &amp; node, const std::string &amp; target, std::uint8_t transition,',
        '  const char * label, std::chrono::seconds timeout)',
        '{',
        '  auto client = node-&gt;create_client&lt;ChangeState&gt;(target + &quot;/change_state&quot;);',
        '  if (!client-&gt;wait_for_service(timeout)) {',
        '    RCLCPP_ERROR(',
        '      node-&gt;get_logger(), &quot;%s: no change_state service after %d s&quot;, target.c_str(),',
        '      static_cast&lt;int&gt;(timeout.count()));',
        '    return false;',
        '  }',
        '  auto request = std::make_shared&lt;ChangeState::Request&gt;();',
        '  request-&gt;transition.id = transition;',
        '  auto future = client-&gt;async_send_request(request);',
        '  const auto answer = rclcpp::spin_until_future_complete(node, future, timeout);',
        '  if (answer != rclcpp::FutureReturnCode::SUCCESS) {',
        '    RCLCPP_ERROR(node-&gt;get_logger(), &quot;%s: %s did not answer&quot;, target.c_str(), label);',
        '    return false;',
        '  }',
        '  if (!future.get()-&gt;success) {',
        '    RCLCPP_ERROR(node-&gt;get_logger(), &quot;%s: %s failed&quot;, target.c_str(), label);',
        '    return false;',
        '  }',
        '  RCLCPP_INFO(node-&gt;get_logger(), &quot;%s: %s&quot;, target.c_str(), label);',
        '  return true;',
        '}',
        '}  // namespace'
  "/>
  </xsl:function>
</xsl:stylesheet>
