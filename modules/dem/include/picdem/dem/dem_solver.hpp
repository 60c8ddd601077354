#pragma once
// The distributed DEM solver. Each rank owns the solids whose centre lies in its region and holds
// ghost copies of the solids of other ranks within contact reach of its region. Four named
// communication verbs (as in LAMMPS): exchange (migrate solids to the rank that now holds their
// centre, with their contact history), borders (rebuild the ghost lists), forward (refresh ghost
// states from their owners, every predictor and corrector stage) and gather (every solid on every
// rank, for output). The forces on a solid are summed over its partners in a fixed order (tank
// walls, obstacles, then solids by global id), each pair evaluated with the lower id as body a,
// so trajectories are bitwise identical for any number of ranks.
#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "picdem/core/comm.hpp"
#include "picdem/core/solid_state.hpp"
#include "picdem/core/vec2.hpp"
#include "picdem/dem/contact_geometry.hpp"
#include "picdem/dem/contact_law.hpp"
#include "picdem/dem/parameters.hpp"
#include "picdem/geometry/shape.hpp"

namespace picdem::dem {

/// One active contact. id_j = -1 for a tank wall or an obstacle. `normal` points from i to j,
/// `delta` is the overlap of the imaginary boundaries (eq. 19).
struct Contact {
  std::int64_t id_i = 0, id_j = -1;
  core::Vec2 point, normal;
  double delta = 0.0;
};

class DemSolver {
 public:
  /// Every piece of history as plain arrays: the solids (ordered by id) and, for the
  /// accumulated tangential model, the springs of every active contact seen from each solid
  /// (sorted by solid, then partner)
  /// (partner < 0: -1 - side for tank walls left, right, bottom, top; -5 - k for obstacle k).
  struct Snapshot {
    std::vector<std::int64_t> id;
    std::vector<double> x, z, theta, u, w, omega;
    std::vector<std::int64_t> spring_solid, spring_partner;
    std::vector<double> spring;

    /// f(name, array) for every array above, in declaration order: the names of a checkpoint.
    template <class F>
    void for_each(F&& f) {
      visit(*this, f);
    }
    template <class F>
    void for_each(F&& f) const {
      visit(*this, f);
    }

   private:
    template <class S, class F>
    static void visit(S& s, F& f) {
      f("id", s.id), f("x", s.x), f("z", s.z), f("theta", s.theta), f("u", s.u), f("w", s.w);
      f("omega", s.omega), f("spring_solid", s.spring_solid);
      f("spring_partner", s.spring_partner), f("spring", s.spring);
    }
  };

  /// regions[r]: the box of space rank r owns; tank: the tank (its sides are walls);
  /// obstacle_polygons: fixed world-frame polygons (counter-clockwise).
  DemSolver(core::Comm comm, DemConfig config, std::vector<core::Box2> regions, core::Box2 tank,
            std::vector<std::vector<core::Vec2>> obstacle_polygons);

  /// Every rank passes the same list; each keeps what it owns. Mass and inertia are set from the
  /// density and the shape. Ids must be unique.
  void add_solids(const std::vector<SolidSpec>& solids);

  /// Collision loads at level n for the pressure equation (dt in place of dt_DEM in eq. 8), for
  /// the owned solids, ordered by id. No history is changed.
  std::vector<core::SolidLoads> predicted_collision_loads(double dt) const;

  /// Eqs. 21-25: K = INT(dt / dt_DEM) subcycles with the fluid loads held fixed; gravity is added
  /// here. `fluid_loads` (any order, any subset of the owned solids) may be empty (dry).
  void advance(double dt, const std::vector<core::SolidLoads>& fluid_loads);

  const std::vector<core::SolidState>& owned() const { return owned_; }
  std::vector<core::SolidState> ghosts() const { return ghosts_; }
  geometry::ShapePtr shape_of(std::int64_t id) const;
  /// Every solid, ordered by id, on every rank.
  std::vector<core::SolidState> gather_all() const;
  /// The active contacts at the current state, each reported once over all ranks: by the owner
  /// of solid i, where i is the lower id of a solid-solid pair (id_j = -1: wall or obstacle).
  std::vector<Contact> active_contacts() const;
  /// Collective: the largest overlap delta of the imaginary boundaries over all active contacts
  /// (eq. 19); the real boundaries cross when it exceeds the gap. 0 without contacts.
  double max_contact_overlap() const {
    double m = 0.0;
    for (const auto& c : active_contacts()) m = std::max(m, c.delta);
    return comm_.max(m);
  }

  double dt_dem() const { return dt_dem_; }
  int last_subcycles() const { return last_subcycles_; }
  const DemConfig& config() const { return cfg_; }
  /// Number of neighbour-list rebuilds so far (migrations happen at rebuilds).
  long long rebuilds() const { return rebuilds_; }

