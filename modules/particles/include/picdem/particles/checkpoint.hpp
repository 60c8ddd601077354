#pragma once
// The particles in a checkpoint (group particles/, doc/restart.md), through io's HDF5 layer.
#include "picdem/grid/grid.hpp"
#include "picdem/io/checkpoint.hpp"
#include "picdem/particles/particle_set.hpp"

namespace picdem::particles {

/// Collective: the arrays of ParticleSet::for_each_saved as particles/<name>, every rank's
/// particles in their order.
void write_checkpoint(const ParticleSet& ps, io::CheckpointWriter& out);
/// Collective: replaces `ps` by the checkpoint's particles on `d`. `same_layout` (the file was
/// written on this decomposition): each rank's own slice, in its order (bitwise); otherwise an
/// even share, then migrated to the ranks owning their cells. Throws core::InputError on every
/// rank for a bad file.
void read_checkpoint(ParticleSet& ps, const io::CheckpointReader& in, const grid::Decomposition& d,
                     bool same_layout);

}  // namespace picdem::particles
