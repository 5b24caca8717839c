#include "sim/system.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "filament/filament_terms.hpp"
#include "interact/inside_membrane.hpp"
#include "interact/membrane_bead_exclusion.hpp"
#include "interact/membrane_crossing.hpp"
#include "mech/resolvable_forces.hpp"
#include "membrane/membrane_terms.hpp"
#include "membrane/shape_relaxation.hpp"
#include "sim/chemistry_builder.hpp"
#include "sim/confinement.hpp"
#include "sim/filament_builder.hpp"
#include "sim/filament_feedback.hpp"
#include "sim/membrane_builder.hpp"
#include "sim/surface_species.hpp"

namespace cortex {

namespace {

// The config reader held the membrane–bead push against [mechanics] force_tolerance. Its
// forces also act on the membrane's vertices, and under "auto" a membrane relaxes to its
// own force scale when no tolerance is given (naturalForceTolerance, far below 0.1 pN for a soft
// vesicle): a push resolvable at 0.1 pN may not be there. Stiffness 1e11 pN·nm³ with a
// 250 nm cut-off on a 300 nm vesicle (own tolerance 0.005 pN) failed after 80 s.
//
// The own scale is taken no lower than kLowestBeadPushTolerance: a giant vesicle's falls
// to ~1e-8 pN (R = 20 µm at 100 nm edges), where even the default push (0.63 pN) would be
// refused, while what this guards against is a unit slip thousands of times the default.
constexpr double kLowestBeadPushTolerance = 1e-3;  // pN

void requireResolvableBeadPush(const Membrane& m, const MembraneBeadExclusionParams& p, const Config& config) {
  // Only the "auto" minimizer relaxes membranes by themselves, to their own scale.
  if (config.mechanics.force_tolerance_given || config.mechanics.kind != MinimizerKind::kAuto) return;
  const std::string problem = unresolvableForces(
      2 * constants::kPi * p.stiffness / std::pow(p.cutoff / 2, 3), "2π stiffness / (cutoff/2)³",
      std::max(kLowestBeadPushTolerance, naturalForceTolerance(m, 0.0)),
      fmt::format("membrane \"{}\"'s own force scale (at least {:g} pN), which its relaxations use when "
                  "[mechanics] force_tolerance is not given",
                  m.name(), kLowestBeadPushTolerance));
  if (!problem.empty()) throw InputError(fmt::format("{}: membrane_filament.stiffness: {}", config.source, problem));
}

}  // namespace

System::System(const Config& config, const SystemState* restored) {
  const auto seed = static_cast<std::uint64_t>(config.simulation.seed);
  // Bodies: membranes in config order, then the filament network.
  for (const MembraneConfig& mc : config.membranes) {
    const MembraneState* state = nullptr;
    if (restored) {
      const auto it = restored->membranes.find(mc.name);
      if (it == restored->membranes.end()) throw InputError(fmt::format("checkpoint has no membrane \"{}\"", mc.name));
      state = &it->second;
    }
    membranes_.push_back(buildMembrane(mc, config.source, state));
  }
  if (!restored) placeSurfaceSpecies(config.membranes, membranes_, seed, config.source);
  if (config.chemistry) grid_ = config.chemistry->grid;  // else the default grid bounds the filaments
  if (config.filaments) {
    if (restored && !restored->filaments) throw InputError("checkpoint has no filaments, the config has");
    try {
      // Filaments placed inside a membrane start clear of its interaction's cut-off.
      const double margin = (config.membrane_filament ? *config.membrane_filament : MembraneBeadExclusionParams{}).cutoff;
      filaments_ = buildFilamentNetwork(*config.filaments, Vec3::Zero(), grid_.extent(), seed,
                                        restored ? &*restored->filaments : nullptr,
                                        placementRegions(*config.filaments, membranes_, margin));
    } catch (const InputError& e) {
      // Placement names the [[filaments]] table; say which file it is in.
      if (restored) throw;
      throw InputError(fmt::format("{}: {}", config.source, e.what()));
    }
  }
  for (auto& m : membranes_) bodies_.push_back(m.get());
  if (filaments_) bodies_.push_back(filaments_.get());
  if (restored) {
    std::vector<std::string> names;
    for (const Body* b : bodies_) names.push_back(b->name());
    if (names != restored->bodies)
      throw InputError("checkpoint: its bodies (membranes, filaments) are not the config's, in the config's order");
  }
  layOut();

  // Every module's energy terms, in body order.
  for (auto& m : membranes_) addMembraneTerms(*m, force_field_);
  FilamentTerms filament_terms;
  if (filaments_) filament_terms = addFilamentTerms(*filaments_, force_field_);
  if (config.membrane_filament && filaments_)
    for (auto& m : membranes_) {
      // At the start only: a resumed run keeps what its start accepted, though the
      // membrane's own scale has moved with its shape since.
      if (!restored) requireResolvableBeadPush(*m, *config.membrane_filament, config);
      coupling_terms_.push_back(
          &force_field_.add(std::make_unique<MembraneBeadExclusion>(*m, *filaments_, *config.membrane_filament)));
    }
  if (config.chemistry) buildChemistry(config, restored, filament_terms);

  // Membranes do not interact: two that pass through each other would overlap their
  // insides (confined species in both) for the whole run. Refused here; a run in which
  // they come to meet stops (Simulation::checkMembranesApart).
  if (const auto c = findCrossingMembranes(membranes_))
    throw InputError(fmt::format("{}: at the start, membranes \"{}\" and \"{}\" pass through each other ({}): "
                                 "membranes do not push on each other in cortex, so they must start apart, one inside "
                                 "the other or side by side",
                                 config.source, c->a->name(), c->b->name(), c->where));
  for (const MembraneBeadExclusion* term : coupling_terms_)
    if (const auto crossing = findMembraneCrossing(term->membrane(), term->network()))
      throw InputError(fmt::format("{}: at the start, {}: place the filaments on one side of it", config.source,
                                   crossing->describe(term->membrane())));

  if (restored) {
    time_ = restored->time;
    step = restored->step;
    counters = restored->counters;
    force_field_.restoreCounters(restored->force_evaluations, restored->energy_evaluations);
  }
  setTime(time_);
  // Confinement and force-dependent rates follow from the positions: nothing is stored.
  // The state here is the config's (or the checkpoint's), so what cannot be fed back is
  // the input's fault (e.g. a potential whose energies overflow).
  try {
    updateFeedback();
  } catch (const RunError& e) {
    throw InputError(fmt::format("{}: {}", config.source, e.what()));
  }
}

System::~System() = default;

void System::buildChemistry(const Config& config, const SystemState* restored, const FilamentTerms& filament_terms) {
  const ChemistryConfig& cc = *config.chemistry;
  checkSlicingResolution(membranes_, cc);  // before anything is built on the slices
  if (const auto what = insideBeyondGrid(membranes_, cc.grid, cc.sides, cc.reaction_restrictions, cc.species, 0.0))
    throw InputError(config.source + ": " + *what);
  checkSurfaceReactionsCanFire(membranes_, cc, config.source);
  const auto seed = static_cast<std::uint64_t>(config.simulation.seed);
  chemistry_model_ = cortex::chemistryModel(cc);
  const ReactionRange config_reactions = chemistry_model_.ranges.front();
  if (filaments_) {
    filament_chemistry_ = std::make_unique<FilamentChemistry>(
        *filaments_, grid_, chemistry_model_.species, constants::kBoltzmann * config.simulation.temperature);
    filament_chemistry_->addReactions(chemistry_model_);
  }
  if (restored) {
    if (!restored->chemistry) throw InputError("checkpoint has no chemistry, the config has");
    const ChemistryState& s = *restored->chemistry;
    if (s.copies.size() != static_cast<std::size_t>(grid_.count()) * chemistry_model_.species.size() ||
        s.reaction_events.size() != chemistry_model_.reactions.size())
      throw InputError("checkpoint chemistry does not match the config (grid, species or reactions changed)");
    try {
      chemistry_ = makeChemistryEngine(cc.engine, chemistry_model_, s.copies, seed);
      chemistry_->restore(s);
    } catch (const std::invalid_argument& e) {
      throw InputError(fmt::format("checkpoint chemistry is damaged: {}", e.what()));
    }
  } else {
    // Confined species start uniform in the volume on their side of the membrane.
    std::vector<std::vector<double>> weights(cc.sides.size());
    const auto fractions = sideFractions(membranes_, cc.sides, grid_);
    for (std::size_t s = 0; s < fractions.size(); ++s)
      if (fractions[s]) weights[s] = fractions[s]->volume;
    chemistry_ = makeChemistryEngine(cc.engine, chemistry_model_, initialCopies(cc, seed, weights), seed);
  }
  chemistry_->setEventLimit(cc.max_events_per_window);
  // The config's reactions' factors: restricted 3D reactions' in the compartments
  // (confinement), unbinding reactions' on the vertices (surface species): disjoint.
  const RateFactors config_factors = chemistry_->claimRateFactors(config_reactions);
  feedback_.push_back(std::make_unique<ConfinementFeedback>(cc, *chemistry_, config_factors));
  if (!cc.surfaces.empty()) {
    auto surfaces = std::make_unique<SurfaceSpeciesFeedback>(
        cc, config.membranes, *chemistry_, membranes_, config_factors,
        constants::kBoltzmann * config.simulation.temperature);
    surface_species_ = surfaces.get();
    feedback_.push_back(std::move(surfaces));
  }
  if (filament_chemistry_) {
    filament_chemistry_->attach(*chemistry_);
    std::vector<EndLoadProbe*> probes;
    if (!coupling_terms_.empty()) {
      end_loads_ = std::make_unique<MembraneEndLoads>(
          std::vector<const MembraneBeadExclusion*>(coupling_terms_.begin(), coupling_terms_.end()));
      probes.push_back(end_loads_.get());
    }
    if (const auto& boundary = config.filaments->boundary) {
      wall_loads_ = std::make_unique<WallEndLoads>(*boundary);
      probes.push_back(wall_loads_.get());
    }
    cylinder_loads_ = std::make_unique<CylinderExclusionEndLoads>(*filaments_);
    probes.push_back(cylinder_loads_.get());
    end_load_sum_ = std::make_unique<EndLoadSum>(std::move(probes));
    filament_chemistry_->setEndLoadProbe(end_load_sum_.get());
    // Nuclei never form through a membrane the filaments push on (a dimer placed
    // straddling it stopped the run as a crossing) ...
    if (!coupling_terms_.empty())
      filament_chemistry_->setNucleationBlocked([this](const Vec3& p, const Vec3& q) {
        for (const MembraneBeadExclusion* term : coupling_terms_)
          if (segmentMeetsMembrane(term->membrane(), p, q)) return true;
        return false;
      });
    // ... and form where their monomers live: on the side of the membrane that confines
    // them (nuclei placed anywhere in the compartment grew filaments outside a vesicle
    // whose inside alone held the monomers, exit 0).
    for (std::size_t t = 0; t < config.filaments->types.size(); ++t) {
      const Index g = config.filaments->types[t].monomer_species_index;
      if (g < 0 || cc.sides[g].membrane.empty()) continue;
      const Membrane* m = &closedMembrane(membranes_, cc.sides[g].membrane, "filament nucleation");
      filament_chemistry_->setNucleationSide(static_cast<Index>(t), [m, outside = cc.sides[g].outside](const Vec3& p) {
        return (windingNumber(m->mesh(), p) > 0.5) != outside;
      });
    }
    feedback_.push_back(
        std::make_unique<FilamentFeedback>(*filaments_, filament_terms, *filament_chemistry_, end_load_sum_.get()));
  }
}

SystemState System::state() const {
  SystemState s;
  s.time = time_;
  s.step = step;
  s.counters = counters;
  s.force_evaluations = force_field_.forceEvaluations();
  s.energy_evaluations = force_field_.energyEvaluations();
  for (const Body* b : bodies_) s.bodies.push_back(b->name());
  for (const auto& m : membranes_) s.membranes.emplace(m->name(), membraneState(*m));
  if (chemistry_) s.chemistry = chemistry_->state();
  if (filaments_) s.filaments = filamentState(*filaments_);
  return s;
}

void System::updateFeedback() {
  for (auto& f : feedback_) f->update(*this);
}

void System::collectSurfaceCopies() {
  if (surface_species_) surface_species_->collect(*this);
}

std::array<Index, 2> System::closedSurfaceEdges() const {
  if (!surface_species_) return {0, 0};
  return {surface_species_->closedEdges().cotangent, surface_species_->closedEdges().drift};
}

void System::layOut() {
  Index offset = 0;
  for (Body* b : bodies_) {
    b->setOffset(offset);
    offset += b->numPoints();
  }
  std::vector<char> points(static_cast<std::size_t>(offset), 0);
  for (const Body* b : bodies_) b->frozen(points.data() + b->offset());
  std::vector<char> frozen;
  frozen.reserve(3 * points.size());
  for (char p : points) frozen.insert(frozen.end(), 3, p);
  force_field_.setFrozen(std::move(frozen));
}

void System::setTime(double t) {
  time_ = t;
  force_field_.setTime(t);
}

Index System::numVertices() const {
  Index n = 0;
  for (const auto& m : membranes_) n += m->mesh().numVertices();
  return n;
}

Index System::numDegreesOfFreedom() const {
  Index n = 0;
  for (const Body* b : bodies_) n += b->numPoints();
  return 3 * n;
}

Eigen::VectorXd System::coordinates() const {
  Eigen::VectorXd x(numDegreesOfFreedom());
  for (const Body* b : bodies_) b->gather(x.data() + 3 * b->offset());
  return x;
}

void System::setCoordinates(const Eigen::VectorXd& x) {
  for (Body* b : bodies_) b->scatter(x.data() + 3 * b->offset());
}

}  // namespace cortex
