<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros1/ros1-launch.xsl - roslaunch XML and parameter YAML of the
  ROS 1 package (seed 002 section IV-D).

  Reads:   r:package of urn:robomda:psm-ros:1 (ros-version 1).
  Writes:  strings (file contents), wrapped into fs:file by main.xsl.
  Params:  none.  Errors: none.

  launch/<model>_<host>.launch  one per host: a <machine> (name = host,
                                address; the host's resources and buses in a
                                comment), one <node> per instance on it in no
                                component set, with machine=, its private
                                parameters (<rosparam> of config/<instance>.yaml)
                                and a <remap> per connected port, and an
                                <include> of each component set on the host;
                                not the instances of the jobs that only a switch
                                starts (idle), but each job coordinator of the
                                host (ros1-jobs.xsl)
  launch/<model>_<set>.launch   one per component set (seed 002): the
                                <machine>s and <node>s of its members
  launch/<model>.launch         includes every host file
  A package with a remap named from the root (a node in a namespace of its
  own, a service client): every launch file takes argument ns (default:
  the root), passes it to the files it includes, and places its nodes in
  <group ns="/$(arg ns)">, those names starting with /$(arg ns): ROS 1 has
  no way to name the namespace of an enclosing <group ns>, so the ends of
  a connection meet only if the file places the system itself.
  config/<instance>.yaml        the instance's private parameters: update_period
                                and the component's parameters (defaults)
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- a <node> of instance $i, its lines -->
  <xsl:function name="fp:ros1-node" as="xs:string+">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="i" as="element(r:instance)"/>
    <xsl:sequence select="
        '',
        concat('  &lt;node pkg=&quot;', $package/@name, '&quot; type=&quot;', $i/@executable, '&quot; ', fp:node-name-attributes($i, 'ns'),
             ' machine=&quot;', fp:xml-text($i/@host), '&quot; output=&quot;screen&quot;&gt;'),
        concat('    &lt;rosparam command=&quot;load&quot; file=&quot;$(find ', $package/@name, ')/config/', $i/@name, '.yaml&quot;/&gt;'),
        concat('    &lt;rosparam command=&quot;load&quot; file=&quot;$(find ', $package/@name, ')/config/', $i/@name, '.user.yaml&quot;/&gt;'),
        $i/r:remap ! (concat('    &lt;remap from=&quot;', @from, '&quot; to=&quot;', if (xs:boolean(@from-root)) then '/$(arg ns)' else '', @to, '&quot;/&gt;')),
        '  &lt;/node&gt;'"/>
  </xsl:function>

  <!-- the <machine> of each host, its resources and buses in a comment -->
  <xsl:function name="fp:ros1-machines" as="xs:string*">
    <xsl:param name="hosts" as="element(r:host)*"/>
    <xsl:for-each select="$hosts">
      <xsl:sequence select="
          '  &lt;!-- ' || string-join(fp:host-lines(.) ! fp:xml-text(.), '&#10;       ') || ' --&gt;',
          concat('  &lt;machine name=&quot;', fp:xml-text(@machine), '&quot; address=&quot;', fp:xml-text(@address), '&quot;/&gt;')"/>
    </xsl:for-each>
  </xsl:function>

  <!-- the topics shared with instances of another middleware, which the
       launch files leave out to their own target: a comment line each -->
  <xsl:function name="fp:ros-elsewhere" as="xs:string*">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:for-each select="$package/r:topic[*/@middleware]">
      <xsl:sequence select="'  Topic ' || @name || ' is shared with ' || string-join(*[@middleware] ! (@instance || ' (' || @middleware || ')'), ', ')
                            || ', which its own target generates.'"/>
    </xsl:for-each>
  </xsl:function>

  <xsl:function name="fp:ros1-host-launch" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="host" as="element(r:host)"/>
    <xsl:sequence select="fp:lines((
        '&lt;?xml version=&quot;1.0&quot;?&gt;',
        '&lt;!--',
        fp:indent(2, fp:banner('', $fp:launch-xsl, concat('host ''', fp:xml-text($host/@name), ''' of model ''', fp:xml-text($package/@model-name), ''''), false())),
        '  The nodes of this host (seed 002) and its component sets; roslaunch',
        '  starts them in no guaranteed order. For a remote machine add',
        '  env-loader=&quot;...&quot; to &lt;machine&gt;.',
        fp:ros-elsewhere($package),
        '--&gt;',
        '&lt;launch&gt;',
        fp:ros1-in-root($package, (
          fp:ros1-machines($host),
          for $i in fp:ros-children('fp:ros-on-host', $package, $host/@name)[not(@set)][not(@idle)] return fp:ros1-node($package, $i),
          $package/r:coordinator[@host eq $host/@name] ! fp:ros1-coordinator-node($package, .),
          fp:ros-children('fp:ros-set-on-host', $package, $host/@name) ! ('', fp:ros1-include($package, @launch)))),
        '&lt;/launch&gt;'))"/>
  </xsl:function>

  <!-- a component set (seed 002): the nodes of its members, on their machines -->
  <xsl:function name="fp:ros1-set-launch" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="set" as="element(r:set)"/>
    <xsl:variable name="members" as="element(r:instance)*" select="fp:ros-children('fp:ros-in-set', $package, $set/@launch)"/>
    <xsl:sequence select="fp:lines((
        '&lt;?xml version=&quot;1.0&quot;?&gt;',
        '&lt;!--',
        fp:indent(2, fp:banner('', $fp:launch-xsl, concat('component set ''', fp:xml-text($set/@name), ''' of model ''', fp:xml-text($package/@model-name), ''''), false())),
        concat('  Deployed on host ''', fp:xml-text($set/@host), ''' (seed 002); included by its launch file, or started alone.'),
        '--&gt;',
        '&lt;launch&gt;',
        fp:ros1-in-root($package, (
          fp:ros1-machines(fp:ros-children('fp:ros-host', $package, distinct-values($members/@host))),
          for $i in $members[not(@idle)] return fp:ros1-node($package, $i))),
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
        if (fp:ros1-from-root($package)) then fp:ros1-ns-arg() else (),
        $package/r:host ! fp:ros1-include($package, @launch),
        '&lt;/launch&gt;'))"/>
  </xsl:function>

  <!-- whether a node of $package names a topic or service from the root
       (a node in a namespace of its own, a service client): ROS 1 resolves
       a remap in the node's namespace and cannot name the namespace an
       enclosing <group ns> sets, so such a package's launch files take it
       as argument ns and place the system there themselves -->
  <xsl:function name="fp:ros1-from-root" as="xs:boolean">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="exists($package/r:instance/r:remap[xs:boolean(@from-root)])"/>
  </xsl:function>

  <xsl:function name="fp:ros1-ns-arg" as="xs:string">
    <xsl:sequence select="'  &lt;arg name=&quot;ns&quot; default=&quot;&quot; doc=&quot;the namespace to run the system in (robot), '
                          || 'in place of a group ns around the include, which ROS 1 cannot pass on to the names taken from the root&quot;/&gt;'"/>
  </xsl:function>

  <!-- the body $lines of a launch file: as they are, or (a package naming
       from the root) under argument ns, indented by two more -->
  <xsl:function name="fp:ros1-in-root" as="xs:string*">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="lines" as="xs:string*"/>
    <xsl:sequence select="if (not(fp:ros1-from-root($package))) then $lines
        else (fp:ros1-ns-arg(), '  &lt;group ns=&quot;/$(arg ns)&quot;&gt;', fp:indent(2, $lines), '  &lt;/group&gt;')"/>
  </xsl:function>

  <!-- an <include> of the launch file of a host or set; argument ns passed on -->
  <xsl:function name="fp:ros1-include" as="xs:string+">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:param name="launch" as="xs:string"/>
    <xsl:variable name="file" as="xs:string" select="concat('$(find ', $package/@name, ')/launch/', $package/@deploy-name, '_', $launch, '.launch')"/>
    <xsl:sequence select="if (fp:ros1-from-root($package))
        then (concat('  &lt;include file=&quot;', $file, '&quot;&gt;'), '    &lt;arg name=&quot;ns&quot; value=&quot;$(arg ns)&quot;/&gt;', '  &lt;/include&gt;')
        else concat('  &lt;include file=&quot;', $file, '&quot;/&gt;')"/>
  </xsl:function>

  <xsl:function name="fp:params-yaml" as="xs:string">
    <xsl:param name="instance" as="element(r:instance)"/>
    <xsl:param name="stylesheet" as="xs:string"/>
    <xsl:sequence select="fp:lines((
        fp:banner('# ', $stylesheet, concat('instance ''', $instance/@name, ''' of model ''', $instance/../@model-name, ''''), false()),
        fp:yaml-mapping($instance/r:parameter-value, '')))"/>
  </xsl:function>
</xsl:stylesheet>
