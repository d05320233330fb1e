<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros1/ros1-launch.xsl - roslaunch XML and parameter YAML of the
  ROS 1 package (seed 002 section IV-D).

  Reads:   r:package of urn:robomda:psm-ros:1 (ros-version 1).
  Writes:  strings (file contents), wrapped into fs:file by main.xsl.
  Params:  none.  Errors: none.

  launch/<model>_<host>.launch  one per host (component set): a <machine>
                                (name = host, address) and one <node> per
                                instance on it, with machine=, its private
                                parameters (<rosparam> of config/<instance>.yaml)
                                and a <remap> per connected port
  launch/<model>.launch         includes every host file
  config/<instance>.yaml        the instance's private parameters: update_period
                                and the component's parameters (defaults)
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:ros1-host-launch" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="host" as="element(r:host)"/>
    <xsl:sequence select="fp:lines((
        '&lt;?xml version=&quot;1.0&quot;?&gt;',
        '&lt;!--',
        fp:indent(2, fp:banner('', $fp:launch-xsl, concat('host ''', fp:xml-text($host/@name), ''' of model ''', fp:xml-text($package/@model-name), ''''), false())),
        '  Component set of this host (seed 002): roslaunch starts the nodes in no',
        '  guaranteed order. For a remote machine add env-loader=&quot;...&quot; to &lt;machine&gt;.',
        '--&gt;',
        '&lt;launch&gt;',
        concat('  &lt;machine name=&quot;', fp:xml-text($host/@machine), '&quot; address=&quot;', fp:xml-text($host/@address), '&quot;/&gt;'),
        for $i in $package/r:instance[@host eq $host/@name] return (
          '',
          concat('  &lt;node pkg=&quot;', $package/@name, '&quot; type=&quot;', $i/@executable, '&quot; ', fp:node-name-attributes($i, 'ns'),
               ' machine=&quot;', fp:xml-text($host/@machine), '&quot; output=&quot;screen&quot;&gt;'),
          concat('    &lt;rosparam command=&quot;load&quot; file=&quot;$(find ', $package/@name, ')/config/', $i/@name, '.yaml&quot;/&gt;'),
          concat('    &lt;rosparam command=&quot;load&quot; file=&quot;$(find ', $package/@name, ')/config/', $i/@name, '.user.yaml&quot;/&gt;'),
          $i/r:remap ! (concat('    &lt;remap from=&quot;', @from, '&quot; to=&quot;', @to, '&quot;/&gt;')),
          '  &lt;/node&gt;'),
        '&lt;/launch&gt;'))"/>
  </xsl:function>

  <xsl:function name="fp:ros1-top-launch" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="fp:lines((
        '&lt;?xml version=&quot;1.0&quot;?&gt;',
        '&lt;!--',
        fp:indent(2, fp:banner('', $fp:launch-xsl, concat('model ''', fp:xml-text($package/@model-name), ''''), false())),
        '  The whole deployment: one included launch file per host.',
        '--&gt;',
        '&lt;launch&gt;',
        $package/r:host ! (concat('  &lt;include file=&quot;$(find ', $package/@name, ')/launch/', $package/@deploy-name, '_', @launch, '.launch&quot;/&gt;')),
        '&lt;/launch&gt;'))"/>
  </xsl:function>

  <xsl:function name="fp:params-yaml" as="xs:string">
    <xsl:param name="instance" as="element(r:instance)"/>
    <xsl:param name="stylesheet" as="xs:string"/>
    <xsl:sequence select="fp:lines((
        fp:banner('# ', $stylesheet, concat('instance ''', $instance/@name, ''' of model ''', $instance/../@model-name, ''''), false()),
        fp:yaml-mapping($instance/r:parameter-value, '')))"/>
  </xsl:function>
</xsl:stylesheet>
