// Typed parameters of filaments and the proteins that act on them, as parsed and
// validated by io/filament_config.cpp. Units: nm, s, pN, pN·nm; end rates 1/(µM·s) and
// 1/s (docs/config.md). Defaults are actin / α-actinin / non-muscle myosin IIA /
// Arp2/3 values from the MEDYAN papers (Popov, Komianos & Papoian 2016, Table S1-S3)
// and the sources docs/filaments.md cites.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace cortex {

struct FilamentType {
  std::string name = "actin";
  std::string monomer_species;     // [[species]] name; empty only when all end rates are 0
  Index monomer_species_index = -1;  // resolved by the parser; -1 when monomer_species is empty
  double monomer_size = 2.7;       // nm, length added per monomer (delta)
  int cylinder_monomers = 40;      // monomers per full cylinder
  double bending_stiffness = 672.0;     // pN·nm, E = K (1 - cos theta) per hinge
  double stretching_stiffness = 100.0;  // pN/nm, E = k/2 (l - l0)^2 per cylinder
  // 1/(µM·s) and 1/s. The parser defaults them to ATP-actin's (Pollard 1986: 11.6, 1.4,
  // 1.3, 0.8) when monomer_species is given; 0 here (a mechanics-only filament).
  double plus_on = 0.0, plus_off = 0.0;
  double minus_on = 0.0, minus_off = 0.0;
  double excluded_volume_stiffness = 10.0; // pN/nm, E = k/2 (d0 - d)^2 for d < d0
  double excluded_volume_distance = 7.0;   // nm, d0 (twice the actin radius)
  double nucleation_rate = 0.0;            // 1/(µM·s), "2 monomer -> dimer filament" per compartment
};

// Initial filaments of one type.
struct FilamentInit {
  std::string type;          // FilamentType name
  Index type_index = 0;      // resolved by the parser
  int count = 1;
  double length = 108.0;     // nm (rounded to whole monomers)
  enum class Placement { kRandom, kBundle } placement = Placement::kRandom;
  // random: minus ends uniform in [region_min, region_max] (default: the boundary's
  // box, shrunk so that whole filaments fit), directions uniform on the sphere.
  std::optional<std::array<Vec3, 2>> region;
  // random: also wholly inside this closed membrane, beads at least the membrane–filament
  // cut-off from it (empty: anywhere in the region).
  std::string inside;
  // bundle: filaments on a hexagonal lattice around `center`, axis `direction`,
  // neighbours `spacing` nm apart; filaments are centred on `center` along the axis.
  // Mixed polarity: every second filament of the lattice walk points against
  // `direction` (the lattice's rings then alternate, so ring neighbours are
  // antiparallel), a bundle that pushes at both of its ends.
  Vec3 center = Vec3::Zero();
  Vec3 direction = Vec3::UnitX();
  double spacing = 10.0;
  bool mixed_polarity = false;
  // Hold the minus-end bead fixed in space (an anchored filament; its minus end is then
  // inert, neither growing nor shrinking).
  bool fixed_minus_end = false;
  // Also hold the direction of the first cylinder (a clamped anchor; implies
  // fixed_minus_end): bundles pushing on a membrane otherwise tip over about their pinned
  // minus ends.
  bool clamped_minus_end = false;
};

// A cross-linker (or a myosin minifilament, see MotorType) is a diffusing species that
// binds two binding sites on different filaments whose distance lies in
// [min_distance, max_distance]; bound, it is a harmonic spring of rest length the
// distance at binding.
struct LinkerType {
  std::string name;
  std::string species;          // diffusing [[species]] name (the unbound copies)
  Index species_index = -1;
  double min_distance = 30.0, max_distance = 40.0;  // nm
  // MEDYAN's α-actinin: 0.01 per copy and site pair in a 500 nm compartment = 0.753
  // /(µM·s) (÷ N_A V = 75.28 copies/µM), off 0.3/s.
  double on_rate = 0.753;       // 1/(µM·s) per available site pair
  double off_rate = 0.3;        // 1/s at zero force
  double stiffness = 8.0;       // pN/nm
  double slip_length = 0.24;    // nm, slip bond: k_off(F) = off_rate exp(|F| x / kBT)
  int site_spacing = 10;        // monomers between binding sites on a filament
};

