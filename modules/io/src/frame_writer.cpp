#include "picdem/io/frame_writer.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "h5.hpp"
#include "picdem/core/error.hpp"
#include "picdem/core/timer.hpp"

namespace picdem::io {
namespace {

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
    if (n.empty() || n.find_first_of("/<>&\"") != std::string::npos)
      throw core::InputError("FrameWriter: " + what + " name '" + n +
                             "' must be non-empty without / < > & \"");
    joined += n + '\n';
  }
  const bool differs = comm.broadcast(joined) != joined;
  if (comm.any(differs))
    throw core::InputError("FrameWriter: every rank must pass the same " + what + " names");
}

struct Counts {
  long long local = 0, offset = 0, global = 0;
};

Counts counts(const core::Comm& comm, long long local) {
  return {local, comm.exclusive_scan(local), comm.sum(local)};
}

std::string data_item(const std::string& dims, const std::string& type, int precision,
                      const std::string& file, const std::string& dataset) {
  return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"" + type + "\" Precision=\"" +
         std::to_string(precision) + "\" Format=\"HDF\">" + file + ":" + dataset + "</DataItem>";
}

// Writes one Polylines set under /<group> and returns its XDMF grid (empty if no lines at all).
std::string write_polylines(const core::Comm& comm, hid_t file, const std::string& group,
                            const Polylines& p, const std::string& h5_name) {
  if (p.body_id.size() != p.lines.size())
    throw core::InputError("FrameWriter: " + group + " has " + std::to_string(p.lines.size()) +
                           " lines but " + std::to_string(p.body_id.size()) + " body ids");
  long long nodes = 0;
  for (const auto& l : p.lines) nodes += static_cast<long long>(l.size());
  const Counts n = counts(comm, nodes);
  const Counts lines = counts(comm, static_cast<long long>(p.lines.size()));
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
  const Counts c = counts(comm, static_cast<long long>(conn.size()));
  h5::write_rows(file, "/" + group + "/xyz", H5T_NATIVE_DOUBLE, xyz.data(), n.local, n.offset,
                 n.global, 3);
  h5::write_rows(file, "/" + group + "/connectivity", H5T_NATIVE_INT64, conn.data(), c.local,
                 c.offset, c.global, 1);
  h5::write_rows(file, "/" + group + "/body_id", H5T_NATIVE_DOUBLE, p.body_id.data(), lines.local,
                 lines.offset, lines.global, 1);
  if (lines.global == 0) return {};
  std::ostringstream x;
  x << "        <Grid Name=\"" << group << "\" GridType=\"Uniform\">\n"
    << "          <Topology TopologyType=\"Mixed\" NumberOfElements=\"" << lines.global << "\">\n"
    << "            "
    << data_item(std::to_string(c.global), "Int", 8, h5_name, "/" + group + "/connectivity") << "\n"
    << "          </Topology>\n"
    << "          <Geometry GeometryType=\"XYZ\">\n"
    << "            "
    << data_item(std::to_string(n.global) + " 3", "Float", 8, h5_name, "/" + group + "/xyz") << "\n"
    << "          </Geometry>\n"
    << "          <Attribute Name=\"body_id\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
    << "            "
    << data_item(std::to_string(lines.global), "Float", 8, h5_name, "/" + group + "/body_id")
    << "\n"
    << "          </Attribute>\n"
    << "        </Grid>\n";
  return x.str();
}

const char* const kFrameOpen = "      <Grid Name=\"step_";
const char* const kFrameClose = "      </Grid>";

}  // namespace

