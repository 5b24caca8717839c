#include "sim/chemistry_builder.hpp"

#include "core/random.hpp"

namespace cortex {

std::vector<int> initialCopies(const ChemistryConfig& config, std::uint64_t seed) {
  const Index compartments = config.model.grid.count();
  const auto species = static_cast<Index>(config.model.species.size());
  std::vector<int> copies(static_cast<std::size_t>(compartments) * species, 0);
  RandomStream random(seed, StreamId::kInitialConditions);
  for (Index s = 0; s < species; ++s)
    for (std::int64_t n = 0; n < config.initial_copies[s]; ++n) {
      const auto c = std::min<Index>(static_cast<Index>(random.uniform() * compartments), compartments - 1);
      ++copies[static_cast<std::size_t>(c) * species + s];
    }
  return copies;
}

std::unique_ptr<ChemistryEngine> buildChemistry(const ChemistryConfig& config, std::uint64_t seed) {
  return makeChemistryEngine(config.engine, config.model, initialCopies(config, seed), seed);
}

}  // namespace cortex
