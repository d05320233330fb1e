// An RT-Component for the openrtm_toolchain tests: one InPort<RTC::TimedDouble> "in"; every sample
// it reads is printed as "value: <sec> <nsec> <datum>" (the datum with 17 significant digits) on
// stdout, flushed, so a test can tell which values a component writes (the job coordinator's run
// test: the per-cycle step of the player's trajectory shows the duration its job set).
// Loaded by rtcd2 (ValueProbeInit), connected by its rtc.conf's preconnect.
#include <rtm/idl/BasicDataTypeSkel.h>  // first: the port templates need its CORBA::Any operators declared
#include <rtm/DataFlowComponentBase.h>
#include <rtm/InPort.h>
#include <rtm/Manager.h>
#include <cstdio>

namespace {
const char* const value_probe_spec[] = {
  "implementation_id", "ValueProbe", "type_name", "ValueProbe", "description", "robomda test probe of double values",
  "version", "1.0.0", "vendor", "robomda", "category", "test", "activity_type", "PERIODIC",
  "kind", "DataFlowComponent", "max_instance", "1", "language", "C++", "lang_type", "compile", ""};
}

class ValueProbe : public RTC::DataFlowComponentBase
{
public:
  explicit ValueProbe(RTC::Manager* manager) : RTC::DataFlowComponentBase(manager), m_inIn("in", m_in) {}
  RTC::ReturnCode_t onInitialize() override
  {
    addInPort("in", m_inIn);
    return RTC::RTC_OK;
  }
  RTC::ReturnCode_t onExecute(RTC::UniqueId) override
  {
    while (m_inIn.isNew()) {
      m_inIn.read();
      std::printf("value: %lu %lu %.17g\n", static_cast<unsigned long>(m_in.tm.sec), static_cast<unsigned long>(m_in.tm.nsec),
                  static_cast<double>(m_in.data));
      std::fflush(stdout);
    }
    return RTC::RTC_OK;
  }

private:
  RTC::TimedDouble m_in;
  RTC::InPort<RTC::TimedDouble> m_inIn;
};

extern "C" void ValueProbeInit(RTC::Manager* manager)
{
  coil::Properties profile(value_probe_spec);
  manager->registerFactory(profile, RTC::Create<ValueProbe>, RTC::Delete<ValueProbe>);
}