FrameWriter::FrameWriter(const std::string& directory, const grid::Decomposition& decomposition,
                         bool continue_existing, long long keep_up_to_step)
    : directory_(directory), decomposition_(decomposition) {
  const core::Comm& comm = decomposition_.comm();
  std::string error;
  if (comm.is_root()) {
    std::error_code ec;
    std::filesystem::create_directories(directory_ + "/frames", ec);
    if (ec) error = "cannot create output directory '" + directory_ + "/frames': " + ec.message();
    std::ifstream in(xdmf_path());
    if (continue_existing && error.empty() && in) {
      // Frames are the blocks between a "step_" grid line and its closing line at that indent.
      std::string line;
      Entry* open = nullptr;
      while (std::getline(in, line)) {
        if (line.rfind(kFrameOpen, 0) == 0) {
          entries_.push_back({std::atoll(line.c_str() + std::string(kFrameOpen).size()), {}});
          open = &entries_.back();
        }
        if (open) open->xml += line + '\n';
        if (open && line == kFrameClose) open = nullptr;
      }
      if (open) entries_.pop_back();  // an unfinished block is not a frame
      entries_.erase(std::remove_if(entries_.begin(), entries_.end(),
                                    [&](const Entry& e) { return e.step > keep_up_to_step; }),
                     entries_.end());
    }
  }
  error = comm.broadcast(error);
  if (!error.empty()) throw core::InputError(error);
}

std::string FrameWriter::frame_path(long long step) const {
  char buf[32];
  std::snprintf(buf, sizeof buf, "frames/frame_%06lld.h5", step);
  return directory_ + "/" + buf;
}

