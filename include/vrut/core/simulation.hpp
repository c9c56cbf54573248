#pragma once
// The DEM engine: particles, walls, contacts and one time step, all
// templated, one source for 2D and 3D.
//
//   Law          contact law between particles (contact/concept.hpp)
//   Space        Kokkos execution space the kernels run in
//   Integrator   time integration policy (integrate/central_difference.hpp)
//   Controller   wall controller policy: by default VelocityControl (walls keep
//                the velocity they are given; control/velocity.hpp), or a
//                servo or dead load (servo/servo.hpp)
//   WallLaw      contact law between particles and walls
//   Dim          Dim2 (disks of thickness t, segment walls) or Dim3 (spheres,
//                rectangular plates, periodic axes); data/dimension.hpp.
//                The laws are given in their 2D names; the engine takes
//                their form in Dim (in_dimension, contact/concept.hpp).
//
// In 3D a contact's stored shear turns with it (contact/geometry3.hpp): over
// a step the normal turns from the one the pair had a step ago, which the
// leapfrog gives exactly, d(t - dt) = d(t) - dt (v_j - v_i), and the pair
// spins about the mean of the two normals by dt times its mean angular
// velocity there.
//
// One step (PFC's cycle): contact forces from the positions at t and the
// velocities at t - dt/2; per disk, the forces summed in a fixed order and
// the motion advanced; the wall loads summed in a fixed order; the
// controllers set the wall velocities; the walls move.
//
// Rigid bodies (data/bodies.hpp, ParticleSet::body): a member disk's
// contact forces and moments are summed as any disk's, but the disk does not
// advance: its body sums its members' loads in a fixed order, advances, and
// places them again. Two members of one body never touch.
//
// Ensembles: the disks may belong to several specimens (ParticleSet::specimen)
// that share every kernel launch but never interact: contacts are searched
// within a specimen only, and each wall belongs to one specimen and touches
// only its disks. Every sum runs in the order a specimen alone would use, so
// each specimen follows exactly the trajectory of its own single run.
#include <vrut/contact/composite.hpp>
#include <vrut/contact/concept.hpp>
#include <vrut/contact/geometry3.hpp>
#include <vrut/control/velocity.hpp>
#include <vrut/core/assignment.hpp>
#include <vrut/core/contact_list.hpp>
#include <vrut/data/bodies.hpp>
#include <vrut/data/dimension.hpp>
#include <vrut/data/particle_set.hpp>
#include <vrut/data/particles.hpp>
#include <vrut/data/walls.hpp>
#include <vrut/data/walls3.hpp>
#include <vrut/geometry/clump3.hpp>
#include <vrut/integrate/central_difference.hpp>
#include <vrut/neighbor/periodic_box3.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace vrut {

// A run that blew up: some disk jumped more than a diameter in one step, or
// its position is no longer finite.
class SimulationUnstable : public std::runtime_error {
 public:
  SimulationUnstable(const std::string& what, long step) : std::runtime_error(what), step_(step) {}
  long step() const { return step_; }  // the step (counted from 1) that made it so

 private:
  long step_;
};

template <class D>
struct SimulationSettingsIn {
  double thickness = 1.0;     // 2D: out-of-plane disk width t, m: mass = rho pi r^2 t (3D: rho 4/3 pi r^3)
  typename D::vector gravity;  // m/s^2
  double skin = -1.0;         // neighbour-list margin, m; < 0: 0.2 * the largest radius
  // 3D: the box, and which of its axes are periodic (none by default).
  PeriodicBox<D> box;
};
using SimulationSettings = SimulationSettingsIn<Dim2>;

template <class LawSpec, class Space = Kokkos::DefaultExecutionSpace, class Integrator = CentralDifference,
          class Controller = VelocityControl, class WallLawSpec = Linear, class Dim = Dim2>
class Simulation {
 public:
  using dimension = Dim;
  // The laws' forms in this dimension (the same types in 2D).
  using Law = in_dimension_t<LawSpec, Dim>;
  using WallLaw = in_dimension_t<WallLawSpec, Dim>;
  static_assert(check_contact_law<Law>(), "vrut::Simulation: Law is not a contact law (see above)");
  static_assert(check_contact_law<WallLaw>(), "vrut::Simulation: WallLaw is not a contact law (see above)");
  static_assert(std::is_same_v<law_dimension_t<Law>, Dim> && std::is_same_v<law_dimension_t<WallLaw>, Dim>,
                "vrut::Simulation: a law has no form in this dimension: a 3D law declares `using dimension = "
                "Dim3;`, or is composed of slots that are templates on their dimension (LinearShearIn<D>)");
  static_assert(std::is_same_v<typename Law::params_type, typename LawSpec::params_type>,
                "vrut::Simulation: a law's 3D form must take its 2D form's parameters");

  using execution_space = Space;
  using memory_space = typename Space::memory_space;
  using vector = typename Dim::vector;
  using spin = typename Dim::spin;
  using wall_type = std::conditional_t<is_3d<Dim>, Wall3, Wall>;
  using wall_load_type = WallLoadIn<Dim>;
  using settings_type = SimulationSettingsIn<Dim>;
  using particles_type = Particles<typename Space::memory_space, Dim>;
  using bodies_type = Bodies<typename Space::memory_space, Dim>;
  using law_type = Law;
  using params_type = typename Law::params_type;
  using wall_params_type = typename WallLaw::params_type;
  using wall_state_type = typename WallLaw::state_type;
  using integrator_params = typename Integrator::params_type;
  using controller_params = typename Controller::params_type;
  using controller_state = typename Controller::state_type;
  using WallMask = unsigned long long;
  static constexpr int max_walls_per_specimen = 64;

