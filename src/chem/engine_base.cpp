#include "chem/engine_base.hpp"

#include <cmath>
#include <deque>
#include <stdexcept>
#include <string>

#include "core/error.hpp"

namespace cortex {

EngineBase::EngineBase(const ChemistryModel& model, const std::vector<int>& copies, std::uint64_t seed)
    : net_(model),
      faces_(model.grid),
      S_(net_.numSpecies),
      R_(net_.numReactions),
      C_(net_.numCompartments),
      copies_(copies),
      rng_(seed, StreamId::kChemistry),
      reaction_events_(net_.numReactions, 0),
      confined_(S_, 0),
      side_species_(R_, -1),
      reaction_order_(R_, 0),
      scale_species_(R_, -1) {
  for (Index r = 0; r < R_; ++r) {
    const ReactionDef& def = model.reactions[r];
    reaction_order_[r] = def.order();
    if (!def.reactants.empty())
      side_species_[r] = def.reactants.front().species;
    else if (!def.products.empty())
      side_species_[r] = def.products.front().species;
  }
  if (copies_.size() != static_cast<std::size_t>(C_) * S_)
    throw std::invalid_argument("chemistry engine: " + std::to_string(copies_.size()) + " initial copies for " +
                                std::to_string(C_) + " compartments x " + std::to_string(S_) + " species");
  for (std::size_t i = 0; i < copies_.size(); ++i)
    if (copies_[i] < 0)
      throw InputError("chemistry: negative initial copies of species \"" + model.species[i % S_].name +
                       "\" in compartment " + std::to_string(i / S_));
}

std::size_t EngineBase::slot(Index compartment, Index species) const {
  if (compartment < 0 || compartment >= C_ || species < 0 || species >= S_)
    throw std::out_of_range("chemistry engine: no species " + std::to_string(species) + " in compartment " +
                            std::to_string(compartment));
  return static_cast<std::size_t>(compartment) * S_ + species;
}

void EngineBase::checkCopies(Index compartment, Index species, int n) const {
  slot(compartment, species);
  if (n < 0) throw std::invalid_argument("chemistry engine: negative copy number " + std::to_string(n));
  if (n > 0 && !active(compartment, species))
    throw std::invalid_argument("chemistry engine: compartment " + std::to_string(compartment) +
                                " has no volume on species " + std::to_string(species) + "'s side of its membrane");
}

void EngineBase::growthOverflow(Index compartment, Index species) const {
  throw RunError("chemistry: copies of species " + std::to_string(species) + " in compartment " +
                 std::to_string(compartment) + " would exceed 2^31 - 1 (a reaction network growing without bound?)");
}

void EngineBase::checkRateFactor(Index reaction, Index compartment, double factor) const {
  if (reaction < 0 || reaction >= R_ || compartment < 0 || compartment >= C_)
    throw std::out_of_range("chemistry engine: no reaction " + std::to_string(reaction) + " in compartment " +
                            std::to_string(compartment));
  if (!std::isfinite(factor) || factor < 0.0)
    throw std::invalid_argument("chemistry engine: rate factor must be finite and >= 0, got " + std::to_string(factor));
}

void EngineBase::restore(const RandomStream& stream, double time, std::int64_t events,
                         const std::vector<std::int64_t>& reaction_events, std::int64_t diffusion_events) {
  if (reaction_events.size() != reaction_events_.size())
    throw std::invalid_argument("chemistry engine: checkpoint has " + std::to_string(reaction_events.size()) +
                                " reaction counters, the model " + std::to_string(reaction_events_.size()));
  rng_ = stream;
  time_ = time;
  events_ = events;
  reaction_events_ = reaction_events;
  diffusion_events_ = diffusion_events;
}

void EngineBase::setConfinement(Index species, const std::vector<double>& volume,
                                const std::vector<std::array<double, 6>>& faces) {
  if (species < 0 || species >= S_)
    throw std::out_of_range("chemistry engine: no species " + std::to_string(species));
  if (volume.size() != static_cast<std::size_t>(C_) || faces.size() != static_cast<std::size_t>(C_))
    throw std::invalid_argument(
        "chemistry engine: confinement needs one volume and six face fractions per compartment");
  for (Index c = 0; c < C_; ++c) {
    bool ok = volume[c] >= 0.0 && volume[c] <= 1.0;
    for (double a : faces[c]) ok = ok && a >= 0.0 && a <= 1.0;
    if (!ok) throw std::invalid_argument("chemistry engine: confinement fractions outside [0, 1] in compartment " +
                                         std::to_string(c));
  }
  // Refused before anything changes, so a failed call leaves the engine as it was.
  bool any_active = false, any_copies = false;
  for (Index c = 0; c < C_; ++c) {
    any_active = any_active || volume[c] > 0.0;
    any_copies = any_copies || copies_[static_cast<std::size_t>(c) * S_ + species] > 0;
  }
  if (any_copies && !any_active)
    throw std::runtime_error("chemistry engine: species " + std::to_string(species) +
                             " has copies but no compartment with volume on its side of the membrane");
  if (volume_.empty()) {
    // Unconfined species keep f = a = 1, which these arrays then also describe.
    volume_.assign(static_cast<std::size_t>(C_) * S_, 1.0);
    hop_out_.assign(volume_.size(), 0.0);
    face_rate_.assign(volume_.size() * 6, 0.0);
    for (Index c = 0; c < C_; ++c)
      for (Index s = 0; s < S_; ++s)
        for (int f = 0; f < 6; ++f)
          if (faces_.mask(c) >> f & 1) {
            face_rate_[(static_cast<std::size_t>(c) * S_ + s) * 6 + f] = net_.hopRate[s];
            hop_out_[static_cast<std::size_t>(c) * S_ + s] += net_.hopRate[s];
          }
  }
  std::vector<char> dirty(C_, 0);
  if (!confined_[species]) {
    confined_[species] = 1;
    std::fill(dirty.begin(), dirty.end(), 1);
    for (Index r = 0; r < R_; ++r)
      if (side_species_[r] == species) scale_species_[r] = species;
  }
  for (Index c = 0; c < C_; ++c) {
    double& f = volume_[static_cast<std::size_t>(c) * S_ + species];
    if (f != volume[c]) dirty[c] = 1;
    f = volume[c];
  }
  // Hop rates D/h^2 * a / f_source, zero into or out of inactive compartments.
  for (Index c = 0; c < C_; ++c) {
    const std::size_t i = static_cast<std::size_t>(c) * S_ + species;
    double total = 0.0;
    for (int f = 0; f < 6; ++f) {
      double rate = 0.0;
      if ((faces_.mask(c) >> f & 1) && volume[c] > 0.0 && volume[faces_.across(c, f)] > 0.0)
        rate = net_.hopRate[species] * faces[c][f] / volume[c];
      if (face_rate_[i * 6 + f] != rate) dirty[c] = 1;
      face_rate_[i * 6 + f] = rate;
      total += rate;
    }
    hop_out_[i] = total;
  }
  relocate(species, dirty);
  for (Index c = 0; c < C_; ++c)
    if (dirty[c]) refreshCompartment(c);
}

// Multi-source breadth-first search from every active compartment (in index order,
// faces in order): each compartment learns its nearest active one, deterministically.
void EngineBase::relocate(Index s, std::vector<char>& dirty) {
  bool stranded = false;
  for (Index c = 0; c < C_ && !stranded; ++c)
    stranded = !active(c, s) && copies_[static_cast<std::size_t>(c) * S_ + s] > 0;
  if (!stranded) return;
  std::vector<Index> nearest(C_, -1);
  std::deque<Index> queue;
  for (Index c = 0; c < C_; ++c)
    if (active(c, s)) {
      nearest[c] = c;
      queue.push_back(c);
    }
  while (!queue.empty()) {
    const Index c = queue.front();
    queue.pop_front();
    for (int f = 0; f < 6; ++f) {
      if (!(faces_.mask(c) >> f & 1)) continue;
      const Index d = faces_.across(c, f);
      if (nearest[d] >= 0) continue;
      nearest[d] = nearest[c];
      queue.push_back(d);
    }
  }
  for (Index c = 0; c < C_; ++c) {
    int& n = copies_[static_cast<std::size_t>(c) * S_ + s];
    if (active(c, s) || n == 0) continue;
    copies_[static_cast<std::size_t>(nearest[c]) * S_ + s] += n;
    n = 0;
    dirty[c] = dirty[nearest[c]] = 1;
  }
}

}  // namespace cortex
