#include "chem/direct_method.hpp"

#include <stdexcept>

namespace cortex {

DirectMethodEngine::DirectMethodEngine(const ChemistryModel& model, const std::vector<int>& copies, std::uint64_t seed)
    : EngineBase(model, copies, seed) {
  relaidOut();
}

void DirectMethodEngine::relaidOut() {
  edge_source_.assign(edge_target_.size(), 0);
  for (Index i = 0; i < N_; ++i)
    for (Index e = edge_start_[i]; e < edge_start_[i + 1]; ++e) edge_source_[e] = i;
  propensity_.assign(static_cast<std::size_t>(N_) * R_ + edge_target_.size() * S_, 0.0);
  for (Index i = 0; i < N_; ++i) recompute(i);
}

void DirectMethodEngine::recompute(Index i) {
  const int* n = &copies_[static_cast<std::size_t>(i) * S_];
  if (region_of_[i] == 0) refreshBindingWeights(i);
  for (Index r = 0; r < R_; ++r) {
    const std::size_t k = static_cast<std::size_t>(i) * R_ + r;
    propensity_[k] = propensityAt(i, r, factor_[k] * constantAt(i, r));
  }
  const std::size_t hops = static_cast<std::size_t>(N_) * R_;
  for (Index e = edge_start_[i]; e < edge_start_[i + 1]; ++e)
    for (Index s = 0; s < S_; ++s)
      propensity_[hops + static_cast<std::size_t>(e) * S_ + s] = (weighted(s) ? edgeRate(e, s) : hopRate(s)) * n[s];
}

void DirectMethodEngine::touch(Index i, Index s) {
  recompute(i);
  if (!net_.heldReaders[s].empty())
    for (Index h : held_[i]) recompute(h);
}

double DirectMethodEngine::sum() const {
  // Four partial sums: the same result every time, and faster than one serial chain.
  double part[4] = {0.0, 0.0, 0.0, 0.0};
  const std::size_t n = propensity_.size();
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4)
    for (int k = 0; k < 4; ++k) part[k] += propensity_[i + k];
  for (; i < n; ++i) part[0] += propensity_[i];
  return (part[0] + part[1]) + (part[2] + part[3]);
}

void DirectMethodEngine::setCopies(Index subvolume, Index species, int n) {
  checkCopies(subvolume, species, n);
  copies_[slot(subvolume, species)] = n;
  touch(subvolume, species);
  if (interacting(species))
    for (Index v : interactionChanged(species, subvolume, subvolume)) recompute(v);
}

void DirectMethodEngine::setRateFactor(Index reaction, Index subvolume, double factor) {
  checkRateFactor(reaction, subvolume, factor);
  factor_[static_cast<std::size_t>(subvolume) * R_ + reaction] = factor;
  recompute(subvolume);
  if (aggregated(reaction)) recompute(holder_[subvolume]);
}

void DirectMethodEngine::advance(double t_end) {
  if (t_end < time_) throw std::invalid_argument("chemistry engine: advance to a time before the current one");
  if (t_end == time_) return;
  checkLoad(sum(), t_end - time_);
  double t = time_;
  for (std::int64_t n = 0;; ++n) {
    const double total = sum();
    if (n > 0 && n % kLoadCheckInterval == 0) checkLoad(total, t_end - t, n);
    if (!(total > 0.0)) break;
    t += rng_.exponential(total);
    if (t > t_end) break;  // memoryless: the overshooting waiting time is simply discarded
    double x = rng_.uniform() * total;
    std::size_t channel = 0, last_positive = 0;
    for (; channel < propensity_.size(); ++channel) {
      if (x < propensity_[channel]) break;
      x -= propensity_[channel];
      if (propensity_[channel] > 0.0) last_positive = channel;
    }
    if (channel == propensity_.size()) channel = last_positive;  // rounding at the very end
    fire(channel);
  }
  time_ = t_end;
}

void DirectMethodEngine::fire(std::size_t channel) {
  const std::size_t reaction_channels = static_cast<std::size_t>(N_) * R_;
  if (channel < reaction_channels) {
    const Index carrier = static_cast<Index>(channel / R_), r = static_cast<Index>(channel % R_);
    // An aggregated reaction fires in one of the surface subvolumes its carrier holds.
    const Index i = aggregated(r) ? drawBindingSite(carrier, r) : carrier;
    if (i < 0 || !accepts(r, i)) return;  // void event (thinning): nothing changes
    for (const SpeciesChange& change : net_.changes[r]) {
      const Index at = change.held ? holder_[i] : i;
      int& n = copies_[static_cast<std::size_t>(at) * S_ + change.species];
      checkGrowth(n, change.delta, at, change.species, r);
      n += change.delta;
      touch(at, change.species);
    }
    ++reaction_events_[r];
    recompute(i);
    for (const SpeciesChange& change : net_.changes[r])
      if (!change.held && interacting(change.species))
        for (Index v : interactionChanged(change.species, i, i)) recompute(v);
  } else {
    const std::size_t hop = channel - reaction_channels;
    const auto e = static_cast<Index>(hop / S_);
    const auto s = static_cast<Index>(hop % S_);
    const Index from = edge_source_[e], to = edge_target_[e];
    if (crowded(to, s, 1)) return;  // into a full subvolume: a void event
    --copies_[static_cast<std::size_t>(from) * S_ + s];
    ++copies_[static_cast<std::size_t>(to) * S_ + s];
    ++diffusion_events_;
    touch(from, s);
    touch(to, s);
    if (interacting(s))
      for (Index v : interactionChanged(s, from, to)) recompute(v);
  }
  ++events_;
}

}  // namespace cortex