void FrameWriter::write(double t, long long step,
                        const std::map<std::string, const grid::CellField*>& cell_fields,
                        const PointSet& particles, const Polylines& solids,
                        const Polylines& obstacles) {
  core::ScopedTimer timer("io: frame");
  const core::Comm& comm = decomposition_.comm();
  const grid::GridSpec& spec = decomposition_.spec();
  std::vector<std::string> field_names, scalar_names;
  for (const auto& [name, f] : cell_fields) {
    field_names.push_back(name);
    if (!f || f->stagger() != grid::Stagger::Cell)
      throw core::InputError("FrameWriter: cell field '" + name + "' is null or not cell-centred");
  }
  for (const auto& [name, v] : particles.scalars) {
    scalar_names.push_back(name);
    if (v.size() != particles.x.size())
      throw core::InputError("FrameWriter: particle scalar '" + name + "' has " +
                             std::to_string(v.size()) + " values for " +
                             std::to_string(particles.x.size()) + " particles");
  }
  if (particles.z.size() != particles.x.size())
    throw core::InputError("FrameWriter: particles have " + std::to_string(particles.x.size()) +
                           " x but " + std::to_string(particles.z.size()) + " z");
  check_same_names(comm, field_names, "cell field");
  check_same_names(comm, scalar_names, "particle scalar");

  const std::string h5_rel = frame_path(step).substr(directory_.size() + 1);
  h5::Handle fapl = h5::mpio_access(comm);
  h5::Handle file;
  {
    h5::QuietErrors quiet;
    const hid_t f = H5Fcreate(frame_path(step).c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
    if (comm.any(f < 0)) {
      if (f >= 0) H5Fclose(f);
      throw core::InputError("cannot create frame file '" + frame_path(step) + "'");
    }
    file = h5::Handle(f, H5Fclose);
  }
  std::ostringstream x;
  x << kFrameOpen;
  char stepname[32];
  std::snprintf(stepname, sizeof stepname, "%06lld", step);
  x << stepname << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
    << "        <Time Value=\"" << real(t) << "\"/>\n";

  // Cell fields: global (1, nz, nx) arrays, each rank writing its owned block. The grid is a
  // 3DCoRectMesh one cell thick, Z in [-h, 0]: ParaView's XDMF reader puts a 2DCoRectMesh in its
  // Y-Z plane (it reads the two values as Z, Y with X = 0), away from the particles and outlines
  // in the X-Y plane; with three dimensions, (Z, Y, X) order is unambiguous in every reader.
  const core::IndexBox own = decomposition_.owned_cells();
  const std::string cells = "1 " + std::to_string(spec.nz) + " " + std::to_string(spec.nx);
  x << "        <Grid Name=\"fluid\" GridType=\"Uniform\">\n"
    << "          <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"2 " << spec.nz + 1 << " "
    << spec.nx + 1 << "\"/>\n"
    << "          <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
    << "            <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">"
    << real(-spec.h) << " " << real(spec.origin.z) << " " << real(spec.origin.x) << "</DataItem>\n"
    << "            <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">"
    << real(spec.h) << " " << real(spec.h) << " " << real(spec.h) << "</DataItem>\n"
    << "          </Geometry>\n";
  std::vector<double> block;
  for (const auto& [name, f] : cell_fields) {
    block.clear();
    for (int k = own.k0; k < own.k1; ++k)
      for (int i = own.i0; i < own.i1; ++i) block.push_back((*f)(i, k));
    const hsize_t dims[3] = {1, static_cast<hsize_t>(spec.nz), static_cast<hsize_t>(spec.nx)};
    const hsize_t start[3] = {0, static_cast<hsize_t>(own.k0), static_cast<hsize_t>(own.i0)};
    const hsize_t count[3] = {1, static_cast<hsize_t>(own.nz()), static_cast<hsize_t>(own.nx())};
    h5::write_block(file, "/fluid/" + name, H5T_NATIVE_DOUBLE, block.data(), 3, dims, start, count);
    x << "          <Attribute Name=\"" << name << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
      << "            " << data_item(cells, "Float", 8, h5_rel, "/fluid/" + name) << "\n"
      << "          </Attribute>\n";
  }
  x << "        </Grid>\n";

  // Particles: (x, z, 0) rows and one dataset per scalar, concatenated in rank order.
  const Counts np = counts(comm, static_cast<long long>(particles.x.size()));
  std::vector<double> xyz;
  xyz.reserve(3 * particles.x.size());
  for (std::size_t n = 0; n < particles.x.size(); ++n)
    xyz.insert(xyz.end(), {particles.x[n], particles.z[n], 0.0});
  h5::write_rows(file, "/particles/xyz", H5T_NATIVE_DOUBLE, xyz.data(), np.local, np.offset,
                 np.global, 3);
  for (const auto& [name, v] : particles.scalars)
    h5::write_rows(file, "/particles/" + name, H5T_NATIVE_DOUBLE, v.data(), np.local, np.offset,
                   np.global, 1);
  if (np.global > 0) {
    const std::string n = std::to_string(np.global);
    x << "        <Grid Name=\"particles\" GridType=\"Uniform\">\n"
      << "          <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
      << "\" NodesPerElement=\"1\"/>\n"
      << "          <Geometry GeometryType=\"XYZ\">\n"
      << "            " << data_item(n + " 3", "Float", 8, h5_rel, "/particles/xyz") << "\n"
      << "          </Geometry>\n";
    for (const auto& name : scalar_names)
      x << "          <Attribute Name=\"" << name
        << "\" AttributeType=\"Scalar\" Center=\"Node\">\n"
        << "            " << data_item(n, "Float", 8, h5_rel, "/particles/" + name) << "\n"
        << "          </Attribute>\n";
    x << "        </Grid>\n";
  }
  x << write_polylines(comm, file, "solids", solids, h5_rel)
    << write_polylines(comm, file, "obstacles", obstacles, h5_rel) << kFrameClose << "\n";
  file.reset();  // collective close before the index points at the file

  if (comm.is_root()) {
    while (!entries_.empty() && entries_.back().step >= step) entries_.pop_back();
    entries_.push_back({step, x.str()});
  }
  std::string error;
  if (comm.is_root()) {
    try {
      write_xdmf();
    } catch (const core::InputError& e) {
      error = e.what();
    }
  }
  error = comm.broadcast(error);
  if (!error.empty()) throw core::InputError(error);
}

void FrameWriter::write_xdmf() const {
  // Written to a temporary and renamed: a viewer never sees half an index.
  const std::string tmp = xdmf_path() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << "<?xml version=\"1.0\" ?>\n"
        << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
        << "<Xdmf Version=\"2.0\">\n"
        << "  <Domain>\n"
        << "    <Grid Name=\"picdem\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& e : entries_) out << e.xml;
    out << "    </Grid>\n"
        << "  </Domain>\n"
        << "</Xdmf>\n";
    if (!out) throw core::InputError("cannot write '" + tmp + "'");
  }
  if (std::rename(tmp.c_str(), xdmf_path().c_str()) != 0)
    throw core::InputError("cannot rename '" + tmp + "' to '" + xdmf_path() + "'");
}

}  // namespace picdem::io
