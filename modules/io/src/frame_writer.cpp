#include "picdem/io/frame_writer.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "h5.hpp"
#include "picdem/core/error.hpp"
#include "picdem/core/timer.hpp"

namespace picdem::io {
namespace {

// The temporal collections in the order of the index. The particles come last: meshio's XDMF
// time-series reader reads the last temporal collection of a file.
const std::vector<std::string> kGrids = {"cells", "solids", "obstacles", "particles"};
const std::string kCollectionOpen = "    <Grid Name=\"";
const std::string kGridOpen = "      <Grid Name=\"";
const std::string kGridClose = "      </Grid>";
const std::string kStepInfo = "        <Information Name=\"step\" Value=\"";

std::string real(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// Rank 0's names joined; every rank compares its own: any difference is an error on all ranks.
void check_same_names(const core::Comm& comm, const std::vector<std::string>& names,
                      const std::string& what) {
  std::string joined;
  for (const auto& n : names) {
    if (n.empty() || n.find_first_of("/<>&\" ") != std::string::npos || n == "xyz" ||
        n == "connectivity")
      throw core::InputError("FrameWriter: " + what + " name '" + n +
                             "' must be non-empty, without / < > & \" or space, and not xyz or "
                             "connectivity");
    joined += n + '\n';
  }
  if (std::set<std::string>(names.begin(), names.end()).size() != names.size())
    throw core::InputError("FrameWriter: a " + what + " name is used twice");
  const bool differs = comm.broadcast(joined) != joined;
  if (comm.any(differs))
    throw core::InputError("FrameWriter: every rank must pass the same " + what + " names");
}

template <class Map>
void add_names(const Map& m, std::vector<std::string>& names) {
  for (const auto& kv : m) names.push_back(kv.first);
}

// Throws InputError (on every rank) unless every array has one value per point / cell.
void check_input(const core::Comm& comm, const CellArrays& cells, const PointSet& particles) {
  std::vector<std::string> cell_names, point_names;
  add_names(cells.reals, cell_names);
  add_names(cells.codes, cell_names);
  add_names(particles.scalars, point_names);
  add_names(particles.integers, point_names);
  add_names(particles.vectors, point_names);
  std::string error;
  for (const auto& [name, f] : cells.reals)
    if (!f || f->stagger() != grid::Stagger::Cell) error = "cell array '" + name + "'";
  for (const auto& [name, f] : cells.codes)
    if (!f || f->stagger() != grid::Stagger::Cell) error = "cell array '" + name + "'";
  if (!error.empty())
    throw core::InputError("FrameWriter: " + error + " is null or not cell-centred");
  const std::size_t n = particles.x.size();
  auto size_error = [&](const std::string& name, std::size_t size) {
    if (size != n)
      error = "particle array '" + name + "' has " + std::to_string(size) + " values for " +
              std::to_string(n) + " particles";
  };
  size_error("z", particles.z.size());
  for (const auto& [name, v] : particles.scalars) size_error(name, v.size());
  for (const auto& [name, v] : particles.integers) size_error(name, v.size());
  for (const auto& [name, v] : particles.vectors) {
    size_error(name + " (x)", v.first.size());
    size_error(name + " (z)", v.second.size());
  }
  if (!error.empty()) throw core::InputError("FrameWriter: " + error);
  check_same_names(comm, cell_names, "cell array");
  check_same_names(comm, point_names, "particle array");
}

struct Counts {
  long long local = 0, offset = 0, global = 0;
};

Counts counts(const core::Comm& comm, long long local) {
  return {local, comm.exclusive_scan(local), comm.sum(local)};
}

// What every grid writer needs: the open frame file and where its index entries point.
struct Frame {
  const core::Comm& comm;
  hid_t file;
  std::string h5_name;  // relative to the index
  double t;
  long long step;

  void units(const std::string& dataset, const Units& u, const std::string& name) const {
    const auto it = u.find(name);
    if (it != u.end()) h5::set_attribute(file, dataset, "units", it->second);
  }
  std::string item(const std::string& dims, const std::string& type, int precision,
                   const std::string& dataset) const {
    return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"" + type + "\" Precision=\"" +
           std::to_string(precision) + "\" Format=\"HDF\">" + h5_name + ":" + dataset +
           "</DataItem>";
  }
  // The opening of a grid's entry: its name is its collection's, so that it is the same in
  // every frame; the step is kept for restarts (and readers that want it).
  std::string open(const std::string& grid) const {
    return kGridOpen + grid + "\" GridType=\"Uniform\">\n        <Time Value=\"" + real(t) +
           "\"/>\n" + kStepInfo + std::to_string(step) + "\"/>\n";
  }
};

std::string attribute(const std::string& name, const std::string& kind, const std::string& center,
                      const std::string& item) {
  return "        <Attribute Name=\"" + name + "\" AttributeType=\"" + kind + "\" Center=\"" +
         center + "\">\n          " + item + "\n        </Attribute>\n";
}

// The owned block of a cell array as a contiguous (k, i) array.
template <class Out, class Field>
std::vector<Out> owned_block(const Field& f, const core::IndexBox& own) {
  std::vector<Out> block;
  block.reserve(static_cast<std::size_t>(own.nx()) * static_cast<std::size_t>(own.nz()));
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i) block.push_back(static_cast<Out>(f(i, k)));
  return block;
}

// Cell arrays: global (1, nz, nx) arrays, each rank writing its owned block. The grid is a
// 3DCoRectMesh one cell thick, Z in [-h, 0]: ParaView's XDMF reader puts a 2DCoRectMesh in its
// Y-Z plane (it reads the two values as Z, Y with X = 0), away from the particles and outlines
// in the X-Y plane; with three dimensions, (Z, Y, X) order is unambiguous in every reader.
std::string write_cells(const Frame& f, const grid::Decomposition& d, const CellArrays& cells) {
  const grid::GridSpec& spec = d.spec();
  const core::IndexBox own = d.owned_cells();
  const hsize_t dims[3] = {1, static_cast<hsize_t>(spec.nz), static_cast<hsize_t>(spec.nx)};
  const hsize_t start[3] = {0, static_cast<hsize_t>(own.k0), static_cast<hsize_t>(own.i0)};
  const hsize_t count[3] = {1, static_cast<hsize_t>(own.nz()), static_cast<hsize_t>(own.nx())};
  const std::string shape = "1 " + std::to_string(spec.nz) + " " + std::to_string(spec.nx);
  std::string x = f.open("cells") +
                  "        <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"2 " +
                  std::to_string(spec.nz + 1) + " " + std::to_string(spec.nx + 1) +
                  "\"/>\n        <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n";
  const std::string xml_item =
      "          <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">";
  x += xml_item + real(-spec.h) + " " + real(spec.origin.z) + " " + real(spec.origin.x) +
       "</DataItem>\n" + xml_item + real(spec.h) + " " + real(spec.h) + " " + real(spec.h) +
       "</DataItem>\n        </Geometry>\n";
  for (const auto& [name, field] : cells.reals) {
    const auto block = owned_block<double>(*field, own);
    const std::string ds = "/cells/" + name;
    h5::write_block(f.file, ds, H5T_NATIVE_DOUBLE, block.data(), 3, dims, start, count);
    f.units(ds, cells.units, name);
    x += attribute(name, "Scalar", "Cell", f.item(shape, "Float", 8, ds));
  }
  for (const auto& [name, field] : cells.codes) {
    const auto block = owned_block<std::int32_t>(*field, own);
    const std::string ds = "/cells/" + name;
    h5::write_block(f.file, ds, H5T_NATIVE_INT32, block.data(), 3, dims, start, count);
    f.units(ds, cells.units, name);
    x += attribute(name, "Scalar", "Cell", f.item(shape, "Int", 4, ds));
  }
  return x + kGridClose + "\n";
}

// (x, z) pairs as (n, 3) rows (x, z, 0).
std::vector<double> rows_xz0(const std::vector<double>& x, const std::vector<double>& z) {
  std::vector<double> xyz;
  xyz.reserve(3 * x.size());
  for (std::size_t n = 0; n < x.size(); ++n) xyz.insert(xyz.end(), {x[n], z[n], 0.0});
  return xyz;
}

// Particles: positions, one vertex cell per particle (explicit connectivity: ParaView's default
// XDMF reader builds no cells without it), every array concatenated in rank order. Empty when
// there is no particle at all.
std::string write_particles(const Frame& f, const PointSet& p) {
  const Counts c = counts(f.comm, static_cast<long long>(p.x.size()));
  const std::string n = std::to_string(c.global);
  const auto rows = [&](const std::string& ds, hid_t type, const void* data, int cols) {
    h5::write_rows(f.file, ds, type, data, c.local, c.offset, c.global, cols);
  };
  const auto xyz = rows_xz0(p.x, p.z);
  rows("/particles/xyz", H5T_NATIVE_DOUBLE, xyz.data(), 3);
  h5::set_attribute(f.file, "/particles/xyz", "units", "m");
  std::vector<std::int64_t> conn(p.x.size());
  for (std::size_t k = 0; k < conn.size(); ++k) conn[k] = c.offset + static_cast<long long>(k);
  // (N, 1): one node per cell, also for readers that take the shape as (cells, nodes per cell).
  const hsize_t dims[2] = {static_cast<hsize_t>(c.global), 1};
  const hsize_t start[2] = {static_cast<hsize_t>(c.offset), 0};
  const hsize_t count[2] = {static_cast<hsize_t>(c.local), 1};
  h5::write_block(f.file, "/particles/connectivity", H5T_NATIVE_INT64, conn.data(), 2, dims, start,
                  count);
  std::string x = f.open("particles") + "        <Topology TopologyType=\"Polyvertex\" " +
                  "NumberOfElements=\"" + n + "\" NodesPerElement=\"1\">\n          " +
                  f.item(n + " 1", "Int", 8, "/particles/connectivity") +
                  "\n        </Topology>\n        <Geometry GeometryType=\"XYZ\">\n          " +
                  f.item(n + " 3", "Float", 8, "/particles/xyz") + "\n        </Geometry>\n";
  for (const auto& [name, v] : p.vectors) {
    const auto data = rows_xz0(v.first, v.second);
    rows("/particles/" + name, H5T_NATIVE_DOUBLE, data.data(), 3);
    f.units("/particles/" + name, p.units, name);
    x += attribute(name, "Vector", "Node", f.item(n + " 3", "Float", 8, "/particles/" + name));
  }
  for (const auto& [name, v] : p.scalars) {
    rows("/particles/" + name, H5T_NATIVE_DOUBLE, v.data(), 1);
    f.units("/particles/" + name, p.units, name);
    x += attribute(name, "Scalar", "Node", f.item(n, "Float", 8, "/particles/" + name));
  }
  for (const auto& [name, v] : p.integers) {
    rows("/particles/" + name, H5T_NATIVE_INT64, v.data(), 1);
    f.units("/particles/" + name, p.units, name);
    x += attribute(name, "Scalar", "Node", f.item(n, "Int", 8, "/particles/" + name));
  }
  // The positions once more as a point array: meshio's time-series reader takes the points of
  // the first frame only and the point arrays of every frame.
  x += attribute("position", "Vector", "Node", f.item(n + " 3", "Float", 8, "/particles/xyz"));
  return c.global > 0 ? x + kGridClose + "\n" : std::string();
}

// One Polylines set under /<group>; its index entry (empty if no lines at all).
std::string write_polylines(const Frame& f, const std::string& group, const Polylines& p) {
  if (f.comm.any(p.body_id.size() != p.lines.size()))
    throw core::InputError("FrameWriter: " + group + " need one body id per line on every rank");
  long long nodes = 0;
  for (const auto& l : p.lines) nodes += static_cast<long long>(l.size());
  const Counts n = counts(f.comm, nodes);
  const Counts lines = counts(f.comm, static_cast<long long>(p.lines.size()));
  std::vector<double> xyz;
  xyz.reserve(3 * static_cast<std::size_t>(nodes));
  // Mixed topology: per line the cell type (2 = polyline), its node count, its global node ids.
  std::vector<std::int64_t> conn;
  long long id = n.offset;
  for (const auto& l : p.lines) {
    conn.push_back(2);
    conn.push_back(static_cast<std::int64_t>(l.size()));
    for (const auto& v : l) {
      xyz.insert(xyz.end(), {v.x, v.z, 0.0});
      conn.push_back(id++);
    }
  }
  const Counts c = counts(f.comm, static_cast<long long>(conn.size()));
  const std::string g = "/" + group;
  h5::write_rows(f.file, g + "/xyz", H5T_NATIVE_DOUBLE, xyz.data(), n.local, n.offset, n.global, 3);
  h5::set_attribute(f.file, g + "/xyz", "units", "m");
  h5::write_rows(f.file, g + "/connectivity", H5T_NATIVE_INT64, conn.data(), c.local, c.offset,
                 c.global, 1);
  h5::write_rows(f.file, g + "/body_id", H5T_NATIVE_INT64, p.body_id.data(), lines.local,
                 lines.offset, lines.global, 1);
  h5::set_attribute(f.file, g + "/body_id", "units", "1");
  if (lines.global == 0) return {};
  return f.open(group) + "        <Topology TopologyType=\"Mixed\" NumberOfElements=\"" +
         std::to_string(lines.global) + "\">\n          " +
         f.item(std::to_string(c.global), "Int", 8, g + "/connectivity") +
         "\n        </Topology>\n        <Geometry GeometryType=\"XYZ\">\n          " +
         f.item(std::to_string(n.global) + " 3", "Float", 8, g + "/xyz") +
         "\n        </Geometry>\n" +
         attribute("body_id", "Scalar", "Cell",
                   f.item(std::to_string(lines.global), "Int", 8, g + "/body_id")) +
         kGridClose + "\n";
}

h5::Handle create_file(const core::Comm& comm, const std::string& path) {
  h5::Handle fapl = h5::mpio_access(comm);
  h5::QuietErrors quiet;
  const hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  if (comm.any(f < 0)) {
    if (f >= 0) H5Fclose(f);
    throw core::InputError("cannot create frame file '" + path + "'");
  }
  return h5::Handle(f, H5Fclose);
}

// Rank 0's error message thrown on every rank.
template <class F>
void on_root(const core::Comm& comm, F&& f) {
  std::string error;
  if (comm.is_root()) {
    try {
      f();
    } catch (const core::InputError& e) {
      error = e.what();
    }
  }
  error = comm.broadcast(error);
  if (!error.empty()) throw core::InputError(error);
}

}  // namespace

FrameWriter::FrameWriter(const std::string& directory, const grid::Decomposition& decomposition,
                         bool continue_existing, long long keep_up_to_step,
                         std::string code_version)
    : directory_(directory), decomposition_(decomposition), code_version_(std::move(code_version)) {
  on_root(decomposition_.comm(), [&] {
    std::error_code ec;
    std::filesystem::create_directories(directory_ + "/frames", ec);
    if (ec)
      throw core::InputError("cannot create output directory '" + directory_ +
                             "/frames': " + ec.message());
    if (continue_existing) read_existing_index(keep_up_to_step);
  });
}

// The index's grid entries: the blocks between a grid line at the entry indent and its closing
// line, each under its temporal collection; the step from the entry's step Information. Entries
// without one (an index of an older format) and unfinished ones are dropped.
void FrameWriter::read_existing_index(long long keep_up_to_step) {
  std::ifstream in(xdmf_path());
  std::string line, collection;
  bool open = false;
  while (std::getline(in, line)) {
    if (!open && line.rfind(kCollectionOpen, 0) == 0) {
      const auto b = kCollectionOpen.size();
      collection = line.substr(b, line.find('"', b) - b);
    } else if (!open && line.rfind(kGridOpen, 0) == 0) {
      entries_.push_back({collection, -1, {}});
      open = true;
    }
    if (!open) continue;
    entries_.back().xml += line + '\n';
    if (line.rfind(kStepInfo, 0) == 0)
      entries_.back().step = std::atoll(line.c_str() + kStepInfo.size());
    if (line == kGridClose) open = false;
  }
  if (open) entries_.pop_back();
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(),
                                [&](const Entry& e) {
                                  return e.step < 0 || e.step > keep_up_to_step ||
                                         std::find(kGrids.begin(), kGrids.end(), e.grid) ==
                                             kGrids.end();
                                }),
                 entries_.end());
}

