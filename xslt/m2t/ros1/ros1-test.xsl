<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros1/ros1-test.xsl - the system test of the ROS 1 package: the
  generated system tests itself (catkin_make run_tests, rostest).

  Reads:   r:package of urn:robomda:psm-ros:1 (ros-version 1).
  Writes:  the texts of test/<model>.test (the rostest launch file: the
           package's top launch file and the test node) and of
           test/test_<model>_system.py (the test node; wrapped into fs:file by
           main.xsl), and the CMake lines that run them (fp:ros1-test-cmake).
  Params:  none.  Errors: none.  Modules: ../ros-common/ros-test.xsl (the
  tables and the helpers both ROS targets' tests share).

  rostest starts a master of its own and the whole system as
  launch/<model>.launch does (every host's file on this machine), then the
  test node, which checks what the model says:
    - every instance runs, under its modelled name;
    - every modelled connection is wired: the master knows its writer as a
      publisher and its reader as a subscriber of one topic of the modelled
      name; where the writer sends on its own (ros-test.xsl, fp:ros-sends) a
      sample arrives on it;
    - every instance's parameters have the values its parameter files give
      (config/<instance>.yaml, then the user's config/<instance>.user.yaml);
    - and, last, every instance still runs (none has died meanwhile).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:variable name="fp:test-xsl" as="xs:string" select="'m2t/ros1/ros1-test.xsl'"/>

  <!-- the paths of the rostest launch file and of the test node -->
  <xsl:function name="fp:ros1-test-paths" as="xs:string+">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="'test/' || $package/@deploy-name || '.test', 'test/test_' || $package/@deploy-name || '_system.py'"/>
  </xsl:function>

  <!-- the CMake lines that run the test (catkin_make run_tests) -->
  <xsl:function name="fp:ros1-test-cmake" as="xs:string+">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="
        '',
        '# catkin_make run_tests: the system as modelled (nodes, connections, parameters)',
        'if(CATKIN_ENABLE_TESTING)',
        '  find_package(rostest REQUIRED)',
        '  add_rostest(' || fp:ros1-test-paths($package)[1] || ')',
        'endif()'"/>
  </xsl:function>

  <xsl:function name="fp:ros1-test-launch" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="fp:lines((
        '&lt;?xml version=&quot;1.0&quot;?&gt;',
        '&lt;!--',
        fp:indent(2, fp:banner('', $fp:test-xsl, 'model ''' || fp:xml-text($package/@model-name) || '''', false())),
        '  rostest: the whole system as its top launch file starts it, then the test node.',
        '--&gt;',
        '&lt;launch&gt;',
        '  &lt;include file=&quot;$(find ' || $package/@name || ')/launch/' || $package/@deploy-name || '.launch&quot;/&gt;',
        '  &lt;test test-name=&quot;system&quot; pkg=&quot;' || $package/@name || '&quot; type=&quot;'
          || tokenize(fp:ros1-test-paths($package)[2], '/')[last()] || '&quot; time-limit=&quot;300&quot;/&gt;',
        '&lt;/launch&gt;'))"/>
  </xsl:function>

  <xsl:function name="fp:ros1-test-node" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="fp:lines((
        '#!/usr/bin/env python3',
        fp:banner('# ', $fp:test-xsl, 'model ''' || $package/@model-name || '''', false()),
        '',
        '&quot;&quot;&quot;Check the running system of this package against its model (a rostest node).&quot;&quot;&quot;',
        '',
        'import os',
        'import time',
        'import unittest',
        '',
        'import rosgraph',
        'import rospkg',
        'import rospy',
        'import rostest',
        'import yaml',
        '',
        fp:ros-test-tables($package),
        $fp:system-test-code, $fp:ros-test-helpers, $fp:system-test-cases))"/>
  </xsl:function>

  <!-- the code of the test node after its tables: the same for every model
       (the helpers of ../ros-common/ros-test.xsl between its two parts) -->
  <xsl:variable name="fp:system-test-code" as="xs:string">
    <xsl:text>


def modelled_parameters(instance):
    """Return the values the parameter files of an instance give (a later file wins)."""
    folder = os.path.join(rospkg.RosPack().get_path(PACKAGE), 'config')
    values = {}
    for name in PARAMETER_FILES[instance]:
        with open(os.path.join(folder, name)) as stream:
            values.update(flat(yaml.safe_load(stream) or {}))
    return values</xsl:text>
  </xsl:variable>

  <xsl:variable name="fp:system-test-cases" as="xs:string">
    <xsl:text>


class TestSystem(unittest.TestCase):
    """The running system is the modelled one."""

    @classmethod
    def setUpClass(cls):
        rospy.init_node('robomda_system_test', anonymous=True)
        cls.master = rosgraph.Master(rospy.get_name())

    def within(self, condition):
        """Return what condition() returns once it is true, or None after TIMEOUT."""
        deadline = time.monotonic() + TIMEOUT
        while time.monotonic() &lt; deadline:
            found = condition()
            if found:
                return found
            time.sleep(0.1)
        return None

    def graph(self):
        """Return the master's publishers and subscribers of each topic."""
        publishers, subscribers, _ = self.master.getSystemState()
        return dict(publishers), dict(subscribers)

    def running(self, instance):
        """Return the full name of the running node of an instance, or None."""
        publishers, subscribers = self.graph()
        for nodes in list(publishers.values()) + list(subscribers.values()):
            for node in nodes:
                if node == NODES[instance] or node.endswith(NODES[instance]):
                    return node
        return None

    def topic(self, writer, reader, topic):
        """Return the topic the writer publishes and the reader reads, or None."""
        ends = [self.running(writer), self.running(reader)]
        if None in ends:
            return None
        publishers, subscribers = self.graph()
        for name, nodes in publishers.items():
            if (name == '/' + topic or name.endswith('/' + topic)) and ends[0] in nodes \
                    and ends[1] in subscribers.get(name, []):
                return name
        return None

    def test_instances_run(self):
        """Every instance runs, under its modelled name."""
        missing = ['instance %s: no node %s' % (instance, NODES[instance]) for instance in NODES
                   if not self.within(lambda: self.running(instance))]
        self.assertFalse(missing, '\n'.join(missing))

    def test_connections_are_wired(self):
        """Each connection's writer publishes to, and its reader reads, one topic."""
        missing = ['connection %s.%s -> %s.%s: %s does not publish on a topic %s that %s reads'
                   % (writer, out, reader, into, writer, topic, reader)
                   for writer, out, reader, into, topic, _, _, _ in CONNECTIONS
                   if not self.within(lambda: self.topic(writer, reader, topic))]
        self.assertFalse(missing, '\n'.join(missing))

    def test_connections_carry_data(self):
        """Samples arrive on the topic of each connection whose writer sends them."""
        missing = []
        for writer, out, reader, into, topic, sends, _, _ in CONNECTIONS:
            name = self.within(lambda: self.topic(writer, reader, topic)) if sends else None
            try:
                if name:
                    rospy.wait_for_message(name, rospy.AnyMsg, timeout=TIMEOUT)
                elif sends:
                    missing.append('connection %s.%s -> %s.%s: not wired' % (writer, out, reader, into))
            except rospy.ROSException:
                missing.append('connection %s.%s -> %s.%s: no sample on %s' % (writer, out, reader, into, name))
        self.assertFalse(missing, '\n'.join(missing))

    def test_parameters_have_their_values(self):
        """Every instance's parameters have the values of its parameter files."""
        wrong = []
        for instance in PARAMETER_FILES:
            node = self.within(lambda: self.running(instance))
            for name, value in sorted(modelled_parameters(instance).items()):
                found = rospy.get_param(node + '/' + name.replace('.', '/'), None) if node else None
                if found is None or not same(found, value):
                    wrong.append('%s: parameter %s is %r, not %r' % (instance, name, found, value))
        self.assertFalse(wrong, '\n'.join(wrong))

    def test_zz_instances_still_run(self):
        """Last: no instance has died while the others were checked."""
        gone = ['instance %s has stopped' % instance for instance in NODES if not self.running(instance)]
        self.assertFalse(gone, '\n'.join(gone))


if __name__ == '__main__':
    rostest.rosrun(PACKAGE, 'system', TestSystem)</xsl:text>
  </xsl:variable>
</xsl:stylesheet>
