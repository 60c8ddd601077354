// ParaView frames: the XDMF index is well-formed XML with the expected structure, every HDF
// DataItem names a dataset that exists with the stated dimensions, and the data equal the global
// reference whatever the rank count (the same frame is also written on 1 .. size ranks and the
// files compared).
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/error.hpp"
#include "picdem/grid/grid.hpp"
#include "picdem/io/frame_writer.hpp"

namespace {

using picdem::core::Comm;
namespace grid = picdem::grid;
namespace io = picdem::io;

// ---- a small strict XML reader: elements, attributes, text; no entities needed here ----------
struct Element {
  std::string name;
  std::map<std::string, std::string> attr;
  std::string text;
  std::vector<Element> children;
  std::vector<const Element*> all(const std::string& n) const {
    std::vector<const Element*> out;
    for (const auto& c : children)
      if (c.name == n) out.push_back(&c);
    return out;
  }
};

class XmlParser {
 public:
  explicit XmlParser(std::string s) : s_(std::move(s)) {}
  Element parse_document() {
    skip_prolog();
    Element root = parse_element();
    skip_space();
    if (p_ != s_.size()) fail("content after the root element");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& what) {
    throw std::runtime_error("XML error at " + std::to_string(p_) + ": " + what);
  }
  void skip_space() {
    while (p_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[p_]))) ++p_;
  }
  void skip_prolog() {
    while (true) {
      skip_space();
      if (s_.compare(p_, 2, "<?") == 0) {
        p_ = s_.find("?>", p_);
        if (p_ == std::string::npos) fail("unterminated <?");
        p_ += 2;
      } else if (s_.compare(p_, 2, "<!") == 0) {
        p_ = s_.find('>', p_);
        if (p_ == std::string::npos) fail("unterminated <!");
        p_ += 1;
      } else {
        return;
      }
    }
  }
  std::string name() {
    const std::size_t b = p_;
    while (p_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[p_])) || s_[p_] == '_'))
      ++p_;
    if (b == p_) fail("expected a name");
    return s_.substr(b, p_ - b);
  }
  Element parse_element() {
    if (s_[p_] != '<') fail("expected <");
    ++p_;
    Element e;
    e.name = name();
    while (true) {
      skip_space();
      if (s_.compare(p_, 2, "/>") == 0) {
        p_ += 2;
        return e;
      }
      if (s_[p_] == '>') {
        ++p_;
        break;
      }
      const std::string key = name();
      skip_space();
      if (s_[p_] != '=') fail("expected =");
      ++p_;
      skip_space();
      if (s_[p_] != '"') fail("expected \"");
      const std::size_t end = s_.find('"', p_ + 1);
      if (end == std::string::npos) fail("unterminated attribute");
      if (e.attr.count(key)) fail("duplicate attribute " + key);
      e.attr[key] = s_.substr(p_ + 1, end - p_ - 1);
      p_ = end + 1;
    }
    while (true) {
      const std::size_t lt = s_.find('<', p_);
      if (lt == std::string::npos) fail("unterminated element " + e.name);
      e.text += s_.substr(p_, lt - p_);
      p_ = lt;
      if (s_.compare(p_, 2, "</") == 0) {
        p_ += 2;
        if (name() != e.name) fail("mismatched closing tag for " + e.name);
        skip_space();
        if (s_[p_] != '>') fail("expected >");
        ++p_;
        return e;
      }
      e.children.push_back(parse_element());
    }
  }
  std::string s_;
  std::size_t p_ = 0;
};

