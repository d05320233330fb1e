<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/orocos/orocos-deploy.xsl - the deployment, three ways (OCL 2.10).

  Reads:   o:deployment of urn:robomda:psm-orocos:1.
  Writes:  strings (file contents), wrapped into fs:file by main.xsl:
           deploy/<model>.xml  OCL deployer XML (cpf), format of
                               /work/shared/orocos-reference/deploy/deploy.xml
           deploy/<model>.ops  Orocos Program Script for `deployer -s`
           deploy/<model>.lua  rttlua script that checks every step and
                               exits 0 / 1 with a verdict
  Params:  none.  Errors: none.

  Choices
  - Activity type "Activity" for every component (Period 0 = non-periodic),
    with Period, Priority and Scheduler always written (the deployer default
    scheduler is ORO_SCHED_RT); CpuAffinity (a CPU mask) only when non-zero.
    In .ops / Lua a single-CPU mask uses setActivityOnCPU (which takes a CPU
    number); a multi-CPU mask can only be expressed in the XML (comment).
  - One ConnPolicy struct per connection point; Ports map each port to it.
    The PSM keeps only connection points with a writer and a reader, so no
    name is used by a single port. In .ops / Lua each writer is connected
    to each reader with connect("a.p", "b.q", cp).
  - Peers only where the PSM lists them (a reader that may call operations
    of the interface's provider).
  - Properties: only names the component declares, with the model defaults.
  - AutoConf and AutoStart are 1 (XML); .ops and Lua configure all, then
    start all, in instance order.
  - Deployment sequence (seed 002): the PSM's instance order is the start
    order, so every file loads, configures and starts in it. The cpf
    format has no order setting: the OCL deployer configures and starts
    the components of a file in the order of their struct elements, which
    is why the XML lists them in start order. When the model has StartAfter
    constraints, each file says so in a comment (fp:sequence-note).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:o="urn:robomda:psm-orocos:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:period" as="xs:string">
    <xsl:param name="p" as="xs:string"/>
    <xsl:sequence select="if (matches($p, '[.eE]')) then $p else concat($p, '.0')"/>
  </xsl:function>

  <!-- the one-bit masks 2^0 ... 2^63, computed once -->
  <xsl:variable name="fp:one-bit-masks" as="xs:integer+" select="(0 to 63) ! fp:pow2(.)"/>

  <!-- the CPU number of a one-bit mask, else () -->
  <xsl:function name="fp:cpu-number" as="xs:integer?">
    <xsl:param name="mask" as="xs:integer"/>
    <xsl:sequence select="if ($mask le 0) then () else index-of($fp:one-bit-masks, $mask)[1] - 1"/>
  </xsl:function>
  <xsl:function name="fp:pow2" as="xs:integer">
    <xsl:param name="n" as="xs:integer"/>
    <xsl:sequence select="if ($n eq 0) then 1 else 2 * fp:pow2($n - 1)"/>
  </xsl:function>

  <xsl:function name="fp:simple" as="xs:string">
    <xsl:param name="name" as="xs:string?"/>
    <xsl:param name="type" as="xs:string"/>
    <xsl:param name="value" as="xs:string"/>
    <xsl:sequence select="concat('&lt;simple', if (exists($name)) then concat(' name=&quot;', fp:xml-text($name), '&quot;') else '',
        ' type=&quot;', $type, '&quot;&gt;&lt;value&gt;', fp:xml-text($value), '&lt;/value&gt;&lt;/simple&gt;')"/>
  </xsl:function>

  <xsl:function name="fp:ends" as="xs:string*">
    <xsl:param name="k" as="element(o:connection)"/>
    <xsl:sequence select="for $w in $k/o:writer, $r in $k/o:reader
                          return (concat($w/@instance, '.', $w/@port), concat($r/@instance, '.', $r/@port))"/>
  </xsl:function>

  <!-- "controller after arm, vision; ..." for the instances with
       constraints; () when the deployment has none -->
  <xsl:function name="fp:sequence-note" as="xs:string?">
    <xsl:param name="d" as="element(o:deployment)"/>
    <xsl:variable name="constrained" as="element(o:instance)*" select="$d/o:instance[o:start-after]"/>
    <xsl:sequence select="if (empty($constrained)) then ()
        else string-join($constrained ! (concat(@name, ' after ', string-join(distinct-values(o:start-after/@instance), ', '))), '; ')"/>
  </xsl:function>

  <!-- ======================================================= XML -->
  <xsl:function name="fp:deploy-xml" as="xs:string">
    <xsl:param name="d" as="element(o:deployment)"/>
    <xsl:sequence select="fp:lines((
        '&lt;?xml version=&quot;1.0&quot; encoding=&quot;UTF-8&quot;?&gt;',
        '&lt;!--',
        fp:indent(2, fp:banner('', $fp:deploy-xsl, concat('the deployment of model ''', fp:xml-text($d/@model-name), ''''), false())),
        concat('  Run: deployer -s ', $d/@deploy-name, '.xml (add the check option to load, connect and configure only)'),
        '--&gt;',
        '&lt;!DOCTYPE properties SYSTEM &quot;cpf.dtd&quot;&gt;',
        '&lt;properties&gt;',
        concat('  &lt;!-- the component package (CMake project ', $d/@package, ') --&gt;'),
        concat('  ', fp:simple('Import', 'string', $d/@package)),
        $d/o:connection ! (
          '',
          concat('  &lt;!-- connection point ', @name, ': ', string-join(o:writer ! (concat(@instance, '.', @port)), ', '),
             ' -&gt; ', string-join(o:reader ! (concat(@instance, '.', @port)), ', '), ' --&gt;'),
          concat('  &lt;struct name=&quot;', @name, '&quot; type=&quot;ConnPolicy&quot;&gt;'),
          concat('    ', fp:simple('type', 'short', @type-code), '  &lt;!-- ', @type, ' --&gt;'),
          concat('    ', fp:simple('size', 'short', @size)),
          concat('    ', fp:simple('lock_policy', 'short', @lock-policy-code), '  &lt;!-- ', @lock-policy, ' --&gt;'),
          concat('    ', fp:simple('init', 'boolean', if (xs:boolean(@init)) then '1' else '0')),
          concat('    ', fp:simple('pull', 'boolean', if (xs:boolean(@pull)) then '1' else '0')),
          '  &lt;/struct&gt;'),
        for $note in fp:sequence-note($d)
        return ('', concat('  &lt;!-- deployment sequence: ', $note, '. The deployer loads, configures and starts'),
                '       the components in the order of this file. --&gt;'),
        $d/o:instance ! fp:xml-instance(.),
        '&lt;/properties&gt;'))"/>
  </xsl:function>

  <xsl:function name="fp:xml-instance" as="xs:string*">
    <xsl:param name="i" as="element(o:instance)"/>
    <xsl:variable name="a" as="element(o:activity)" select="$i/o:activity"/>
    <xsl:sequence select="
        '',
        concat('  &lt;struct name=&quot;', $i/@name, '&quot; type=&quot;', $i/@type-name, '&quot;&gt;'),
        concat('    &lt;struct name=&quot;Activity&quot; type=&quot;', $a/@type, '&quot;&gt;'),
        concat('      ', fp:simple('Period', 'double', fp:period($a/@period))),
        concat('      ', fp:simple('Priority', 'short', $a/@priority)),
        concat('      ', fp:simple('Scheduler', 'string', $a/@scheduler)),
        if (xs:integer($a/@cpu-affinity) ne 0) then concat('      ', fp:simple('CpuAffinity', 'ulong', $a/@cpu-affinity)) else (),
        '    &lt;/struct&gt;',
        concat('    ', fp:simple('AutoConf', 'boolean', '1')),
        concat('    ', fp:simple('AutoStart', 'boolean', '1')),
        if ($i/o:peer) then (
          '    &lt;struct name=&quot;Peers&quot; type=&quot;PropertyBag&quot;&gt;',
          $i/o:peer ! (concat('      ', fp:simple((), 'string', @instance))),
          '    &lt;/struct&gt;') else (),
        if ($i/o:port-connection) then (
          '    &lt;struct name=&quot;Ports&quot; type=&quot;PropertyBag&quot;&gt;',
          $i/o:port-connection ! (concat('      ', fp:simple(@port, 'string', @connection))),
          '    &lt;/struct&gt;') else (),
        if ($i/o:property-value) then (
          '    &lt;struct name=&quot;Properties&quot; type=&quot;PropertyBag&quot;&gt;',
          $i/o:property-value ! (concat('      ', fp:simple(@name, @xml-type, @value))),
          '    &lt;/struct&gt;') else (),
        '  &lt;/struct&gt;'"/>
  </xsl:function>

  <!-- ======================================================= .ops -->
  <xsl:function name="fp:deploy-ops" as="xs:string">
    <xsl:param name="d" as="element(o:deployment)"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:deploy-xsl, concat('the deployment of model ''', $d/@model-name, ''''), false()),
        concat('// Run: deployer -s ', $d/@deploy-name, '.ops'),
        concat('import(', fp:cpp-string($d/@package), ')'),
        '',
        $d/o:instance ! (concat('loadComponent(', fp:cpp-string(@name), ', ', fp:cpp-string(@type-name), ')')),
        '',
        '// activities (R5): setActivity(component, period [s], priority, scheduler)',
        $d/o:instance ! fp:ops-activity(.),
        if ($d/o:instance/o:peer) then ('', '// peers', $d/o:instance ! (for $p in o:peer return
            concat('addPeer(', fp:cpp-string(@name), ', ', fp:cpp-string($p/@instance), ')'))) else (),
        if ($d/o:instance/o:property-value) then ('', '// properties (R4)',
            $d/o:instance ! (for $p in o:property-value return concat(@name, '.', $p/@name, ' = ', $p/@script-value))) else (),
        $d/o:connection ! (
          '',
          concat('// connection point ', @name),
          concat('var ConnPolicy cp_', @name),
          concat('cp_', @name, '.type = ', @type),
          concat('cp_', @name, '.size = ', @size),
          concat('cp_', @name, '.lock_policy = ', @lock-policy),
          concat('cp_', @name, '.init = ', @init),
          concat('cp_', @name, '.pull = ', @pull),
          let $k := ., $e := fp:ends(.)
          return for $j in 1 to count($e) idiv 2
                 return concat('connect(', fp:cpp-string($e[2 * $j - 1]), ', ', fp:cpp-string($e[2 * $j]), ', cp_', $k/@name, ')')),
        '',
        '// lifecycle',
        fp:sequence-note($d) ! (concat('// in start order (deployment sequence: ', ., ')')),
        $d/o:instance ! (concat(@name, '.configure()')),
        $d/o:instance ! (concat(@name, '.start()'))))"/>
  </xsl:function>

  <xsl:function name="fp:ops-activity" as="xs:string">
    <xsl:param name="i" as="element(o:instance)"/>
    <xsl:variable name="a" as="element(o:activity)" select="$i/o:activity"/>
    <xsl:variable name="mask" as="xs:integer" select="xs:integer($a/@cpu-affinity)"/>
    <xsl:variable name="cpu" as="xs:integer?" select="fp:cpu-number($mask)"/>
    <xsl:variable name="args" as="xs:string"
        select="concat(fp:cpp-string($i/@name), ', ', fp:period($a/@period), ', ', $a/@priority, ', ', $a/@scheduler)"/>
    <xsl:sequence select="
        if ($mask eq 0) then concat('setActivity(', $args, ')')
        else if (exists($cpu)) then concat('setActivityOnCPU(', $args, ', ', $cpu, ')  // CpuAffinity mask ', $mask)
        else concat('setActivity(', $args, ')  // CpuAffinity mask ', $mask, ' (several CPUs): only the XML deployment sets it')"/>
  </xsl:function>

  <!-- ======================================================= Lua -->
  <xsl:function name="fp:lua-activity" as="xs:string">
    <xsl:param name="i" as="element(o:instance)"/>
    <xsl:variable name="a" as="element(o:activity)" select="$i/o:activity"/>
    <xsl:variable name="mask" as="xs:integer" select="xs:integer($a/@cpu-affinity)"/>
    <xsl:variable name="cpu" as="xs:integer?" select="fp:cpu-number($mask)"/>
    <xsl:variable name="args" as="xs:string"
        select="concat(fp:cpp-string($i/@name), ', ', fp:period($a/@period), ', ', $a/@priority, ', rtt.globals.', $a/@scheduler)"/>
    <xsl:sequence select="
        if ($mask ne 0 and exists($cpu))
        then concat('  check(depl:setActivityOnCPU(', $args, ', ', $cpu, '), &quot;setActivityOnCPU ', $i/@name, '&quot;)  -- CpuAffinity mask ', $mask)
        else concat('  check(depl:setActivity(', $args, '), &quot;setActivity ', $i/@name, '&quot;)',
              (if ($mask ne 0) then concat('  -- CpuAffinity mask ', $mask, ' (several CPUs): only the XML deployment sets it') else ''))"/>
  </xsl:function>

  <xsl:function name="fp:lua-value" as="xs:string">
    <xsl:param name="p" as="element()"/>
    <xsl:sequence select="$p/@script-value"/>
  </xsl:function>

  <xsl:function name="fp:deploy-lua" as="xs:string">
    <xsl:param name="d" as="element(o:deployment)"/>
    <xsl:variable name="names" as="xs:string*" select="$d/o:instance/@name"/>
    <xsl:sequence select="fp:lines((
        fp:banner('-- ', $fp:deploy-xsl, concat('the deployment of model ''', $d/@model-name, ''''), false()),
        concat('-- Run: rttlua ', $d/@deploy-name, '.lua   (or deployer -s ', $d/@deploy-name, '.lua)'),
        'require(&quot;rttlib&quot;)',
        'rttlib.color = false',
        '',
        'local ok = true',
        'local function check(cond, msg)',
        '  if not cond then',
        '    rtt.logl(&quot;Error&quot;, &quot;DEPLOY-CHECK FAILED: &quot; .. msg)',
        '    print(&quot;DEPLOY-CHECK FAILED: &quot; .. msg)',
        '    ok = false',
        '  end',
        '  return cond',
        'end',
        '',
        'local tc = rtt.getTC()',
        'local depl',
        'if tc:getName() == &quot;Deployer&quot; then depl = tc else depl = tc:getPeer(&quot;Deployer&quot;) end',
        concat('local names = {', string-join($names ! fp:cpp-string(.), ', '), '}'),
        'local comps = {}',
        '',
        concat('check(depl:import(', fp:cpp-string($d/@package), '), &quot;import ', $d/@package, '&quot;)'),
        $d/o:instance ! (concat('check(depl:loadComponent(', fp:cpp-string(@name), ', ', fp:cpp-string(@type-name),
                          '), &quot;loadComponent ', @name, '&quot;)')),
        '',
        'if ok then',
        '  for _, n in ipairs(names) do comps[n] = depl:getPeer(n) end',
        '',
        '  -- activities (R5): setActivity(name, period [s], priority, scheduler)',
        $d/o:instance ! fp:lua-activity(.),
        if ($d/o:instance/o:peer) then ('', '  -- peers', $d/o:instance ! (for $p in o:peer return
            concat('  check(depl:addPeer(', fp:cpp-string(@name), ', ', fp:cpp-string($p/@instance),
             '), &quot;addPeer ', @name, ' -&gt; ', $p/@instance, '&quot;)'))) else (),
        if ($d/o:instance/o:property-value) then ('', '  -- properties (R4)',
            $d/o:instance ! (for $p in o:property-value return
              concat('  check(pcall(function() comps[', fp:cpp-string(@name), ']:getProperty(', fp:cpp-string($p/@name),
               '):set(', fp:lua-value($p), ') end), &quot;property ', @name, '.', $p/@name, '&quot;)'))) else (),
        $d/o:connection ! (
          '',
          concat('  -- connection point ', @name),
          '  do',
          '    local cp = rtt.Variable(&quot;ConnPolicy&quot;)',
          concat('    cp.type = rtt.globals.', @type),
          concat('    cp.size = ', @size),
          concat('    cp.lock_policy = rtt.globals.', @lock-policy),
          concat('    cp.init = ', @init),
          concat('    cp.pull = ', @pull),
          let $e := fp:ends(.)
          return for $j in 1 to count($e) idiv 2
                 return concat('    check(depl:connect(', fp:cpp-string($e[2 * $j - 1]), ', ', fp:cpp-string($e[2 * $j]),
                         ', cp), &quot;connect ', $e[2 * $j - 1], ' -&gt; ', $e[2 * $j], '&quot;)'),
          '  end'),
        '',
        '  -- lifecycle: configure all, then start all',
        fp:sequence-note($d) ! (concat('  -- in start order (deployment sequence: ', ., ')')),
        '  for _, n in ipairs(names) do check(comps[n]:configure(), &quot;configure &quot; .. n) end',
        '  for _, n in ipairs(names) do check(comps[n]:start(), &quot;start &quot; .. n) end',
        '',
        '  rtt.sleep(1, 0)  -- let it run 1 s',
        '  for _, n in ipairs(names) do',
        '    local s = comps[n]:getState()',
        '    check(s == &quot;Running&quot;, n .. &quot; Running (is &quot; .. tostring(s) .. &quot;)&quot;)',
        '  end',
        '',
        '  for _, n in ipairs(names) do comps[n]:stop() end',
        '  for _, n in ipairs(names) do comps[n]:cleanup() end',
        '  for i = #names, 1, -1 do depl:unloadComponent(names[i]) end',
        'end',
        '',
        'print(ok and &quot;DEPLOY-RESULT: OK&quot; or &quot;DEPLOY-RESULT: FAILED&quot;)',
        '-- rttlua always exits 0 by itself; os.exit propagates the verdict.',
        'os.exit(ok and 0 or 1)'))"/>
  </xsl:function>
</xsl:stylesheet>
