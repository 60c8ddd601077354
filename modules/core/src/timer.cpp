#include "picdem/core/timer.hpp"

#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <cstdlib>
#include <ostream>

namespace picdem::core {

namespace {
// The timers made here, by name (Teuchos keeps its own list but does not expose it).
std::map<std::string, Teuchos::RCP<Teuchos::Time>>& registry() {
  static std::map<std::string, Teuchos::RCP<Teuchos::Time>> timers;
  return timers;
}
Teuchos::Time& timer(const std::string& name) {
  auto& t = registry()[name];
  if (t.is_null()) t = Teuchos::TimeMonitor::getNewCounter("picdem: " + name);
  return *t;
}
}  // namespace

struct ScopedTimer::Impl {
  explicit Impl(const std::string& name) : monitor(timer(name)) {}
  Teuchos::TimeMonitor monitor;
};

ScopedTimer::ScopedTimer(const std::string& name) : impl_(std::make_unique<Impl>(name)) {}
ScopedTimer::~ScopedTimer() = default;

std::map<std::string, double> timer_totals() {
  std::map<std::string, double> out;
  for (const auto& [name, t] : registry()) out[name] = t->totalElapsedTime();
  return out;
}

void reset_timers() {
  Teuchos::TimeMonitor::zeroOutTimers();
}

void summarize_timers(const Comm& comm, std::ostream& out) {
  auto tcomm = Teuchos::rcp(new Teuchos::MpiComm<int>(comm.raw()));
  // PICDEM_ALL_TIMERS set: Trilinos' own timers too (doc/output.md)
  const char* filter = std::getenv("PICDEM_ALL_TIMERS") ? "" : "picdem: ";
  Teuchos::TimeMonitor::summarize(tcomm.ptr(), out, false, true, false, Teuchos::Union, filter);
}

}  // namespace picdem::core