std::vector<long long> numbers(const std::string& s) {
  std::istringstream in(s);
  std::vector<long long> v;
  for (long long n; in >> n;) v.push_back(n);
  return v;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \n\t"), e = s.find_last_not_of(" \n\t");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// ---- reference data ---------------------------------------------------------------------------
const int kNx = 12, kNz = 7;
const double kH = 0.25;

double pressure(int i, int k) {
  return 1000.0 * k + i + 0.5;
}

// 50 particles spread over the tank; each rank passes those in the cells it owns.
struct Particle {
  double x, z, id;
};
std::vector<Particle> all_particles() {
  std::vector<Particle> p;
  for (int n = 0; n < 50; ++n)
    p.push_back({0.05 + 0.059 * n, 0.02 + 0.0347 * ((n * 17) % 50), static_cast<double>(n)});
  return p;
}

struct Frame {
  std::unique_ptr<grid::CellField> p;
  std::unique_ptr<grid::GridArray<signed char>> state;
  io::PointSet particles;
  io::Polylines solids, obstacles;
};

Frame make_frame(const grid::Decomposition& d, double shift) {
  Frame f;
  f.p = std::make_unique<grid::CellField>(d, grid::Stagger::Cell, -1.0);
  f.state = std::make_unique<grid::GridArray<signed char>>(d, grid::Stagger::Cell, -1);
  const auto own = d.owned_cells();
  for (int k = own.k0; k < own.k1; ++k)
    for (int i = own.i0; i < own.i1; ++i) {
      (*f.p)(i, k) = pressure(i, k) + shift;
      (*f.state)(i, k) = static_cast<signed char>((i + k) % 3);
    }
  for (const auto& q : all_particles())
    if (d.owner_of_point({q.x, q.z}) == d.rank()) {
      f.particles.x.push_back(q.x);
      f.particles.z.push_back(q.z);
      f.particles.integers["id"].push_back(static_cast<std::int64_t>(q.id));
      f.particles.scalars["speed"].push_back(q.id * 0.5 + shift);
      f.particles.vectors["velocity"].first.push_back(q.x + shift);
      f.particles.vectors["velocity"].second.push_back(-q.z);
    }
  f.particles.units = {{"speed", "m/s"}, {"velocity", "m/s"}, {"id", "1"}};
  // Two solids, owned by the last rank; one obstacle from rank 0.
  if (d.rank() == d.size() - 1) {
    f.solids.lines = {{{1, 1}, {1.5, 1}, {1.5, 1.2}}, {{2, 0.5}, {2.2, 0.5}, {2.2, 0.7}, {2, 0.7}}};
    f.solids.body_id = {3, 4};
  }
  if (d.rank() == 0) {
    f.obstacles.lines = {{{0, 0}, {0.5, 0}, {0, 0.5}}};
    f.obstacles.body_id = {-1};
  }
  return f;
}

io::CellArrays arrays(const Frame& f) {
  io::CellArrays a;
  a.reals["pressure"] = f.p.get();
  a.codes["state"] = f.state.get();
  a.units = {{"pressure", "Pa"}, {"state", "code"}};
  return a;
}

void write_frames(const grid::Decomposition& d, const std::string& dir) {
  io::FrameWriter w(dir, d, false, std::numeric_limits<long long>::max(), "test 1.0");
  for (int step = 0; step < 3; ++step) {
    Frame f = make_frame(d, step);
    w.write(0.1 * step, 10 * step, arrays(f), f.particles, f.solids, f.obstacles);
  }
}

grid::GridSpec spec() {
  grid::GridSpec s;
  s.nx = kNx;
  s.nz = kNz;
  s.h = kH;
  s.origin = {0.0, 0.0};
  return s;
}

std::string dir_for(int writers) {
  return "frames_np" + std::to_string(Comm().size()) + "_w" + std::to_string(writers);
}

// Reads a whole dataset (serial HDF5) with its dimensions.
std::vector<double> read_h5(const std::string& file, const std::string& dset,
                            std::vector<hsize_t>* dims, bool as_int = false) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0) << file;
  if (f < 0) return {};
  std::vector<double> v;
  if (H5Lexists(f, dset.substr(0, dset.find('/', 1)).c_str(), H5P_DEFAULT) > 0 &&
      H5Lexists(f, dset.c_str(), H5P_DEFAULT) > 0) {
    const hid_t d = H5Dopen2(f, dset.c_str(), H5P_DEFAULT);
    const hid_t s = H5Dget_space(d);
    const int rank = H5Sget_simple_extent_ndims(s);
    dims->assign(static_cast<std::size_t>(rank), 0);
    H5Sget_simple_extent_dims(s, dims->data(), nullptr);
    v.resize(static_cast<std::size_t>(H5Sget_simple_extent_npoints(s)));
    if (as_int) {
      std::vector<long long> w(v.size());
      H5Dread(d, H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, w.data());
      std::copy(w.begin(), w.end(), v.begin());
    } else {
      H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    }
    H5Sclose(s);
    H5Dclose(d);
  } else {
    ADD_FAILURE() << file << " has no dataset " << dset;
    dims->clear();
  }
  H5Fclose(f);
  return v;
}

