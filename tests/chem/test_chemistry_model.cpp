// Reaction parsing, stochastic rate constants and the compartment grid.
#include <gtest/gtest.h>

#include "chem/chemistry_model.hpp"
#include "core/error.hpp"

namespace cortex {
namespace {

const std::vector<SpeciesDef> kSpecies = {{"A", 0.0}, {"B", 0.0}, {"C", 0.0}, {"G-actin", 0.0}};

using Terms = std::vector<std::pair<Index, int>>;
Terms terms(const std::vector<Stoichiometry>& side) {
  Terms t;
  for (const Stoichiometry& s : side) t.emplace_back(s.species, s.count);
  return t;
}

TEST(ParseReaction, ReadsEveryAllowedForm) {
  const ReactionDef bind = parseReaction("A + B -> C", 2.0, kSpecies);
  EXPECT_EQ(terms(bind.reactants), (Terms{{0, 1}, {1, 1}}));
  EXPECT_EQ(terms(bind.products), (Terms{{2, 1}}));
  EXPECT_EQ(bind.order(), 2);
  EXPECT_EQ(bind.rate, 2.0);
  EXPECT_EQ(bind.equation, "A + B -> C");

  const ReactionDef dimer = parseReaction("2 A -> B", 1.0, kSpecies);
  EXPECT_EQ(terms(dimer.reactants), (Terms{{0, 2}}));
  EXPECT_EQ(dimer.order(), 2);

  const ReactionDef inflow = parseReaction("-> A", 1.0, kSpecies);
  EXPECT_TRUE(inflow.reactants.empty());
  EXPECT_EQ(terms(inflow.products), (Terms{{0, 1}}));
  EXPECT_EQ(inflow.order(), 0);

  const ReactionDef decay = parseReaction("A ->", 1.0, kSpecies);
  EXPECT_EQ(terms(decay.reactants), (Terms{{0, 1}}));
  EXPECT_TRUE(decay.products.empty());
  EXPECT_EQ(decay.order(), 1);

  EXPECT_EQ(terms(parseReaction("A -> 3 B + C", 1.0, kSpecies).products), (Terms{{1, 3}, {2, 1}}));
  EXPECT_EQ(terms(parseReaction("  A+B->C  ", 1.0, kSpecies).reactants), (Terms{{0, 1}, {1, 1}}));
  // A hyphen inside a name is not an arrow.
  EXPECT_EQ(terms(parseReaction("G-actin -> A", 1.0, kSpecies).reactants), (Terms{{3, 1}}));
}

TEST(ParseReaction, MergesRepeatedSpecies) {
  const ReactionDef r = parseReaction("A + A -> B + B + C", 1.0, kSpecies);
  EXPECT_EQ(terms(r.reactants), (Terms{{0, 2}}));
  EXPECT_EQ(terms(r.products), (Terms{{1, 2}, {2, 1}}));
  EXPECT_EQ(r.order(), 2);
}

void expectError(const std::string& equation, const std::string& fragment, double rate = 1.0) {
  try {
    parseReaction(equation, rate, kSpecies);
    ADD_FAILURE() << "\"" << equation << "\" was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("\"" + equation + "\""), std::string::npos) << what;  // names the equation
    EXPECT_NE(what.find(fragment), std::string::npos) << what;
  }
}

TEST(ParseReaction, RefusesMalformedEquationsNamingThem) {
  expectError("A + D -> B", "unknown species \"D\"");
  expectError("A -> B + X", "unknown species \"X\"");
  expectError("->", "both sides are empty");
  expectError("  ->  ", "both sides are empty");
  expectError("A B -> C", "unknown species \"A B\"");
  expectError("A + -> B", "empty term");
  expectError("+ A -> B", "empty term");
  expectError("A -> B -> C", "more than one");
  expectError("A = B", "no \"->\"");
  expectError("2A -> B", "write a count as");
  expectError("0 A -> B", "count 0");
  expectError("2 -> B", "no species");
  expectError("A + B + C -> A", "order 3");
  expectError("A + 2 A -> B", "order 3");
  expectError("3 A -> B", "order 3");
  expectError("A -> B", "rate", -1.0);
}