std::string FrameWriter::frame_path(long long step) const {
  char buf[32];
  std::snprintf(buf, sizeof buf, "frames/frame_%06lld.h5", step);
  return directory_ + "/" + buf;
}

std::size_t FrameWriter::frames() const {
  std::set<long long> steps;
  for (const auto& e : entries_) steps.insert(e.step);
  return steps.size();
}

void FrameWriter::write(double t, long long step, const CellArrays& cells,
                        const PointSet& particles, const Polylines& solids,
                        const Polylines& obstacles) {
  core::ScopedTimer timer("io: frame");
  const core::Comm& comm = decomposition_.comm();
  check_input(comm, cells, particles);
  std::vector<Entry> grids;
  {
    h5::Handle file = create_file(comm, frame_path(step));
    const Frame f{comm, file, frame_path(step).substr(directory_.size() + 1), t, step};
    h5::set_attribute(file, "/", "time", t);
    h5::set_attribute(file, "/", "step", step);
    h5::set_attribute(file, "/", "code_version", code_version_);
    h5::set_attribute(file, "/", "ranks", static_cast<long long>(comm.size()));
    grids.push_back({"cells", step, write_cells(f, decomposition_, cells)});
    grids.push_back({"solids", step, write_polylines(f, "solids", solids)});
    grids.push_back({"obstacles", step, write_polylines(f, "obstacles", obstacles)});
    grids.push_back({"particles", step, write_particles(f, particles)});
  }  // collective close before the index points at the file
  update_index(step, std::move(grids));
}

