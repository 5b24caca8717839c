#include "filament/filament_chemistry.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <unordered_map>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "filament/boundary_energy.hpp"

namespace cortex {

namespace {

double copiesPerMicromolar(const CompartmentGrid& grid) {
  return kCopiesPerMicromolarFemtoliter * grid.volume() * 1e-9;
}

Vec3 randomDirection(RandomStream& random) {
  const double z = 2.0 * random.uniform() - 1.0;
  const double phi = 2.0 * constants::kPi * random.uniform();
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

bool isBinding(FilamentReaction k) {
  return k == FilamentReaction::kLinkerBind || k == FilamentReaction::kMotorBind || k == FilamentReaction::kBranch;
}

}  // namespace

FilamentChemistry::FilamentChemistry(FilamentNetwork& network, const ChemistryModel& model, double kT)
    : net_(network), grid_(model.grid), kT_(kT) {
  const auto species = static_cast<Index>(model.species.size());
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
  const double nv = copiesPerMicromolar(grid_);
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
    d.hooked = true;
    row[type] = static_cast<Index>(channels_.size());
    channels_.push_back({kind, type, static_cast<Index>(model.reactions.size())});
    model.reactions.push_back(std::move(d));
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
    add(K::kBranch, i, b.name + " branching", {{b.species_index, 1}}, {}, b.rate / nv);
    add(K::kUnbranch, i, b.name + " unbranching", {}, {{b.species_index, 1}}, b.unbranch_rate / nv);
  }
  // The engine starts every rate factor at 1.
  factor_.assign(channels_.size() * static_cast<std::size_t>(grid_.count()), 1.0);
  candidates_.assign(channels_.size(), Candidates{std::vector<Index>(grid_.count() + 1, 0), {}});
}

Index FilamentChemistry::channelOf(FilamentReaction kind, Index type) const {
  const auto& row = lookup_[static_cast<int>(kind)];
  return type < static_cast<Index>(row.size()) ? row[type] : -1;
}

// --- force-dependent laws -------------------------------------------------------------

double FilamentChemistry::slipFactor(const LinkerType& l, double tension) const {
  return std::exp(std::abs(tension) * l.slip_length / kT_);
}

double FilamentChemistry::catchFactor(const MotorType& m, double tension) {
  return tension > 0.0 ? std::exp(-tension / m.catch_force) : 1.0;
}

double FilamentChemistry::walkFactor(const MotorType& m, double tension) {
  if (tension <= 0.0) return 1.0;
  return std::max(0.0, (m.stall_force - tension) / (m.stall_force + tension / m.hill_alpha));
}

// --- after each minimization --------------------------------------------------------------

void FilamentChemistry::updateMechanochemistry(ChemistryEngine& engine) {
  computeLoads();
  computeTensions();
  findCandidates();
  syncFactors(engine);
}

void FilamentChemistry::computeLoads() {
  const auto& fils = net_.filaments();
  ratchet_.assign(fils.size(), {1.0, 1.0});
  load_.assign(fils.size(), {0.0, 0.0});
  const auto& boundary = net_.config().boundary;
  if (!boundary) return;
  for (std::size_t i = 0; i < fils.size(); ++i) {
    const Filament& f = fils[i];
    const double delta = net_.type(f.type).monomer_size;
    for (int e = 0; e < 2; ++e) {
      const Vec3& tip = e ? f.beads.back() : f.beads.front();
      const Vec3 u = e ? f.plusDirection() : f.minusDirection();
      // Brownian ratchet (thesis eq. 2.14): a load f opposing growth slows it by
      // exp(-f delta / kT); a pulling force does not speed it beyond free growth.
      const double load = std::max(0.0, -boundaryForce(*boundary, tip).dot(u));
      load_[i][e] = load;
      ratchet_[i][e] = std::exp(-load * delta / kT_);
    }
  }
}

void FilamentChemistry::computeTensions() {
  for (BinderKind kind : {BinderKind::kLinker, BinderKind::kMotor})
    for (Binding& b : net_.bound(kind)) {
      const double k = kind == BinderKind::kLinker ? net_.config().linkers[b.type].stiffness
                                                   : net_.config().motors[b.type].stiffness;
      const double l = (net_.sitePosition(kind, b.type, b.filament[1], b.site[1]) -
                        net_.sitePosition(kind, b.type, b.filament[0], b.site[0]))
                           .norm();
      b.tension = k * (l - b.rest_length);
    }
}

void FilamentChemistry::findCandidates() {
  const FilamentConfig& cfg = net_.config();
  for (std::size_t ch = 0; ch < channels_.size(); ++ch) {
    const Channel& c = channels_[ch];
    if (c.kind == FilamentReaction::kLinkerBind) {
      const LinkerType& l = cfg.linkers[c.type];
      candidates_[ch] = pairsFor(BinderKind::kLinker, c.type, l.min_distance, l.max_distance, 1);
    } else if (c.kind == FilamentReaction::kMotorBind) {
      const MotorType& m = cfg.motors[c.type];
      const int every = std::max(1, static_cast<int>(std::lround(static_cast<double>(m.site_spacing) /
                                                                 net_.spacing(BinderKind::kMotor, c.type))));
      candidates_[ch] = pairsFor(BinderKind::kMotor, c.type, m.min_distance, m.max_distance, every);
    } else if (c.kind == FilamentReaction::kBranch) {
      // Every brancher site on a filament of the brancher's type.
      std::vector<std::pair<Index, Candidate>> sites;
      const auto& fils = net_.filaments();
      for (Index f = 0; f < static_cast<Index>(fils.size()); ++f) {
        if (fils[f].type != cfg.branchers[c.type].filament_type_index) continue;
        for (Index cyl = 0; cyl < fils[f].numCylinders(); ++cyl) {
          const auto [first, last] = net_.sitesOnCylinder(BinderKind::kBrancher, c.type, f, cyl);
          for (std::int64_t s = first; s <= last; ++s)
            sites.push_back({compartmentOf(net_.sitePosition(BinderKind::kBrancher, c.type, f, s)), {{f, f}, {s, s}}});
        }
      }
      Candidates& out = candidates_[ch];
      out.start.assign(grid_.count() + 1, 0);
      for (const auto& [comp, _] : sites) ++out.start[comp + 1];
      for (Index k = 0; k < grid_.count(); ++k) out.start[k + 1] += out.start[k];
      out.list.resize(sites.size());
      std::vector<Index> fill(out.start.begin(), out.start.end() - 1);
      for (const auto& [comp, cand] : sites) out.list[fill[comp]++] = cand;
    }
  }
}

// Site pairs on cylinders of different filaments at a distance in [rmin, rmax], found
// through a cell list of cylinder midpoints and grouped by the compartment of the
// pair's midpoint. Only sites whose index is a multiple of `every` may bind.
FilamentChemistry::Candidates FilamentChemistry::pairsFor(BinderKind kind, Index type, double rmin, double rmax,
                                                          int every) const {
  const auto& fils = net_.filaments();
  struct Cyl {
    Index f, c;
    Vec3 mid;
    double half;
  };
  std::vector<Cyl> cyls;
  double max_half = 0.0;
  for (Index f = 0; f < static_cast<Index>(fils.size()); ++f)
    for (Index c = 0; c < fils[f].numCylinders(); ++c) {
      const Vec3 &a = fils[f].beads[c], &b = fils[f].beads[c + 1];
      cyls.push_back({f, c, 0.5 * (a + b), 0.5 * (b - a).norm()});
      max_half = std::max(max_half, cyls.back().half);
    }
  const double cell = rmax + 2.0 * max_half;
  auto cellOf = [&](const Vec3& x) {
    return std::array<std::int64_t, 3>{static_cast<std::int64_t>(std::floor(x.x() / cell)),
                                       static_cast<std::int64_t>(std::floor(x.y() / cell)),
                                       static_cast<std::int64_t>(std::floor(x.z() / cell))};
  };
  auto hash = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    return static_cast<std::uint64_t>((i * 73856093) ^ (j * 19349663) ^ (k * 83492791));
  };
  std::unordered_map<std::uint64_t, std::vector<Index>> cells;
  for (Index i = 0; i < static_cast<Index>(cyls.size()); ++i) {
    const auto ijk = cellOf(cyls[i].mid);
    cells[hash(ijk[0], ijk[1], ijk[2])].push_back(i);
  }
  std::vector<std::pair<Index, Candidate>> found;
  std::vector<Index> near;
  for (Index i = 0; i < static_cast<Index>(cyls.size()); ++i) {
    const auto ijk = cellOf(cyls[i].mid);
    near.clear();
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = cells.find(hash(ijk[0] + dx, ijk[1] + dy, ijk[2] + dz));
          if (it == cells.end()) continue;
          for (Index j : it->second)
            if (j > i && cyls[j].f != cyls[i].f) near.push_back(j);
        }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());  // hash collisions
    for (Index j : near) {
      const Cyl &a = cyls[i], &b = cyls[j];
      if ((a.mid - b.mid).norm() > rmax + a.half + b.half) continue;
      const auto [a0, a1] = net_.sitesOnCylinder(kind, type, a.f, a.c);
      const auto [b0, b1] = net_.sitesOnCylinder(kind, type, b.f, b.c);
      for (std::int64_t sa = a0; sa <= a1; ++sa) {
        if (sa % every != 0) continue;
        const Vec3 pa = net_.sitePosition(kind, type, a.f, sa);
        for (std::int64_t sb = b0; sb <= b1; ++sb) {
          if (sb % every != 0) continue;
          const Vec3 pb = net_.sitePosition(kind, type, b.f, sb);
          const double d = (pb - pa).norm();
          if (d >= rmin && d <= rmax) found.push_back({compartmentOf(0.5 * (pa + pb)), {{a.f, b.f}, {sa, sb}}});
        }
      }
    }
  }
  Candidates out;
  out.start.assign(grid_.count() + 1, 0);
  for (const auto& [comp, _] : found) ++out.start[comp + 1];
  for (Index k = 0; k < grid_.count(); ++k) out.start[k + 1] += out.start[k];
  out.list.resize(found.size());
  std::vector<Index> fill(out.start.begin(), out.start.end() - 1);
  for (const auto& [comp, cand] : found) out.list[fill[comp]++] = cand;
  return out;
}

