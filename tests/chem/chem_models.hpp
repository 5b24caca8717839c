// Small models and sampling loops shared by the chemistry engine tests.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "chem/chemistry_engine.hpp"

namespace cortex::chemtest {

inline const char* engineName(EngineKind kind) { return kind == EngineKind::kNextSubvolume ? "nsm" : "direct"; }

// Non-diffusing species in one 500 nm compartment with the given reactions (equation, rate),
// owned by "test".
ChemistryModel wellMixed(const std::vector<std::string>& species,
                         const std::vector<std::pair<std::string, double>>& reactions);

// A random but fixed network (generated from `seed` with the counter-based stream):
// every species has an inflow and a first-order decay, the other reactions are
// conversions, bindings, dimerizations and exchanges. None of those creates copies, so
// the total is bounded by the inflow-decay process and the network is ergodic.
ChemistryModel randomNetwork(int num_species, int num_reactions, std::uint64_t seed, const CompartmentGrid& grid,
                             double diffusion);

// Advances the engine `count` times by `interval`, recording observe(engine) after each.
std::vector<int> sample(ChemistryEngine& engine, double interval, int count,
                        const std::function<int(const ChemistryEngine&)>& observe);

// Copies of `species` summed over all compartments.
int total(const ChemistryEngine& engine, Index compartments, Index species);

}  // namespace cortex::chemtest
