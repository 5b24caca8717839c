// The membrane–bead excluded volume as a term: the energy of a bead over a large flat
// membrane against the closed form of an unbounded plane less the part beyond the
// cut-off; the same energy and gradients whether both bodies move or one is relaxed
// alone; the Verlet list complete after large random moves and a remeshing, and what was
// kept of a held body read again in the next relaxation (the energy equals that of a
// term built afresh, to the last bit); infinite energy for a bead on the membrane.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/constants.hpp"
#include "filament/filament.hpp"
#include "interact/membrane_bead_exclusion.hpp"
#include "mesh/planar_patch.hpp"
#include "mesh/surface_mesh.hpp"

namespace cortex {
namespace {

struct Scene {
  std::unique_ptr<Membrane> membrane;
  std::unique_ptr<FilamentNetwork> network;
  std::vector<double> x;  // [membrane, beads]

  Scene(double size, double edge) {
    membrane = std::make_unique<Membrane>(
        "patch", SurfaceMesh::fromSoup(planarPatch(Vec3(0, 0, 0), size, size, edge), "patch"), MembraneMechanics{},
        std::vector<char>{});
    FilamentConfig config;
    config.types.resize(1);
    network = std::make_unique<FilamentNetwork>(config);
  }
  void layOut() {
    membrane->setOffset(0);
    network->setOffset(membrane->numPoints());
    x.assign(3 * static_cast<std::size_t>(membrane->numPoints() + network->numPoints()), 0.0);
    membrane->gather(x.data());
    network->gather(x.data() + 3 * membrane->numPoints());
  }
  std::size_t vertexCoordinates() const { return 3 * static_cast<std::size_t>(membrane->numPoints()); }
};

TEST(MembraneBeadExclusion, ABeadOverAPlaneFeelsTheClosedForm) {
  // A bead at height h over the middle of a 600 nm patch of 10 nm triangles. The plane
  // gives k π/h² = k ∫ 2πρ dρ/(h² + ρ²)². Every triangle with a point within cutoff/2 of
  // the bead counts fully (they cover the disk of distances up to cutoff/2), none with
  // all its points beyond cutoff + edge counts: the energy lies between the plane's less
  // beyond those distances, k π (1/h² − 1/r²) for r = cutoff/2 and r = cutoff + edge.
  Scene s(600.0, 10.0);
  s.network->addFilament(makeStraightFilament(0, Vec3(0.3, -0.2, -40.0), Vec3(0, 0, 1), 14, 40, 2.7));
  s.layOut();
  const MembraneBeadExclusionParams p{100.0, 20.0, ExclusionBeads::kPlusEnds};
  MembraneBeadExclusion term(*s.membrane, *s.network, p);
  const double h = -s.network->filaments()[0].beads.back().z();
  ASSERT_NEAR(h, 2.2, 1e-9);
  const double energy = term.evaluate({s.x.data(), nullptr, 1});
  const auto lessBeyond = [&](double r) { return p.stiffness * constants::kPi * (1.0 / (h * h) - 1.0 / (r * r)); };
  EXPECT_GT(energy, lessBeyond(0.5 * p.cutoff));
  EXPECT_LT(energy, lessBeyond(p.cutoff + 10.0 * std::sqrt(2.0)));
  // Those bounds are 4.6% apart here: the fade and cut-off remove little of the plane's.
  EXPECT_GT(term.activePairs(), 10u);
  // And what they remove depends on the distance alone, so over a plane it pushes with
  // nothing: the force is the full plane's 2πk/h³, up to whole triangles entering the
  // fade by their nearest point.
  std::vector<double> g(s.x.size(), 0.0);
  term.evaluate({s.x.data(), g.data(), 2});
  const double push = g.back();  // the tip is below the membrane and pushed down: dE/dz > 0, pN
  EXPECT_NEAR(push / (2 * constants::kPi * p.stiffness / (h * h * h)), 1.0, 1e-3);  // measured 1.1e-4
}

TEST(MembraneBeadExclusion, OneBodyAloneSeesTheOtherWhereItIsHeld) {
  Scene s(300.0, 15.0);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int f = 0; f < 8; ++f)
    s.network->addFilament(makeStraightFilament(0, Vec3(100 * u(rng), 100 * u(rng), -40.0 - 10 * u(rng)),
                                                Vec3(0.3 * u(rng), 0.3 * u(rng), 1.0).normalized(), 14, 4, 2.7));
  s.layOut();
  MembraneBeadExclusion term(*s.membrane, *s.network, {});
  std::vector<double> full(s.x.size(), 0.0);
  const double energy = term.evaluate({s.x.data(), full.data(), 1});
  ASSERT_GT(energy, 0.0);
  // The membrane alone, at offset zero: the same energy and vertex gradient.
  std::vector<double> vertices(s.x.begin(), s.x.begin() + s.vertexCoordinates()), g_vertices(vertices.size(), 0.0);
  EXPECT_EQ(term.evaluate({vertices.data(), g_vertices.data(), 2, s.membrane.get()}), energy);
  for (std::size_t i = 0; i < vertices.size(); ++i) EXPECT_EQ(g_vertices[i], full[i]);
  double norm = 0.0;
  for (double g : g_vertices) norm += g * g;
  EXPECT_GT(norm, 0.0);
  // The network alone: the same energy and bead gradient.
  s.network->setOffset(0);
  std::vector<double> beads(s.x.begin() + s.vertexCoordinates(), s.x.end()), g_beads(beads.size(), 0.0);
  // To rounding: the kernel differentiated along the beads alone is other instructions
  // than along everything (triangle_inverse_fourth.hpp).
  EXPECT_NEAR(term.evaluate({beads.data(), g_beads.data(), 3, s.network.get()}), energy, 1e-13 * energy);
  double scale = 0.0;
  for (std::size_t i = 0; i < beads.size(); ++i) scale = std::max(scale, std::abs(full[s.vertexCoordinates() + i]));
  for (std::size_t i = 0; i < beads.size(); ++i) EXPECT_NEAR(g_beads[i], full[s.vertexCoordinates() + i], 1e-12 * scale);
}

TEST(MembraneBeadExclusion, EnergyDoesNotDependOnWhenThePairsWereListed) {
  Scene s(300.0, 15.0);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int f = 0; f < 30; ++f)
    s.network->addFilament(makeStraightFilament(0, Vec3(130 * u(rng), 130 * u(rng), 25 * u(rng)),
                                                Vec3(u(rng), u(rng), u(rng)).normalized(), 12, 4, 2.7));
  s.layOut();
  MembraneBeadExclusion kept(*s.membrane, *s.network, {});
  std::int64_t energies = 0;
  for (int move = 0; move < 200; ++move) {
    // Moves of every size: within the skin (the list is reused) and beyond (rebuilt). Two
    // moves in three move the beads alone and put the membrane back at its base positions,
    // as a filament relaxation holds it; on the second of them a rebuild keeps the
    // triangles' cells.
    const double scale = std::pow(10.0, -2.0 + 3.0 * (0.5 + 0.5 * u(rng)));
    std::vector<double> x = s.x;
    const std::size_t first_moved = move % 3 == 0 ? 0 : s.vertexCoordinates();
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double step = scale * u(rng);
      if (i >= first_moved) x[i] += step;
    }
    if (move % 3 == 0) {
      // The patch also slides within its plane, by more than a cell of the triangles'
      // index: kept cells would then list the wrong triangles.
      const double dx = 60.0 * u(rng), dy = 60.0 * u(rng);
      for (std::size_t i = 0; i < s.vertexCoordinates(); i += 3) x[i] += dx, x[i + 1] += dy;
    }
    if (move == 100) {
      // A remeshing changes the connectivity and the vertex count.
      RemeshSettings settings;
      settings.sizing.flat_size = 10.0;
      settings.sizing.min_size = 5.0;
      s.membrane->remesh(settings);
      s.layOut();
      x = s.x;
    }
    // The bodies hold the moved positions, as after an accepted step.
    s.membrane->scatter(x.data());
    s.network->scatter(x.data() + s.vertexCoordinates());
    MembraneBeadExclusion fresh(*s.membrane, *s.network, {});
    const double e_kept = kept.evaluate({x.data(), nullptr, static_cast<std::uint64_t>(10 + move)});
    const double e_fresh = fresh.evaluate({x.data(), nullptr, 1});
    if (!std::isfinite(e_fresh)) continue;  // a bead landed on the membrane
    ASSERT_EQ(e_kept, e_fresh) << "move " << move << " of scale " << scale;
    ++energies;
  }
  EXPECT_GT(energies, 150);
  EXPECT_GT(kept.rebuilds(), 10);
  EXPECT_LT(kept.rebuilds(), 190);
}

