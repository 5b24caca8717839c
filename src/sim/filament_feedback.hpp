// The mechanochemical feedback of the cytoskeleton: after a relaxation, the forces the
// force field's contact terms (walls, excluded volume; later membranes) put on every
// filament end load the Brownian ratchet, and the spring terms give the tensions that
// set slip and catch bonds and motor stalls. Both read from the terms the minimizer
// used, never from private copies.
#pragma once

#include <memory>

#include "chem/compartment_grid.hpp"
#include "filament/filament_chemistry.hpp"
#include "filament/filament_terms.hpp"
#include "filament/end_load_probe.hpp"
#include "sim/feedback.hpp"

namespace cortex {

// How far (in compartments) a filament bead may lie outside the compartment grid before
// a run stops: an end just beyond a wall reacts with the edge compartment, whose centre is
// then at most 0.6 of a compartment away instead of 0.5.
inline constexpr double kLargestReachOutsideGrid = 0.1;

class FilamentFeedback final : public Feedback {
 public:
  // `end_loads` (may be null): the chemistry's probe of the loads on ends between
  // relaxations, brought up to date here before the chemistry reads it.
  FilamentFeedback(FilamentNetwork& network, FilamentTerms terms, FilamentChemistry& chemistry,
                   EndLoadProbe* end_loads = nullptr);
  // Also stops the run (RunError) when a bead reached farther than
  // kLargestReachOutsideGrid compartments outside the grid: its ends and sites react with
  // the compartment the grid clamps them to (a filament grew 3 µm out of a one-compartment
  // grid on that compartment's monomers, exit 0).
  void update(System& system) override;
  // The same from coordinates x (the network laid out in them) and the force field that
  // holds the filament terms.
  void apply(const Eigen::VectorXd& x, ForceField& force_field);

 private:
  void checkWithinGrid(const CompartmentGrid& grid, double t) const;

  FilamentNetwork& network_;
  FilamentTerms terms_;
  FilamentChemistry& chemistry_;
  EndLoadProbe* end_loads_;
};

}  // namespace cortex