// Header convention: order 0 k·N·V, order 1 k, order 2 k/(N·V), N = 602.214 per µM fL.
TEST(StochasticRateConstant, ConvertsConcentrationUnitsToCopies) {
  const double volume = 500.0 * 500.0 * 500.0;               // nm^3 = 0.125 fL
  const double nv = kCopiesPerMicromolarFemtoliter * 0.125;  // copies per µM
  auto constant = [&](const char* equation, double rate) {
    const ReactionDef r = parseReaction(equation, rate, kSpecies);
    return stochasticRateConstant(r.rate, r.order(), volume);
  };
  EXPECT_NEAR(constant("-> A", 2.0), 2.0 * nv, 1e-12 * nv);
  EXPECT_DOUBLE_EQ(constant("A -> B", 3.0), 3.0);
  EXPECT_NEAR(constant("A + B -> C", 5.0), 5.0 / nv, 1e-12);
  EXPECT_NEAR(constant("2 A -> C", 5.0), 5.0 / nv, 1e-12);
}

// The grid's subvolume graph: one subvolume of h^3 per compartment, an edge per face
// neighbour (none through the walls) with l^2 = h^2, in face order; a consistent graph.
TEST(CompartmentGrid, GraphHasAnEdgePerFaceNeighbourInFaceOrder) {
  const CompartmentGrid g{100.0, {4, 3, 2}};
  const SubvolumeGraph graph = gridGraph(g);
  ASSERT_EQ(graph.count(), g.count());
  EXPECT_NO_THROW(validate(graph, "grid"));
  std::vector<std::array<double, 6>> faces(g.count());
  for (Index c = 0; c < g.count(); ++c)
    for (int f = 0; f < 6; ++f) faces[c][f] = 10.0 * c + f;
  const std::vector<double> per_edge = gridEdgeValues(g, faces);
  ASSERT_EQ(per_edge.size(), graph.target.size());
  for (Index c = 0; c < g.count(); ++c) {
    EXPECT_EQ(graph.size[c], 1e6);
    const auto [i, j, k] = g.coords(c);
    const int expected = (i > 0) + (i < 3) + (j > 0) + (j < 2) + (k > 0) + (k < 1);
    ASSERT_EQ(graph.start[c + 1] - graph.start[c], expected) << "compartment " << c;
    int last_face = -1;
    for (Index e = graph.start[c]; e < graph.start[c + 1]; ++e) {
      EXPECT_EQ(graph.hop_length2[e], 1e4);
      const auto [a, b, d] = g.coords(graph.target[e]);
      EXPECT_EQ(std::abs(a - i) + std::abs(b - j) + std::abs(d - k), 1);
      // The face this edge crosses, from the value carried over for it.
      const int face = static_cast<int>(per_edge[e] - 10.0 * c);
      const int axis = face / 2, step = face % 2 ? 1 : -1;
      const std::array<int, 3> from{i, j, k}, to{a, b, d};
      EXPECT_EQ(to[axis] - from[axis], step);
      EXPECT_GT(face, last_face);
      last_face = face;
    }
  }
}

TEST(CompartmentGrid, LocateFindsTheHoldingCompartmentAndClamps) {
  CompartmentGrid g;
  g.size = 100.0;
  g.shape = {4, 3, 2};
  EXPECT_EQ(g.locate(Vec3(150.0, 250.0, 50.0)), g.index(1, 2, 0));
  EXPECT_EQ(g.locate(Vec3(399.9, 0.0, 199.9)), g.index(3, 0, 1));
  EXPECT_EQ(g.locate(Vec3(-10.0, 1e9, 200.0)), g.index(0, 2, 1));
  EXPECT_EQ(g.locate(Vec3(std::nan(""), 0.0, 0.0)), g.index(0, 0, 0));
}

}  // namespace
}  // namespace cortex
