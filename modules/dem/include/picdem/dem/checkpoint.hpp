#pragma once
// The solids in a checkpoint (group dem/, doc/restart.md), through io's HDF5 layer.
#include "picdem/dem/dem_solver.hpp"
#include "picdem/io/checkpoint.hpp"

namespace picdem::dem {

/// Collective: the arrays of DemSolver::Snapshot::for_each as dem/<name>, from rank 0 (`dem`
/// nullptr, a case without solids: the same datasets, empty).
void write_checkpoint(const DemSolver* dem, io::CheckpointWriter& out, const core::Comm& comm);
/// Collective: replaces every solid's state and history by the checkpoint's (any rank count).
/// Throws core::InputError on every rank for a bad file or solids that do not match the case.
void read_checkpoint(DemSolver& dem, const io::CheckpointReader& in, const core::Comm& comm);

}  // namespace picdem::dem
