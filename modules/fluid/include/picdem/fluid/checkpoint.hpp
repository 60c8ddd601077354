#pragma once
// The fluid's grid state in a checkpoint (group grid/, doc/restart.md), through io's HDF5 layer.
#include "picdem/fluid/fluid_state.hpp"
#include "picdem/io/checkpoint_grid.hpp"

namespace picdem::fluid {

/// Collective: the fields of FluidState::for_each_saved as grid/<name> (every rank's storage
/// box) and the rank layout grid/boxes of `d`.
void write_checkpoint(const FluidState& fluid, const grid::Decomposition& d,
                      io::CheckpointWriter& out);
/// Collective: the fields of FluidState::for_each_saved from the checkpoint written on `layout`
/// (io::read_grid_layout). Throws core::InputError on every rank for a bad file.
void read_checkpoint(FluidState& fluid, const io::CheckpointReader& in,
                     const io::GridLayout& layout, const core::Comm& comm);

}  // namespace picdem::fluid
