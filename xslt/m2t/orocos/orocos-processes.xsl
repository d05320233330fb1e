<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/orocos/orocos-processes.xsl - one deployment per process, and a
  start script per host (seed 002).

  Reads:   o:deployment of urn:robomda:psm-orocos:1 (its o:process,
           o:connection transports, o:instance/@process).
  Writes:  fp:process-view: the deployment of one process, an o:deployment
           that orocos-deploy.xsl writes as it writes a whole one (never
           validated, never written out); fp:start-script: the text of
           deploy/start_<host>.sh.
  Params:  none.  Errors: none.
  Keys:    fp:view-end (on a view's connections), fp:instance-in and
           fp:connection-in (on the PSM: a process's instances and
           connections, so that each view reads only its own).

  The view of process P: @deploy-name its file; the library and typekit;
  its connections: the part of each connection point inside P (writers
  and readers of P, when it has both), one single-port connection per
  stream of a port of P (MQueue or ROS: @transport-code, @name-id), one
  connection per CORBA link P makes (@proxy: the far instance, loaded as a
  proxy, o:proxy); its instances, with their ports mapped to those
  connections and only the peers that run in P.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:o="urn:robomda:psm-orocos:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- the ends of the connections of a view, by instance (fp:port-connections) -->
  <xsl:key name="fp:view-end" match="o:connection/o:writer | o:connection/o:reader" use="@instance"/>
  <!-- on the PSM: the instances of a process, and the connections with a
       writer, stream or CORBA link in it (by the process's file), so that
       a process's view reads its own, not every instance and connection -->
  <xsl:key name="fp:instance-in" match="o:deployment/o:instance" use="@process"/>
  <xsl:key name="fp:connection-in" match="o:deployment/o:connection"
           use="o:writer/@process, o:stream/@process, o:remote/@process"/>

  <xsl:function name="fp:process-view" as="element(o:deployment)">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:param name="process" as="element(o:process)"/>
    <xsl:variable name="p" as="xs:string" select="$process/@file"/>
    <!-- in a document of their own, for key fp:view-end -->
    <xsl:variable name="view-connections" as="document-node()">
      <xsl:document>
      <xsl:for-each select="fp:in-process('fp:connection-in', $deployment, $p)">
        <xsl:if test="o:writer[@process eq $p] and o:reader[@process eq $p]">
          <o:connection>
            <xsl:sequence select="@*, o:writer[@process eq $p], o:reader[@process eq $p]"/>
          </o:connection>
        </xsl:if>
        <xsl:for-each select="o:stream[@process eq $p]">
          <o:connection>
            <xsl:sequence select="../@*"/>
            <xsl:attribute name="name" select="../@name || '_' || @instance || '_' || @port"/>
            <xsl:sequence select="@transport, @transport-code, @name-id"/>
            <xsl:element name="{if (@direction eq 'out') then 'o:writer' else 'o:reader'}">
              <xsl:sequence select="@instance, @port"/>
            </xsl:element>
          </o:connection>
        </xsl:for-each>
        <xsl:for-each select="o:remote[@process eq $p]">
          <o:connection>
            <xsl:sequence select="../@*"/>
            <xsl:attribute name="name" select="../@name || '_' || @proxy"/>
            <xsl:sequence select="@proxy"/>
            <o:writer instance="{@writer}" port="{@writer-port}"/>
            <o:reader instance="{@reader}" port="{@reader-port}"/>
          </o:connection>
        </xsl:for-each>
      </xsl:for-each>
      </xsl:document>
    </xsl:variable>
    <xsl:variable name="connections" as="element(o:connection)*" select="$view-connections/o:connection"/>
    <xsl:variable name="instances" as="element(o:instance)*" select="fp:in-process('fp:instance-in', $deployment, $p)"/>
    <o:deployment>
      <xsl:sequence select="$deployment/@*"/>
      <xsl:attribute name="deploy-name" select="$p"/>
      <xsl:attribute name="process" select="$process/@name"/>
      <xsl:attribute name="processes" select="count($deployment/o:process)"/>
      <xsl:sequence select="$process/(@host, @corba, @start-script)"/>
      <xsl:if test="$process/@corba = 'true'">
        <xsl:attribute name="naming" select="($deployment/o:process/@address, 'localhost')[1]"/>
      </xsl:if>
      <xsl:sequence select="$deployment/(o:library, o:types), $connections"/>
      <xsl:for-each select="distinct-values($connections/@proxy)">
        <o:proxy name="{.}">
          <xsl:sequence select="fp:port-connections(., $view-connections)"/>
        </o:proxy>
      </xsl:for-each>
      <xsl:for-each select="$instances">
        <xsl:copy>
          <xsl:sequence select="@*, o:activity, o:peer[@instance = $instances/@name], o:call"/>
          <xsl:sequence select="fp:port-connections(@name, $view-connections)"/>
          <xsl:sequence select="o:property-value, o:start-after"/>
        </xsl:copy>
      </xsl:for-each>
    </o:deployment>
  </xsl:function>

  <!-- the children of $deployment that key $key finds for process file $p
       (fp:instance-in: its instances; fp:connection-in: the connections
       that may have a part in it), in document order -->
  <xsl:function name="fp:in-process" as="element()*">
    <xsl:param name="key" as="xs:string"/>
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:param name="p" as="xs:string"/>
    <xsl:sequence select="if (root($deployment) instance of document-node())
                          then key($key, $p, root($deployment))[.. is $deployment]
                          else if ($key eq 'fp:instance-in') then $deployment/o:instance[@process eq $p]
                          else $deployment/o:connection"/>
  </xsl:function>

  <!-- o:port-connection of each port of instance $name in the connections
       of a view, in their order -->
  <xsl:function name="fp:port-connections" as="element(o:port-connection)*">
    <xsl:param name="name" as="xs:string"/>
    <xsl:param name="connections" as="document-node()"/>
    <xsl:for-each-group select="key('fp:view-end', $name, $connections)" group-by="../@name || '|' || @port">
      <o:port-connection port="{@port}" connection="{../@name}"/>
    </xsl:for-each-group>
  </xsl:function>

  <!-- the command that runs deployment file $file of $view; $naming: the
       naming service's host (an address, or a shell variable) -->
  <xsl:function name="fp:deployer-command" as="xs:string">
    <xsl:param name="view" as="element(o:deployment)"/>
    <xsl:param name="file" as="xs:string"/>
    <xsl:param name="naming" as="xs:string"/>
    <xsl:sequence select="if ($view/@corba = 'true')
        then 'deployer-corba --DeployerName ' || $view/@deploy-name || ' -s ' || $file || ' -- -ORBInitRef NameService=corbaname::' || $naming
        else 'deployer -s ' || $file"/>
  </xsl:function>

  <!-- the naming service's host of a deployment that uses CORBA: the
       address of the first process's host -->
  <xsl:function name="fp:naming-address" as="xs:string">
    <xsl:param name="view" as="element(o:deployment)"/>
    <xsl:sequence select="string(($view/@naming, 'localhost')[1])"/>
  </xsl:function>

  <!-- ================================================== start script -->
  <!-- deploy/start_<host>.sh: starts the processes of host $host (in
       o:process order, the start order) with the deployment format given
       as $1 (lua, default; xml; ops), waits for the CORBA components of
       other processes it connects to, and stops them all on Ctrl-C -->
  <xsl:function name="fp:start-script" as="xs:string">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:param name="host" as="element(o:host)?"/>
    <xsl:param name="processes" as="element(o:process)+"/>
    <xsl:variable name="corba" as="xs:boolean" select="$processes[1]/@corba = 'true'"/>
    <xsl:variable name="naming" as="element(o:process)?" select="($deployment/o:process[@corba = 'true'])[1]"/>
    <xsl:sequence select="fp:lines((
        '#!/bin/sh',
        fp:banner('# ', $fp:deploy-xsl, 'the start script of host ''' || ($host/@name, 'localhost')[1] || ''' of model '''
                  || $deployment/@model-name || '''', false()),
        fp:host-lines($host) ! ('# ' || .),
        '# Starts the Orocos processes of this host in the modelled sequence:',
        $processes ! ('#   ' || @position || '. ' || @file || ' (process ''' || @name || ''')'),
        '# Usage: ' || $processes[1]/@start-script || ' [lua|xml|ops]   (default lua; the deployment file format)',
        '# Runs until Ctrl-C (or SIGTERM), then stops every process it started.',
        if ($corba) then (
          '# CORBA: every component registers with the naming service on the host of NAMESERVICE',
          '# (default ' || $naming/@address || ', host ''' || $naming/@host || ''', where '
          || $naming/@start-script || ' starts omniNames when none answers).') else (),
        'set -e',
        'here=$(cd &quot;$(dirname &quot;$0&quot;)&quot; &amp;&amp; pwd)',
        'format=${1:-lua}',
        'case &quot;$format&quot; in lua|xml|ops) ;; *) echo &quot;usage: $0 [lua|xml|ops]&quot; &gt;&amp;2; exit 2 ;; esac',
        if ($corba) then (
          'NAMESERVICE=${NAMESERVICE:-' || $naming/@address || '}',
          'ORB=&quot;-ORBInitRef NameService=corbaname::$NAMESERVICE&quot;',
          'named() { nameclt $ORB list TaskContexts 2&gt;/dev/null | grep -qx &quot;$1&quot;; }',
          '# wait_for PID NAME...: until the components NAME are in the naming service (PID: the process',
          '# that makes them, - for another host''s); 60 s at most',
          'wait_for() {',
          '  pid=$1; shift',
          '  for c in &quot;$@&quot;; do',
          '    n=0',
          '    until named &quot;$c&quot;; do',
          '      if [ &quot;$pid&quot; != - ] &amp;&amp; ! kill -0 &quot;$pid&quot; 2&gt;/dev/null; then echo &quot;$0: the process of $c ended&quot; &gt;&amp;2; exit 1; fi',
          '      n=$((n + 1)); if [ $n -gt 600 ]; then echo &quot;$0: $c not in the naming service after 60 s&quot; &gt;&amp;2; exit 1; fi',
          '      sleep 0.1',
          '    done',
          '  done',
          '}') else (),
        'pids=&quot;&quot;',
        'ns=&quot;&quot;',
        'alive() { for p in $pids; do kill -0 &quot;$p&quot; 2&gt;/dev/null &amp;&amp; return 0; done; return 1; }',
        '# Ctrl-C: each deployer stops and unloads its components; one that hangs (a CORBA peer gone) is',
        '# killed after 10 s; the naming service last',
        'stop() {',
        '  trap - INT TERM EXIT',
        '  [ -z &quot;$pids&quot; ] || kill -INT $pids 2&gt;/dev/null || true',
        '  n=0; while alive &amp;&amp; [ $n -lt 100 ]; do sleep 0.1; n=$((n + 1)); done',
        '  [ -z &quot;$pids&quot; ] || kill -KILL $pids 2&gt;/dev/null || true',
        '  [ -z &quot;$ns&quot; ] || kill $ns 2&gt;/dev/null || true',
        '  wait',
        '}',
        'trap stop INT TERM EXIT',
        'cd &quot;$here&quot;',
        if ($naming and string($naming/@host) eq string($host/@name)) then (
          'if ! nameclt $ORB list &gt;/dev/null 2&gt;&amp;1; then',
          '  mkdir -p &quot;${TMPDIR:-/tmp}/omninames-$$&quot;',
          '  port=2809; case &quot;$NAMESERVICE&quot; in *:*) port=${NAMESERVICE##*:} ;; esac',
          '  omniNames -start $port -logdir &quot;${TMPDIR:-/tmp}/omninames-$$&quot; &gt;/dev/null 2&gt;&amp;1 &amp;',
          '  ns=$!',
          '  until nameclt $ORB list &gt;/dev/null 2&gt;&amp;1; do sleep 0.1; done',
          'fi') else (),
        $processes ! (
          let $process := .,
              $remote := distinct-values(fp:in-process('fp:connection-in', $deployment, $process/@file)/o:remote[@process eq $process/@file]/@proxy)
          return (
            '',
            '# ' || @position || '. process ''' || @name || '''',
            if (exists($remote)) then 'wait_for - ' || string-join($remote, ' ') else (),
            fp:deployer-command(fp:process-view($deployment, .), @file || '.$format', '$NAMESERVICE') || ' &lt;/dev/null &amp;',
            'pids=&quot;$pids $!&quot;',
            if ($corba) then 'wait_for $! ' || string-join(fp:in-process('fp:instance-in', $deployment, $process/@file)/@name, ' ') else ())),
        '',
        'wait'))"/>
  </xsl:function>
</xsl:stylesheet>
