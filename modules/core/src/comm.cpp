#include "picdem/core/comm.hpp"

#include "picdem/core/error.hpp"

namespace picdem::core {

int Comm::rank() const {
  int r = 0;
  MPI_Comm_rank(comm_, &r);
  return r;
}
int Comm::size() const {
  int s = 1;
  MPI_Comm_size(comm_, &s);
  return s;
}
void Comm::barrier() const {
  MPI_Barrier(comm_);
}

namespace {
template <class T>
T reduce(MPI_Comm c, T v, MPI_Datatype t, MPI_Op op) {
  T out{};
  MPI_Allreduce(&v, &out, 1, t, op, c);
  return out;
}
}  // namespace

double Comm::sum(double v) const {
  return reduce(comm_, v, MPI_DOUBLE, MPI_SUM);
}
long long Comm::sum(long long v) const {
  return reduce(comm_, v, MPI_LONG_LONG, MPI_SUM);
}
double Comm::max(double v) const {
  return reduce(comm_, v, MPI_DOUBLE, MPI_MAX);
}
double Comm::min(double v) const {
  return reduce(comm_, v, MPI_DOUBLE, MPI_MIN);
}
long long Comm::max(long long v) const {
  return reduce(comm_, v, MPI_LONG_LONG, MPI_MAX);
}
long long Comm::min(long long v) const {
  return reduce(comm_, v, MPI_LONG_LONG, MPI_MIN);
}
bool Comm::any(bool v) const {
  return reduce(comm_, v ? 1 : 0, MPI_INT, MPI_MAX) != 0;
}

long long Comm::exclusive_scan(long long v) const {
  long long out = 0;
  MPI_Exscan(&v, &out, 1, MPI_LONG_LONG, MPI_SUM, comm_);
  return rank() == 0 ? 0 : out;
}

void Comm::sum_in_place(std::vector<double>& v) const {
  MPI_Allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_DOUBLE, MPI_SUM, comm_);
}
void Comm::sum_in_place(std::vector<long long>& v) const {
  MPI_Allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_LONG_LONG, MPI_SUM, comm_);
}

std::string Comm::broadcast(const std::string& s, int root) const {
  long long n = static_cast<long long>(s.size());
  MPI_Bcast(&n, 1, MPI_LONG_LONG, root, comm_);
  std::string out = rank() == root ? s : std::string(static_cast<std::size_t>(n), '\0');
  if (n > 0) MPI_Bcast(out.data(), static_cast<int>(n), MPI_CHAR, root, comm_);
  return out;
}

std::vector<double> Comm::all_gather(const std::vector<double>& mine) const {
  const int p = size();
  int n = static_cast<int>(mine.size());
  std::vector<int> counts(p), displs(p, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_);
  for (int r = 1; r < p; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<double> out(static_cast<std::size_t>(displs[p - 1] + counts[p - 1]));
  MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, out.data(), counts.data(), displs.data(), MPI_DOUBLE,
                 comm_);
  return out;
}

void Comm::throw_if_any(const std::string& failure) const {
  if (!any(!failure.empty())) return;
  std::string first = failure;
  for (int r = 0; r < size(); ++r) {
    const std::string theirs = broadcast(failure, r);
    if (first.empty() && !theirs.empty()) first = theirs;
  }
  throw SolverError(first);
}

}  // namespace picdem::core
