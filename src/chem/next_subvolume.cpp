#include "chem/next_subvolume.hpp"

#include <limits>
#include <stdexcept>

namespace cortex {

namespace {
constexpr double kNever = std::numeric_limits<double>::infinity();

// For each 6-bit mask of existing faces: which face is the k-th existing one.
struct FaceTable {
  std::array<std::array<std::uint8_t, 6>, 64> face{};
};
constexpr FaceTable makeFaceTable() {
  FaceTable t;
  for (int m = 0; m < 64; ++m) {
    int count = 0;
    for (int f = 0; f < 6; ++f)
      if (m & (1 << f)) t.face[m][count++] = static_cast<std::uint8_t>(f);
  }
  return t;
}
constexpr FaceTable kFaceTable = makeFaceTable();
}  // namespace

Index NextSubvolumeEngine::neighbour(Index i, const Subvolume& v, Index k) const {
  if (lattice_ && v.region == 0) return i + lattice_step_[kFaceTable.face[v.faces][k]];
  return edge_target_[v.first_edge + k];
}

NextSubvolumeEngine::NextSubvolumeEngine(const ChemistryModel& model, const std::vector<int>& copies,
                                         std::uint64_t seed)
    : EngineBase(model, copies, seed), blocks_((R_ + kBlock - 1) / kBlock) {
  relaidOut();
}

void NextSubvolumeEngine::relaidOut() {
  const auto [nx, ny, nz] = lattice();
  lattice_ = nx > 0;
  lattice_step_ = {-1, 1, -nx, nx, -nx * ny, nx * ny};
  rate_.assign(static_cast<std::size_t>(N_) * R_, 0.0);
  propensity_.assign(rate_.size(), 0.0);
  block_sum_.assign(static_cast<std::size_t>(N_) * blocks_, 0.0);
  sub_.assign(N_, Subvolume{});
  read_.assign(S_, 0);
  for (Index s = 0; s < S_; ++s) read_[s] = !net_.dependents[s].empty() || !net_.heldReaders[s].empty();
  for (Index i = 0; i < N_; ++i) {
    sub_[i].first_edge = edge_start_[i];
    if (degree(i) > 0xffff || region_of_[i] > 0xff)
      throw std::invalid_argument("chemistry engine: a subvolume with more than 65535 edges, or 255 surfaces");
    sub_[i].degree = static_cast<std::uint16_t>(degree(i));
    sub_[i].region = static_cast<std::uint8_t>(region_of_[i]);
    if (lattice_ && region_of_[i] == 0) {
      const int x = i % nx, y = i / nx % ny, z = i / (nx * ny);
      const bool has[6] = {x > 0, x + 1 < nx, y > 0, y + 1 < ny, z > 0, z + 1 < nz};
      for (int f = 0; f < 6; ++f) sub_[i].faces |= static_cast<std::uint8_t>(has[f] << f);
    }
    const std::size_t base = static_cast<std::size_t>(i) * R_;
    for (Index r = 0; r < R_; ++r) rate_[base + r] = factor_[base + r] * constantAt(i, r);
    refresh(i);
  }
}

// Exact propensities and sums of subvolume i from its copies.
void NextSubvolumeEngine::refresh(Index i) {
  Subvolume& v = sub_[i];
  const std::size_t base = static_cast<std::size_t>(i) * R_;
  if (v.region == 0) refreshBindingWeights(i);
  v.reactions = 0.0;
  for (Index b = 0; b < blocks_; ++b) {
    double sum = 0.0;
    for (Index r = b * kBlock; r < std::min(R_, (b + 1) * kBlock); ++r) {
      propensity_[base + r] = propensityAt(i, r, rate_[base + r]);
      sum += propensity_[base + r];
    }
    block_sum_[static_cast<std::size_t>(i) * blocks_ + b] = sum;
    v.reactions += sum;
  }
  v.diffusion = diffusionSum(i);
}

double NextSubvolumeEngine::totalRate() const {
  double sum = 0.0;
  for (const Subvolume& v : sub_) sum += total(v);
  return sum;
}

double NextSubvolumeEngine::diffusionSum(Index i) const {
  const int* n = &copies_[static_cast<std::size_t>(i) * S_];
  double hops = 0.0;
  for (Index s : diffusing_[sub_[i].region]) hops += hopOutOf(i, s) * n[s];
  return hops;
}

// After copies of an interacting species moved: every subvolume whose hop rates changed
// gets its diffusion sum anew.
[[gnu::noinline]] void NextSubvolumeEngine::interactionMoved(Index s, Index a, Index b) {
  const std::vector<Index>& changed = interactionChanged(s, a, b);
  const std::size_t fields = interactionFieldsChanged();
  for (std::size_t k = 0; k < changed.size(); ++k) {
    const Index v = changed[k];
    changeSubvolume(v, [&] {
      sub_[v].diffusion = diffusionSum(v);
      if (k < fields && !unbinding_.empty())  // unbinding reads the field (s's or a coupled one's)
        for (Index r = 0; r < R_; ++r)
          if (unbinding_[r] >= 0 && fieldReads(unbinding_[r], s)) setPropensity(v, r);
    });
  }
}

void NextSubvolumeEngine::setPropensity(Index i, Index r) {
  const std::size_t k = static_cast<std::size_t>(i) * R_ + r;
  const double p = propensityAt(i, r, rate_[k]);
  const double delta = p - propensity_[k];
  propensity_[k] = p;
  block_sum_[static_cast<std::size_t>(i) * blocks_ + r / kBlock] += delta;
  sub_[i].reactions += delta;
}

void NextSubvolumeEngine::updateReaders(Index i, Index s) {
  for (Index r : net_.dependents[s]) setPropensity(i, r);
  if (net_.heldReaders[s].empty()) return;
  for (Index h : held_[i])
    changeSubvolume(h, [&] {
      for (Index r : net_.heldReaders[s]) setPropensity(h, r);
    });
}

template <class Change>
void NextSubvolumeEngine::changeSubvolume(Index i, Change&& change) {
  if (!advancing_ || i == firing_) {
    change();
    return;
  }
  const double a_old = total(sub_[i]);
  const double t_old = heap_.time(i);
  change();
  const double a_new = total(sub_[i]);
  double t_new = kNever;
  if (a_new > 0.0)
    t_new = a_old > 0.0 && t_old < kNever ? now_ + a_old / a_new * (t_old - now_) : now_ + rng_.exponential(a_new);
  heap_.update(i, t_new);
}

void NextSubvolumeEngine::setCopies(Index subvolume, Index species, int n) {
  checkCopies(subvolume, species, n);
  changeSubvolume(subvolume, [&] { changeCopies(subvolume, species, n - copies_[slot(subvolume, species)]); });
  if (interacting(species)) interactionMoved(species, subvolume, subvolume);
}

void NextSubvolumeEngine::setRateFactor(Index reaction, Index subvolume, double factor) {
  checkRateFactor(reaction, subvolume, factor);
  factor_[static_cast<std::size_t>(subvolume) * R_ + reaction] = factor;
  if (aggregated(reaction)) {
    if (region_of_[subvolume] == 0) return;  // the reaction never fires in a 3D subvolume
    const Index h = holder_[subvolume];
    changeSubvolume(h, [&] {
      refreshBindingWeight(h, reaction);
      setPropensity(h, reaction);
    });
    return;
  }
  changeSubvolume(subvolume, [&] {
    rate_[static_cast<std::size_t>(subvolume) * R_ + reaction] = factor * constantAt(subvolume, reaction);
    setPropensity(subvolume, reaction);
  });
}

void NextSubvolumeEngine::advance(double t_end) {
  if (t_end < time_) throw std::invalid_argument("chemistry engine: advance to a time before the current one");
  if (t_end == time_) return;
  // Nothing is pending between advances: every subvolume draws a fresh waiting time.
  first_times_.resize(N_);
  double sum = 0.0;
  for (Index i = 0; i < N_; ++i) {
    refresh(i);
    const double a = total(sub_[i]);
    sum += a;
    first_times_[i] = a > 0.0 ? time_ + rng_.exponential(a) : kNever;
  }
  checkLoad(sum, t_end - time_);
  heap_.assign(first_times_);
  advancing_ = true;
  for (std::int64_t n = 1; heap_.topTime() <= t_end; ++n) {
    fire(heap_.topId(), heap_.topTime());
    if (n % kLoadCheckInterval == 0) checkLoad(totalRate(), t_end - now_, n);
  }
  advancing_ = false;
  time_ = t_end;
}

void NextSubvolumeEngine::fire(Index i, double t) {
  // The copies of i are read only after the uniform number below is drawn; fetching them
  // now overlaps their cache miss with the record's and the draw.
  __builtin_prefetch(&copies_[static_cast<std::size_t>(i) * S_]);
  const Subvolume& v = sub_[i];
  const double reactions = std::max(v.reactions, 0.0);
  const double x = rng_.uniform() * (reactions + std::max(v.diffusion, 0.0));
  firing_ = i;
  now_ = t;
  Index r = -1;
  bool fired = false;
  if (x < reactions) {
    r = pickReaction(i, x);
    // A reaction that would overfill a crowded subvolume, or that its hook refuses, is a
    // void event (thinning): nothing changes.
    if (r >= 0 && aggregated(r)) {
      fired = fireBinding(i, r);
    } else if (r >= 0 && accepts(r, i)) {
      react(i, r);
      fired = true;
    }
    if (fired) ++reaction_events_[r];
  } else {
    const HopOutcome h = hop(i, x - reactions);
    fired = h == HopOutcome::kMoved;
    if (fired) ++diffusion_events_;
    if (h == HopOutcome::kCrowded) r = kCrowdedHop;  // a void event, not a miss
  }
  firing_ = -1;
  // A miss (no channel picked) means rounding in the incremental sums put x past the last
  // channel: the rebuilt sums are smaller, and dropping the event is exact thinning of
  // the excess.
  if (fired)
    ++events_;
  else if (r != kCrowdedHop && (x >= reactions || r < 0))
    refresh(i);
  reschedule(i, t);
}

Index NextSubvolumeEngine::pickReaction(Index i, double x) const {
  const double* sums = &block_sum_[static_cast<std::size_t>(i) * blocks_];
  const double* p = &propensity_[static_cast<std::size_t>(i) * R_];
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

bool NextSubvolumeEngine::changeLocally(Index i, Index r) {
  int* n = &copies_[static_cast<std::size_t>(i) * S_];
  bool cascades = false;
  for (const SpeciesChange& change : net_.changes[r]) {
    if (change.held) continue;
    checkGrowth(n[change.species], change.delta, i, change.species, r);
    n[change.species] += change.delta;
    sub_[i].diffusion += change.delta * hopOutOf(i, change.species);
    cascades = cascades || !net_.heldReaders[change.species].empty();
  }
  for (Index dependent : net_.affected[r]) setPropensity(i, dependent);
  return cascades;
}

void NextSubvolumeEngine::changeHeld(Index h, Index r) {
  for (const SpeciesChange& change : net_.changes[r]) {
    if (!change.held) continue;
    checkGrowth(copies_[static_cast<std::size_t>(h) * S_ + change.species], change.delta, h, change.species, r);
    changeSubvolume(h, [&] { changeCopies(h, change.species, change.delta); });
  }
}

void NextSubvolumeEngine::moveInteracting(Index i, Index r) {
  for (const SpeciesChange& change : net_.changes[r])
    if (!change.held && interacting(change.species)) interactionMoved(change.species, i, i);
}

void NextSubvolumeEngine::react(Index i, Index r) {
  const bool cascades = changeLocally(i, r);
  moveInteracting(i, r);
  // What the local changes do to the surface subvolumes i holds, and the held changes of
  // a surface reaction in i's holder (which in turn reach every subvolume it holds).
  if (cascades)
    for (const SpeciesChange& change : net_.changes[r]) {
      if (change.held || net_.heldReaders[change.species].empty()) continue;
      for (Index h : held_[i])
        changeSubvolume(h, [&] {
          for (Index reader : net_.heldReaders[change.species]) setPropensity(h, reader);
        });
    }
  changeHeld(holder_[i], r);
}

// The firing 3D subvolume h carries the aggregated reaction r: it happens in one of the
// surface subvolumes h holds, drawn by its weight (there its cap and hook decide).
bool NextSubvolumeEngine::fireBinding(Index h, Index r) {
  const Index j = drawBindingSite(h, r);
  if (j < 0 || !accepts(r, j)) return false;  // a void event
  changeHeld(h, r);  // h is firing: no rescaling
  // Binding changes only surface species of j: nothing cascades to other subvolumes.
  changeSubvolume(j, [&] { changeLocally(j, r); });
  moveInteracting(j, r);
  return true;
}

// x in [0, diffusion of i) picks the species by its share and, with what is left of it,
// the edge: one uniform number serves both choices.
NextSubvolumeEngine::HopOutcome NextSubvolumeEngine::hop(Index i, double x) {
  const Subvolume& v = sub_[i];
  const int* n = &copies_[static_cast<std::size_t>(i) * S_];
  Index s = -1;
  double w = 0.0;
  for (Index d : diffusing_[v.region]) {
    w = hopOutOf(i, d) * n[d];
    if (x < w) {
      s = d;
      break;
    }
    x -= w;
  }
  if (s < 0) return HopOutcome::kMissed;
  Index dest;
  if (!weighted(s)) {
    dest = neighbour(i, v, std::min(static_cast<Index>(x / w * v.degree), static_cast<Index>(v.degree) - 1));
  } else {
    // Edges weighted by their rates; what is left of x picks one.
    double y = x / n[s];
    Index edge = -1;
    for (Index e = v.first_edge; e < v.first_edge + v.degree; ++e) {
      const double rate = edgeRate(e, s);
      if (!(rate > 0.0)) continue;
      edge = e;
      if (y < rate) break;
      y -= rate;
    }
    if (edge < 0) return HopOutcome::kMissed;
    dest = edge_target_[edge];
  }
  if (crowded(dest, s, 1)) return HopOutcome::kCrowded;

  changeCopies(i, s, -1);
  changeSubvolume(dest, [&] { changeCopies(dest, s, +1); });
  if (interacting(s)) interactionMoved(s, i, dest);
  return HopOutcome::kMoved;
}

// i is the subvolume that fired, still at the top of the heap.
void NextSubvolumeEngine::reschedule(Index i, double t) {
  const double a = total(sub_[i]);
  heap_.replaceTop(a > 0.0 ? t + rng_.exponential(a) : kNever);
}

}  // namespace cortex
