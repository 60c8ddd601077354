// Where each rank waits: the seconds every rank spends inside MPI calls, split by the picdem phase
// (core::ScopedTimer, "picdem: NAME" Teuchos timers) that is running, next to each phase's own
// seconds on that rank. Loaded with LD_PRELOAD; it interposes Teuchos::Time::start / stop (in
// libtrilinos_teuchoscore.so) to follow the running phases and PMPI to time the MPI calls.
// At MPI_Finalize every rank appends to $MPI_WAIT_FILE (default mpi_wait.txt) one line per phase:
//   rank level phase seconds_in_phase seconds_in_mpi mpi_calls cpu_in_phase cpu_in_mpi
// (wall seconds, then this thread's CPU seconds: a loaded machine inflates the wall seconds of the
// compute between the MPI calls, hardly its CPU seconds).
// level "top": the phase directly inside "picdem: step" (or outside any step: setup, rebalance);
// level "inner": the innermost picdem timer running (its seconds exclusive of the picdem timers
// inside it; "top" seconds include them). Time in MPI outside every picdem timer is
// counted under "(none)". A phase's compute on a rank is its seconds less its MPI seconds.
// Build: mpicxx -O2 -DOMPI_SKIP_MPICXX -shared -fPIC -I/usr/include/trilinos -o mpi_wait.so
// mpi_wait.cpp -ldl Use:   mpirun -x LD_PRELOAD=$PWD/mpi_wait.so -x MPI_WAIT_FILE=out.txt -n 2
// picdem ... (drivers/bench/ranks/wait_split.sh runs it and prints the split.)
#include <dlfcn.h>
#include <mpi.h>
#include <Teuchos_Time.hpp>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <string>
#include <vector>

namespace {

struct Account {
  double seconds = 0, mpi = 0, cpu = 0, mpi_cpu = 0;  // wall and this thread's CPU seconds
  long long calls = 0;
};
struct Running {
  const Teuchos::Time* timer;
  std::string name;  // without "picdem: "; empty for a timer that is not picdem's
  double start, start_cpu;
};

std::vector<Running>& stack() {
  static std::vector<Running> s;
  return s;
}
std::map<std::string, Account>& top() {
  static std::map<std::string, Account> m;
  return m;
}
std::map<std::string, Account>& inner() {
  static std::map<std::string, Account> m;
  return m;
}

double cpu_now() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

double now() {
  int up = 0;
  MPI_Initialized(&up);
  return up ? PMPI_Wtime() : 0.0;
}

// The running top-level phase and innermost picdem timer ("(none)" outside them).
void running(std::string& t, std::string& i) {
  t = i = "(none)";
  bool first = true, in_step = false;
  for (const auto& r : stack()) {
    if (r.name.empty()) continue;
    if (first && r.name == "step") in_step = true;
    if (first && !in_step) t = r.name;
    if (!first && t == "(none)") t = r.name;
    first = false;
    i = r.name;
  }
  if (in_step && t == "(none)") t = "step, outside its phases";
}

void charge_mpi(double dt, double dcpu) {
  std::string t, i;
  running(t, i);
  for (Account* a : {&top()[t], &inner()[i]}) a->mpi += dt, a->mpi_cpu += dcpu, a->calls++;
}

template <class F>
int timed(F&& call) {
  const double t0 = PMPI_Wtime(), c0 = cpu_now();
  const int rc = call();
  charge_mpi(PMPI_Wtime() - t0, cpu_now() - c0);
  return rc;
}

}  // namespace

namespace Teuchos {

void Time::start(bool reset) {
  using Fn = void (*)(Time*, bool);
  static Fn real = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "_ZN7Teuchos4Time5startEb"));
  const std::string& n = name();
  const std::string prefix = "picdem: ";
  stack().push_back({this, n.compare(0, prefix.size(), prefix) == 0 ? n.substr(prefix.size()) : "",
                     now(), cpu_now()});
  real(this, reset);
}

double Time::stop() {
  using Fn = double (*)(Time*);
  static Fn real = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "_ZN7Teuchos4Time4stopEv"));
  auto& s = stack();
  for (auto it = s.rbegin(); it != s.rend(); ++it) {
    if (it->timer != this) continue;
    if (!it->name.empty()) {
      std::string t, i;
      running(t, i);  // with this timer still on the stack
      const double dt = now() - it->start, dcpu = cpu_now() - it->start_cpu;
      // inner: exclusive of the picdem timers running inside (taken off their parent)
      if (i == it->name) inner()[i].seconds += dt, inner()[i].cpu += dcpu;
      for (auto p = std::next(it); p != s.rend(); ++p)
        if (!p->name.empty()) {
          inner()[p->name].seconds -= dt, inner()[p->name].cpu -= dcpu;
          break;
        }
      if (t == it->name) top()[t].seconds += dt, top()[t].cpu += dcpu;
      if (it->name == "step")
        top()["step (whole)"].seconds += dt, top()["step (whole)"].cpu += dcpu;
    }
    s.erase(std::next(it).base());
    break;
  }
  return real(this);
}

}  // namespace Teuchos

