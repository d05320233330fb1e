<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/openrtm/openrtm-deploy.xsl - how the system starts (part of
  xslt/m2t/openrtm/main.xsl): each instance's .conf, each manager's
  rtc.conf, and a start script per host.

  Reads:   r:instance, r:process, r:connection, r:component, r:system of the OpenRTM PSM.
  Writes:  strings:
           conf/<instance>.conf    execution context (type, rate, CPU
                                   affinity when modelled) and the values of
                                   configuration set "default"
           deploy/<process>.rtc.conf  the manager rtcd2 runs: naming
                                   (%n.rtc), its modules, its components
                                   (precreate, in start order, each with its
                                   .conf), the connections it makes
                                   (preconnect: each connection and operation
                                   call is made by the later of its ends'
                                   managers in start order, the other end
                                   found through the naming service,
                                   rtcname://*/), activation
                                   in start order (preactivation); with
                                   jobs its job coordinators after its
                                   instances, and no instance of a job
                                   other than the initial one activated
                                   (fp:rtm-activated, openrtm-jobs.xsl)
           deploy/start_<host>.sh  starts the host's managers in order, each
                                   once the one before has activated its
                                   components (those it activates)
  Params:  none (main.xsl's).
  Errors:  none.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-openrtm:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- look-ups in the PSM (the document main.xsl reads; its r:system is
       the document element): a process by its file, an instance by its
       name, the instances of a process, a component by its class. No scan
       of every instance or component per instance, connection or process
       (issue 35) -->
  <xsl:key name="fp:rtm-process" match="r:system/r:process" use="@file"/>
  <xsl:key name="fp:rtm-instance" match="r:system/r:instance" use="@name"/>
  <xsl:key name="fp:rtm-instance-in" match="r:system/r:instance" use="@process"/>
  <xsl:key name="fp:rtm-component" match="r:system/r:component" use="@class"/>
  <!-- the connections with an end in a process (the only ones its manager may make) -->
  <xsl:key name="fp:rtm-connection-in" match="r:system/r:connection" use="(r:writer | r:reader)/@process"/>

  <xsl:function name="fp:instance-conf" as="xs:string">
    <xsl:param name="i" as="element(r:instance)"/>
    <xsl:sequence select="fp:lines((
      fp:banner('# ', $fp:deploy-xsl, 'instance ''' || $i/@name || ''' of model ''' || $i/../@model-name || '''', false()),
      '# execution context: period ' || $i/@period || ' s',
      'exec_cxt.periodic.type: PeriodicExecutionContext',
      'exec_cxt.periodic.rate: ' || $i/@rate,
      $i/@cpu-affinity ! ('exec_cxt.periodic.cpu_affinity: ' || .),
      $i/r:parameter-value ! ('conf.default.' || @name || ': ' || @value)))"/>
  </xsl:function>

  <!-- a port in a preconnect entry: local by instance name, else through the naming service -->
  <xsl:function name="fp:rtm-port-ref" as="xs:string">
    <xsl:param name="end" as="element()"/>
    <xsl:param name="process" as="element(r:process)"/>
    <xsl:sequence select="(if ($end/@process eq $process/@file) then '' else 'rtcname://*/') || $end/@instance || '.' || $end/@port"/>
  </xsl:function>

  <!-- the manager that makes the connection of $a and $b: the later of theirs
       in start order (the other one's components exist by then) -->
  <xsl:function name="fp:rtm-maker" as="element(r:process)">
    <xsl:param name="a" as="element()"/>
    <xsl:param name="b" as="element()"/>
    <xsl:param name="s" as="element(r:system)"/>
    <xsl:variable name="processes" as="element(r:process)+" select="key('fp:rtm-process', ($a/@process, $b/@process) ! string(.), root($s))"/>
    <xsl:sequence select="$processes[last()]"/>
  </xsl:function>

  <xsl:function name="fp:rtm-service-ref" as="xs:string">
    <xsl:param name="instance" as="xs:string"/>
    <xsl:param name="port" as="xs:string"/>
    <xsl:param name="s" as="element(r:system)"/>
    <xsl:param name="process" as="element(r:process)"/>
    <xsl:sequence select="(if (key('fp:rtm-instance', $instance, root($s))/@process eq $process/@file) then '' else 'rtcname://*/') || $instance || '.' || $port"/>
  </xsl:function>

  <xsl:function name="fp:rtc-conf" as="xs:string">
    <xsl:param name="s" as="element(r:system)"/>
    <xsl:param name="p" as="element(r:process)"/>
    <xsl:variable name="members" as="element(r:instance)*" select="key('fp:rtm-instance-in', string($p/@file), root($s))"/>
    <xsl:variable name="connects" as="xs:string*"
        select="for $r in key('fp:rtm-connection-in', string($p/@file), root($s))/r:reader, $w in $r/../r:writer[fp:rtm-maker(., $r, $s) is $p] return (
                  fp:rtm-port-ref($w, $p) || '?port=' || fp:rtm-port-ref($r, $p)
                  || '&amp;dataflow_type=' || $r/../@dataflow-type || '&amp;interface_type=' || $r/../@interface-type
                  || '&amp;subscription_type=' || $r/../@subscription-type || '&amp;buffer.length=' || $r/../@buffer-length
                  || '&amp;buffer.write.full_policy=' || $r/../@full-policy)"/>
    <xsl:variable name="calls" as="xs:string*"
        select="for $k in $s/r:service-connection
                return (if (fp:rtm-maker(key('fp:rtm-instance', string($k/@caller), root($s)), key('fp:rtm-instance', string($k/@provider), root($s)), $s) is $p)
                        then $k else ())
                ! (
                  fp:rtm-service-ref(@caller, @caller-port, $s, $p) || '?port=' || fp:rtm-service-ref(@provider, @provider-port, $s, $p))"/>
    <xsl:sequence select="fp:lines((
      fp:banner('# ', $fp:deploy-xsl, 'process ''' || $p/@name || ''' of model ''' || $s/@model-name || '''', false()),
      '# Run: rtcd2 -f ' || $p/@file || '.rtc.conf (deploy/start_*.sh does, in the modelled order)',
      'corba.nameservers: ' || $p/@host,
      'naming.formats: %n.rtc',
      'manager.instance_name: ' || $p/@file,
      'manager.shutdown_on_nortcs: NO',
      'manager.shutdown_auto: NO',
      'logger.enable: YES',
      'logger.file_name: ' || $p/@file || '.log',
      'logger.log_level: INFO',
      '',
      '# the component modules (lib/' || $s/@package || '/&lt;Class&gt;.so; the start script sets the folder)',
      'manager.preload.modules: ' || string-join(distinct-values(($members/@component, fp:rtm-coordinators-in($p)/@class)) ! (. || '.so'), ', '),
      '# the instances, in start order, each with its configuration',
      'manager.components.precreate: ' || string-join(($members ! (@component || '?instance_name=' || @name),
                                                       fp:rtm-coordinators-in($p) ! (@class || '?instance_name=' || @name)), ', '),
      $members ! (@category || '.' || @name || '.config_file: ../conf/' || @name || '.conf'),
      fp:rtm-coordinators-in($p) ! ('# the job coordinator of subsystem ' || @name || ': it polls its events at 20 Hz',
                                    ../@package || '.' || @name || '.exec_cxt.periodic.rate: 20'),
      '# the connections and operation calls whose later end (in start order) is here',
      'manager.components.preconnect: ' || string-join(($connects, $calls), ', '),
      '# activation in start order' || (if ($members/@idle = 'true') then
        ('; not the instances of a job other than the initial one: the job coordinator activates them') else ''),
      'manager.components.preactivation: ' || string-join(fp:rtm-activated($p), ', ')))"/>
  </xsl:function>

  <xsl:function name="fp:rtm-start-script" as="xs:string">
    <xsl:param name="s" as="element(r:system)"/>
    <xsl:param name="processes" as="element(r:process)+"/>
    <xsl:sequence select="fp:lines((
      '#!/bin/sh',
      fp:banner('# ', $fp:deploy-xsl, 'host ''' || $processes[1]/@host-name || ''' of model ''' || $s/@model-name || '''', false()),
      '# Starts the managers of this host in the modelled order; each starts once the one',
      '# before has activated its components. Needs a naming service (rtm2-naming or',
      '# omniNames) at corba.nameservers. Environment: RTM_MODULES (the folder of the',
      '# component modules, default ../build), RTM_NAMESERVER (host:port, default the',
      '# rtc.conf''s), RTM_WAIT (seconds to wait for each manager, default 30).',
      'set -e',
      'cd &quot;$(dirname &quot;$0&quot;)&quot;',
      'MODULES=${RTM_MODULES:-$(cd ../build &amp;&amp; pwd)}',
      'WAIT=${RTM_WAIT:-30}',
      'set -- -o &quot;manager.modules.load_path: $MODULES&quot;',
      '[ -n &quot;${RTM_NAMESERVER:-}&quot; ] &amp;&amp; set -- &quot;$@&quot; -o &quot;corba.nameservers: $RTM_NAMESERVER&quot;',
      '# wait_active LOG NAME...: until the manager''s log says each NAME is activated',
      'wait_active() {',
      '  log=$1; shift',
      '  for n in &quot;$@&quot;; do',
      '    t=0',
      '    until grep -q &quot;$n activated&quot; &quot;$log&quot; 2&gt;/dev/null; do',
      '      t=$((t + 1)); [ $t -le $((WAIT * 10)) ] || { echo &quot;start: $n not active after $WAIT s (see $log)&quot; &gt;&amp;2; exit 1; }',
      '      sleep 0.1',
      '    done',
      '  done',
      '}',
      $processes ! (
        '',
        '# manager ' || @name || ': ' || string-join(tokenize(@members), ', '),
        'rm -f ' || @file || '.log',
        'rtcd2 -f ' || @file || '.rtc.conf &quot;$@&quot; &amp;',
        'echo &quot;started manager ' || @file || ' (pid $!)&quot;',
        'wait_active ' || @file || '.log ' || string-join(fp:rtm-activated(.), ' ')),
      'wait'))"/>
  </xsl:function>
</xsl:stylesheet>
