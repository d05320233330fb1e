<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros-common/ros-test.xsl - what the system tests of both ROS
  targets share (ros1/ros1-test.xsl: rostest; ros2/ros2-test.xsl:
  launch_testing): the tables the model fills and the Python helpers.

  Reads:   r:package of urn:robomda:psm-ros:1.
  Writes:  strings (lines of a Python test module).
  Params:  none.  Errors: none.
    fp:ros-test-tables($package)  NODES, CONNECTIONS, STATES, PARAMETER_FILES, TIMEOUT
    fp:ros-expected-state($i)     the lifecycle state a managed instance is in once up
    fp:ros-idle-at-start($i)      whether only jobs other than the initial one run it
    fp:ros-sends($t, $writer)     whether a topic's writer sends samples on its own
    fp:py-string($s), fp:py-bool($b)  Python literals
    $fp:ros-test-helpers          flat() and same(): parameter files and values compared
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- the tables of the test, after its imports: each instance's node,
       each connection (writer, its port, reader, its port, topic, whether
       samples are expected, reliable, latched), each managed instance's
       lifecycle state, each instance's parameter files in the order its
       launch file loads them -->
  <xsl:function name="fp:ros-test-tables" as="xs:string+">
    <xsl:param name="package" as="element(r:package)"/>
    <!-- what runs once the system is up: ROS 1 starts an instance only a
         job other than the initial one runs when that job starts; ROS 2
         loads it (unconfigured, without its topics) -->
    <xsl:variable name="instances" as="element(r:instance)*"
        select="$package/r:instance[$package/@ros-version ne '1' or not(fp:ros-idle-at-start(.))]"/>
    <xsl:sequence select="
        'PACKAGE = ' || fp:py-string($package/@name),
        '# the full name of each instance (relative to the namespace a launch file may push)',
        'NODES = {',
        $instances ! ('    ' || fp:py-string(@name) || ': ' || fp:py-string(fp:ros-fqn(.)) || ','),
        '}',
        '# (writer, its port, reader, its port, topic, samples expected, reliable, latched)',
        'CONNECTIONS = [',
        (: both ends in this package (not another middleware's) and running once the system is up :)
        for $t in $package/r:topic, $w in $t/r:writer[@instance = $instances/@name], $rd in $t/r:reader
        [@instance = $instances/@name][not(($w, .)/@instance = $package/r:instance[fp:ros-idle-at-start(.)]/@name)] return
          let $writer := $instances[@name eq $w/@instance],
              $from := fp:py-string($w/@instance) || ', ' || fp:py-string($w/@port),
              $to := fp:py-string($rd/@instance) || ', ' || fp:py-string($rd/@port),
              $flags := string-join((fp:ros-sends($t, $writer), $t/r:qos/@reliability eq 'reliable',
                                     ($t/r:qos/@durability eq 'transient_local' or $t/r:qos/@latch eq 'true')) ! fp:py-bool(.), ', '),
              $line := '    (' || string-join(($from, $to, fp:py-string($t/@name), $flags), ', ') || '),'
          return if (string-length($line) le 99) then $line
                 else ('    (' || $from || ',', '     ' || $to || ',', '     ' || fp:py-string($t/@name) || ',', '     ' || $flags || '),'),
        ']',
        '# the lifecycle state of each managed instance once the system is up',
        'STATES = {',
        for $i in $instances, $state in fp:ros-expected-state($i)
        return '    ' || fp:py-string($i/@name) || ': ' || fp:py-string($state) || ',',
        '}',
        '# the parameter files of each instance, in the order its launch file loads them',
        'PARAMETER_FILES = {',
        $instances ! ('    ' || fp:py-string(@name) || ': [' || fp:py-string(@name || '.yaml') || ', '
                      || fp:py-string(@name || '.user.yaml') || '],'),
        '}',
        'TIMEOUT = 30.0'"/>
  </xsl:function>

  <!-- a Python string literal (single quotes, as flake8-quotes wants) -->
  <xsl:function name="fp:py-string" as="xs:string">
    <xsl:param name="text" as="xs:string?"/>
    <xsl:sequence select="'''' || replace(replace(string($text), '\\', '\\\\'), '''', '\\''') || ''''"/>
  </xsl:function>

  <!-- a Python boolean -->
  <xsl:function name="fp:py-bool" as="xs:string">
    <xsl:param name="value" as="xs:boolean"/>
    <xsl:sequence select="if ($value) then 'True' else 'False'"/>
  </xsl:function>

  <!-- the lifecycle state instance $i is in once the system is up: active,
       unconfigured when only a job other than the initial one runs it, ()
       when it is not managed -->
  <xsl:function name="fp:ros-expected-state" as="xs:string?">
    <xsl:param name="i" as="element(r:instance)"/>
    <xsl:sequence select="if (not(xs:boolean(($i/@managed, 'false')[1]))) then ()
                          else if (fp:ros-idle-at-start($i)) then 'unconfigured' else 'active'"/>
  </xsl:function>

  <!-- true when only jobs other than the initial one run instance $i
       (docs/jobs.md): it does not run its ports once the system is up -->
  <xsl:function name="fp:ros-idle-at-start" as="xs:boolean">
    <xsl:param name="i" as="element(r:instance)"/>
    <xsl:variable name="jobs" as="element(r:job)*" select="$i/../r:coordinator/r:job[r:member/@instance = $i/@name]"/>
    <xsl:sequence select="exists($jobs) and not($jobs/../@initial-job = $jobs/@name)"/>
  </xsl:function>

  <!-- whether the writer of topic $t sends samples without being asked:
       its node publishes the port, and it runs periodically (or the port
       is a «Constant», published once and latched) and is not left
       unconfigured by a job -->
  <xsl:function name="fp:ros-sends" as="xs:boolean">
    <xsl:param name="t" as="element(r:topic)"/>
    <xsl:param name="writer" as="element(r:instance)?"/>
    <xsl:variable name="port" as="element(r:port)?"
        select="$writer/../r:node[@class eq $writer/@node]/r:port[@direction eq 'out'][@name eq $t/r:writer/@port]"/>
    <xsl:sequence select="exists($port) and xs:boolean($port/@accessor-declared)
                          and ($port/@constant = 'true' or $writer/@periodic = 'true')
                          and not(fp:ros-idle-at-start($writer))"/>
  </xsl:function>

  <!-- flat() and same(): the values of parameter files, compared with
       those a node has -->
  <xsl:variable name="fp:ros-test-helpers" as="xs:string">
    <xsl:text>

def flat(values, prefix=''):
    """Return the parameters of a YAML mapping, the keys of nested ones joined by dots."""
    found = {}
    for key, value in values.items():
        if isinstance(value, dict):
            found.update(flat(value, prefix + str(key) + '.'))
        else:
            found[prefix + str(key)] = value
    return found


def same(found, expected):
    """Return whether a parameter's value is the one expected (numbers to 1e-9)."""
    if isinstance(expected, (list, tuple)):
        found = list(found)
        return len(found) == len(expected) and all(map(same, found, expected))
    if isinstance(expected, float) or isinstance(found, float):
        return abs(float(found) - float(expected)) &lt;= 1e-9 * max(1.0, abs(float(expected)))
    return found == expected</xsl:text>
  </xsl:variable>
</xsl:stylesheet>