// Non-muscle myosin II minifilament: binds like a linker, walks both ends towards the
// plus ends, stalls under load (Hill), and unbinds more slowly under tension (catch bond).
struct MotorType {
  std::string name;
  std::string species;
  Index species_index = -1;
  double min_distance = 175.0, max_distance = 225.0;  // nm
  // MEDYAN's non-muscle myosin IIA: on 0.2 per copy and site pair in a 500 nm
  // compartment = 15.06 /(µM·s), off 1.7/s, walking 0.2/s.
  double on_rate = 15.06;       // 1/(µM·s) per available site pair
  double off_rate = 1.7;        // 1/s at zero force
  double walk_rate = 0.2;       // 1/s per end at zero force
  double step_size = 6.0;       // nm per step (rounded to whole monomers)
  double stall_force = 90.0;    // pN, walking stops: k_walk(F) = k0 max(0, (Fs - F)/(Fs + F/alpha))
  double hill_alpha = 0.2;      // Hill's constant alpha
  double catch_force = 12.62;   // pN, catch bond: k_off(F) = off_rate exp(-F / F_c) for F > 0
  double stiffness = 2.5;       // pN/nm
  int site_spacing = 10;        // monomers between the sites where a motor may bind (walking
                                // then moves it step by step between them)
  // Head count (MEDYAN's NUMMOTORHEADSMIN/MAX; Erdmann & Schwarz's parallel cluster
  // model, as in Popov et al. 2016): 0 = not modelled. Otherwise each motor draws N
  // heads uniformly in [heads_min, heads_max] when it binds; with the duty ratio
  // rho = head_binding_rate / (head_binding_rate + off_rate) and N_b = rho N bound heads,
  //   k_off(F) = N k_h / ((1 + k_h/off_rate)^N - 1) e^(-F/(N_b F_c))   (F > 0)
  //   k_walk(F) = walk_rate (N - N_b)/N_b * Hill(F),
  // (docs/filaments.md, Motors; docs/medyan.md).
  //   N_b(F) = rho N + head_load F / N under tension F > 0, the walking factor
  //   (N - N_b)/N_b and the catch bond's shared load F/N_b both use it.
  int heads_min = 0, heads_max = 0;
  double head_binding_rate = 0.2;  // 1/s, k_h: one head's attachment rate
  double head_load = 2.0;          // 1/pN, beta: heads recruited per unit load and head

  // The step in whole monomers of size `monomer_size` (nm), rounded; 0 for a step under
  // half a monomer, which the config refuses.
  int stepMonomers(double monomer_size) const { return static_cast<int>(std::lround(step_size / monomer_size)); }
};

// Arp2/3: a diffusing complex that, with one monomer from the pool, binds a site on a
// filament and nucleates there a one-monomer daughter filament at `angle` to its mother;
// the complex caps the daughter's minus end until it unbranches.
struct BrancherType {
  std::string name;
  std::string species;
  Index species_index = -1;
  std::string filament_type;    // type of mothers and daughters
  Index filament_type_index = 0;
  double rate = 0.0;            // 1/(µM²·s) per available site: k [Arp2/3] [monomer]
  double unbranch_rate = 0.0;   // 1/s: the daughter detaches, the complex is released
  double angle = 70.0;          // degrees between mother and daughter
  double angle_stiffness = 100.0;     // pN·nm, E = K (cos theta - cos theta0)^2
  double position_stiffness = 100.0;  // pN/nm, daughter's minus end to the site
  int site_spacing = 10;        // monomers
};

// Walls that keep filament beads in: E = F0 λ exp(-d/λ) per bead and wall (force
// F0 exp(-d/λ)), d the distance to the wall.
struct BoundaryConfig {
  enum class Shape { kBox, kSphere } shape = Shape::kBox;
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();  // box (default: the compartment grid's box)
  Vec3 center = Vec3::Zero();                   // sphere
  double radius = 0.0;
  double repulsion = 41.0;         // pN, F0
  double screening_length = 2.7;   // nm, λ
};

struct FilamentConfig {
  std::vector<FilamentType> types;
  std::vector<FilamentInit> initial;
  std::vector<LinkerType> linkers;
  std::vector<MotorType> motors;
  std::vector<BrancherType> branchers;
  std::optional<BoundaryConfig> boundary;
};

}  // namespace cortex
