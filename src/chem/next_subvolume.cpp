#include "chem/next_subvolume.hpp"

#include <limits>
#include <stdexcept>

namespace cortex {

namespace {
constexpr double kNever = std::numeric_limits<double>::infinity();
}

NextSubvolumeEngine::NextSubvolumeEngine(const ChemistryModel& model, const std::vector<int>& copies,
                                         std::uint64_t seed)
    : EngineBase(model, copies, seed),
      blocks_((R_ + kBlock - 1) / kBlock),
      rate_(static_cast<std::size_t>(C_) * R_),
      propensity_(rate_.size(), 0.0),
      block_sum_(static_cast<std::size_t>(C_) * blocks_, 0.0),
      sub_(C_) {
  for (Index c = 0; c < C_; ++c) {
    for (Index r = 0; r < R_; ++r) rate_[static_cast<std::size_t>(c) * R_ + r] = net_.kernels[r].constant;
    refresh(c);
  }
}

// Exact propensities and sums of compartment c from its copies.
void NextSubvolumeEngine::refresh(Index c) {
  Subvolume& v = sub_[c];
  const int* n = &copies_[static_cast<std::size_t>(c) * S_];
  const std::size_t base = static_cast<std::size_t>(c) * R_;
  v.reactions = 0.0;
  for (Index b = 0; b < blocks_; ++b) {
    double sum = 0.0;
    for (Index r = b * kBlock; r < std::min(R_, (b + 1) * kBlock); ++r) {
      propensity_[base + r] = rate_[base + r] * confinementScale(c, r) * combinations(net_.kernels[r], n);
      sum += propensity_[base + r];
    }
    block_sum_[static_cast<std::size_t>(c) * blocks_ + b] = sum;
    v.reactions += sum;
  }
  v.faces = GridFaces::count(faces_.mask(c));
  double hops = 0.0;
  for (Index s : net_.diffusing) hops += hopOutOf(c, s) * n[s];
  v.diffusion = hops;
}

void NextSubvolumeEngine::setPropensity(Index c, Index r) {
  const std::size_t i = static_cast<std::size_t>(c) * R_ + r;
  const double p =
      rate_[i] * confinementScale(c, r) * combinations(net_.kernels[r], &copies_[static_cast<std::size_t>(c) * S_]);
  const double delta = p - propensity_[i];
  propensity_[i] = p;
  block_sum_[static_cast<std::size_t>(c) * blocks_ + r / kBlock] += delta;
  sub_[c].reactions += delta;
}

void NextSubvolumeEngine::changeCopies(Index c, Index s, int delta) {
  copies_[static_cast<std::size_t>(c) * S_ + s] += delta;
  sub_[c].diffusion += delta * hopOutOf(c, s);
  for (Index r : net_.dependents[s]) setPropensity(c, r);
}

template <class Change>
void NextSubvolumeEngine::changeSubvolume(Index c, Change&& change) {
  if (!advancing_ || c == firing_) {
    change();
    return;
  }
  const double a_old = total(sub_[c]);
  const double t_old = heap_.time(c);
  change();
  const double a_new = total(sub_[c]);
  double t_new = kNever;
  if (a_new > 0.0)
    t_new = a_old > 0.0 && t_old < kNever ? now_ + a_old / a_new * (t_old - now_) : now_ + rng_.exponential(a_new);
  heap_.update(c, t_new);
}

void NextSubvolumeEngine::setCopies(Index compartment, Index species, int n) {
  checkCopies(compartment, species, n);
  changeSubvolume(compartment,
                  [&] { changeCopies(compartment, species, n - copies_[slot(compartment, species)]); });
}

void NextSubvolumeEngine::setRateFactor(Index reaction, Index compartment, double factor) {
  checkRateFactor(reaction, compartment, factor);
  changeSubvolume(compartment, [&] {
    rate_[static_cast<std::size_t>(compartment) * R_ + reaction] = factor * net_.kernels[reaction].constant;
    setPropensity(compartment, reaction);
  });
}

void NextSubvolumeEngine::advance(double t_end) {
  if (t_end < time_) throw std::invalid_argument("chemistry engine: advance to a time before the current one");
  if (t_end == time_) return;
  // Nothing is pending between advances: every compartment draws a fresh waiting time.
  first_times_.resize(C_);
  for (Index c = 0; c < C_; ++c) {
    refresh(c);
    const double a = total(sub_[c]);
    first_times_[c] = a > 0.0 ? time_ + rng_.exponential(a) : kNever;
  }
  heap_.assign(first_times_);
  advancing_ = true;
  while (heap_.topTime() <= t_end) fire(heap_.topId(), heap_.topTime());
  advancing_ = false;
  time_ = t_end;
}

void NextSubvolumeEngine::fire(Index c, double t) {
  const Subvolume& v = sub_[c];
  const double reactions = std::max(v.reactions, 0.0);
  const double x = rng_.uniform() * (reactions + std::max(v.diffusion, 0.0));
  firing_ = c;
  now_ = t;
  Index r = -1;
  bool fired = false;
  if (x < reactions) {
    r = pickReaction(c, x);
    // A hooked reaction its hook refuses is a void event (thinning): nothing changes.
    if (r >= 0 && hookAccepts(r, c)) {
      react(c, r);
      ++reaction_events_[r];
      fired = true;
    }
  } else {
    fired = hop(c, x - reactions);
    if (fired) ++diffusion_events_;
  }
  firing_ = -1;
  // A miss (no channel picked) means rounding in the incremental sums put x past the last
  // channel: the rebuilt sums are smaller, and dropping the event is exact thinning of
  // the excess.
  if (fired)
    ++events_;
  else if (x >= reactions || r < 0)
    refresh(c);
  reschedule(c, t);
}

Index NextSubvolumeEngine::pickReaction(Index c, double x) const {
  const double* sums = &block_sum_[static_cast<std::size_t>(c) * blocks_];
  const double* p = &propensity_[static_cast<std::size_t>(c) * R_];
  for (Index b = 0; b < blocks_; ++b) {
    if (x < sums[b]) {
      const Index begin = b * kBlock, end = std::min(R_, begin + kBlock);
      for (Index r = begin; r < end; ++r) {
        if (x < p[r]) return r;
        x -= p[r];
      }
      for (Index r = end - 1; r >= begin; --r)
        if (p[r] > 0.0) return r;
      return -1;
    }
    x -= sums[b];
  }
  return -1;
}

void NextSubvolumeEngine::react(Index c, Index r) {
  Subvolume& v = sub_[c];
  int* n = &copies_[static_cast<std::size_t>(c) * S_];
  for (const SpeciesChange& change : net_.changes[r]) {
    checkGrowth(n[change.species], change.delta, c, change.species);
    n[change.species] += change.delta;
    v.diffusion += change.delta * hopOutOf(c, change.species);
  }
  for (Index dependent : net_.affected[r]) setPropensity(c, dependent);
}

// x in [0, diffusion of c) picks the species by its share and, with what is left of it,
// the face: one uniform number serves both choices.
bool NextSubvolumeEngine::hop(Index c, double x) {
  const int faces = sub_[c].faces;
  const int* n = &copies_[static_cast<std::size_t>(c) * S_];
  Index s = -1;
  double w = 0.0;
  for (Index d : net_.diffusing) {
    w = hopOutOf(c, d) * n[d];
    if (x < w) {
      s = d;
      break;
    }
    x -= w;
  }
  if (s < 0) return false;
  Index dest;
  if (!confined(s)) {
    dest = faces_.neighbour(c, std::min(static_cast<int>(x / w * faces), faces - 1));
  } else {
    // Faces weighted by their rates a_face / f; what is left of x picks one.
    const double* rate = faceRates(c, s);
    double y = x / n[s];
    int face = -1;
    for (int f = 0; f < 6; ++f) {
      if (!(rate[f] > 0.0)) continue;
      face = f;
      if (y < rate[f]) break;
      y -= rate[f];
    }
    if (face < 0) return false;
    dest = faces_.across(c, face);
  }

  changeCopies(c, s, -1);
  changeSubvolume(dest, [&] { changeCopies(dest, s, +1); });
  return true;
}

// c is the compartment that fired, still at the top of the heap.
void NextSubvolumeEngine::reschedule(Index c, double t) {
  const double a = total(sub_[c]);
  heap_.replaceTop(a > 0.0 ? t + rng_.exponential(a) : kNever);
}

}  // namespace cortex
