#include "sim/chemistry_builder.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/random.hpp"

namespace cortex {

ChemistryModel chemistryModel(const ChemistryConfig& config) {
  ChemistryModel model;
  model.volumes = gridGraph(config.grid);
  model.surfaces = config.surfaces;
  model.species = config.species;
  model.addReactions("config", config.reactions);
  return model;
}

std::vector<int> initialCopies(const ChemistryConfig& config, std::uint64_t seed,
                               const std::vector<std::vector<double>>& volume_weights) {
  const Index compartments = config.grid.count();
  const auto species = static_cast<Index>(config.species.size());
  std::vector<int> copies(static_cast<std::size_t>(compartments) * species, 0);
  RandomStream random(seed, StreamId::kInitialConditions);
  for (Index s = 0; s < species; ++s) {
    const bool weighted = static_cast<std::size_t>(s) < volume_weights.size() && !volume_weights[s].empty();
    std::vector<double> cumulative;
    if (weighted) {
      cumulative.resize(compartments);
      double sum = 0.0;
      for (Index c = 0; c < compartments; ++c) cumulative[c] = sum += volume_weights[s][c];
      if (!(sum > 0.0) && config.initial_copies[s] > 0)
        throw InputError(fmt::format(
            "[[species]] \"{}\": {} \"{}\" has no volume inside the compartment grid (does the membrane "
            "lie outside the box [0, shape*size]?), so its {} copies have nowhere to go",
            config.species[s].name, config.sides[s].outside ? "outside" : "inside",
            config.sides[s].membrane, config.initial_copies[s]));
    }
    // One uniform number per copy either way, so unconfined species draw as before.
    for (std::int64_t n = 0; n < config.initial_copies[s]; ++n) {
      const double u = random.uniform();
      Index c;
      if (weighted) {
        // First compartment whose cumulative weight exceeds u * total: never one of weight 0.
        c = static_cast<Index>(std::upper_bound(cumulative.begin(), cumulative.end(), u * cumulative.back()) -
                               cumulative.begin());
        c = std::min<Index>(c, compartments - 1);
        while (volume_weights[s][c] <= 0.0) --c;  // u * total rounded onto the very end
      } else {
        c = std::min<Index>(static_cast<Index>(u * compartments), compartments - 1);
      }
      ++copies[static_cast<std::size_t>(c) * species + s];
    }
  }
  return copies;
}

}  // namespace cortex