// --- rate factors ------------------------------------------------------------------------

Vec3 FilamentChemistry::bindingMidpoint(BinderKind kind, const Binding& b) const {
  return 0.5 * (net_.sitePosition(kind, b.type, b.filament[0], b.site[0]) +
                net_.sitePosition(kind, b.type, b.filament[1], b.site[1]));
}

void FilamentChemistry::syncFactors(ChemistryEngine& engine) {
  using K = FilamentReaction;
  const Index C = grid_.count();
  const auto& fils = net_.filaments();
  if (ratchet_.size() < fils.size()) {
    ratchet_.resize(fils.size(), {1.0, 1.0});
    load_.resize(fils.size(), {0.0, 0.0});
  }
  std::vector<double> next(factor_.size(), 0.0);
  auto add = [&](K kind, Index type, Index c, double w) {
    const Index ch = channelOf(kind, type);
    if (ch >= 0) next[static_cast<std::size_t>(ch) * C + c] += w;
  };
  for (std::size_t i = 0; i < fils.size(); ++i) {
    const Filament& f = fils[i];
    const Index plus = compartmentOf(f.beads.back());
    add(K::kPlusGrow, f.type, plus, ratchet_[i][1]);
    add(K::kPlusShrink, f.type, plus, 1.0);
    if (!f.minusEndActive()) continue;
    const Index minus = compartmentOf(f.beads.front());
    add(K::kMinusGrow, f.type, minus, ratchet_[i][0]);
    add(K::kMinusShrink, f.type, minus, 1.0);
  }
  for (const Binding& b : net_.linkers())
    add(K::kLinkerUnbind, b.type, compartmentOf(bindingMidpoint(BinderKind::kLinker, b)),
        slipFactor(net_.config().linkers[b.type], b.tension));
  for (const Binding& b : net_.motors()) {
    const Index c = compartmentOf(bindingMidpoint(BinderKind::kMotor, b));
    const MotorType& m = net_.config().motors[b.type];
    add(K::kMotorUnbind, b.type, c, catchFactor(m, b.tension));
    add(K::kMotorWalk, b.type, c, 2.0 * walkFactor(m, b.tension));
  }
  for (const Branch& b : net_.branches()) add(K::kUnbranch, b.type, compartmentOf(fils[b.daughter].beads.front()), 1.0);
  for (std::size_t ch = 0; ch < channels_.size(); ++ch) {
    if (channels_[ch].kind == K::kNucleate)
      for (Index c = 0; c < C; ++c) next[ch * C + c] = 1.0;
    else if (isBinding(channels_[ch].kind))
      for (Index c = 0; c < C; ++c) next[ch * C + c] = candidates_[ch].count(c);
  }
  for (std::size_t ch = 0; ch < channels_.size(); ++ch)
    for (Index c = 0; c < C; ++c) {
      const std::size_t i = ch * C + c;
      if (next[i] == factor_[i]) continue;
      factor_[i] = next[i];
      engine.setRateFactor(channels_[ch].reaction, c, next[i]);
    }
}

