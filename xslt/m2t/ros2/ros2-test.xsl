<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros2/ros2-test.xsl - the launch test of the ROS 2 package: the
  generated system tests itself (colcon test, launch_testing).

  Reads:   r:package of urn:robomda:psm-ros:1 (ros-version 2).
  Writes:  the text of test/test_<model>_launch.py (wrapped into fs:file by
           main.xsl) and the CMake lines that run it (fp:ros2-launch-test-cmake).
  Params:  none.  Errors: none.  Modules: ../ros-common/ros-test.xsl (the
  tables and the helpers both ROS targets' tests share).

  The test starts the whole system as launch/<model>.launch.xml does (every
  host's file on this machine) and checks what the model says:
    - every instance is running, under its modelled name (and namespace);
    - every modelled connection is wired: its writer publishes, and its
      reader subscribes to, one topic of the modelled name; where the
      writer runs periodically (and is active) and publishes its port, a
      sample arrives on that topic (a «Constant» is read latched);
    - every instance's parameters have the values its parameter files give
      (config/<instance>.yaml, then the user's config/<instance>.user.yaml);
    - every managed instance is in its modelled lifecycle state (active;
      unconfigured when only a job other than the initial one runs it);
    - once the launch stops the system, every process has exited with 0.
  Written to pass ROS 2's own linters (flake8, pep257, copyright).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:variable name="fp:test-xsl" as="xs:string" select="'m2t/ros2/ros2-test.xsl'"/>

  <!-- the path of the launch test in the package -->
  <xsl:function name="fp:ros2-launch-test-path" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="'test/test_' || $package/@deploy-name || '_launch.py'"/>
  </xsl:function>

  <!-- the CMake lines (in the BUILD_TESTING block) that run it -->
  <xsl:function name="fp:ros2-launch-test-cmake" as="xs:string+">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="
        '  # the system as modelled: nodes, connections, parameters, lifecycle states, clean stop',
        '  find_package(launch_testing_ament_cmake REQUIRED)',
        '  add_launch_test(' || fp:ros2-launch-test-path($package) || ' TIMEOUT 180)'"/>
  </xsl:function>




  <xsl:function name="fp:ros2-launch-test" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="fp:lines((
        fp:banner('# ', $fp:test-xsl, 'model ''' || $package/@model-name || '''', false()),
        '',
        '&quot;&quot;&quot;Launch the system of this package and check it against its model.&quot;&quot;&quot;',
        '',
        'import os',
        'import time',
        'import unittest',
        '',
        'from ament_index_python.packages import get_package_share_directory',
        'import launch',
        'from launch.actions import IncludeLaunchDescription',
        'from launch.launch_description_sources import AnyLaunchDescriptionSource',
        'import launch_testing',
        'import launch_testing.actions',
        'import launch_testing.asserts',
        'from lifecycle_msgs.srv import GetState',
        'import pytest',
        'from rcl_interfaces.srv import GetParameters',
        'import rclpy',
        'from rclpy.parameter import parameter_value_to_python',
        'from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy',
        'from rosidl_runtime_py.utilities import get_message',
        'import yaml',
        '',
        'LAUNCH_FILE = ' || fp:py-string($package/@deploy-name || '.launch.xml'),
        fp:ros-test-tables($package),
        $fp:launch-test-code, $fp:ros-test-helpers, $fp:launch-test-cases))"/>
  </xsl:function>


  <!-- the code of the test, after its tables: the same for every model
       (the helpers of ../ros-common/ros-test.xsl between its two parts) -->
  <xsl:variable name="fp:launch-test-code" as="xs:string">
    <xsl:text>

@pytest.mark.launch_test
def generate_test_description():
    """Launch every host's part of the system, as the package's top launch file does."""
    share = get_package_share_directory(PACKAGE)
    system = IncludeLaunchDescription(
        AnyLaunchDescriptionSource(os.path.join(share, 'launch', LAUNCH_FILE)))
    return launch.LaunchDescription([system, launch_testing.actions.ReadyToTest()])


def modelled_parameters(instance):
    """Return the values the parameter files of an instance give (a later file wins)."""
    share = get_package_share_directory(PACKAGE)
    values = {}
    for name in PARAMETER_FILES[instance]:
        with open(os.path.join(share, 'config', name)) as stream:
            loaded = yaml.safe_load(stream) or {}
        for section in loaded.values():
            values.update(flat((section or {}).get('ros__parameters') or {}))
    return values</xsl:text>
  </xsl:variable>

  <xsl:variable name="fp:launch-test-cases" as="xs:string">
    <xsl:text>

class TestSystem(unittest.TestCase):
    """The running system is the modelled one."""

    @classmethod
    def setUpClass(cls):
        rclpy.init()
        cls.node = rclpy.create_node('robomda_system_test')

    @classmethod
    def tearDownClass(cls):
        cls.node.destroy_node()
        rclpy.shutdown()

    def wait_for(self, condition, what):
        """Return what condition() returns once it is true; fail saying what, after TIMEOUT."""
        deadline = time.monotonic() + TIMEOUT
        while time.monotonic() &lt; deadline:
            found = condition()
            if found:
                return found
            rclpy.spin_once(self.node, timeout_sec=0.1)
        self.fail('after %.0f s: %s' % (TIMEOUT, what))

    def running(self, instance):
        """Return (name, namespace) of the running node of an instance, or None."""
        for name, namespace in self.node.get_node_names_and_namespaces():
            full = namespace.rstrip('/') + '/' + name
            if full == NODES[instance] or full.endswith(NODES[instance]):
                return name, namespace
        return None

    def full_name(self, instance):
        """Return the full name of the running node of an instance, waiting for it."""
        what = 'instance %s: no node %s' % (instance, NODES[instance])
        name, namespace = self.wait_for(lambda: self.running(instance), what)
        return namespace.rstrip('/') + '/' + name

    def topic(self, writer, reader, topic):
        """Return (name, type) of the topic the writer publishes and the reader reads, or None."""
        ends = [self.running(writer), self.running(reader)]
        if None in ends:
            return None
        try:
            published = dict(self.node.get_publisher_names_and_types_by_node(*ends[0]))
            read = dict(self.node.get_subscriber_names_and_types_by_node(*ends[1]))
        except Exception:  # a node that has just gone
            return None
        for name, kinds in published.items():
            if (name == '/' + topic or name.endswith('/' + topic)) and name in read:
                return name, kinds[0]
        return None

    def call(self, service, kind, request):
        """Return the answer of a service to a request, or fail."""
        client = self.node.create_client(kind, service)
        try:
            self.assertTrue(client.wait_for_service(timeout_sec=TIMEOUT), 'no service ' + service)
            future = client.call_async(request)
            rclpy.spin_until_future_complete(self.node, future, timeout_sec=TIMEOUT)
            self.assertIsNotNone(future.result(), service + ' did not answer')
            return future.result()
        finally:
            self.node.destroy_client(client)

    def test_instances_run(self):
        """Every instance runs, under its modelled name."""
        for instance in NODES:
            with self.subTest(instance=instance):
                self.full_name(instance)

    def test_connections_are_wired(self):
        """Each connection's writer publishes to, and its reader reads, one topic."""
        for writer, out, reader, into, topic, _, _, _ in CONNECTIONS:
            with self.subTest(connection='%s.%s -&gt; %s.%s' % (writer, out, reader, into)):
                self.wait_for(
                    lambda: self.topic(writer, reader, topic),
                    'connection %s.%s -&gt; %s.%s: %s does not publish on a topic %s that %s reads'
                    % (writer, out, reader, into, writer, topic, reader))

    def test_connections_carry_data(self):
        """Samples arrive on the topic of each connection whose writer sends them."""
        for writer, out, reader, into, topic, sends, reliable, latched in CONNECTIONS:
            if not sends:
                continue
            with self.subTest(connection='%s.%s -&gt; %s.%s' % (writer, out, reader, into)):
                name, kind = self.wait_for(
                    lambda: self.topic(writer, reader, topic),
                    'connection %s.%s -&gt; %s.%s: not wired' % (writer, out, reader, into))
                qos = QoSProfile(
                    depth=10,
                    reliability=ReliabilityPolicy.RELIABLE if reliable
                    else ReliabilityPolicy.BEST_EFFORT,
                    durability=DurabilityPolicy.TRANSIENT_LOCAL if latched
                    else DurabilityPolicy.VOLATILE)
                samples = []
                subscription = self.node.create_subscription(
                    get_message(kind), name, samples.append, qos)
                try:
                    self.wait_for(lambda: samples, 'connection %s.%s -&gt; %s.%s: no sample on %s'
                                  % (writer, out, reader, into, name))
                finally:
                    self.node.destroy_subscription(subscription)

    def test_parameters_have_their_values(self):
        """Every instance's parameters have the values of its parameter files."""
        for instance in PARAMETER_FILES:
            expected = modelled_parameters(instance)
            if not expected:
                continue
            names = sorted(expected)
            answer = self.call(
                self.full_name(instance) + '/get_parameters', GetParameters,
                GetParameters.Request(names=names))
            for name, value in zip(names, answer.values):
                with self.subTest(instance=instance, parameter=name):
                    found = parameter_value_to_python(value)
                    self.assertTrue(
                        same(found, expected[name]),
                        '%s: parameter %s is %r, not %r' % (instance, name, found, expected[name]))

    def test_lifecycle_states(self):
        """Every managed instance is in its modelled lifecycle state."""
        for instance, state in STATES.items():
            with self.subTest(instance=instance):
                service = self.full_name(instance) + '/get_state'
                self.wait_for(
                    lambda: self.call(service, GetState, GetState.Request()).current_state.label
                    == state, 'instance %s is not %s' % (instance, state))


@launch_testing.post_shutdown_test()
class TestStop(unittest.TestCase):
    """The system stops cleanly."""

    def test_exit_codes(self, proc_info):
        """Every process has exited with 0 once the launch stopped it."""
        launch_testing.asserts.assertExitCodes(proc_info)</xsl:text>
  </xsl:variable>
</xsl:stylesheet>