extern "C" {

#define TIMED(ret_sig, params, args)               \
  int ret_sig params {                             \
    return timed([&] { return P##ret_sig args; }); \
  }

TIMED(MPI_Send, (const void* b, int c, MPI_Datatype d, int p, int t, MPI_Comm m),
      (b, c, d, p, t, m))
TIMED(MPI_Recv, (void* b, int c, MPI_Datatype d, int p, int t, MPI_Comm m, MPI_Status* s),
      (b, c, d, p, t, m, s))
TIMED(MPI_Isend, (const void* b, int c, MPI_Datatype d, int p, int t, MPI_Comm m, MPI_Request* r),
      (b, c, d, p, t, m, r))
TIMED(MPI_Irecv, (void* b, int c, MPI_Datatype d, int p, int t, MPI_Comm m, MPI_Request* r),
      (b, c, d, p, t, m, r))
TIMED(MPI_Sendrecv,
      (const void* sb, int sc, MPI_Datatype sd, int dst, int st, void* rb, int rc, MPI_Datatype rd,
       int src, int rt, MPI_Comm m, MPI_Status* s),
      (sb, sc, sd, dst, st, rb, rc, rd, src, rt, m, s))
TIMED(MPI_Wait, (MPI_Request * r, MPI_Status* s), (r, s))
TIMED(MPI_Waitall, (int n, MPI_Request* r, MPI_Status* s), (n, r, s))
TIMED(MPI_Waitany, (int n, MPI_Request* r, int* i, MPI_Status* s), (n, r, i, s))
TIMED(MPI_Waitsome, (int n, MPI_Request* r, int* o, int* i, MPI_Status* s), (n, r, o, i, s))
TIMED(MPI_Probe, (int p, int t, MPI_Comm m, MPI_Status* s), (p, t, m, s))
TIMED(MPI_Iprobe, (int p, int t, MPI_Comm m, int* f, MPI_Status* s), (p, t, m, f, s))
TIMED(MPI_Barrier, (MPI_Comm m), (m))
TIMED(MPI_Allreduce, (const void* s, void* r, int c, MPI_Datatype d, MPI_Op o, MPI_Comm m),
      (s, r, c, d, o, m))
TIMED(MPI_Reduce, (const void* s, void* r, int c, MPI_Datatype d, MPI_Op o, int root, MPI_Comm m),
      (s, r, c, d, o, root, m))
TIMED(MPI_Bcast, (void* b, int c, MPI_Datatype d, int root, MPI_Comm m), (b, c, d, root, m))
TIMED(MPI_Scan, (const void* s, void* r, int c, MPI_Datatype d, MPI_Op o, MPI_Comm m),
      (s, r, c, d, o, m))
TIMED(MPI_Exscan, (const void* s, void* r, int c, MPI_Datatype d, MPI_Op o, MPI_Comm m),
      (s, r, c, d, o, m))
TIMED(MPI_Allgather,
      (const void* s, int sc, MPI_Datatype sd, void* r, int rc, MPI_Datatype rd, MPI_Comm m),
      (s, sc, sd, r, rc, rd, m))
TIMED(MPI_Allgatherv,
      (const void* s, int sc, MPI_Datatype sd, void* r, const int* rc, const int* dp,
       MPI_Datatype rd, MPI_Comm m),
      (s, sc, sd, r, rc, dp, rd, m))
TIMED(MPI_Gather,
      (const void* s, int sc, MPI_Datatype sd, void* r, int rc, MPI_Datatype rd, int root,
       MPI_Comm m),
      (s, sc, sd, r, rc, rd, root, m))
TIMED(MPI_Gatherv,
      (const void* s, int sc, MPI_Datatype sd, void* r, const int* rc, const int* dp,
       MPI_Datatype rd, int root, MPI_Comm m),
      (s, sc, sd, r, rc, dp, rd, root, m))
TIMED(MPI_Scatter,
      (const void* s, int sc, MPI_Datatype sd, void* r, int rc, MPI_Datatype rd, int root,
       MPI_Comm m),
      (s, sc, sd, r, rc, rd, root, m))
TIMED(MPI_Scatterv,
      (const void* s, const int* sc, const int* dp, MPI_Datatype sd, void* r, int rc,
       MPI_Datatype rd, int root, MPI_Comm m),
      (s, sc, dp, sd, r, rc, rd, root, m))
TIMED(MPI_Alltoall,
      (const void* s, int sc, MPI_Datatype sd, void* r, int rc, MPI_Datatype rd, MPI_Comm m),
      (s, sc, sd, r, rc, rd, m))
TIMED(MPI_Alltoallv,
      (const void* s, const int* sc, const int* sdp, MPI_Datatype sd, void* r, const int* rc,
       const int* rdp, MPI_Datatype rd, MPI_Comm m),
      (s, sc, sdp, sd, r, rc, rdp, rd, m))
TIMED(MPI_Iallreduce,
      (const void* s, void* r, int c, MPI_Datatype d, MPI_Op o, MPI_Comm m, MPI_Request* q),
      (s, r, c, d, o, m, q))
TIMED(MPI_Test, (MPI_Request * r, int* f, MPI_Status* s), (r, f, s))
TIMED(MPI_Testall, (int n, MPI_Request* r, int* f, MPI_Status* s), (n, r, f, s))

int MPI_Finalize(void) {
  int rank = 0;
  PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const char* path = std::getenv("MPI_WAIT_FILE");
  if (FILE* f = std::fopen(path ? path : "mpi_wait.txt", "a")) {
    for (const char* level : {"top", "inner"})
      for (const auto& [n, a] : (level[0] == 't' ? top() : inner()))
        std::fprintf(f, "%d %s \"%s\" %.6f %.6f %lld %.6f %.6f\n", rank, level, n.c_str(),
                     a.seconds, a.mpi, a.calls, a.cpu, a.mpi_cpu);
    std::fclose(f);
  }
  return PMPI_Finalize();
}

}  // extern "C"
