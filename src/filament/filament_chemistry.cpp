#include "filament/filament_chemistry.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <stdexcept>

#include "core/error.hpp"

namespace cortex {

namespace {

bool isBinding(FilamentReaction k) {
  return k == FilamentReaction::kLinkerBind || k == FilamentReaction::kMotorBind || k == FilamentReaction::kBranch;
}

}  // namespace

FilamentChemistry::FilamentChemistry(FilamentNetwork& network, const CompartmentGrid& grid,
                                     const std::vector<SpeciesDef>& species_defs, double kT)
    : net_(network), grid_(grid), walls_(wallsOf(network.config(), Vec3::Zero(), grid.extent(), 0.0)), kT_(kT) {
  const auto species = static_cast<Index>(species_defs.size());
  auto check = [&](Index s, const std::string& what) {
    if (s < 0 || s >= species) throw InputError(fmt::format("{}: its species is not a [[species]]", what));
  };
  for (const FilamentType& t : net_.config().types)
    if (t.plus_on > 0 || t.plus_off > 0 || t.minus_on > 0 || t.minus_off > 0 || t.nucleation_rate > 0)
      check(t.monomer_species_index, "[[filament_type]] \"" + t.name + "\"");
  for (const LinkerType& l : net_.config().linkers) check(l.species_index, "[[linker]] \"" + l.name + "\"");
  for (const MotorType& m : net_.config().motors) check(m.species_index, "[[motor]] \"" + m.name + "\"");
  for (const BrancherType& b : net_.config().branchers) check(b.species_index, "[[brancher]] \"" + b.name + "\"");
}

void FilamentChemistry::addReactions(ChemistryModel& model) {
  const double nv = grid_.copiesPerMicromolar();
  std::vector<ReactionDef> defs;
  const auto first = static_cast<Index>(model.reactions.size());
  auto add = [&](FilamentReaction kind, Index type, std::string equation, std::vector<Stoichiometry> reactants,
                 std::vector<Stoichiometry> products, double rate) {
    auto& row = lookup_[static_cast<int>(kind)];
    if (static_cast<Index>(row.size()) <= type) row.resize(type + 1, -1);
    if (!(rate > 0.0)) return;
    ReactionDef d;
    d.equation = std::move(equation);
    d.reactants = std::move(reactants);
    d.products = std::move(products);
    d.rate = rate;
    d.per_site = kind != FilamentReaction::kNucleate;  // nucleation is volumetric mass action
    row[type] = static_cast<Index>(channels_.size());
    channels_.push_back({kind, type, first + static_cast<Index>(defs.size())});
    defs.push_back(std::move(d));
  };
  using K = FilamentReaction;
  // Per-site rates: order-1 reactions keep their constant as is, order-0 ones are
  // multiplied by the copies per µM (stochasticRateConstant), hence the divisions by nv.
  const FilamentConfig& cfg = net_.config();
  for (Index t = 0; t < static_cast<Index>(cfg.types.size()); ++t) {
    const FilamentType& f = cfg.types[t];
    const Index m = f.monomer_species_index;
    add(K::kPlusGrow, t, f.name + " plus-end growth", {{m, 1}}, {}, f.plus_on / nv);
    add(K::kPlusShrink, t, f.name + " plus-end shrinkage", {}, {{m, 1}}, f.plus_off / nv);
    add(K::kMinusGrow, t, f.name + " minus-end growth", {{m, 1}}, {}, f.minus_on / nv);
    add(K::kMinusShrink, t, f.name + " minus-end shrinkage", {}, {{m, 1}}, f.minus_off / nv);
    add(K::kNucleate, t, f.name + " nucleation", {{m, 2}}, {}, f.nucleation_rate);
  }
  for (Index i = 0; i < static_cast<Index>(cfg.linkers.size()); ++i) {
    const LinkerType& l = cfg.linkers[i];
    add(K::kLinkerBind, i, l.name + " binding", {{l.species_index, 1}}, {}, l.on_rate / nv);
    add(K::kLinkerUnbind, i, l.name + " unbinding", {}, {{l.species_index, 1}}, l.off_rate / nv);
  }
  for (Index i = 0; i < static_cast<Index>(cfg.motors.size()); ++i) {
    const MotorType& m = cfg.motors[i];
    add(K::kMotorBind, i, m.name + " binding", {{m.species_index, 1}}, {}, m.on_rate / nv);
    add(K::kMotorUnbind, i, m.name + " unbinding", {}, {{m.species_index, 1}}, m.off_rate / nv);
    add(K::kMotorWalk, i, m.name + " walking", {}, {}, m.walk_rate / nv);
  }
  for (Index i = 0; i < static_cast<Index>(cfg.branchers.size()); ++i) {
    const BrancherType& b = cfg.branchers[i];
    // The daughter's first monomer is an actin from the pool (MEDYAN's branching reaction
    // consumes the complex and one monomer), so actin is conserved through unbranching.
    const Index monomer = cfg.types[b.filament_type_index].monomer_species_index;
    add(K::kBranch, i, b.name + " branching", {{b.species_index, 1}, {monomer, 1}}, {}, b.rate / nv);
    add(K::kUnbranch, i, b.name + " unbranching", {}, {{b.species_index, 1}}, b.unbranch_rate / nv);
  }
  range_ = model.addReactions("filaments", std::move(defs));
  // The engine starts every rate factor at 1.
  factor_.assign(channels_.size() * static_cast<std::size_t>(grid_.count()), 1.0);
  pending_.assign(factor_.size(), 0.0);
  for (auto& side : ends_in_) side.assign(grid_.count(), {});
  is_dirty_.assign(factor_.size(), 0);
  candidates_.assign(channels_.size(), BindingCandidates{});
}

void FilamentChemistry::setNucleationSide(Index type, Side side) {
  if (static_cast<std::size_t>(type) >= nucleation_side_.size()) nucleation_side_.resize(type + 1);
  nucleation_side_[type] = std::move(side);
}

void FilamentChemistry::attach(ChemistryEngine& engine) {
  factors_ = engine.claimRateFactors(range_);
  engine.setReactionHook(range_, this);
}

Index FilamentChemistry::channelOf(FilamentReaction kind, Index type) const {
  const auto& row = lookup_[static_cast<int>(kind)];
  return type < static_cast<Index>(row.size()) ? row[type] : -1;
}

// --- force-dependent laws -------------------------------------------------------------

// Force-dependent speed-ups are capped at kMaxFactor times the zero-force rate: beyond
// that the bond breaks within the window anyway, and unbounded weights (e^700 = inf)
// would swamp the other objects' weights in the rate-factor sums.
constexpr double kMaxFactor = 1e6;

double FilamentChemistry::slipFactor(const LinkerType& l, double tension) const {
  return std::min(kMaxFactor, std::exp(std::min(std::abs(tension) * l.slip_length / kT_, 50.0)));
}

// With heads (parallel cluster model, low duty ratio): the ensemble detaches at the
// inverse of its mean unloaded lifetime ((1 + k_h/k_off)^N - 1)/(N k_h) (Erdmann &
// Schwarz), the load F is shared by the N_b(F) = rho N + beta F/N bound heads of the
// catch bond (more heads stay bound under load), and the ensemble steps each time one of
// its N - N_b free heads binds, per bound head.
double FilamentChemistry::boundHeads(const MotorType& m, double tension, int heads) {
  const double n = heads;
  return n * m.head_binding_rate / (m.head_binding_rate + m.off_rate) + m.head_load * std::max(tension, 0.0) / n;
}

double FilamentChemistry::catchFactor(const MotorType& m, double tension, int heads) {
  if (heads <= 0) return tension > 0.0 ? std::exp(-tension / m.catch_force) : 1.0;
  if (m.off_rate <= 0.0) return 0.0;
  const double n = heads, kh = m.head_binding_rate;
  // (1 + x)^N − 1 as expm1(N log1p(x)): exact where x = k_h/k_off is below round-off
  // (the pow form gave 0/0 and a rate factor that was not a number).
  const double unloaded = n * kh / std::expm1(n * std::log1p(kh / m.off_rate)) / m.off_rate;
  return tension > 0.0 ? unloaded * std::exp(-tension / (boundHeads(m, tension, heads) * m.catch_force)) : unloaded;
}

double FilamentChemistry::walkFactor(const MotorType& m, double tension, int heads) {
  double ensemble = 1.0;
  if (heads > 0) {
    const double bound = boundHeads(m, tension, heads);
    ensemble = std::clamp((heads - bound) / bound, 0.0, kMaxFactor);  // (N - N_b)/N_b, capped like the others
  }
  if (tension <= 0.0) return ensemble;
  return ensemble * std::max(0.0, (m.stall_force - tension) / (m.stall_force + tension / m.hill_alpha));
}

double FilamentChemistry::maxEndLoad() const {
  double max = 0.0;
  for (const auto& ends : load_) max = std::max({max, ends[0], ends[1]});
  return max;
}

// --- after each minimization --------------------------------------------------------------

void FilamentChemistry::update(const std::vector<std::array<Vec3, 2>>& end_forces) {
  computeLoads(end_forces);
  locateBound();
  findCandidates();
  rebuildFactors();
  flush();
}

// Every end's load from the contact forces of the relaxation just done.
void FilamentChemistry::computeLoads(const std::vector<std::array<Vec3, 2>>& end_forces) {
  const auto& fils = net_.filaments();
  if (end_forces.size() != fils.size())
    throw std::logic_error("FilamentChemistry::update: one pair of end forces per filament");
  ratchet_.assign(fils.size(), {1.0, 1.0});
  load_.assign(fils.size(), {0.0, 0.0});
  relaxed_force_ = end_forces;
  probe_force_.assign(fils.size(), {Vec3::Zero(), Vec3::Zero()});
  for (std::size_t i = 0; i < fils.size(); ++i)
    for (int e = 0; e < 2; ++e) {
      const Index f = static_cast<Index>(i);
      if (probe_) {
        // The probe's bodies weighed over the growth step where they say how.
        const Vec3& x = endBead(f, e == 1);
        const Vec3 correction = probe_->stepCorrection(f, x, e == 1, growthStep(f, e == 1));
        probe_force_[i][e] = probe_->forceAt(f, x, e == 1) + correction;
        relaxed_force_[i][e] += correction;
      }
      loadEnd(f, e == 1, relaxed_force_[i][e]);
    }
}

Vec3 FilamentChemistry::growthStep(Index i, bool plus_end) const {
  const Filament& f = net_.filaments()[i];
  return (plus_end ? f.plusDirection() : f.minusDirection()) * net_.type(f.type).monomer_size;
}

// Brownian ratchet (thesis eq. 2.14): a load f opposing growth slows it by
// exp(-f delta / kT); a pulling force does not speed it beyond free growth. f is the
// mean over the step where the probe knows it (EndLoadProbe::stepCorrection): f delta is
// then the step's energy change.
void FilamentChemistry::loadEnd(Index i, bool plus_end, const Vec3& force) {
  const Filament& f = net_.filaments()[i];
  const int e = plus_end ? 1 : 0;
  const Vec3 u = plus_end ? f.plusDirection() : f.minusDirection();
  load_[i][e] = std::max(0.0, -force.dot(u));
  ratchet_[i][e] = std::exp(-load_[i][e] * net_.type(f.type).monomer_size / kT_);
}

// The membranes stand still during a window, but in the quasi-static picture of the
// ratchet they relax much faster than an end grows: one the end has withdrawn from would
// have followed it. So an end's load never drops below the relaxed one within a window
// (taking the probe's lower value after a shrink step overestimated the stall force
// against a tensed patch by 20%), and it rises to the probe's when the end advances into
// the membrane as it stood (which keeps a second growth step from carrying it through).
void FilamentChemistry::reload(Index i, bool plus_end) {
  if (!probe_) return;
  const int e = plus_end ? 1 : 0;
  // A filament made since the last relaxation (a nucleus, a branch) has no relaxed load:
  // the probe's alone. Unloaded, a nucleus formed beside a membrane grew through it
  // within the window.
  const bool relaxed = static_cast<std::size_t>(i) < relaxed_force_.size();
  const Vec3 before = relaxed ? relaxed_force_[i][e] : Vec3::Zero();
  const Vec3& x = endBead(i, plus_end);
  const Vec3 probed = before - (relaxed ? probe_force_[i][e] : Vec3::Zero()) + probe_->forceAt(i, x, plus_end) +
                      probe_->stepCorrection(i, x, plus_end, growthStep(i, plus_end));
  const Filament& f = net_.filaments()[i];
  const Vec3 u = plus_end ? f.plusDirection() : f.minusDirection();
  loadEnd(i, plus_end, probed.dot(u) < before.dot(u) ? probed : before);
}

void FilamentChemistry::track(Index i) {
  if (ratchet_.size() > static_cast<std::size_t>(i)) return;
  ratchet_.resize(i + 1, {1.0, 1.0});  // unloaded until loaded (addNew) or relaxed
  load_.resize(i + 1, {0.0, 0.0});
}

void FilamentChemistry::addNew(Index i) {
  track(i);
  reload(i, true);
  if (net_.filaments()[i].minusEndActive()) reload(i, false);
  contributeEnds(i, 1.0);
}

// Bound proteins fire in the compartment of their first site.
void FilamentChemistry::locateBound() {
  for (BinderKind kind : {BinderKind::kLinker, BinderKind::kMotor})
    for (Binding& b : net_.bound(kind)) b.compartment = compartmentOf(net_.sitePosition(kind, b.type, b.filament[0], b.site[0]));
  for (Branch& b : net_.branches()) b.compartment = compartmentOf(net_.filaments()[b.daughter].beads.front());
}

void FilamentChemistry::findCandidates() {
  const FilamentConfig& cfg = net_.config();
  for (std::size_t ch = 0; ch < channels_.size(); ++ch) {
    const Channel& c = channels_[ch];
    if (c.kind == FilamentReaction::kLinkerBind) {
      const LinkerType& l = cfg.linkers[c.type];
      candidates_[ch] = BindingCandidates(net_, grid_, BinderKind::kLinker, c.type, l.min_distance, l.max_distance, 1);
    } else if (c.kind == FilamentReaction::kMotorBind) {
      const MotorType& m = cfg.motors[c.type];
      const int every = std::max(1, static_cast<int>(std::lround(static_cast<double>(m.site_spacing) /
                                                                 net_.spacing(BinderKind::kMotor, c.type))));
      candidates_[ch] =
          BindingCandidates(net_, grid_, BinderKind::kMotor, c.type, m.min_distance, m.max_distance, every);
    } else if (c.kind == FilamentReaction::kBranch) {
      candidates_[ch] = findBranchSites(net_, grid_, c.type);
    }
  }
}

// --- rate factors ------------------------------------------------------------------------

void FilamentChemistry::contribute(FilamentReaction kind, Index type, Index c, double w) {
  const Index ch = channelOf(kind, type);
  if (ch < 0) return;
  const std::size_t i = static_cast<std::size_t>(ch) * grid_.count() + c;
  pending_[i] += w;
  if (!is_dirty_[i]) {
    is_dirty_[i] = 1;
    dirty_.push_back(i);
  }
}

// Buckets stay sorted, so a pick visits ends in filament order whatever the history:
// a resumed run, whose buckets are refiled from scratch, picks the same ends.
void FilamentChemistry::file(std::vector<Index>& bucket, Index i, double sign) {
  const auto at = std::lower_bound(bucket.begin(), bucket.end(), i);
  if (sign > 0)
    bucket.insert(at, i);
  else if (at != bucket.end() && *at == i)
    bucket.erase(at);
}

void FilamentChemistry::contributeEnds(Index i, double sign) {
  using K = FilamentReaction;
  const Filament& f = net_.filaments()[i];
  track(i);
  if (end_compartment_.size() <= static_cast<std::size_t>(i)) end_compartment_.resize(i + 1, {0, 0});
  // Adding (+1) records where the ends are now and files them in their compartments'
  // buckets; removing (-1) uses the record, so the two always cancel and picks (fireEnd)
  // see the same ends the rate factors count.
  if (sign > 0) end_compartment_[i] = {compartmentOf(f.beads.front()), compartmentOf(f.beads.back())};
  const Index plus = end_compartment_[i][1];
  file(ends_in_[1][plus], i, sign);
  contribute(K::kPlusGrow, f.type, plus, sign * ratchet_[i][1]);
  contribute(K::kPlusShrink, f.type, plus, sign);
  if (!f.minusEndActive()) return;
  const Index minus = end_compartment_[i][0];
  file(ends_in_[0][minus], i, sign);
  contribute(K::kMinusGrow, f.type, minus, sign * ratchet_[i][0]);
  contribute(K::kMinusShrink, f.type, minus, sign);
}

void FilamentChemistry::contributeBinding(BinderKind kind, const Binding& b, double sign) {
  using K = FilamentReaction;
  if (kind == BinderKind::kLinker) {
    contribute(K::kLinkerUnbind, b.type, b.compartment, sign * slipFactor(net_.config().linkers[b.type], b.tension));
    return;
  }
  const MotorType& m = net_.config().motors[b.type];
  contribute(K::kMotorUnbind, b.type, b.compartment, sign * catchFactor(m, b.tension, b.heads));
  contribute(K::kMotorWalk, b.type, b.compartment, sign * 2.0 * walkFactor(m, b.tension, b.heads));
}

void FilamentChemistry::contributeBranch(const Branch& b, double sign) {
  contribute(FilamentReaction::kUnbranch, b.type, b.compartment, sign);
}

void FilamentChemistry::rebuildFactors() {
  const Index C = grid_.count();
  std::fill(pending_.begin(), pending_.end(), 0.0);
  for (auto& side : ends_in_) side.assign(grid_.count(), {});
  for (Index i = 0; i < static_cast<Index>(net_.filaments().size()); ++i) contributeEnds(i, 1.0);
  for (BinderKind kind : {BinderKind::kLinker, BinderKind::kMotor})
    for (const Binding& b : net_.bound(kind)) contributeBinding(kind, b, 1.0);
  for (const Branch& b : net_.branches()) contributeBranch(b, 1.0);
  for (std::size_t ch = 0; ch < channels_.size(); ++ch) {
    if (channels_[ch].kind == FilamentReaction::kNucleate)
      for (Index c = 0; c < C; ++c) pending_[ch * C + c] = 1.0;
    else if (isBinding(channels_[ch].kind))
      for (Index c = 0; c < C; ++c) pending_[ch * C + c] = static_cast<double>(candidates_[ch].count(c));
  }
  dirty_.clear();
  for (std::size_t i = 0; i < pending_.size(); ++i) {
    is_dirty_[i] = 1;
    dirty_.push_back(i);
  }
}

void FilamentChemistry::flush() {
  const Index C = grid_.count();
  for (const std::size_t i : dirty_) {
    is_dirty_[i] = 0;
    // Sums of +-contributions may leave rounding dust where nothing is left: a factor
    // without an object behind it only fires void events (thinning), but never < 0.
    const double f = std::max(0.0, pending_[i]);
    if (f == factor_[i]) continue;
    factor_[i] = f;
    factors_.set(channels_[i / C].reaction, static_cast<Index>(i % C), f);
  }
  dirty_.clear();
}

}  // namespace cortex
