#pragma once
// ParaView output: one HDF5 file per frame (frames/frame_NNNNNN.h5, NNNNNN = step) and one XDMF
// file (picdem.xdmf) indexing all frames as a temporal collection. Every frame is a spatial
// collection of up to four grids: "fluid" (3DCoRectMesh one cell thick, Z in [-h, 0], with cell
// fields), "particles" (Polyvertex with point scalars), "solids" and "obstacles" (Mixed polylines
// with a cell scalar body_id). Written collectively: each rank writes its hyperslab of every
// dataset.
//
// Coordinates: the paper's (x, z) plane is written as ParaView's (X, Y) with Z = 0.
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "picdem/core/vec2.hpp"
#include "picdem/grid/field.hpp"
#include "picdem/grid/grid.hpp"

namespace picdem::io {

/// This rank's points (particles). Every scalar has one value per point; every rank passes the
/// same scalar names.
struct PointSet {
  std::vector<double> x, z;
  std::map<std::string, std::vector<double>> scalars;
};

/// Outlines (solids, obstacles), split over ranks: each rank passes a disjoint share (solids:
/// those it owns; data known on every rank, like fixed obstacles: rank 0 only). The output holds
/// the concatenation in rank order. body_id has one value per line.
struct Polylines {
  std::vector<std::vector<core::Vec2>> lines;
  std::vector<double> body_id;
};

class FrameWriter {
 public:
  /// Collective. Creates `directory` and `directory/frames`. continue_existing = true keeps the
  /// frames already indexed in an existing picdem.xdmf (a restart) up to step `keep_up_to_step`
  /// (the restart step: later frames belong to the abandoned run); frames at or after the step of
  /// the next write() are dropped from the index then.
  FrameWriter(const std::string& directory, const grid::Decomposition& decomposition,
              bool continue_existing = false,
              long long keep_up_to_step = std::numeric_limits<long long>::max());

  /// Collective. cell_fields: every rank passes the same names; the owned cells are written.
  void write(double t, long long step,
             const std::map<std::string, const grid::CellField*>& cell_fields,
             const PointSet& particles, const Polylines& solids, const Polylines& obstacles);

  std::string xdmf_path() const { return directory_ + "/picdem.xdmf"; }
  std::string frame_path(long long step) const;
  /// Number of frames indexed in picdem.xdmf.
  std::size_t frames() const { return entries_.size(); }

 private:
  struct Entry {
    long long step;
    std::string xml;  // the frame's <Grid> element
  };
  void write_xdmf() const;

  std::string directory_;
  grid::Decomposition decomposition_;
  std::vector<Entry> entries_;  // meaningful on rank 0
};

/// The standard picture of a state, written by rank 0 from data gathered from all ranks:
/// particles as small discs coloured by scalars["speed"] (colormap from the global min to max,
/// whose values go into tEXt chunks speed_min / speed_max), solids filled light grey, obstacles
/// mid grey, outlines and tank walls dark grey, and a colour bar on the right. The picture is
/// width_pixels wide; the height follows the tank's aspect ratio. Collective.
void render_snapshot(const core::Comm& comm, const std::string& png_path, const core::Box2& tank,
                     const PointSet& particles, const Polylines& solids, const Polylines& obstacles,
                     int width_pixels);

}  // namespace picdem::io
