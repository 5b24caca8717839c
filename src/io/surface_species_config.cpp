#include "io/surface_species_config.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "io/box_region_config.hpp"

namespace cortex {
namespace {

SurfacePotentialConfig readPotential(const ConfigReader& r) {
  SurfacePotentialConfig p;
  const std::string type = r.choice("type", "gaussian_stripe", {"gaussian_stripe", "ramp"});
  const std::string axis = r.choice("axis", "x", {"x", "y", "z"});
  p.axis = axis[0] - 'x';
  // Farther out, V = slope (x - center) at the vertices would be so large that its
  // differences from vertex to vertex, all the drift is, drown in rounding.
  p.center = r.number("center", 0.0, Range{-1e7, 1e7}, "nm");
  if (type == "gaussian_stripe") {
    p.kind = SurfacePotentialConfig::Kind::kGaussianStripe;
    p.height = r.requiredNumber("height", Range{-100.0, 100.0}, "k_BT");
    p.width = r.requiredNumber("width", Range::positive(), "nm");
  } else {
    p.kind = SurfacePotentialConfig::Kind::kRamp;
    p.slope = r.requiredNumber("slope", Range{-10.0, 10.0}, "k_BT/nm");
  }
  r.finish();
  return p;
}

CurvatureSensingConfig readCurvature(const ConfigReader& r) {
  CurvatureSensingConfig c;
  c.area = r.requiredNumber("area", Range::positive(), "nm^2");
  c.bending_modulus = r.requiredNumber("bending_modulus", Range::nonNegative(), "pN nm");
  c.spontaneous_curvature = r.number("spontaneous_curvature", 0.0, Range{-1.0, 1.0}, "1/nm");
  c.generates = r.boolean("generates", false);
  r.finish();
  return c;
}

SurfaceInteractionConfig readInteraction(const ConfigReader& r) {
  SurfaceInteractionConfig i;
  r.choice("type", "gaussian", {"gaussian"});
  // Expanded to second order, a Gaussian repulsion's kernel is μ₀ − μ₂k² with μ₀, μ₂ > 0:
  // attractive for waves shorter than πσ, which any mesh finer than σ resolves. Copies
  // then pile onto single vertices (an attraction's expansion errs the stable way).
  // Read over both signs so that a repulsion gets that reason, not only a range.
  i.height = r.requiredNumber("height", Range{}, "k_BT");
  if (i.height > 10.0) r.fail("height", fmt::format("must be in [0, 10] k_BT, got {:g}", i.height));
  if (i.height < 0)
    r.fail("height", "must be >= 0: a repulsive mean field is not modelled (its expansion R = mu0 n + mu2 Lap n, "
                     "thesis eqs. 3.4-3.5, attracts at the mesh scale and piles copies onto single vertices; "
                     "docs/proteins.md); for excluded area give the species a footprint");
  i.range = r.requiredNumber("range", Range::positive(), "nm");
  r.finish();
  return i;
}

SurfaceSpeciesConfig readOne(const ConfigReader& r) {
  SurfaceSpeciesConfig s;
  if (!r.has("name")) r.fail("name", "is required");
  s.name = r.name("name", "");
  s.diffusion = r.number("diffusion", 0.0, Range::nonNegative(), "nm^2/s");
  if (r.has("copies") && r.has("density")) r.fail("density", "give either copies or density, not both");
  s.copies = r.integer("copies", 0, 0, 2'000'000'000);
  if (r.has("density")) s.density = r.requiredNumber("density", Range::nonNegative(), "copies/µm^2");
  s.region = readBoxRegion(r, "region");
  s.footprint = r.number("footprint", 0.0, Range::nonNegative(), "nm^2");
  if (const auto p = r.table("potential")) s.potential = readPotential(*p);
  if (const auto c = r.table("curvature")) s.curvature = readCurvature(*c);
  if (const auto i = r.table("interaction")) s.interaction = readInteraction(*i);
  for (const ConfigReader& c : r.tableArray("cross_interaction")) {
    if (!c.has("species")) c.fail("species", "is required: the other species of this membrane");
    const std::string other = c.name("species", "");
    s.cross.push_back({other, readInteraction(c)});
  }
  s.drift = r.choice("drift", "exponential", {"exponential", "linear"}) == "linear" ? DriftScheme::kLinear
                                                                                 : DriftScheme::kExponential;
  r.finish();
  return s;
}

}  // namespace

std::vector<SurfaceSpeciesConfig> readSurfaceSpecies(const ConfigReader& membrane) {
  std::vector<SurfaceSpeciesConfig> out;
  for (const ConfigReader& r : membrane.tableArray("species")) {
    SurfaceSpeciesConfig s = readOne(r);
    for (const SurfaceSpeciesConfig& other : out) {
      if (other.name == s.name) r.fail("name", fmt::format("\"{}\" is declared twice on this membrane", s.name));
      if (s.curvature && s.curvature->generates && other.curvature && other.curvature->generates)
        r.fail("curvature", fmt::format("\"{}\" generates curvature as well: one species per membrane may", other.name));
    }
    out.push_back(std::move(s));
  }
  // Cross interactions name another species of this membrane, once per pair.
  const std::vector<ConfigReader> readers = membrane.tableArray("species");
  for (std::size_t j = 0; j < out.size(); ++j) {
    const std::vector<ConfigReader> cross = readers[j].tableArray("cross_interaction");
    for (std::size_t k = 0; k < out[j].cross.size(); ++k) {
      const std::string& other = out[j].cross[k].species;
      const auto partner = std::find_if(out.begin(), out.end(), [&](const auto& s) { return s.name == other; });
      if (partner == out.end() || other == out[j].name)
        cross[k].fail("species", fmt::format("\"{}\" is not another species of this membrane", other));
      for (std::size_t m = 0; m < out[j].cross.size(); ++m)
        if (m != k && out[j].cross[m].species == other)
          cross[k].fail("species", fmt::format("\"{}\" is named twice", other));
      for (const CrossInteractionConfig& back : partner->cross)
        if (back.species == out[j].name)
          cross[k].fail("species", fmt::format("\"{}\" declares the same pair: declare it on one of the two",
                                               other));
    }
  }
  return out;
}

}  // namespace cortex
