#include "picdem/particles/checkpoint.hpp"

#include <string>
#include <type_traits>
#include <utility>

#include "picdem/io/checkpoint_grid.hpp"
#include "picdem/particles/motion.hpp"

namespace picdem::particles {

void write_checkpoint(const ParticleSet& ps, io::CheckpointWriter& out) {
  ps.for_each_saved(
      [&](const char* name, const auto& v) { out.write(std::string("particles/") + name, v); });
}

void read_checkpoint(ParticleSet& ps, const io::CheckpointReader& in, const grid::Decomposition& d,
                     bool same_layout) {
  const core::Comm& comm = d.comm();
  io::on_all_ranks(comm, [&] {
    long long begin = 0, end = 0;
    if (!same_layout)
      io::even_split(in.length("particles/x"), comm.rank(), comm.size(), begin, end);
    ps.for_each_saved([&](const char* name, auto& v) {
      using T = typename std::decay_t<decltype(v)>::value_type;
      const std::string key = std::string("particles/") + name;
      v = same_layout ? io::read_slice<T>(in, key) : io::read_range<T>(in, key, begin, end);
    });
    bool equal_lengths = true;
    std::as_const(ps).for_each_saved([&](const char*, const auto& v) {
      equal_lengths = equal_lengths && v.size() == ps.size();
    });
    if (!equal_lengths)
      throw core::InputError("checkpoint file '" + in.path() +
                             "': the particle arrays differ in length (corrupted)");
    ps.spec = d.spec();
  });
  if (!same_layout) migrate(ps, d);
}

}  // namespace picdem::particles
