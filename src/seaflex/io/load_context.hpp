// Internal to the model loader: what section loaders share, and the registries that let a
// new body kind, load kind or integrator be added as one function in one file plus one
// line in its registry.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "seaflex/elements/ancf_beam.hpp"
#include "seaflex/elements/ancf_plate.hpp"
#include "seaflex/forces/hydro_matrices.hpp"
#include "seaflex/io/model_loader.hpp"
#include "seaflex/io/yaml_reader.hpp"
#include "seaflex/model/motion.hpp"
#include "seaflex/model/time_signal.hpp"

namespace seaflex::io {

/// The reserved body name of the fixed world frame in marker references.
inline constexpr std::string_view kGroundName = "ground";

/// An imposed motion (load_motion.cpp): motion is null for `free` or an absent key;
/// origin is the point its rotations turn about.
struct MotionEntry {
  std::shared_ptr<const Motion> motion;
  Vec3 origin = Vec3::Zero();
};

struct LoadContext {
  Diagnostics& diag;
  System& system;
  Model& model;
  /// bodies that were named but could not be built: references to them are not
  /// reported again
  std::vector<std::string> failed_bodies;
  /// named markers (markers section) that were read without error, and those with errors
  std::map<std::string, YAML::Node> markers;
  std::vector<std::string> failed_markers;
  /// names of joints and connections, which share the channel namespace
  std::set<std::string> joint_and_connection_names;
  /// where each constraint was defined (name -> mark, key path), for the model check
  std::map<std::string, std::pair<YAML::Mark, std::string>> constraint_origin;
  /// where each connection was defined (name -> mark, key path)
  std::map<std::string, std::pair<YAML::Mark, std::string>> connection_origin;
  /// run once the system is numbered, with its initial state: settings that depend on the
  /// initial geometry (a cylinder's reference length, a rope's free length from its
  /// initial tension) and checks of it; they report problems to diag
  std::vector<std::function<void(const State& s0)>> at_start;
  /// rigid bodies with an imposed motion (body name -> motion, where `motion` was given);
  /// load_bodies adds the prescribing joint once the body is in the system
  struct Prescribed {
    MotionEntry motion;
    YAML::Mark mark;
    Vec3 rest_position;  ///< the body's pose that the motion displaces
    Mat3 rest_orientation;
  };
  std::map<std::string, Prescribed> prescribed;
  /// where each output.channels pattern was given (mark, key path), in order
  std::vector<std::pair<YAML::Mark, std::string>> output_patterns;
  /// run once every body and the hydrodynamics section are read (seabed contact)
  std::vector<std::function<void(LoadContext&)>> after_bodies;
  /// the `hydrodynamics` maps of a line's sections (beam name -> section index, node, key
  /// path), read with the beam's hydrodynamics entry (load_ocean.cpp)
  struct SectionHydrodynamics {
    std::size_t section;
    YAML::Node node;
    std::string path;
  };
  std::map<std::string, std::vector<SectionHydrodynamics>> section_hydrodynamics;

  /// Reads the body name at key: a body of the model, or ground (nullptr with *ground set)
  /// when allow_ground. Reports a dangling reference with a suggestion.
  const Body* body_ref(MapReader& reader, std::string_view key, bool allow_ground, bool* ground);
  /// A marker from a reference at path: the name of a marker of the markers section, or an
  /// inline mapping {body, node | arc_length | position, orientation | axis | euler_zxz}.
  /// nullptr after reporting the problem.
  std::unique_ptr<Marker> marker(const YAML::Node& node, const std::string& path);

