<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros-common/ros-jobs.xsl - what the ROS 1 and ROS 2 job
  coordinators share (seed 004 §4.3, docs/jobs.md, docs/ros.md "Jobs").

  Reads:   r:coordinator of urn:robomda:psm-ros:1 (xslt/m2m/ros/jobs.xsl).
  Writes:  strings (C++ lines), used by ros1/ros1-jobs.xsl and
           ros2/ros2-jobs.xsl.
  Params:  none.  Errors: none.

    fp:ros-job-tables($coordinator, $version)  the C++ tables of a
        coordinator (m2t/common/jobs.xsl, with the template of mode
        m:job-value here): kInitialJob, kJobs (each job's members in start order)
        and kSwitches (per transition: from, event, to, the instances to
        stop, in reverse start order, to reconfigure and to start, with
        their values, and to keep), in an anonymous namespace; a value is
        an rclcpp::Parameter (ROS 2) or a setter of the parameter server
        (ROS 1)
    fp:ros-job-value($value, $version)  one value of that table
    fp:ros-job-event-loop($ok, $spin, $info, $warn, $error)  the
        coordinator's main loop: while $ok, it runs the callbacks ($spin),
        which queue the events of the event topic, runs the switch from the
        current job on each event (run_switch) and publishes the new job
        (publish_job); $info / $warn / $error open a log call
    fp:ros-job-instance($coordinator, $name)  the r:instance of that name
    fp:ros-switched($node)  whether a switch sets values on an instance of
        $node (it then takes them while it runs)
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:m="urn:robomda:xslt:mode"
    exclude-result-prefixes="#all">

  <xsl:key name="fp:ros-instance-by-name" match="r:package/r:instance" use="@name"/>
  <!-- the package's coordinators and a node's instances, looked up per
       node: through the node's parent they were a scan of every node and
       instance of the package per node (issue 35) -->
  <xsl:key name="fp:ros-coordinator" match="r:package/r:coordinator" use="'coordinator'"/>
  <xsl:key name="fp:ros-instance-of-node" match="r:package/r:instance" use="@node"/>

  <!-- true when a job coordinator sets values on an instance of $node
       (xslt/m2m/ros/jobs.xsl): it then writes them into the atomic code
       (ROS 2: a parameter callback; ROS 1: ~reload_parameters) -->
  <xsl:function name="fp:ros-switched" as="xs:boolean">
    <xsl:param name="node" as="element(r:node)"/>
    <!-- ROS 1 sets a starting node's values in its launch file: only a
         reconfigured one reloads them -->
    <xsl:sequence select="exists(key('fp:ros-coordinator', 'coordinator', root($node))/r:transition/*[r:value]
                                 [$node/../@ros-version eq '2' or self::r:reconfigure]/@instance
                                 [. = key('fp:ros-instance-of-node', string($node/@class), root($node))/@name])"/>
  </xsl:function>

  <xsl:function name="fp:ros-job-instance" as="element(r:instance)">
    <xsl:param name="coordinator" as="element(r:coordinator)"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:sequence select="key('fp:ros-instance-by-name', $name, root($coordinator))"/>
  </xsl:function>

  <!-- a value a switch sets: ROS 2 an rclcpp::Parameter of its declared
       type; ROS 1 the pair (private name, setter of the parameter server) -->
  <xsl:function name="fp:ros-job-value" as="xs:string">
    <xsl:param name="value" as="element(r:value)"/>
    <xsl:param name="version" as="xs:string"/>
    <xsl:variable name="type" as="xs:string" select="if ($version eq '2') then $value/@param2 else $value/@param1"/>
    <xsl:variable name="typed" as="xs:string"
        select="if (starts-with($value/@cpp, '{')) then $type || $value/@cpp else 'static_cast&lt;' || $type || '&gt;(' || $value/@cpp || ')'"/>
    <xsl:sequence select="if ($version eq '2') then 'rclcpp::Parameter(' || fp:cpp-string($value/@name) || ', ' || $typed || ')'
        else '{' || fp:cpp-string(translate($value/@name, '.', '/')) || ', [](const std::string &amp; key) { ros::param::set(key, '
             || $typed || '); }}'"/>
  </xsl:function>

  <xsl:function name="fp:ros-job-tables" as="xs:string+">
    <xsl:param name="coordinator" as="element(r:coordinator)"/>
    <xsl:param name="version" as="xs:string"/>
    <xsl:sequence select="fp:job-tables($coordinator, if ($version eq '2') then 'rclcpp::Parameter'
        else 'std::pair&lt;std::string, std::function&lt;void(const std::string&amp;)&gt;&gt;', $version)"/>
  </xsl:function>

  <!-- a value of the tables (m2t/common/jobs.xsl) -->
  <xsl:template match="r:value" mode="m:job-value" as="xs:string">
    <xsl:param name="version" as="xs:string"/>
    <xsl:sequence select="fp:ros-job-value(., $version)"/>
  </xsl:template>

  <!-- the main loop of a coordinator (after the initial job runs): $spin
       runs the callbacks, which queue the events; $run-switch (a call of
       found, the switch) and $publish-job (a call of job) are the version's
       own; the log statements $info, $warn and $error ("ROS_INFO(") broken
       where they would pass 100 columns -->
  <xsl:function name="fp:ros-job-event-loop" as="xs:string+">
    <xsl:param name="ok" as="xs:string"/>
    <xsl:param name="spin" as="xs:string"/>
    <xsl:param name="info" as="xs:string"/>
    <xsl:param name="warn" as="xs:string"/>
    <xsl:param name="error" as="xs:string"/>
    <xsl:param name="run-switch" as="xs:string"/>
    <xsl:param name="publish-job" as="xs:string"/>
    <xsl:sequence select="
        concat('  while (', $ok, ') {'),
        concat('    ', $spin, ';'),
        '    if (events.empty()) {',
        '      std::this_thread::sleep_for(std::chrono::milliseconds(50));',
        '      continue;',
        '    }',
        '    const std::string event = events.front();',
        '    events.pop_front();',
        '    const auto found = std::find_if(',
        '      kSwitches.begin(), kSwitches.end(),',
        '      [&amp;](const Switch &amp; s) {return s.from == job &amp;&amp; s.event == event;});',
        '    if (found == kSwitches.end()) {',
        fp:ros-log(6, $warn, '&quot;event %s: no switch from job %s&quot;, event.c_str(), job.c_str());'),
        '      continue;',
        '    }',
        '    if (!' || $run-switch || ') {',
        fp:ros-log(6, $error, '&quot;event %s: the switch from job %s to job %s failed&quot;, event.c_str(), job.c_str(), found-&gt;to.c_str());'),
        '      continue;',
        '    }',
        '    job = found-&gt;to;',
        fp:ros-log(4, $info, '&quot;job %s active (event %s)&quot;, job.c_str(), event.c_str());'),
        '    ' || $publish-job || ';',
        '  }'"/>
  </xsl:function>

  <!-- a log statement at $indent columns: macro and logger $log ("ROS_WARN(",
       "RCLCPP_WARN(node->get_logger(), "), then $rest (message, arguments
       and ");"), broken where it would pass 100 columns -->
  <xsl:function name="fp:ros-log" as="xs:string+">
    <xsl:param name="indent" as="xs:integer"/>
    <xsl:param name="log" as="xs:string"/>
    <xsl:param name="rest" as="xs:string"/>
    <xsl:sequence select="fp:fit($indent, substring-before($log, '(') || '(', substring-after($log, '(') || $rest)"/>
  </xsl:function>
</xsl:stylesheet>