  Simulation(const ParticleSet& set, const AssignmentTable<LawSpec>& table, const settings_type& settings = {},
             const integrator_params& integrator = {}, const execution_space& space = execution_space())
      : space_(space), settings_(settings), integrator_(integrator), particles_(set.size()),
        law_params_("law_params", table.groups(), table.groups()), max_law_stiffness_(table.max_stiffness()) {
    if (set.size() == 0) throw std::invalid_argument("vrut::Simulation: no particles");
    if (!is_3d<Dim> && !(settings.thickness > 0.0))
      throw std::invalid_argument("vrut::Simulation: thickness must be positive");
    if (is_3d<Dim> && set.z.size() != set.size())
      throw std::invalid_argument("vrut::Simulation: a 3D simulation needs a z for every particle (ParticleSet::z)");
    const int n = static_cast<int>(set.size());
    auto h = Kokkos::create_mirror_view(particles_.position);
    auto hr = Kokkos::create_mirror_view(particles_.radius);
    auto hm = Kokkos::create_mirror_view(particles_.mass);
    auto hi = Kokkos::create_mirror_view(particles_.inertia);
    auto hg = Kokkos::create_mirror_view(particles_.group);
    auto hs = Kokkos::create_mirror_view(particles_.specimen);
    if (!set.specimen.empty() && set.specimen.size() != set.size())
      throw std::invalid_argument("vrut::Simulation: the specimen index list has the wrong length");
    if (!set.body.empty() && set.body.size() != set.size())
      throw std::invalid_argument("vrut::Simulation: the body index list has the wrong length");
    specimen_begin_host_.assign(1, 0);
    double rmax = 0.0;
    for (int i = 0; i < n; ++i) {
      if (set.group[i] >= table.groups())
        throw std::invalid_argument("vrut::Simulation: disk " + std::to_string(i) + " has group " +
                                    std::to_string(set.group[i]) + " but the table has " +
                                    std::to_string(table.groups()) + " groups");
      if constexpr (is_3d<Dim>) {
        h(i) = {set.x[i], set.y[i], set.z[i]};
        hm(i) = set.density[i] * (4.0 / 3.0 * 3.14159265358979323846) * set.radius[i] * set.radius[i] * set.radius[i];
        hi(i) = 0.4 * hm(i) * set.radius[i] * set.radius[i];
      } else {
        h(i) = {set.x[i], set.y[i]};
        hm(i) = set.density[i] * 3.14159265358979323846 * set.radius[i] * set.radius[i] * settings.thickness;
        hi(i) = 0.5 * hm(i) * set.radius[i] * set.radius[i];
      }
      hr(i) = set.radius[i];
      hg(i) = set.group[i];
      hs(i) = set.specimen.empty() ? 0 : set.specimen[i];
      const int previous = i == 0 ? 0 : hs(i - 1);
      if (hs(i) != previous && hs(i) != previous + 1)
        throw std::invalid_argument("vrut::Simulation: disk " + std::to_string(i) + " has specimen " +
                                    std::to_string(hs(i)) + " after " + std::to_string(previous) +
                                    " (each specimen's disks must be contiguous, in order from 0)");
      if (hs(i) != previous) specimen_begin_host_.push_back(i);
      rmax = std::max(rmax, set.radius[i]);
    }
    specimen_begin_host_.push_back(n);
    int largest = 0;  // the wall loads are summed in blocks of the largest specimen
    for (int s = 0; s < specimens(); ++s)
      largest = std::max(largest, specimen_begin_host_[s + 1] - specimen_begin_host_[s]);
    wall_blocks_ = (largest + reduce_block - 1) / reduce_block;
    Kokkos::deep_copy(particles_.position, h);
    Kokkos::deep_copy(particles_.radius, hr);
    Kokkos::deep_copy(particles_.mass, hm);
    Kokkos::deep_copy(particles_.inertia, hi);
    Kokkos::deep_copy(particles_.group, hg);
    Kokkos::deep_copy(particles_.specimen, hs);
    build_bodies(set, h, hm, hi, hs);
    specimen_begin_ = Kokkos::View<int*, memory_space>("specimen_begin", specimen_begin_host_.size());
    {
      auto hb = Kokkos::create_mirror_view(specimen_begin_);
      for (std::size_t k = 0; k < specimen_begin_host_.size(); ++k) hb(k) = specimen_begin_host_[k];
      Kokkos::deep_copy(specimen_begin_, hb);
    }
    contacts_.specimens = specimens();
    contacts_.box = settings_.box;
    if (settings_.skin < 0.0) settings_.skin = 0.2 * rmax;
    largest_diameter_ = 2.0 * rmax;

    auto hp = Kokkos::create_mirror_view(law_params_);
    pair_stiffness_.assign(static_cast<std::size_t>(table.groups()) * table.groups(), -1.0);
    for (int a = 0; a < table.groups(); ++a)
      for (int b = 0; b < table.groups(); ++b)
        if (table.is_set(a, b)) {
          hp(a, b) = table(a, b);
          pair_stiffness_[static_cast<std::size_t>(a) * table.groups() + b] = Law::stiffness(table(a, b));
        }
    Kokkos::deep_copy(law_params_, hp);
    rebuild_walls(0);
  }

  // --- set-up ---------------------------------------------------------------
  // Adds a wall that touches the disks of one specimen (0 in a single run).
  int add_wall(const wall_type& wall, const wall_params_type& params, const controller_params& control = {},
               int specimen = 0) {
    if constexpr (is_3d<Dim>) {
      const double u = norm(wall.half_u), v = norm(wall.half_v);
      if (!(area(wall) > 0.0) || !(std::abs(dot(wall.half_u, wall.half_v)) <= 1e-12 * u * v))
        throw std::invalid_argument("vrut::Simulation: a plate needs two orthogonal half-edges of nonzero length");
    } else if (!(length(wall) > 0.0)) {
      throw std::invalid_argument("vrut::Simulation: a wall needs two distinct ends");
    }
    if (specimen < 0 || specimen >= specimens())
      throw std::invalid_argument("vrut::Simulation: wall for specimen " + std::to_string(specimen) + ", but there are " +
                                  std::to_string(specimens()));
    pull_walls();  // the device holds where the existing walls have moved to
    const int w = static_cast<int>(walls_host_.size());
    walls_host_.push_back(wall);
    wall_params_host_.push_back(params);
    control_host_.push_back(control);
    wall_specimen_host_.push_back(specimen);
    wall_stiffness_ = std::max(wall_stiffness_, static_cast<double>(WallLaw::stiffness(params)));
    rebuild_walls(w + 1);
    return w;
  }
  int specimens() const { return static_cast<int>(specimen_begin_host_.size()) - 1; }
  // Disks [first, second) belong to specimen s.
  std::pair<int, int> specimen_range(int s) const { return {specimen_begin_host_.at(s), specimen_begin_host_.at(s + 1)}; }
  int wall_specimen(int w) const { return wall_specimen_host_.at(w); }
  void set_controller(int w, const controller_params& control) {
    pull_walls();
    control_host_.at(w) = control;
    push_walls();
  }
  void set_wall_velocity(int w, vector v) {
    pull_walls();
    walls_host_.at(w).velocity = v;
    push_walls();
  }
  int walls() const { return static_cast<int>(walls_host_.size()); }
  void set_integrator(const integrator_params& p) { integrator_ = p; }

  // Bonds every disk pair whose gap is at most tolerance (m). Returns the count.
  int bond_touching_contacts(double tolerance) {
    contacts_.rebuild(space_, particles_, settings_.skin);
    auto ps = particles_;
    auto partner = contacts_.partner;
    auto count = contacts_.count;
    auto state = contacts_.state;
    const auto box = settings_.box;
    int bonded = 0;
    Kokkos::parallel_reduce("vrut::bond", Kokkos::RangePolicy<execution_space>(space_, 0, ps.size()),
        KOKKOS_LAMBDA(const int i, int& sum) {
          for (int k = 0; k < count(i); ++k) {
            const int j = partner(i, k);
            const double gap = norm(box.separation(ps.position(i), ps.position(j))) - ps.radius(i) - ps.radius(j);
            if (gap <= tolerance) {
              make_bonded<Law>(state(i, k));
              if (is_bonded<Law>(state(i, k))) ++sum;
            }
          }
        },
        bonded);
    return bonded;
  }