  /// Reads the body name at key and returns the body when it exists and is an ANCF beam;
  /// reports a dangling reference (with a suggestion) or a wrong kind otherwise.
  const AncfBeam* beam_ref(MapReader& reader, std::string_view key);
  /// Reads a node reference at key: a whole number, "start" or "end".
  std::optional<int> node_ref(MapReader& reader, std::string_view key, const AncfBeam& beam,
                              Need need);
};

using BodyBuilder =
    std::function<std::unique_ptr<Body>(MapReader& reader, const std::string& name, LoadContext&)>;
using ForceBuilder =
    std::function<std::unique_ptr<Force>(MapReader& reader, const std::string& name, LoadContext&)>;
using IntegratorBuilder =
    std::function<std::function<std::unique_ptr<Integrator>()>(MapReader& reader, LoadContext&)>;

/// body "type" -> builder (load_bodies.cpp)
const std::map<std::string, BodyBuilder>& body_builders();
/// load "type" -> builder (load_loads.cpp)
const std::map<std::string, ForceBuilder>& load_builders();
/// dynamics "integrator" -> builder (load_analysis.cpp)
const std::map<std::string, IntegratorBuilder>& integrator_builders();

/// A frame (columns = axes) from `orientation` [roll, pitch, yaw] (deg), `euler_zxz`
/// [phi, theta, psi] (deg, thesis eq. 136) or, when allow_axis, `axis` [x, y, z] (the z
/// axis; x and y completed); identity when none is given, nullopt after an error.
std::optional<Mat3> read_orientation(MapReader& reader, bool allow_axis);

/// Reads owner's key as a motion (`free` only when allow_free); nullopt after a reported
/// problem.
std::optional<MotionEntry> read_motion(MapReader& owner, std::string_view key,
                                       const Vec3& default_origin, bool allow_free,
                                       LoadContext& ctx);

/// A load's time factor from optional `ramp` or `factor_table` (load_loads.cpp); constant 1
/// when neither is given, nullopt after an error.
std::optional<TimeSignal> read_time_factor(MapReader& reader);

// ANCF plates (load_plate.cpp): the body, its supports, markers at its nodes, pressure
std::unique_ptr<Body> build_ancf_plate(MapReader& reader, const std::string& name, LoadContext&);
std::unique_ptr<Force> build_plate_pressure(MapReader& reader, const std::string& name,
                                            LoadContext& ctx);
/// Attachments on a line (load_attachments.cpp): a clump weight or point buoy, and
/// buoyancy modules over a range of arc length.
std::unique_ptr<Force> build_clump(MapReader& reader, const std::string& name, LoadContext& ctx);
std::unique_ptr<Force> build_buoyancy_modules(MapReader& reader, const std::string& name,
                                              LoadContext& ctx);
/// The plate named by the `body` key of a support, or nullptr (without reporting) when
/// the body is not a plate; *skip is set when the body failed to build and the support
/// is written for a plate (it is then not checked).
const AncfPlate* plate_of(const YAML::Node& support, const LoadContext& ctx, bool* skip);
/// One support of a plate: edges or a node. held: (body, local coordinate) already held.
void load_plate_support(MapReader& reader, const AncfPlate& plate, const YAML::Node& node,
                        std::set<std::pair<std::string, Index>>& held, LoadContext& ctx);
/// A marker at a plate node (`node: n<i>_<j>`), after reporting other keys as errors.
std::unique_ptr<Marker> plate_marker(MapReader& reader, const AncfPlate& plate);

// entries of joints and connections (load_joints.cpp)
/// name, from and to of a joint or connection entry; from and to are read whatever becomes
/// of the name, so their problems are reported too
struct PairEntry {
  std::optional<std::string> name;  ///< nullopt after a reported problem
  YAML::Node from, to;              ///< undefined when missing (reported)
};
/// The `name` of an entry, checked (letters, digits, '_', '-') and unique among names;
/// what = "joint" or "connection" for messages.
/// The longest name of a body, joint, connection or wave probe: 64 characters. Names become
/// output channel names (CSV column headers) and file names (statics_partial.<beam>.envelope
/// .csv), which file systems limit to 255 bytes.
inline constexpr std::size_t kMaxNameLength = 64;
/// "" for a valid name: 1 to kMaxNameLength letters, digits, '_' and '-' (no comma, quote,
/// newline or '.', which would break a CSV header or a channel name); otherwise the message.
/// what: "body", "joint", "wave probe"; channel: an example of the channel ("<body>.n0.x").
std::string name_problem(const std::string& name, std::string_view what, std::string_view channel);
/// The key to report a name at: "parent.name", or parent alone when the name is too long
/// or holds control characters (a newline would split the message).
std::string name_key(std::string_view parent, const std::string& name);
std::optional<std::string> read_entry_name(MapReader& r, std::set<std::string>& names,
                                           const char* what);
PairEntry read_pair(MapReader& r, std::set<std::string>& names, const char* what);
/// The markers of an entry (nullptr where missing or after a reported problem).
std::pair<std::unique_ptr<Marker>, std::unique_ptr<Marker>> read_markers(MapReader& r,
                                                                         const PairEntry& e,
                                                                         LoadContext& ctx);
/// true or false only (absent: false; nullopt after a reported problem).
std::optional<bool> read_bool(MapReader& r, std::string_view key);

/// The densest material (osmium, 22,590 kg/m^3) with a margin for lumped masses: 30,000
/// kg/m^3. A larger structural density is a unit mistake (a unit weight in N/m^3).
inline constexpr double kMaxDensity = 30000.0;
/// Unit mistakes in the material of a beam or plate, reported at youngs_modulus or density:
/// a modulus in GPa or MPa (below 1e4 Pa), a density in t/m^3 (below 100 kg/m^3) or a unit
/// weight in N/m^3 (above kMaxDensity). False when any.
bool check_material(MapReader& r, std::optional<double> E, std::optional<double> rho);

void load_bodies(const YAML::Node& node, LoadContext& ctx);
void load_markers(const YAML::Node& node, LoadContext& ctx);
void load_joints(const YAML::Node& node, LoadContext& ctx);
void load_connections(const YAML::Node& node, LoadContext& ctx);
void load_supports(const YAML::Node& node, LoadContext& ctx);
void load_loads(const YAML::Node& node, LoadContext& ctx);
void load_statics(const YAML::Node& node, LoadContext& ctx);
/// environment.water, waves, current, wave_probes (load_ocean.cpp); g = |gravity|
void load_water(MapReader& env, LoadContext& ctx, double g);
/// environment.seabed (load_seabed.cpp), after load_water: its contact forces are added
/// through ctx.after_bodies
void load_seabed(MapReader& env, LoadContext& ctx);
/// hydrodynamics.<body>.bem (load_bem.cpp): adds the BEM forces, and A(inf) and the
/// hydrostatic matrix to set
void load_bem(MapReader& bem, const RigidBody& body, HydroMatrixSet& set, LoadContext& ctx);
/// the hydrodynamics section (load_ocean.cpp)
void load_hydrodynamics(const YAML::Node& node, LoadContext& ctx);
void load_dynamics(const YAML::Node& node, LoadContext& ctx);
/// the output section (load_output.cpp); check_output, once the system is finalized,
/// reports channel patterns that match no channel
void load_output(const YAML::Node& node, LoadContext& ctx);
void check_output(LoadContext& ctx);
/// the statistics section (load_statistics.cpp), after the dynamics section
void load_statistics(const YAML::Node& node, LoadContext& ctx);
/// the fatigue and code_check sections (load_design.cpp)
void load_fatigue(const YAML::Node& node, LoadContext& ctx);
void load_code_check(const YAML::Node& node, LoadContext& ctx);

/// keys of a registry, for messages
template <class Map>
std::vector<std::string> keys_of(const Map& map) {
  std::vector<std::string> keys;
  for (const auto& kv : map) keys.push_back(kv.first);
  return keys;
}

}  // namespace seaflex::io