// A numeric attribute of the object at `path`, as a double.
double read_h5_attribute(const std::string& file, const std::string& path,
                         const std::string& name) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  double v = -1.0;
  const hid_t a = H5Aopen_by_name(f, path.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(a, 0) << file << " " << path << " " << name;
  if (a >= 0) {
    H5Aread(a, H5T_NATIVE_DOUBLE, &v);
    H5Aclose(a);
  }
  H5Fclose(f);
  return v;
}

std::string units_of(const std::string& file, const std::string& dataset) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  std::string v;
  const hid_t a = H5Aopen_by_name(f, dataset.c_str(), "units", H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(a, 0) << file << " " << dataset;
  if (a >= 0) {
    const hid_t t = H5Aget_type(a);
    v.assign(H5Tget_size(t), '\0');
    H5Aread(a, t, v.data());
    H5Tclose(t);
    H5Aclose(a);
  }
  H5Fclose(f);
  return v;
}

// Every HDF DataItem below `e`: dataset exists with the stated dimensions.
void check_data_items(const Element& e, const std::string& dir, int& count) {
  if (e.name == "DataItem" && e.attr.count("Format") && e.attr.at("Format") == "HDF") {
    const std::string ref = trim(e.text);
    const auto colon = ref.find(':');
    ASSERT_NE(colon, std::string::npos) << ref;
    std::vector<hsize_t> dims;
    read_h5(dir + "/" + ref.substr(0, colon), ref.substr(colon + 1), &dims,
            e.attr.at("NumberType") == "Int");
    const auto want = numbers(e.attr.at("Dimensions"));
    EXPECT_EQ(std::vector<long long>(dims.begin(), dims.end()), want) << ref;
    ++count;
  }
  for (const auto& c : e.children) check_data_items(c, dir, count);
}

Element read_index(const std::string& dir) {
  std::ifstream in(dir + "/picdem.xdmf");
  std::stringstream ss;
  ss << in.rdbuf();
  return XmlParser(ss.str()).parse_document();
}

// The temporal collections of the index, by name, in file order.
std::vector<const Element*> collections(const Element& root, std::vector<std::string>* names) {
  const auto domains = root.all("Domain");
  EXPECT_EQ(domains.size(), 1u);
  if (domains.empty()) return {};
  const auto c = domains[0]->all("Grid");
  for (const auto* g : c) {
    names->push_back(g->attr.at("Name"));
    EXPECT_EQ(g->attr.at("GridType"), "Collection");
    EXPECT_EQ(g->attr.at("CollectionType"), "Temporal");
  }
  return c;
}

// The step of a grid entry (its Information element).
long long step_of(const Element& g) {
  const auto info = g.all("Information");
  EXPECT_EQ(info.size(), 1u);
  if (info.empty()) return -1;
  EXPECT_EQ(info[0]->attr.at("Name"), "step");
  return std::stoll(info[0]->attr.at("Value"));
}

std::string root_string_attribute(const std::string& file, const std::string& name) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t a = H5Aopen(f, name.c_str(), H5P_DEFAULT);
  const hid_t t = H5Aget_type(a);
  std::string v(H5Tget_size(t), '\0');
  H5Aread(a, t, v.data());
  H5Tclose(t);
  H5Aclose(a);
  H5Fclose(f);
  return v;
}

