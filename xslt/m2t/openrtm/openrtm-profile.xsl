<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/openrtm/openrtm-profile.xsl - the XML profiles of OpenRTM's tools
  (part of xslt/m2t/openrtm/main.xsl): a component's RTC.xml (RtcProfile,
  as RTCBuilder writes it) and the system's RtsProfile (as RTSystemEditor
  and rtshell read it).

  Reads:   r:component, r:instance, r:connection, r:system of the OpenRTM PSM.
  Writes:  strings: RTC.xml (BasicInfo, Actions, ConfigurationSet,
           DataPorts, ServicePorts, Language) and the RtsProfile (Components with their
           data ports, configuration set and execution context,
           DataPortConnectors with the buffer settings as rtsExt
           Properties, ServicePortConnectors, StartUp and Activation with a Preceding condition
           per modelled StartAfter; Activation without the instances a job
           coordinator activates later). Checked against
           tests/schemas/openrtm/*.xsd by tests/test_openrtm.py.
  Params:  none (main.xsl's).
  Errors:  none.
  Dates: an RtsProfile requires creation and update dates; robomda writes
  a fixed one (the output is the same for the same model).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-openrtm:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- the instances of a component (its RTC.xml's rate is the first one's):
       a look-up, not a scan of the system's instances per component -->
  <xsl:key name="fp:rtm-instance-of" match="r:system/r:instance" use="@component"/>

  <xsl:variable name="fp:rtm-date" as="xs:string" select="'2000-01-01T00:00:00'"/>
  <!-- RTC.xml's Actions, in RTCBuilder's order, and the lifecycle hook each calls -->
  <xsl:variable name="fp:rtc-actions" as="xs:string+" select="('OnInitialize', 'OnFinalize', 'OnStartup', 'OnShutdown',
      'OnActivated', 'OnDeactivated', 'OnAborting', 'OnError', 'OnReset', 'OnExecute', 'OnStateUpdate', 'OnRateChanged')"/>
  <xsl:variable name="fp:rtc-action-hook" as="map(xs:string, xs:string)"
      select="map { 'OnInitialize': 'configure', 'OnFinalize': 'cleanup', 'OnActivated': 'start',
                    'OnDeactivated': 'stop', 'OnExecute': 'update' }"/>

  <!-- attribute text: name="value" with the value escaped -->
  <xsl:function name="fp:att" as="xs:string">
    <xsl:param name="name" as="xs:string"/>
    <xsl:param name="value" as="xs:string?"/>
    <xsl:sequence select="$name || '=&quot;' || fp:xml-text($value) || '&quot;'"/>
  </xsl:function>

  <xsl:function name="fp:rtc-id" as="xs:string">
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:sequence select="'RTC:robomda:' || $c/@category || ':' || $c/@type-name || ':1.0.0'"/>
  </xsl:function>

  <xsl:function name="fp:rtc-profile" as="xs:string">
    <xsl:param name="c" as="element(r:component)"/>
    <xsl:param name="version" as="xs:string"/>
    <xsl:variable name="rate" as="xs:string" select="(key('fp:rtm-instance-of', string($c/@class), root($c))/@rate, '1000.0')[1]"/>
    <!-- the IDL file of the system's data types (openrtm-cpp.xsl's key) -->
    <xsl:variable name="idl" as="xs:string?" select="key('fp:rtm-data-types', 'data-types', root($c))/@idl"/>
    <xsl:variable name="wrapper" as="xs:boolean" select="$c/@kind eq 'wrapper'"/>
    <xsl:sequence select="fp:lines((
      '&lt;?xml version=&quot;1.0&quot; encoding=&quot;UTF-8&quot;?&gt;',
      fp:banner('&lt;!-- ', $fp:profile-xsl, fp:what($c), false()) ! (. || ' --&gt;'),
      '&lt;rtc:RtcProfile xmlns:rtc=&quot;http://www.openrtp.org/namespaces/rtc&quot; ' || fp:att('rtc:version', '0.3') || ' '
        || fp:att('rtc:id', fp:rtc-id($c)) || '&gt;',
      '  &lt;rtc:BasicInfo ' || string-join((fp:att('rtc:name', $c/@type-name), fp:att('rtc:category', $c/@category),
          fp:att('rtc:vendor', 'robomda'), fp:att('rtc:version', '1.0.0'), fp:att('rtc:description', fp:doc-of($c, 'component ' || $c/@name)),
          fp:att('rtc:componentType', 'STATIC'), fp:att('rtc:activityType', 'PERIODIC'), fp:att('rtc:componentKind', 'DataFlowComponent'),
          fp:att('rtc:maxInstances', '0'), fp:att('rtc:executionType', 'PeriodicExecutionContext'), fp:att('rtc:executionRate', $rate),
          fp:att('rtc:creationDate', $fp:rtm-date), fp:att('rtc:updateDate', $fp:rtm-date)), ' ') || '/&gt;',
      '  &lt;rtc:Actions&gt;',
      $fp:rtc-actions ! ('    &lt;rtc:' || . || ' ' || fp:att('rtc:implemented',
          string(. = 'OnInitialize' or ($wrapper and map:contains($fp:rtc-action-hook, .)))) || '/&gt;'),
      '  &lt;/rtc:Actions&gt;',
      if ($c/r:parameter) then (
        '  &lt;rtc:ConfigurationSet&gt;',
        $c/r:parameter ! ('    &lt;rtc:Configuration ' || fp:att('rtc:name', @name) || ' ' || fp:att('rtc:type', @type) || ' '
                          || fp:att('rtc:defaultValue', @default) || '/&gt;'),
        '  &lt;/rtc:ConfigurationSet&gt;') else (),
      $c/r:data-port ! ('  &lt;rtc:DataPorts ' || string-join((
          fp:att('rtc:portType', if (@direction eq 'out') then 'DataOutPort' else 'DataInPort'), fp:att('rtc:name', @name),
          fp:att('rtc:type', @timed),
          fp:att('rtc:idlFile', if (starts-with(@timed, 'RTC::')) then 'BasicDataType.idl' else $idl || '.idl'), fp:att('rtc:interfaceType', 'corba_cdr'),
          fp:att('rtc:dataflowType', 'push,pull'), fp:att('rtc:subscriptionType', 'flush,new,periodic')), ' ') || '/&gt;'),
      $c/r:service-port ! (
        '  &lt;rtc:ServicePorts ' || fp:att('rtc:name', @name) || '&gt;',
        '    &lt;rtc:ServiceInterface ' || string-join((fp:att('rtc:direction', if (@role eq 'provided') then 'Provided' else 'Required'),
            fp:att('rtc:name', @interface), fp:att('rtc:type', @interface), fp:att('rtc:instanceName', @interface),
            fp:att('rtc:idlFile', @interface || '.idl')), ' ') || '/&gt;',
        '  &lt;/rtc:ServicePorts&gt;'),
      '  &lt;rtc:Language ' || fp:att('rtc:kind', 'C++') || '/&gt;',
      '&lt;/rtc:RtcProfile&gt;'))"
      xmlns:map="http://www.w3.org/2005/xpath-functions/map"/>
  </xsl:function>

  <!-- the IDL repository id of a TimedXxx type: RTC::TimedLong -> IDL:RTC/TimedLong:1.0 -->
  <xsl:function name="fp:idl-id" as="xs:string">
    <xsl:param name="type" as="xs:string"/>
    <xsl:sequence select="'IDL:' || replace($type, '::', '/') || ':1.0'"/>
  </xsl:function>

  <xsl:function name="fp:rts-profile" as="xs:string">
    <xsl:param name="s" as="element(r:system)"/>
    <xsl:param name="version" as="xs:string"/>
    <xsl:variable name="component-id" as="map(xs:string, xs:string)"
        select="map:merge(for $i in $s/r:instance return map:entry(string($i/@name), fp:rtc-id(key('fp:rtm-component', string($i/@component), root($s)))))"
        xmlns:map="http://www.w3.org/2005/xpath-functions/map"/>
    <xsl:sequence select="fp:lines((
      '&lt;?xml version=&quot;1.0&quot; encoding=&quot;UTF-8&quot;?&gt;',
      fp:banner('&lt;!-- ', $fp:profile-xsl, 'model ''' || $s/@model-name || '''', false()) ! (. || ' --&gt;'),
      '&lt;rts:RtsProfile xmlns:rts=&quot;http://www.openrtp.org/namespaces/rts&quot; xmlns:rtsExt=&quot;http://www.openrtp.org/namespaces/rts_ext&quot; xmlns:xsi=&quot;http://www.w3.org/2001/XMLSchema-instance&quot; '
        || string-join((fp:att('rts:id', 'RTSystem:robomda:' || $s/@deploy-name || ':' || $version), fp:att('rts:abstract', 'model ' || $s/@model-name),
                        fp:att('rts:creationDate', $fp:rtm-date), fp:att('rts:updateDate', $fp:rtm-date), fp:att('rts:version', '0.2')), ' ') || '&gt;',
      $s/r:instance ! fp:rts-component(., $s, $component-id(string(@name))),
      $s/r:connection ! fp:rts-connector(., $s, $component-id),
      $s/r:service-connection ! (
        '  &lt;rts:ServicePortConnectors ' || fp:att('rts:connectorId', @name) || ' ' || fp:att('rts:name', @name) || '&gt;',
        '    &lt;rts:sourceServicePort ' || string-join((fp:att('rts:portName', @caller || '.' || @caller-port),
            fp:att('rts:instanceName', @caller), fp:att('rts:componentId', $component-id(string(@caller)))), ' ') || '/&gt;',
        '    &lt;rts:targetServicePort ' || string-join((fp:att('rts:portName', @provider || '.' || @provider-port),
            fp:att('rts:instanceName', @provider), fp:att('rts:componentId', $component-id(string(@provider)))), ' ') || '/&gt;',
        '  &lt;/rts:ServicePortConnectors&gt;'),
      fp:rts-sequence('StartUp', $s, $component-id),
      fp:rts-sequence('Activation', $s, $component-id),
      '&lt;/rts:RtsProfile&gt;'))"/>
  </xsl:function>

  <xsl:function name="fp:rts-component" as="xs:string+">
    <xsl:param name="i" as="element(r:instance)"/>
    <xsl:param name="s" as="element(r:system)"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:variable name="c" as="element(r:component)" select="key('fp:rtm-component', string($i/@component), root($s))"/>
    <xsl:sequence select="(
      '  &lt;rts:Components ' || string-join((fp:att('rts:id', $id), fp:att('rts:pathUri', key('fp:rtm-process', string($i/@process), root($s))/@host || '/' || $i/@name || '.rtc'),
          fp:att('rts:instanceName', $i/@name), fp:att('rts:activeConfigurationSet', 'default'), fp:att('rts:compositeType', 'None'),
          fp:att('rts:isRequired', 'true')), ' ') || '&gt;',
      $c/r:data-port ! ('    &lt;rts:DataPorts ' || fp:att('rts:name', $i/@name || '.' || @name) || '/&gt;'),
      $c/r:service-port ! ('    &lt;rts:ServicePorts ' || fp:att('rts:name', $i/@name || '.' || @name) || '/&gt;'),
      '    &lt;rts:ConfigurationSets ' || fp:att('rts:id', 'default') || (if ($i/r:parameter-value) then '&gt;' else '/&gt;'),
      if ($i/r:parameter-value) then (
        $i/r:parameter-value ! ('      &lt;rts:ConfigurationData ' || fp:att('rts:name', @name) || ' ' || fp:att('rts:data', @value) || '/&gt;'),
        '    &lt;/rts:ConfigurationSets&gt;') else (),
      '    &lt;rts:ExecutionContexts ' || fp:att('rts:id', '0') || ' ' || fp:att('rts:kind', 'PERIODIC') || ' ' || fp:att('rts:rate', $i/@rate) || '/&gt;',
      '  &lt;/rts:Components&gt;')"/>
  </xsl:function>

  <xsl:function name="fp:rts-connector" as="xs:string*">
    <xsl:param name="k" as="element(r:connection)"/>
    <xsl:param name="s" as="element(r:system)"/>
    <xsl:param name="component-id" as="map(xs:string, xs:string)"/>
    <xsl:for-each select="$k/r:writer">
      <xsl:variable name="w" as="element(r:writer)" select="."/>
      <xsl:variable name="timed" as="xs:string"
          select="key('fp:rtm-component', string(key('fp:rtm-instance', string($w/@instance), root($s))/@component), root($s))/r:data-port[@name eq $w/@port]/@timed"/>
      <xsl:for-each select="$k/r:reader">
        <xsl:variable name="name" as="xs:string" select="$k/@name || (if (count($k/r:writer) * count($k/r:reader) gt 1) then '_' || $w/@instance || '_' || @instance else '')"/>
        <xsl:sequence select="(
          '  &lt;rts:DataPortConnectors xsi:type=&quot;rtsExt:dataport_connector_ext&quot; ' || string-join((fp:att('rts:connectorId', $name),
              fp:att('rts:name', $name), fp:att('rts:dataType', fp:idl-id($timed)), fp:att('rts:interfaceType', $k/@interface-type),
              fp:att('rts:dataflowType', $k/@dataflow-type), fp:att('rts:subscriptionType', $k/@subscription-type)), ' ') || '&gt;',
          fp:rts-port('sourceDataPort', $w, $component-id),
          fp:rts-port('targetDataPort', ., $component-id),
          '    &lt;rtsExt:Properties ' || fp:att('rtsExt:name', 'dataport.buffer.length') || ' ' || fp:att('rtsExt:value', $k/@buffer-length) || '/&gt;',
          '    &lt;rtsExt:Properties ' || fp:att('rtsExt:name', 'dataport.buffer.write.full_policy') || ' ' || fp:att('rtsExt:value', $k/@full-policy) || '/&gt;',
          '  &lt;/rts:DataPortConnectors&gt;')"/>
      </xsl:for-each>
    </xsl:for-each>
  </xsl:function>

  <xsl:function name="fp:rts-port" as="xs:string">
    <xsl:param name="element" as="xs:string"/>
    <xsl:param name="end" as="element()"/>
    <xsl:param name="component-id" as="map(xs:string, xs:string)"/>
    <xsl:sequence select="'    &lt;rts:' || $element || ' ' || string-join((fp:att('rts:portName', $end/@instance || '.' || $end/@port),
        fp:att('rts:instanceName', $end/@instance), fp:att('rts:componentId', $component-id(string($end/@instance)))), ' ') || '/&gt;'"/>
  </xsl:function>

  <!-- StartUp / Activation: a target per instance in start order (Activation: not one of a job other
       than the initial one, which the job coordinator activates); its StartAfter instances precede it.
       TargetComponent and PrecedingComponents name an execution context of the instance (rts:id, the
       id of its ExecutionContexts: "0"), as rtsprofile's TargetExecutionContext reads them -->
  <xsl:function name="fp:rts-sequence" as="xs:string+">
    <xsl:param name="element" as="xs:string"/>
    <xsl:param name="s" as="element(r:system)"/>
    <xsl:param name="component-id" as="map(xs:string, xs:string)"/>
    <xsl:sequence select="(
      '  &lt;rts:' || $element || '&gt;',
      $s/r:instance[not($element eq 'Activation' and @idle = 'true')] ! (
        '    &lt;rts:targets ' || fp:att('rts:sequence', string(position() - 1)) || '&gt;',
        '      &lt;rts:TargetComponent ' || fp:att('rts:componentId', $component-id(string(@name))) || ' ' || fp:att('rts:instanceName', @name)
          || ' ' || fp:att('rts:id', '0') || '/&gt;',
        if (r:start-after) then (
          '      &lt;rts:Preceding ' || fp:att('rts:timeout', '10000') || ' ' || fp:att('rts:sendingTiming', 'SYNC') || '&gt;',
          r:start-after ! ('        &lt;rts:PrecedingComponents ' || fp:att('rts:componentId', $component-id(string(@instance))) || ' '
                            || fp:att('rts:instanceName', @instance) || ' ' || fp:att('rts:id', '0') || '/&gt;'),
          '      &lt;/rts:Preceding&gt;') else (),
        '    &lt;/rts:targets&gt;'),
      '  &lt;/rts:' || $element || '&gt;')"/>
  </xsl:function>
</xsl:stylesheet>
