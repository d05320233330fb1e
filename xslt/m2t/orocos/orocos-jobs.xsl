<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/orocos/orocos-jobs.xsl - the job coordinator on Orocos (seed 004 §4.3, docs/jobs.md).

  Reads:   o:coordinator of urn:robomda:psm-orocos:1 (xslt/m2m/orocos/jobs.xsl).
  Writes:  strings (file contents), wrapped into fs:file by main.xsl:
           deploy/<model>_<subsystem>.lua  the coordinator's program, run by
                                     an OCL::LuaComponent named after the
                                     subsystem when it is configured (its
                                     property lua_file)
           and the lines of each deployment file (orocos-deploy.xsl) that
           load, connect, configure and start the coordinator.
  Params:  none.  Errors: none.

  Choices (what OCL 2.10 ships, /root/orocos/install): the Lua scripting of
  OCL (liborocos-ocl-lua: rttlua, OCL::LuaComponent, rttlib) but not rFSM
  (OCL's lua/modules install rttlib, utils, ansicolors, tlsf_ext and rttros
  only), and RTT's own state-machine scripting (scripting service, .osd
  StateMachine). The coordinator is a plain Lua table of switches run by an
  OCL::LuaComponent: every deployment format can load it (the XML as a
  component with a lua_file property, .ops and Lua with loadComponent),
  a switch is data (which components stop, which are reconfigured with
  which values, which start), and it needs nothing OCL does not install.
  - Events: the input event port 'events' (string): each event name that
    arrives wakes the coordinator (non-periodic activity), which runs the
    switch of the current job on that event, if any (else a warning).
    The output port 'job' and the property 'job' say the job running.
  - A switch stops the instances that leave (reverse start order), then
    reconfigures the ones that stay with other values (stop, set the
    properties, configure, start: the component's configure sees the new
    values), then starts the ones that come (set their values, configure,
    start), in start order. The instances both jobs share with the same
    values are not touched: never stopped.
  - The initial job: the deployment starts its instances (and every
    instance in no job) and only configures the others (AutoStart 0 in the
    XML); the coordinator starts last.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:o="urn:robomda:psm-orocos:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:variable name="fp:jobs-xsl" as="xs:string" select="'m2t/orocos/orocos-jobs.xsl'"/>

  <!-- a Lua list of strings: {"a", "b"} -->
  <xsl:function name="fp:lua-list" as="xs:string">
    <xsl:param name="items" as="xs:string*"/>
    <xsl:sequence select="'{' || string-join($items ! fp:cpp-string(.), ', ') || '}'"/>
  </xsl:function>

  <!-- one step of a switch with values: { name = "x", set = { {"p", 1.0} } } -->
  <xsl:function name="fp:lua-step" as="xs:string">
    <xsl:param name="step" as="element()"/>
    <xsl:sequence select="'{ name = ' || fp:cpp-string($step/@instance) || ', set = {'
        || string-join($step/o:set ! (' {' || fp:cpp-string(@name) || ', ' || @script-value || '}'), ',') || ' } }'"/>
  </xsl:function>

  <xsl:function name="fp:coordinator-lua" as="xs:string">
    <xsl:param name="coordinator" as="element(o:coordinator)"/>
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:variable name="name" as="xs:string" select="$coordinator/@name"/>
    <xsl:sequence select="fp:lines((
        fp:banner('-- ', $fp:jobs-xsl, concat('the job coordinator of subsystem ''', $name, ''' of model ''', $deployment/@model-name, ''''), false()),
        concat('-- Run by the OCL::LuaComponent ', fp:cpp-string($name), ' of the deployment (', $deployment/@deploy-name,
               '.xml / .ops / .lua), which executes it when it is configured (property lua_file).'),
        concat('-- Write an event name to its input port ', $name, '.events (string) to switch jobs: ',
               string-join(distinct-values($coordinator/o:transition/@event), ', '), '.'),
        concat('-- Its output port ', $name, '.job and its property ', $name, '.job give the job running.'),
        'require(&quot;rttlib&quot;)',
        '',
        'local tc = rtt.getTC()',
        concat('local subsystem = ', fp:cpp-string($name)),
        concat('local initial = ', fp:cpp-string($coordinator/@initial-job)),
        '-- the instances of each job, in start order',
        'local members = {',
        $coordinator/o:job ! concat('  [', fp:cpp-string(@name), '] = ', fp:lua-list(o:member/@instance), ','),
        '}',
        '-- per job, per event: the switch (stop, reconfigure, start, in that order; keep: never touched)',
        'local switches = {',
        for $job in distinct-values($coordinator/o:transition/@from) return (
          concat('  [', fp:cpp-string($job), '] = {'),
          $coordinator/o:transition[@from eq $job] ! (
            concat('    [', fp:cpp-string(@event), '] = { to = ', fp:cpp-string(@to), ','),
            concat('      stop = ', fp:lua-list(o:stop/@instance), ','),
            concat('      reconfigure = {', string-join(o:reconfigure ! fp:lua-step(.), ', '), '},'),
            concat('      start = {', string-join(o:start ! fp:lua-step(.), ', '), '},'),
            concat('      keep = ', fp:lua-list(o:keep/@instance), ' },')),
          '  },'),
        '}',
        '',
        'local peers, current, events, jobport, jobprop = {}, nil, nil, nil, nil',
        '',
        'local function log(level, text) rtt.logl(level, subsystem .. &quot;: &quot; .. text) end',
        '',
        '-- one lifecycle call of a peer, logged when it fails',
        'local function call(n, what)',
        '  local ok = peers[n][what](peers[n])',
        '  if not ok then log(&quot;Error&quot;, n .. &quot;.&quot; .. what .. &quot;() failed&quot;) end',
        '  return ok',
        'end',
        '',
        '-- the job''s values of one instance, then configure and start it',
        'local function bring_up(step)',
        '  for _, kv in ipairs(step.set) do',
        '    local set = pcall(function() peers[step.name]:getProperty(kv[1]):set(kv[2]) end)',
        '    if not set then log(&quot;Error&quot;, step.name .. &quot;.&quot; .. kv[1] .. &quot; not set&quot;); return false end',
        '  end',
        '  return call(step.name, &quot;configure&quot;) and call(step.name, &quot;start&quot;)',
        'end',
        '',
        'local function switch(event)',
        '  local s = switches[current] and switches[current][event]',
        '  if not s then',
        '    log(&quot;Warning&quot;, &quot;event &quot; .. tostring(event) .. &quot; switches nothing in job &quot; .. current .. &quot;: ignored&quot;)',
        '    return false',
        '  end',
        '  local ok = true',
        '  for _, n in ipairs(s.stop) do ok = call(n, &quot;stop&quot;) and ok end',
        '  for _, step in ipairs(s.reconfigure) do',
        '    if peers[step.name]:getState() == &quot;Running&quot; then ok = call(step.name, &quot;stop&quot;) and ok end',
        '    ok = bring_up(step) and ok',
        '  end',
        '  for _, step in ipairs(s.start) do ok = bring_up(step) and ok end',
        '  log(&quot;Info&quot;, &quot;job &quot; .. current .. &quot; -&gt; &quot; .. s.to .. &quot; on &quot; .. event .. (ok and &quot;&quot; or &quot; (a step failed)&quot;))',
        '  current = s.to',
        '  jobprop:set(current)',
        '  jobport:write(current)',
        '  return ok',
        'end',
        '',
        'function configureHook()',
        '  if events == nil then',
        concat('    events = rtt.InputPort(&quot;string&quot;, &quot;events&quot;, ', fp:cpp-string('events that switch jobs: ' || string-join(distinct-values($coordinator/o:transition/@event), ', ')), ')'),
        '    tc:addEventPort(events)',
        '    jobport = rtt.OutputPort(&quot;string&quot;, &quot;job&quot;, &quot;the job running&quot;)',
        '    tc:addPort(jobport)',
        '    jobprop = rtt.Property(&quot;string&quot;, &quot;job&quot;, &quot;the job running&quot;)',
        '    tc:addProperty(jobprop)',
        '  end',
        '  for _, names in pairs(members) do',
        '    for _, n in ipairs(names) do',
        '      local found, peer = pcall(tc.getPeer, tc, n)',
        '      if not found or peer == nil then log(&quot;Error&quot;, &quot;peer &quot; .. n .. &quot; missing&quot;); return false end',
        '      peers[n] = peer',
        '    end',
        '  end',
        '  current = initial',
        '  jobprop:set(current)',
        '  return true',
        'end',
        '',
        'function startHook()',
        '  jobport:write(current)',
        '  return true',
        'end',
        '',
        'function updateHook()',
        '  local fs, event = events:read()',
        '  while fs == &quot;NewData&quot; do',
        '    switch(event)',
        '    fs, event = events:read()',
        '  end',
        'end'))"/>
  </xsl:function>

  <!-- all the instances a coordinator manages -->
  <xsl:function name="fp:coordinator-peers" as="xs:string*">
    <xsl:param name="coordinator" as="element(o:coordinator)"/>
    <xsl:sequence select="distinct-values($coordinator/o:job/o:member/@instance)"/>
  </xsl:function>

  <!-- the XML deployer's struct of a coordinator (after the instances: configured and started last) -->
  <xsl:function name="fp:xml-coordinator" as="xs:string*">
    <xsl:param name="coordinator" as="element(o:coordinator)"/>
    <xsl:sequence select="
        '',
        concat('  &lt;!-- the job coordinator of subsystem ', $coordinator/@name, ' (', $coordinator/@script,
               ', docs/jobs.md): write an event to ', $coordinator/@name, '.events --&gt;'),
        concat('  &lt;struct name=&quot;', $coordinator/@name, '&quot; type=&quot;OCL::LuaComponent&quot;&gt;'),
        '    &lt;struct name=&quot;Activity&quot; type=&quot;Activity&quot;&gt;',
        concat('      ', fp:simple('Period', 'double', '0.0')),
        concat('      ', fp:simple('Priority', 'long', '0')),
        concat('      ', fp:simple('Scheduler', 'string', 'ORO_SCHED_OTHER')),
        '    &lt;/struct&gt;',
        concat('    ', fp:simple('AutoConf', 'boolean', '1')),
        concat('    ', fp:simple('AutoStart', 'boolean', '1')),
        '    &lt;struct name=&quot;Peers&quot; type=&quot;PropertyBag&quot;&gt;',
        fp:coordinator-peers($coordinator) ! concat('      ', fp:simple((), 'string', .)),
        '    &lt;/struct&gt;',
        '    &lt;struct name=&quot;Properties&quot; type=&quot;PropertyBag&quot;&gt;',
        concat('      ', fp:simple('lua_file', 'string', $coordinator/@script)),
        '    &lt;/struct&gt;',
        '  &lt;/struct&gt;'"/>
  </xsl:function>

  <!-- .ops: load, activity, peers and program of each coordinator -->
  <xsl:function name="fp:ops-coordinators" as="xs:string*">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:sequence select="$deployment/o:coordinator ! (
        '',
        concat('// the job coordinator of subsystem ', @name, ' (', @script, ', docs/jobs.md): write an event to ', @name, '.events'),
        concat('loadComponent(', fp:cpp-string(@name), ', &quot;OCL::LuaComponent&quot;)'),
        concat('setActivity(', fp:cpp-string(@name), ', 0.0, 0, ORO_SCHED_OTHER)'),
        let $c := . return fp:coordinator-peers(.) ! concat('addPeer(', fp:cpp-string($c/@name), ', ', fp:cpp-string(.), ')'),
        concat(@name, '.lua_file = ', fp:cpp-string(@script)))"/>
  </xsl:function>

  <!-- Lua: the same, the program found beside the deployment file -->
  <xsl:function name="fp:lua-coordinators" as="xs:string*">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:sequence select="$deployment/o:coordinator ! (
        '',
        concat('  -- the job coordinator of subsystem ', @name, ' (', @script, ', docs/jobs.md): write an event to ', @name, '.events'),
        concat('  check(depl:loadComponent(', fp:cpp-string(@name), ', &quot;OCL::LuaComponent&quot;), &quot;loadComponent ', @name, '&quot;)'),
        concat('  check(depl:setActivity(', fp:cpp-string(@name), ', 0.0, 0, rtt.globals.ORO_SCHED_OTHER), &quot;setActivity ', @name, '&quot;)'),
        let $c := . return fp:coordinator-peers(.) ! concat('  check(depl:addPeer(', fp:cpp-string($c/@name), ', ', fp:cpp-string(.),
                                                            '), &quot;addPeer ', $c/@name, ' ', ., '&quot;)'),
        concat('  coordinators[', fp:cpp-string(@name), '] = depl:getPeer(', fp:cpp-string(@name), ')'),
        concat('  check(pcall(function() coordinators[', fp:cpp-string(@name), ']:getProperty(&quot;lua_file&quot;):set(here .. ',
               fp:cpp-string('/' || @script), ') end), &quot;property ', @name, '.lua_file&quot;)'))"/>
  </xsl:function>
</xsl:stylesheet>
