#pragma once
/// \file
/// The DEM engine: particles, walls, contacts and one time step, all
/// templated, one source for 2D and 3D.
///
///   Law          contact law between particles (contact/concept.hpp)
///   Space        Kokkos execution space the kernels run in
///   Integrator   time integration policy (integrate/central_difference.hpp)
///   Controller   wall controller policy: by default VelocityControl (walls keep
///                the velocity they are given; control/velocity.hpp), or a
///                servo or dead load (servo/servo.hpp)
///   WallLaw      contact law between particles and walls
///   Dim          Dim2 (disks of thickness t, segment walls) or Dim3 (spheres,
///                plates, periodic axes): Geometry<Dim>, core/geometry2.hpp
///                and core/geometry3.hpp. The laws are given in their 2D
///                names; the engine takes their form in Dim (in_dimension).
///
/// One step (PFC's cycle), each part in a room of its own:
///   - the contact list, rebuilt once a particle has moved half the skin
///     (core/contact_list.hpp);
///   - the contact forces from the positions at t and the velocities at
///     t - dt/2 (core/force_pass.hpp);
///   - per particle, the forces summed in a fixed order, the wall contacts,
///     and the motion advanced (core/sum_and_advance.hpp);
///   - the rigid bodies advanced from their members (core/body_set.hpp);
///   - the wall loads summed in a fixed order, the controllers, the walls
///     moved (core/wall_set.hpp).
///
/// Ensembles: the particles may belong to several specimens
/// (ParticleSet::specimen) that share every kernel launch but never interact:
/// contacts are searched within a specimen only, and each wall belongs to one
/// specimen and touches only its particles. Every sum runs in the order a
/// specimen alone would use, so each specimen follows exactly the trajectory
/// of its own single run.
#include <vrut/contact/composite.hpp>
#include <vrut/contact/concept.hpp>
#include <vrut/control/velocity.hpp>
#include <vrut/core/assignment.hpp>
#include <vrut/core/body_set.hpp>
#include <vrut/core/contact_bonds.hpp>
#include <vrut/core/contact_list.hpp>
#include <vrut/core/force_pass.hpp>
#include <vrut/core/geometry2.hpp>
#include <vrut/core/geometry3.hpp>
#include <vrut/core/instability.hpp>
#include <vrut/core/particles_from_set.hpp>
#include <vrut/core/settings.hpp>
#include <vrut/core/sum_and_advance.hpp>
#include <vrut/core/time_step.hpp>
#include <vrut/core/wall_set.hpp>
#include <vrut/integrate/central_difference.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace vrut {

template <class LawSpec, class Space = Kokkos::DefaultExecutionSpace, class Integrator = CentralDifference,
          class Controller = VelocityControl, class WallLawSpec = Linear, class Dim = Dim2>
class Simulation {
 public:
  using dimension = Dim;
  /// The laws' forms in this dimension (the same types in 2D).
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
  using walls_type = WallSet<Dim, WallLaw, Controller, Space>;
  using wall_type = typename walls_type::wall_type;
  using wall_load_type = WallLoadIn<Dim>;
  using settings_type = SimulationSettingsIn<Dim>;
  using particles_type = Particles<memory_space, Dim>;
  using bodies_type = Bodies<memory_space, Dim>;
  using law_type = Law;
  using params_type = typename Law::params_type;
  using wall_params_type = typename WallLaw::params_type;
  using integrator_params = typename Integrator::params_type;
  using controller_params = typename Controller::params_type;

  Simulation(const ParticleSet& set, const AssignmentTable<LawSpec>& table, const settings_type& settings = {},
             const integrator_params& integrator = {}, const execution_space& space = execution_space())
      : space_(space), settings_(settings), integrator_(integrator), particles_(set.size()),
        law_params_("law_params", table.groups(), table.groups()), max_law_stiffness_(table.max_stiffness()) {
    const ParticlesFromSet from_set = fill_particles(set, table.groups(), settings.thickness, particles_);
    specimen_begin_host_ = from_set.specimen_begin;
    specimen_begin_ = from_set.specimen_begin_view<memory_space>();
    body_set_.build(set, particles_);
    int largest = 0;  // the wall loads are summed in blocks of the largest specimen
    for (int s = 0; s < specimens(); ++s)
      largest = std::max(largest, specimen_begin_host_[s + 1] - specimen_begin_host_[s]);
    walls_.blocks = (largest + walls_type::reduce_block - 1) / walls_type::reduce_block;
    contacts_.specimens = specimens();
    contacts_.box = settings_.box;
    if (settings_.skin < 0.0) settings_.skin = 0.2 * from_set.largest_radius;
    largest_diameter_ = 2.0 * from_set.largest_radius;

    scales_.pair_stiffness = upload_table<Law>(table, law_params_);
    scales_.lightest_contact_mass = body_set_.lightest_contact_mass;
    walls_.rebuild(space_, static_cast<int>(particles_.size()), specimens());
  }

