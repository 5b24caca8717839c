#include "chem/chemistry_model.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string_view>

#include "core/error.hpp"

namespace cortex {

int ReactionDef::order() const {
  int n = 0;
  for (const Stoichiometry& s : reactants) n += s.count;
  return n;
}

namespace {

std::string_view trim(std::string_view s) {
  const auto space = [](char ch) { return std::isspace(static_cast<unsigned char>(ch)) != 0; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

// One side of the arrow: terms separated by '+', each "name" or "count name". Repeated
// species are merged in order of first appearance, so "A + A" is stored as "2 A".
std::vector<Stoichiometry> parseSide(std::string_view side, const std::vector<SpeciesDef>& species,
                                     const std::string& equation) {
  std::vector<Stoichiometry> terms;
  side = trim(side);
  if (side.empty()) return terms;
  const auto fail = [&](const std::string& what) { throw InputError("reaction \"" + equation + "\": " + what); };
  while (true) {
    const std::size_t plus = side.find('+');
    std::string_view term = trim(side.substr(0, plus));
    if (term.empty()) fail("empty term around '+'");

    int count = 1;
    std::size_t digits = 0;
    while (digits < term.size() && std::isdigit(static_cast<unsigned char>(term[digits]))) ++digits;
    const bool known_as_is =
        std::any_of(species.begin(), species.end(), [&](const SpeciesDef& s) { return s.name == term; });
    if (digits > 0 && !known_as_is) {
      if (digits == term.size()) fail("term \"" + std::string(term) + "\" has a count but no species");
      if (!std::isspace(static_cast<unsigned char>(term[digits])))
        fail("unknown species \"" + std::string(term) + "\" (write a count as \"2 A\")");
      if (digits > 6) fail("count in \"" + std::string(term) + "\" is too large");
      count = std::stoi(std::string(term.substr(0, digits)));
      if (count == 0) fail("count 0 in \"" + std::string(term) + "\"");
      term = trim(term.substr(digits));
    }

    const auto it = std::find_if(species.begin(), species.end(), [&](const SpeciesDef& s) { return s.name == term; });
    if (it == species.end()) fail("unknown species \"" + std::string(term) + "\"");
    const Index id = static_cast<Index>(it - species.begin());
    const auto same = std::find_if(terms.begin(), terms.end(), [&](const Stoichiometry& s) { return s.species == id; });
    if (same != terms.end())
      same->count += count;
    else
      terms.push_back({id, count});

    if (plus == std::string_view::npos) break;
    side = side.substr(plus + 1);
  }
  return terms;
}

}  // namespace

ReactionDef parseReaction(const std::string& equation, double rate, const std::vector<SpeciesDef>& species) {
  const std::string_view text = equation;
  const std::size_t arrow = text.find("->");
  if (arrow == std::string_view::npos)
    throw InputError("reaction \"" + equation + "\": no \"->\" between reactants and products");
  if (text.find("->", arrow + 2) != std::string_view::npos)
    throw InputError("reaction \"" + equation + "\": more than one \"->\"");
  if (!std::isfinite(rate) || rate < 0.0)
    throw InputError("reaction \"" + equation + "\": rate must be finite and >= 0");

  ReactionDef r;
  r.equation = equation;
  r.rate = rate;
  r.reactants = parseSide(text.substr(0, arrow), species, equation);
  r.products = parseSide(text.substr(arrow + 2), species, equation);
  if (r.reactants.empty() && r.products.empty())
    throw InputError("reaction \"" + equation + "\": both sides are empty");
  if (r.order() > 2)
    throw InputError("reaction \"" + equation + "\": order " + std::to_string(r.order()) +
                     " is not supported (at most 2 reactant copies, mass action)");
  return r;
}

ReactionRange ChemistryModel::addReactions(const std::string& owner, std::vector<ReactionDef> defs) {
  ReactionRange range{owner, static_cast<Index>(reactions.size()), static_cast<Index>(reactions.size() + defs.size())};
  for (ReactionDef& d : defs) reactions.push_back(std::move(d));
  ranges.push_back(range);
  return range;
}

double stochasticRateConstant(double rate, int order, double volume_nm3) {
  const double nv = copiesPerMicromolar(volume_nm3);
  switch (order) {
    case 0:
      return rate * nv;
    case 1:
      return rate;
    default:
      return rate / nv;  // A + B and 2 A alike: h = n_A n_B or n (n - 1)
  }
}

}  // namespace cortex
