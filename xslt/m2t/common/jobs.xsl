<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/common/jobs.xsl - the C++ tables every generated job coordinator
  runs (seed 004 §4.3, docs/jobs.md): ROS 1, ROS 2 (ros-common/ros-jobs.xsl)
  and OpenRTM (openrtm/openrtm-jobs.xsl).

  Reads:   a coordinator element of a PSM, in any namespace (psm-ros,
           psm-openrtm): @initial-job, job/member/@instance, and per
           transition @from, @event, @to and its stop, reconfigure, start and
           keep children (@instance, value children).
  Writes:  strings (C++ lines).
  Params:  none.  Errors: none.
  Hook:    mode m:job-value: the including target renders one value element
           of a reconfigure / start as a C++ initialiser of $value-type (param
           version: the target's flavour, e.g. the ROS version); no default.

    fp:job-tables($coordinator, $value-type, $version)  in an anonymous
        namespace: struct Member (an instance and the values set before it is
        reconfigured or started), struct Switch (from, event, to; the
        instances to stop, in reverse start order, to reconfigure, to start,
        in start order, and to keep), kInitialJob, kJobs (each job's members
        in start order) and kSwitches (one per transition)
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:m="urn:robomda:xslt:mode"
    exclude-result-prefixes="#all">

  <xsl:mode name="m:job-value" on-no-match="fail"/>

  <xsl:function name="fp:job-tables" as="xs:string+">
    <xsl:param name="coordinator" as="element()"/>
    <xsl:param name="value-type" as="xs:string"/>
    <xsl:param name="version" as="xs:string"/>
    <xsl:sequence select="
        'namespace',
        '{',
        '// an instance a switch reconfigures or starts, with the values it sets first',
        'struct Member',
        '{',
        '  std::string instance;',
        concat('  std::vector&lt;', $value-type, '&gt; values;'),
        '};',
        '',
        '// a transition of the subsystem: on event, from job from to job to',
        'struct Switch',
        '{',
        '  std::string from;',
        '  std::string event;',
        '  std::string to;',
        '  std::vector&lt;std::string&gt; stop;  // in reverse start order',
        '  std::vector&lt;Member&gt; reconfigure;',
        '  std::vector&lt;Member&gt; start;  // in start order',
        '  std::vector&lt;std::string&gt; keep;  // never stopped',
        '};',
        '',
        concat('const char * const kInitialJob = ', fp:cpp-string($coordinator/@initial-job), ';'),
        '',
        '// the members of each job, in start order',
        'const std::map&lt;std::string, std::vector&lt;std::string&gt;&gt; kJobs = {',
        $coordinator/*:job ! concat('  {', fp:cpp-string(@name), ', {', string-join(*:member ! fp:cpp-string(@instance), ', '), '}},'),
        '};',
        '',
        'const std::vector&lt;Switch&gt; kSwitches = {',
        for $t in $coordinator/*:transition return (
          concat('  {', fp:cpp-string($t/@from), ', ', fp:cpp-string($t/@event), ', ', fp:cpp-string($t/@to), ','),
          concat('    {', string-join($t/*:stop ! fp:cpp-string(@instance), ', '), '},'),
          concat('    {', string-join($t/*:reconfigure ! fp:job-member(., $version), ', '), '},'),
          concat('    {', string-join($t/*:start ! fp:job-member(., $version), ', '), '},'),
          concat('    {', string-join($t/*:keep ! fp:cpp-string(@instance), ', '), '}},')),
        '};',
        '}  // namespace'"/>
  </xsl:function>

  <!-- {"instance", {value, ...}}: each value as the target renders it -->
  <xsl:function name="fp:job-member" as="xs:string">
    <xsl:param name="switched" as="element()"/>
    <xsl:param name="version" as="xs:string"/>
    <xsl:variable name="values" as="xs:string*">
      <xsl:apply-templates select="$switched/*:value" mode="m:job-value">
        <xsl:with-param name="version" select="$version"/>
      </xsl:apply-templates>
    </xsl:variable>
    <xsl:sequence select="'{' || fp:cpp-string($switched/@instance) || ', {' || string-join($values, ', ') || '}}'"/>
  </xsl:function>
</xsl:stylesheet>
