<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/diagrams/diagrams-deployment.xsl - the deployment view of a model,
  as PlantUML (diagrams/<model>-deployment.puml).

  Reads:   the bound PIM (urn:robomda:pim:1): pim:binding (hosts, links,
           processes and their threads, component sets, instances, bound
           components) and the platform's nodes (devices at a bus's end).
           Keys of main.xsl.
  Writes:  the text of one PlantUML deployment diagram:
           - each host as a node <<host>> (hostname, address, cores,
             memory, real-time kernel), holding its processes;
           - each process as a node stereotyped with its middleware
             (<<OROCOS>>, <<ROS>>, <<ROS2>> ...; "managed" for lifecycle
             nodes; a model's default process, which has none, <<process,
             middleware of the target>>), holding its threads (frames <<thread>>, with their
             period and priority) and its instances;
           - each instance as a component "name : ComponentType", in its
             thread, else its process;
           - each component set as an artifact <<component set>> on the
             host its deployment names, a grey dashed arrow to each member;
           - the facts of a host or thread in a smaller font under its name;
           - each bus (communication path) as a line between the nodes at
             its ends ("name", kind, bandwidth), through a queue <<bus>>
             when it has other than two ends; a device at an end as a node
             <<device>> (a process at an end: its own node);
           - what lies on no host (a process without host, an instance
             without process) at the top level, and a note when the model
             deploys nothing.
  Params:  none.
  Errors:  none.
  Provides: fp:deployment-view($model).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:deployment-view" as="xs:string">
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:variable name="binding" as="element(pim:binding)?" select="$model/pim:binding"/>
    <xsl:variable name="devices" as="xs:string*"
        select="distinct-values($binding/pim:link/pim:link-end/@node[empty(key('fp:host', ., root(.)) | key('fp:process', ., root(.)))])"/>
    <xsl:sequence select="fp:lines((
        fp:puml-open('Deployment of model ''' || $model/@name || '''', $fp:deployment-xsl, 'model ''' || $model/@name || ''''),
        $binding/pim:host ! fp:host-node(.),
        $devices ! fp:device-node(., $model),
        $binding/pim:process[not(key('fp:host', @host))] ! fp:process-node(.),
        $binding/pim:component-set[not(key('fp:host', pim:on[@host][1]/@host))] ! fp:set-artifact(.),
        $binding/pim:instance[not(key('fp:process', @execution-environment))] ! fp:instance-box(.),
        if (empty($binding/pim:instance)) then ('note as N_empty', '  The model deploys no component instance.', 'end note') else (),
        $binding/pim:link ! fp:bus-edges(.),
        $binding/pim:component-set ! (for $set in . return key('fp:instance-by-set', @xmi-id)
            ! (fp:puml-alias('s', string($set/@xmi-id)) || ' .[#7f7f7f].&gt; ' || fp:puml-alias('i', string(@name)) || ' : member')),
        fp:puml-close()))"/>
  </xsl:function>

  <xsl:function name="fp:host-node" as="xs:string+">
    <xsl:param name="host" as="element(pim:host)"/>
    <xsl:variable name="facts" as="xs:string" select="string-join((
        $host/@hostname[. ne $host/@name] ! ('hostname ' || .), $host/@address[normalize-space()] ! ('address ' || .),
        $host/@cores ! (. || ' cores'), $host/@memory ! (. || ' MiB'), 'real-time kernel'[$host/@real-time = 'true']), ', ')"/>
    <xsl:variable name="inside" as="xs:string*" select="(
        key('fp:process-by-host', string($host/@xmi-id), root($host)) ! fp:process-node(.),
        key('fp:set-by-host', string($host/@xmi-id), root($host)) ! fp:set-artifact(.))"/>
    <xsl:variable name="head" as="xs:string" select="'node &quot;' || fp:puml-label($host/@name)
        || (if ($facts) then '\n&lt;size:12&gt;' || fp:puml-label($facts) else '') || '&quot; &lt;&lt;host&gt;&gt; as ' || fp:puml-alias('h', string($host/@xmi-id))"/>
    <xsl:sequence select="if (empty($inside)) then $head else ($head || ' {', fp:indent(2, $inside), '}')"/>
  </xsl:function>

  <xsl:function name="fp:device-node" as="xs:string">
    <xsl:param name="id" as="xs:string"/>
    <xsl:param name="model" as="element(pim:model)"/>
    <xsl:sequence select="'node ' || fp:puml-quoted((key('fp:id', $id, root($model))/@name, $id)[1]) || ' &lt;&lt;device&gt;&gt; as '
                          || fp:puml-alias('h', $id)"/>
  </xsl:function>

  <xsl:function name="fp:process-node" as="xs:string+">
    <xsl:param name="process" as="element(pim:process)"/>
    <xsl:variable name="members" as="element(pim:instance)*" select="key('fp:instance-by-ee', $process/@xmi-id, root($process))"/>
    <xsl:variable name="inside" as="xs:string*" select="(
        $process/pim:thread ! fp:thread-frame(.),
        $members[not(@thread = $process/pim:thread/@xmi-id)] ! fp:instance-box(.))"/>
    <xsl:variable name="head" as="xs:string" select="'node ' || fp:puml-quoted($process/@name) || ' &lt;&lt;'
        || fp:puml-label(string-join((($process/@middleware/string(), 'process, middleware of the target')[1], distinct-values($members/@middleware-version),
                                      'managed'[$process/@managed = 'true']), ' ')) || '&gt;&gt; as '
        || fp:puml-alias('e', string($process/@xmi-id))"/>
    <xsl:sequence select="if (empty($inside)) then $head else ($head || ' {', fp:indent(2, $inside), '}')"/>
  </xsl:function>

  <xsl:function name="fp:thread-frame" as="xs:string+">
    <xsl:param name="thread" as="element()"/>
    <xsl:variable name="activity" as="element(pim:activity)?" select="$thread/pim:activity"/>
    <xsl:variable name="facts" as="xs:string" select="string-join((
        $activity/@period ! ('period ' || . || ' s'), $activity/@priority ! ('priority ' || .), $activity/@scheduler), ', ')"/>
    <xsl:variable name="head" as="xs:string" select="'frame &quot;' || fp:puml-label($thread/@name)
        || (if ($facts) then '\n&lt;size:12&gt;' || fp:puml-label($facts) else '') || '&quot; &lt;&lt;thread&gt;&gt; as ' || fp:puml-alias('t', string($thread/@xmi-id))"/>
    <xsl:variable name="members" as="element(pim:instance)*" select="key('fp:instance-by-thread', $thread/@xmi-id, root($thread))"/>
    <xsl:sequence select="if (empty($members)) then $head else ($head || ' {', fp:indent(2, $members ! fp:instance-box(.)), '}')"/>
  </xsl:function>

  <xsl:function name="fp:instance-box" as="xs:string">
    <xsl:param name="instance" as="element(pim:instance)"/>
    <xsl:variable name="type" as="xs:string?"
        select="(key('fp:bc', $instance/@component, root($instance))/@name, key('fp:id', $instance/@component, root($instance))/@name)[1]"/>
    <xsl:sequence select="'component ' || fp:puml-quoted($instance/@name || $type ! (' : ' || .)) || ' as '
                          || fp:puml-alias('i', string($instance/@name))"/>
  </xsl:function>

  <xsl:function name="fp:set-artifact" as="xs:string">
    <xsl:param name="set" as="element(pim:component-set)"/>
    <xsl:sequence select="'artifact ' || fp:puml-quoted($set/@name) || ' &lt;&lt;component set&gt;&gt; as ' || fp:puml-alias('s', string($set/@xmi-id))"/>
  </xsl:function>

  <!-- a bus: one line between its two ends, else a queue joined to each end -->
  <xsl:function name="fp:bus-edges" as="xs:string*">
    <xsl:param name="link" as="element(pim:link)"/>
    <xsl:variable name="facts" as="xs:string" select="string-join(($link/@kind[. ne 'unspecified'], $link/@bandwidth ! (. || ' Mbit/s')), ', ')"/>
    <xsl:variable name="label" as="xs:string" select="'&quot;' || fp:puml-label($link/@name)
        || (if ($facts) then '\n&lt;size:12&gt;' || fp:puml-label($facts) else '') || '&quot;'"/>
    <xsl:variable name="ends" as="xs:string*"
        select="$link/pim:link-end/@node ! fp:puml-alias(if (key('fp:process', ., root(.))) then 'e' else 'h', string(.))"/>
    <xsl:sequence select="
        if (count($ends) eq 2) then $ends[1] || ' -- ' || $ends[2] || ' : ' || $label
        else (for $bus in fp:puml-alias('b', string($link/@xmi-id))
              return ('queue ' || $label || ' &lt;&lt;bus&gt;&gt; as ' || $bus, $ends ! (. || ' -- ' || $bus)))"/>
  </xsl:function>
</xsl:stylesheet>
