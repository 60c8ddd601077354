#include "picdem/core/log.hpp"

#include <cstdio>
#include <iostream>
#include <sstream>

namespace picdem::core {

void log(const Comm& comm, const std::string& message) {
  if (comm.is_root()) std::cout << message << std::endl;
}
void log_error(const Comm& comm, const std::string& message) {
  if (comm.is_root()) std::cerr << message << std::endl;
}

double wall_seconds() {
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
}

std::string format_duration(double s) {
  if (!(s >= 0) || s > 1e8) return "--";
  const long long t = static_cast<long long>(s + 0.5);
  char buf[64];
  if (t >= 3600)
    std::snprintf(buf, sizeof buf, "%lldh%02lldm", t / 3600, (t / 60) % 60);
  else if (t >= 60)
    std::snprintf(buf, sizeof buf, "%lldm%02llds", t / 60, t % 60);
  else
    std::snprintf(buf, sizeof buf, "%llds", t);
  return buf;
}

Progress::Progress(Comm comm, double t_start, double t_end, double interval_seconds)
    : comm_(comm),
      t_start_(t_start),
      t_end_(t_end),
      interval_(interval_seconds),
      wall_start_(wall_seconds()) {}

void Progress::report(double t, long long step, double dt, int solver_iterations, bool force) {
  if (!comm_.is_root()) return;
  const double now = wall_seconds();
  if (!force && now - wall_last_ < interval_) return;
  if (force && step == last_step_) return;  // the closing call after this step's line
  wall_last_ = now;
  last_step_ = step;
  const double done = std::min(1.0, (t - t_start_) / (t_end_ - t_start_));
  const double elapsed = now - wall_start_;
  const double eta = done > 1e-9 ? elapsed * (1.0 - done) / done : -1.0;
  const int width = 20;
  const int filled = static_cast<int>(width * std::max(0.0, done) + 1e-9);
  char line[256];
  std::snprintf(
      line, sizeof line,
      "[%-*s] %5.1f%%  t = %.4f s  step %lld  dt = %.2e s  PPE its %d  elapsed %s  ETA %s", width,
      std::string(static_cast<std::size_t>(filled), '#').c_str(), 100.0 * done, t, step, dt,
      solver_iterations, format_duration(elapsed).c_str(), format_duration(eta).c_str());
  std::cout << line << std::endl;
}

}  // namespace picdem::core
