// An RT-Component for the openrtm_toolchain tests: one OutPort<RTC::TimedString> "out" that
// writes each line its manager's standard input receives (without the line break), one sample
// per line, and prints "events: wrote <line>" on stdout, flushed. A test connects "out" to a job
// coordinator's InPort "event" (its rtc.conf's preconnect) and types the events into rtcd2.
// Loaded by rtcd2 (EventSourceInit).
#include <rtm/idl/BasicDataTypeSkel.h>  // first: the port templates need its CORBA::Any operators declared
#include <rtm/DataFlowComponentBase.h>
#include <rtm/Manager.h>
#include <rtm/OutPort.h>
#include <sys/select.h>
#include <unistd.h>
#include <cstdio>
#include <string>

namespace {
const char* const events_spec[] = {
  "implementation_id", "EventSource", "type_name", "EventSource", "description", "robomda test event source",
  "version", "1.0.0", "vendor", "robomda", "category", "test", "activity_type", "PERIODIC",
  "kind", "DataFlowComponent", "max_instance", "1", "language", "C++", "lang_type", "compile", ""};
}

class EventSource : public RTC::DataFlowComponentBase
{
public:
  explicit EventSource(RTC::Manager* manager) : RTC::DataFlowComponentBase(manager), m_outOut("out", m_out) {}
  RTC::ReturnCode_t onInitialize() override
  {
    addOutPort("out", m_outOut);
    return RTC::RTC_OK;
  }
  RTC::ReturnCode_t onExecute(RTC::UniqueId) override
  {
    fd_set ready;
    FD_ZERO(&ready);
    FD_SET(0, &ready);
    timeval none{0, 0};
    if (::select(1, &ready, nullptr, nullptr, &none) > 0) {
      char chunk[256];
      const ssize_t got = ::read(0, chunk, sizeof chunk);
      if (got > 0) {
        m_pending.append(chunk, static_cast<std::string::size_type>(got));
      }
    }
    std::string::size_type end;
    while ((end = m_pending.find('\n')) != std::string::npos) {
      const std::string line = m_pending.substr(0, end);
      m_pending.erase(0, end + 1);
      m_out.data = line.c_str();
      setTimestamp(m_out);
      m_outOut.write();
      std::printf("events: wrote %s\n", line.c_str());
      std::fflush(stdout);
    }
    return RTC::RTC_OK;
  }

private:
  RTC::TimedString m_out;
  RTC::OutPort<RTC::TimedString> m_outOut;
  std::string m_pending;
};

extern "C" void EventSourceInit(RTC::Manager* manager)
{
  coil::Properties profile(events_spec);
  manager->registerFactory(profile, RTC::Create<EventSource>, RTC::Delete<EventSource>);
}
