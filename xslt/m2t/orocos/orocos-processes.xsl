<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/orocos/orocos-processes.xsl - one deployment per process, and a
  start script per host (seed 002).

  Reads:   o:deployment of urn:robomda:psm-orocos:1 (its o:process,
           o:connection transports, o:instance/@process).
  Writes:  fp:process-view: the deployment of one process, an o:deployment
           that orocos-deploy.xsl writes as it writes a whole one (never
           validated, never written out); fp:start-script: the text of
           deploy/start_<host>.sh (processes in start order, each once the
           components before it are Running; stopped in reverse order);
           fp:start-helper: deploy/start-helper.lua, the rttlua-corba
           client those scripts run to wait for a component's Running
           state and to stop a process's components before it ends.
  Params:  none.  Errors: none.
  Keys:    fp:view-end (on a view's connections), fp:instance-in,
           fp:connection-in, fp:process-at and fp:host-named (on the PSM:
           a process's instances and connections, so that each view reads
           only its own; the process before another and the host of a
           start script).

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
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
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
  <!-- the process at a place in the start order (a start script's process before another) -->
  <xsl:key name="fp:process-at" match="o:deployment/o:process" use="@position"/>
  <!-- a host by its name (the host of a start script) -->
  <xsl:key name="fp:host-named" match="o:deployment/o:host" use="@name"/>

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
    <!-- their names as a set: whether a peer runs in $p is one look-up, not
         a comparison with every instance of the process (issue 35) -->
    <xsl:variable name="names" as="map(xs:string, xs:boolean)"
        select="map:merge(distinct-values($instances/@name ! string(.)) ! map:entry(., true()))"/>
    <o:deployment>
      <xsl:sequence select="$deployment/@*"/>
      <xsl:attribute name="deploy-name" select="$p"/>
      <xsl:attribute name="process" select="$process/@name"/>
      <xsl:attribute name="processes" select="count($deployment/o:process)"/>
      <xsl:sequence select="$process/(@host, @address, @corba, @start-script)"/>
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
          <xsl:sequence select="@*, o:activity, o:peer[map:contains($names, string(@instance))], o:call"/>
          <xsl:sequence select="fp:port-connections(@name, $view-connections)"/>
          <xsl:sequence select="o:property-value, o:start-after"/>
        </xsl:copy>
      </xsl:for-each>
      <!-- the job coordinators of this process (orocos-jobs.xsl) -->
      <xsl:sequence select="$deployment/o:coordinator[@process eq $p]"/>
    </o:deployment>
  </xsl:function>

  <!-- the children of $deployment that key $key finds for $p
       (fp:instance-in: the instances of process file $p; fp:connection-in:
       the connections that may have a part in it; fp:process-at: the
       process at position $p; fp:host-named: the host named $p), in
       document order. $deployment is the PSM's document element
       (main.xsl), never a view, so there is no fallback for an
       o:deployment outside a document: a scan of every instance or
       connection per process would make the cost of the views grow with
       the square of the deployment -->
  <xsl:function name="fp:in-process" as="element()*">
    <xsl:param name="key" as="xs:string"/>
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:param name="p" as="xs:string"/>
    <xsl:sequence select="key($key, $p, root($deployment))[.. is $deployment]"/>
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
       naming service's host (an address, or a shell variable); $address:
       the address the process's CORBA objects listen on (omniORB
       -ORBendPoint: its host's modelled address, or a shell variable), ''
       for the interface omniORB picks -->
  <xsl:function name="fp:deployer-command" as="xs:string">
    <xsl:param name="view" as="element(o:deployment)"/>
    <xsl:param name="file" as="xs:string"/>
    <xsl:param name="naming" as="xs:string"/>
    <xsl:param name="address" as="xs:string"/>
    <xsl:sequence select="if ($view/@corba = 'true')
        then 'deployer-corba --DeployerName ' || $view/@deploy-name || ' -s ' || $file || ' -- -ORBInitRef NameService=corbaname::' || $naming
             || (if ($address ne '') then ' -ORBendPoint giop:tcp:' || $address || ':' else '')
        else 'deployer -s ' || $file"/>
  </xsl:function>

  <!-- the naming service's host of a deployment that uses CORBA: the
       address of the first process's host -->
  <xsl:function name="fp:naming-address" as="xs:string">
    <xsl:param name="view" as="element(o:deployment)"/>
    <xsl:sequence select="string(($view/@naming, 'localhost')[1])"/>
  </xsl:function>

  <!-- deploy/start-helper.lua: the CORBA client the start scripts run
       (rttlua-corba) to wait until components are Running and to stop the
       components of a process before it ends -->
  <xsl:function name="fp:start-helper" as="xs:string">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:sequence select="fp:lines((
        fp:banner('-- ', $fp:deploy-xsl, 'the start scripts of model ''' || $deployment/@model-name || '''', false()),
        '-- A CORBA client of the naming service that the start scripts (start_&lt;host&gt;.sh) run under rttlua-corba,',
        '-- the ORB options after --:',
        '--   rttlua-corba start-helper.lua wait SECONDS PID NAME... -- -ORBInitRef NameService=corbaname::HOST',
        '--     waits until every component NAME is Running; fails, naming the component and its state, after',
        '--     SECONDS, or as soon as process PID ends (-: the components of another host)',
        '--   rttlua-corba start-helper.lua stop DEPLOYER NAME... -- -ORBInitRef NameService=corbaname::HOST',
        '--     stops the components NAME of deployer process DEPLOYER (its --DeployerName) in the order given, the',
        '--     reverse start order, disconnects their ports (those connected to other processes too, while both',
        '--     ends still run), cleans them up, and tells the deployer to leave what is loaded when it ends (it',
        '--     would try to unload the proxies of components of other processes, and fail while those run)',
        '-- Its last line is its verdict, START-HELPER OK or START-HELPER FAILED: ...; exit status 0 or 1.',
        'require(&quot;rttlib&quot;)',
        'rttlib.color = false',
        '',
        'local depl = rtt.getTC():getPeer(&quot;Deployer&quot;)',
        '-- this client''s proxies stay loaded when it ends (never unloaded while their components run)',
        'depl:getProperty(&quot;AutoUnload&quot;):set(false)',
        'local function finish(ok, why)',
        '  print(ok and &quot;START-HELPER OK&quot; or (&quot;START-HELPER FAILED: &quot; .. why))',
        '  io.stdout:flush()',
        '  -- the ORB down first, and its thread given time to end: os.exit with it running never returns,',
        '  -- and right after shutdown it may crash',
        '  depl:getOperation(&quot;shutdown&quot;)()',
        '  rtt.sleep(0, 500000000)',
        '  os.exit(ok and 0 or 1)',
        'end',
        'local function proxy(name)',
        '  local ok, c = pcall(depl.getPeer, depl, name)',
        '  if ok then return c end',
        '  if depl:loadComponent(name, &quot;CORBA&quot;) then return depl:getPeer(name) end',
        '  return nil',
        'end',
        '',
        'if arg[1] == &quot;wait&quot; then',
        '  local seconds, pid = tonumber(arg[2]), arg[3]',
        '  for i = 4, #arg do',
        '    local name, state, tenths = arg[i], &quot;not in the naming service&quot;, 0',
        '    while true do',
        '      local c = proxy(name)',
        '      if c then state = c:getState() end',
        '      if state == &quot;Running&quot; then break end',
        '      if pid ~= &quot;-&quot; and os.execute(&quot;kill -0 &quot; .. pid .. &quot; 2&gt;/dev/null&quot;) ~= 0 then',
        '        finish(false, &quot;the process of component &quot; .. name .. &quot; ended (&quot; .. name .. &quot; was &quot; .. state .. &quot;)&quot;)',
        '      end',
        '      if tenths &gt;= seconds * 10 then',
        '        finish(false, &quot;component &quot; .. name .. &quot; is not Running after &quot; .. seconds .. &quot; s (it is &quot; .. state .. &quot;)&quot;)',
        '      end',
        '      rtt.sleep(0, 100000000)',
        '      tenths = tenths + 1',
        '    end',
        '    print(&quot;START-HELPER &quot; .. name .. &quot; Running&quot;)',
        '  end',
        '  finish(true)',
        'elseif arg[1] == &quot;stop&quot; then',
        '  local remote = proxy(arg[2])',
        '  if not remote then finish(false, &quot;no deployer &quot; .. tostring(arg[2]) .. &quot; in the naming service&quot;) end',
        '  local failed, comps = {}, {}',
        '  for i = 3, #arg do',
        '    comps[i] = proxy(arg[i])',
        '    if not comps[i] then failed[#failed + 1] = arg[i] .. &quot; not in the naming service&quot; end',
        '  end',
        '  for i = 3, #arg do',
        '    local c = comps[i]',
        '    if c and c:getState() == &quot;Running&quot; and not c:stop() then failed[#failed + 1] = &quot;stop &quot; .. arg[i] end',
        '  end',
        '  -- every port disconnected, those connected to other processes too, while both ends run',
        '  for i = 3, #arg do',
        '    local c = comps[i]',
        '    for _, p in ipairs(c and c:getPortNames() or {}) do',
        '      if not pcall(function() c:getPort(p):disconnect() end) then failed[#failed + 1] = &quot;disconnect &quot; .. arg[i] .. &quot;.&quot; .. p end',
        '    end',
        '  end',
        '  for i = 3, #arg do',
        '    local c = comps[i]',
        '    if c and c:getState() == &quot;Stopped&quot; and not c:cleanup() then failed[#failed + 1] = &quot;cleanup &quot; .. arg[i] end',
        '  end',
        '  -- what is left for the deployer to unload as it ends: its components, stopped and cleaned up, and the',
        '  -- proxies of components of other processes, which it refuses to unload while those run: it leaves them',
        '  if #failed == 0 then remote:getProperty(&quot;AutoUnload&quot;):set(false) end',
        '  finish(#failed == 0, table.concat(failed, &quot;, &quot;))',
        'else',
        '  finish(false, &quot;usage: start-helper.lua wait SECONDS PID NAME... | stop DEPLOYER NAME...&quot;)',
        'end'))"/>
  </xsl:function>

  <!-- ================================================== start script -->
  <!-- deploy/start_<host>.sh: starts the processes of host $host (in
       o:process order, the start order) with the deployment format given
       as $1 (lua, default; xml; ops); before each, waits until every
       component of the processes before it on other hosts is Running, and
       after it, until its own are (start-helper.lua); on Ctrl-C / SIGTERM
       stops them in the reverse order, each process's components first -->
  <xsl:function name="fp:start-script" as="xs:string">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:param name="host" as="element(o:host)?"/>
    <xsl:param name="processes" as="element(o:process)+"/>
    <xsl:variable name="naming" as="element(o:process)" select="($deployment/o:process[@corba = 'true'], $processes[1])[1]"/>
    <xsl:variable name="script" as="xs:string" select="string($processes[1]/@start-script)"/>
    <xsl:sequence select="fp:lines((
        '#!/bin/sh',
        fp:banner('# ', $fp:deploy-xsl, 'the start script of host ''' || ($host/@name, 'localhost')[1] || ''' of model '''
                  || $deployment/@model-name || '''', false()),
        fp:host-lines($host) ! ('# ' || .),
        '# Starts the Orocos processes of this host in the modelled sequence:',
        $processes ! ('#   ' || @position || '. ' || @file || ' (process ''' || @name || ''')'),
        '# Usage: ' || $script || ' [lua|xml|ops]   (default lua; the deployment file format)',
        '# Before a process starts, every component of the processes before it on other hosts is Running;',
        '# after it, the next waits until its own components are Running (start-helper.lua, a CORBA client).',
        '# Runs until Ctrl-C (or SIGTERM), then stops the processes in the reverse order: the components of',
        '# each first (reverse start order; what they connect to in other processes is disconnected while',
        '# both ends run), then the process. Stop the hosts in the reverse order of their processes too.',
        '# Every component registers with the naming service on host ''' || $naming/@host || ''', where '
          || $naming/@start-script || ' starts omniNames when none answers.',
        '# Environment:',
        '#   NAMESERVICE  host[:port] of the naming service (default ' || $naming/@address || ')',
        '#   ADDRESS      the address this host''s processes listen on (omniORB -ORBendPoint giop:tcp:ADDRESS:;',
        '#                default the modelled ' || ($host/@address[. ne ''], 'none: the interface omniORB picks')[1] || ')',
        '#   LOGDIR       the folder of the logs: each process writes LOGDIR/&lt;process file&gt;.log (default: this folder)',
        '#   WAIT         seconds to wait for the naming service or a component (default 60)',
        'set -e',
        'here=$(cd &quot;$(dirname &quot;$0&quot;)&quot; &amp;&amp; pwd)',
        'format=${1:-lua}',
        'case &quot;$format&quot; in lua|xml|ops) ;; *) echo &quot;usage: $0 [lua|xml|ops]&quot; &gt;&amp;2; exit 2 ;; esac',
        'NAMESERVICE=${NAMESERVICE:-' || $naming/@address || '}',
        'ADDRESS=${ADDRESS-' || $host/@address || '}',
        'LOGDIR=${LOGDIR:-$here}',
        'WAIT=${WAIT:-60}',
        'ORB=&quot;-ORBInitRef NameService=corbaname::$NAMESERVICE&quot;',
        'ENDPOINT=${ADDRESS:+-ORBendPoint giop:tcp:$ADDRESS:}',
        'say() { echo &quot;$0 [$(date +%s.%N)]: $*&quot;; }',
        'fail() { echo &quot;$0 [$(date +%s.%N)]: $*&quot; &gt;&amp;2; exit 1; }',
        'answers() { timeout 10 nameclt $ORB list &gt;/dev/null 2&gt;&amp;1; }',
        'named() { timeout 10 nameclt $ORB list TaskContexts 2&gt;/dev/null | grep -qx &quot;$1&quot;; }',
        '# helper COMMAND ARGS...: start-helper.lua under rttlua-corba; its log LOGDIR/' || substring-before($script, '.sh') || '-helper.log',
        'helper() {',
        '  ORO_LOGFILE=&quot;$LOGDIR/' || substring-before($script, '.sh') || '-helper.log&quot; timeout -k 5 $((WAIT + 30)) \',
        '    rttlua-corba &quot;$here/start-helper.lua&quot; &quot;$@&quot; -- $ORB $ENDPOINT &lt;/dev/null 2&gt;&amp;1',
        '}',
        '# verdict OUTPUT: the helper''s lines, and its verdict as exit status',
        'verdict() {',
        '  printf ''%s\n'' &quot;$1&quot; | sed -n ''s/^START-HELPER \(.* Running\)$/\1/p'' | while read -r line; do say &quot;$line&quot;; done',
        '  printf ''%s\n'' &quot;$1&quot; | grep -qx ''START-HELPER OK''',
        '}',
        '# wait_ns: until the naming service answers, WAIT s at most',
        'wait_ns() {',
        '  end=$(($(date +%s) + WAIT))',
        '  until answers; do',
        '    [ &quot;$(date +%s)&quot; -lt &quot;$end&quot; ] || fail &quot;no naming service answers at $NAMESERVICE after $WAIT s (it runs on host ''' || $naming/@host
          || ''': start ' || $naming/@start-script || ' there first, or set NAMESERVICE=host[:port])&quot;',
        '    sleep 0.5',
        '  done',
        '}',
        '# wait_running PID NAME...: until the components NAME are in the naming service, then Running (PID:',
        '# the process that makes them, - for other hosts''); fails naming the component after WAIT s',
        'wait_running() {',
        '  pid=$1; shift',
        '  end=$(($(date +%s) + WAIT))',
        '  for c in &quot;$@&quot;; do',
        '    until named &quot;$c&quot;; do',
        '      if [ &quot;$pid&quot; != - ] &amp;&amp; ! kill -0 &quot;$pid&quot; 2&gt;/dev/null; then fail &quot;the process of component $c ended (its log: $LOGDIR)&quot;; fi',
        '      [ &quot;$(date +%s)&quot; -lt &quot;$end&quot; ] || fail &quot;component $c is not in the naming service at $NAMESERVICE after $WAIT s&quot;',
        '      sleep 0.1',
        '    done',
        '  done',
        '  out=$(helper wait &quot;$WAIT&quot; &quot;$pid&quot; &quot;$@&quot;) || true',
        '  verdict &quot;$out&quot; || fail &quot;waiting for $*: $(printf ''%s\n'' &quot;$out&quot; | sed -n ''s/^START-HELPER FAILED: //p'')&quot; &quot;$(printf ''%s\n'' &quot;$out&quot; | tail -n 5)&quot;',
        '}',
        '# stop_process PID DEPLOYER NAME...: stop the components NAME of process PID (deployer DEPLOYER) and',
        '# take them out of it, then end it (SIGINT; killed after 10 s)',
        'stop_process() {',
        '  p=$1; shift',
        '  if [ -z &quot;$p&quot; ] || ! kill -0 &quot;$p&quot; 2&gt;/dev/null; then return 0; fi',
        '  say &quot;stopping $*&quot;',
        '  out=$(helper stop &quot;$@&quot;) || true',
        '  verdict &quot;$out&quot; || say &quot;stopping $1: $(printf ''%s\n'' &quot;$out&quot; | tail -n 3 | tr ''\n'' '' '')&quot;',
        '  kill -INT &quot;$p&quot; 2&gt;/dev/null || true',
        '  n=0; while kill -0 &quot;$p&quot; 2&gt;/dev/null &amp;&amp; [ $n -lt 100 ]; do sleep 0.1; n=$((n + 1)); done',
        '  if kill -0 &quot;$p&quot; 2&gt;/dev/null; then say &quot;$1 still runs 10 s after SIGINT: killed&quot;; kill -KILL &quot;$p&quot; 2&gt;/dev/null || true; fi',
        '  wait &quot;$p&quot; 2&gt;/dev/null || true',
        '}',
        $processes ! ('pid_' || @position || '=&quot;&quot;'),
        'ns=&quot;&quot;',
        'stop() {',
        '  trap - INT TERM EXIT',
        for $p in reverse($processes) return '  stop_process &quot;$pid_' || $p/@position || '&quot; ' || $p/@file || ' '
            || string-join(reverse(fp:in-process('fp:instance-in', $deployment, $p/@file)/@name), ' '),
        '  if [ -n &quot;$ns&quot; ]; then kill &quot;$ns&quot; 2&gt;/dev/null || true; wait &quot;$ns&quot; 2&gt;/dev/null || true; fi',
        '  say &quot;stopped&quot;',
        '}',
        '# a failed start keeps its exit status; Ctrl-C and SIGTERM end with 0 once all is stopped',
        'trap stop EXIT',
        'trap ''stop; exit 0'' INT TERM',
        'cd &quot;$here&quot;',
        'mkdir -p &quot;$LOGDIR&quot;',
        if (string($naming/@host) eq string($host/@name)) then (
          'if ! answers; then',
          '  port=2809; case &quot;$NAMESERVICE&quot; in *:*) port=${NAMESERVICE##*:} ;; esac',
          '  mkdir -p &quot;$LOGDIR/omninames-$$&quot;',
          '  say &quot;starting omniNames on ${NAMESERVICE%%:*}:$port&quot;',
          '  omniNames -start &quot;$port&quot; -ignoreport -ORBendPoint &quot;giop:tcp:${NAMESERVICE%%:*}:$port&quot; -logdir &quot;$LOGDIR/omninames-$$&quot; \',
          '    &gt;&quot;$LOGDIR/omninames-$$/omniNames.out&quot; 2&gt;&amp;1 &amp;',
          '  ns=$!',
          'fi') else (),
        'wait_ns',
        $processes ! (
          let $process := .,
              $before := fp:in-process('fp:process-at', $deployment, string(xs:integer($process/@position) - 1))
                                             [string(@host) ne string($process/@host)],
              $remote := distinct-values((fp:in-process('fp:instance-in', $deployment, string($before/@file))/@name,
                                          fp:in-process('fp:connection-in', $deployment, $process/@file)
                                            /o:remote[@process eq $process/@file]/@proxy))
          return (
            '',
            '# ' || @position || '. process ''' || @name || '''',
            if (exists($remote)) then 'wait_running - ' || string-join($remote, ' ') else (),
            'say &quot;starting process ' || @position || ' ''' || @name || ''' (' || @file || '.$format, log $LOGDIR/' || @file || '.log)&quot;',
            'ORO_LOGFILE=&quot;$LOGDIR/' || @file || '.log&quot; setsid '
              || fp:deployer-command(fp:process-view($deployment, .), @file || '.$format', '$NAMESERVICE', '') || ' $ENDPOINT &lt;/dev/null &amp;',
            'pid_' || @position || '=$!',
            'wait_running $! ' || string-join(fp:in-process('fp:instance-in', $deployment, $process/@file)/@name, ' '))),
        '',
        'say &quot;every process of host ''' || ($host/@name, 'localhost')[1] || ''' started; Ctrl-C stops them&quot;',
        'wait'))"/>
  </xsl:function>
</xsl:stylesheet>