  /// --- set-up ---------------------------------------------------------------
  /// Adds a wall that touches the particles of one specimen (0 in a single run).
  int add_wall(const wall_type& wall, const wall_params_type& params, const controller_params& control = {},
               int specimen = 0) {
    const int w = walls_.add(space_, wall, params, control, specimen, specimens(), static_cast<int>(particles_.size()));
    scales_.wall_stiffness = walls_.stiffness;
    return w;
  }
  int specimens() const { return static_cast<int>(specimen_begin_host_.size()) - 1; }
  /// Particles [first, second) belong to specimen s.
  std::pair<int, int> specimen_range(int s) const { return {specimen_begin_host_.at(s), specimen_begin_host_.at(s + 1)}; }
  int wall_specimen(int w) const { return walls_.specimen_host.at(w); }
  void set_controller(int w, const controller_params& control) { walls_.set_control(w, control); }
  void set_wall_velocity(int w, vector v) { walls_.set_velocity(w, v); }
  int walls() const { return walls_.size(); }
  void set_integrator(const integrator_params& p) { integrator_ = p; }

  /// Bonds every particle pair whose gap is at most tolerance (m). Returns the count.
  int bond_touching_contacts(double tolerance) {
    rebuild_contacts();
    return vrut::bond_touching_contacts<Law>(space_, particles_, contacts_, settings_.box, tolerance);
  }
  /// Bonds the given particle pairs (each i != j), and only those, e.g. the
  /// initially touching pairs of a specimen. Returns how many were in contact
  /// range and got a bond.
  int bond_pairs(const std::vector<std::pair<int, int>>& pairs) {
    rebuild_contacts();
    return vrut::bond_pairs<Law>(space_, contacts_, pairs);
  }

  /// sqrt(m_min / k_max): the time scale of the lightest particle on the
  /// stiffest spring. Multiply by a safety factor (0.1 to 0.3 for dense
  /// packings). With rigid bodies, the time scale of the contacts that exist
  /// instead (contact_timestep): a member's mass is its body's, and a stiff
  /// spring between heavy bodies does not set the step of the light disks.
  double critical_timestep() const {
    if (body_count() > 0) return contact_timestep();
    const double mmin = lightest_mass(space_, particles_.mass);
    const double k = std::max(max_law_stiffness_, walls_.stiffness);
    if (!(k > 0.0)) throw std::logic_error("vrut::Simulation: no positive contact stiffness");
    return std::sqrt(mmin / k);
  }
  /// The smallest sqrt(m / k) over the springs that can act (core/time_step.hpp).
  double contact_timestep() const { return scales_.contact_timestep(); }
  /// contact_timestep's terms, each spring's own; empty without bodies
  /// (critical_timestep then takes the lightest particle on the stiffest spring).
  std::vector<SpringStep> spring_steps() const {
    return body_count() > 0 ? scales_.spring_steps() : std::vector<SpringStep>{};
  }

  /// --- rigid bodies ---------------------------------------------------------
  int body_count() const { return static_cast<int>(body_set_.bodies.size()); }
  bodies_type& bodies() { return body_set_.bodies; }
  const bodies_type& bodies() const { return body_set_.bodies; }
  /// Sets body b's velocity and angular velocity, and its members' with it.
  void set_body_motion(int b, vector velocity, spin angular_velocity) {
    body_set_.set_motion(b, velocity, angular_velocity);
    place_members();
  }
  /// Puts every member where its body says, with the body's motion there.
  void place_members() { vrut::place_members(space_, particles_, body_set_.bodies); }