// --- events ------------------------------------------------------------------------------

bool FilamentChemistry::fired(Index reaction, Index compartment, ChemistryEngine& engine, RandomStream& random) {
  const auto it = std::find_if(channels_.begin(), channels_.end(),
                               [&](const Channel& ch) { return ch.reaction == reaction; });
  if (it == channels_.end()) return true;  // not ours: plain mass action
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
  if (done) syncFactors(engine);
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
  const Index f = pickWeighted(
      static_cast<Index>(fils.size()),
      [&](Index i) {
        const Filament& fil = fils[i];
        if (fil.type != ch.type || (!plus && !fil.minusEndActive())) return 0.0;
        if (compartmentOf(plus ? fil.beads.back() : fil.beads.front()) != c) return 0.0;
        return grow ? ratchet_[i][plus ? 1 : 0] : 1.0;
      },
      random);
  if (f < 0) return false;
  if (grow) {
    net_.grow(f, plus);
    return true;
  }
  released_.clear();
  if (!net_.shrink(f, plus, released_)) return false;  // at its smallest: nothing to lose
  release(released_, engine);
  return true;
}

void FilamentChemistry::release(const std::vector<Release>& released, ChemistryEngine& engine) {
  for (const Release& r : released) {
    const Index c = compartmentOf(r.where);
    engine.setCopies(c, r.species, engine.copies(c, r.species) + 1);
  }
}