TEST(Frames, XdmfWellFormedAndDatasetsMatchTheGlobalReference) {
  const Comm comm;
  const grid::Decomposition d(spec(), comm, 1);
  const std::string dir = dir_for(comm.size());
  write_frames(d, dir);
  comm.barrier();
  if (!comm.is_root()) return;
  const Element root = read_index(dir);
  ASSERT_EQ(root.name, "Xdmf");
  EXPECT_EQ(root.attr.at("Version"), "3.0");
  std::vector<std::string> names;
  const auto series = collections(root, &names);
  // One temporal collection per grid, the particles last (meshio reads the last one).
  ASSERT_EQ(names, (std::vector<std::string>{"cells", "solids", "obstacles", "particles"}));
  int items = 0;
  for (const auto* c : series) {
    const auto frames = c->all("Grid");
    ASSERT_EQ(frames.size(), 3u);
    for (std::size_t n = 0; n < frames.size(); ++n) {
      const Element& g = *frames[n];
      EXPECT_EQ(g.attr.at("Name"), c->attr.at("Name"));  // the same name in every frame
      EXPECT_EQ(g.attr.at("GridType"), "Uniform");
      ASSERT_EQ(g.all("Time").size(), 1u);
      EXPECT_DOUBLE_EQ(std::stod(g.all("Time")[0]->attr.at("Value")), 0.1 * n);
      EXPECT_EQ(step_of(g), 10 * static_cast<long long>(n));
      check_data_items(g, dir, items);
    }
  }
  const Element& cells = *series[0]->all("Grid")[2];
  EXPECT_EQ(cells.all("Topology")[0]->attr.at("TopologyType"), "3DCoRectMesh");
  EXPECT_EQ(numbers(cells.all("Topology")[0]->attr.at("Dimensions")),
            (std::vector<long long>{2, kNz + 1, kNx + 1}));
  // Origin and spacing in (Z, Y, X) order: the slab Z in [-h, 0], the tank corner at (0, 0).
  const auto geometry = cells.all("Geometry")[0]->all("DataItem");
  ASSERT_EQ(geometry.size(), 2u);
  std::istringstream origin(geometry[0]->text), spacing(geometry[1]->text);
  double oz, oy, ox, dz, dy, dx;
  origin >> oz >> oy >> ox;
  spacing >> dz >> dy >> dx;
  EXPECT_EQ(oz, -kH);
  EXPECT_EQ(oy, 0.0);
  EXPECT_EQ(ox, 0.0);
  EXPECT_EQ(dz, kH);
  EXPECT_EQ(dy, kH);
  EXPECT_EQ(dx, kH);
  ASSERT_EQ(cells.all("Attribute").size(), 2u);
  EXPECT_EQ(cells.all("Attribute")[1]->attr.at("Name"), "state");
  EXPECT_EQ(cells.all("Attribute")[1]->all("DataItem")[0]->attr.at("NumberType"), "Int");
  // Particles: an explicit connectivity, one node per cell.
  const Element& particles = *series[3]->all("Grid")[2];
  const Element& topology = *particles.all("Topology")[0];
  EXPECT_EQ(topology.attr.at("TopologyType"), "Polyvertex");
  EXPECT_EQ(topology.attr.at("NumberOfElements"), "50");
  EXPECT_EQ(topology.attr.at("NodesPerElement"), "1");
  ASSERT_EQ(topology.all("DataItem").size(), 1u);
  std::vector<std::string> arrays;
  for (const auto* a : particles.all("Attribute"))
    arrays.push_back(a->attr.at("Name") + ":" + a->attr.at("AttributeType"));
  EXPECT_EQ(arrays, (std::vector<std::string>{"velocity:Vector", "speed:Scalar", "id:Scalar",
                                              "position:Vector"}));
  // Per frame: 2 cell arrays + 3 per polyline set + particle connectivity, xyz, velocity,
  // speed, id, position.
  EXPECT_EQ(items, 3 * (2 + 3 + 3 + 6));

  // Values of the last frame (shift 2) against the reference.
  const std::string file = dir + "/frames/frame_000020.h5";
  std::vector<hsize_t> dims;
  const auto p = read_h5(file, "/cells/pressure", &dims);
  ASSERT_EQ(p.size(), static_cast<std::size_t>(kNx * kNz));
  for (int k = 0; k < kNz; ++k)
    for (int i = 0; i < kNx; ++i) EXPECT_EQ(p[k * kNx + i], pressure(i, k) + 2.0) << i << "," << k;
  const auto state = read_h5(file, "/cells/state", &dims, true);
  ASSERT_EQ(state.size(), static_cast<std::size_t>(kNx * kNz));
  for (int k = 0; k < kNz; ++k)
    for (int i = 0; i < kNx; ++i) EXPECT_EQ(state[k * kNx + i], (i + k) % 3);
  const auto xyz = read_h5(file, "/particles/xyz", &dims);
  const auto id = read_h5(file, "/particles/id", &dims, true);
  const auto speed = read_h5(file, "/particles/speed", &dims);
  const auto velocity = read_h5(file, "/particles/velocity", &dims);
  const auto conn = read_h5(file, "/particles/connectivity", &dims, true);
  EXPECT_EQ(dims, (std::vector<hsize_t>{50, 1}));
  const auto ref = all_particles();
  ASSERT_EQ(id.size(), ref.size());
  ASSERT_EQ(velocity.size(), 3 * ref.size());
  std::vector<bool> seen(ref.size(), false);
  for (std::size_t n = 0; n < id.size(); ++n) {
    const auto& q = ref[static_cast<std::size_t>(id[n])];
    seen[static_cast<std::size_t>(id[n])] = true;
    EXPECT_EQ(conn[n], static_cast<double>(n));
    EXPECT_EQ(xyz[3 * n], q.x);
    EXPECT_EQ(xyz[3 * n + 1], q.z);
    EXPECT_EQ(xyz[3 * n + 2], 0.0);
    EXPECT_EQ(speed[n], q.id * 0.5 + 2.0);
    EXPECT_EQ(velocity[3 * n], q.x + 2.0);
    EXPECT_EQ(velocity[3 * n + 1], -q.z);
    EXPECT_EQ(velocity[3 * n + 2], 0.0);
  }
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](bool b) { return b; }));
  const auto sconn = read_h5(file, "/solids/connectivity", &dims, true);
  EXPECT_EQ(sconn, (std::vector<double>{2, 3, 0, 1, 2, 2, 4, 3, 4, 5, 6}));
  EXPECT_EQ(read_h5(file, "/solids/body_id", &dims, true), (std::vector<double>{3, 4}));
  const auto sxyz = read_h5(file, "/solids/xyz", &dims);
  ASSERT_EQ(sxyz.size(), 21u);
  EXPECT_EQ(sxyz[3 * 4], 2.2);
  EXPECT_EQ(sxyz[3 * 4 + 1], 0.5);
  // Attributes of the frame file and units of its datasets.
  EXPECT_EQ(root_string_attribute(file, "code_version"), "test 1.0");
  EXPECT_EQ(read_h5_attribute(file, "/", "time"), 0.2);
  EXPECT_EQ(read_h5_attribute(file, "/", "step"), 20.0);
  EXPECT_EQ(read_h5_attribute(file, "/", "ranks"), static_cast<double>(comm.size()));
  EXPECT_EQ(units_of(file, "/cells/pressure"), "Pa");
  EXPECT_EQ(units_of(file, "/particles/velocity"), "m/s");
  EXPECT_EQ(units_of(file, "/particles/xyz"), "m");
}

