#include "io/filament_config.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "io/membrane_reference.hpp"
#include "io/resolvable_forces.hpp"

namespace cortex {
namespace {

using Shape = BoundaryConfig::Shape;
constexpr std::int64_t kMaxCount = 10'000'000;

Vec3 readVec(const ConfigReader& r, const std::string& key, const char* unit) {
  const auto v = r.numbers(key, 3, Range{}, unit);
  return Vec3(v[0], v[1], v[2]);
}

Index speciesIndex(const ConfigReader& r, const std::string& key, const std::vector<SpeciesDef>& species) {
  if (!r.has(key)) r.fail(key, "is required (the name of a [[species]])");
  const std::string name = r.string(key, "");
  for (std::size_t i = 0; i < species.size(); ++i) {
    if (species[i].name != name) continue;
    if (species[i].surface >= 0)
      r.fail(key, fmt::format("\"{}\" is a membrane species; filaments exchange with [[species]] in 3D", name));
    return static_cast<Index>(i);
  }
  r.fail(key, species.empty() ? fmt::format("names \"{}\" but the config has no [[species]]", name)
                              : fmt::format("no [[species]] is named \"{}\"", name));
}

// `key` names a [[filament_type]]; it may be omitted when there is only one.
Index typeIndex(const ConfigReader& r, const std::string& key, const std::vector<FilamentType>& types,
                std::string& name) {
  if (!r.has(key) && types.size() > 1) r.fail(key, "is required when there are several [[filament_type]]");
  name = r.string(key, types.front().name);
  for (std::size_t i = 0; i < types.size(); ++i)
    if (types[i].name == name) return static_cast<Index>(i);
  r.fail(key, fmt::format("no [[filament_type]] is named \"{}\"", name));
}

FilamentType readType(const ConfigReader& r, bool single, const std::vector<SpeciesDef>& species,
                      double force_tolerance) {
  FilamentType t;
  if (!single && !r.has("name")) r.fail("name", "is required when there are several [[filament_type]]");
  t.name = r.name("name", t.name);
  t.monomer_size = r.number("monomer_size", t.monomer_size, Range{1e-3, 1e6, false, false}, "nm");
  t.cylinder_monomers = static_cast<int>(r.integer("cylinder_monomers", t.cylinder_monomers, 1, 1'000'000));
  t.bending_stiffness = r.number("bending_stiffness", t.bending_stiffness, Range::nonNegative(), "pN·nm");
  t.stretching_stiffness = r.number("stretching_stiffness", t.stretching_stiffness, Range::positive(), "pN/nm");
  // End rates default to ATP-actin's (Pollard 1986, as in MEDYAN) once there is a monomer
  // species to exchange with, and to 0 (mechanics only) without one.
  if (r.has("monomer_species")) {
    t.monomer_species_index = speciesIndex(r, "monomer_species", species);
    t.monomer_species = species[t.monomer_species_index].name;
    t.plus_on = 11.6, t.plus_off = 1.4, t.minus_on = 1.3, t.minus_off = 0.8;
  }
  t.plus_on = r.number("plus_on", t.plus_on, Range::nonNegative(), "1/(µM·s)");
  t.plus_off = r.number("plus_off", t.plus_off, Range::nonNegative(), "1/s");
  t.minus_on = r.number("minus_on", t.minus_on, Range::nonNegative(), "1/(µM·s)");
  t.minus_off = r.number("minus_off", t.minus_off, Range::nonNegative(), "1/s");
  t.excluded_volume_stiffness =
      r.number("excluded_volume_stiffness", t.excluded_volume_stiffness, Range::nonNegative(), "pN/nm");
  t.excluded_volume_distance =
      r.number("excluded_volume_distance", t.excluded_volume_distance, Range::positive(), "nm");
  t.nucleation_rate = r.number("nucleation_rate", t.nucleation_rate, Range::nonNegative(), "1/(µM·s)");
  // Each force at a 1% deformation (0.01 rad, 1% strain, 1% overlap): a network relaxed to
  // 1e-4 pN with actin's 100 pN/nm over 108 nm cylinders (1.1e4 pN at 100%) converges.
  const double cylinder = t.monomer_size * t.cylinder_monomers;
  requireResolvableForces(r, "bending_stiffness", 0.01 * t.bending_stiffness / cylinder,
                          "bending_stiffness / cylinder length x 1%", force_tolerance);
  requireResolvableForces(r, "stretching_stiffness", 0.01 * t.stretching_stiffness * cylinder,
                          "stretching_stiffness x cylinder length x 1%", force_tolerance);
  requireResolvableForces(r, r.has("excluded_volume_distance") ? "excluded_volume_distance" : "excluded_volume_stiffness",
                          0.01 * t.excluded_volume_stiffness * t.excluded_volume_distance,
                          "excluded_volume_stiffness x excluded_volume_distance x 1%", force_tolerance);
  // Cylinders shorter than the filament is thick overlap their own filament's next-but-one
  // within the excluded volume: monomer_size 0.0011 nm failed after 83 s with forces of
  // 1e6 pN, or took 4 GB placing linker sites.
  if (cylinder < t.excluded_volume_distance)
    r.fail(r.has("monomer_size")        ? "monomer_size"
           : r.has("cylinder_monomers") ? "cylinder_monomers"
                                        : "excluded_volume_distance",
           fmt::format("makes cylinders of {:g} nm (monomer_size x cylinder_monomers), shorter than the filament is "
                       "thick (excluded_volume_distance {:g} nm)",
                       cylinder, t.excluded_volume_distance));
  const bool exchanges = t.plus_on > 0 || t.plus_off > 0 || t.minus_on > 0 || t.minus_off > 0 || t.nucleation_rate > 0;
  if (exchanges && t.monomer_species_index < 0)
    r.fail("monomer_species", "is required (the [[species]] of free monomers) when an end rate or "
                              "nucleation_rate is non-zero");
  r.finish();
  return t;
}

BoundaryConfig readBoundary(const ConfigReader& r, const Vec3& grid_max, double force_tolerance) {
  BoundaryConfig b;
  if (r.choice("shape", "box", {"box", "sphere"}) == "sphere") {
    b.shape = Shape::kSphere;
    for (const char* k : {"min", "max"})
      if (r.has(k)) r.fail(k, "is for shape = \"box\"; a sphere takes center and radius");
    b.center = readVec(r, "center", "nm");
    b.radius = r.requiredNumber("radius", Range::positive(), "nm");
  } else {
    for (const char* k : {"center", "radius"})
      if (r.has(k)) r.fail(k, "is for shape = \"sphere\"; a box takes min and max");
    b.min = r.has("min") ? readVec(r, "min", "nm") : Vec3::Zero();
    b.max = r.has("max") ? readVec(r, "max", "nm") : grid_max;
    if (!(b.min.array() < b.max.array()).all())
      r.fail(r.has("max") ? "max" : "min",
             fmt::format("min [{:g}, {:g}, {:g}] must be below max [{:g}, {:g}, {:g}] on every axis (nm)", b.min.x(),
                         b.min.y(), b.min.z(), b.max.x(), b.max.y(), b.max.z()));
  }
  b.repulsion = r.number("repulsion", b.repulsion, Range::nonNegative(), "pN");
  requireResolvableForces(r, "repulsion", b.repulsion, "repulsion", force_tolerance);
  b.screening_length = r.number("screening_length", b.screening_length, Range::positive(), "nm");
  r.finish();
  return b;
}

// The space filaments start in: its centre, and its largest extent (box diagonal or
// sphere diameter) with a description for messages, and its volume.
struct Space {
  Vec3 centre;
  double extent;
  const char* what;
  double volume;
};

double boxVolume(const Vec3& lo, const Vec3& hi) { return (hi - lo).prod(); }

Space spaceOf(const std::optional<BoundaryConfig>& b, const Vec3& grid_max) {
  if (!b) return {grid_max / 2, grid_max.norm(), "compartment grid's box diagonal", grid_max.prod()};
  if (b->shape == Shape::kSphere)
    return {b->center, 2 * b->radius, "boundary sphere's diameter", 4.0 / 3.0 * constants::kPi * std::pow(b->radius, 3)};
  return {(b->min + b->max) / 2, (b->max - b->min).norm(), "boundary box's diagonal", boxVolume(b->min, b->max)};
}

// Randomly placed filaments whose bodies (cylinders of the excluded-volume diameter) would
// fill more than this fraction of the volume they start in: they cannot lie there without
// overlapping wholesale, and the linker and motor pairs in reach grow as the density
// squared (10,000 filaments of 2 µm in 1 µm³, 77% filled, took over 2 minutes and 2 GB
// in `check`). The actin cortex is a few percent.
constexpr double kMaxFilledFraction = 0.5;

void requireRoom(const ConfigReader& r, const FilamentInit& f, const FilamentType& t, const Space& space,
                 const std::vector<MembraneConfig>& membranes) {
  double volume = f.region ? boxVolume((*f.region)[0], (*f.region)[1]) : space.volume;
  for (const MembraneConfig& m : membranes)
    if (m.name == f.inside && m.shape != "mesh") volume = std::min(volume, 4.0 / 3.0 * constants::kPi * m.radii.prod());
  const double radius = t.excluded_volume_distance / 2;
  const double filled = f.count * f.length * constants::kPi * radius * radius / volume;
  if (filled > kMaxFilledFraction)
    r.fail("count", fmt::format("{} filaments of {:g} nm (radius {:g} nm, excluded_volume_distance / 2) would fill "
                                "{:.0f}% of the {:.3g} nm³ they start in, over {:.0f}%: they cannot lie there without "
                                "overlapping",
                                f.count, f.length, radius, 100 * filled, volume, 100 * kMaxFilledFraction));
}

FilamentInit readInit(const ConfigReader& r, const std::vector<FilamentType>& types, const Space& space,
                      const std::vector<MembraneConfig>& membranes) {
  FilamentInit f;
  f.type_index = typeIndex(r, "type", types, f.type);
  const FilamentType& t = types[f.type_index];
  f.count = static_cast<int>(r.integer("count", f.count, 0, kMaxCount));
  f.length = r.number("length", f.length, Range::positive(), "nm");
  if (f.length < 1.5 * t.monomer_size)
    r.fail("length", fmt::format("({:g} nm) is shorter than a dimer of \"{}\" (2 x {:g} nm), the smallest filament",
                                 f.length, t.name, t.monomer_size));
  if (f.length > space.extent)
    r.fail("length", fmt::format("({:g} nm) exceeds the {} ({:g} nm): no filament fits", f.length, space.what,
                                 space.extent));
  f.clamped_minus_end = r.boolean("clamped_minus_end", f.clamped_minus_end);
  f.fixed_minus_end = r.boolean("fixed_minus_end", f.fixed_minus_end) || f.clamped_minus_end;
  if (r.choice("placement", "random", {"random", "bundle"}) == "bundle") {
    f.placement = FilamentInit::Placement::kBundle;
    for (const char* k : {"region", "inside"})
      if (r.has(k)) r.fail(k, "is for placement = \"random\"");
    f.center = r.has("center") ? readVec(r, "center", "nm") : space.centre;
    if (r.has("direction")) {
      const Vec3 d = readVec(r, "direction", "");
      if (!(d.squaredNorm() > 0)) r.fail("direction", "must not be the zero vector");
      f.direction = d.normalized();
    }
    f.spacing = r.number("spacing", f.spacing, Range::positive(), "nm");
    // Closer than a filament's radius, each axis lies inside its neighbour (a spacing of
    // 1e-300 laid coincident filaments, whose excluded volume has no direction to push).
    if (t.excluded_volume_stiffness > 0 && f.count > 1 && f.spacing < t.excluded_volume_distance / 2)
      r.fail("spacing", fmt::format("({:g} nm) is below the radius of \"{}\" filaments (excluded_volume_distance / 2 "
                                    "= {:g} nm): each would lie inside its neighbour",
                                    f.spacing, t.name, t.excluded_volume_distance / 2));
    f.mixed_polarity = r.choice("polarity", "parallel", {"parallel", "mixed"}) == "mixed";
  } else {
    for (const char* k : {"center", "direction", "spacing", "polarity"})
      if (r.has(k)) r.fail(k, "is for placement = \"bundle\"");
    if (const auto g = r.table("region")) {
      const Vec3 lo = readVec(*g, "min", "nm"), hi = readVec(*g, "max", "nm");
      g->finish();
      if (!(lo.array() < hi.array()).all()) r.fail("region", "min must be below max on every axis");
      f.region = std::array<Vec3, 2>{lo, hi};
    }
    if (r.has("inside")) f.inside = readClosedMembraneName(r, "inside", membranes);
    requireRoom(r, f, t, space, membranes);
  }
  r.finish();
  return f;
}

// Name and species of a linker, motor or brancher; the name defaults to the species'.
template <class Protein>
void readIdentity(const ConfigReader& r, Protein& p, const std::vector<SpeciesDef>& species) {
  p.species_index = speciesIndex(r, "species", species);
  p.species = species[p.species_index].name;
  p.name = r.name("name", p.species);
}

// 1/(µM·s): a thousand times the diffusion limit of protein association.
constexpr double kMaxBindingOnRate = 1e6;

// Binding between two filaments, shared by linkers and motors.
template <class Protein>
void readBinding(const ConfigReader& r, Protein& p, double force_tolerance) {
  p.min_distance = r.number("min_distance", p.min_distance, Range::nonNegative(), "nm");
  p.max_distance = r.number("max_distance", p.max_distance, Range::positive(), "nm");
  if (!(p.min_distance < p.max_distance))
    r.fail("max_distance",
           fmt::format("({:g} nm) must exceed min_distance ({:g} nm)", p.max_distance, p.min_distance));
  // Binding picks among the site pairs found at the last minimization and voids those
  // taken since (thinning). Far past the diffusion limit (~10³ /(µM·s)) the few pairs are
  // taken at once and the rest of the window is spent on void draws: 1e9 took 70 s for
  // 0.1 s of a small network. 10⁶ is a thousand times that limit: a unit slip beyond.
  p.on_rate = r.number("on_rate", p.on_rate, Range::nonNegative(), "1/(µM·s)");
  if (p.on_rate > kMaxBindingOnRate)
    r.fail("on_rate", fmt::format("{:g} /(µM·s) is over {:g}, a thousand times the diffusion limit of protein "
                                  "association (~10³ /(µM·s)): is it in 1/(µM·s)?",
                                  p.on_rate, kMaxBindingOnRate));
  p.off_rate = r.number("off_rate", p.off_rate, Range::nonNegative(), "1/s");
  p.stiffness = r.number("stiffness", p.stiffness, Range::positive(), "pN/nm");
  requireResolvableForces(r, "stiffness", 0.01 * p.stiffness * p.max_distance, "stiffness x max_distance x 1%",
                          force_tolerance);
}

int readSiteSpacing(const ConfigReader& r, int fallback) {
  return static_cast<int>(r.integer("site_spacing", fallback, 1, 1'000'000));
}

LinkerType readLinker(const ConfigReader& r, const std::vector<SpeciesDef>& species, double force_tolerance) {
  LinkerType l;
  readIdentity(r, l, species);
  readBinding(r, l, force_tolerance);
  l.slip_length = r.number("slip_length", l.slip_length, Range::nonNegative(), "nm");
  l.site_spacing = readSiteSpacing(r, l.site_spacing);
  r.finish();
  return l;
}

MotorType readMotor(const ConfigReader& r, const std::vector<SpeciesDef>& species, double force_tolerance) {
  MotorType m;
  readIdentity(r, m, species);
  readBinding(r, m, force_tolerance);
  m.walk_rate = r.number("walk_rate", m.walk_rate, Range::nonNegative(), "1/s");
  // Rounded to whole monomers: 1e300 nm overflowed that count and walked like 2.7 nm.
  m.step_size = r.number("step_size", m.step_size, Range{0.0, 1e4, true, false}, "nm");
  m.stall_force = r.number("stall_force", m.stall_force, Range::positive(), "pN");
  m.hill_alpha = r.number("hill_alpha", m.hill_alpha, Range::positive(), "");
  m.catch_force = r.number("catch_force", m.catch_force, Range::positive(), "pN");
  m.site_spacing = readSiteSpacing(r, m.site_spacing);
  if (r.has("heads_min") != r.has("heads_max"))
    r.fail(r.has("heads_min") ? "heads_max" : "heads_min", "is required with heads_min / heads_max (give both)");
  m.heads_min = static_cast<int>(r.integer("heads_min", 0, 1, 10'000));
  m.heads_max = static_cast<int>(r.integer("heads_max", 0, 1, 10'000));
  if (m.heads_max < m.heads_min)
    r.fail("heads_max", fmt::format("({}) must be >= heads_min ({})", m.heads_max, m.heads_min));
  m.head_binding_rate = r.number("head_binding_rate", m.head_binding_rate, Range::positive(), "1/s");
  m.head_load = r.number("head_load", m.head_load, Range::nonNegative(), "1/pN");
  if (m.heads_max > 0 && m.off_rate <= 0)
    r.fail("off_rate", "must be > 0 with heads (it is then one head's unbinding rate)");
  r.finish();
  return m;
}

BrancherType readBrancher(const ConfigReader& r, const std::vector<FilamentType>& types,
                          const std::vector<SpeciesDef>& species, double force_tolerance) {
  BrancherType b;
  readIdentity(r, b, species);
  b.filament_type_index = typeIndex(r, "filament_type", types, b.filament_type);
  b.rate = r.number("rate", b.rate, Range::nonNegative(), "1/(µM²·s)");
  if (b.rate > 0 && types[b.filament_type_index].monomer_species_index < 0)
    r.fail("filament_type", fmt::format("\"{}\" has no monomer_species: a branch's first monomer comes from it",
                                        types[b.filament_type_index].name));
  b.unbranch_rate = r.number("unbranch_rate", b.unbranch_rate, Range::nonNegative(), "1/s");
  b.angle = r.number("angle", b.angle, Range{0.0, 180.0, true, true}, "degrees");
  b.angle_stiffness = r.number("angle_stiffness", b.angle_stiffness, Range::nonNegative(), "pN·nm");
  b.position_stiffness = r.number("position_stiffness", b.position_stiffness, Range::positive(), "pN/nm");
  const FilamentType& t = types[b.filament_type_index];
  const double cylinder = t.monomer_size * t.cylinder_monomers;
  requireResolvableForces(r, "angle_stiffness", 0.01 * b.angle_stiffness / cylinder,
                          "angle_stiffness / cylinder length x 1%", force_tolerance);
  requireResolvableForces(r, "position_stiffness", 0.01 * b.position_stiffness * cylinder,
                          "position_stiffness x cylinder length x 1%", force_tolerance);
  b.site_spacing = readSiteSpacing(r, b.site_spacing);
  r.finish();
  return b;
}

// Linkers, motors and branchers each need their own name and their own diffusing
// species, distinct from every filament type's monomers (a copy cannot be two things).
class ProteinNames {
 public:
  explicit ProteinNames(const std::vector<FilamentType>& types) : types_(types) {}
  void add(const ConfigReader& r, const std::string& owner, const std::string& name, const std::string& species) {
    for (const auto& [n, o] : names_)
      if (n == name) r.fail("name", fmt::format("\"{}\" is the name of {} already", name, o));
    for (const auto& [s, o] : species_)
      if (s == species) r.fail("species", fmt::format("\"{}\" is the species of {} already", species, o));
    for (const FilamentType& t : types_)
      if (t.monomer_species == species)
        r.fail("species", fmt::format("\"{}\" is the monomer species of filament type \"{}\"", species, t.name));
    names_.emplace_back(name, owner);
    species_.emplace_back(species, owner);
  }

 private:
  const std::vector<FilamentType>& types_;
  std::vector<std::pair<std::string, std::string>> names_, species_;
};

}  // namespace

std::optional<FilamentConfig> readFilaments(const ConfigReader& root, const std::optional<ChemistryConfig>& chemistry,
                                            const std::vector<MembraneConfig>& membranes, double force_tolerance) {
  const auto type_tables = root.tableArray("filament_type");
  if (type_tables.empty()) {
    for (const char* k : {"filaments", "boundary", "linker", "motor", "brancher"})
      if (root.has(k)) root.fail(k, "needs at least one [[filament_type]]");
    return std::nullopt;
  }
  const std::vector<SpeciesDef> no_species;
  const std::vector<SpeciesDef>& species = chemistry ? chemistry->species : no_species;
  const CompartmentGrid grid = chemistry ? chemistry->grid : CompartmentGrid{};
  const Vec3 grid_max = grid.extent();

  FilamentConfig f;
  for (std::size_t i = 0; i < type_tables.size(); ++i) {
    f.types.push_back(readType(type_tables[i], type_tables.size() == 1, species, force_tolerance));
    for (std::size_t j = 0; j < i; ++j)
      if (f.types[j].name == f.types[i].name)
        type_tables[i].fail("name", fmt::format("\"{}\" is used by filament_type.{} already", f.types[i].name, j));
  }
  if (const auto b = root.table("boundary")) {
    f.boundary = readBoundary(*b, grid_max, force_tolerance);
    // Ends outside the grid would draw monomers from the nearest compartment: refuse.
    const Vec3 lo = f.boundary->shape == BoundaryConfig::Shape::kSphere
                        ? Vec3(f.boundary->center.array() - f.boundary->radius)
                        : f.boundary->min;
    const Vec3 hi = f.boundary->shape == BoundaryConfig::Shape::kSphere
                        ? Vec3(f.boundary->center.array() + f.boundary->radius)
                        : f.boundary->max;
    if (chemistry && ((lo.array() < -1e-9).any() || (hi.array() > grid_max.array() + 1e-9).any()))
      b->fail(f.boundary->shape == BoundaryConfig::Shape::kSphere ? "radius" : "max",
              fmt::format("the boundary reaches outside the compartment grid [0, {:g}] x [0, {:g}] x [0, {:g}] nm, "
                          "where filament ends would have no monomers to exchange with",
                          grid_max.x(), grid_max.y(), grid_max.z()));
  }
  const Space space = spaceOf(f.boundary, grid_max);
  for (const ConfigReader& r : root.tableArray("filaments")) f.initial.push_back(readInit(r, f.types, space, membranes));

  ProteinNames names(f.types);
  const auto linkers = root.tableArray("linker");
  for (std::size_t i = 0; i < linkers.size(); ++i) {
    f.linkers.push_back(readLinker(linkers[i], species, force_tolerance));
    names.add(linkers[i], fmt::format("linker.{}", i), f.linkers.back().name, f.linkers.back().species);
  }
  const auto motors = root.tableArray("motor");
  for (std::size_t i = 0; i < motors.size(); ++i) {
    f.motors.push_back(readMotor(motors[i], species, force_tolerance));
    // Steps are whole monomers of the first type (FilamentNetwork::spacing): one that
    // rounds to none was taken as one, 2.7 times (or 2,700 times) the step asked for.
    const double monomer = f.types.front().monomer_size;
    if (f.motors.back().stepMonomers(monomer) < 1)
      motors[i].fail("step_size", fmt::format("{:g} nm rounds to no monomer of {:g} nm (filament_type.0's "
                                              "monomer_size); a motor steps whole monomers: at least {:g} nm",
                                              f.motors.back().step_size, monomer, 0.5 * monomer));
    names.add(motors[i], fmt::format("motor.{}", i), f.motors.back().name, f.motors.back().species);
  }
  const auto branchers = root.tableArray("brancher");
  for (std::size_t i = 0; i < branchers.size(); ++i) {
    f.branchers.push_back(readBrancher(branchers[i], f.types, species, force_tolerance));
    names.add(branchers[i], fmt::format("brancher.{}", i), f.branchers.back().name, f.branchers.back().species);
  }
  return f;
}

}  // namespace cortex
