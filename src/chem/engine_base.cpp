#include "chem/engine_base.hpp"

#include <cmath>
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
      reaction_events_(net_.numReactions, 0) {
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

}  // namespace cortex