bool FilamentChemistry::insideBoundary(const Vec3& x) const {
  const auto& b = net_.config().boundary;
  if (b && b->shape == BoundaryConfig::Shape::kSphere) return (x - b->center).norm() <= b->radius;
  const Vec3 lo = b ? b->min : Vec3::Zero();
  const Vec3 hi = b ? b->max
                    : Vec3(grid_.shape[0] * grid_.size, grid_.shape[1] * grid_.size, grid_.shape[2] * grid_.size);
  return (x.array() >= lo.array()).all() && (x.array() <= hi.array()).all();
}

bool FilamentChemistry::fireNucleation(const Channel& ch, Index c, RandomStream& random) {
  const FilamentType& t = net_.type(ch.type);
  const auto ijk = grid_.coords(c);
  const Vec3 corner(ijk[0] * grid_.size, ijk[1] * grid_.size, ijk[2] * grid_.size);
  const Vec3 at = corner + grid_.size * Vec3(random.uniform(), random.uniform(), random.uniform());
  Filament f = makeStraightFilament(ch.type, at, randomDirection(random), 2, t.cylinder_monomers, t.monomer_size);
  // Nucleation happens only inside the boundary: thinning by the fraction of the
  // compartment that lies inside.
  if (!insideBoundary(f.beads.front()) || !insideBoundary(f.beads.back())) return false;
  net_.addFilament(std::move(f));
  return true;
}

