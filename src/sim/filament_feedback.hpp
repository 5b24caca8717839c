// The mechanochemical feedback of the cytoskeleton: after a relaxation, the forces the
// force field's contact terms (walls, excluded volume; later membranes) put on every
// filament end load the Brownian ratchet, and the spring terms give the tensions that
// set slip and catch bonds and motor stalls. Both read from the terms the minimizer
// used, never from private copies.
#pragma once

#include <memory>

#include "filament/filament_chemistry.hpp"
#include "filament/filament_terms.hpp"
#include "filament/end_load_probe.hpp"
#include "sim/feedback.hpp"

namespace cortex {

class FilamentFeedback final : public Feedback {
 public:
  // `end_loads` (may be null): the chemistry's probe of the loads on ends between
  // relaxations, brought up to date here before the chemistry reads it.
  FilamentFeedback(FilamentNetwork& network, FilamentTerms terms, FilamentChemistry& chemistry,
                   EndLoadProbe* end_loads = nullptr);
  void update(System& system) override;
  // The same from coordinates x (the network laid out in them) and the force field that
  // holds the filament terms.
  void apply(const Eigen::VectorXd& x, ForceField& force_field);

 private:
  FilamentNetwork& network_;
  FilamentTerms terms_;
  FilamentChemistry& chemistry_;
  EndLoadProbe* end_loads_;
};

}  // namespace cortex