// Through one relaxation of a body alone (one Evaluation::held), the term keeps what it
// read of the held bodies; a new relaxation (another held number) must read them again.
// Each relaxation here moves its own body at random between evaluations, and the held
// body was moved in between relaxations (by up to 10 nm, the list's skin): every energy
// equals that of a term built afresh, to the last bit.
TEST(MembraneBeadExclusion, AHeldBodyIsReadAgainInTheNextRelaxation) {
  Scene s(300.0, 15.0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int f = 0; f < 20; ++f)
    s.network->addFilament(makeStraightFilament(0, Vec3(120 * u(rng), 120 * u(rng), -40.0 + 10 * u(rng)),
                                                Vec3(0.3 * u(rng), 0.3 * u(rng), 1.0).normalized(), 12, 3, 2.7));
  s.layOut();
  MembraneBeadExclusion kept(*s.membrane, *s.network, {});
  std::uint64_t version = 0;
  int compared = 0, pushing = 0;
  for (std::uint64_t relaxation = 1; relaxation <= 12; ++relaxation) {
    const bool membrane_alone = relaxation % 2 == 1;
    Body& alone = membrane_alone ? static_cast<Body&>(*s.membrane) : static_cast<Body&>(*s.network);
    Body& held = membrane_alone ? static_cast<Body&>(*s.network) : static_cast<Body&>(*s.membrane);
    // Between relaxations the held body moves where the last one left it.
    std::vector<double> h(3 * static_cast<std::size_t>(held.numPoints()));
    held.gather(h.data());
    const double shift = 10.0 * u(rng);
    for (std::size_t i = 2; i < h.size(); i += 3) h[i] += shift;
    held.scatter(h.data());
    // As the run relaxes a body alone: its offset moved, nothing else rebuilt.
    const BodyAtOffsetZero at_zero(alone);
    std::vector<double> base(3 * static_cast<std::size_t>(alone.numPoints()));
    alone.gather(base.data());
    for (int step = 0; step < 10; ++step) {
      std::vector<double> x = base;
      const double scale = std::pow(10.0, -2.0 + 3.0 * (0.5 + 0.5 * u(rng)));
      for (double& c : x) c += scale * u(rng);
      MembraneBeadExclusion fresh(*s.membrane, *s.network, {});
      const double e_kept = kept.evaluate({x.data(), nullptr, ++version, &alone, relaxation});
      const double e_fresh = fresh.evaluate({x.data(), nullptr, ++version, &alone, 0});
      if (!std::isfinite(e_fresh)) continue;  // a step onto or through the membrane
      ASSERT_EQ(e_kept, e_fresh) << "relaxation " << relaxation << ", step " << step;
      ++compared;
      pushing += e_fresh > 0.0;
    }
  }
  EXPECT_GT(compared, 80);
  EXPECT_GT(pushing, 40);  // beads within the cut-off: the energies compared are not all zero
  EXPECT_GT(kept.rebuilds(), 6);
}

