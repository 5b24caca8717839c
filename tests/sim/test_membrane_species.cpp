// Membrane species in a System (issue 14): the config's [[membrane.species]] become
// copies on the vertices that the engine's surface subvolumes take over for each
// chemistry window and hand back after it.
//
// - Adsorption from the bulk and desorption (thesis eqs. 3.12–3.14): every copy flips
//   independently between the bulk (adsorbing at r_ad A / V per copy) and the membrane
//   (desorbing at r_de), so the number on the membrane is exactly binomial with
//   p = r_ad A / (r_ad A + r_de V) at equilibrium: N_surface/N_bulk = r_ad A/(r_de V).
//   Chi-square of 2000 samples spaced 5 relaxation times apart, for a bulk species free
//   in the box and one confined to the vesicle's inside (V = its volume on that side as
//   the engine sees it: Σ_c f_c V_c over the sliced compartments). The bulk mixes over
//   the 2 x 2 x 2 grid in ~0.1 s (hops at D/h² = 4 /s per face), faster than the
//   sampling interval (0.25 s).
// - Through a run that deflates and remeshes the vesicle, surface copies are conserved
//   exactly at every window, and the engine and the membrane agree on them.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <numeric>

#include "chem/chem_statistics.hpp"
#include "io/config.hpp"
#include "sim/confinement.hpp"
#include "sim/simulation.hpp"
#include "sim/surface_drift.hpp"
#include "sim/surface_graph.hpp"
#include "sim/system.hpp"

namespace cortex {
namespace {

std::string adsorptionConfig(const std::string& side, const std::string& potential) {
  return fmt::format(R"([simulation]
seed = 11
[[membrane]]
name = "vesicle"
shape = "sphere"
center = [500.0, 500.0, 500.0]
radius = 400.0
mesh_size = 50.0
bending_modulus = 100.0
[[membrane.species]]
name = "M"
diffusion = 1.0e4
{}
[compartments]
size = 500.0
shape = [2, 2, 2]
[[species]]
name = "G"
diffusion = 1.0e6
copies = 200
{}
[[reaction]]
equation = "G -> M"
rate = 5000.0
[[reaction]]
equation = "M -> G"
rate = 10.0
)",
                     potential, side);
}

constexpr const char* kStripe = R"([membrane.species.potential]
type = "gaussian_stripe"
center = 500.0
width = 200.0
height = 1.5)";

// Σ_j |C_j| e^{−βV_j}: the membrane's area weighted by the potential of its species.
double boltzmannArea(const Membrane& m, const std::optional<SurfacePotentialConfig>& potential) {
  const auto& x = m.mesh().positions();
  const std::vector<double> cell = dualCellAreas(m.mesh());
  double a = 0.0;
  for (Index v = 0; v < m.mesh().numVertices(); ++v)
    a += cell[v] * (potential ? std::exp(-surfacePotential(*potential, x[v])) : 1.0);
  return a;
}

int surfaceCopies(const System& system) {
  const ChemistryEngine& chem = *system.chemistry();
  int n = 0;
  for (Index i = chem.regionStart(1); i < chem.numSubvolumes(); ++i) n += chem.copies(i, 1);
  return n;
}

void expectBinomialAdsorption(const std::string& side, const std::string& potential = "",
                              const std::string& engine = "", int count = 2000) {
  const Config config = parseConfig(adsorptionConfig(side, potential) + engine, "adsorption.toml", ".", {});
  System system(config);
  const Membrane& m = *system.membranes()[0];
  double bulk_volume = system.grid().count() * system.grid().volume();
  if (!side.empty()) {
    const auto fractions = sideFractions(system.membranes(), config.chemistry->sides, system.grid());
    bulk_volume = 0.0;
    for (double f : fractions[0]->volume) bulk_volume += f * system.grid().volume();
  }
  // Per copy, 1/s: a bulk copy binds vertex j at r_ad |C_j| / V, leaves it at r_de e^{βV_j}.
  const double adsorb = 5000.0 * boltzmannArea(m, config.membranes[0].species[0].potential) / bulk_volume;
  const double desorb = 10.0;
  const double p = adsorb / (adsorb + desorb);
  const double spacing = 5.0 / (adsorb + desorb);
  std::vector<int> samples;
  double t = 10.0 * spacing;
  system.chemistry()->advance(t);
  for (int k = 0; k < count; ++k) {
    t += spacing;
    system.chemistry()->advance(t);
    samples.push_back(surfaceCopies(system));
  }
  const int n = 200;
  const auto binomial = [&](int k) {
    if (k > n) return 0.0;
    return std::exp(std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0) + k * std::log(p) +
                    (n - k) * std::log1p(-p));
  };
  const chemtest::ChiSquare fit = chemtest::goodnessOfFit(samples, binomial);
  EXPECT_GT(fit.p, 1e-3) << side << ": chi2 " << fit.statistic << " on " << fit.dof << " dof; p_surface = " << p;
  EXPECT_LT(std::abs(chemtest::lagOneCorrelation(samples)), 0.1);
  const double mean = chemtest::moments(samples).mean;
  EXPECT_NEAR(mean / (n - mean), adsorb / desorb, 0.05 * adsorb / desorb) << "N_surface / N_bulk";
}

