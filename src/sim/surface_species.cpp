#include "sim/surface_species.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "chem/chemistry_model.hpp"
#include "core/error.hpp"
#include "core/random.hpp"
#include "membrane/curvature.hpp"
#include "sim/confinement.hpp"
#include "sim/curvature_sensing.hpp"
#include "sim/pair_interaction.hpp"
#include "sim/surface_drift.hpp"
#include "sim/surface_graph.hpp"
#include "sim/system.hpp"

namespace cortex {
namespace {
// `count` copies placed uniformly by area on the vertices with room > 0, none above its
// room: a multinomial over those vertices drawn as a chain of binomials (work per vertex,
// not per copy, so 2e9 copies take as long as 2), then what lands above a vertex's room
// is drawn again over the vertices that still have room. The caller keeps count well
// under the total room, so few rounds are needed.
std::vector<int> placeByArea(std::int64_t count, const std::vector<double>& area, std::vector<std::int64_t> room,
                             RandomStream& random) {
  const auto n = static_cast<Index>(area.size());
  std::vector<int> copies(static_cast<std::size_t>(n), 0);
  for (std::int64_t left = count; left > 0;) {
    double weight_left = 0.0;
    for (Index v = 0; v < n; ++v)
      if (room[v] > 0) weight_left += area[v];
    std::int64_t unplaced = left, overflow = 0;
    for (Index v = 0; v < n && unplaced > 0; ++v) {
      if (room[v] <= 0) continue;
      const double p = std::min(1.0, area[v] / weight_left);
      const std::int64_t k = p >= 1.0 ? unplaced : std::binomial_distribution<std::int64_t>(unplaced, p)(random);
      weight_left -= area[v];
      unplaced -= k;
      const std::int64_t kept = std::min(k, room[v]);
      copies[v] += static_cast<int>(kept);
      room[v] -= kept;
      overflow += k - kept;
    }
    left = overflow + unplaced;  // unplaced is 0 unless round-off left weight past the last vertex
  }
  return copies;
}
}  // namespace

void placeSurfaceSpecies(const std::vector<MembraneConfig>& configs, std::vector<std::unique_ptr<Membrane>>& membranes,
                         std::uint64_t seed, const std::string& source) {
  RandomStream random(seed, StreamId::kSurfaceSpeciesPlacement);
  for (std::size_t m = 0; m < configs.size(); ++m) {
    const MembraneConfig& mc = configs[m];
    Membrane& membrane = *membranes[m];
    const std::vector<double> area = dualCellAreas(membrane.mesh());
    const auto n = static_cast<Index>(area.size());
    std::vector<std::string> names;
    std::vector<std::vector<int>> copies;
    std::vector<double> covered(static_cast<std::size_t>(n), 0.0);  // nm² per vertex, by the species placed so far
    for (std::size_t j = 0; j < mc.species.size(); ++j) {
      const SurfaceSpeciesConfig& s = mc.species[j];
      // The key at fault, dotted as the config reader names keys, and whose it is.
      const auto where = [&](const char* key) {
        return fmt::format("{}: membrane.{}.species.{}.{} (species \"{}\" of membrane \"{}\")", source, m, j, key,
                           s.name, mc.name);
      };
      // Weights: the dual-cell areas of the vertices where copies may start.
      std::vector<char> inside(static_cast<std::size_t>(n));
      double sum = 0.0;
      for (Index v = 0; v < n; ++v) {
        inside[v] = !s.region || s.region->contains(membrane.mesh().positions()[v]);
        if (inside[v]) sum += area[v];
      }
      if (!(sum > 0.0)) throw InputError(where("region") + ": holds no vertex of the membrane");
      std::int64_t count = s.copies;
      if (s.density) {
        const double expected = *s.density * sum * 1e-6;  // copies/µm^2 × nm^2
        if (!(expected <= 2e9))
          throw InputError(fmt::format("{}: gives {:.3g} copies, more than 2e9", where("density"), expected));
        count = std::llround(expected);
      }
      // Proteins that sense or make curvature cover A_p each; more of them than the whole
      // membrane holds is no state at all (φ is capped at 1 per cell, docs/proteins.md).
      if (s.curvature) {
        double membrane_area = 0.0;
        for (Index v = 0; v < n; ++v) membrane_area += area[v];
        if (static_cast<double>(count) * s.curvature->area > membrane_area)
          throw InputError(fmt::format("{}: {} copies of area {:g} nm^2 (curvature.area) would cover {:.3g} times "
                                       "the membrane's {:.6g} nm^2; give fewer copies or a lower density",
                                       where(s.density ? "density" : "copies"), count, s.curvature->area,
                                       static_cast<double>(count) * s.curvature->area / membrane_area, membrane_area));
      }
      // With a footprint, the copies of all such species share a vertex's area as the
      // engine counts them (SpeciesDef::footprint): a vertex holds at most `room` more.
      // A footprint past every vertex's room holds no copy anywhere: binding onto the
      // membrane was accepted and never fired (exit 0, 0 events).
      if (s.footprint > 0.0) {
        double largest = 0.0;
        for (Index v = 0; v < n; ++v) largest = std::max(largest, crowdingRoom(area[v]));
        if (s.footprint > largest)
          throw InputError(fmt::format("{}: footprint {:g} nm^2 exceeds the room of every vertex (at most {:.4g} "
                                       "nm^2, about 0.87 mesh_size²): no copy could ever sit on the membrane; "
                                       "a copy must fit in a vertex's cell",
                                       where("footprint"), s.footprint, largest));
      }
      std::vector<std::int64_t> room(static_cast<std::size_t>(n), 0);
      double places = 0.0;
      for (Index v = 0; v < n; ++v) {
        if (!inside[v]) continue;
        // Room past twice the copies changes neither the placement nor the 99% rule below,
        // and the cap keeps a tiny footprint's quotient within the integers.
        room[v] = s.footprint > 0.0
                      ? static_cast<std::int64_t>(std::min(
                            std::floor(std::max(crowdingRoom(area[v]) - covered[v], 0.0) / s.footprint),
                            2.0 * static_cast<double>(count) + 1.0))
                      : count;
        places += static_cast<double>(room[v]);
      }
      if (s.footprint > 0.0 && static_cast<double>(count) > 0.99 * places)
        throw InputError(fmt::format("{}: {} copies do not fit on the {:.0f} places of footprint {:g} nm^2 "
                                     "left by the species before it (keep them under 99% full)",
                                     where(s.density ? "density" : "copies"), count, places, s.footprint));
      std::vector<int> c = placeByArea(count, area, room, random);
      if (s.footprint > 0.0)
        for (Index v = 0; v < n; ++v) covered[v] += c[v] * s.footprint;
      names.push_back(s.name);
      copies.push_back(std::move(c));
    }
    membrane.setSpecies(std::move(names), std::move(copies));
  }
}

SurfaceSpeciesFeedback::SurfaceSpeciesFeedback(const ChemistryConfig& config,
                                               const std::vector<MembraneConfig>& membrane_configs,
                                               ChemistryEngine& engine,
                                               const std::vector<std::unique_ptr<Membrane>>& membranes,
                                               RateFactors config_factors, double thermal_energy)
    : grid_(config.grid),
      engine_(engine),
      species_count_(static_cast<Index>(config.species.size())),
      factors_(std::move(config_factors)),
      thermal_energy_(thermal_energy) {
  for (const std::string& name : config.surfaces) {
    Surface s{-1, {}, {}, {}};
    for (std::size_t m = 0; m < membranes.size(); ++m)
      if (membranes[m]->name() == name) s.membrane = static_cast<Index>(m), s.configs = membrane_configs[m].species;
    const auto k = static_cast<Index>(surfaces_.size());
    for (Index sp = 0; sp < species_count_; ++sp)
      if (config.species[sp].surface == k) s.species.push_back(sp);
    for (std::size_t r = 0; r < config.reactions.size() && s.joined_to_3d.empty(); ++r)
      if (surfaceJoinedTo3D(config.reactions[r], config) == k) s.joined_to_3d = fmt::format("reaction.{}.equation", r);
    surfaces_.push_back(std::move(s));
  }
  for (std::size_t r = 0; r < config.reactions.size(); ++r) {
    const ReactionDef& def = config.reactions[r];
    bool surface_products = false;
    for (const Stoichiometry& p : def.products) surface_products = surface_products || config.species[p.species].surface >= 0;
    if (surface_products) continue;
    Unbinding u{factors_.range().begin + static_cast<Index>(r), -1, {}};
    for (const Stoichiometry& x : def.reactants) {
      const Index k = config.species[x.species].surface;
      if (k < 0) continue;
      const Surface& s = surfaces_[k];
      const auto j = static_cast<Index>(std::find(s.species.begin(), s.species.end(), x.species) - s.species.begin());
      u.surface = k;
      // The unbinding of a species with an interaction or curvature sensing carries its
      // energy in the engine (exactly, copy by copy).
      if (s.configs[j].potential && !copyDependentEnergy(s.configs, j)) u.reactants.emplace_back(j, x.count);
    }
    if (!u.reactants.empty()) unbinding_.push_back(std::move(u));
  }
}

void SurfaceSpeciesFeedback::update(System& system) {
  closed_ = {};
  for (std::size_t k = 0; k < surfaces_.size(); ++k) {
    const Surface& s = surfaces_[k];
    const Membrane& membrane = *system.membranes()[s.membrane];
    const SurfaceMesh& mesh = membrane.mesh();
    DualCellGraph cells = dualCellGraph(mesh);
    closed_.cotangent += cells.clipped_edges;
    // The start refuses a membrane reaching beyond the grid (checkSurfaceReactionsCanFire);
    // one that grew or moved there since binds into the grid's edge from the area beyond
    // it, where no volume holds species: tolerated up to kLargestAreaOutsideGrid.
    if (!s.joined_to_3d.empty())
      if (const OutsideGrid out = outsideGrid(membrane, grid_); out.area_fraction > kLargestAreaOutsideGrid)
        throw RunError(fmt::format("t = {:.6g} s: membrane \"{}\": {} of its {} vertices ({:.3g}% of its area, over "
                                   "the {:g}% a run tolerates) moved outside the compartment grid (the box from "
                                   "[0, 0, 0] to [{}] nm), where no volume holds the 3D species its proteins react "
                                   "with ({}): widen [compartments] or keep the membrane farther from the grid's "
                                   "walls",
                                   system.time(), membrane.name(), out.vertices, mesh.numVertices(),
                                   100.0 * out.area_fraction, 100.0 * kLargestAreaOutsideGrid,
                                   fmt::join(grid_.extent(), ", "), s.joined_to_3d));
    const Index n = mesh.numVertices();
    std::vector<Index> holders(static_cast<std::size_t>(n));
    for (Index v = 0; v < n; ++v) holders[v] = grid_.locate(mesh.positions()[v]);
    std::vector<int> copies(static_cast<std::size_t>(n) * species_count_, 0);
    for (std::size_t j = 0; j < s.species.size(); ++j) {
      const std::vector<int>& c = membrane.speciesCopies()[j];
      for (Index v = 0; v < n; ++v) copies[static_cast<std::size_t>(v) * species_count_ + s.species[j]] = c[v];
    }
    try {
      engine_.setSurface(static_cast<Index>(k), cells.graph, holders, copies);
    } catch (const InputError& e) {
      // A dual cell of zero area: the mesh degenerated (the run's mesh checks say where).
      throw RunError(fmt::format("t = {:.6g} s: membrane \"{}\": its species cannot live on this mesh: {}",
                                 system.time(), membrane.name(), e.what()));
    }
    // The engine refuses energies that are not finite (std::invalid_argument); here that
    // is a parameter's doing, said with the species and the block that made them.
    const auto feed = [&](std::size_t j, const char* block, auto&& set) {
      try {
        set();
      } catch (const std::invalid_argument& e) {
        throw RunError(fmt::format("t = {:.6g} s: membrane \"{}\", species \"{}\": its {} gives rates that are not "
                                   "finite ({}); check that block's parameters (sizes, heights, ranges, moduli)",
                                   system.time(), membrane.name(), s.configs[j].name, block, e.what()));
      }
    };
    const std::vector<std::vector<double>> potential = potentials(s, membrane);
    std::vector<double> curvature;  // per vertex, 1/nm, once a species senses it
    for (std::size_t j = 0; j < s.species.size(); ++j) {
      const SurfaceSpeciesConfig& c = s.configs[j];
      if (copyDependentEnergy(s.configs, j)) {
        // The engine biases the hops by the pair field and the on-site energy itself,
        // event by event.
        std::vector<double> v = potential[j];
        v.resize(static_cast<std::size_t>(n), 0.0);
        const PairMoments moments = c.interaction ? gaussianPairMoments(c.interaction->height, c.interaction->range)
                                                  : PairMoments{};
        ChemistryEngine::SurfaceInteraction interaction = pairInteraction(cells.graph, moments, std::move(v), c.drift);
        if (c.curvature) {
          if (curvature.empty())
            curvature = vertexMeanCurvature(membrane.currentGeometry(), membrane.topology(),
                                            membrane.mechanics().bending.estimator);
          setSensingRows(c, membrane, cells.graph, curvature, system.time(), interaction);
        }
        // The external potential rides in the same field: name every block that fed it.
        std::vector<std::string> blocks;
        if (c.curvature) blocks.push_back("curvature");
        if (c.interaction) blocks.push_back("interaction");
        if (blocks.empty()) blocks.push_back("cross_interaction");  // coupled to another species only
        if (!potential[j].empty()) blocks.push_back("potential");
        const std::string fed_by = fmt::format("{}", fmt::join(blocks, " or "));
        feed(j, fed_by.c_str(), [&] { engine_.setSurfaceInteraction(s.species[j], std::move(interaction)); });
        continue;
      }
      if (potential[j].empty()) continue;
      const DriftFactors drift = driftFactors(cells.graph, potential[j], c.drift);
      closed_.drift += drift.closed_edges;
      feed(j, "potential", [&] { engine_.setSurfaceDrift(s.species[j], drift.factors); });
    }
    for (std::size_t j = 0; j < s.species.size(); ++j)
      for (const CrossInteractionConfig& x : s.configs[j].cross) {
        const auto other = static_cast<std::size_t>(
            std::find_if(s.configs.begin(), s.configs.end(), [&](const auto& c) { return c.name == x.species; }) -
            s.configs.begin());
        PairKernel kernel = pairKernel(cells.graph, gaussianPairMoments(x.interaction.height, x.interaction.range));
        feed(j, "cross_interaction",
             [&] { engine_.setSurfaceCoupling(s.species[j], s.species[other], std::move(kernel.self), std::move(kernel.pair)); });
      }
    setUnbindingFactors(static_cast<Index>(k), membrane.name(), potential, n, system.time());
  }
}

std::vector<std::vector<double>> SurfaceSpeciesFeedback::potentials(const Surface& s, const Membrane& membrane) const {
  const SurfaceMesh& mesh = membrane.mesh();
  std::vector<std::vector<double>> out(s.species.size());
  for (std::size_t j = 0; j < s.species.size(); ++j) {
    if (!s.configs[j].potential) continue;
    out[j].resize(static_cast<std::size_t>(mesh.numVertices()));
    for (Index v = 0; v < mesh.numVertices(); ++v) out[j][v] = surfacePotential(*s.configs[j].potential, mesh.positions()[v]);
  }
  return out;
}

void SurfaceSpeciesFeedback::setSensingRows(const SurfaceSpeciesConfig& c, const Membrane& membrane,
                                            const SubvolumeGraph& cells, const std::vector<double>& curvature,
                                            double t, ChemistryEngine::SurfaceInteraction& interaction) const {
  const double kappa_lipid = membrane.mechanics().bending.modulus.at(t);
  const double lipid_curvature = membrane.mechanics().bending.spontaneous_curvature.at(t);
  if (!(kappa_lipid > 0.0))
    throw RunError(fmt::format("t = {:.6g} s: membrane \"{}\": bending_modulus {:g} pN nm: curvature sensing "
                               "needs it > 0", t, membrane.name(), kappa_lipid));
  const CurvatureSensingConfig& p = *c.curvature;
  interaction.onsite_start.assign(1, 0);
  interaction.onsite.clear();
  for (Index v = 0; v < cells.count(); ++v) {
    // φ = m A_p/|C| reaches 1 at m = ⌈|C|/A_p⌉; a footprint caps the copies before that.
    double last = std::ceil(cells.size[v] / p.area);
    if (c.footprint > 0.0) last = std::min(last, std::floor(cells.size[v] / c.footprint));
    for (int m = 0; m <= static_cast<int>(last); ++m)
      interaction.onsite.push_back(
          curvatureSensingEnergy(p, kappa_lipid, lipid_curvature, curvature[v], m, cells.size[v]) / thermal_energy_);
    interaction.onsite_start.push_back(static_cast<Index>(interaction.onsite.size()));
  }
}

void SurfaceSpeciesFeedback::setUnbindingFactors(Index surface, const std::string& membrane_name,
                                                 const std::vector<std::vector<double>>& potentials, Index vertices,
                                                 double t) const {
  const Index start = engine_.regionStart(surface + 1);
  for (const Unbinding& u : unbinding_) {
    if (u.surface != surface) continue;
    for (Index v = 0; v < vertices; ++v) {
      double exponent = 0.0;
      for (const auto& [j, count] : u.reactants) exponent += count * potentials[j][v];
      // e^700 is near the largest double: a copy that bound so firmly would unbind at
      // more than 1e300 /s.
      if (!(exponent < 700.0)) {
        const Surface& s = surfaces_[static_cast<std::size_t>(surface)];
        std::string species;
        for (const auto& [j, count] : u.reactants)
          species += fmt::format("{}\"{}\" (membrane.{}.species.{}.potential)", species.empty() ? "" : ", ",
                                 s.configs[static_cast<std::size_t>(j)].name, s.membrane, j);
        throw RunError(fmt::format("t = {:.6g} s: membrane \"{}\": the potential of {} is {:.3g} k_BT at vertex {}: "
                                   "unbinding at r e^(beta V) overflows there; check the potential's parameters",
                                   t, membrane_name, species, exponent, v));
      }
      factors_.set(u.reaction, start + v, std::exp(exponent));
    }
  }
}

void SurfaceSpeciesFeedback::collect(System& system) const {
  for (std::size_t k = 0; k < surfaces_.size(); ++k) {
    const Surface& s = surfaces_[k];
    Membrane& membrane = *system.membranes()[s.membrane];
    const Index start = engine_.regionStart(static_cast<Index>(k) + 1);
    const Index n = membrane.mesh().numVertices();
    for (std::size_t j = 0; j < s.species.size(); ++j) {
      std::vector<int>& c = membrane.speciesCopies(static_cast<Index>(j));
      for (Index v = 0; v < n; ++v) c[v] = engine_.copies(start + v, s.species[j]);
    }
  }
}

}  // namespace cortex
