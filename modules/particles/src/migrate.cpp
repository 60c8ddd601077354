#include <mpi.h>

#include <cstring>

#include "picdem/core/timer.hpp"
#include "picdem/particles/motion.hpp"

namespace picdem::particles {

namespace {
/// One particle on the wire.
struct Packed {
  double v[8];
  std::int64_t id;
};
}  // namespace

void migrate(ParticleSet& p, const grid::Decomposition& d) {
  core::ScopedTimer timer("particles: migrate");
  const int ranks = d.size(), me = d.rank();
  if (ranks > 1) {
    const MPI_Comm comm = d.comm().raw();
    std::vector<int> dest(p.size());
    std::vector<int> send_count(static_cast<std::size_t>(ranks), 0);
    std::vector<char> keep(p.size(), 1);
    for (std::size_t n = 0; n < p.size(); ++n) {
      dest[n] = d.owner_of_point({p.x[n], p.z[n]});
      if (dest[n] != me) ++send_count[static_cast<std::size_t>(dest[n])], keep[n] = 0;
    }
    std::vector<int> send_start(static_cast<std::size_t>(ranks) + 1, 0);
    for (int r = 0; r < ranks; ++r)
      send_start[static_cast<std::size_t>(r) + 1] =
          send_start[static_cast<std::size_t>(r)] + send_count[static_cast<std::size_t>(r)];
    std::vector<Packed> send(static_cast<std::size_t>(send_start.back()));
    std::vector<int> fill(send_start.begin(), send_start.end() - 1);
    for (std::size_t n = 0; n < p.size(); ++n) {
      if (keep[n]) continue;
      Packed& q = send[static_cast<std::size_t>(fill[static_cast<std::size_t>(dest[n])]++)];
      const double v[8] = {p.x[n], p.z[n], p.u[n], p.w[n], p.cxx[n], p.cxz[n], p.czx[n], p.czz[n]};
      std::memcpy(q.v, v, sizeof v);
      q.id = p.id[n];
    }
    std::vector<int> recv_count(static_cast<std::size_t>(ranks), 0);
    MPI_Alltoall(send_count.data(), 1, MPI_INT, recv_count.data(), 1, MPI_INT, comm);
    std::vector<int> recv_start(static_cast<std::size_t>(ranks) + 1, 0);
    for (int r = 0; r < ranks; ++r)
      recv_start[static_cast<std::size_t>(r) + 1] =
          recv_start[static_cast<std::size_t>(r)] + recv_count[static_cast<std::size_t>(r)];
    std::vector<Packed> recv(static_cast<std::size_t>(recv_start.back()));
    // counts and offsets in bytes
    const int b = static_cast<int>(sizeof(Packed));
    std::vector<int> sc(send_count), sd(send_start), rc(recv_count), rd(recv_start);
    for (auto* v : {&sc, &sd, &rc, &rd})
      for (int& c : *v) c *= b;
    MPI_Alltoallv(send.data(), sc.data(), sd.data(), MPI_BYTE, recv.data(), rc.data(), rd.data(),
                  MPI_BYTE, comm);
    p.keep_if(keep);
    p.reserve(p.size() + recv.size());
    for (const Packed& q : recv) {
      const double c[4] = {q.v[4], q.v[5], q.v[6], q.v[7]};
      p.push_back(q.id, {q.v[0], q.v[1]}, {q.v[2], q.v[3]}, c);
    }
  }
  sort_by_cell(p, d.spec());
}

}  // namespace picdem::particles