  Snapshot snapshot() const;
  /// Replaces every solid's state and history (any rank count); add_solids must have been
  /// called with the case's solids first (it builds the shape table).
  void restore(const Snapshot& snap);
  /// Collective: gives rank r the region regions[r] (a new decomposition of the same ranks) and
  /// moves every solid, with its contact history, to the rank whose region now holds it.
  void set_regions(std::vector<core::Box2> regions);

 private:
  struct ShapeInfo {
    geometry::ShapePtr shape;
    Boundary body;        ///< body frame, with the arcs' end data
    bool circle = false;  ///< declares the centred-circle fast path (Shape::fast_paths)
    double radius = 0.0;  ///< bounding radius
  };
  /// Accumulated tangential springs of one owned solid, sorted by partner key.
  using Springs = std::vector<std::pair<std::int64_t, double>>;
  struct Stage {
    std::vector<core::Vec2> force;
    std::vector<double> torque;
  };

  // -- forces
  void collision_forces(double dt_t, Stage& out, std::vector<Springs>* new_springs,
                        std::vector<Contact>* contacts) const;
  bool solid_pair(const core::SolidState& a, const core::SolidState& b, ContactKinematics& k) const;
  bool wall_pair(const core::SolidState& a, int side, ContactKinematics& k) const;
  bool obstacle_pair(const core::SolidState& a, std::size_t obstacle, ContactKinematics& k) const;

  // -- communication verbs
  int owner_of(const core::Vec2& x) const;
  void exchange();
  void borders();
  void forward();
  void rebuild();
  void build_neighbours();
  void maybe_rebuild();
  void sort_owned();

  core::Comm comm_;
  DemConfig cfg_;
  std::vector<core::Box2> regions_;
  core::Box2 tank_;
  std::vector<Boundary> obstacles_;
  std::vector<core::Box2> obstacle_boxes_;
  std::vector<ShapeInfo> shapes_;
  std::map<const geometry::Shape*, int> shape_index_;  // shapes_ index of each shape
  struct Statics {
    std::int64_t id = 0;
    int shape = 0;
    double mass = 0.0, inertia = 0.0;
    double mu = 0.0;  ///< friction coefficient (SolidSpec::friction, or dem/mu)
  };
  std::vector<Statics> statics_;  // every solid, sorted by id
  const Statics& statics_of(std::int64_t id) const;
  /// Friction coefficient of solid `id` (ids are usually 0..N-1: statics_[id] without a search).
  double friction_of(std::int64_t id) const;
  bool own_friction_ = false;  // some solid sets its own friction: pairs take pair_friction()
  ContactLawPtr law_;          // cfg_.contact_law, or the paper's law built from cfg_
  double max_radius_ = 0.0, skin_ = 0.0, dt_dem_ = 0.0;
  // lightest and heaviest solid [kg/m], for the messages that name what sets dt_DEM
  std::pair<double, double> mass_range_{0.0, 0.0};
  int last_subcycles_ = 0;
  long long rebuilds_ = 0;

  std::vector<core::SolidState> owned_, ghosts_;
  // parallel to owned_: contact history and the velocities U^n at the start of the fluid step
  std::vector<Springs> springs_;
  std::vector<core::Vec2> v_start_;
  std::vector<double> omega_start_;
  std::vector<core::Vec2> x_at_build_;       // owned positions at the last rebuild
  std::vector<std::vector<int>> send_list_;  // per rank: owned indices sent as ghosts
  std::vector<int> recv_count_;              // per rank: doubles received in borders()
  // neighbour list of owned solids (CSR): partners are local indices (owned, then ghosts),
  // sorted by global id
  std::vector<int> nbr_start_, nbr_;
  // half evaluation of the owned pairs: for an entry of solid i whose partner j is owned with
  // j < i, the index of j's entry for i (whose pair was evaluated first, with the same bits as
  // here, since a pair is always evaluated with the lower id as body a); -1 where the pair is
  // evaluated at this entry (j > i, or a ghost)
  std::vector<int> mirror_;
  // results of the pairs evaluated in one collision_forces call (scratch, no state): per entry
  // the index into pair_hits_ of its contact, or -1 without contact
  struct PairHit {
    ContactKinematics kin;
    ContactForce cf;
  };
  mutable std::vector<int> pair_slot_;
  mutable std::vector<PairHit> pair_hits_;
  // obstacles within reach of each owned solid plus the skin (CSR, ascending obstacle index, the
  // summation order): built with the neighbour list, so that a subcycle does not test every
  // obstacle's box (a floor of 300 teeth made that 3/4 of a dry collapse's time)
  std::vector<int> obs_start_, obs_;
  // world-frame boundary pieces of the pair being evaluated (scratch, no state)
  mutable Boundary scratch_a_, scratch_b_;
};

}  // namespace picdem::dem
