#pragma once
// ParaView output: one HDF5 file per frame (frames/frame_NNNNNN.h5, NNNNNN = step) and one XDMF 3
// file (picdem.xdmf) with one temporal collection per grid, so that a grid keeps its name over
// time: "cells" (3DCoRectMesh one cell thick, Z in [-h, 0], with cell arrays), "solids" and
// "obstacles" (Mixed polylines with an integer cell array body_id) and "particles" (Polyvertex
// with an explicit connectivity, point arrays). Every frame file carries the attributes time,
// step, code_version and ranks; every dataset its units. Written collectively: each rank writes
// its hyperslab of every dataset. doc/output.md describes the files.
//
// Next to picdem.xdmf, one index per grid (cells.xdmf, solids.xdmf, obstacles.xdmf,
// particles.xdmf: the same entries, one temporal collection each): ParaView's default XDMF
// reader (Xdmf3ReaderS) flattens the grids of a file into unnamed pieces, so a grid opened from
// its own index is what carries its name there (the pipeline source). And per frame
// frames/frame_NNNNNN_particles.xdmf: that frame's particles as the single grid without Time that
// meshio.read takes.
//
// Coordinates: the paper's (x, z) plane is written as ParaView's (X, Y) with Z = 0.
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "picdem/core/vec2.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/grid/grid.hpp"

namespace picdem::io {

/// Units by array name ("Pa", "m/s", "1" for a pure number, "code" for an enumeration); stored as
/// the attribute "units" of each dataset. Names without an entry get no attribute.
using Units = std::map<std::string, std::string>;

/// This rank's points (particles). Every array has one value (vectors: one (x, z) pair) per
/// point; every rank passes the same array names, unique over the three kinds.
struct PointSet {
  std::vector<double> x, z;
  std::map<std::string, std::vector<double>> scalars;         ///< float64 (N)
  std::map<std::string, std::vector<std::int64_t>> integers;  ///< int64 (N), e.g. id
  /// In-plane vectors, components along x and z; written as (N, 3) rows (x, z, 0).
  std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> vectors;
  Units units;
};

/// The cell arrays of a frame over the owned cells of each rank; every rank passes the same names.
struct CellArrays {
  std::map<std::string, const grid::CellField*> reals;               ///< float64 (1, nz, nx)
  std::map<std::string, const grid::GridArray<signed char>*> codes;  ///< int32 (1, nz, nx)
  Units units;
};

/// Outlines (solids, obstacles), split over ranks: each rank passes a disjoint share (solids:
/// those it owns; data known on every rank, like fixed obstacles: rank 0 only). The output holds
/// the concatenation in rank order. body_id has one value per line.
struct Polylines {
  std::vector<std::vector<core::Vec2>> lines;
  std::vector<std::int64_t> body_id;
};

class FrameWriter {
 public:
  /// Collective. Creates `directory` and `directory/frames`. continue_existing = true keeps the
  /// frames already indexed in an existing picdem.xdmf (a restart) up to step `keep_up_to_step`
  /// (the restart step: later frames belong to the abandoned run); frames at or after the step of
  /// the next write() are dropped from the index then. `code_version` goes into every frame file.
  /// `decomposition` must outlive the writer; each frame is written on its blocks of the moment.
  FrameWriter(const std::string& directory, const grid::Decomposition& decomposition,
              bool continue_existing = false,
              long long keep_up_to_step = std::numeric_limits<long long>::max(),
              std::string code_version = "");

  /// Collective. Writes frames/frame_<step>.h5 (and frames/frame_<step>_particles.xdmf when there
  /// are particles) and rewrites picdem.xdmf and the per-grid indexes. A grid without any element
  /// on any rank is left out of this frame's index.
  void write(double t, long long step, const CellArrays& cells, const PointSet& particles,
             const Polylines& solids, const Polylines& obstacles);

  std::string xdmf_path() const { return directory_ + "/picdem.xdmf"; }
  std::string frame_path(long long step) const;
  /// Number of frames (distinct steps) indexed in picdem.xdmf; meaningful on rank 0.
  std::size_t frames() const;

 private:
  struct Entry {
    std::string grid;  // the temporal collection it belongs to
    long long step;
    std::string xml;  // the grid's <Grid> element at this step
  };
  void read_existing_index(long long keep_up_to_step);
  void update_index(long long step, std::vector<Entry> grids);
  void write_xdmf(const std::string& path, const std::vector<std::string>& grids) const;

  std::string directory_;
  const grid::Decomposition& decomposition_;  // the run's: its cut lines may change (rebalance)
  std::string code_version_;
  std::vector<Entry> entries_;  // meaningful on rank 0
};

}  // namespace picdem::io