TEST(MembraneBeadExclusion, AStepThroughTheMembraneIsRefused) {
  // A bead 3 nm below the patch, then a trial point 3 nm above it: finite energy there
  // (the far side looks like the near one), but relative to where the bodies hold the
  // bead it went through, so the energy is infinite; once the bodies hold it above
  // (an accepted state, say a restart), the same point is finite again.
  Scene s(200.0, 10.0);
  s.network->addFilament(makeStraightFilament(0, Vec3(1.0, 2.0, -30.0), Vec3(0, 0, 1), 10, 40, 2.7));
  s.layOut();
  MembraneBeadExclusion term(*s.membrane, *s.network, {});
  const std::size_t tip = s.x.size() - 1;  // z of the last bead
  ASSERT_NEAR(s.x[tip], -3.0, 1e-12);
  EXPECT_TRUE(std::isfinite(term.evaluate({s.x.data(), nullptr, 1})));
  std::vector<double> through = s.x;
  through[tip] = 3.0;
  EXPECT_EQ(term.evaluate({through.data(), nullptr, 2}), std::numeric_limits<double>::infinity());
  s.network->scatter(through.data() + s.vertexCoordinates());
  EXPECT_TRUE(std::isfinite(term.evaluate({through.data(), nullptr, 3})));
  // The membrane moved over the bead instead (the bead held below it): refused too.
  s.network->scatter(s.x.data() + s.vertexCoordinates());
  std::vector<double> swept = s.x;
  for (std::size_t i = 2; i < s.vertexCoordinates(); i += 3) swept[i] -= 6.0;
  EXPECT_EQ(term.evaluate({swept.data(), nullptr, 4}), std::numeric_limits<double>::infinity());
}

TEST(MembraneBeadExclusion, ABeadOnTheMembraneHasInfiniteEnergy) {
  Scene s(100.0, 10.0);
  s.network->addFilament(makeStraightFilament(0, Vec3(1.0, 2.0, -27.0), Vec3(0, 0, 1), 10, 40, 2.7));
  s.layOut();
  MembraneBeadExclusion term(*s.membrane, *s.network, {});
  EXPECT_EQ(s.network->filaments()[0].beads.back().z(), 0.0);
  std::vector<double> g(s.x.size(), 0.0);
  EXPECT_EQ(term.evaluate({s.x.data(), g.data(), 1}), std::numeric_limits<double>::infinity());
  EXPECT_EQ(term.evaluate({s.x.data(), nullptr, 2}), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace cortex