  /// --- running --------------------------------------------------------------
  void step(double dt) {
    if (!(dt > 0.0)) throw std::invalid_argument("vrut::Simulation: dt must be positive");
    // The list is rebuilt once a particle has moved half the skin, so one
    // that has moved more than that plus a diameter jumped a diameter in one
    // step: through its neighbours, which only a blown-up run does. A
    // position that is not finite counts as such a jump. The check costs
    // nothing: the displacement is measured every step anyway.
    const double moved = contacts_.builds == 0 ? 0.0 : contacts_.max_displacement(space_, particles_);
    if (!(moved <= 0.5 * settings_.skin + largest_diameter_)) report_instability(dt);
    if (contacts_.builds == 0 || moved > 0.5 * settings_.skin) rebuild_contacts();
    if (dt != prepared_dt_) prepare_laws(dt);
    contact_forces<Law>(space_, particles_, contacts_, law_params_, settings_.box, dt);
    sum_and_advance<Integrator, WallLaw>(space_, particles_, contacts_, walls_, settings_.gravity, integrator_, dt);
    if (body_count() > 0) advance_bodies<Integrator>(space_, particles_, body_set_.bodies, integrator_, dt);
    walls_.move(space_, specimen_begin_, dt);
    time_ += dt;
    ++steps_;
  }
  // Throws SimulationUnstable (core/instability.hpp) naming the step that
  // blew up (the last one done) and the first particle that jumped.
  [[noreturn]] void report_instability(double dt) const {
    throw_instability<Dim>(particles_, contacts_.position_at_build, 0.5 * settings_.skin + largest_diameter_, steps_,
                           time_, dt, critical_timestep());
  }

  /// Lets the law work out, once per time step size, what depends only on its
  /// parameters and dt (contact/concept.hpp, prepare); the results are the same.
  void prepare_laws(double dt) {
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), law_params_);
    for (std::size_t a = 0; a < h.extent(0); ++a)
      for (std::size_t b = 0; b < h.extent(1); ++b) prepare_law<Law>(h(a, b), dt);
    Kokkos::deep_copy(law_params_, h);
    prepared_dt_ = dt;
  }

  /// Forces a contact-list rebuild now (it happens by itself when particles
  /// have moved more than half the skin).
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

  // Wall w where it is now; every wall, in one copy from the device; the
  // loads; and the time integral of each load since the wall was added (N s:
  // the mean load over an interval is the difference of two readings over
  // its length).
  wall_type wall(int w) { return walls_.at(w); }
  const std::vector<wall_type>& all_walls() { return walls_.all(); }
  wall_load_type wall_load(int w) const { return walls_.load_of(w); }
  vector wall_impulse(int w) const { return walls_.impulses().at(w); }
  std::vector<vector> all_wall_impulses() const { return walls_.impulses(); }
  /// Counts of touching (or bonded) contacts and of intact bonds, in all
  /// specimens or in one.
  int active_contacts(int specimen = -1) const { return count(false, specimen); }
  int intact_bonds(int specimen = -1) const { return count(true, specimen); }

  /// --- checkpoints ----------------------------------------------------------
  /// Everything that changes while the simulation runs, item by item, for a
  /// checkpoint: a.view(name, v), a.value(name, x) and a.vector(name, v) each
  /// write one item or read it back (io/checkpoint.hpp has both archives), so
  /// one list serves both ways. Read into a Simulation built the same way
  /// (particles, table, settings, walls), it goes on bit for bit as the one
  /// written would have. What the construction fixes (masses, the law table,
  /// the wall owners) is not written; the cell grid is rebuilt with the list.
  template <class Archive>
  void visit_state(Archive& a) {
    visit_particles(a, particles_);
    body_set_.visit(a);
    contacts_.visit(a);
    walls_.visit(a);
    a.value("integrator", integrator_);
    a.value("time", time_);
    a.value("steps", steps_);
  }

 private:
  int count(bool bonds_only, int specimen) const {
    if (contacts_.builds == 0) return 0;
    const int first = specimen < 0 ? 0 : specimen_range(specimen).first;
    const int last = specimen < 0 ? static_cast<int>(particles_.size()) : specimen_range(specimen).second;
    return count_contacts<Law>(space_, particles_, contacts_, settings_.box, bonds_only, first, last);
  }

  execution_space space_;
  settings_type settings_;
  integrator_params integrator_;
  particles_type particles_;
  BodySet<memory_space, Dim> body_set_;
  SpringScales scales_;
  Kokkos::View<params_type**, memory_space> law_params_;
  double max_law_stiffness_ = 0.0, largest_diameter_ = 0.0;
  ContactList<Law, execution_space, Dim> contacts_;
  walls_type walls_;
  std::vector<int> specimen_begin_host_;
  Kokkos::View<int*, memory_space> specimen_begin_;
  double time_ = 0.0, prepared_dt_ = 0.0;
  long steps_ = 0;
};

/// The engine in 3D: spheres, rectangular plates (Wall3), periodic axes.
template <class Law, class Space = Kokkos::DefaultExecutionSpace, class Integrator = CentralDifference,
          class Controller = VelocityControl, class WallLaw = Linear>
using Simulation3 = Simulation<Law, Space, Integrator, Controller, WallLaw, Dim3>;
using SimulationSettings3 = SimulationSettingsIn<Dim3>;

}  // namespace vrut
