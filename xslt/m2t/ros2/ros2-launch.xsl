<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros2/ros2-launch.xsl - ROS 2 launch XML and parameter YAML.

  Reads:   r:package of urn:robomda:psm-ros:1 (ros-version 2).
  Writes:  strings (file contents), wrapped into fs:file by main.xsl.
  Params:  none.  Errors: none.

  launch/<model>_<host>.launch.xml  one per host (ROS 2 launch has no
        machine tag: start each on its host; the PSM stage warns, ROS102):
        a <node_container> per process of the model (component_container,
        component_container_mt where the model has threads in it) whose
        <composable_node>s, in the model's start order, are its instances
        (intra-process communication stays off: Humble refuses it with the
        transient_local durability a latched connection asks for), each with
        <param from="config/<instance>.yaml"/> and its .user.yaml
        and a <remap> per connected port (relative for a node in the root
        namespace; a name from the root starts with $(var ros_namespace ''),
        the pushed namespace) (a managed instance: its node's
        lifecycle class); a <node> per instance in no process; an <include>
        per component set on the host; a lifecycle_manager <node> when the
        host has managed instances, their names in start order (node_names,
        after the pushed namespace; not the jobs' instances); the job
        coordinator of each subsystem on the host (ros2-jobs.xsl)
  launch/<model>_<set>.launch.xml  one per component set (seed 002): the
        containers of the processes wholly in it, and its members in other
        processes loaded into theirs (<load_composable_node target>)
  launch/<model>.launch.xml  includes every host file (one-machine runs)
  config/<instance>.yaml  "/**: ros__parameters: ..." per instance, given to
        its node alone, so that it applies under a pushed namespace too
        (launch_ros matches a composable node's keys by full name or /**)
  Checked against schemas/ros2-launch/1/launch.xsd (launch_ros attributes).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- the namespace a <push-ros-namespace> (or an including file's) has
       set, empty when none: a name the PSM made absolute (from-root: a node
       in a namespace, a service client) starts with it, so that both ends
       of a connection meet wherever this file is included -->
  <xsl:variable name="fp:ros2-root" as="xs:string" select="'$(var ros_namespace '''')'"/>

  <!-- the settings of a node or composable node of instance $i: its
       parameter files and remaps, indented by $n -->
  <xsl:function name="fp:ros2-node-settings" as="xs:string*">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="i" as="element(r:instance)"/>
    <xsl:param name="n" as="xs:integer"/>
    <xsl:sequence select="fp:indent($n, (
        concat('&lt;param from=&quot;$(find-pkg-share ', $package/@name, ')/config/', $i/@name, '.yaml&quot;/&gt;'),
        concat('&lt;param from=&quot;$(find-pkg-share ', $package/@name, ')/config/', $i/@name, '.user.yaml&quot;/&gt;'),
        $i/r:remap ! (concat('&lt;remap from=&quot;', @from, '&quot; to=&quot;',
                             if (xs:boolean(@from-root)) then $fp:ros2-root else '', @to, '&quot;/&gt;'))))"/>
  </xsl:function>

  <!-- instance $i as a node of its own; a managed one (a lifecycle
       component) in a container of its own, <instance>_container -->
  <xsl:function name="fp:ros2-node" as="xs:string+">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="i" as="element(r:instance)"/>
    <xsl:sequence select="if ($i/@managed) then (
        concat('  &lt;node_container pkg=&quot;rclcpp_components&quot; exec=&quot;component_container&quot; name=&quot;', $i/@name,
               '_container&quot; namespace=&quot;/&quot; output=&quot;screen&quot;&gt;'),
        fp:ros2-composable($package, $i, 4),
        '  &lt;/node_container&gt;') else (
        concat('  &lt;node pkg=&quot;', $package/@name, '&quot; exec=&quot;', $i/@executable, '&quot; ', fp:node-name-attributes($i, 'namespace'), ' output=&quot;screen&quot;&gt;'),
        fp:ros2-node-settings($package, $i, 4),
        '  &lt;/node&gt;')"/>
  </xsl:function>

  <!-- instance $i as a composable node in a container, indented by $n -->
  <xsl:function name="fp:ros2-composable" as="xs:string+">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="i" as="element(r:instance)"/>
    <xsl:param name="n" as="xs:integer"/>
    <xsl:variable name="node" as="element(r:node)" select="fp:ros-children('fp:ros-node', $package, string($i/@node))"/>
    <xsl:sequence select="fp:indent($n, (
        concat('&lt;composable_node pkg=&quot;', $package/@name, '&quot; plugin=&quot;',
               if ($i/@managed) then $node/@lifecycle-type-name else $node/@type-name, '&quot; ', fp:node-name-attributes($i, 'namespace'), '&gt;'),
        fp:ros2-node-settings($package, $i, 2),
        '&lt;/composable_node&gt;'))"/>
  </xsl:function>

  <!-- a process as a component container holding $members (in start order) -->
  <xsl:function name="fp:ros2-container" as="xs:string+">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="process" as="element(r:process)"/>
    <xsl:param name="members" as="element(r:instance)*"/>
    <xsl:sequence select="
        concat('  &lt;!-- process ''', fp:xml-text($process/@name), '''',
               $process/@threads ! concat(', threads ', fp:xml-text(.), ': a multi-threaded container'),
               if (xs:boolean($process/@managed)) then ', managed: lifecycle nodes' else '', ' --&gt;'),
        concat('  &lt;node_container pkg=&quot;rclcpp_components&quot; exec=&quot;component_container',
               if ($process/@executor eq 'multi') then '_mt' else '', '&quot; name=&quot;', $process/@container,
               '&quot; namespace=&quot;/&quot; output=&quot;screen&quot;', if (empty($members)) then '/&gt;' else '&gt;'),
        if (empty($members)) then () else (
          fp:in-start-order($members) ! fp:ros2-composable($package, ., 4),
          '  &lt;/node_container&gt;')"/>
  </xsl:function>

  <!-- $members loaded into the running container of $process -->
  <xsl:function name="fp:ros2-load" as="xs:string+">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="process" as="element(r:process)"/>
    <xsl:param name="members" as="element(r:instance)+"/>
    <xsl:sequence select="
        concat('  &lt;load_composable_node target=&quot;/', $process/@container, '&quot;&gt;'),
        fp:in-start-order($members) ! fp:ros2-composable($package, ., 4),
        '  &lt;/load_composable_node&gt;'"/>
  </xsl:function>

  <xsl:function name="fp:ros2-host-launch" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="host" as="element(r:host)"/>
    <xsl:variable name="here" as="element(r:instance)*" select="fp:ros-children('fp:ros-on-host', $package, $host/@name)"/>
    <xsl:sequence select="fp:lines((
        '&lt;?xml version=&quot;1.0&quot;?&gt;',
        '&lt;!--',
        fp:indent(2, fp:banner('', $fp:launch-xsl, concat('host ''', fp:xml-text($host/@name), ''' (', fp:xml-text($host/@address),
             ') of model ''', fp:xml-text($package/@model-name), ''''), false())),
        '  ROS 2 launch has no machine tag: start this file on that host. Each',
        '  process of the model is a component container; its component sets',
        '  are included.',
        fp:indent(2, fp:host-lines($host) ! fp:xml-text(.)),
        '--&gt;',
        '&lt;launch&gt;',
        for $p in fp:ros-children('fp:ros-process-on-host', $package, $host/@name)[not(@set)]
        return fp:ros2-container($package, $p, $here[@process eq $p/@name][not(@set)]),
        for $i in $here[not(@process)][not(@set)] return fp:ros2-node($package, $i),
        fp:ros-children('fp:ros-set-on-host', $package, $host/@name) ! concat('  &lt;include file=&quot;$(find-pkg-share ', $package/@name, ')/launch/',
                                                       $package/@deploy-name, '_', @launch, '.launch.xml&quot;/&gt;'),
        $host/@lifecycle-manager ! fp:ros2-lifecycle-manager-node($package, $host, $here[@managed][not(@job)]),
        $package/r:coordinator[@host eq $host/@name] ! fp:ros2-coordinator-node($package, .),
        '&lt;/launch&gt;'))"/>
  </xsl:function>

  <!-- the lifecycle manager of a host: configures, then activates, its
       managed nodes in the deployment sequence (ros2-lifecycle.xsl) -->
  <xsl:function name="fp:ros2-lifecycle-manager-node" as="xs:string+">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="host" as="element(r:host)"/>
    <xsl:param name="managed" as="element(r:instance)+"/>
    <xsl:sequence select="
        '  &lt;!-- the managed (lifecycle) nodes on this host: configured, then activated, in the deployment sequence --&gt;',
        concat('  &lt;node pkg=&quot;', $package/@name, '&quot; exec=&quot;lifecycle_manager&quot; name=&quot;', $host/@lifecycle-manager,
               '&quot; namespace=&quot;/&quot; output=&quot;screen&quot;&gt;'),
        concat('    &lt;param name=&quot;node_names&quot; value=&quot;', string-join(fp:in-start-order($managed) ! ($fp:ros2-root || fp:ros-fqn(.)), ','),
               '&quot; value-sep=&quot;,&quot;/&gt;'),
        '  &lt;/node&gt;'"/>
  </xsl:function>

  <!-- a component set (seed 002): the containers of the processes wholly
       in it; its members in other processes loaded into theirs -->
  <xsl:function name="fp:ros2-set-launch" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="set" as="element(r:set)"/>
    <xsl:variable name="members" as="element(r:instance)*" select="fp:ros-children('fp:ros-in-set', $package, $set/@launch)"/>
    <xsl:sequence select="fp:lines((
        '&lt;?xml version=&quot;1.0&quot;?&gt;',
        '&lt;!--',
        fp:indent(2, fp:banner('', $fp:launch-xsl, concat('component set ''', fp:xml-text($set/@name), ''' of model ''',
             fp:xml-text($package/@model-name), ''''), false())),
        concat('  Deployed on host ''', fp:xml-text($set/@host), ''' (seed 002): included by its launch file.'),
        '--&gt;',
        '&lt;launch&gt;',
        for $p in fp:ros-children('fp:ros-process-in-set', $package, $set/@launch) return fp:ros2-container($package, $p, $members[@process eq $p/@name]),
        for $p in fp:ros-children('fp:ros-process', $package, distinct-values($members/@process))[not(@set)]
        return fp:ros2-load($package, $p, $members[@process eq $p/@name]),
        for $i in $members[not(@process)] return fp:ros2-node($package, $i),
        '&lt;/launch&gt;'))"/>
  </xsl:function>

  <xsl:function name="fp:ros2-top-launch" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="fp:lines((
        '&lt;?xml version=&quot;1.0&quot;?&gt;',
        '&lt;!--',
        fp:indent(2, fp:banner('', $fp:launch-xsl, concat('model ''', fp:xml-text($package/@model-name), ''''), false())),
        '  Every host file, on this one machine.',
        '--&gt;',
        '&lt;launch&gt;',
        $package/r:host ! (concat('  &lt;include file=&quot;$(find-pkg-share ', $package/@name, ')/launch/', $package/@deploy-name, '_', @launch, '.launch.xml&quot;/&gt;')),
        '&lt;/launch&gt;'))"/>
  </xsl:function>

  <!-- the parameters of instance $i under the key /**: the file is given
       to that node alone, and launch_ros matches a composable node's keys
       only by its full name or /** (not /**/name), which a pushed
       namespace changes -->
  <xsl:function name="fp:ros2-params-yaml" as="xs:string">
    <xsl:param name="i" as="element(r:instance)"/>
    <xsl:sequence select="fp:lines((
        fp:banner('# ', $fp:launch-xsl, concat('instance ''', $i/@name, ''' of model ''', $i/../@model-name, ''''), false()),
        '/**:',
        '  ros__parameters:',
        fp:indent(4, fp:yaml-mapping($i/r:parameter-value, ''))))"/>
  </xsl:function>
</xsl:stylesheet>
