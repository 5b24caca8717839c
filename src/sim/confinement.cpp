#include "sim/confinement.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <Eigen/Geometry>
#include <map>
#include <set>

#include "chem/compartment_slicing.hpp"
#include "core/error.hpp"
#include "interact/inside_membrane.hpp"
#include "sim/membrane_builder.hpp"
#include "sim/system.hpp"

namespace cortex {

std::vector<std::optional<SideFractions>> sideFractions(const std::vector<std::unique_ptr<Membrane>>& membranes,
                                                        const std::vector<SpeciesSide>& sides,
                                                        const CompartmentGrid& grid) {
  std::vector<std::optional<SideFractions>> out(sides.size());
  std::map<std::string, CompartmentSlices> slices;
  for (std::size_t s = 0; s < sides.size(); ++s) {
    const SpeciesSide& side = sides[s];
    if (side.membrane.empty()) continue;
    auto it = slices.find(side.membrane);
    if (it == slices.end()) {
      const Membrane& m = closedMembrane(membranes, side.membrane,
                                         fmt::format("[[species]] {}", side.outside ? "outside" : "inside"));
      it = slices.emplace(side.membrane, sliceCompartments(m.mesh().positions(), m.mesh().triangles(), grid)).first;
    }
    const CompartmentSlices& cut = it->second;
    SideFractions f{cut.volume, cut.faces};
    if (side.outside) {
      for (double& v : f.volume) v = 1.0 - v;
      for (auto& face : f.faces)
        for (double& a : face) a = 1.0 - a;
    }
    out[s] = std::move(f);
  }
  return out;
}

void checkSlicingResolution(const std::vector<std::unique_ptr<Membrane>>& membranes, const ChemistryConfig& config) {
  // Below this many compartments across, the planar cut misses more than ~1% of the
  // volume (a warning); below the second, 10-50% (an input error: not a result).
  constexpr double kFewestCompartmentsAcross = 2.0, kTooFewCompartmentsAcross = 1.0;
  std::set<std::string> confining;
  for (const SpeciesSide& s : config.sides)
    if (!s.membrane.empty()) confining.insert(s.membrane);
  for (const ReactionRestriction& r : config.reaction_restrictions)
    if (!r.side.membrane.empty()) confining.insert(r.side.membrane);
  for (const auto& m : membranes) {
    if (!confining.count(m->name()) || m->mesh().numVertices() == 0) continue;
    Eigen::AlignedBox3d box;
    for (const Vec3& p : m->mesh().positions()) box.extend(p);
    const double smallest = box.sizes().minCoeff(), across = smallest / config.grid.size;
    if (!(across < kFewestCompartmentsAcross)) continue;
    const std::string what = fmt::format(
        "membrane \"{}\" confines species but is only {:.2g} compartments across ({:.0f} nm against [compartments] "
        "size = {:g} nm)",
        m->name(), across, smallest, config.grid.size);
    if (across < kTooFewCompartmentsAcross)
      throw InputError(what + ": slicing would miss 10-50% of the volume inside; make [compartments] size at most "
                              "half the membrane's smallest extent (docs/chemistry.md)");
    spdlog::warn("{}: slicing treats the membrane in a compartment as a plane and misses the volume inside by over 1% "
                 "below 2 compartments across, 10-20% at one; a smaller [compartments] size fixes it "
                 "(docs/chemistry.md)",
                 what);
  }
}

namespace {

// Whether some vertex of `surface` lies on `side` of the closed mesh `wall`. Vertices
// outside the wall's bounding box are outside without a winding number; the search
// stops at the first vertex found on the side, so a config that passes costs little.
bool someVertexOnSide(const SurfaceMesh& surface, const SurfaceMesh& wall, bool outside) {
  Eigen::AlignedBox3d box;
  for (Index v = 0; v < wall.numVertices(); ++v)
    if (!wall.isDeletedVertex(v)) box.extend(wall.positions()[v]);
  for (Index v = 0; v < surface.numVertices(); ++v) {
    if (surface.isDeletedVertex(v)) continue;
    const Vec3& p = surface.positions()[v];
    const bool inside = box.contains(p) && windingNumber(wall, p) > 0.5;
    if (inside != outside) return true;
  }
  return false;
}

const Membrane& membraneNamed(const std::vector<std::unique_ptr<Membrane>>& membranes, const std::string& name) {
  for (const auto& m : membranes)
    if (m->name() == name) return *m;
  throw std::logic_error("surface species on an unknown membrane \"" + name + "\"");
}

}  // namespace

Index surfaceJoinedTo3D(const ReactionDef& def, const ChemistryConfig& config) {
  Index surface = -1;
  bool has3D = false;
  for (const auto* list : {&def.reactants, &def.products})
    for (const Stoichiometry& x : *list) {
      const Index k = config.species[x.species].surface;
      if (k >= 0) surface = k;
      else has3D = true;
    }
  return has3D ? surface : -1;
}

OutsideGrid outsideGrid(const Membrane& membrane, const CompartmentGrid& grid) {
  const SurfaceMesh& surface = membrane.mesh();
  const double slack = 1e-9 * grid.extent().maxCoeff();
  const Eigen::AlignedBox3d box(Vec3::Constant(-slack), grid.extent() + Vec3::Constant(slack));
  std::vector<Index> outside;
  for (Index v = 0; v < surface.numVertices(); ++v)
    if (!surface.isDeletedVertex(v) && !box.contains(surface.positions()[v])) outside.push_back(v);
  if (outside.empty()) return {};
  const MeshGeometry g = membrane.currentGeometry();
  double area = 0.0;
  for (Index v : outside) area += g.vertex_area[v];
  return {static_cast<Index>(outside.size()), area / g.area};
}

std::optional<std::string> insideBeyondGrid(const std::vector<std::unique_ptr<Membrane>>& membranes,
                                            const CompartmentGrid& grid, const std::vector<SpeciesSide>& sides,
                                            const std::vector<ReactionRestriction>& restrictions,
                                            const std::vector<SpeciesDef>& species, double tolerated) {
  std::set<std::string> checked;  // several species and reactions may share a membrane
  const auto beyond = [&](const SpeciesSide& side, const std::string& key) -> std::optional<std::string> {
    if (side.membrane.empty() || side.outside || !checked.insert(side.membrane).second) return std::nullopt;
    const Membrane& m = membraneNamed(membranes, side.membrane);
    const OutsideGrid out = outsideGrid(m, grid);
    if (out.vertices == 0 || out.area_fraction <= tolerated) return std::nullopt;
    return fmt::format("{} = \"{}\": {} of the {} vertices of \"{}\" ({:.3g}% of its area) lie outside the "
                       "compartment grid (the box from [0, 0, 0] to [{}] nm); the part of its inside beyond the grid "
                       "would hold none of the copies, which would crowd into the rest: keep the membrane within the "
                       "grid or widen [compartments]",
                       key, side.membrane, out.vertices, m.mesh().numVertices(), side.membrane,
                       100.0 * out.area_fraction, fmt::join(grid.extent(), ", "));
  };
  for (std::size_t s = 0; s < sides.size(); ++s)
    if (auto what = beyond(sides[s], fmt::format("[[species]] \"{}\" inside", species[s].name))) return what;
  for (std::size_t r = 0; r < restrictions.size(); ++r)
    if (auto what = beyond(restrictions[r].side, fmt::format("reaction.{}.inside", r))) return what;
  return std::nullopt;
}

void checkSurfaceReactionsCanFire(const std::vector<std::unique_ptr<Membrane>>& membranes, const ChemistryConfig& config,
                               const std::string& source) {
  const CompartmentGrid& grid = config.grid;
  for (std::size_t r = 0; r < config.reactions.size(); ++r) {
    const ReactionDef& def = config.reactions[r];
    const Index surface = surfaceJoinedTo3D(def, config);
    if (surface < 0) continue;
    Index confined = -1;
    for (const auto* list : {&def.reactants, &def.products})
      for (const Stoichiometry& x : *list)
        if (config.species[x.species].surface < 0 && !config.sides[x.species].membrane.empty()) confined = x.species;
    const std::string& on = config.surfaces[surface];
    const std::string key = fmt::format("reaction.{}.equation", r);
    // Its 3D species are those of the compartment holding each vertex, found by clamping
    // into the grid: a membrane wholly outside reacted with a compartment far away, and
    // one partly outside bound into the grid's edge from its whole area while the volume
    // it encloses beyond the grid held nothing (a vesicle with 16% of its volume outside
    // came to a binding equilibrium 18% off, exit 0).
    const Membrane& membrane = membraneNamed(membranes, on);
    const SurfaceMesh& mesh = membrane.mesh();
    if (const Index outside = outsideGrid(membrane, grid).vertices; outside > 0)
      throw InputError(fmt::format("{}: {}: it joins species on membrane \"{}\" with 3D species, but {} of the {} "
                                   "vertices of \"{}\" lie outside the compartment grid (the box from [0, 0, 0] to "
                                   "[{}] nm), where no volume holds species: place the membrane within the grid or "
                                   "widen [compartments]",
                                   source, key, on, outside, mesh.numVertices(), on, fmt::join(grid.extent(), ", ")));
    if (confined < 0) continue;
    const SpeciesSide& side = config.sides[confined];
    if (side.membrane == on) continue;
    const Membrane& wall = closedMembrane(membranes, side.membrane, key);
    if (someVertexOnSide(mesh, wall.mesh(), side.outside)) continue;
    const char* where = side.outside ? "outside" : "inside";
    throw InputError(fmt::format(
        "{}: {}: it joins species on membrane \"{}\" with \"{}\", which lives {} membrane \"{}\", but no vertex "
        "of \"{}\" lies {} \"{}\": the reaction could never fire (a species that reacts with a membrane's "
        "proteins must be free on a side that membrane touches)",
        source, key, on, config.species[confined].name, where, side.membrane, on, where, side.membrane));
  }
}

ConfinementFeedback::ConfinementFeedback(const ChemistryConfig& config, ChemistryEngine& engine,
                                         RateFactors config_factors)
    : grid_(config.grid),
      sides_(config.sides),
      restrictions_(config.reaction_restrictions),
      engine_(engine),
      factors_(std::move(config_factors)) {
  active_ = false;
  for (const SpeciesSide& s : sides_) active_ = active_ || !s.membrane.empty();
  for (const ReactionRestriction& r : restrictions_) active_ = active_ || r.restricted();
}

void ConfinementFeedback::update(System& system) {
  if (!active_) return;
  // Species sides first, then reaction sides: each membrane is sliced once for both.
  std::vector<SpeciesSide> sides = sides_;
  const std::size_t species = sides.size();
  for (const ReactionRestriction& r : restrictions_) sides.push_back(r.side);
  if (const auto what = insideBeyondGrid(system.membranes(), grid_, sides_, restrictions_,
                                         system.chemistryModel().species, kLargestAreaOutsideGrid))
    throw RunError(fmt::format("t = {:.6g} s, after the relaxation: {}", system.time(), *what));
  const auto fractions = sideFractions(system.membranes(), sides, grid_);
  for (std::size_t s = 0; s < species; ++s) {
    if (!fractions[s]) continue;
    try {
      engine_.setConfinement(static_cast<Index>(s), fractions[s]->volume, gridEdgeValues(grid_, fractions[s]->faces));
    } catch (const std::runtime_error& e) {
      // The membrane moved so that a confined species with copies has no volume left.
      throw RunError(fmt::format("t = {:.6g} s: species \"{}\" lost all its volume inside the compartment grid: {}",
                                 system.time(), system.chemistryModel().species[s].name, e.what()));
    }
  }
  // A restricted reaction fires at the rate of the part of each compartment it may use:
  // none outside its box, and the volume fraction on its side of a membrane (reactants
  // spread uniformly over the compartment, so that fraction of them is there).
  for (std::size_t r = 0; r < restrictions_.size(); ++r) {
    const ReactionRestriction& restriction = restrictions_[r];
    if (!restriction.restricted()) continue;
    const auto& side = fractions[species + r];
    for (Index c = 0; c < grid_.count(); ++c) {
      double factor = side ? side->volume[c] : 1.0;
      if (restriction.region && !restriction.region->contains(grid_.centre(c))) factor = 0.0;
      factors_.set(factors_.range().begin + static_cast<Index>(r), c, factor);
    }
  }
}

}  // namespace cortex
