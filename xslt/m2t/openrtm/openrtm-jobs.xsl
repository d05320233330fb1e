<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/openrtm/openrtm-jobs.xsl - the job coordinator of each subsystem
  of the OpenRTM package (seed 004 §4.3, docs/jobs.md "On OpenRTM"; part of
  xslt/m2t/openrtm/main.xsl).

  Reads:   r:coordinator, r:process, r:instance of the OpenRTM PSM
           (xslt/m2m/openrtm/jobs.xsl).
  Writes:  strings:
           src/<Subsystem>Coordinator.cpp  an RT-Component (DataFlowComponentBase,
                 module <Subsystem>Coordinator.so, entry <Subsystem>CoordinatorInit),
                 instance named after the subsystem, periodic at 20 Hz (its
                 manager's rtc.conf: <package>.<subsystem>.exec_cxt.periodic.rate). Its
                 InPort "event" (RTC::TimedString) takes the events (a
                 transition's event name), its OutPort "job" (RTC::TimedString)
                 writes the job that runs, on its first cycle and after each
                 switch. It runs the tables of m2t/common/jobs.xsl (a value a
                 pair of parameter name and .conf text). A switch, over CORBA:
                   stop         deactivate on the instance's own execution
                                context (reverse start order)
                   reconfigure  the values set in its configuration set
                                "default" (SDO Configuration:
                                set_configuration_set_values, then
                                activate_configuration_set) while it stays
                                Active: OpenRTM updates the bound variables at
                                the end of its next cycle (on_state_update)
                   start        the values set likewise (taken on activation,
                                before onActivated), then activate (start order)
                   keep         nothing: never deactivated
                 An instance is found in the coordinator's manager
                 (RTC::Manager::getComponent), else through the naming service
                 (rtcname://*/<instance>), as preconnect finds a port of
                 another manager. An event with no switch from the current job
                 is a WARN and changes nothing; a failed step stops the switch
                 (ERROR naming the instance and the step), the job stays.
           the coordinator's CMake lines (fp:rtm-coordinator-cmake) and, for
           openrtm-deploy.xsl, which instances a manager activates at start
           (fp:rtm-activated: not the idle ones; its coordinators last).
  Params:  none (main.xsl's).
  Errors:  none.
  Uses:    ../common/jobs.xsl (fp:job-tables; this file's template of mode m:job-value),
           key fp:rtm-instance (openrtm-deploy.xsl), $fp:rtm-version and $fp:jobs-xsl (main.xsl).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-openrtm:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:m="urn:robomda:xslt:mode"
    exclude-result-prefixes="#all">

  <!-- a value of the tables: {"name", "text of the .conf"} -->
  <xsl:template match="r:value" mode="m:job-value" as="xs:string">
    <xsl:param name="version" as="xs:string"/>
    <xsl:sequence select="'{' || fp:cpp-string(@name) || ', ' || fp:cpp-string(@value) || '}'"/>
  </xsl:template>

  <!-- the coordinators a manager creates -->
  <xsl:function name="fp:rtm-coordinators-in" as="element(r:coordinator)*">
    <xsl:param name="p" as="element(r:process)"/>
    <xsl:sequence select="$p/../r:coordinator[@process eq $p/@file]"/>
  </xsl:function>

  <!-- the instances a manager activates at start, in start order: not those
       of a job other than the initial one (a switch activates them); then
       its coordinators -->
  <xsl:function name="fp:rtm-activated" as="xs:string*">
    <xsl:param name="p" as="element(r:process)"/>
    <xsl:sequence select="tokenize($p/@members)[not(key('fp:rtm-instance', ., root($p))/@idle = 'true')],
                          fp:rtm-coordinators-in($p)/@name ! string(.)"/>
  </xsl:function>

  <xsl:function name="fp:rtm-coordinator-cmake" as="xs:string+">
    <xsl:param name="c" as="element(r:coordinator)"/>
    <xsl:sequence select="(
      '# the job coordinator of subsystem ' || $c/@name || ' (docs/jobs.md): a module as the components''',
      'add_library(' || $c/@class || ' MODULE src/' || $c/@class || '.cpp)',
      'set_target_properties(' || $c/@class || ' PROPERTIES PREFIX &quot;&quot;)',
      'target_link_libraries(' || $c/@class || ' ${OPENRTM_LIBRARIES})',
      'install(TARGETS ' || $c/@class || ' LIBRARY DESTINATION lib/' || $c/../@package || ')')"/>
  </xsl:function>

  <xsl:function name="fp:rtm-coordinator" as="xs:string">
    <xsl:param name="c" as="element(r:coordinator)"/>
    <xsl:variable name="class" as="xs:string" select="$c/@class"/>
    <xsl:variable name="pkg" as="xs:string" select="$c/../@package"/>
    <xsl:variable name="spec" as="xs:string+" select="(
        'implementation_id', $class, 'type_name', $class, 'description', 'robomda job coordinator of subsystem ' || $c/@name,
        'version', $fp:rtm-version, 'vendor', 'robomda', 'category', $pkg, 'activity_type', 'PERIODIC',
        'kind', 'DataFlowComponent', 'max_instance', '1', 'language', 'C++', 'lang_type', 'compile')"/>
    <xsl:sequence select="fp:lines((
      fp:banner('// ', $fp:jobs-xsl, 'subsystem ''' || $c/@name || ''' of model ''' || $c/../@model-name || '''', false()),
      '//',
      '// The job coordinator of subsystem ' || $c/@name || ' (seed 004; docs/jobs.md &quot;On OpenRTM&quot;): RT-Component',
      '// ' || $class || ', instance ' || $c/@name || '. Job ' || $c/@initial-job || ' runs from the start (its managers activate its',
      '// members); each event written to InPort &quot;event&quot; (RTC::TimedString) switches jobs, over CORBA: the',
      '// instances that leave are deactivated, the ones that stay with other values get them in their',
      '// configuration set while Active, the ones that come get theirs and are activated. OutPort',
      '// &quot;job&quot; (RTC::TimedString) writes the job that runs.',
      '',
      '#include &lt;rtm/idl/BasicDataTypeSkel.h&gt;',
      '#include &lt;rtm/CORBA_RTCUtil.h&gt;',
      '#include &lt;rtm/DataFlowComponentBase.h&gt;',
      '#include &lt;rtm/InPort.h&gt;',
      '#include &lt;rtm/Manager.h&gt;',
      '#include &lt;rtm/NVUtil.h&gt;',
      '#include &lt;rtm/NamingManager.h&gt;',
      '#include &lt;rtm/OutPort.h&gt;',
      '',
      '#include &lt;algorithm&gt;',
      '#include &lt;chrono&gt;',
      '#include &lt;map&gt;',
      '#include &lt;string&gt;',
      '#include &lt;thread&gt;',
      '#include &lt;utility&gt;',
      '#include &lt;vector&gt;',
      '',
      fp:job-tables($c, 'std::pair&lt;std::string, std::string&gt;', 'openrtm'),
      '',
      'namespace ' || $pkg,
      '{',
      'namespace',
      '{',
      'const char* const spec[] = {',
      for $i in 1 to count($spec) idiv 2 return '  ' || fp:cpp-string($spec[2 * $i - 1]) || ', ' || fp:cpp-string($spec[2 * $i]) || ',',
      '  &quot;&quot;};',
      '',
      '// an RT-Component of this manager by its instance name, else through the naming service',
      'RTC::RTObject_var find_rtc(const std::string&amp; instance)',
      '{',
      '  RTC::Manager&amp; manager = RTC::Manager::instance();',
      '  RTC::RTObject_impl* local = manager.getComponent(instance.c_str());',
      '  if (local != nullptr) {',
      '    return RTC::RTObject_var(local-&gt;getObjRef());',
      '  }',
      '  RTC::RTCList found = manager.getNaming()-&gt;string_to_component(&quot;rtcname://*/&quot; + instance);',
      '  if (found.length() == 0) {',
      '    return RTC::RTObject_var(RTC::RTObject::_nil());',
      '  }',
      '  return RTC::RTObject_var(RTC::RTObject::_duplicate(found[0]));',
      '}',
      '}  // namespace',
      '',
      'class ' || $class || ' : public RTC::DataFlowComponentBase',
      '{',
      'public:',
      '  explicit ' || $class || '(RTC::Manager* manager)',
      '    : RTC::DataFlowComponentBase(manager), m_eventIn(&quot;event&quot;, m_event), m_jobOut(&quot;job&quot;, m_job), m_current(kInitialJob)',
      '  {',
      '  }',
      '',
      '  RTC::ReturnCode_t onInitialize() override',
      '  {',
      '    addInPort(&quot;event&quot;, m_eventIn);',
      '    addOutPort(&quot;job&quot;, m_jobOut);',
      '    return RTC::RTC_OK;',
      '  }',
      '',
      '  // the initial job''s members are activated by their managers (rtc.conf preactivation)',
      '  RTC::ReturnCode_t onActivated(RTC::UniqueId /*ec_id*/) override',
      '  {',
      '    std::string members;',
      '    for (const auto&amp; instance : kJobs.at(m_current)) {',
      '      members += (members.empty() ? &quot;&quot; : &quot;, &quot;) + instance;',
      '    }',
      '    RTC_INFO((&quot;job %s active: %s&quot;, m_current.c_str(), members.c_str()));',
      '    m_written = false;',
      '    return RTC::RTC_OK;',
      '  }',
      '',
      '  RTC::ReturnCode_t onExecute(RTC::UniqueId /*ec_id*/) override',
      '  {',
      '    if (!m_written) {',
      '      write_job();',
      '    }',
      '    while (m_eventIn.isNew()) {',
      '      m_eventIn.read();',
      '      on_event(std::string(m_event.data));',
      '    }',
      '    return RTC::RTC_OK;',
      '  }',
      '',
      'private:',
      '  void write_job()',
      '  {',
      '    m_job.data = m_current.c_str();',
      '    setTimestamp(m_job);',
      '    m_jobOut.write();',
      '    m_written = true;',
      '  }',
      '',
      '  void on_event(const std::string&amp; event)',
      '  {',
      '    const auto s = std::find_if(kSwitches.begin(), kSwitches.end(),',
      '                                [&amp;](const Switch&amp; candidate) { return candidate.from == m_current &amp;&amp; candidate.event == event; });',
      '    if (s == kSwitches.end()) {',
      '      RTC_WARN((&quot;event %s: no switch from job %s: ignored&quot;, event.c_str(), m_current.c_str()));',
      '      return;',
      '    }',
      '    RTC_INFO((&quot;event %s: job %s -&gt; %s&quot;, event.c_str(), m_current.c_str(), s-&gt;to.c_str()));',
      '    for (const auto&amp; instance : s-&gt;stop) {',
      '      if (!change(instance, false)) {',
      '        return;',
      '      }',
      '    }',
      '    for (const auto&amp; member : s-&gt;reconfigure) {',
      '      if (!configure(member)) {',
      '        return;',
      '      }',
      '    }',
      '    for (const auto&amp; member : s-&gt;start) {',
      '      if (!configure(member) || !change(member.instance, true)) {',
      '        return;',
      '      }',
      '    }',
      '    m_current = s-&gt;to;',
      '    RTC_INFO((&quot;job %s active (event %s)&quot;, m_current.c_str(), event.c_str()));',
      '    write_job();',
      '  }',
      '',
      '  // activates / deactivates an instance on its own execution context; a synchronous',
      '  // transition that outlasts the context''s timeout (0.5 s) returns an error but goes on:',
      '  // the state decides, waited for up to 10 s',
      '  bool change(const std::string&amp; instance, bool activate)',
      '  {',
      '    const char* const step = activate ? &quot;activate&quot; : &quot;deactivate&quot;;',
      '    try {',
      '      RTC::RTObject_var rtc = find_rtc(instance);',
      '      if (CORBA::is_nil(rtc.in())) {',
      '        RTC_ERROR((&quot;%s %s: no such RT-Component in this manager or the naming service&quot;, step, instance.c_str()));',
      '        return false;',
      '      }',
      '      const RTC::ReturnCode_t ret = activate ? CORBA_RTCUtil::activate(rtc.in(), 0) : CORBA_RTCUtil::deactivate(rtc.in(), 0);',
      '      for (int i = 0; i &lt; 100; ++i) {',
      '        if (activate ? CORBA_RTCUtil::is_in_active(rtc.in(), 0) : CORBA_RTCUtil::is_in_inactive(rtc.in(), 0)) {',
      '          RTC_INFO((&quot;%s %s: %s&quot;, step, instance.c_str(), activate ? &quot;Active&quot; : &quot;Inactive&quot;));',
      '          return true;',
      '        }',
      '        std::this_thread::sleep_for(std::chrono::milliseconds(100));',
      '      }',
      '      RTC_ERROR((&quot;%s %s failed (return code %d)&quot;, step, instance.c_str(), static_cast&lt;int&gt;(ret)));',
      '    } catch (const CORBA::Exception&amp; e) {',
      '      RTC_ERROR((&quot;%s %s: %s&quot;, step, instance.c_str(), e._name()));',
      '    }',
      '    return false;',
      '  }',
      '',
      '  // sets values in the instance''s configuration set &quot;default&quot; and activates the set: an',
      '  // Active RT-Component takes them at the end of its next cycle, an Inactive one on activation',
      '  bool configure(const Member&amp; member)',
      '  {',
      '    if (member.values.empty()) {',
      '      return true;',
      '    }',
      '    try {',
      '      RTC::RTObject_var rtc = find_rtc(member.instance);',
      '      if (CORBA::is_nil(rtc.in())) {',
      '        RTC_ERROR((&quot;configure %s: no such RT-Component in this manager or the naming service&quot;, member.instance.c_str()));',
      '        return false;',
      '      }',
      '      SDOPackage::Configuration_var configuration = rtc-&gt;get_configuration();',
      '      SDOPackage::ConfigurationSet_var set = configuration-&gt;get_configuration_set(&quot;default&quot;);',
      '      coil::Properties values;',
      '      NVUtil::copyToProperties(values, set-&gt;configuration_data);',
      '      for (const auto&amp; value : member.values) {',
      '        values[value.first] = value.second;',
      '      }',
      '      NVUtil::copyFromProperties(set-&gt;configuration_data, values);',
      '      if (!configuration-&gt;set_configuration_set_values(set.in()) || !configuration-&gt;activate_configuration_set(&quot;default&quot;)) {',
      '        RTC_ERROR((&quot;configure %s: its configuration set default refused the values&quot;, member.instance.c_str()));',
      '        return false;',
      '      }',
      '      for (const auto&amp; value : member.values) {',
      '        RTC_INFO((&quot;configure %s: %s = %s&quot;, member.instance.c_str(), value.first.c_str(),',
      '                  CORBA_RTCUtil::get_parameter_by_key(rtc.in(), &quot;default&quot;, value.first).c_str()));',
      '      }',
      '      return true;',
      '    } catch (const CORBA::Exception&amp; e) {',
      '      RTC_ERROR((&quot;configure %s: %s&quot;, member.instance.c_str(), e._name()));',
      '    }',
      '    return false;',
      '  }',
      '',
      '  RTC::TimedString m_event;',
      '  RTC::InPort&lt;RTC::TimedString&gt; m_eventIn;',
      '  RTC::TimedString m_job;',
      '  RTC::OutPort&lt;RTC::TimedString&gt; m_jobOut;',
      '  std::string m_current;',
      '  bool m_written = false;',
      '};',
      '}  // namespace ' || $pkg,
      '',
      'extern &quot;C&quot;',
      '{',
      '  void ' || $class || 'Init(RTC::Manager* manager)',
      '  {',
      '    coil::Properties profile(' || $pkg || '::spec);',
      '    manager-&gt;registerFactory(profile, RTC::Create&lt;' || $pkg || '::' || $class || '&gt;, RTC::Delete&lt;' || $pkg || '::' || $class || '&gt;);',
      '  }',
      '}'))"/>
  </xsl:function>
</xsl:stylesheet>
