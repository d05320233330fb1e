<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros1/ros1-jobs.xsl - the job coordinator of each subsystem of the
  ROS 1 package (seed 004 §4.3, docs/jobs.md, docs/ros.md "Jobs").

  Reads:   r:coordinator of urn:robomda:psm-ros:1 (ros-version 1).
  Writes:  strings (file contents), wrapped into fs:file by main.xsl.
  Params:  none.  Errors: none (the PSM stage warns JOB050: ROS 1 has no
           node lifecycle).
  Uses:    ../ros-common/ros-jobs.xsl (tables, event loop), ros1-launch.xsl
           (fp:ros1-node, fp:ros1-machines).

  src/<subsystem>_coordinator.cpp: node <subsystem>_coordinator. ROS 1 has
  no node lifecycle, so what a switch does is done with processes and the
  parameter server:
    stop         the node is shut down through its slave API (shutdown,
                 as rosnode kill does; the master gives its URI), and the
                 coordinator waits until the master no longer knows it
    reconfigure  its values set on the parameter server (its private
                 names), then its ~reload_parameters service (std_srvs/
                 Empty) reads them into the atomic code while it runs
    start        roslaunch of launch/<model>_<job>_<instance>.launch, a
                 child process of the coordinator: the node with its
                 parameter files, the job's values and the user's file
                 (last: a tuned value wins); the coordinator waits until the
                 master knows the node
    keep         nothing: its process is never touched
  The host's launch file starts the initial job (the jobs' other instances
  are in no launch file but their job's); the coordinator waits until
  every member of it is registered, publishes the job on <subsystem>/job
  (std_msgs/String, latched), then takes events from <subsystem>/event
  (std_msgs/String, the event's name). On its own shutdown it stops the
  roslaunch processes it started (SIGINT, then SIGKILL after 20 s).
  Parameter ~timeout (s).

  launch/<model>_<job>_<instance>.launch: per instance a switch starts, for
  the job it starts in.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- the (job, instance) pairs a switch starts: a launch file each -->
  <xsl:function name="fp:ros1-job-starts" as="element(r:start)*">
    <xsl:param name="coordinator" as="element(r:coordinator)"/>
    <xsl:for-each-group select="$coordinator/r:transition/r:start" group-by="../@to || '_' || @instance">
      <xsl:sequence select="current-group()[1]"/>
    </xsl:for-each-group>
  </xsl:function>

  <xsl:function name="fp:ros1-job-launch-name" as="xs:string">
    <xsl:param name="start" as="element(r:start)"/>
    <xsl:sequence select="$start/ancestor::r:package/@deploy-name || '_' || $start/../@to || '_' || $start/@instance || '.launch'"/>
  </xsl:function>

  <!-- launch/<model>_<job>_<instance>.launch: the node a switch starts,
       with the job's values between its parameter file and the user's -->
  <xsl:function name="fp:ros1-job-launch" as="xs:string">
    <xsl:param name="start" as="element(r:start)"/>
    <xsl:variable name="package" as="element(r:package)" select="$start/ancestor::r:package"/>
    <xsl:variable name="i" as="element(r:instance)" select="fp:ros-job-instance($start/../.., $start/@instance)"/>
    <xsl:variable name="lines" as="xs:string+" select="fp:ros1-node($package, $i)"/>
    <xsl:sequence select="fp:lines((
        '&lt;?xml version=&quot;1.0&quot;?&gt;',
        '&lt;!--',
        fp:indent(2, fp:banner('', $fp:jobs-xsl, concat('instance ''', $i/@name, ''' in job ''', fp:xml-text($start/../@to),
             ''' of model ''', fp:xml-text($package/@model-name), ''''), false())),
        concat('  Started by the coordinator of subsystem ''', $start/../../@name, ''' when job ''', $start/../@to, ''' comes.'),
        '--&gt;',
        '&lt;launch&gt;',
        fp:ros1-machines($package/r:host[@name eq $i/@host]),
        (: the node's lines, the job's values before the user's file (the last rosparam) :)
        $lines[position() lt 4],
        if ($start/r:value) then (
          '    &lt;rosparam&gt;',
          $start/r:value ! fp:ros1-job-yaml(.),
          '    &lt;/rosparam&gt;') else (),
        $lines[position() ge 4],
        '&lt;/launch&gt;'))"/>
  </xsl:function>

  <!-- a value as a YAML line of the node's private namespace -->
  <xsl:function name="fp:ros1-job-yaml" as="xs:string">
    <xsl:param name="value" as="element(r:value)"/>
    <xsl:variable name="path" as="xs:string*" select="tokenize($value/@name, '\.')"/>
    <xsl:sequence select="'      ' || string-join($path, ': {') || ': ' || fp:xml-text($value/@yaml)
                          || string-join((2 to count($path)) ! '}')"/>
  </xsl:function>

  <xsl:function name="fp:ros1-coordinator" as="xs:string">
    <xsl:param name="coordinator" as="element(r:coordinator)"/>
    <xsl:variable name="name" as="xs:string" select="$coordinator/@name"/>
    <xsl:variable name="package" as="element(r:package)" select="$coordinator/.."/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:jobs-xsl, concat('subsystem ''', $name, ''' of model ''', $package/@model-name, ''''), false()),
        '//',
        concat('// The job coordinator of subsystem ', $name, ' (seed 004): job ', $coordinator/@initial-job, ' runs first (its'),
        concat('// launch file starts it); then it switches jobs on the events of topic ', $name, '/event and'),
        concat('// publishes the job on ', $name, '/job. ROS 1 has no node lifecycle: nodes leave by shutting'),
        '// down and come as new processes (roslaunch of their launch file in the job).',
        '',
        '#include &lt;signal.h&gt;',
        '#include &lt;spawn.h&gt;',
        '#include &lt;sys/wait.h&gt;',
        '',
        '#include &lt;algorithm&gt;',
        '#include &lt;chrono&gt;',
        '#include &lt;deque&gt;',
        '#include &lt;functional&gt;',
        '#include &lt;map&gt;',
        '#include &lt;string&gt;',
        '#include &lt;thread&gt;',
        '#include &lt;utility&gt;',
        '#include &lt;vector&gt;',
        '',
        '#include &lt;ros/master.h&gt;',
        '#include &lt;ros/network.h&gt;',
        '#include &lt;ros/ros.h&gt;',
        '#include &lt;std_msgs/String.h&gt;',
        '#include &lt;std_srvs/Empty.h&gt;',
        '#include &lt;xmlrpcpp/XmlRpc.h&gt;',
        '',
        'extern char** environ;',
        '',
        fp:ros-job-tables($coordinator, '1'),
        '',
        'namespace',
        '{',
        '// the node name of each instance, and the launch file that starts it in a job',
        'const std::map&lt;std::string, std::string&gt; kNodes = {',
        distinct-values($coordinator/r:job/r:member/@instance)
          ! concat('  {', fp:cpp-string(.), ', ', fp:cpp-string(fp:ros1-node-name(fp:ros-job-instance($coordinator, .))), '},'),
        '};',
        'const std::map&lt;std::string, std::string&gt; kLaunchFiles = {',
        fp:ros1-job-starts($coordinator) ! concat('  {', fp:cpp-string(../@to || '/' || @instance), ', ',
                                                 fp:cpp-string(fp:ros1-job-launch-name(.)), '},'),
        '};',
        concat('const char* const kPackage = ', fp:cpp-string($package/@name), ';'),
        '',
        '// the slave URI the master has for node `name`, or &quot;&quot;',
        'std::string lookup(const std::string&amp; name)',
        '{',
        '  XmlRpc::XmlRpcValue request, response, payload;',
        '  request[0] = ros::this_node::getName();',
        '  request[1] = name;',
        '  if (!ros::master::execute(&quot;lookupNode&quot;, request, response, payload, false)) {',
        '    return &quot;&quot;;',
        '  }',
        '  return static_cast&lt;std::string&gt;(payload);',
        '}',
        '',
        '// waits until the master knows node `name` (or, `gone`, no longer knows it)',
        'bool wait_for(const std::string&amp; name, bool gone, double timeout)',
        '{',
        '  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);',
        '  while (ros::ok() &amp;&amp; ros::WallTime::now() &lt; deadline) {',
        '    if (lookup(name).empty() == gone) {',
        '      return true;',
        '    }',
        '    std::this_thread::sleep_for(std::chrono::milliseconds(100));',
        '  }',
        '  ROS_ERROR(&quot;%s: %s after %.0f s&quot;, name.c_str(), gone ? &quot;still running&quot; : &quot;not registered&quot;, timeout);',
        '  return false;',
        '}',
        '',
        '// shuts node `name` down through its slave API (as rosnode kill does)',
        'bool shut_down(const std::string&amp; name, double timeout)',
        '{',
        '  const std::string uri = lookup(name);',
        '  std::string host;',
        '  uint32_t port = 0;',
        '  if (uri.empty() || !ros::network::splitURI(uri, host, port)) {',
        '    ROS_ERROR(&quot;%s: unknown to the master&quot;, name.c_str());',
        '    return false;',
        '  }',
        '  XmlRpc::XmlRpcClient client(host.c_str(), static_cast&lt;int&gt;(port), &quot;/&quot;);',
        '  XmlRpc::XmlRpcValue request, response;',
        '  request[0] = ros::this_node::getName();',
        '  request[1] = std::string(&quot;its job ended&quot;);',
        '  client.execute(&quot;shutdown&quot;, request, response);',
        '  client.close();',
        '  ROS_INFO(&quot;%s: shut down&quot;, name.c_str());',
        '  return wait_for(name, true, timeout);',
        '}',
        '',
        '// roslaunch of `file` of this package, a child process; 0 when it cannot start',
        'pid_t spawn(const std::string&amp; file)',
        '{',
        '  std::vector&lt;std::string&gt; words = {&quot;roslaunch&quot;, kPackage, file};',
        '  std::vector&lt;char*&gt; argv;',
        '  for (auto&amp; word : words) {',
        '    argv.push_back(&amp;word[0]);',
        '  }',
        '  argv.push_back(nullptr);',
        '  pid_t pid = 0;',
        '  if (posix_spawnp(&amp;pid, &quot;roslaunch&quot;, nullptr, nullptr, argv.data(), environ) != 0) {',
        '    return 0;',
        '  }',
        '  return pid;',
        '}',
        '}  // namespace',
        '',
        'int main(int argc, char** argv)',
        '{',
        concat('  ros::init(argc, argv, ', fp:cpp-string($coordinator/@node), ');'),
        '  ros::NodeHandle nh;',
        '  ros::NodeHandle private_nh(&quot;~&quot;);',
        '  double timeout = 30.0;',
        '  private_nh.param&lt;double&gt;(&quot;timeout&quot;, timeout, timeout);',
        '  std::vector&lt;pid_t&gt; children;',
        '  const auto run_switch = [&amp;](const Switch&amp; s) {',
        '    for (const auto&amp; instance : s.stop) {',
        '      if (!shut_down(kNodes.at(instance), timeout)) {',
        '        return false;',
        '      }',
        '    }',
        '    for (const auto&amp; member : s.reconfigure) {',
        '      const std::string name = kNodes.at(member.instance);',
        '      for (const auto&amp; value : member.values) {',
        '        value.second(name + &quot;/&quot; + value.first);',
        '      }',
        '      std_srvs::Empty reload;',
        '      if (!ros::service::waitForService(name + &quot;/reload_parameters&quot;, ros::Duration(timeout)) ||',
        '          !ros::service::call(name + &quot;/reload_parameters&quot;, reload)) {',
        '        ROS_ERROR(&quot;%s: reload_parameters did not answer&quot;, name.c_str());',
        '        return false;',
        '      }',
        '      ROS_INFO(&quot;%s: %zu values reloaded&quot;, name.c_str(), member.values.size());',
        '    }',
        '    for (const auto&amp; member : s.start) {',
        '      // its values are in its launch file, between its parameters and the user''s',
        '      const std::string file = kLaunchFiles.at(s.to + &quot;/&quot; + member.instance);',
        '      const pid_t pid = spawn(file);',
        '      if (pid == 0) {',
        '        ROS_ERROR(&quot;roslaunch %s %s could not start&quot;, kPackage, file.c_str());',
        '        return false;',
        '      }',
        '      children.push_back(pid);',
        '      if (!wait_for(kNodes.at(member.instance), false, timeout)) {',
        '        return false;',
        '      }',
        '      ROS_INFO(&quot;%s: started (roslaunch %s)&quot;, kNodes.at(member.instance).c_str(), file.c_str());',
        '    }',
        '    return true;',
        '  };',
        concat('  ros::Publisher job_publisher = nh.advertise&lt;std_msgs::String&gt;(', fp:cpp-string($name || '/job'), ', 1, true);'),
        '  const auto publish_job = [&amp;](const std::string&amp; name) {',
        '    std_msgs::String message;',
        '    message.data = name;',
        '    job_publisher.publish(message);',
        '  };',
        '  std::deque&lt;std::string&gt; events;',
        concat('  ros::Subscriber event_subscriber = nh.subscribe&lt;std_msgs::String&gt;(', fp:cpp-string($name || '/event'), ', 10,'),
        '    [&amp;events](const std_msgs::String::ConstPtr&amp; message) { events.push_back(message-&gt;data); });',
        '  std::string job = kInitialJob;',
        '  for (const auto&amp; instance : kJobs.at(job)) {',
        '    if (!wait_for(kNodes.at(instance), false, timeout)) {',
        '      ROS_ERROR(&quot;initial job %s: %s did not come up&quot;, job.c_str(), kNodes.at(instance).c_str());',
        '      return 1;',
        '    }',
        '  }',
        '  ROS_INFO(&quot;job %s active&quot;, job.c_str());',
        '  publish_job(job);',
        fp:ros-job-event-loop('ros::ok()', 'ros::spinOnce(); while (waitpid(-1, nullptr, WNOHANG) &gt; 0) {}', 'ROS_INFO(', 'ROS_WARN(', 'ROS_ERROR(',
                              'run_switch(*found)', 'publish_job(job)'),
        '  // the roslaunch processes it started end with it',
        '  for (const pid_t pid : children) {',
        '    kill(pid, SIGINT);',
        '  }',
        '  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);',
        '  for (const pid_t pid : children) {',
        '    while (waitpid(pid, nullptr, WNOHANG) == 0 &amp;&amp; std::chrono::steady_clock::now() &lt; deadline) {',
        '      std::this_thread::sleep_for(std::chrono::milliseconds(100));',
        '    }',
        '    if (waitpid(pid, nullptr, WNOHANG) == 0) {',
        '      kill(pid, SIGKILL);',
        '      waitpid(pid, nullptr, 0);',
        '    }',
        '  }',
        '  return 0;',
        '}'))"/>
  </xsl:function>

  <!-- the node name of instance $i, from the root -->
  <xsl:function name="fp:ros1-node-name" as="xs:string">
    <xsl:param name="i" as="element(r:instance)"/>
    <xsl:sequence select="if ($i/@namespace) then concat('/', $i/@namespace, '/', $i/@node-name) else concat('/', $i/@name)"/>
  </xsl:function>

  <!-- the coordinator's node in its host's launch file -->
  <xsl:function name="fp:ros1-coordinator-node" as="xs:string+">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="coordinator" as="element(r:coordinator)"/>
    <xsl:sequence select="
        '',
        concat('  &lt;!-- subsystem ''', fp:xml-text($coordinator/@name), ''': job ''', fp:xml-text($coordinator/@initial-job),
               ''' runs first; its coordinator switches jobs on topic ', fp:xml-text($coordinator/@name), '/event --&gt;'),
        concat('  &lt;node pkg=&quot;', $package/@name, '&quot; type=&quot;', $coordinator/@executable, '&quot; name=&quot;',
               $coordinator/@node, '&quot; machine=&quot;', fp:xml-text($coordinator/@host), '&quot; output=&quot;screen&quot;/&gt;')"/>
  </xsl:function>
</xsl:stylesheet>
