#include "picdem/dem/checkpoint.hpp"

#include <string>
#include <type_traits>
#include <utility>

#include "picdem/io/checkpoint_grid.hpp"

namespace picdem::dem {

void write_checkpoint(const DemSolver* dem, io::CheckpointWriter& out, const core::Comm& comm) {
  DemSolver::Snapshot snap;
  if (dem) snap = dem->snapshot();
  const bool root = comm.is_root();
  std::as_const(snap).for_each([&](const char* name, const auto& v) {
    out.write(std::string("dem/") + name, root ? v : std::decay_t<decltype(v)>{});
  });
}

namespace {

DemSolver::Snapshot read_snapshot(const io::CheckpointReader& in) {
  DemSolver::Snapshot snap;
  snap.for_each([&](const char* name, auto& v) {
    using T = typename std::decay_t<decltype(v)>::value_type;
    const std::string key = std::string("dem/") + name;
    v = io::read_range<T>(in, key, 0, in.length(key));
  });
  const std::string where = "checkpoint file '" + in.path() + "'";
  const std::size_t n = snap.id.size();
  for (const auto* v : {&snap.x, &snap.z, &snap.theta, &snap.u, &snap.w, &snap.omega})
    if (v->size() != n)
      throw core::InputError(where + ": the solid arrays differ in length (corrupted)");
  if (snap.spring_partner.size() != snap.spring_solid.size() ||
      snap.spring.size() != snap.spring_solid.size())
    throw core::InputError(where + ": the contact spring arrays differ in length (corrupted)");
  return snap;
}

}  // namespace

void read_checkpoint(DemSolver& dem, const io::CheckpointReader& in, const core::Comm& comm) {
  DemSolver::Snapshot snap;
  io::on_all_ranks(comm, [&] { snap = read_snapshot(in); });
  try {
    dem.restore(snap);
  } catch (const std::exception& e) {
    throw core::InputError("checkpoint file '" + in.path() +
                           "': its solids do not match the case: " + e.what());
  }
}

}  // namespace picdem::dem
