<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/orocos/orocos-deploy.xsl - the deployment, three ways (OCL 2.10).

  Reads:   o:deployment of urn:robomda:psm-orocos:1.
  Writes:  strings (file contents), wrapped into fs:file by main.xsl:
           deploy/<model>.xml        OCL deployer XML (cpf), format of
                                     ../shared/orocos-reference/deploy/deploy.xml
           deploy/<model>.ops        Orocos Program Script for `deployer -s`
           deploy/<model>.lua        the same deployment for `deployer -s` or
                                     `rttlua -i`: it keeps running
           deploy/<model>-check.lua  runs <model>.lua for a second, reads the
                                     modelled (or tuned) values back, checks
                                     every connection (connected; data where
                                     its writer is periodic), stops
                                     everything and exits 0 / 1 with a verdict
           deploy/<instance>.user.cpf  the user's tuned values (fp:user-cpf-text,
                                     a user file: main.xsl writes it once)
  Params:  none.  Errors: none.

  Choices
  - The component library is loaded with LoadLibrary / loadLibrary
    ("<pkg>/<pkg>"), which RTT looks up in RTT_COMPONENT_PATH only
    (<dir>/<target>/<pkg>/lib<pkg>-<target>.so). Import / import("<pkg>")
    would take a folder named <pkg> in the working directory instead of the
    component path (ComponentLoader::importInstalledPackage), so running
    next to the generated package's own folder failed.
  - Activity type "Activity" for every component (Period 0 = non-periodic),
    with Period, Priority and Scheduler always written (the deployer default
    scheduler is ORO_SCHED_RT); CpuAffinity (a CPU mask) only when non-zero:
    the XML's CpuAffinity, and in .ops / Lua setActivity followed by the
    component's setCpuAffinity(mask) (RTT 2.10), whatever CPUs the mask has.
  - Integers (ConnPolicy fields, Priority) are written as "long": RTT 2.10
    logs two deprecation warnings for every "short".
  - Under ORO_SCHED_OTHER the priority written is 0, with a note: RTT has
    no priorities there and would force it to 0 with a warning per thread
    (the PSM keeps the modelled one, for rule ORO102).
  - Every lifecycle call is checked: .ops logs an [ ERROR ] line through
    OCL's print service for each configure() / start() / setCpuAffinity()
    that returns false and starts nothing when a configure failed; Lua logs
    the same and raises an error at the end (the deployer then exits
    non-zero, as it does for a failing XML file).
  - Comments in .ops stand on their own line: after a statement, a comment
    swallows its line end (a syntax error for the whole script).
  - One ConnPolicy struct per connection point; Ports map each port to it.
    The PSM keeps only connection points with a writer and a reader, so no
    name is used by a single port. In .ops / Lua each writer is connected
    to each reader with connect("a.p", "b.q", cp).
  - Peers only where the PSM lists them (a reader that may call operations
    of the interface's provider).
  - Properties: only names the component declares, with the model defaults.
  - Then the user's tuned values, deploy/<instance>.user.cpf (written once,
    empty): the XML's UpdateProperties (the deployer applies it after the
    Properties struct), in .ops / Lua the marshalling service's
    updateProperties before configure(). Neither the cpf format nor .ops can
    name a file relative to themselves, so those two read it from the
    working directory (run them from deploy/; elsewhere they fail loudly);
    Lua finds it beside itself, and the check expects its values.
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
    <xsl:param name="item" as="xs:string"/>
    <xsl:sequence select="if (matches($item, '[.eE]')) then $item else concat($item, '.0')"/>
  </xsl:function>

  <!-- the one-bit masks 2^0 ... 2^63, computed once: bit n of a mask is ($mask idiv $fp:one-bit-masks[n + 1]) mod 2 -->
  <xsl:variable name="fp:one-bit-masks" as="xs:integer+" select="(0 to 63) ! fp:pow2(.)"/>

  <xsl:function name="fp:pow2" as="xs:integer">
    <xsl:param name="name" as="xs:integer"/>
    <xsl:sequence select="if ($name eq 0) then 1 else 2 * fp:pow2($name - 1)"/>
  </xsl:function>

  <!-- the priority RTT runs the activity at: the modelled one, except under
       ORO_SCHED_OTHER, which has none (RTT would force it to 0 with a
       warning; rule ORO102 tells the user at generation time) -->
  <xsl:function name="fp:priority" as="xs:string">
    <xsl:param name="activity" as="element(o:activity)"/>
    <xsl:sequence select="if ($activity/@scheduler eq 'ORO_SCHED_OTHER') then '0' else string($activity/@priority)"/>
  </xsl:function>

  <!-- a note where fp:priority is not the modelled priority, else () -->
  <xsl:function name="fp:priority-note" as="xs:string?">
    <xsl:param name="activity" as="element(o:activity)"/>
    <xsl:sequence select="if (fp:priority($activity) eq string($activity/@priority)) then ()
        else concat('priority ', $activity/@priority, ' of the model: ORO_SCHED_OTHER has no priorities, so 0 (warning ORO102)')"/>
  </xsl:function>

  <!-- what LoadLibrary / loadLibrary takes: first the typekit of the
       model's data types, when there is one, "<pkg>/<typekit>" (RTT's
       plugin loader looks in <pkg>/types/), so that properties of those
       types are read with their types; then the components, "<pkg>/<pkg>" -->
  <xsl:function name="fp:deploy-libraries" as="xs:string+">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:sequence select="$deployment/o:types ! concat($deployment/@package, '/', @typekit),
                          concat($deployment/@package, '/', $deployment/@package)"/>
  </xsl:function>

  <!-- "CpuAffinity mask 6 (CPUs 1, 2)" -->
  <xsl:function name="fp:affinity-note" as="xs:string">
    <xsl:param name="mask" as="xs:integer"/>
    <xsl:variable name="cpus" as="xs:integer*" select="for $n in 0 to 63 return $n[($mask idiv $fp:one-bit-masks[$n + 1]) mod 2 eq 1]"/>
    <xsl:sequence select="concat('CpuAffinity mask ', $mask, ' (CPU', if (count($cpus) gt 1) then 's ' else ' ',
                                 string-join($cpus ! string(.), ', '), ')')"/>
  </xsl:function>

  <!-- the cpf XML of a property's value: a simple element, or for a data
       type or an array a struct of them, named $name -->
  <xsl:function name="fp:property-xml" as="xs:string+">
    <xsl:param name="value" as="element()"/><!-- o:property-value or o:value -->
    <xsl:param name="name" as="xs:string"/>
    <xsl:sequence select="
        if ($value/self::o:property-value/o:value) then fp:property-xml($value/o:value, $name)
        else if ($value/@value) then fp:simple($name, $value/@xml-type, $value/@value)
        else (concat('&lt;struct name=&quot;', fp:xml-text($name), '&quot; type=&quot;', fp:xml-text($value/@xml-type), '&quot;&gt;'),
              fp:indent(2, $value/o:value ! fp:property-xml(., @name)),
              '&lt;/struct&gt;')"/>
  </xsl:function>

  <!-- what the scripts do to give a data type or an array property the
       value the deployer XML gives it (issue 37): in document order, each
       array (@script-type: sized to @size first, as a script cannot set an
       element an array does not have) and each leaf, zeros included -->
  <xsl:function name="fp:script-steps" as="element()*">
    <xsl:param name="property" as="element(o:property-value)"/>
    <xsl:sequence select="if ($property/@script-value) then $property
                          else $property/o:value/descendant-or-self::o:value[@script-type or @script-value]"/>
  </xsl:function>

  <!-- .ops: one step of fp:script-steps on instance $instance -->
  <xsl:function name="fp:ops-step" as="xs:string">
    <xsl:param name="instance" as="element(o:instance)"/>
    <xsl:param name="p" as="element(o:property-value)"/>
    <xsl:param name="step" as="element()"/>
    <!-- the size of a std.vector<int> as an unsigned literal (7u): with an
         int, RTT takes the constructor that builds a vector of its
         arguments ({7}), not the one of 7 elements; every other sequence
         type takes an int size (its elements are not ints) -->
    <xsl:sequence select="concat($instance/@name, '.', $p/@name, $step/@path, ' = ',
        if ($step/@script-type) then concat($step/@script-type, '(', $step/@size, if ($step/@script-type eq 'std.vector&lt;int&gt;') then 'u' else '', ')')
        else $step/@script-value)"/>
  </xsl:function>

  <xsl:function name="fp:simple" as="xs:string">
    <xsl:param name="name" as="xs:string?"/>
    <xsl:param name="type" as="xs:string"/>
    <xsl:param name="value" as="xs:string"/>
    <xsl:sequence select="concat('&lt;simple', if (exists($name)) then concat(' name=&quot;', fp:xml-text($name), '&quot;') else '',
        ' type=&quot;', $type, '&quot;&gt;&lt;value&gt;', fp:xml-text($value), '&lt;/value&gt;&lt;/simple&gt;')"/>
  </xsl:function>

  <xsl:function name="fp:connection-ends" as="xs:string*">
    <xsl:param name="connection" as="element(o:connection)"/>
    <xsl:sequence select="for $w in $connection/o:writer, $r in $connection/o:reader
                          return (concat($w/@instance, '.', $w/@port), concat($r/@instance, '.', $r/@port))"/>
  </xsl:function>

  <!-- "controller after arm, vision; ..." for the instances with
       constraints; () when the deployment has none -->
  <xsl:function name="fp:sequence-note" as="xs:string?">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:variable name="constrained" as="element(o:instance)*" select="$deployment/o:instance[o:start-after]"/>
    <xsl:sequence select="if (empty($constrained)) then ()
        else string-join($constrained ! (concat(@name, ' after ', string-join(distinct-values(o:start-after/@instance), ', '))), '; ')"/>
  </xsl:function>

  <!-- the packages a deployment imports when it streams to ROS topics:
       rtt_ros (its typekit names the C++ primitives as ROS does: int is
       also int32, double float64; RTT 2.10 calls them int, double), the ROS
       node (rtt_rosnode), the ROS transport (rtt_roscomm) and rtt_std_msgs,
       whose primitives transport carries exactly those ROS names: without
       rtt_ros first an int port has no ROS transport ("No such transport
       registered ... for type int") -->
  <xsl:function name="fp:deploy-imports" as="xs:string*">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:sequence select="(if ($deployment/o:connection[@transport eq 'ros']) then fp:deploy-imports-ros() else (),
                          (: OCL's components: the job coordinators are OCL::LuaComponent (orocos-jobs.xsl) :)
                          if ($deployment/o:coordinator) then 'ocl' else ())"/>
  </xsl:function>
  <!-- those packages (also the package.xml's dependencies, orocos-build.xsl) -->
  <xsl:function name="fp:deploy-imports-ros" as="xs:string+">
    <xsl:sequence select="('rtt_ros', 'rtt_rosnode', 'rtt_roscomm', 'rtt_std_msgs')"/>
  </xsl:function>

  <!-- "process 'P' of host 'H': one of N" for the deployment of one of
       several processes (orocos-processes.xsl) -->
  <xsl:function name="fp:process-note" as="xs:string?">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:sequence select="$deployment/@process[xs:integer($deployment/@processes) gt 1]
        ! ('Process ''' || . || '''' || $deployment/@host ! (' of host ''' || . || '''')
           || '; ' || $deployment/@start-script || ' starts the processes of the host in sequence.')"/>
  </xsl:function>

  <!-- what a connection of the deployment is, for a comment -->
  <xsl:function name="fp:connection-note" as="xs:string">
    <xsl:param name="connection" as="element(o:connection)"/>
    <xsl:for-each select="$connection">
      <xsl:sequence select="
          if (@transport-code) then 'stream of ' || (o:writer, o:reader)[1]/(@instance || '.' || @port) || ' to '
               || (if (@transport eq 'ros') then 'ROS topic ' else 'message queue ') || @name-id || ' (connection ' || @name || ')'
          else 'connection point ' || @name || ': ' || string-join(o:writer ! (@instance || '.' || @port), ', ')
               || ' -&gt; ' || string-join(o:reader ! (@instance || '.' || @port), ', ')
               || (if (@proxy) then ' (CORBA: ' || @proxy || ' runs in another process)' else '')"/>
    </xsl:for-each>
  </xsl:function>

  <!-- ================================================ user's tuned values -->
  <!-- the file name of the user's tuned values of instance $i, in deploy/ -->
  <xsl:function name="fp:user-cpf" as="xs:string">
    <xsl:param name="instance" as="element(o:instance)"/>
    <xsl:sequence select="concat($instance/@name, '.user.cpf')"/>
  </xsl:function>

  <!-- deploy/<instance>.user.cpf, written once: an empty property bag (the
       deployer's UpdateProperties then changes nothing) and, in a comment,
       every property of the instance with the model's value, to copy -->
  <xsl:function name="fp:user-cpf-text" as="xs:string">
    <xsl:param name="instance" as="element(o:instance)"/>
    <xsl:variable name="deployment" as="element(o:deployment)" select="$instance/.."/>
    <xsl:sequence select="fp:lines((
        '&lt;?xml version=&quot;1.0&quot; encoding=&quot;UTF-8&quot;?&gt;',
        '&lt;!--',
        fp:indent(2, fp:banner('', $fp:deploy-xsl, fp:comment-text(concat('the tuned property values of instance ''', $instance/@name,
            ''' (', $instance/@type-name, ') of model ''', $deployment/@model-name, '''')), true())),
        concat('  The deployment files load it after the model''s values (', $deployment/@deploy-name, '.xml: UpdateProperties;'),
        concat('  ', $deployment/@deploy-name, '.ops and ', $deployment/@deploy-name, '.lua: the marshalling service''s updateProperties), so a'),
        '  property set here wins and tuning on the robot never means editing a generated file.',
        concat('  ', $deployment/@deploy-name, '.lua finds this file beside itself; ', $deployment/@deploy-name, '.xml and ', $deployment/@deploy-name, '.ops in the'),
        '  working directory: run them from this folder. A property the component does not',
        '  declare is ignored by the deployer (robomda warns, OUT005). The properties and the',
        '  model''s values; copy a line into the properties element below and change its value:',
        $instance/o:property-value ! (fp:indent(4, fp:property-xml(., @name)) ! fp:comment-text(.)),
        '--&gt;',
        '&lt;!DOCTYPE properties SYSTEM &quot;cpf.dtd&quot;&gt;',
        '&lt;properties&gt;',
        '&lt;/properties&gt;'))"/>
  </xsl:function>

  <!-- $s made safe inside an XML comment (no two hyphens in a row) -->
  <xsl:function name="fp:comment-text" as="xs:string">
    <xsl:param name="text" as="xs:string"/>
    <xsl:sequence select="replace($text, '--', '- -')"/>
  </xsl:function>

  <!-- ======================================================= XML -->
  <xsl:function name="fp:deploy-xml" as="xs:string">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:sequence select="fp:lines((
        '&lt;?xml version=&quot;1.0&quot; encoding=&quot;UTF-8&quot;?&gt;',
        '&lt;!--',
        fp:indent(2, fp:banner('', $fp:deploy-xsl, concat('the deployment of model ''', fp:xml-text($deployment/@model-name), ''''), false())),
        concat('  Run: ', fp:deployer-command($deployment, $deployment/@deploy-name || '.xml', fp:naming-address($deployment), string($deployment/@address)),
               ' (add the check option to load, connect and configure only)'),
        fp:process-note($deployment) ! ('  ' || .),
        if ($deployment/o:instance/o:property-value)
        then '  from this folder: the tuned values (*.user.cpf, yours) are read from the working directory.'
        else if ($deployment/o:coordinator)
        then '  from this folder: the job coordinators'' programs are read from the working directory.'
        else (),
        '--&gt;',
        '&lt;!DOCTYPE properties SYSTEM &quot;cpf.dtd&quot;&gt;',
        '&lt;properties&gt;',
        concat('  &lt;!-- the ', if ($deployment/o:types) then 'typekit and the ' else '', 'component library of package ',
               $deployment/@package, ', found through RTT_COMPONENT_PATH --&gt;'),
        fp:deploy-libraries($deployment) ! concat('  ', fp:simple('LoadLibrary', 'string', .)),
        fp:deploy-imports($deployment) ! concat('  ', fp:simple('Import', 'string', .)),
        $deployment/o:connection ! (
          '',
          concat('  &lt;!-- ', fp:connection-note(.), ' --&gt;'),
          concat('  &lt;struct name=&quot;', @name, '&quot; type=&quot;ConnPolicy&quot;&gt;'),
          concat('    ', fp:simple('type', 'long', @type-code), '  &lt;!-- ', @type, ' --&gt;'),
          concat('    ', fp:simple('size', 'long', @size)),
          concat('    ', fp:simple('lock_policy', 'long', @lock-policy-code), '  &lt;!-- ', @lock-policy, ' --&gt;'),
          concat('    ', fp:simple('init', 'boolean', if (xs:boolean(@init)) then '1' else '0')),
          concat('    ', fp:simple('pull', 'boolean', if (xs:boolean(@pull)) then '1' else '0')),
          if (@transport-code) then (concat('    ', fp:simple('transport', 'long', @transport-code), '  &lt;!-- ', @transport, ' --&gt;'),
                                     concat('    ', fp:simple('name_id', 'string', @name-id))) else (),
          '  &lt;/struct&gt;'),
        $deployment/o:proxy ! (
          '',
          concat('  &lt;!-- ', @name, ' runs in another process: a CORBA proxy, found in the naming service --&gt;'),
          concat('  &lt;struct name=&quot;', @name, '&quot; type=&quot;CORBA&quot;&gt;'),
          '    &lt;struct name=&quot;Ports&quot; type=&quot;PropertyBag&quot;&gt;',
          o:port-connection ! (concat('      ', fp:simple(@port, 'string', @connection))),
          '    &lt;/struct&gt;',
          '  &lt;/struct&gt;'),
        for $note in fp:sequence-note($deployment)
        return ('', concat('  &lt;!-- deployment sequence: ', $note, '. The deployer loads, configures and starts'),
                '       the components in the order of this file. --&gt;'),
        $deployment/o:instance ! fp:xml-instance(.),
        $deployment/o:coordinator ! fp:xml-coordinator(.),
        '&lt;/properties&gt;'))"/>
  </xsl:function>

  <xsl:function name="fp:xml-instance" as="xs:string*">
    <xsl:param name="instance" as="element(o:instance)"/>
    <xsl:variable name="activity" as="element(o:activity)" select="$instance/o:activity"/>
    <xsl:sequence select="
        '',
        concat('  &lt;struct name=&quot;', $instance/@name, '&quot; type=&quot;', $instance/@type-name, '&quot;&gt;'),
        concat('    &lt;struct name=&quot;Activity&quot; type=&quot;', $activity/@type, '&quot;&gt;'),
        if ($activity/@master) then (
          concat('      &lt;!-- runs in thread ', $activity/@master, ' (its updateHook executes this one) --&gt;'),
          concat('      ', fp:simple('Master', 'string', $activity/@master)))
        else (
          concat('      ', fp:simple('Period', 'double', fp:period($activity/@period))),
          fp:priority-note($activity) ! concat('      &lt;!-- ', ., ' --&gt;'),
          concat('      ', fp:simple('Priority', 'long', fp:priority($activity))),
          concat('      ', fp:simple('Scheduler', 'string', $activity/@scheduler)),
          if (xs:integer($activity/@cpu-affinity) ne 0) then concat('      ', fp:simple('CpuAffinity', 'ulong', $activity/@cpu-affinity)) else ()),
        '    &lt;/struct&gt;',
        if ($instance/@server = 'true') then (
          concat('    ', fp:simple('Server', 'boolean', '1')),
          concat('    ', fp:simple('UseNamingService', 'boolean', '1'))) else (),
        concat('    ', fp:simple('AutoConf', 'boolean', '1')),
        if ($instance/@idle = 'true') then '    &lt;!-- in a job that runs later: its coordinator starts it --&gt;' else (),
        concat('    ', fp:simple('AutoStart', 'boolean', if ($instance/@idle = 'true') then '0' else '1')),
        if ($instance/o:peer) then (
          '    &lt;struct name=&quot;Peers&quot; type=&quot;PropertyBag&quot;&gt;',
          $instance/o:peer ! (concat('      ', fp:simple((), 'string', @instance))),
          '    &lt;/struct&gt;') else (),
        if ($instance/o:port-connection) then (
          '    &lt;struct name=&quot;Ports&quot; type=&quot;PropertyBag&quot;&gt;',
          $instance/o:port-connection ! (concat('      ', fp:simple(@port, 'string', @connection))),
          '    &lt;/struct&gt;') else (),
        if ($instance/o:property-value) then (
          '    &lt;struct name=&quot;Properties&quot; type=&quot;PropertyBag&quot;&gt;',
          $instance/o:property-value ! fp:indent(6, fp:property-xml(., @name)),
          '    &lt;/struct&gt;',
          '    &lt;!-- then your tuned values (a file of yours, in the working directory) --&gt;',
          concat('    ', fp:simple('UpdateProperties', 'string', fp:user-cpf($instance)))) else (),
        '  &lt;/struct&gt;'"/>
  </xsl:function>

  <!-- ======================================================= .ops -->
  <xsl:function name="fp:deploy-ops" as="xs:string">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:variable name="file" as="xs:string" select="concat($deployment/@deploy-name, '.ops')"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:deploy-xsl, concat('the deployment of model ''', $deployment/@model-name, ''''), false()),
        fp:process-note($deployment) ! ('// ' || .),
        concat('// Run: ', fp:deployer-command($deployment, $file, fp:naming-address($deployment), string($deployment/@address)), if ($deployment/o:instance/o:property-value)
               then ' from this folder (the tuned values, *.user.cpf, are read from the working directory);'
               else if ($deployment/o:coordinator) then ' from this folder (the job coordinators'' programs are read from the working directory);'
               else ' (from any folder;'),
        '// RTT_COMPONENT_PATH must hold the installed package.',
        '// A failing configure() or start() is logged as an [ ERROR ] line; nothing starts when a configure() failed.',
        'require(&quot;print&quot;)',
        fp:deploy-libraries($deployment) ! concat('loadLibrary(', fp:cpp-string(.), ')'),
        fp:deploy-imports($deployment) ! concat('import(', fp:cpp-string(.), ')'),
        'var bool configured = true',
        '',
        $deployment/o:instance ! (concat('loadComponent(', fp:cpp-string(@name), ', ', fp:cpp-string(@type-name), ')')),
        $deployment/o:instance[@server = 'true'] ! concat('server(', fp:cpp-string(@name), ', true)'),
        if ($deployment/o:proxy) then ('', '// components of other processes: CORBA proxies from the naming service',
            $deployment/o:proxy ! concat('loadComponent(', fp:cpp-string(@name), ', &quot;CORBA&quot;)')) else (),
        '',
        '// activities (R5): setActivity(component, period [s], priority, scheduler)',
        $deployment/o:instance ! fp:ops-activity(., $file),
        if ($deployment/o:instance/o:peer) then ('', '// peers', $deployment/o:instance ! (for $p in o:peer return
            concat('addPeer(', fp:cpp-string(@name), ', ', fp:cpp-string($p/@instance), ')'))) else (),
        if ($deployment/o:instance/o:call) then ('', '// operation calls: required interfaces to the components that provide them',
            $deployment/o:instance ! (for $c in o:call return
            concat('connectServices(', fp:cpp-string(@name), ', ', fp:cpp-string($c/@provider), ')  // ', $c/@service))) else (),
        if ($deployment/o:instance/o:property-value) then ('', '// properties (R4)',
            $deployment/o:instance ! (for $p in o:property-value, $step in fp:script-steps($p) return fp:ops-step(., $p, $step)),
            '',
            '// then your tuned values (files of yours, in the working directory)',
            $deployment/o:instance[o:property-value] ! (
              concat('loadService(', fp:cpp-string(@name), ', &quot;marshalling&quot;)'),
              concat('if ( !', @name, '.marshalling.updateProperties(', fp:cpp-string(fp:user-cpf(.)), ') ) then {'),
              (: .ops cannot tell a missing file from a refused one: both causes, and the deployer's own line says which :)
              concat('  print.log(Error, ', fp:cpp-string(concat($file, ': ', fp:user-cpf(.), ' not loaded: it is not in the working directory',
                     ' (run from the folder of ', $file, '), or the deployer refused a value in it (its error above names it)')), ')'),
              '  configured = false',
              '}')) else (),
        $deployment/o:connection ! (
          '',
          concat('// connection point ', @name),
          concat('var ConnPolicy cp_', @name),
          concat('cp_', @name, '.type = ', @type),
          concat('cp_', @name, '.size = ', @size),
          concat('cp_', @name, '.lock_policy = ', @lock-policy),
          concat('cp_', @name, '.init = ', @init),
          concat('cp_', @name, '.pull = ', @pull),
          if (@transport-code) then (concat('// transport ', @transport), concat('cp_', @name, '.transport = ', @transport-code),
                                     concat('cp_', @name, '.name_id = ', fp:cpp-string(@name-id)),
                                     (o:writer, o:reader) ! (
                                       concat('if ( !stream(', fp:cpp-string(@instance || '.' || @port), ', cp_', ../@name, ') ) then {'),
                                       concat('  print.log(Error, ', fp:cpp-string(concat($file, ': stream ', @instance, '.', @port, ' to ', ../@name-id, ' failed')), ')'),
                                       '  configured = false',
                                       '}')) else (),
          let $k := ., $e := fp:connection-ends(.)
          return for $j in 1 to count($e) idiv 2
                 return concat('connect(', fp:cpp-string($e[2 * $j - 1]), ', ', fp:cpp-string($e[2 * $j]), ', cp_', $k/@name, ')')),
        fp:ops-coordinators($deployment),
        '',
        '// lifecycle: configure all, then start all',
        fp:sequence-note($deployment) ! (concat('// in start order (deployment sequence: ', ., ')')),
        if ($deployment/o:instance/@idle = 'true') then '// (the instances of the jobs that run later are only configured: their coordinator starts them)' else (),
        ($deployment/o:instance, $deployment/o:coordinator) ! (
          concat('if ( !', @name, '.configure() ) then {'),
          concat('  print.log(Error, ', fp:cpp-string(concat($file, ': ', @name, '.configure() failed')), ')'),
          '  configured = false',
          '}'),
        'if ( configured ) then {',
        ($deployment/o:instance[not(@idle = 'true')], $deployment/o:coordinator) ! (concat('  if ( !', @name, '.start() ) then print.log(Error, ',
                                 fp:cpp-string(concat($file, ': ', @name, '.start() failed')), ')')),
        '} else {',
        concat('  print.log(Error, ', fp:cpp-string(concat($file, ': not started, a step before the start failed')), ')'),
        '}'))"/>
  </xsl:function>

  <xsl:function name="fp:ops-activity" as="xs:string+">
    <xsl:param name="instance" as="element(o:instance)"/>
    <xsl:param name="file" as="xs:string"/>
    <xsl:variable name="activity" as="element(o:activity)" select="$instance/o:activity"/>
    <xsl:variable name="mask" as="xs:integer" select="xs:integer($activity/@cpu-affinity)"/>
    <xsl:sequence select="
        if ($activity/@master) then (
          concat('// ', $instance/@name, ' runs in thread ', $activity/@master),
          concat('setMasterSlaveActivity(', fp:cpp-string($activity/@master), ', ', fp:cpp-string($instance/@name), ')'))
        else (
        fp:priority-note($activity) ! concat('// ', .),
        concat('setActivity(', fp:cpp-string($instance/@name), ', ', fp:period($activity/@period), ', ', fp:priority($activity), ', ', $activity/@scheduler, ')'),
        if ($mask eq 0) then () else (
          concat('// ', fp:affinity-note($mask)),
          concat('if ( !', $instance/@name, '.setCpuAffinity(', $mask, ') ) then print.log(Error, ',
                 fp:cpp-string(concat($file, ': ', $instance/@name, '.setCpuAffinity(', $mask, ') failed')), ')')))"/>
  </xsl:function>

  <!-- ======================================================= Lua -->
  <!-- the Lua line that sets "here", the folder of the running script -->
  <xsl:variable name="fp:lua-here" as="xs:string"
      select="'local here = debug.getinfo(1, &quot;S&quot;).source:match(&quot;^@(.*)[/\\]&quot;) or &quot;.&quot;'"/>

  <xsl:function name="fp:lua-activity" as="xs:string+">
    <xsl:param name="instance" as="element(o:instance)"/>
    <xsl:variable name="activity" as="element(o:activity)" select="$instance/o:activity"/>
    <xsl:variable name="mask" as="xs:integer" select="xs:integer($activity/@cpu-affinity)"/>
    <xsl:sequence select="
        if ($activity/@master) then
          concat('  check(depl:setMasterSlaveActivity(', fp:cpp-string($activity/@master), ', ', fp:cpp-string($instance/@name),
                 '), &quot;setMasterSlaveActivity ', $activity/@master, ' ', $instance/@name, '&quot;)  -- runs in thread ', $activity/@master)
        else (
        fp:priority-note($activity) ! concat('  -- ', .),
        concat('  check(depl:setActivity(', fp:cpp-string($instance/@name), ', ', fp:period($activity/@period), ', ', fp:priority($activity),
               ', rtt.globals.', $activity/@scheduler, '), &quot;setActivity ', $instance/@name, '&quot;)'),
        if ($mask eq 0) then () else (
          concat('  -- ', fp:affinity-note($mask)),
          concat('  check(comps[', fp:cpp-string($instance/@name), ']:setCpuAffinity(', $mask, '), &quot;', $instance/@name,
                 '.setCpuAffinity(', $mask, ')&quot;)')))"/>
  </xsl:function>

  <!-- Lua deployment: peers, the model's property values, then the tuned
       values of the user files -->
  <xsl:function name="fp:lua-settings" as="xs:string*">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:sequence select="(
        if ($deployment/o:instance/o:peer) then ('', '  -- peers', $deployment/o:instance ! (for $p in o:peer return
            concat('  check(depl:addPeer(', fp:cpp-string(@name), ', ', fp:cpp-string($p/@instance),
             '), &quot;addPeer ', @name, ' -&gt; ', $p/@instance, '&quot;)'))) else (),
        if ($deployment/o:instance/o:call) then ('', '  -- operation calls: required interfaces to the components that provide them',
            $deployment/o:instance ! (for $c in o:call return
            concat('  check(depl:connectServices(', fp:cpp-string(@name), ', ', fp:cpp-string($c/@provider),
             '), &quot;connectServices ', @name, ' -&gt; ', $c/@provider, ' (', $c/@service, ')&quot;)'))) else (),
        if ($deployment/o:instance/o:property-value) then ('', '  -- properties (R4)',
            $deployment/o:instance ! (for $p in o:property-value return fp:lua-property(., $p)),
            '',
            '  -- then your tuned values (files of yours, beside this file)',
            $deployment/o:instance[o:property-value] ! (
              concat('  check(depl:loadService(', fp:cpp-string(@name), ', &quot;marshalling&quot;), &quot;loadService ', @name, ' marshalling&quot;)'),
              concat('  check(comps[', fp:cpp-string(@name), ']:provides(&quot;marshalling&quot;):getOperation(&quot;updateProperties&quot;)(here .. ',
                     fp:cpp-string(concat('/', fp:user-cpf(.))), '), &quot;load ', fp:user-cpf(.), '&quot;)'))) else ())"/>
  </xsl:function>

  <!-- Lua deployment: the model's value of property $p of $instance; a
       data type's or an array's leaves are set on a copy of its value
       (rttlua reaches members and elements by name and index), an
       enumeration literal through RTT's int conversion -->
  <xsl:function name="fp:lua-property" as="xs:string+">
    <xsl:param name="instance" as="element(o:instance)"/>
    <xsl:param name="p" as="element(o:property-value)"/>
    <xsl:variable name="property" as="xs:string"
        select="concat('comps[', fp:cpp-string($instance/@name), ']:getProperty(', fp:cpp-string($p/@name), ')')"/>
    <xsl:variable name="what" as="xs:string" select="concat('&quot;property ', $instance/@name, '.', $p/@name, '&quot;')"/>
    <xsl:sequence select="
        if (empty($p/o:value)) then concat('  check(pcall(function() ', $property, ':set(', $p/@script-value, ') end), ', $what, ')')
        else ('  check(pcall(function()',
              concat('    local p = ', $property),
              '    local v = p:get()',
              fp:script-steps($p) ! (if (@script-type) then concat('    v', @path, ':resize(', @size, ')')
                                     else if (@enum = 'true') then concat('    v', @path, ':assign(rtt.Variable(&quot;int&quot;, ', @script-value, '))')
                                     else concat('    v', @path, ' = ', @script-value)),
              '    p:set(v)',
              concat('  end), ', $what, ')'))"/>
  </xsl:function>

  <!-- check script: a check that Lua expression $get has the value $want
       (near it, for a $real number), saying $label (a Lua expression) and
       what it is -->
  <xsl:function name="fp:lua-value-check" as="xs:string">
    <xsl:param name="get" as="xs:string"/>
    <xsl:param name="want" as="xs:string"/>
    <xsl:param name="real" as="xs:boolean"/>
    <xsl:param name="label" as="xs:string"/>
    <xsl:sequence select="concat('check(', if ($real) then concat('near(', $get, ', ', $want, ')') else concat($get, ' == ', $want),
                                 ', ', $label, ' .. &quot; (is &quot; .. tostring(', $get, ') .. &quot;)&quot;)')"/>
  </xsl:function>

  <!-- check script: the leaves of a data type or an array property, unless
       the user's file tunes it -->
  <xsl:function name="fp:lua-structured-checks" as="xs:string*">
    <xsl:param name="instance" as="element(o:instance)"/>
    <xsl:param name="p" as="element(o:property-value)"/>
    <xsl:variable name="steps" as="element(o:value)*" select="fp:script-steps($p)"/>
    <xsl:if test="exists($steps)">
      <!-- an array's size before its elements; reading an element the
           array lacks is a Lua error, caught and reported as a failure -->
      <xsl:sequence select="
          concat('  if tuned[', fp:cpp-string($instance/@name), '][', fp:cpp-string($p/@name), '] == nil then'),
          '    check(pcall(function()',
          $steps ! (
            let $get := concat('comps[', fp:cpp-string($instance/@name), ']:getProperty(', fp:cpp-string($p/@name), '):get()', @path),
                $value := if (@script-type) then $get || '.size' else if (@enum = 'true') then concat('enum_int(', $get, ')') else $get,
                $want := if (@script-type) then string(@size) else string(@script-value)
            return '      ' || fp:lua-value-check($value, $want, @xml-type = ('double', 'float'),
                fp:cpp-string(concat('property ', $instance/@name, '.', $p/@name, @path, if (@script-type) then '.size' else '', ' = ', $want)))),
          concat('    end), ', fp:cpp-string(concat('property ', $instance/@name, '.', $p/@name, ' read back whole')), ')'),
          '  end'"/>
    </xsl:if>
  </xsl:function>

  <!-- Lua deployment: one connection point, its policy and its links -->
  <xsl:function name="fp:lua-connection" as="xs:string+">
    <xsl:param name="connection" as="element(o:connection)"/>
    <xsl:for-each select="$connection">
      <xsl:sequence select="(
          '',
          concat('  -- connection point ', @name),
          '  do',
          '    local cp = rtt.Variable(&quot;ConnPolicy&quot;)',
          concat('    cp.type = rtt.globals.', @type),
          concat('    cp.size = ', @size),
          concat('    cp.lock_policy = rtt.globals.', @lock-policy),
          concat('    cp.init = ', @init),
          concat('    cp.pull = ', @pull),
          if (@transport-code) then (concat('    cp.transport = ', @transport-code, '  -- ', @transport),
                                     concat('    cp.name_id = ', fp:cpp-string(@name-id)),
                                     (o:writer, o:reader) ! concat('    check(depl:stream(', fp:cpp-string(@instance || '.' || @port),
                                         ', cp), &quot;stream ', @instance, '.', @port, ' to ', ../@name-id, '&quot;)')) else (),
          let $e := fp:connection-ends(.)
          return for $j in 1 to count($e) idiv 2
                 return concat('    check(depl:connect(', fp:cpp-string($e[2 * $j - 1]), ', ', fp:cpp-string($e[2 * $j]),
                         ', cp), &quot;connect ', $e[2 * $j - 1], ' -&gt; ', $e[2 * $j], '&quot;)'),
          '  end')"/>
    </xsl:for-each>
  </xsl:function>

  <xsl:function name="fp:deploy-lua" as="xs:string">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:variable name="file" as="xs:string" select="concat($deployment/@deploy-name, '.lua')"/>
    <xsl:sequence select="fp:lines((
        fp:banner('-- ', $fp:deploy-xsl, concat('the deployment of model ''', $deployment/@model-name, ''''), false()),
        fp:process-note($deployment) ! ('-- ' || .),
        if ($deployment/@corba = 'true')
        then concat('-- Run: ', fp:deployer-command($deployment, $file, fp:naming-address($deployment), string($deployment/@address)))
        else concat('-- Run: deployer -s ', $file, '   or   rttlua -i ', $file),
        '-- (from any folder; RTT_COMPONENT_PATH must hold the installed package). The components keep',
        concat('-- running until the deployer is stopped (Ctrl-C). ', $deployment/@deploy-name, '-check.lua runs this deployment'),
        '-- for a second, checks it and exits with a verdict. A failed step is logged as an [ ERROR ] line;',
        '-- nothing starts when a step before the start failed, and the script ends with a Lua error.',
        'require(&quot;rttlib&quot;)',
        'rttlib.color = false',
        '',
        'local failures = {}',
        'local function check(cond, what)',
        '  if not cond then',
        concat('    rtt.logl(&quot;Error&quot;, ', fp:cpp-string(concat($file, ': ')), ' .. what .. &quot; failed&quot;)'),
        '    failures[#failures + 1] = what',
        '  end',
        '  return cond',
        'end',
        '',
        $fp:lua-here,
        'local tc = rtt.getTC()',
        'local depl',
        '-- rttlua: the deployer is a peer of the lua component; deployer -s: it runs this script itself (any name)',
        'if tc:getName() == &quot;lua&quot; then depl = tc:getPeer(&quot;Deployer&quot;) else depl = tc end',
        concat('local names = {', string-join($deployment/o:instance/@name ! fp:cpp-string(.), ', '), '}'),
        'local comps = {}',
        if ($deployment/o:coordinator) then (
          '-- the instances of the jobs that run later: configured only, their coordinator starts them',
          concat('local idle = {', string-join($deployment/o:instance[@idle = 'true'] ! (fp:cpp-string(@name) ! ('[' || . || '] = true')), ', '), '}'),
          'local coordinators = {}') else (),
        '',
        fp:deploy-libraries($deployment) ! concat('check(depl:loadLibrary(', fp:cpp-string(.), '), &quot;loadLibrary ', ., '&quot;)'),
        fp:deploy-imports($deployment) ! concat('check(depl:import(', fp:cpp-string(.), '), &quot;import ', ., '&quot;)'),
        $deployment/o:instance ! (concat('check(depl:loadComponent(', fp:cpp-string(@name), ', ', fp:cpp-string(@type-name),
                          '), &quot;loadComponent ', @name, '&quot;)')),
        $deployment/o:instance[@server = 'true'] ! concat('check(depl:server(', fp:cpp-string(@name), ', true), &quot;server ', @name, '&quot;)'),
        $deployment/o:proxy ! concat('check(depl:loadComponent(', fp:cpp-string(@name), ', &quot;CORBA&quot;), &quot;proxy ', @name,
                                     ' (a component of another process, from the naming service)&quot;)'),
        '',
        'if #failures == 0 then',
        '  for _, n in ipairs(names) do comps[n] = depl:getPeer(n) end',
        '',
        '  -- activities (R5): setActivity(name, period [s], priority, scheduler)',
        $deployment/o:instance ! fp:lua-activity(.),
        fp:lua-settings($deployment),
        $deployment/o:connection ! fp:lua-connection(.),
        fp:lua-coordinators($deployment),
        '',
        '  -- lifecycle: configure all, then start all',
        fp:sequence-note($deployment) ! (concat('  -- in start order (deployment sequence: ', ., ')')),
        '  for _, n in ipairs(names) do check(comps[n]:configure(), n .. &quot;.configure()&quot;) end',
        $deployment/o:coordinator ! concat('  check(coordinators[', fp:cpp-string(@name), ']:configure(), &quot;', @name, '.configure()&quot;)'),
        '  if #failures == 0 then',
        if ($deployment/o:coordinator)
        then '    for _, n in ipairs(names) do if not idle[n] then check(comps[n]:start(), n .. &quot;.start()&quot;) end end'
        else '    for _, n in ipairs(names) do check(comps[n]:start(), n .. &quot;.start()&quot;) end',
        $deployment/o:coordinator ! concat('    check(coordinators[', fp:cpp-string(@name), ']:start(), &quot;', @name, '.start()&quot;)'),
        '  end',
        'end',
        '',
        'if #failures &gt; 0 then',
        concat('  error(', fp:cpp-string(concat($file, ': deployment failed: ')), ' .. table.concat(failures, &quot;, &quot;), 0)'),
        'end',
        '-- what the check script (or another script that runs this one with dofile) reads',
        if ($deployment/o:coordinator)
        then 'return { deployer = depl, names = names, components = comps, idle = idle, coordinators = coordinators }'
        else 'return { deployer = depl, names = names, components = comps }'))"/>
  </xsl:function>

  <!-- the self-check: deploy with <model>.lua, read back what can be read
       (state, period, CPU affinity, property values), stop, verdict -->
  <!-- check script: the value each property should have, the tuned one of
       <instance>.user.cpf (read with Lua patterns), else the model's -->
  <xsl:function name="fp:lua-tuned-values" as="xs:string+">
    <!-- some property is a data type or an array (its value an o:value tree) -->
    <xsl:param name="structured" as="xs:boolean"/>
    <xsl:sequence select="(
        '  -- the value a property should have: the tuned one of &lt;instance&gt;.user.cpf, else the model''s',
        '  local tuned = {}',
        '  for _, n in ipairs(names) do',
        '    tuned[n] = {}',
        '    local f = io.open(here .. &quot;/&quot; .. n .. &quot;.user.cpf&quot;)',
        '    if f then',
        '      local text = f:read(&quot;*a&quot;):gsub(&quot;&lt;!%-%-.-%-%-&gt;&quot;, &quot;&quot;)',
        '      f:close()',
        '      for p, v in text:gmatch(&quot;&lt;simple%s+name=\&quot;([^\&quot;]*)\&quot;[^&gt;]*&gt;%s*&lt;value&gt;(.-)&lt;/value&gt;&quot;) do tuned[n][p] = v end',
        if ($structured) then (
          '      -- a data type or an array tuned there: its members are the user''s, not checked',
          '      for p in text:gmatch(&quot;&lt;struct%s+name=\&quot;([^\&quot;]*)\&quot;&quot;) do tuned[n][p] = &quot;&quot; end') else (),
        '    end',
        '  end',
        '  local function want(n, p, model)',
        '    local v = tuned[n][p]',
        '    if v == nil then return model end',
        '    if type(model) == &quot;number&quot; then return tonumber(v) end',
        '    if type(model) == &quot;boolean&quot; then return v == &quot;1&quot; or v == &quot;true&quot; end',
        '    v = v:gsub(&quot;&amp;lt;&quot;, &quot;&lt;&quot;):gsub(&quot;&amp;gt;&quot;, &quot;&gt;&quot;):gsub(&quot;&amp;quot;&quot;, &quot;\&quot;&quot;):gsub(&quot;&amp;apos;&quot;, &quot;''&quot;)',
        '    return (v:gsub(&quot;&amp;amp;&quot;, &quot;&amp;&quot;))',
        '  end')"/>
  </xsl:function>

  <!-- check script: the period, CPU affinity and property values of one
       instance read back through the deployer -->
  <xsl:function name="fp:lua-instance-checks" as="xs:string+">
    <xsl:param name="instance" as="element(o:instance)"/>
    <xsl:for-each select="$instance">
      <xsl:sequence select="(
          concat('  check(near(comps[', fp:cpp-string(@name), ']:getPeriod(), ', fp:period(o:activity/@period), '), &quot;',
                 @name, ' period ', fp:period(o:activity/@period), ' (is &quot; .. tostring(comps[', fp:cpp-string(@name), ']:getPeriod()) .. &quot;)&quot;)'),
          if (xs:integer(o:activity/@cpu-affinity) eq 0 or o:activity/@master) then () else
          concat('  check(comps[', fp:cpp-string(@name), ']:getCpuAffinity() == ', o:activity/@cpu-affinity, ', &quot;',
                 @name, ' ', fp:affinity-note(xs:integer(o:activity/@cpu-affinity)), ' (is &quot; .. tostring(comps[',
                 fp:cpp-string(@name), ']:getCpuAffinity()) .. &quot;)&quot;)'),
          for $property in o:property-value[o:value] return fp:lua-structured-checks(., $property),
          for $property in o:property-value[not(o:value)] return
          let $get := concat('comps[', fp:cpp-string(@name), ']:getProperty(', fp:cpp-string($property/@name), '):get()'),
              $want := concat('want(', fp:cpp-string(@name), ', ', fp:cpp-string($property/@name), ', ', $property/@script-value, ')')
          return '  ' || fp:lua-value-check($get, $want, $property/@xml-type = ('double', 'float'),
              fp:cpp-string(concat('property ', @name, '.', $property/@name, ' = ')) || ' .. tostring(' || $want || ')'),
          for $call in o:call return
          concat('  check(comps[', fp:cpp-string(@name), ']:requires(', fp:cpp-string($call/@service), '):ready(), ',
                 fp:cpp-string(concat(@name, ' calls ', $call/@provider, ' through ', $call/@service, ' (every operation connected)')), ')'))"/>
    </xsl:for-each>
  </xsl:function>

  <!-- check script: both ends of each connection of this process connected,
       and, where the writer runs periodically (and is not an instance of a
       job that runs later) and writes its port, data at the reader's port
       (a DATA connection keeps its last sample; an input port read outside
       its component: the check runs once the deployment has run); $whole:
       the deployment of every process, with the task contexts -->
  <xsl:function name="fp:lua-connection-checks" as="xs:string*">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:param name="whole" as="element(o:deployment)"/>
    <xsl:variable name="here" as="xs:string*" select="$deployment/o:instance/@name"/>
    <xsl:for-each select="$deployment/o:connection">
      <xsl:variable name="connection" as="element(o:connection)" select="."/>
      <xsl:variable name="writer" as="element(o:instance)?" select="$deployment/o:instance[@name eq current()/o:writer[1]/@instance]"/>
      <xsl:variable name="sends" as="xs:boolean" select="exists($writer) and $writer/o:activity/@periodic = 'true'
          and exists(o:reader) and exists($whole/o:task-context[@name eq $writer/@task-context]/o:port[@direction eq 'out']
                     [@name eq $connection/o:writer[1]/@port][@accessor-declared = 'true'])"/>
      <xsl:sequence select="(o:writer, o:reader)[@instance = $here] ! concat('  check(comps[', fp:cpp-string(@instance), ']:getPort(',
              fp:cpp-string(@port), '):info().connected, &quot;connection ', $connection/@name, ': ', @instance, '.', @port, ' connected&quot;)'),
          o:reader[$sends][@instance = $here] ! (
              concat('  if not (deployment.idle or {})[', fp:cpp-string($writer/@name), '] then'),
              concat('    local fs = comps[', fp:cpp-string(@instance), ']:getPort(', fp:cpp-string(@port), '):read()'),
              concat('    check(fs ~= &quot;NoData&quot;, &quot;connection ', $connection/@name, ': data from ', $writer/@name, '.',
                     $connection/o:writer[1]/@port, ' at ', @instance, '.', @port, ' (read &quot; .. tostring(fs) .. &quot;)&quot;)'),
              '  end')"/>
    </xsl:for-each>
  </xsl:function>

  <xsl:function name="fp:deploy-check-lua" as="xs:string">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:param name="whole" as="element(o:deployment)"/>
    <xsl:variable name="file" as="xs:string" select="concat($deployment/@deploy-name, '-check.lua')"/>
    <xsl:variable name="corba" as="xs:boolean" select="$deployment/@corba = 'true'"/>
    <xsl:sequence select="fp:lines((
        fp:banner('-- ', $fp:deploy-xsl, concat('the self-check of the deployment of model ''', $deployment/@model-name, ''''), false()),
        if ($corba) then (
          concat('-- Run: rttlua-corba ', $file, ' -- -ORBInitRef NameService=corbaname::', fp:naming-address($deployment),
                 $deployment/@address[. ne ''] ! (' -ORBendPoint giop:tcp:' || . || ':')),
          concat('-- instead of this process (', $deployment/@start-script, ' starts it), with the processes before it running.'))
        else concat('-- Run: rttlua ', $file, '   (or deployer -s ', $file, ')'),
        concat('-- Runs ', $deployment/@deploy-name, '.lua (beside this file) for one second, checks that every component is Running'),
        '-- with the modelled period, CPU affinity and property values, that both ends of every connection',
        '-- are connected and data reached each reader whose writer runs periodically, stops and unloads',
        '-- everything, and exits 0 when all is as modelled, 1 otherwise.',
        'require(&quot;rttlib&quot;)',
        'rttlib.color = false',
        '',
        if ($corba) then (
          '-- a process of several: its components are CORBA servers, the deployer must be rttlua-corba''s',
          'if not rtt.getTC():getPeer(&quot;Deployer&quot;):hasOperation(&quot;server&quot;) then',
          concat('  print(&quot;DEPLOY-CHECK FAILED: no CORBA deployer: run rttlua-corba ', $file,
                 ' -- -ORBInitRef NameService=corbaname::', fp:naming-address($deployment), '&quot;)'),
          '  print(&quot;DEPLOY-RESULT: FAILED&quot;)',
          '  os.exit(1)',
          'end') else (),
        $fp:lua-here,
        concat('local loaded, deployment = pcall(dofile, here .. ', fp:cpp-string(concat('/', $deployment/@deploy-name, '.lua')), ')'),
        'local ok = loaded',
        'local function check(cond, what)',
        '  if not cond then',
        '    rtt.logl(&quot;Error&quot;, &quot;DEPLOY-CHECK FAILED: &quot; .. what)',
        '    print(&quot;DEPLOY-CHECK FAILED: &quot; .. what)',
        '    ok = false',
        '  end',
        'end',
        'if not loaded then print(&quot;DEPLOY-CHECK FAILED: &quot; .. tostring(deployment)) end',
        '',
        'if loaded then',
        '  local depl, comps, names = deployment.deployer, deployment.components, deployment.names',
        '  rtt.sleep(1, 0)  -- let it run 1 s',
        if ($deployment/o:coordinator) then (
          '  -- the instances of the jobs that run later are configured, not started',
          '  for _, n in ipairs(names) do',
          '    local s, w = comps[n]:getState(), deployment.idle[n] and &quot;Stopped&quot; or &quot;Running&quot;',
          '    check(s == w, n .. &quot; &quot; .. w .. &quot; (is &quot; .. tostring(s) .. &quot;)&quot;)',
          '  end',
          '  for c, coordinator in pairs(deployment.coordinators) do',
          '    local s = coordinator:getState()',
          '    check(s == &quot;Running&quot;, c .. &quot; Running (is &quot; .. tostring(s) .. &quot;)&quot;)',
          '  end') else (
        '  for _, n in ipairs(names) do',
        '    local s = comps[n]:getState()',
        '    check(s == &quot;Running&quot;, n .. &quot; Running (is &quot; .. tostring(s) .. &quot;)&quot;)',
        '  end'),
        '  -- numbers read back as doubles (a float property to about 7 digits)',
        '  local function near(a, b) return math.abs(a - b) &lt;= 1e-6 * math.max(1, math.abs(b)) end',
        if ($deployment//o:value[@enum = 'true'])
        then '  local function enum_int(v) local i = rtt.Variable(&quot;int&quot;); i:assign(v); return i:tolua() end' else (),
        fp:lua-tuned-values(exists($deployment/o:instance/o:property-value/o:value)),
        '  -- a Lua error in a check is a failed check (rttlua would exit 0 on it)',
        '  local checked, failure = pcall(function()',
        $deployment/o:instance ! fp:lua-instance-checks(.),
        fp:lua-connection-checks($deployment, $whole),
        $deployment/o:proxy ! concat('  check(depl:getPeer(', fp:cpp-string(@name), '):getState() == &quot;Running&quot;, &quot;', @name,
                 ' (a component of another process) Running&quot;)'),
        '  end)',
        '  check(checked, &quot;the check itself: &quot; .. tostring(failure))',
        if ($deployment/o:coordinator) then (
          '  -- the coordinators first (no switch while the rest stops)',
          '  for c, coordinator in pairs(deployment.coordinators) do coordinator:stop(); coordinator:cleanup(); depl:unloadComponent(c) end')
        else (),
        '  -- in the reverse start order',
        '  for i = #names, 1, -1 do comps[names[i]]:stop() end',
        if ($corba) then (
          '  -- every port disconnected before the unload: RTT 2.10 unloads a component''s CORBA server first, and',
          '  -- then never returns from disconnecting a port connected to another process',
          '  for i = #names, 1, -1 do',
          '    for _, p in ipairs(comps[names[i]]:getPortNames()) do comps[names[i]]:getPort(p):disconnect() end',
          '  end') else (),
        '  for i = #names, 1, -1 do comps[names[i]]:cleanup() end',
        '  for i = #names, 1, -1 do depl:unloadComponent(names[i]) end',
        'end',
        '',
        if ($corba) then (
          'if not loaded then',
          '  -- what the failed deployment loaded goes all the same (its connections to other processes with it)',
          '  local depl = rtt.getTC():getPeer(&quot;Deployer&quot;)',
          concat('  local names = {', string-join($deployment/o:instance/@name ! fp:cpp-string(.), ', '), '}'),
          '  for i = #names, 1, -1 do',
          '    local there, c = pcall(depl.getPeer, depl, names[i])',
          '    if there then',
          '      pcall(function() c:stop() end)',
          '      for _, p in ipairs(c:getPortNames()) do pcall(function() c:getPort(p):disconnect() end) end',
          '      pcall(function() c:cleanup(); depl:unloadComponent(names[i]) end)',
          '    end',
          '  end',
          'end') else (),
        'print(ok and &quot;DEPLOY-RESULT: OK&quot; or &quot;DEPLOY-RESULT: FAILED&quot;)',
        if ($corba) then (
          '-- the proxies of the other processes'' components stay (they cannot be unloaded while those run);',
          '-- the ORB goes down first: os.exit with it running never returns',
          'local depl = rtt.getTC():getPeer(&quot;Deployer&quot;)',
          'depl:getProperty(&quot;AutoUnload&quot;):set(false)',
          'depl:getOperation(&quot;shutdown&quot;)()',
          'rtt.sleep(0, 500000000)  -- its thread ends (os.exit right after shutdown may crash)') else (),
        '-- rttlua always exits 0 by itself; os.exit propagates the verdict.',
        'os.exit(ok and 0 or 1)'))"/>
  </xsl:function>
</xsl:stylesheet>
