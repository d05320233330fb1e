<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/orocos/processes.xsl - the Orocos PSM (psm.xsl): the runtime
  architecture of seed 002 on Orocos: deployer processes, shared threads,
  and the transport of every connection between them.

  Reads:   the bound PIM (pim:binding: pim:process, pim:thread, pim:host,
           pim:instance, pim:connection).
  Writes:  o:process, o:thread-instance helpers, and the transport children
           of o:connection (schemas/psm-orocos/1/psm-orocos.xsd).
  Params:  none.  Keys: those of psm.xsl.
  Provides: fp:oro-processes, fp:oro-process-file, fp:oro-transport,
           fp:oro-legs, fp:oro-thread-instances, fp:oro-single-process.
  Choices (docs/orocos.md, "Processes, threads and transports"):
  - One deployer process per pim:process that holds Orocos instances. A
    package with one process keeps the files deploy/<model>.*; with
    several, each has deploy/<host>_<process>.* (snake case), and each host
    a start script (the text stage).
  - Processes are ordered by their first instance in the start order
    (pim:instance/@start-order); that is the order the start scripts
    start them in, and a connection between two processes on two hosts is
    made by the later one.
  - A transport per writer / reader pair: the same process, local; two
    processes of one host, the MQueue transport (2), each port streaming
    to the queue /<package>_<connection>; two hosts, CORBA: the later
    process loads the other end as a proxy (deployer-corba, naming
    service) and connects the ports; an end on ROS, rtt_roscomm (3) on
    the topic '/' + (policy topic, else the connection name).
  - A thread (pim:thread) is a component of its own, <pkg>::SharedThread,
    named after the thread, with the thread's activity; its members get a
    SlaveActivity whose master it is, and its updateHook runs theirs in
    start order. It starts just before its first member.
  Errors:  ORO014 a connection whose data has no transport between the
           processes of its ends (a data type, an enumeration or an array
           of the model crosses processes: the package's typekit has no
           MQueue / CORBA / ROS transport), or an end on a middleware
           Orocos cannot reach (ROS 2, OpenRTM); names both ends.
           ORO015 a thread named like an instance.
           ORO016 an operation call between two processes.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:o="urn:robomda:psm-orocos:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:key name="fp:process" match="pim:process" use="@xmi-id"/>
  <xsl:key name="fp:instance-by-name" match="pim:instance" use="@name"/>

  <!-- the file name of the deployment of process $p: deploy/<this>.xml -->
  <xsl:function name="fp:oro-process-file" as="xs:string">
    <xsl:param name="process" as="element(pim:process)"/>
    <xsl:variable name="host" as="element(pim:host)?" select="key('fp:host', $process/@host, root($process))"/>
    <xsl:sequence select="string-join(($host/@name, $process/@name) ! f:snake-case(.), '_')"/>
  </xsl:function>

  <!-- the processes that hold instances of $instances, in start order -->
  <xsl:function name="fp:oro-process-order" as="element(pim:process)*">
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:variable name="binding" as="element(pim:binding)?" select="$instances[1]/.."/>
    <!-- process id -> the earliest start order of its instances (one pass, not a scan per process) -->
    <xsl:variable name="first" as="map(xs:string, xs:integer)">
      <xsl:map>
        <xsl:for-each-group select="$instances" group-by="@execution-environment">
          <xsl:map-entry key="string(current-grouping-key())" select="min(current-group()/xs:integer((@start-order, 999999)[1]))"/>
        </xsl:for-each-group>
      </xsl:map>
    </xsl:variable>
    <xsl:perform-sort select="$binding/pim:process[map:contains($first, string(@xmi-id))]">
      <xsl:sort select="$first(string(@xmi-id))"/>
    </xsl:perform-sort>
  </xsl:function>

  <!-- true when the Orocos instances $instances run in one process -->
  <xsl:function name="fp:oro-single-process" as="xs:boolean">
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:sequence select="count(distinct-values($instances/@execution-environment)) le 1"/>
  </xsl:function>

  <!-- o:process per process of $instances (the Orocos ones), with its
       host's name, its file, its place in the start order and whether it
       takes part in CORBA ($corba: the package has several processes or
       a CORBA link: the start scripts read every component's state over
       CORBA) -->
  <xsl:function name="fp:oro-processes" as="element(o:process)*">
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:param name="corba" as="xs:boolean"/>
    <xsl:param name="ros" as="xs:string*"/><!-- names of the processes with a ROS stream -->
    <xsl:variable name="single" as="xs:boolean" select="fp:oro-single-process($instances)"/>
    <!-- thread id -> its instances (one pass, not a scan per thread) -->
    <xsl:variable name="members" as="map(xs:string, element(pim:instance)+)">
      <xsl:map>
        <xsl:for-each-group select="$instances" group-by="@thread">
          <xsl:map-entry key="string(current-grouping-key())" select="current-group()"/>
        </xsl:for-each-group>
      </xsl:map>
    </xsl:variable>
    <xsl:for-each select="fp:oro-process-order($instances)">
      <xsl:variable name="host" as="element(pim:host)?" select="key('fp:host', @host, root(.))"/>
      <o:process xmi-id="{@xmi-id}" name="{@name}" position="{position()}"
                 file="{if ($single) then f:snake-case(root(.)/pim:model/@name) else fp:oro-process-file(.)}"
                 corba="{$corba}" ros="{@name = $ros}" start-script="start_{f:snake-case(($host/@name, 'localhost')[1])}.sh">
        <xsl:if test="$host">
          <xsl:attribute name="host" select="$host/@name"/>
          <xsl:attribute name="address" select="$host/@address"/>
        </xsl:if>
        <xsl:for-each select="pim:thread">
          <o:thread xmi-id="{@xmi-id}" name="{@name}"
                    members="{fp:in-start-order($members(string(@xmi-id))) ! string(@name)}"/>
        </xsl:for-each>
      </o:process>
    </xsl:for-each>
  </xsl:function>

  <!-- the transport between instances $a and $b: local, mqueue, corba,
       ros; () when Orocos cannot reach $b's middleware ($a is Orocos) -->
  <xsl:function name="fp:oro-transport" as="xs:string?">
    <xsl:param name="a" as="element(pim:instance)"/>
    <xsl:param name="b" as="element(pim:instance)"/>
    <xsl:param name="on-target" as="xs:boolean"/><!-- $b is in the package -->
    <xsl:sequence select="
        if (not($on-target)) then (if ($b/@middleware eq 'ROS') then 'ros' else ())
        else if ($a/@execution-environment eq $b/@execution-environment) then 'local'
        else if (string($a/@host) eq string($b/@host)) then 'mqueue'
        else 'corba'"/>
  </xsl:function>

  <!-- the transport children of the o:connection of $connection: o:stream
       per port that streams (MQueue, ROS), o:remote per CORBA pair, made
       in the later process of the two ($order: each process id's place
       in start order, a look-up per pair); ORO014 for a pair no transport
       joins -->
  <xsl:function name="fp:oro-legs" as="element()*">
    <xsl:param name="connection" as="element(pim:connection)"/>
    <xsl:param name="targets" as="map(xs:string, xs:boolean)"/>
    <xsl:param name="order" as="map(xs:string, xs:integer)"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:param name="transportable" as="xs:boolean"/><!-- the data has MQueue / CORBA / ROS transports -->
    <xsl:variable name="root" as="document-node()" select="root($connection)"/>
    <xsl:variable name="topic" as="xs:string" select="($connection/pim:policy/@topic[normalize-space(.)], $connection/@name)[1]"/>
    <xsl:variable name="pairs" as="element()*">
      <xsl:for-each select="$connection/pim:writer, $connection/pim:reader">
        <xsl:variable name="end" as="element()" select="."/>
        <xsl:variable name="me" as="element(pim:instance)" select="key('fp:instance-by-name', @instance, $root)"/>
        <xsl:if test="map:contains($targets, string(@instance))">
          <xsl:for-each select="if (self::pim:writer) then ../pim:reader else ../pim:writer">
            <xsl:variable name="other" as="element(pim:instance)" select="key('fp:instance-by-name', @instance, $root)"/>
            <xsl:variable name="transport" as="xs:string?" select="fp:oro-transport($me, $other, map:contains($targets, string(@instance)))"/>
            <fp:pair transport="{($transport, 'none')[1]}" me="{$me/@name}" my-port="{$end/@data-port}" my-port-id="{$end/@port}"
                     other="{$other/@name}" other-port="{@data-port}" direction="{local-name($end)}"
                     my-process="{$me/@execution-environment}" other-process="{$other/@execution-environment}"
                     other-middleware="{$other/@middleware}"/>
          </xsl:for-each>
        </xsl:if>
      </xsl:for-each>
    </xsl:variable>
    <xsl:for-each select="$pairs[@transport eq 'none' or (@transport ne 'local' and not($transportable))][1]">
      <xsl:sequence select="f:fail('ORO014', string(@my-port-id), 'connection ''' || $connection/@name || ''' joins '
          || @me || '.' || @my-port || ' to ' || @other || '.' || @other-port
          || (if (@transport eq 'none') then ', which runs on ' || @other-middleware || ': Orocos RTT reaches ROS 1 (rtt_roscomm) only'
              else ' in another process (' || @transport || '): its data type has no transport there; the generated typekit'
                   || ' marshals it inside a process only; carry numbers, booleans or strings between processes'))"/>
    </xsl:for-each>
    <!-- one stream per port (MQueue, ROS) -->
    <xsl:for-each-group select="$pairs[@transport = ('mqueue', 'ros')]" group-by="@me || '.' || @my-port || '|' || @transport">
      <o:stream instance="{@me}" port="{@my-port}" direction="{if (@direction eq 'writer') then 'out' else 'in'}"
                process="{@my-process}" transport="{@transport}" transport-code="{if (@transport eq 'ros') then 3 else 2}"
                name-id="{if (@transport eq 'ros') then (if (starts-with($topic, '/')) then $topic else '/' || $topic)
                          else '/' || $package || '_' || $connection/@name}"/>
    </xsl:for-each-group>
    <!-- one CORBA link per writer / reader pair, made by the later process -->
    <xsl:for-each select="$pairs[@transport eq 'corba'][@direction eq 'writer']">
      <xsl:variable name="later-is-me" as="xs:boolean" select="$order(string(@my-process)) gt $order(string(@other-process))"/>
      <o:remote process="{if ($later-is-me) then @my-process else @other-process}" proxy="{if ($later-is-me) then @other else @me}"
                writer="{@me}" writer-port="{@my-port}" reader="{@other}" reader-port="{@other-port}"/>
    </xsl:for-each>
  </xsl:function>

  <!-- ORO015 a thread named like an instance; ORO016 a call between
       processes. $names: the names of $instances as a set; the processes
       of $instances likewise (a look-up each, not a scan of every instance
       per process, thread and call) -->
  <xsl:function name="fp:oro-process-problems" as="empty-sequence()">
    <xsl:param name="instances" as="element(pim:instance)*"/>
    <xsl:param name="names" as="map(xs:string, xs:boolean)"/>
    <xsl:param name="calls" as="element(pim:call)*"/>
    <xsl:variable name="root" as="document-node()?" select="root($instances[1])"/>
    <xsl:variable name="processes" as="map(xs:string, xs:boolean)"
        select="map:merge(distinct-values($instances/@execution-environment ! string(.)) ! map:entry(., true()))"/>
    <xsl:for-each select="$instances[1]/../pim:process[@xmi-id ! map:contains($processes, string(.))]
                          /pim:thread[@name ! map:contains($names, string(.))]">
      <xsl:sequence select="f:fail('ORO015', string(@xmi-id), 'thread ''' || @name || ''' has the name of an instance: the thread'
          || ' is a component of the deployment (SharedThread) named after it; rename one')"/>
    </xsl:for-each>
    <xsl:for-each select="$calls[some $i in pim:caller/@instance satisfies map:contains($names, string($i))]
                                [some $i in pim:provider/@instance satisfies map:contains($names, string($i))]">
      <xsl:if test="key('fp:instance-by-name', pim:caller/@instance, $root)/@execution-environment
                    ne key('fp:instance-by-name', pim:provider/@instance, $root)/@execution-environment">
        <xsl:sequence select="f:fail('ORO016', string(@xmi-id), 'instance ''' || pim:caller/@instance || ''' calls operations of '''
            || pim:provider/@instance || ''', which runs in another process: operation calls do not cross Orocos processes here;'
            || ' deploy both in one process, or exchange the data through data ports')"/>
      </xsl:if>
    </xsl:for-each>
  </xsl:function>
  <!-- ========================================================= threads -->
  <!-- the task context of the threads, <pkg>::SharedThread, when the
       processes $processes have threads -->
  <xsl:function name="fp:oro-thread-task-context" as="element(o:task-context)?">
    <xsl:param name="processes" as="element(o:process)*"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:for-each select="($processes/o:thread)[1]">
      <o:task-context xmi-id="{@xmi-id}" name="SharedThread" class="SharedThread" namespace="{$package}"
                      type-name="{$package}::SharedThread" kind="thread" generated-class="SharedThread">
        <o:doc>A thread that components share (seed 002): its activity runs the updateHook of each member, a component with a SlaveActivity whose master it is, in the order of property members.</o:doc>
        <xsl:for-each select="'configure', 'start', 'update', 'stop', 'cleanup'">
          <o:hook name="{.}"/>
        </xsl:for-each>
        <o:property xmi-id="{@xmi-id}" name="members" member="members_" cpp-default="&quot;&quot;"
                    primitive="string" cpp-type="std::string" xml-type="string" script-default="&quot;&quot;"/>
      </o:task-context>
    </xsl:for-each>
  </xsl:function>

  <!-- the o:instance of thread $thread of process $process, its activity
       the thread's ($activity), its members its peers -->
  <xsl:function name="fp:oro-thread-instance" as="element(o:instance)">
    <xsl:param name="thread" as="element(o:thread)"/>
    <xsl:param name="activity" as="element(pim:activity)"/>
    <xsl:param name="package" as="xs:string"/>
    <xsl:param name="server" as="xs:boolean"/>
    <o:instance xmi-id="{$thread/@xmi-id}" name="{$thread/@name}" task-context="SharedThread"
                type-name="{$package}::SharedThread" process="{$thread/../@file}" server="{$server}" role="thread">
      <xsl:sequence select="fp:oro-activity($activity, ())"/>
      <xsl:for-each select="tokenize($thread/@members)">
        <o:peer instance="{.}"/>
      </xsl:for-each>
      <o:property-value name="members" xml-type="string" value="{$thread/@members}" script-value="&quot;{$thread/@members}&quot;"/>
    </o:instance>
  </xsl:function>

  <!-- o:activity of pim:activity $a; a member of thread $master gets a
       SlaveActivity (the values are the thread's, for the record) -->
  <xsl:function name="fp:oro-activity" as="element(o:activity)">
    <xsl:param name="activity" as="element(pim:activity)"/>
    <xsl:param name="master" as="xs:string?"/>
    <o:activity type="{if ($master) then 'SlaveActivity' else 'Activity'}" periodic="{number($activity/@period) ne 0}"
                period="{$activity/@period}" priority="{$activity/@priority}" scheduler="ORO_SCHED_{$activity/@scheduler}"
                cpu-affinity="{$activity/@cpu-affinity}">
      <xsl:if test="$master"><xsl:attribute name="master" select="$master"/></xsl:if>
    </o:activity>
  </xsl:function>
</xsl:stylesheet>