TEST(MembraneSpecies, AdsorptionEquilibriumIsBinomialWithRatioRadATimesAreaOverRdeTimesVolume) {
  expectBinomialAdsorption("");
}

// Binding is carried by each compartment as one channel (ReactionNetwork::aggregated); the
// direct method draws the vertex through its own event loop (500 samples: it sums every
// channel per event and is 40× slower here).
TEST(MembraneSpecies, AdsorptionEquilibriumIsBinomialWithTheDirectMethodToo) {
  expectBinomialAdsorption("", "", "[chemistry]\nengine = \"direct\"", 500);
}

TEST(MembraneSpecies, AdsorptionFromAConfinedBulkUsesTheVolumeOnItsSide) {
  expectBinomialAdsorption("inside = \"vesicle\"");
}

// With a potential V on the membrane species, unbinding fires at r_de e^{βV} (thesis eq.
// 3.14): N_surface/N_bulk = r_ad Σ_j |C_j| e^{−βV_j} / (r_de V) (the issue's
// r_ad A e^{−βV}/(r_de V) for a uniform V), here for a 1.5 k_BT stripe across the vesicle.
TEST(MembraneSpecies, AdsorptionUnderAPotentialWeighsTheAreaByBoltzmannFactors) {
  expectBinomialAdsorption("", kStripe);
}

// Copies on the membrane at a window's end, from the membrane's vertices.
class CopyCounter : public RunObserver {
 public:
  void onWindow(const System& system, const MinimizationResult&) override {
    const Membrane& m = *system.membranes()[0];
    const ChemistryEngine& chem = *system.chemistry();
    ASSERT_EQ(chem.numSubvolumes() - chem.regionStart(1), m.mesh().numVertices());
    for (std::size_t s = 0; s < m.speciesNames().size(); ++s) {
      const std::vector<int>& c = m.speciesCopies()[s];
      totals[s].push_back(std::accumulate(c.begin(), c.end(), 0L));
      const Index model_index = 1 + static_cast<Index>(s);  // after the one 3D species
      for (Index v = 0; v < m.mesh().numVertices(); ++v)
        ASSERT_EQ(chem.copies(chem.regionStart(1) + v, model_index), c[v]) << "vertex " << v;
    }
    bulk.push_back(0);
    for (Index i = 0; i < chem.regionStart(1); ++i) bulk.back() += chem.copies(i, 0);
  }
  std::vector<long> totals[2];
  std::vector<long> bulk;
};

TEST(MembraneSpecies, CopiesAreConservedThroughADeflatingRemeshedRun) {
  const Config config = loadConfig(CORTEX_SOURCE_DIR "/examples/membrane_proteins.toml", {"simulation.end_time=0.03"});
  System system(config);
  CopyCounter counter;
  Simulation sim(system, config.simulation, config.mechanics, counter);
  ASSERT_EQ(sim.run(true), RunOutcome::kFinished);
  const RemeshStats& remeshed = system.membranes()[0]->remeshTotals();
  EXPECT_GT(remeshed.splits + remeshed.collapses + remeshed.flips, 0) << "the run did not remesh";
  ASSERT_EQ(counter.totals[0].size(), 7u);
  for (std::size_t k = 0; k < counter.bulk.size(); ++k) {
    EXPECT_EQ(counter.totals[0][k], 5000) << "P, window " << k;
    EXPECT_EQ(counter.totals[1][k] + counter.bulk[k], 20000) << "M + G, window " << k;
  }
  EXPECT_GT(counter.totals[1].back(), 0) << "nothing adsorbed";
}

}  // namespace
}  // namespace cortex
