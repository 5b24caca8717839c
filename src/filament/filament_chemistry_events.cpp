// FilamentChemistry's events: what each hooked reaction does to the network when the
// engine fires it (the bookkeeping of rate factors is in filament_chemistry.cpp).
#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "filament/filament_chemistry.hpp"

namespace cortex {

bool FilamentChemistry::fired(Index reaction, Index compartment, ChemistryEngine& engine, RandomStream& random) {
  // The engine calls this hook for its own reactions only, one channel each, in order.
  const auto it = channels_.begin() + (reaction - range_.begin);
  using K = FilamentReaction;
  bool done = false;
  switch (it->kind) {
    case K::kPlusGrow:
    case K::kPlusShrink:
    case K::kMinusGrow:
    case K::kMinusShrink:
      done = fireEnd(*it, compartment, engine, random);
      break;
    case K::kNucleate:
      done = fireNucleation(*it, compartment, random);
      break;
    case K::kLinkerBind:
    case K::kMotorBind:
      done = fireBind(*it, compartment, random);
      break;
    case K::kLinkerUnbind:
    case K::kMotorUnbind:
      done = fireUnbind(*it, compartment, random);
      break;
    case K::kMotorWalk:
      done = fireWalk(*it, compartment, random);
      break;
    case K::kBranch:
      done = fireBranch(*it, compartment, random);
      break;
    case K::kUnbranch:
      done = fireUnbranch(*it, compartment, random);
      break;
  }
  flush();
  return done;
}

// Picks an index among n items with weights weight(i) (only those with weight > 0 count);
// -1 if the total is zero.
template <class Weight>
static Index pickWeighted(Index n, Weight&& weight, RandomStream& random) {
  double total = 0.0;
  for (Index i = 0; i < n; ++i) total += weight(i);
  if (!(total > 0.0)) return -1;
  double x = random.uniform() * total;
  Index last = -1;
  for (Index i = 0; i < n; ++i) {
    const double w = weight(i);
    if (!(w > 0.0)) continue;
    last = i;
    if (x < w) return i;
    x -= w;
  }
  return last;  // rounding at the very end
}

bool FilamentChemistry::fireEnd(const Channel& ch, Index c, ChemistryEngine& engine, RandomStream& random) {
  using K = FilamentReaction;
  const bool plus = ch.kind == K::kPlusGrow || ch.kind == K::kPlusShrink;
  const bool grow = ch.kind == K::kPlusGrow || ch.kind == K::kMinusGrow;
  const auto& fils = net_.filaments();
  const std::vector<Index>& here = ends_in_[plus ? 1 : 0][c];
  const Index k = pickWeighted(
      static_cast<Index>(here.size()),
      [&](Index j) {
        const Index i = here[j];
        if (fils[i].type != ch.type) return 0.0;
        return grow ? ratchet_[i][plus ? 1 : 0] : 1.0;
      },
      random);
  if (k < 0) return false;
  const Index f = here[k];
  if (grow) {
    contributeEnds(f, -1.0);
    net_.grow(f, plus);
    reload(f, plus);
    contributeEnds(f, 1.0);
    return true;
  }
  if (fils[f].monomers() <= net_.minimumMonomers(fils[f])) return false;  // at its smallest: nothing to lose
  contributeEnds(f, -1.0);
  released_.clear();
  net_.shrink(f, plus, released_);
  reload(f, plus);
  if (released_.empty()) {
    contributeEnds(f, 1.0);
  } else {
    // Proteins came off (rare): recount everything rather than track each one.
    release(released_, engine);
    rebuildFactors();
  }
  return true;
}

void FilamentChemistry::release(const std::vector<Release>& released, ChemistryEngine& engine) {
  for (const Release& r : released) {
    const Index c = compartmentOf(r.where);
    engine.setCopies(c, r.species, engine.copies(c, r.species) + 1);
  }
}

bool FilamentChemistry::fireNucleation(const Channel& ch, Index c, RandomStream& random) {
  // Draws until the dimer lies on its monomers' side of a confining membrane (uniform in
  // that part of the compartment); past this many the compartment's part there is too
  // small to find (under 1e-4 of it: then P(void) > 1/e) and the event is void.
  constexpr int kMostDraws = 10'000;
  const FilamentType& t = net_.type(ch.type);
  const Side* side = static_cast<std::size_t>(ch.type) < nucleation_side_.size() && nucleation_side_[ch.type]
                         ? &nucleation_side_[ch.type]
                         : nullptr;
  const auto ijk = grid_.coords(c);
  const Vec3 corner(ijk[0] * grid_.size, ijk[1] * grid_.size, ijk[2] * grid_.size);
  for (int draw = 0; draw < kMostDraws; ++draw) {
    const Vec3 at = corner + grid_.size * Vec3(random.uniform(), random.uniform(), random.uniform());
    Filament f = makeStraightFilament(ch.type, at, uniformDirection(random), 2, t.cylinder_monomers, t.monomer_size);
    if (side && !((*side)(f.beads.front()) && (*side)(f.beads.back()))) continue;
    // Nucleation happens only inside the boundary: thinning by the fraction of the
    // compartment (or of its part on the monomers' side) that lies inside.
    if (!walls_.contains(f.beads.front()) || !walls_.contains(f.beads.back())) return false;
    if (nucleation_blocked_ && nucleation_blocked_(f.beads.front(), f.beads.back())) return false;
    addNew(net_.addFilament(std::move(f)));
    return true;
  }
  return false;
}

bool FilamentChemistry::fireBind(const Channel& ch, Index c, RandomStream& random) {
  const BinderKind kind = ch.kind == FilamentReaction::kMotorBind ? BinderKind::kMotor : BinderKind::kLinker;
  const BindingCandidates& cand = candidates_[&ch - channels_.data()];
  if (cand.count(c) == 0) return false;
  const BindingCandidate p = cand.pick(c, random.uniform());
  // The candidate list is from the last minimization: a site since lost or taken makes
  // this a void event (thinning).
  for (int e = 0; e < 2; ++e)
    if (!net_.siteExists(kind, ch.type, p.filament[e], p.site[e]) ||
        net_.occupied(kind, ch.type, p.filament[e], p.site[e]))
      return false;
  Binding b;
  b.type = ch.type;
  b.filament = p.filament;
  b.site = {p.site[0], p.site[1]};
  b.rest_length = (net_.sitePosition(kind, ch.type, p.filament[1], p.site[1]) -
                   net_.sitePosition(kind, ch.type, p.filament[0], p.site[0]))
                      .norm();
  b.compartment = c;
  if (kind == BinderKind::kMotor) {
    const MotorType& m = net_.config().motors[ch.type];
    if (m.heads_max > 0)
      b.heads = m.heads_min + std::min(m.heads_max - m.heads_min,
                                       static_cast<int>(random.uniform() * (m.heads_max - m.heads_min + 1)));
    ++net_.events().motor_bindings;
  } else {
    ++net_.events().linker_bindings;
  }
  net_.bind(kind, b);
  contributeBinding(kind, b, 1.0);
  return true;
}

bool FilamentChemistry::fireUnbind(const Channel& ch, Index c, RandomStream& random) {
  const BinderKind kind = ch.kind == FilamentReaction::kMotorUnbind ? BinderKind::kMotor : BinderKind::kLinker;
  const auto& bound = net_.bound(kind);
  const Index i = pickWeighted(
      static_cast<Index>(bound.size()),
      [&](Index k) {
        const Binding& b = bound[k];
        if (b.type != ch.type || b.compartment != c) return 0.0;
        return kind == BinderKind::kLinker ? slipFactor(net_.config().linkers[b.type], b.tension)
                                           : catchFactor(net_.config().motors[b.type], b.tension, b.heads);
      },
      random);
  if (i < 0) return false;
  contributeBinding(kind, bound[i], -1.0);
  ++(kind == BinderKind::kMotor ? net_.events().motor_unbindings : net_.events().linker_unbindings);
  net_.unbind(kind, static_cast<std::size_t>(i));
  return true;
}

bool FilamentChemistry::fireWalk(const Channel& ch, Index c, RandomStream& random) {
  const auto& motors = net_.motors();
  // Items are motor ends: 2k and 2k + 1 for motor k.
  const Index i = pickWeighted(
      static_cast<Index>(2 * motors.size()),
      [&](Index k) {
        const Binding& b = motors[k / 2];
        if (b.type != ch.type || b.compartment != c) return 0.0;
        return walkFactor(net_.config().motors[b.type], b.tension, b.heads);
      },
      random);
  if (i < 0) return false;
  if (!net_.walk(static_cast<std::size_t>(i / 2), i % 2)) return false;  // blocked: void (thinning)
  ++net_.events().motor_steps;
  return true;
}

bool FilamentChemistry::fireBranch(const Channel& ch, Index c, RandomStream& random) {
  const BindingCandidates& cand = candidates_[&ch - channels_.data()];
  if (cand.count(c) == 0) return false;
  const BindingCandidate site = cand.pick(c, random.uniform());
  const Index mother = site.filament[0];
  if (!net_.siteExists(BinderKind::kBrancher, ch.type, mother, site.site[0]) ||
      net_.occupied(BinderKind::kBrancher, ch.type, mother, site.site[0]))
    return false;
  const Filament& m = net_.filaments()[mother];
  const auto [cyl, w] = m.locate(net_.siteCoordinate(BinderKind::kBrancher, ch.type, site.site[0]));
  const Vec3 u = (m.beads[cyl + 1] - m.beads[cyl]).normalized();
  // Daughter direction: the branch angle away from the mother's axis, in a random plane.
  Vec3 v = uniformDirection(random);
  v = (v - v.dot(u) * u).normalized();
  const double angle = net_.config().branchers[ch.type].angle * constants::kPi / 180.0;
  const Index daughter = net_.branch(ch.type, mother, site.site[0], std::cos(angle) * u + std::sin(angle) * v);
  net_.branches().back().compartment = c;
  addNew(daughter);
  contributeBranch(net_.branches().back(), 1.0);
  return true;
}

bool FilamentChemistry::fireUnbranch(const Channel& ch, Index c, RandomStream& random) {
  const auto& branches = net_.branches();
  const Index i = pickWeighted(
      static_cast<Index>(branches.size()),
      [&](Index k) {
        const Branch& b = branches[k];
        return b.type == ch.type && b.compartment == c ? 1.0 : 0.0;
      },
      random);
  if (i < 0) return false;
  const Index daughter = branches[i].daughter;
  contributeEnds(daughter, -1.0);  // its minus end comes free
  contributeBranch(branches[i], -1.0);
  net_.unbranch(static_cast<std::size_t>(i));
  contributeEnds(daughter, 1.0);
  return true;
}

}  // namespace cortex
