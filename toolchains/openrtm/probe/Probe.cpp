// An RT-Component for the openrtm_toolchain tests: one InPort<PROBE_TYPE> "in" (any
// type of OpenRTM's data-port convention, with a time stamp "tm"; CMakeLists.txt sets
// it, default RTC::TimedLong); every sample it reads is printed as
// "probe: <sec> <nsec>" (with PROBE_PRINT_DATA: "probe: <sec> <nsec> <data>"; with PROBE_PRINT_REAL,
// RTC::TimedDouble: the datum with 17 significant digits) on stdout,
// flushed, so a test can tell that data flows on a connection of a running system.
// Loaded by rtcd2 (ProbeInit), connected by its rtc.conf's preconnect.
#include PROBE_HEADER  // first: the port templates need its CORBA::Any operators declared
#include <rtm/DataFlowComponentBase.h>
#include <rtm/InPort.h>
#include <rtm/Manager.h>
#include <cstdio>

namespace {
const char* const probe_spec[] = {
  "implementation_id", "Probe", "type_name", "Probe", "description", "robomda test probe",
  "version", "1.0.0", "vendor", "robomda", "category", "test", "activity_type", "PERIODIC",
  "kind", "DataFlowComponent", "max_instance", "1", "language", "C++", "lang_type", "compile", ""};
}

class Probe : public RTC::DataFlowComponentBase
{
public:
  explicit Probe(RTC::Manager* manager) : RTC::DataFlowComponentBase(manager), m_inIn("in", m_in) {}
  RTC::ReturnCode_t onInitialize() override
  {
    addInPort("in", m_inIn);
    return RTC::RTC_OK;
  }
  RTC::ReturnCode_t onExecute(RTC::UniqueId) override
  {
    while (m_inIn.isNew()) {
      m_inIn.read();
#if defined(PROBE_PRINT_DATA)
      std::printf("probe: %lu %lu %ld\n", static_cast<unsigned long>(m_in.tm.sec), static_cast<unsigned long>(m_in.tm.nsec),
                  static_cast<long>(m_in.data));
#elif defined(PROBE_PRINT_REAL)
      std::printf("probe: %lu %lu %.17g\n", static_cast<unsigned long>(m_in.tm.sec), static_cast<unsigned long>(m_in.tm.nsec),
                  static_cast<double>(m_in.data));
#else
      std::printf("probe: %lu %lu\n", static_cast<unsigned long>(m_in.tm.sec), static_cast<unsigned long>(m_in.tm.nsec));
#endif
      std::fflush(stdout);
    }
    return RTC::RTC_OK;
  }

private:
  PROBE_TYPE m_in;
  RTC::InPort<PROBE_TYPE> m_inIn;
};

extern "C" void ProbeInit(RTC::Manager* manager)
{
  coil::Properties profile(probe_spec);
  manager->registerFactory(profile, RTC::Create<Probe>, RTC::Delete<Probe>);
}