  // Bonds the given disk pairs (each i != j), and only those, e.g. the
  // initially touching pairs of a specimen. Returns how many were in contact
  // range and got a bond.
  int bond_pairs(const std::vector<std::pair<int, int>>& pairs) {
    contacts_.rebuild(space_, particles_, settings_.skin);
    Kokkos::View<int* [2], memory_space> dev("bond_pairs", pairs.size());
    auto host = Kokkos::create_mirror_view(dev);
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      host(k, 0) = std::min(pairs[k].first, pairs[k].second);
      host(k, 1) = std::max(pairs[k].first, pairs[k].second);
    }
    Kokkos::deep_copy(dev, host);
    auto partner = contacts_.partner;
    auto count = contacts_.count;
    auto state = contacts_.state;
    int bonded = 0;
    Kokkos::parallel_reduce("vrut::bond_pairs", Kokkos::RangePolicy<execution_space>(space_, 0, pairs.size()),
        KOKKOS_LAMBDA(const int k, int& sum) {
          const int i = dev(k, 0), j = dev(k, 1);
          for (int q = 0; q < count(i); ++q)
            if (partner(i, q) == j) {
              make_bonded<Law>(state(i, q));
              if (is_bonded<Law>(state(i, q))) ++sum;
            }
        },
        bonded);
    return bonded;
  }

  // sqrt(m_min / k_max): the time scale of the lightest disk on the stiffest
  // spring. Multiply by a safety factor (0.1 to 0.3 for dense packings).
  // With rigid bodies, the time scale of the contacts that exist instead
  // (contact_timestep): a member's mass is its body's, and a stiff spring
  // between heavy bodies does not set the step of the light disks.
  double critical_timestep() const {
    if (bodies_.size() > 0) return contact_timestep();
    auto m = particles_.mass;
    double mmin = 0.0;
    Kokkos::parallel_reduce("vrut::min_mass", Kokkos::RangePolicy<execution_space>(space_, 0, m.extent(0)),
        KOKKOS_LAMBDA(const int i, double& a) { if (m(i) < a) a = m(i); }, Kokkos::Min<double>(mmin));
    const double k = std::max(max_law_stiffness_, wall_stiffness_);
    if (!(k > 0.0)) throw std::logic_error("vrut::Simulation: no positive contact stiffness");
    return std::sqrt(mmin / k);
  }

  // The smallest sqrt(m / k) over the springs that can act: for each two
  // material groups present, the table's stiffness over the lighter of the
  // two groups' lightest masses; for the walls, their stiffest spring over
  // the lightest mass of any group. A disk's mass is its own; a member's is
  // 1 / (1 / M + d^2 / I), its body's mass M as felt at its centre, d from
  // the body's (a normal force acts through the member's centre).
  double contact_timestep() const {
    const int groups = static_cast<int>(std::lround(std::sqrt(static_cast<double>(pair_stiffness_.size()))));
    auto lightest = [&](int g) {
      return g < static_cast<int>(lightest_contact_mass_.size()) ? lightest_contact_mass_[g] : 0.0;
    };
    double worst = 0.0;  // largest k / m
    double mall = 0.0;
    for (int a = 0; a < groups; ++a) {
      if (!(lightest(a) > 0.0)) continue;
      mall = mall > 0.0 ? std::min(mall, lightest(a)) : lightest(a);
      for (int b = 0; b < groups; ++b) {
        const double k = pair_stiffness_[static_cast<std::size_t>(a) * groups + b];
        if (lightest(b) > 0.0 && k > 0.0) worst = std::max(worst, k / std::min(lightest(a), lightest(b)));
      }
    }
    if (wall_stiffness_ > 0.0) worst = std::max(worst, wall_stiffness_ / mall);
    if (!(worst > 0.0)) throw std::logic_error("vrut::Simulation: no positive contact stiffness");
    return 1.0 / std::sqrt(worst);
  }

  // contact_timestep's terms, each spring's own sqrt(m / k): for each two
  // groups present (a <= b) and for the walls (a = b = -1). The step is the
  // smallest; the others say how far each trails it. Empty without bodies
  // (critical_timestep then takes the lightest particle on the stiffest spring).
  struct SpringStep {
    int group_a = -1, group_b = -1;
    double step = 0.0;
  };
  std::vector<SpringStep> spring_steps() const {
    std::vector<SpringStep> out;
    if (bodies_.size() == 0) return out;
    const int groups = static_cast<int>(std::lround(std::sqrt(static_cast<double>(pair_stiffness_.size()))));
    auto lightest = [&](int g) {
      return g < static_cast<int>(lightest_contact_mass_.size()) ? lightest_contact_mass_[g] : 0.0;
    };
    double mall = 0.0;
    for (int a = 0; a < groups; ++a) {
      if (!(lightest(a) > 0.0)) continue;
      mall = mall > 0.0 ? std::min(mall, lightest(a)) : lightest(a);
      for (int b = a; b < groups; ++b) {
        const double k = pair_stiffness_[static_cast<std::size_t>(a) * groups + b];
        if (lightest(b) > 0.0 && k > 0.0) out.push_back({a, b, 1.0 / std::sqrt(k / std::min(lightest(a), lightest(b)))});
      }
    }
    if (wall_stiffness_ > 0.0 && mall > 0.0) out.push_back({-1, -1, 1.0 / std::sqrt(wall_stiffness_ / mall)});
    return out;
  }

  // --- rigid bodies ---------------------------------------------------------
  int body_count() const { return static_cast<int>(bodies_.size()); }
  bodies_type& bodies() { return bodies_; }
  const bodies_type& bodies() const { return bodies_; }
  // Sets body b's velocity and angular velocity, and its members' with it
  // (in 3D the angular momentum that gives that angular velocity).
  void set_body_motion(int b, vector velocity, spin angular_velocity) {
    if (b < 0 || b >= body_count()) throw std::invalid_argument("vrut::Simulation: no body " + std::to_string(b));
    auto v = Kokkos::subview(bodies_.velocity, b);
    auto w = Kokkos::subview(bodies_.angular_velocity, b);
    Kokkos::deep_copy(v, velocity);
    Kokkos::deep_copy(w, angular_velocity);
    if constexpr (is_3d<Dim>) {
      Quaternion q;
      Vec3 inertia;
      Kokkos::deep_copy(q, Kokkos::subview(bodies_.rotation, b));
      Kokkos::deep_copy(inertia, Kokkos::subview(bodies_.inertia, b));
      // L = q I (q* w q) q*: the world-frame angular momentum.
      const Vec3 momentum = rotate(q, times_each(inertia, rotate_back(q, angular_velocity)));
      Kokkos::deep_copy(Kokkos::subview(bodies_.angular_momentum, b), momentum);
    }
    place_members();
  }
  // Puts every member where its body says, with the body's motion at that
  // point: x = X + R offset, v = V + omega x (R offset).
  void place_members() {
    if (bodies_.size() == 0) return;
    auto ps = particles_;
    auto bs = bodies_;
    Kokkos::parallel_for("vrut::place_members", Kokkos::RangePolicy<execution_space>(space_, 0, bs.size()),
        KOKKOS_LAMBDA(const int b) { place_members_of(ps, bs, b); });
  }
  KOKKOS_INLINE_FUNCTION static void place_members_of(const particles_type& ps, const bodies_type& bs, int b) {
    const vector X = bs.position(b), V = bs.velocity(b);
    const typename Dim::orientation theta = bs.rotation(b);
    const spin w = bs.angular_velocity(b);
    for (int k = bs.member_begin(b); k < bs.member_begin(b + 1); ++k) {
      const int i = bs.member(k);
      vector off, turning;  // the offset in the world frame, and the body's velocity there less V
      if constexpr (is_3d<Dim>) {
        off = rotate(theta, bs.offset(k));
        turning = cross(w, off);
      } else {
        off = rotated(bs.offset(k), theta);
        turning = w * perp(off);
      }
      const vector x = X + off;
      ps.displacement(i) += x - ps.position(i);
      ps.position(i) = x;
      ps.velocity(i) = V + turning;
      ps.angular_velocity(i) = w;
      ps.rotation(i) = theta;
    }
  }

  // --- running --------------------------------------------------------------
  void step(double dt) {
    if (!(dt > 0.0)) throw std::invalid_argument("vrut::Simulation: dt must be positive");
    // The list is rebuilt once a disk has moved half the skin, so a disk that
    // has moved more than that plus a diameter jumped a diameter in one step:
    // through its neighbours, which only a blown-up run does. A position that
    // is not finite counts as such a jump. The check costs nothing: the
    // displacement is measured every step anyway.
    const double moved = contacts_.builds == 0 ? 0.0 : contacts_.max_displacement(space_, particles_);
    if (!(moved <= 0.5 * settings_.skin + largest_diameter_)) report_instability(dt);
    if (contacts_.builds == 0 || moved > 0.5 * settings_.skin) contacts_.rebuild(space_, particles_, settings_.skin);
    if (dt != prepared_dt_) prepare_laws(dt);
    contact_forces(dt);
    sum_and_advance(dt);
    if (bodies_.size() > 0) advance_bodies(dt);
    move_walls(dt);
    time_ += dt;
    ++steps_;
  }
  // Throws SimulationUnstable naming the step that blew up (the last one
  // done), the first disk that jumped, and the time step against the critical one.
  [[noreturn]] void report_instability(double dt) const {
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles_.position);
    auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), contacts_.position_at_build);
    auto s = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles_.specimen);
    const double limit = 0.5 * settings_.skin + largest_diameter_;
    std::size_t bad = 0, count = 0;
    for (std::size_t i = x.extent(0); i-- > 0;)
      if (!(norm(x(i) - x0(i)) <= limit)) bad = i, ++count;
    const double critical = critical_timestep();
    char text[512];
    char where[96];
    if constexpr (is_3d<Dim>)
      std::snprintf(where, sizeof where, "sphere %zu (specimen %d), now at (%.4g, %.4g, %.4g) m", bad, s(bad),
                    x(bad).x, x(bad).y, x(bad).z);
    else
      std::snprintf(where, sizeof where, "disk %zu (specimen %d), now at (%.4g, %.4g) m", bad, s(bad), x(bad).x,
                    x(bad).y);
    std::snprintf(text, sizeof text,
                  "vrut: the simulation became unstable at step %ld (t = %.4g s): %s, and %zu more jumped more than "
                  "a diameter in one step or are not finite. The time step %.4g s is %.3g of sqrt(m_min / k_max) = "
                  "%.4g s; dense packings need 0.1 to 0.3 of it.",
                  steps_, time_, where, count - 1, dt, dt / critical, critical);
    throw SimulationUnstable(text, steps_);
  }

  // Lets the law work out, once per time step size, what depends only on its
  // parameters and dt (contact/concept.hpp, prepare); the results are the same.
  void prepare_laws(double dt) {
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), law_params_);
    for (std::size_t a = 0; a < h.extent(0); ++a)
      for (std::size_t b = 0; b < h.extent(1); ++b) prepare_law<Law>(h(a, b), dt);
    Kokkos::deep_copy(law_params_, h);
    prepared_dt_ = dt;
  }

  // Forces a contact-list rebuild now (it happens by itself when disks have
  // moved more than half the skin).
  void rebuild_contacts() { contacts_.rebuild(space_, particles_, settings_.skin); }
  void run(long steps, double dt) {
    for (long s = 0; s < steps; ++s) step(dt);
  }

  // --- reading --------------------------------------------------------------
  particles_type& particles() { return particles_; }
  const particles_type& particles() const { return particles_; }
  const ContactList<Law, execution_space, Dim>& contacts() const { return contacts_; }
  double time() const { return time_; }
  long steps() const { return steps_; }
  const settings_type& settings() const { return settings_; }
  const execution_space& space() const { return space_; }

  wall_type wall(int w) {
    pull_walls();
    return walls_host_.at(w);
  }
  // Every wall where it is now, in one copy from the device.
  const std::vector<wall_type>& all_walls() {
    pull_walls();
    return walls_host_;
  }
  std::vector<vector> all_wall_impulses() const {
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), wall_impulse_);
    return std::vector<vector>(h.data(), h.data() + h.extent(0));
  }
  wall_load_type wall_load(int w) const {
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), wall_total_);
    return h(w);
  }
  // Time integral of the load on wall w since it was added (N s): the mean
  // load over an interval is the difference of two readings over its length.
  vector wall_impulse(int w) const {
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), wall_impulse_);
    return h(w);
  }
  // Counts of touching (or bonded) contacts and of intact bonds, in all
  // specimens or in one.
  int active_contacts(int specimen = -1) const { return count_contacts(false, specimen); }
  int intact_bonds(int specimen = -1) const { return count_contacts(true, specimen); }

  // --- checkpoints ----------------------------------------------------------
  // Everything that changes while the simulation runs, item by item, for a
  // checkpoint: a.view(name, v), a.value(name, x) and a.vector(name, v) each
  // write one item or read it back (io/checkpoint.hpp has both archives), so
  // one list serves both ways. Read into a Simulation built the same way
  // (disks, table, settings, walls), it goes on bit for bit as the one
  // written would have. What the construction fixes (masses, the law table,
  // the wall owners) is not written; the cell grid is rebuilt with the list.
  template <class Archive>
  void visit_state(Archive& a) {
    pull_walls();
    const std::size_t nwalls = walls_host_.size();
    auto& p = particles_;
    a.view("position", p.position);
    a.view("velocity", p.velocity);
    a.view("force", p.force);
    a.view("external_force", p.external_force);
    a.view("displacement", p.displacement);
    a.view("rotation", p.rotation);
    a.view("angular_velocity", p.angular_velocity);
    a.view("moment", p.moment);
    a.view("fixity", p.fixity);
    if (bodies_.size() > 0) {  // only then: checkpoints without bodies stay as they were
      a.view("body_position", bodies_.position);
      a.view("body_velocity", bodies_.velocity);
      a.view("body_force", bodies_.force);
      a.view("body_rotation", bodies_.rotation);
      a.view("body_angular_velocity", bodies_.angular_velocity);
      a.view("body_moment", bodies_.moment);
      if constexpr (is_3d<Dim>) a.view("body_angular_momentum", bodies_.angular_momentum);
    }
    a.view("contact_partner", contacts_.partner);
    a.view("contact_count", contacts_.count);
    a.view("contact_state", contacts_.state);
    a.view("contact_load", contacts_.load);
    a.view("contact_reverse", contacts_.reverse);
    a.view("contact_reverse_count", contacts_.reverse_count);
    a.view("position_at_build", contacts_.position_at_build);
    a.value("contact_capacity", contacts_.capacity);
    a.value("contact_reverse_capacity", contacts_.reverse_capacity);
    a.value("contact_most_partners", contacts_.most_partners);
    a.value("contact_most_reverse", contacts_.most_reverse);
    a.value("contact_builds", contacts_.builds);
    a.vector("walls", walls_host_);
    a.vector("wall_control", control_host_);
    if (walls_host_.size() != nwalls || control_host_.size() != nwalls)
      throw std::invalid_argument("vrut::Simulation: the checkpoint has " + std::to_string(walls_host_.size()) +
                                  " walls, this simulation " + std::to_string(nwalls));
    a.view("wall_control_state", control_state_);
    a.view("wall_state", wall_state_);
    a.view("wall_load", wall_load_);
    a.view("wall_touch", wall_touch_);
    a.view("wall_total", wall_total_);
    a.view("wall_impulse", wall_impulse_);
    a.value("integrator", integrator_);
    a.value("time", time_);
    a.value("steps", steps_);
    push_walls();
  }

  // --- kernels (public only because device lambdas cannot be private) -----
  void contact_forces(double dt) {
    auto ps = particles_;
    auto partner = contacts_.partner;
    auto count = contacts_.count;
    auto state = contacts_.state;
    auto load = contacts_.load;
    auto params = law_params_;
    const auto box = settings_.box;
    Kokkos::parallel_for("vrut::contact_forces", Kokkos::RangePolicy<execution_space>(space_, 0, ps.size()),
        KOKKOS_LAMBDA(const int i) {
          for (int k = 0; k < count(i); ++k) {
            const int j = partner(i, k);
            const vector d = box.separation(ps.position(i), ps.position(j));
            // In 3D a pair apart is found without a square root (most listed pairs are).
            if (is_3d<Dim> && dot(d, d) >= (ps.radius(i) + ps.radius(j)) * (ps.radius(i) + ps.radius(j)) &&
                !is_bonded<Law>(state(i, k))) {
              state(i, k) = typename Law::state_type{};
              load(i, k) = ContactLoadIn<Dim>{};
              continue;
            }
            const double dist = norm(d);
            ContactGeometryIn<Dim> g;
            g.normal = (1.0 / dist) * d;
            g.overlap = ps.radius(i) + ps.radius(j) - dist;
            if (g.overlap <= 0.0 && !is_bonded<Law>(state(i, k))) {
              state(i, k) = typename Law::state_type{};
              load(i, k) = ContactLoadIn<Dim>{};
              continue;
            }
            load(i, k) = particle_contact(params(ps.group(i), ps.group(j)), state(i, k), g, d, ps, i, j, dt);
          }
        });
  }

  // The contact of particles i and j, d their separation, g's normal and
  // overlap set. (The dimension is chosen here, not in the kernel: nvcc
  // refuses a lambda that first captures a variable inside `if constexpr`.)
  KOKKOS_INLINE_FUNCTION static ContactLoadIn<Dim> particle_contact(const params_type& p, typename Law::state_type& s,
                                                                    ContactGeometryIn<Dim>& g, vector d,
                                                                    const particles_type& ps, int i, int j, double dt) {
    if constexpr (is_3d<Dim>)
      return sphere_contact(p, s, g, d, ps, i, j, dt);
    else
      return disk_contact(p, s, g, ps, i, j, dt);
  }

  // What a law reads of a pair besides its motion: dt, the radii and, for a
  // law that reads them, the masses the contact moves.
  KOKKOS_INLINE_FUNCTION static void describe_pair(ContactGeometryIn<Dim>& g, const particles_type& ps, int i, int j,
                                                   double dt) {
    g.dt = dt;
    g.radius_1 = ps.radius(i);
    g.radius_2 = ps.radius(j);
    if constexpr (law_uses_mass<Law>()) {
      g.mass_1 = ps.contact_mass(i);
      g.mass_2 = ps.contact_mass(j);
    }
  }

  // A 2D contact between disks i and j, g's normal and overlap set: the
  // increments, the law, and the load.
  KOKKOS_INLINE_FUNCTION static ContactLoadIn<Dim> disk_contact(const params_type& p, typename Law::state_type& s,
                                                                ContactGeometryIn<Dim>& g, const particles_type& ps,
                                                                int i, int j, double dt) {
    const Vec2 t = perp(g.normal);
    // Lever arms to the contact point, the middle of the overlap.
    const double arm_i = ps.radius(i) - 0.5 * g.overlap, arm_j = ps.radius(j) - 0.5 * g.overlap;
    const Vec2 v_rel = (ps.velocity(j) - (ps.angular_velocity(j) * arm_j) * t) -
                       (ps.velocity(i) + (ps.angular_velocity(i) * arm_i) * t);
    g.normal_increment = -dot(v_rel, g.normal) * dt;
    g.shear_increment = dot(v_rel, t) * dt;
    describe_pair(g, ps, i, j, dt);
    const ContactForceIn<Dim> f = Law::force(p, s, g);
    ContactLoadIn<Dim> l;
    l.force = f.normal * g.normal + f.shear * t;
    l.moment_first = -arm_i * f.shear;
    l.moment_second = -arm_j * f.shear;
    return l;
  }

  // A 3D contact between spheres i and j, their separation d (through the
  // nearest image) and g's normal and overlap set: the stored shear turned
  // into the contact's new frame, the increments, the law, and the load.
  KOKKOS_INLINE_FUNCTION static ContactLoadIn<Dim> sphere_contact(const params_type& p, typename Law::state_type& s,
                                                                  ContactGeometryIn<Dim>& g, Vec3 d,
                                                                  const particles_type& ps, int i, int j, double dt) {
    const double arm_i = ps.radius(i) - 0.5 * g.overlap, arm_j = ps.radius(j) - 0.5 * g.overlap;
    const Vec3 w_i = ps.angular_velocity(i), w_j = ps.angular_velocity(j);
    const Vec3 v_rel = (ps.velocity(j) + cross(w_j, -arm_j * g.normal)) - (ps.velocity(i) + cross(w_i, arm_i * g.normal));
    // The leapfrog moved the centres by dt v: a step ago they were d - dt (v_j - v_i) apart.
    // The pair's mean spin about the step's mean normal (second order):
    // |n + n'| = sqrt(2 (1 + n . n')).
    const Vec3 before = d - dt * (ps.velocity(j) - ps.velocity(i));
    const double before_length = norm(before);
    if (before_length > 0.0) {
      const Vec3 old_normal = (1.0 / before_length) * before, mid = old_normal + g.normal;
      const double mid_length = sqrt(2.0 * (1.0 + dot(old_normal, g.normal)));
      const double twist = mid_length > 0.0 ? 0.5 * dt * dot(w_i + w_j, mid) / mid_length : 0.0;
      turn_history<Law>(s, ContactTurn(old_normal, g.normal, twist));
    }
    const double along = dot(v_rel, g.normal);
    g.normal_increment = -along * dt;
    g.shear_increment = dt * (v_rel - along * g.normal);
    describe_pair(g, ps, i, j, dt);
    const ContactForceIn<Dim> f = Law::force(p, s, g);
    ContactLoadIn<Dim> l;
    l.force = f.normal * g.normal + f.shear;
    // The force on j acts at -arm_j n from its centre, its reaction on i at +arm_i n.
    l.moment_first = cross(arm_i * g.normal, -l.force);
    l.moment_second = cross(-arm_j * g.normal, l.force);
    return l;
  }

  void sum_and_advance(double dt) {
    auto ps = particles_;
    auto count = contacts_.count;
    auto load = contacts_.load;
    auto rev = contacts_.reverse;
    auto rcount = contacts_.reverse_count;
    const int cap = contacts_.capacity;
    auto wall_view = walls_;
    auto wnormal = wall_normal_;
    auto wparams = wall_params_;
    auto wstate = wall_state_;
    auto wload = wall_load_;
    auto wtouch = wall_touch_;
    auto swalls = specimen_walls_;
    auto swall_count = specimen_wall_count_;
    const vector gravity = settings_.gravity;
    const integrator_params integrator = integrator_;
    Kokkos::parallel_for("vrut::sum_and_advance", Kokkos::RangePolicy<execution_space>(space_, 0, ps.size()),
        KOKKOS_LAMBDA(const int i) {
          vector f = ps.external_force(i) + ps.mass(i) * gravity;
          spin m{};
          for (int k = 0; k < count(i); ++k) {
            f -= load(i, k).force;
            m += load(i, k).moment_first;
          }
          for (int q = 0; q < rcount(i); ++q) {
            const int c = rev(i, q);
            const ContactLoadIn<Dim>& l = load(c / cap, c % cap);
            f += l.force;
            m += l.moment_second;
          }
          // The walls of this disk's specimen, by slot: (disk, slot) indexes the wall state and load.
          // A slot whose bit in wall_touch is clear holds the default state
          // and a zero load: most disks touch no wall, and skipping their
          // slots saves most of the memory traffic the walls would cost.
          const int sp = ps.specimen(i);
          const WallMask held = wtouch(i);
          WallMask holds = 0;
          for (int q = 0; q < swall_count(sp); ++q) {
            const int w = swalls(sp, q);
            // In 3D, a cheap look first: most spheres are far from every plate.
            if (is_3d<Dim> && !((held >> q) & 1u) &&
                !reaches_wall(wall_view(w), wnormal(w), ps.position(i), ps.radius(i)))
              continue;
            ContactGeometryIn<Dim> g;
            const double dist = wall_distance(wall_view(w), ps.position(i), g.normal);
            g.overlap = ps.radius(i) - dist;
            if (g.overlap <= 0.0 && !((held >> q) & 1u)) continue;
            if (g.overlap <= 0.0 && !is_bonded<WallLaw>(wstate(i, q))) {
              wstate(i, q) = wall_state_type{};
              wload(i, q) = wall_load_type{};
              continue;
            }
            holds |= WallMask(1) << q;
            const WallPush push = wall_contact(wparams(w), wstate(i, q), g, wall_view(w).velocity, ps, i, dt);
            f += push.force;
            m -= push.lever;
            wall_load_type wl;
            wl.force = -push.force;
            wl.contacts = g.overlap > 0.0 ? 1.0 : 0.0;
            wload(i, q) = wl;
          }
          wtouch(i) = holds;
          ps.force(i) = f;
          ps.moment(i) = m;
          if (ps.body(i) < 0) Integrator::advance(integrator, ps, i, f, m, dt);  // a member moves with its body
        });
  }

  // Whether a particle (centre c, radius r) may reach wall w, of inward
  // unit normal n; in 2D the distance below decides alone. In 3D a sphere
  // farther from the plate's plane than r cannot reach it (one dot
  // product); for one nearer, wall_distance measures the plate's edges too.
  KOKKOS_INLINE_FUNCTION static bool reaches_wall(const wall_type& w, vector n, vector c, double r) {
    if constexpr (is_3d<Dim>) {
      const double height = dot(c - w.centre, n);
      return height < r && height > -r;
    } else {
      return (void)w, (void)n, (void)c, (void)r, true;
    }
  }

  // A wall's push on a particle: the force, and the lever whose negative is
  // its moment about the particle's centre.
  struct WallPush {
    vector force;
    spin lever;
  };
  // The contact of particle i (the second body) with a wall (the first, at
  // rest but for its velocity), g's normal (wall -> particle) and overlap
  // set; the contact point lies on the wall, arm = r - overlap from the centre.
  KOKKOS_INLINE_FUNCTION static WallPush wall_contact(const wall_params_type& p, wall_state_type& s,
                                                      ContactGeometryIn<Dim>& g, vector wall_velocity,
                                                      const particles_type& ps, int i, double dt) {
    const double arm = ps.radius(i) - g.overlap;
    g.dt = dt;
    g.radius_1 = 0.0;
    g.radius_2 = ps.radius(i);
    if constexpr (law_uses_mass<WallLaw>()) g.mass_2 = ps.contact_mass(i);  // mass_1 = 0: a wall
    if constexpr (is_3d<Dim>) {
      const Vec3 w = ps.angular_velocity(i);
      const Vec3 v_rel = ps.velocity(i) + cross(w, -arm * g.normal) - wall_velocity;
      // A plate does not turn: the frame turns only as the sphere spins about the normal.
      turn_history<WallLaw>(s, ContactTurn(g.normal, g.normal, 0.5 * dt * dot(w, g.normal)));
      const double along = dot(v_rel, g.normal);
      g.normal_increment = -along * dt;
      g.shear_increment = dt * (v_rel - along * g.normal);
      const ContactForceIn<Dim> cf = WallLaw::force(p, s, g);
      return {cf.normal * g.normal + cf.shear, arm * cross(g.normal, cf.shear)};
    } else {
      const Vec2 t = perp(g.normal);
      const Vec2 v_rel = ps.velocity(i) - (ps.angular_velocity(i) * arm) * t - wall_velocity;
      g.normal_increment = -dot(v_rel, g.normal) * dt;
      g.shear_increment = dot(v_rel, t) * dt;
      const ContactForceIn<Dim> cf = WallLaw::force(p, s, g);
      return {cf.normal * g.normal + cf.shear * t, arm * cf.shear};
    }
  }

  // Each body sums its members' forces and their moments about its centre,
  // in the members' order, advances, and places its members again.
  void advance_bodies(double dt) {
    auto ps = particles_;
    auto bs = bodies_;
    const integrator_params integrator = integrator_;
    Kokkos::parallel_for("vrut::advance_bodies", Kokkos::RangePolicy<execution_space>(space_, 0, bs.size()),
        KOKKOS_LAMBDA(const int b) {
          const vector X = bs.position(b);
          vector f;
          spin m{};
          for (int k = bs.member_begin(b); k < bs.member_begin(b + 1); ++k) {
            const int i = bs.member(k);
            f += ps.force(i);
            m += ps.moment(i) + cross(ps.position(i) - X, ps.force(i));
          }
          bs.force(b) = f;
          bs.moment(b) = m;
          Integrator::advance_body(integrator, bs, b, f, m, dt);
          place_members_of(ps, bs, b);
        });
  }

  // Wall loads summed in fixed blocks of the wall's specimen, then the blocks
  // in order, so the sum does not depend on the backend nor on the other
  // specimens; then the controllers and the motion.
  static constexpr int reduce_block = 512;
  void move_walls(double dt) {
    const int nwalls = walls();
    if (nwalls == 0) return;
    const int blocks = wall_blocks_;
    if (block_load_.extent(0) != static_cast<std::size_t>(blocks) || block_load_.extent(1) != static_cast<std::size_t>(nwalls))
      block_load_ = Kokkos::View<wall_load_type**, memory_space>("wall_block_load", blocks, nwalls);
    auto bl = block_load_;
    auto wload = wall_load_;
    auto wtouch = wall_touch_;
    auto begin = specimen_begin_;
    auto owner = wall_specimen_;
    auto slot = wall_slot_;
    Kokkos::parallel_for("vrut::wall_blocks",
        Kokkos::RangePolicy<execution_space>(space_, 0, blocks * nwalls), KOKKOS_LAMBDA(const int bw) {
          const int b = bw / nwalls, w = bw % nwalls;
          const int first = begin(owner(w)), last = begin(owner(w) + 1), q = slot(w);
          wall_load_type sum;
          const int end = first + (b + 1) * reduce_block < last ? first + (b + 1) * reduce_block : last;
          // Clear bits stand for zero loads: skipping them leaves the sum bit for bit the same.
          for (int i = first + b * reduce_block; i < end; ++i)
            if ((wtouch(i) >> q) & 1u) sum += wload(i, q);
          bl(b, w) = sum;
        });
    auto wall_view = walls_;
    auto total = wall_total_;
    auto impulse = wall_impulse_;
    auto control = control_;
    auto control_state = control_state_;
    Kokkos::parallel_for("vrut::move_walls", Kokkos::RangePolicy<execution_space>(space_, 0, nwalls),
        KOKKOS_LAMBDA(const int w) {
          wall_load_type sum;
          const int own_blocks = (begin(owner(w) + 1) - begin(owner(w)) + reduce_block - 1) / reduce_block;
          for (int b = 0; b < own_blocks; ++b) sum += bl(b, w);
          total(w) = sum;
          impulse(w) += dt * sum.force;
          wall_type wall = wall_view(w);
          Controller::control(control(w), control_state(w), wall, sum, dt);
          translate(wall, dt * wall.velocity);
          wall_view(w) = wall;
        });
  }

  int count_contacts(bool bonds_only, int specimen = -1) const {
    auto ps = particles_;
    auto partner = contacts_.partner;
    auto count = contacts_.count;
    auto state = contacts_.state;
    const auto box = settings_.box;
    int total = 0;
    if (contacts_.builds == 0) return 0;
    const int first = specimen < 0 ? 0 : specimen_range(specimen).first;
    const int last = specimen < 0 ? static_cast<int>(ps.size()) : specimen_range(specimen).second;
    Kokkos::parallel_reduce("vrut::count_contacts", Kokkos::RangePolicy<execution_space>(space_, first, last),
        KOKKOS_LAMBDA(const int i, int& sum) {
          for (int k = 0; k < count(i); ++k) {
            const bool bonded = is_bonded<Law>(state(i, k));
            const int j = partner(i, k);
            const bool touching = norm(box.separation(ps.position(i), ps.position(j))) < ps.radius(i) + ps.radius(j);
            if (bonds_only ? bonded : (bonded || touching)) ++sum;
          }
        },
        total);
    return total;
  }

  // Public only because device lambdas cannot live in private members (nvcc).
  void rebuild_walls(int nwalls) {
    const int n = static_cast<int>(particles_.size());
    // Each specimen's walls get slots 0, 1, ... in the order they were added.
    const int nspec = specimens();
    std::vector<int> slots_used(nspec, 0), slot_of(nwalls);
    for (int w = 0; w < nwalls; ++w) slot_of[w] = slots_used[wall_specimen_host_[w]]++;
    const int slots = nspec > 0 ? *std::max_element(slots_used.begin(), slots_used.end()) : 0;
    if (slots > max_walls_per_specimen)
      throw std::invalid_argument("vrut::Simulation: more than " + std::to_string(max_walls_per_specimen) +
                                  " walls for one specimen");
    if (wall_touch_.extent(0) != static_cast<std::size_t>(n)) wall_touch_ = Kokkos::View<WallMask*, memory_space>("wall_touch", n);
    wall_specimen_ = Kokkos::View<int*, memory_space>("wall_specimen", nwalls);
    wall_slot_ = Kokkos::View<int*, memory_space>("wall_slot", nwalls);
    specimen_walls_ = Kokkos::View<int**, memory_space>("specimen_walls", nspec, slots);
    specimen_wall_count_ = Kokkos::View<int*, memory_space>("specimen_wall_count", nspec);
    {
      auto hs = Kokkos::create_mirror_view(wall_specimen_);
      auto hq = Kokkos::create_mirror_view(wall_slot_);
      auto hw = Kokkos::create_mirror_view(specimen_walls_);
      auto hc = Kokkos::create_mirror_view(specimen_wall_count_);
      for (int w = 0; w < nwalls; ++w) {
        hs(w) = wall_specimen_host_[w];
        hq(w) = slot_of[w];
        hw(hs(w), hq(w)) = w;
      }
      for (int s = 0; s < nspec; ++s) hc(s) = slots_used[s];
      Kokkos::deep_copy(wall_specimen_, hs);
      Kokkos::deep_copy(wall_slot_, hq);
      Kokkos::deep_copy(specimen_walls_, hw);
      Kokkos::deep_copy(specimen_wall_count_, hc);
    }
    walls_ = Kokkos::View<wall_type*, memory_space>("walls", nwalls);
    wall_normal_ = Kokkos::View<vector*, memory_space>("wall_normal", nwalls);
    wall_params_ = Kokkos::View<wall_params_type*, memory_space>("wall_params", nwalls);
    control_ = Kokkos::View<controller_params*, memory_space>("wall_control", nwalls);
    Kokkos::View<controller_state*, memory_space> control_state("wall_control_state", nwalls);
    if (control_state_.extent(0) > 0)
      Kokkos::deep_copy(Kokkos::subview(control_state, std::make_pair(std::size_t(0), control_state_.extent(0))),
                        control_state_);
    control_state_ = control_state;
    wall_total_ = Kokkos::View<wall_load_type*, memory_space>("wall_total", nwalls);
    wall_impulse_ = Kokkos::View<vector*, memory_space>("wall_impulse", nwalls);
    // Contact state with walls: keep what the existing walls had (a new wall
    // takes a new slot of its specimen, so the existing slots keep their walls).
    Kokkos::View<wall_state_type**, memory_space> state("wall_state", n, slots);
    if (wall_state_.extent(1) > 0) {
      auto old = wall_state_;
      const int kept = static_cast<int>(old.extent(1));
      Kokkos::parallel_for("vrut::keep_wall_state", Kokkos::RangePolicy<execution_space>(space_, 0, n),
          KOKKOS_LAMBDA(const int i) { for (int w = 0; w < kept; ++w) state(i, w) = old(i, w); });
    }
    wall_state_ = state;
    wall_load_ = Kokkos::View<wall_load_type**, memory_space>("wall_load", n, slots);
    block_load_ = {};
    push_walls();
  }
 private:
  // Bodies from ParticleSet::body, on the host mirrors of the particles'
  // centres, masses, inertias and specimens: each body's mass is its
  // members', its centre their centre of mass, its inertia theirs about it
  // (in 3D its principal moments and axes, geometry/clump3.hpp). A body's
  // members are given where they lie together, not wrapped across a
  // periodic face.
  template <class HostVector, class HostDouble, class HostInt>
  void build_bodies(const ParticleSet& set, const HostVector& x, const HostDouble& mass, const HostDouble& inertia,
                    const HostInt& specimen) {
    const int n = static_cast<int>(set.size());
    auto hcm = Kokkos::create_mirror_view(particles_.contact_mass);
    for (int i = 0; i < n; ++i) hcm(i) = mass(i);
    const int nb = set.bodies();
    lightest_contact_mass_.clear();
    std::vector<std::vector<int>> members(nb);
    for (int i = 0; i < n && !set.body.empty(); ++i)
      if (set.body[i] >= 0) members[set.body[i]].push_back(i);
    std::size_t total = 0;
    for (int b = 0; b < nb; ++b) {
      if (members[b].empty()) throw std::invalid_argument("vrut::Simulation: body " + std::to_string(b) + " has no member");
      total += members[b].size();
    }
    std::vector<double> member_mass(n, 0.0);
    if (nb > 0) {
      bodies_ = bodies_type(nb, total);
      auto hx = Kokkos::create_mirror_view(bodies_.position);
      auto hm = Kokkos::create_mirror_view(bodies_.mass);
      auto hi = Kokkos::create_mirror_view(bodies_.inertia);
      auto hbegin = Kokkos::create_mirror_view(bodies_.member_begin);
      auto hmember = Kokkos::create_mirror_view(bodies_.member);
      auto hoff = Kokkos::create_mirror_view(bodies_.offset);
      auto hbody = Kokkos::create_mirror_view(particles_.body);
      auto hq = Kokkos::create_mirror_view(bodies_.rotation);
      Kokkos::deep_copy(hbody, -1);
      int slot = 0;
      for (int b = 0; b < nb; ++b) {
        for (int i : members[b])
          if (specimen(i) != specimen(members[b].front()))
            throw std::invalid_argument("vrut::Simulation: body " + std::to_string(b) + " has members in two specimens");
        hbegin(b) = slot;
        if constexpr (is_3d<Dim>) {
          std::vector<Vec3> centres;
          std::vector<double> radii, masses;
          for (int i : members[b]) centres.push_back(x(i)), radii.push_back(set.radius[i]), masses.push_back(mass(i));
          const ClumpProperties3 c = clump_properties_of_masses(centres, radii, masses);
          hx(b) = c.centre, hm(b) = c.mass, hi(b) = c.principal_moments, hq(b) = c.orientation;
          for (std::size_t k = 0; k < members[b].size(); ++k) {
            const int i = members[b][k];
            hmember(slot) = i;
            hoff(slot) = c.offsets[k];
            hbody(i) = b;
            hcm(i) = c.mass;
            // The body as felt at the member's centre, for the time step.
            member_mass[i] = mass_felt_at_member(c, c.offsets[k]);
            ++slot;
          }
        } else {
          double M = 0.0, mx = 0.0, my = 0.0;
          for (int i : members[b]) M += mass(i), mx += mass(i) * x(i).x, my += mass(i) * x(i).y;
          const Vec2 X{mx / M, my / M};
          double I = 0.0;
          for (int i : members[b]) I += inertia(i) + mass(i) * dot(x(i) - X, x(i) - X);
          hx(b) = X, hm(b) = M, hi(b) = I;
          for (int i : members[b]) {
            hmember(slot) = i;
            hoff(slot) = x(i) - X;
            hbody(i) = b;
            hcm(i) = M;
            // The body as felt at the member's centre, for the time step.
            member_mass[i] = 1.0 / (1.0 / M + dot(x(i) - X, x(i) - X) / I);
            ++slot;
          }
        }
      }
      hbegin(nb) = slot;
      Kokkos::deep_copy(bodies_.rotation, hq);
      Kokkos::deep_copy(bodies_.position, hx);
      Kokkos::deep_copy(bodies_.mass, hm);
      Kokkos::deep_copy(bodies_.inertia, hi);
      Kokkos::deep_copy(bodies_.member_begin, hbegin);
      Kokkos::deep_copy(bodies_.member, hmember);
      Kokkos::deep_copy(bodies_.offset, hoff);
      Kokkos::deep_copy(particles_.body, hbody);
    }
    Kokkos::deep_copy(particles_.contact_mass, hcm);
    // Each group's lightest mass a contact moves (0: the group is absent).
    int groups = 0;
    for (int g : set.group) groups = std::max(groups, g + 1);
    lightest_contact_mass_.assign(groups, 0.0);
    for (int i = 0; i < n; ++i) {
      const double m = nb > 0 && !set.body.empty() && set.body[i] >= 0 ? member_mass[i] : mass(i);
      double& l = lightest_contact_mass_[set.group[i]];
      l = l > 0.0 ? std::min(l, m) : m;
    }
  }

  void push_walls() {
    const int nwalls = walls();
    // A wall's normal: walls translate (move_walls) but never turn, so it
    // stays as it is computed here.
    auto hn = Kokkos::create_mirror_view(wall_normal_);
    for (int w = 0; w < nwalls; ++w) hn(w) = inward_normal(walls_host_[w]);
    Kokkos::deep_copy(wall_normal_, hn);
    auto hw = Kokkos::create_mirror_view(walls_);
    auto hp = Kokkos::create_mirror_view(wall_params_);
    auto hc = Kokkos::create_mirror_view(control_);
    for (int w = 0; w < nwalls; ++w) {
      hw(w) = walls_host_[w];
      hp(w) = wall_params_host_[w];
      hc(w) = control_host_[w];
    }
    Kokkos::deep_copy(walls_, hw);
    Kokkos::deep_copy(wall_params_, hp);
    Kokkos::deep_copy(control_, hc);
  }
  void pull_walls() {
    if (walls_host_.empty()) return;
    auto hw = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), walls_);
    for (int w = 0; w < walls(); ++w) walls_host_[w] = hw(w);
  }

  execution_space space_;
  settings_type settings_;
  integrator_params integrator_;
  particles_type particles_;
  bodies_type bodies_;
  std::vector<double> pair_stiffness_;         // groups x groups, the table's stiffness (-1: not set)
  std::vector<double> lightest_contact_mass_;  // per group (0: absent)
  Kokkos::View<params_type**, memory_space> law_params_;
  double max_law_stiffness_ = 0.0, wall_stiffness_ = 0.0, largest_diameter_ = 0.0;
  int wall_blocks_ = 0;
  ContactList<Law, execution_space, Dim> contacts_;

  std::vector<wall_type> walls_host_;
  std::vector<wall_params_type> wall_params_host_;
  std::vector<controller_params> control_host_;
  std::vector<int> wall_specimen_host_, specimen_begin_host_;
  Kokkos::View<int*, memory_space> specimen_begin_, wall_specimen_, wall_slot_, specimen_wall_count_;
  Kokkos::View<int**, memory_space> specimen_walls_;
  Kokkos::View<wall_type*, memory_space> walls_;
  Kokkos::View<vector*, memory_space> wall_normal_;  // inward, unit
  Kokkos::View<wall_params_type*, memory_space> wall_params_;
  Kokkos::View<controller_params*, memory_space> control_;
  Kokkos::View<controller_state*, memory_space> control_state_;
  Kokkos::View<wall_state_type**, memory_space> wall_state_;
  Kokkos::View<wall_load_type**, memory_space> wall_load_, block_load_;
  Kokkos::View<WallMask*, memory_space> wall_touch_;  // per disk: bit q set where wall slot q holds state or load
  Kokkos::View<wall_load_type*, memory_space> wall_total_;
  Kokkos::View<vector*, memory_space> wall_impulse_;

  double time_ = 0.0, prepared_dt_ = 0.0;
  long steps_ = 0;
};

// The engine in 3D: spheres, rectangular plates (Wall3), periodic axes.
template <class Law, class Space = Kokkos::DefaultExecutionSpace, class Integrator = CentralDifference,
          class Controller = VelocityControl, class WallLaw = Linear>
using Simulation3 = Simulation<Law, Space, Integrator, Controller, WallLaw, Dim3>;
using SimulationSettings3 = SimulationSettingsIn<Dim3>;

}  // namespace vrut
