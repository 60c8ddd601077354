#include "picdem/fluid/checkpoint.hpp"

#include <string>

namespace picdem::fluid {

void write_checkpoint(const FluidState& fluid, const grid::Decomposition& d,
                      io::CheckpointWriter& out) {
  fluid.for_each_saved([&](const char* name, const auto& f) {
    io::write_grid_array(out, std::string("grid/") + name, f);
  });
  io::write_grid_boxes(out, &d);
}

void read_checkpoint(FluidState& fluid, const io::CheckpointReader& in,
                     const io::GridLayout& layout, const core::Comm& comm) {
  io::on_all_ranks(comm, [&] {
    fluid.for_each_saved([&](const char* name, auto& f) {
      io::read_grid_array(in, std::string("grid/") + name, layout, f);
    });
  });
}

}  // namespace picdem::fluid
