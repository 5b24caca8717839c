#include "io/config.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/chemistry_config.hpp"
#include "io/config_override.hpp"
#include "io/config_reader.hpp"
#include "io/filament_config.hpp"
#include "io/resolvable_forces.hpp"
#include "io/surface_species_config.hpp"

namespace cortex {
namespace {

SimulationConfig readSimulation(const ConfigReader& r) {
  SimulationConfig s;
  s.seed = r.integer("seed", s.seed, 0, std::numeric_limits<std::int64_t>::max());
  s.end_time = r.number("end_time", s.end_time, Range::nonNegative(), "s");
  s.chemistry_window = r.number("chemistry_window", s.chemistry_window, Range::positive(), "s");
  s.snapshot_interval = r.number("snapshot_interval", s.snapshot_interval, Range::positive(), "s");
  s.checkpoint_interval = r.number("checkpoint_interval", 0.0, Range::nonNegative(), "s");
  s.temperature = r.number("temperature", s.temperature, Range::positive(), "K");
  if (s.end_time > 0 && s.end_time / s.chemistry_window > 1e9)
    r.fail(r.has("end_time") ? "end_time" : "chemistry_window",
           fmt::format("{:g} s in windows of {:g} s (chemistry_window) is more than 1e9 windows", s.end_time,
                       s.chemistry_window));
  r.finish();
  return s;
}

MinimizerSettings readMechanics(const ConfigReader& r) {
  MinimizerSettings m;
  const std::string kind = r.choice("minimizer", "auto", {"auto", "cg", "lbfgs"});
  m.kind = kind == "lbfgs" ? MinimizerKind::kLbfgs
           : kind == "cg"  ? MinimizerKind::kConjugateGradient
                           : MinimizerKind::kAuto;
  m.force_tolerance_given = r.has("force_tolerance");
  m.force_tolerance = r.number("force_tolerance", m.force_tolerance, Range::positive(), "pN");
  m.max_iterations = r.integer("max_iterations", m.max_iterations, 1, 1'000'000'000);
  m.max_step = r.number("max_step", m.max_step, Range::positive(), "nm");
  const std::string filaments = r.choice("filament_minimizer", "cg", {"cg", "preconditioned_lbfgs"});
  if (filaments != "cg" && m.kind != MinimizerKind::kAuto)
    r.fail("filament_minimizer", "applies under minimizer = \"auto\" only (the others relax everything at once)");
  m.precondition_filaments = filaments == "preconditioned_lbfgs";
  r.finish();
  return m;
}

// A generated membrane's area (nm²): exact for spheres and planes, Knud Thomsen's formula
// (within 1.1%) for ellipsoids.
double shapeArea(const MembraneConfig& m) {
  if (m.shape == "plane") return m.size[0] * m.size[1];
  constexpr double p = 1.6075;
  const double a = std::pow(m.radii[0], p), b = std::pow(m.radii[1], p), c = std::pow(m.radii[2], p);
  return 4.0 * constants::kPi * std::pow((a * b + a * c + b * c) / 3.0, 1.0 / p);
}

// The largest generated mesh (vertices): 100 times the largest membrane benchmarked (45k).
constexpr double kMaxGeneratedVertices = 5e6;

void readShape(const ConfigReader& r, MembraneConfig& m, const std::filesystem::path& base_dir) {
  m.shape = r.choice("shape", "sphere", {"sphere", "ellipsoid", "plane", "mesh"});
  const bool generated = m.shape != "mesh";
  const double far = constants::kMaxCoordinate;
  const Range coordinate{-far, far}, extent{0.0, far, true, false};
  if (m.shape != "mesh") {
    const auto c = r.has("center") ? r.numbers("center", 3, coordinate, "nm") : std::vector<double>{0, 0, 0};
    m.center = Vec3(c[0], c[1], c[2]);
  }
  if (m.shape == "sphere") {
    m.radii = Vec3::Constant(r.requiredNumber("radius", extent, "nm"));
    m.mesher = r.choice("mesher", "marching_tetrahedra", {"marching_tetrahedra", "icosphere"});
  } else if (m.shape == "ellipsoid") {
    const auto a = r.numbers("radii", 3, extent, "nm");
    m.radii = Vec3(a[0], a[1], a[2]);
  } else if (m.shape == "plane") {
    const auto s = r.numbers("size", 2, extent, "nm");
    m.size = {s[0], s[1]};
  } else {
    const std::string file = r.string("file", "");
    if (file.empty()) r.fail("file", "is required for shape = \"mesh\" (an .obj or .ply file)");
    m.file = std::filesystem::path(file).is_absolute() ? std::filesystem::path(file) : base_dir / file;
  }
  if (m.shape == "plane" || m.shape == "mesh") r.choice("boundary", "fixed", {"fixed"});
  if (generated) {
    m.mesh_size = r.requiredNumber("mesh_size", Range::positive(), "nm");
    const double smallest = m.shape == "plane" ? std::min(m.size[0], m.size[1]) : m.radii.minCoeff();
    if (m.mesh_size > smallest)
      r.fail("mesh_size", fmt::format("({:g} nm) must not exceed the membrane's smallest "
                                      "radius or side ({:g} nm)", m.mesh_size, smallest));
    // Equilateral triangles of side h: about 2A/(√3 h²) vertices. Past the limit meshing
    // alone takes minutes and gigabytes (a mesh_size in the wrong unit, most likely).
    const double area = shapeArea(m), vertices = 2.0 * area / (std::sqrt(3.0) * m.mesh_size * m.mesh_size);
    if (vertices > kMaxGeneratedVertices)
      r.fail("mesh_size", fmt::format("({:g} nm) would mesh this shape (area {:.3g} nm²) with about {:.3g} vertices, "
                                      "over the limit of {:g}: is it in nm?",
                                      m.mesh_size, area, vertices, kMaxGeneratedVertices));
  } else {
    // A loaded mesh keeps its own triangles; mesh_size only sets the remesher's target
    // on flat parts (default: the file's mean edge length).
    m.mesh_size = r.number("mesh_size", 0.0, Range::positive(), "nm");
  }
}

// The times of the schedules' points, where schedules linear between their points take
// their extremes: a condition on their values holds throughout if it holds at these.
std::vector<double> knots(const std::vector<const Schedule*>& schedules) {
  std::vector<double> times;
  for (const Schedule* s : schedules)
    for (const auto& point : s->points()) times.push_back(point.first);
  return times;
}

// " at t = T s" for a message about time t, unless all the schedules are constant.
std::string atTime(const std::vector<const Schedule*>& schedules, double t) {
  for (const Schedule* s : schedules)
    if (!s->isConstant()) return fmt::format(" at t = {:g} s", t);
  return "";
}

// Each term's parameters into its own struct (membrane.hpp). How area and volume are
// held depends on the minimizer: the default relaxation holds them exactly unless a
// modulus asks for the penalty form; cg and lbfgs have only the penalty forms.
// `protein_curvature`: the name of a membrane species whose proteins carry a spontaneous
// curvature (sensing or generating), empty if none.
// `filaments`: the config has filaments, which may hold a vesicle out from inside.
MembraneMechanics readMechanicsOfMembrane(const ConfigReader& r, const std::string& shape, MinimizerKind minimizer,
                                          const std::string& protein_curvature, bool filaments) {
  MembraneMechanics m;
  // A loaded mesh may be closed or not: volume keys are accepted here and checked once it
  // is read (sim/), and the checks that need it closed are left to the run.
  const bool closed = shape != "plane", surely_closed = shape == "sphere" || shape == "ellipsoid";
  const Range any{};
  const bool by_shape = minimizer == MinimizerKind::kAuto;
  const char* other_minimizer = "[mechanics] minimizer = \"cg\" or \"lbfgs\"";
  BendingParameters& bending = m.bending;
  bending.modulus = r.schedule("bending_modulus", 100.0, Range::nonNegative(), "pN·nm");
  bending.spontaneous_curvature = r.schedule("spontaneous_curvature", 0.0, any, "1/nm");
  // Default as the thesis advises (sec. 2.2.2): the signed estimator where the sign
  // matters (H0 != 0, or proteins with a spontaneous curvature), the unsigned one
  // otherwise, which resists folded vertices.
  const bool signs = !bending.spontaneous_curvature.isZero() || !protein_curvature.empty();
  bending.estimator = r.choice("curvature", signs ? "signed" : "unsigned", {"signed", "unsigned"}) == "signed"
                          ? CurvatureEstimator::kSigned
                          : CurvatureEstimator::kUnsigned;
  if (!bending.spontaneous_curvature.isZero() && bending.estimator == CurvatureEstimator::kUnsigned)
    r.fail("spontaneous_curvature", "needs curvature = \"signed\" (the unsigned estimator has no sign)");
  if (!protein_curvature.empty() && bending.estimator == CurvatureEstimator::kUnsigned)
    r.fail("curvature", fmt::format("must be \"signed\": the proteins of species \"{}\" have a spontaneous "
                                    "curvature (the unsigned estimator has no sign)", protein_curvature));

  // A patch's area is free by default: its lipids come and go through the frame, and a
  // flat one starts at the least area its boundary allows, where the area's gradient has
  // no normal part for an exact constraint to act with (the default "exact" failed on a
  // patch with H0 with non-finite forces). A loaded mesh found open gets the same default
  // (sim/membrane_builder.cpp).
  const char* default_area = by_shape && !r.has("area_modulus") ? (closed ? "exact" : "none") : "global";
  const std::string model = r.choice("area_model", default_area, {"exact", "global", "per_vertex", "none"});
  m.area.model = model == "exact"        ? AreaModel::kExact
                 : model == "global"     ? AreaModel::kGlobal
                 : model == "per_vertex" ? AreaModel::kPerVertex
                                         : AreaModel::kNone;
  const bool penalty = model == "global" || model == "per_vertex";
  m.area.modulus = r.schedule("area_modulus", penalty ? 400.0 : 0.0, Range::nonNegative(), "pN/nm");
  if (!penalty && !m.area.modulus.isZero())
    r.fail("area_modulus", fmt::format("is for the penalty area models (\"global\", \"per_vertex\"), not \"{}\"", model));
  if (penalty && m.area.modulus.isZero())
    r.fail("area_modulus", fmt::format("is 0: the \"{}\" penalty then holds nothing; to leave the area free say "
                                       "area_model = \"none\"",
                                       model));
  if (model == "exact" && !closed)
    r.fail("area_model", "\"exact\" on a flat patch: it starts at the least area its boundary allows, where the "
                         "area's gradient has no normal part for the constraint to act with; leave the area free "
                         "(\"none\", the default for patches, with a tension if wanted) or use a penalty "
                         "(\"global\")");
  if (model == "exact" && !by_shape)
    r.fail("area_model", fmt::format("\"exact\" needs the default minimizer ([mechanics] minimizer = \"auto\"); with "
                                     "{} use the penalty \"global\" with an area_modulus",
                                     "cg or lbfgs"));
  if (model == "per_vertex" && by_shape)
    r.fail("area_model", fmt::format("\"per_vertex\" treats vertices as material points, which the default "
                                     "relaxation moves within the surface; use it with {}",
                                     other_minimizer));
  m.target_area = r.schedule("target_area", std::nullopt, Range::positive(), "nm^2");
  m.tension.tension = r.schedule("tension", 0.0, any, "pN/nm");
  // E = γA with γ < 0 is bounded only by an area term: the area held exactly, or a penalty
  // with a modulus > 0 at that time. Without one the membrane grows without end (the
  // relaxation failed at once "far from equilibrium", naming no key). Both schedules are
  // linear between their points, so their points are where to look.
  if (m.area.model != AreaModel::kExact) {
    const std::vector<const Schedule*> schedules = {&m.tension.tension, &m.area.modulus};
    for (double t : knots(schedules)) {
      const double gamma = m.tension.tension.at(t);
      if (!(gamma < 0.0) || (penalty && m.area.modulus.at(t) > 0.0)) continue;
      r.fail("tension", fmt::format("is negative ({:g} pN/nm{}) with no area term to hold it (area_model = \"{}\"{}): "
                                    "the energy γA then has no lower bound and the membrane grows without end; "
                                    "hold the area (area_model = \"exact\", or a penalty with an area_modulus "
                                    "> 0)",
                                    gamma, atTime(schedules, t), model, penalty ? ", area_modulus 0" : ""));
    }
  }
  m.regularization.strength = r.schedule("mesh_regularization", 0.0, Range::nonNegative(), "pN·nm");
  if (by_shape && !m.regularization.strength.isZero())
    r.fail("mesh_regularization", fmt::format("acts within the surface, which the default relaxation (normal "
                                              "displacements, remeshing) keeps healthy without it; it is for {}",
                                              other_minimizer));

  const char* volume_keys[] = {"volume_modulus", "reduced_volume", "target_volume"};
  if (!closed) {
    for (const char* k : volume_keys)
      if (r.has(k)) r.fail(k, "an open membrane encloses no volume");
    return m;
  }
  VolumeParameters& volume = m.volume;
  volume.modulus = r.schedule("volume_modulus", 0.0, Range::nonNegative(), "pN/nm^2");
  volume.reduced_volume = r.schedule("reduced_volume", std::nullopt, Range{0.0, 1.0, true, false}, "");
  volume.target_volume = r.schedule("target_volume", std::nullopt, Range::positive(), "nm^3");
  if (volume.reduced_volume.isSet() && volume.target_volume.isSet())
    r.fail("target_volume", "give either reduced_volume or target_volume, not both");
  const bool has_target = volume.reduced_volume.isSet() || volume.target_volume.isSet();
  // A target without a modulus: held exactly (or refused where nothing could hold it).
  volume.exact = has_target && !r.has("volume_modulus");
  if (has_target && r.has("volume_modulus") && volume.modulus.isZero())
    r.fail("volume_modulus", "is 0 with a volume target: nothing would hold the target (it was dropped, with exit "
                             "0); leave volume_modulus out to hold it exactly, or give it > 0");
  // A tension with nothing holding the area or the volume shrinks a vesicle to a point:
  // it ran for seconds before failing with "area changed 0.0001-fold". (Filaments inside
  // may hold it out: then it is for the run to see.)
  if (surely_closed && !filaments && m.area.model != AreaModel::kExact && !volume.exact) {
    const std::vector<const Schedule*> schedules = {&m.tension.tension, &m.area.modulus, &volume.modulus};
    for (double t : knots(schedules)) {
      const bool area_held = penalty && m.area.modulus.at(t) > 0.0, volume_held = volume.modulus.at(t) > 0.0;
      if (m.tension.tension.at(t) > 0.0 && !area_held && !volume_held)
        r.fail("tension", fmt::format("pulls a closed membrane with nothing holding its area or its volume{} "
                                      "(area_model = \"{}\", volume_modulus 0): it shrinks to a point; hold the "
                                      "volume (reduced_volume, target_volume or volume_modulus) or the area",
                                      atTime(schedules, t), model));
    }
  }
  if (volume.exact && !by_shape)
    r.fail(volume.reduced_volume.isSet() ? "reduced_volume" : "target_volume",
           fmt::format("needs a volume_modulus with {} (the default minimizer holds it exactly)", other_minimizer));
  return m;
}

// The largest absolute value a schedule takes.
double largest(const Schedule& s) {
  double v = 0.0;
  for (const auto& point : s.points()) v = std::max(v, std::abs(point.second));
  return v;
}

// Each modulus against the force tolerance at the mesh's scale h (io/resolvable_forces.hpp).
// A loaded mesh without mesh_size has its scale only once it is read: not checked here.
void requireResolvable(const ConfigReader& r, const MembraneMechanics& m, double h, double tolerance) {
  if (!(h > 0)) return;
  requireResolvableForces(r, "bending_modulus", largest(m.bending.modulus) / h, "bending_modulus / mesh_size",
                          tolerance);
  requireResolvableForces(r, "tension", largest(m.tension.tension) * h, "|tension| x mesh_size", tolerance);
  // The penalties' forces scale with the strain they hold back: taken at 1%.
  requireResolvableForces(r, "area_modulus", 0.01 * largest(m.area.modulus) * h, "area_modulus x mesh_size x 1%",
                          tolerance);
  requireResolvableForces(r, "volume_modulus", 0.01 * largest(m.volume.modulus) * h * h,
                          "volume_modulus x mesh_size² x 1%", tolerance);
}

// `filaments`: the config has filaments (readMechanicsOfMembrane).
MembraneConfig readMembrane(const ConfigReader& r, std::size_t index, const std::filesystem::path& base_dir,
                            const MinimizerSettings& mechanics, bool filaments) {
  const MinimizerKind minimizer = mechanics.kind;
  MembraneConfig m;
  m.name = r.name("name", fmt::format("membrane{}", index));
  readShape(r, m, base_dir);
  // Closedness of a loaded mesh is only known once it is read; sim/ checks it again.
  m.species = readSurfaceSpecies(r);
  std::string protein_curvature;
  for (const SurfaceSpeciesConfig& sp : m.species)
    if (sp.curvature && sp.curvature->spontaneous_curvature != 0.0) protein_curvature = sp.name;
  m.mechanics = readMechanicsOfMembrane(r, m.shape, minimizer, protein_curvature, filaments);
  m.area_model_given = r.has("area_model");
  requireResolvable(r, m.mechanics, m.mesh_size, mechanics.force_tolerance);
  m.remesh = r.boolean("remesh", false);
  // A loaded mesh has no mesh_size: its sizes default from its own mean edge (sim/).
  m.min_size = r.number("min_size", m.mesh_size / 4.0, Range::positive(), "nm");
  m.max_size = r.number("max_size", m.mesh_size * 2.0, Range::positive(), "nm");
  m.remesh_tolerance = r.number("remesh_tolerance", m.mesh_size / 120.0, Range::positive(), "nm");
  if (r.has("min_size") && r.has("max_size") && m.min_size > m.max_size)
    r.fail("min_size", fmt::format("({:g} nm) exceeds max_size ({:g} nm)", m.min_size, m.max_size));
  if (m.mesh_size > 0 && m.min_size > m.mesh_size)
    r.fail("min_size", fmt::format("({:g} nm) must not exceed mesh_size ({:g} nm)", m.min_size, m.mesh_size));
  if (m.mesh_size > 0 && m.max_size < m.mesh_size)
    r.fail("max_size", fmt::format("({:g} nm) must not be below mesh_size ({:g} nm)", m.max_size, m.mesh_size));
  // A schedule is linear between its points: all of them > 0 keeps it > 0 throughout.
  for (const SurfaceSpeciesConfig& sp : m.species)
    for (const auto& [t, kappa] : m.mechanics.bending.modulus.points())
      if (sp.curvature && !(kappa > 0.0))
        r.fail("bending_modulus", fmt::format("must be > 0{}: species \"{}\" senses curvature, which needs the "
                                              "lipid's κ (thesis eq. 3.19)",
                                              m.mechanics.bending.modulus.isConstant() ? ""
                                                                                       : fmt::format(" (at t = {:g} s)", t),
                                              sp.name));
  r.finish();
  return m;
}

// [membrane_filament]: the membrane–bead excluded volume, on by default when the config
// has membranes and filaments (docs/coupling.md).
std::optional<MembraneBeadExclusionParams> readMembraneFilament(const ConfigReader& root, const Config& c) {
  const std::optional<ConfigReader> r = root.table("membrane_filament");
  const bool both = !c.membranes.empty() && c.filaments.has_value();
  if (r && !both) r->fail("enabled", "needs at least one [[membrane]] and a [[filament_type]]");
  if (!both) return std::nullopt;
  MembraneBeadExclusionParams p;
  if (!r) return p;
  const bool enabled = r->boolean("enabled", true);
  p.stiffness = r->number("stiffness", p.stiffness, Range::positive(), "pN nm^3");
  p.cutoff = r->number("cutoff", p.cutoff, Range::positive(), "nm");
  const std::string beads = r->choice("beads", "all", {"all", "ends", "plus_ends"});
  p.beads = beads == "all" ? ExclusionBeads::kAll : beads == "ends" ? ExclusionBeads::kEnds : ExclusionBeads::kPlusEnds;
  // A contact term: a bead feels the membrane near it as a wall. With a cut-off past a
  // membrane's radius it felt the far side too, and with a stiffness of 1e12 such a run
  // never finished its first relaxation.
  for (const MembraneConfig& m : c.membranes) {
    const double size = m.shape == "plane" ? std::min(m.size[0], m.size[1]) / 2 : m.radii.minCoeff();
    if (m.shape != "mesh" && p.cutoff > size)
      r->fail("cutoff", fmt::format("({:g} nm) exceeds the {} of membrane \"{}\" ({:g} nm): a bead would feel its far "
                                    "side; the interaction is a contact (default 20 nm)",
                                    p.cutoff, m.shape == "plane" ? "half-width" : "smallest radius", m.name, size));
  }
  // The push on a bead where the fade begins, cutoff/2 from a flat membrane: 2πk/(cutoff/2)³.
  requireResolvableForces(*r, r->has("stiffness") ? "stiffness" : "cutoff",
                          2 * constants::kPi * p.stiffness / std::pow(p.cutoff / 2, 3),
                          "2π stiffness / (cutoff/2)³", c.mechanics.force_tolerance);
  r->finish();
  if (!enabled) return std::nullopt;
  return p;
}

}  // namespace

Config parseConfig(const std::string& text, const std::string& source,
                   const std::filesystem::path& base_dir, const std::vector<std::string>& overrides) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}: invalid TOML: {}", source, e.source().begin.line, e.description()));
  }
  for (const std::string& o : overrides) applyOverride(root, o);

  Config c;
  c.source = source;
  std::ostringstream effective;
  effective << root;
  c.effective_toml = effective.str();

  const ConfigReader r(root, source, "");
  if (auto s = r.table("simulation")) c.simulation = readSimulation(*s);
  if (auto m = r.table("mechanics")) c.mechanics = readMechanics(*m);
  const auto membranes = r.tableArray("membrane");
  for (std::size_t i = 0; i < membranes.size(); ++i) {
    c.membranes.push_back(readMembrane(membranes[i], i, base_dir, c.mechanics, r.has("filament_type")));
    for (std::size_t j = 0; j < i; ++j)
      if (c.membranes[j].name == c.membranes[i].name)
        membranes[i].fail("name", fmt::format("\"{}\" is used by membrane {} already", c.membranes[i].name, j));
  }
  c.chemistry = readChemistry(r, c.membranes);
  c.filaments = readFilaments(r, c.chemistry, c.membranes, c.mechanics.force_tolerance);
  c.membrane_filament = readMembraneFilament(r, c);
  if (c.membranes.empty() && !c.chemistry && !c.filaments)
    throw InputError(fmt::format("{}: no [[membrane]], [[species]] or [[filament_type]] given: nothing to simulate",
                                 source));
  r.finish();
  return c;
}

Config loadConfig(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) throw InputError(fmt::format("{}: cannot open config file", file.string()));
  // Bounded, and regular files only: /dev/zero as a config (or a sweep's base) was read
  // until memory ran out, and a folder said "nothing to simulate".
  constexpr std::size_t kMaxConfigBytes = 16u << 20;
  return parseConfig(readWholeFile(file, kMaxConfigBytes), file.string(), file.parent_path(), overrides);
}

}  // namespace cortex
