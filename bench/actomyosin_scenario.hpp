// The actomyosin scenario of docs/benchmarks.md (MEDYAN 5.4.0's `50filaments_motor_linker`
// example) as a Config written in C++: the benchmark builds its System from it without
// parsing anything. bench/actomyosin_50filaments.toml is the same scenario as a file for
// `cortex run`; tests/io/test_bench_scenario.cpp checks that the two stay one scenario.
#pragma once

#include "sim/run_config.hpp"

namespace cortex::bench {

inline Config actomyosin50Filaments() {
  Config c;
  c.source = "actomyosin_50filaments";
  c.simulation.seed = 1;
  c.simulation.end_time = 20.0;
  c.simulation.chemistry_window = 0.05;  // s between relaxations, as in MEDYAN's run
  c.simulation.snapshot_interval = 1.0;
  c.mechanics.kind = MinimizerKind::kConjugateGradient;  // MEDYAN's Polak-Ribiere CG
  c.mechanics.force_tolerance = 1.0;                      // pN, MEDYAN's gradient tolerance

  ChemistryConfig& chem = c.chemistry.emplace();
  chem.grid = {500.0, {2, 2, 1}};  // 1 x 1 x 0.5 µm
  chem.species = {{"G", 2.0e7}, {"AA", 2.0e6}, {"MII", 2.0e5}};  // G-actin (~16.6 µM), α-actinin, myosin II
  chem.initial_copies = {5000, 500, 50};
  chem.sides.resize(3);

  FilamentConfig& f = c.filaments.emplace();
  FilamentType actin;
  actin.monomer_species = "G";
  actin.monomer_species_index = 0;
  actin.plus_on = 11.6, actin.plus_off = 1.4, actin.minus_on = 1.3, actin.minus_off = 0.8;
  f.types = {actin};
  FilamentInit init;
  init.type = "actin";
  init.count = 30;
  init.length = 108.0;  // one full cylinder each
  f.initial = {init};
  BoundaryConfig box;  // the grid's box
  box.max = chem.grid.extent();
  f.boundary = box;
  LinkerType aa;
  aa.name = "alpha-actinin";
  aa.species = "AA";
  aa.species_index = 1;
  f.linkers = {aa};  // the defaults are MEDYAN's α-actinin
  MotorType myosin;
  myosin.name = "myosin";
  myosin.species = "MII";
  myosin.species_index = 2;
  f.motors = {myosin};  // the defaults are MEDYAN's non-muscle myosin IIA
  return c;
}

}  // namespace cortex::bench