bool FilamentChemistry::fireBind(const Channel& ch, Index c, RandomStream& random) {
  const BinderKind kind = ch.kind == FilamentReaction::kMotorBind ? BinderKind::kMotor : BinderKind::kLinker;
  const Candidates& cand = candidates_[&ch - channels_.data()];
  const Index n = cand.count(c);
  if (n == 0) return false;
  const Candidate& p =
      cand.list[cand.start[c] + std::min<Index>(n - 1, static_cast<Index>(random.uniform() * n))];
  // The candidate list is from the last minimization: a site since lost or taken makes
  // this a void event (thinning).
  for (int e = 0; e < 2; ++e)
    if (!net_.siteExists(kind, ch.type, p.filament[e], p.site[e]) ||
        net_.occupied(kind, ch.type, p.filament[e], p.site[e]))
      return false;
  Binding b;
  b.type = ch.type;
  b.filament = p.filament;
  b.site = p.site;
  b.rest_length = (net_.sitePosition(kind, ch.type, p.filament[1], p.site[1]) -
                   net_.sitePosition(kind, ch.type, p.filament[0], p.site[0]))
                      .norm();
  net_.bind(kind, b);
  return true;
}

bool FilamentChemistry::fireUnbind(const Channel& ch, Index c, RandomStream& random) {
  const BinderKind kind = ch.kind == FilamentReaction::kMotorUnbind ? BinderKind::kMotor : BinderKind::kLinker;
  const auto& bound = net_.bound(kind);
  const Index i = pickWeighted(
      static_cast<Index>(bound.size()),
      [&](Index k) {
        const Binding& b = bound[k];
        if (b.type != ch.type || compartmentOf(bindingMidpoint(kind, b)) != c) return 0.0;
        return kind == BinderKind::kLinker ? slipFactor(net_.config().linkers[b.type], b.tension)
                                           : catchFactor(net_.config().motors[b.type], b.tension);
      },
      random);
  if (i < 0) return false;
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
        if (b.type != ch.type || compartmentOf(bindingMidpoint(BinderKind::kMotor, b)) != c) return 0.0;
        return walkFactor(net_.config().motors[b.type], b.tension);
      },
      random);
  if (i < 0) return false;
  return net_.walk(static_cast<std::size_t>(i / 2), i % 2);  // blocked: void (thinning)
}

bool FilamentChemistry::fireBranch(const Channel& ch, Index c, RandomStream& random) {
  const Candidates& cand = candidates_[&ch - channels_.data()];
  const Index n = cand.count(c);
  if (n == 0) return false;
  const Candidate& site = cand.list[cand.start[c] + std::min<Index>(n - 1, static_cast<Index>(random.uniform() * n))];
  const Index mother = site.filament[0];
  if (!net_.siteExists(BinderKind::kBrancher, ch.type, mother, site.site[0]) ||
      net_.occupied(BinderKind::kBrancher, ch.type, mother, site.site[0]))
    return false;
  const Filament& m = net_.filaments()[mother];
  const auto [cyl, w] = m.locate(net_.siteCoordinate(BinderKind::kBrancher, ch.type, site.site[0]));
  const Vec3 u = (m.beads[cyl + 1] - m.beads[cyl]).normalized();
  // Daughter direction: the branch angle away from the mother's axis, in a random plane.
  Vec3 v = randomDirection(random);
  v = (v - v.dot(u) * u).normalized();
  const double angle = net_.config().branchers[ch.type].angle * constants::kPi / 180.0;
  net_.branch(ch.type, mother, site.site[0], std::cos(angle) * u + std::sin(angle) * v);
  return true;
}

bool FilamentChemistry::fireUnbranch(const Channel& ch, Index c, RandomStream& random) {
  const auto& branches = net_.branches();
  const Index i = pickWeighted(
      static_cast<Index>(branches.size()),
      [&](Index k) {
        const Branch& b = branches[k];
        return b.type == ch.type && compartmentOf(net_.filaments()[b.daughter].beads.front()) == c ? 1.0 : 0.0;
      },
      random);
  if (i < 0) return false;
  net_.unbranch(static_cast<std::size_t>(i));
  return true;
}

}  // namespace cortex