TEST(Frames, SameFilesOnOneToSizeRanks) {
  const Comm world;
  for (int n = 1; n <= world.size(); ++n) {
    MPI_Comm sub;
    MPI_Comm_split(world.raw(), world.rank() < n ? 0 : MPI_UNDEFINED, world.rank(), &sub);
    if (sub != MPI_COMM_NULL) {
      const grid::Decomposition d(spec(), Comm(sub), 1);
      write_frames(d, dir_for(n) + "_sub");
      MPI_Comm_free(&sub);
    }
    world.barrier();
  }
  if (!world.is_root()) return;
  // Cell arrays and polylines are identical; particles the same set (order follows ranks).
  for (int n = 2; n <= world.size(); ++n)
    for (const char* ds : {"/cells/pressure", "/cells/state", "/solids/xyz", "/obstacles/xyz"}) {
      std::vector<hsize_t> d1, dn;
      const bool as_int = std::string(ds) == "/cells/state";
      const auto a = read_h5(dir_for(1) + "_sub/frames/frame_000010.h5", ds, &d1, as_int);
      const auto b = read_h5(dir_for(n) + "_sub/frames/frame_000010.h5", ds, &dn, as_int);
      EXPECT_EQ(a, b) << ds << " on " << n << " ranks";
      EXPECT_EQ(d1, dn) << ds;
    }
}

