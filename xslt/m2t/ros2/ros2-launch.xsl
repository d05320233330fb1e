<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros2/ros2-launch.xsl - ROS 2 launch XML and parameter YAML.

  Reads:   r:package of urn:robomda:psm-ros:1 (ros-version 2).
  Writes:  strings (file contents), wrapped into fs:file by main.xsl.
  Params:  none.  Errors: none.

  launch/<model>_<host>.launch.xml  one per host (ROS 2 launch has no
        machine tag: start each on its host; the PSM stage warns, ROS102):
        one <node pkg exec name> per instance with <param from=".yaml"/>
        and a <remap> per connected port
  launch/<model>.launch.xml  includes every host file (one-machine runs)
  config/params.yaml  "<instance>: ros__parameters: ..." for every instance
  Checked against schemas/ros2-launch/1/launch.xsd (launch_ros attributes).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:ros2-host-launch" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="host" as="element(r:host)"/>
    <xsl:sequence select="fp:lines((
        '&lt;?xml version=&quot;1.0&quot;?&gt;',
        '&lt;!--',
        fp:indent(2, fp:banner('', $fp:launch-xsl, concat('host ''', fp:xml-text($host/@name), ''' (', fp:xml-text($host/@address),
             ') of model ''', fp:xml-text($package/@model-name), ''''), false())),
        '  ROS 2 launch has no machine tag: start this file on that host.',
        '--&gt;',
        '&lt;launch&gt;',
        for $i in $package/r:instance[@host eq $host/@name] return (
          concat('  &lt;node pkg=&quot;', $package/@name, '&quot; exec=&quot;', $i/@executable, '&quot; ', fp:node-name-attributes($i, 'namespace'), ' output=&quot;screen&quot;&gt;'),
          concat('    &lt;param from=&quot;$(find-pkg-share ', $package/@name, ')/config/params.yaml&quot;/&gt;'),
          concat('    &lt;param from=&quot;$(find-pkg-share ', $package/@name, ')/config/params.user.yaml&quot;/&gt;'),
          $i/r:remap ! (concat('    &lt;remap from=&quot;', @from, '&quot; to=&quot;', @to, '&quot;/&gt;')),
          '  &lt;/node&gt;'),
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

  <xsl:function name="fp:ros2-params-yaml" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="fp:lines((
        fp:banner('# ', $fp:launch-xsl, concat('model ''', $package/@model-name, ''''), false()),
        for $i in $package/r:instance return (
          (: a node in a namespace: its fully qualified name :)
          concat(if ($i/@namespace) then concat('/', $i/@namespace, '/', $i/@node-name) else $i/@name, ':'),
          '  ros__parameters:',
          fp:indent(4, fp:yaml-mapping($i/r:parameter-value, '')))))"/>
  </xsl:function>
</xsl:stylesheet>