namespace {

// The particles of one frame for meshio.read (meshio 5): one grid, no Time and no Information
// (it reads neither) and the HDF paths relative to frames/, where the file is.
void write_meshio_frame(const std::string& path, const std::string& grid_xml) {
  std::istringstream in(grid_xml);
  std::string line, body;
  while (std::getline(in, line)) {
    if (line.rfind("        <Time ", 0) == 0 || line.rfind(kStepInfo, 0) == 0) continue;
    const auto at = line.find(">frames/frame_");
    if (at != std::string::npos) line.erase(at + 1, 7);
    body += line + '\n';
  }
  std::ofstream out(path, std::ios::trunc);
  out << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n"
      << body << "  </Domain>\n</Xdmf>\n";
  if (!out) throw core::InputError("cannot write '" + path + "'");
}

}  // namespace

void FrameWriter::update_index(long long step, std::vector<Entry> grids) {
  on_root(decomposition_.comm(), [&] {
    entries_.erase(std::remove_if(entries_.begin(), entries_.end(),
                                  [&](const Entry& e) { return e.step >= step; }),
                   entries_.end());
    for (auto& g : grids) {
      if (g.xml.empty()) continue;
      if (g.grid == "particles") {
        const std::string h5 = frame_path(step);
        write_meshio_frame(h5.substr(0, h5.size() - 3) + "_particles.xdmf", g.xml);
      }
      entries_.push_back(std::move(g));
    }
    write_xdmf(xdmf_path(), kGrids);
    for (const auto& grid : kGrids) write_xdmf(directory_ + "/" + grid + ".xdmf", {grid});
  });
}

void FrameWriter::write_xdmf(const std::string& path, const std::vector<std::string>& grids) const {
  // Written to a temporary and renamed: a viewer never sees half an index.
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << "<?xml version=\"1.0\" ?>\n"
        << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
        << "<Xdmf Version=\"3.0\">\n"
        << "  <Domain>\n";
    for (const auto& grid : grids) {
      const bool any = std::any_of(entries_.begin(), entries_.end(),
                                   [&](const Entry& e) { return e.grid == grid; });
      if (!any) continue;
      out << kCollectionOpen << grid << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
      for (const auto& e : entries_)
        if (e.grid == grid) out << e.xml;
      out << "    </Grid>\n";
    }
    out << "  </Domain>\n"
        << "</Xdmf>\n";
    if (!out) throw core::InputError("cannot write '" + tmp + "'");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0)
    throw core::InputError("cannot rename '" + tmp + "' to '" + path + "'");
}

}  // namespace picdem::io
