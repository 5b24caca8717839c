#include "chem_models.hpp"

namespace cortex::chemtest {

ChemistryModel wellMixed(const std::vector<std::string>& species,
                         const std::vector<std::pair<std::string, double>>& reactions) {
  ChemistryModel m;
  for (const std::string& s : species) m.species.push_back({s, 0.0});
  std::vector<ReactionDef> defs;
  for (const auto& [equation, rate] : reactions) defs.push_back(parseReaction(equation, rate, m.species));
  m.addReactions("test", std::move(defs));
  return m;
}

ChemistryModel randomNetwork(int num_species, int num_reactions, std::uint64_t seed, const CompartmentGrid& grid,
                             double diffusion) {
  ChemistryModel m;
  m.volumes = gridGraph(grid);
  std::vector<ReactionDef> defs;
  for (int s = 0; s < num_species; ++s) m.species.push_back({"X" + std::to_string(s), diffusion});
  RandomStream rng(seed, StreamId::kInitialConditions);
  const auto pick = [&] { return "X" + std::to_string(static_cast<int>(rng.uniform() * num_species)); };
  const double nv = grid.copiesPerMicromolar();
  for (int s = 0; s < num_species; ++s) {
    const std::string x = "X" + std::to_string(s);
    defs.push_back(parseReaction("-> " + x, (2.0 + 4.0 * rng.uniform()) / nv, m.species));
    defs.push_back(parseReaction(x + " ->", 0.5 + rng.uniform(), m.species));
  }
  while (static_cast<int>(defs.size()) < num_reactions) {
    // Draws in separate statements: the operands of + are evaluated in unspecified order.
    const double u = rng.uniform();
    const double first = 0.2 + 0.8 * rng.uniform();            // 1/s
    const double second = (0.02 + 0.08 * rng.uniform()) * nv;  // 1/(µM s): 0.02-0.1 per pair and s
    std::string x[4];
    for (std::string& name : x) name = pick();
    if (u < 0.4)
      defs.push_back(parseReaction(x[0] + " -> " + x[1], first, m.species));
    else if (u < 0.7)
      defs.push_back(parseReaction(x[0] + " + " + x[1] + " -> " + x[2], second, m.species));
    else if (u < 0.8)
      defs.push_back(parseReaction("2 " + x[0] + " -> " + x[1], second, m.species));
    else
      defs.push_back(parseReaction(x[0] + " + " + x[1] + " -> " + x[2] + " + " + x[3], second, m.species));
  }
  m.addReactions("test", std::move(defs));
  return m;
}

std::vector<int> sample(ChemistryEngine& engine, double interval, int count,
                        const std::function<int(const ChemistryEngine&)>& observe) {
  std::vector<int> out;
  out.reserve(count);
  for (int i = 0; i < count; ++i) {
    engine.advance(engine.time() + interval);
    out.push_back(observe(engine));
  }
  return out;
}

int total(const ChemistryEngine& engine, Index compartments, Index species) {
  int n = 0;
  for (Index c = 0; c < compartments; ++c) n += engine.copies(c, species);
  return n;
}

}  // namespace cortex::chemtest
