<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros2/ros2-jobs.xsl - the job coordinator of each subsystem of the
  ROS 2 package (seed 004 §4.3, docs/jobs.md, docs/ros.md "Jobs").

  Reads:   r:coordinator of urn:robomda:psm-ros:1 (ros-version 2).
  Writes:  strings (file contents), wrapped into fs:file by main.xsl.
  Params:  none.  Errors: none.
  Uses:    ../ros-common/ros-jobs.xsl (tables, event loop),
           ros2-lifecycle.xsl (fp:ros2-change-state), ros2-launch.xsl
           (fp:ros-fqn).

  src/<subsystem>_coordinator.cpp: node <subsystem>_coordinator. The jobs'
  instances are lifecycle nodes loaded unconfigured; the coordinator
  configures, then activates, each member of the initial job in start
  order (a configuration constant's writer is active before its reader
  configures), publishes the job on <subsystem>/job (std_msgs/String,
  transient local) and then takes events from <subsystem>/event
  (std_msgs/String, the event's name). A switch:
    stop         deactivate, then cleanup (reverse start order): the node
                 is unconfigured, as before its first job
    reconfigure  its values set through its parameter service while it
                 stays active (the node's parameter callback writes them
                 into the atomic code; configure() does not run again)
    start        its values set, then configure and activate (start order)
    keep         nothing: never leaves Active
  An event with no switch from the current job is logged and ignored; a
  failed step stops the switch (ERROR naming node and transition) and the
  job stays the one it was. It runs in the namespace its launch file
  pushed, and prefixes it to each node's name. Parameter: timeout (s).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:ros2-coordinator" as="xs:string">
    <xsl:param name="coordinator" as="element(r:coordinator)"/>
    <xsl:variable name="name" as="xs:string" select="$coordinator/@name"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:jobs-xsl, concat('subsystem ''', $name, ''' of model ''', $coordinator/../@model-name, ''''), false()),
        '//',
        concat('// The job coordinator of subsystem ', $name, ' (seed 004): starts job ', $coordinator/@initial-job, ', then'),
        concat('// switches jobs on the events of topic ', $name, '/event and publishes the job on ', $name, '/job.'),
        '',
        '#include &lt;algorithm&gt;',
        '#include &lt;chrono&gt;',
        '#include &lt;cstdint&gt;',
        '#include &lt;deque&gt;',
        '#include &lt;map&gt;',
        '#include &lt;memory&gt;',
        '#include &lt;string&gt;',
        '#include &lt;thread&gt;',
        '#include &lt;vector&gt;',
        '',
        '#include &lt;lifecycle_msgs/msg/transition.hpp&gt;',
        '#include &lt;lifecycle_msgs/srv/change_state.hpp&gt;',
        '#include &lt;rclcpp/rclcpp.hpp&gt;',
        '#include &lt;std_msgs/msg/string.hpp&gt;',
        '',
        fp:ros2-change-state(),
        '',
        fp:ros-job-tables($coordinator, '2'),
        '',
        'namespace',
        '{',
        '// the fully qualified name of each instance',
        'const std::map&lt;std::string, std::string&gt; kNodes = {',
        distinct-values($coordinator/r:job/r:member/@instance)
          ! concat('  {', fp:cpp-string(.), ', ', fp:cpp-string(fp:ros-fqn(fp:ros-job-instance($coordinator, .))), '},'),
        '};',
        '',
        '// sets the values of node `target` through its parameter service',
        'bool set_values(',
        '  const rclcpp::Node::SharedPtr &amp; node, const std::string &amp; target,',
        '  const std::vector&lt;rclcpp::Parameter&gt; &amp; values, std::chrono::seconds timeout)',
        '{',
        '  if (values.empty()) {',
        '    return true;',
        '  }',
        '  auto client = std::make_shared&lt;rclcpp::AsyncParametersClient&gt;(node, target);',
        '  if (!client-&gt;wait_for_service(timeout)) {',
        '    RCLCPP_ERROR(node-&gt;get_logger(), &quot;%s: no parameter service&quot;, target.c_str());',
        '    return false;',
        '  }',
        '  auto future = client-&gt;set_parameters(values);',
        '  const auto answer = rclcpp::spin_until_future_complete(node, future, timeout);',
        '  if (answer != rclcpp::FutureReturnCode::SUCCESS) {',
        '    RCLCPP_ERROR(node-&gt;get_logger(), &quot;%s: setting parameters did not answer&quot;, target.c_str());',
        '    return false;',
        '  }',
        '  for (const auto &amp; result : future.get()) {',
        '    if (!result.successful) {',
        '      RCLCPP_ERROR(',
        '        node-&gt;get_logger(), &quot;%s: a parameter was refused: %s&quot;, target.c_str(),',
        '        result.reason.c_str());',
        '      return false;',
        '    }',
        '  }',
        '  RCLCPP_INFO(node-&gt;get_logger(), &quot;%s: %zu values set&quot;, target.c_str(), values.size());',
        '  return true;',
        '}',
        '',
        '// what a switch needs: the coordinator''s node, the namespace of the nodes, the timeout',
        'struct Context',
        '{',
        '  rclcpp::Node::SharedPtr node;',
        '  std::string prefix;',
        '  std::chrono::seconds timeout;',
        '};',
        '',
        '// asks instance `instance` for `transition`',
        'bool change(',
        '  const Context &amp; c, const std::string &amp; instance, std::uint8_t transition, const char * label)',
        '{',
        '  return change_state(c.node, c.prefix + kNodes.at(instance), transition, label, c.timeout);',
        '}',
        '',
        '// sets the values of instance `instance`',
        'bool set_values_of(',
        '  const Context &amp; c, const std::string &amp; instance, const std::vector&lt;rclcpp::Parameter&gt; &amp; values)',
        '{',
        '  return set_values(c.node, c.prefix + kNodes.at(instance), values, c.timeout);',
        '}',
        '',
        '// stops, reconfigures, then starts the instances of switch s; false when a step fails',
        'bool run_switch(const Context &amp; c, const Switch &amp; s)',
        '{',
        '  for (const auto &amp; instance : s.stop) {',
        '    if (!change(c, instance, Transition::TRANSITION_DEACTIVATE, &quot;deactivate&quot;) ||',
        '      !change(c, instance, Transition::TRANSITION_CLEANUP, &quot;cleanup&quot;))',
        '    {',
        '      return false;',
        '    }',
        '  }',
        '  for (const auto &amp; member : s.reconfigure) {',
        '    if (!set_values_of(c, member.instance, member.values)) {',
        '      return false;',
        '    }',
        '  }',
        '  for (const auto &amp; member : s.start) {',
        '    if (!set_values_of(c, member.instance, member.values) ||',
        '      !change(c, member.instance, Transition::TRANSITION_CONFIGURE, &quot;configure&quot;) ||',
        '      !change(c, member.instance, Transition::TRANSITION_ACTIVATE, &quot;activate&quot;))',
        '    {',
        '      return false;',
        '    }',
        '  }',
        '  return true;',
        '}',
        '',
        '// publishes job `name` on the subsystem''s job topic',
        'void publish_job(',
        '  const rclcpp::Publisher&lt;std_msgs::msg::String&gt;::SharedPtr &amp; publisher, const std::string &amp; name)',
        '{',
        '  std_msgs::msg::String message;',
        '  message.data = name;',
        '  publisher-&gt;publish(message);',
        '}',
        '}  // namespace',
        '',
        'int main(int argc, char ** argv)',
        '{',
        '  rclcpp::init(argc, argv);',
        concat('  auto node = std::make_shared&lt;rclcpp::Node&gt;(', fp:cpp-string($coordinator/@node), ');'),
        '  // in the namespace a launch file pushed: so are the nodes it switches',
        '  const std::string prefix =',
        '    std::string(node-&gt;get_namespace()) == &quot;/&quot; ? &quot;&quot; : node-&gt;get_namespace();',
        '  const std::chrono::seconds timeout(node-&gt;declare_parameter&lt;std::int64_t&gt;(&quot;timeout&quot;, 30));',
        '  const Context context{node, prefix, timeout};',
        '  auto job_publisher = node-&gt;create_publisher&lt;std_msgs::msg::String&gt;(',
        concat('    ', fp:cpp-string($name || '/job'), ', rclcpp::QoS(rclcpp::KeepLast(1)).reliable().transient_local());'),
        '  std::deque&lt;std::string&gt; events;',
        '  auto event_subscription = node-&gt;create_subscription&lt;std_msgs::msg::String&gt;(',
        concat('    ', fp:cpp-string($name || '/event'), ', rclcpp::QoS(rclcpp::KeepLast(10)).reliable(),'),
        '    [&amp;events](std_msgs::msg::String::ConstSharedPtr message) {events.push_back(message-&gt;data);});',
        '  std::string job = kInitialJob;',
        '  for (const auto &amp; instance : kJobs.at(job)) {',
        '    if (!change(context, instance, Transition::TRANSITION_CONFIGURE, &quot;configure&quot;) ||',
        '      !change(context, instance, Transition::TRANSITION_ACTIVATE, &quot;activate&quot;))',
        '    {',
        '      RCLCPP_ERROR(node-&gt;get_logger(), &quot;initial job %s failed&quot;, job.c_str());',
        '      rclcpp::shutdown();',
        '      return 1;',
        '    }',
        '  }',
        '  RCLCPP_INFO(node-&gt;get_logger(), &quot;job %s active&quot;, job.c_str());',
        '  publish_job(job_publisher, job);',
        fp:ros-job-event-loop('rclcpp::ok()', 'rclcpp::spin_some(node)', 'RCLCPP_INFO(node-&gt;get_logger(), ',
                              'RCLCPP_WARN(node-&gt;get_logger(), ', 'RCLCPP_ERROR(node-&gt;get_logger(), ',
                              'run_switch(context, *found)', 'publish_job(job_publisher, job)'),
        '  rclcpp::shutdown();',
        '  return 0;',
        '}'))"/>
  </xsl:function>

  <!-- the coordinator's node in its host's launch file: after the pushed
       namespace, like the nodes it switches -->
  <xsl:function name="fp:ros2-coordinator-node" as="xs:string+">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="coordinator" as="element(r:coordinator)"/>
    <xsl:sequence select="
        concat('  &lt;!-- subsystem ''', fp:xml-text($coordinator/@name), ''': its coordinator starts job ''',
               fp:xml-text($coordinator/@initial-job), ''' and switches jobs on topic ', fp:xml-text($coordinator/@name), '/event --&gt;'),
        concat('  &lt;node pkg=&quot;', $package/@name, '&quot; exec=&quot;', $coordinator/@executable, '&quot; name=&quot;',
               $coordinator/@node, '&quot; output=&quot;screen&quot;/&gt;')"/>
  </xsl:function>
</xsl:stylesheet>