TEST(Frames, ContinueExistingDropsFramesFromTheRestartStepOn) {
  const Comm comm;
  const grid::Decomposition d(spec(), comm, 1);
  const std::string dir = dir_for(comm.size()) + "_restart";
  write_frames(d, dir);  // steps 0, 10, 20
  io::FrameWriter w(dir, d, /*continue_existing=*/true);
  EXPECT_EQ(comm.is_root() ? w.frames() : 3u, 3u);
  Frame f = make_frame(d, 5);
  w.write(0.15, 15, arrays(f), f.particles, f.solids, f.obstacles);
  comm.barrier();
  if (!comm.is_root()) return;
  EXPECT_EQ(w.frames(), 3u);
  std::vector<std::string> names;
  const Element root = read_index(dir);
  const auto series = collections(root, &names);
  ASSERT_EQ(names, (std::vector<std::string>{"cells", "solids", "obstacles", "particles"}));
  for (const auto* c : series) {
    std::vector<long long> steps;
    for (const auto* g : c->all("Grid")) steps.push_back(step_of(*g));
    EXPECT_EQ(steps, (std::vector<long long>{0, 10, 15})) << c->attr.at("Name");
  }
}

TEST(Frames, RestartAtAnEarlierStepKeepsOnlyTheFramesUpToIt) {
  const Comm comm;
  const grid::Decomposition d(spec(), comm, 1);
  const std::string dir = dir_for(comm.size()) + "_keep";
  write_frames(d, dir);  // steps 0, 10, 20
  io::FrameWriter w(dir, d, /*continue_existing=*/true, /*keep_up_to_step=*/10);
  if (comm.is_root()) {
    EXPECT_EQ(w.frames(), 2u);
  }
}

TEST(Frames, MismatchedInputIsInputError) {
  const Comm comm;
  const grid::Decomposition d(spec(), comm, 1);
  io::FrameWriter w(dir_for(comm.size()) + "_bad", d);
  Frame f = make_frame(d, 0);
  f.particles.scalars["speed"].push_back(1.0);  // one value too many on every rank
  EXPECT_THROW(w.write(0.0, 0, arrays(f), f.particles, f.solids, f.obstacles),
               picdem::core::InputError);
  Frame g = make_frame(d, 0);
  g.solids.lines.clear();
  g.solids.body_id = {1};
  EXPECT_THROW(w.write(0.0, 0, arrays(g), g.particles, g.solids, g.obstacles),
               picdem::core::InputError);
  Frame h = make_frame(d, 0);
  h.particles.scalars["id"] = h.particles.scalars["speed"];  // "id" twice
  EXPECT_THROW(w.write(0.0, 0, arrays(h), h.particles, h.solids, h.obstacles),
               picdem::core::InputError);
}

TEST(Frames, EmptyParticlesAndOutlinesLeaveOnlyTheCellGrid) {
  const Comm comm;
  const grid::Decomposition d(spec(), comm, 1);
  const std::string dir = dir_for(comm.size()) + "_empty";
  io::FrameWriter w(dir, d);
  grid::CellField p(d, grid::Stagger::Cell, 2.5);
  io::CellArrays a;
  a.reals["pressure"] = &p;
  w.write(1.0, 7, a, {}, {}, {});
  comm.barrier();
  if (!comm.is_root()) return;
  std::vector<std::string> names;
  const Element root = read_index(dir);
  const auto series = collections(root, &names);
  ASSERT_EQ(names, std::vector<std::string>{"cells"});
  ASSERT_EQ(series[0]->all("Grid").size(), 1u);
  int items = 0;
  check_data_items(*series[0], dir, items);
  EXPECT_EQ(items, 1);
  std::vector<hsize_t> dims;
  const auto v = read_h5(dir + "/frames/frame_000007.h5", "/cells/pressure", &dims);
  EXPECT_EQ(v, std::vector<double>(kNx * kNz, 2.5));
}

}  // namespace
