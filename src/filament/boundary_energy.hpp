// Soft walls keeping filament beads inside the boundary: per bead and wall
// E = F0 λ exp(-d/λ), d the signed distance from the wall into the domain (box: each of
// the 6 faces; sphere: R - |x - center|). Force magnitude F0 exp(-d/λ), pointing inwards.
#pragma once

#include <string>

#include "filament/end_load_probe.hpp"
#include "filament/filament_layout.hpp"
#include "filament/filament_params.hpp"
#include "filament/filament_term.hpp"

namespace cortex {

// Energy of one bead at x (pN·nm).
double boundaryEnergy(const BoundaryConfig& b, const Vec3& x);
// -dE/dx for one bead at x (pN): the load the wall puts on a growing tip.
Vec3 boundaryForce(const BoundaryConfig& b, const Vec3& x);

// The walls' push on an end where it now is (end_load_probe.hpp): they never move, so
// between relaxations the load of an end that grows towards them is exact.
class WallEndLoads final : public EndLoadProbe {
 public:
  explicit WallEndLoads(BoundaryConfig boundary) : boundary_(boundary) {}
  Vec3 forceAt(Index /*filament*/, const Vec3& point, bool /*plus_end*/) const override {
    return boundaryForce(boundary_, point);
  }
  // Along the step, −(E(point + step) − E(point))/|step| in place of the force at point:
  // the walls' energy is known.
  Vec3 stepCorrection(Index filament, const Vec3& point, bool plus_end, const Vec3& step) const override;

 private:
  BoundaryConfig boundary_;
};

class BoundaryRepulsionEnergy final : public FilamentTerm {
 public:
  BoundaryRepulsionEnergy(const FilamentLayout& layout, BoundaryConfig boundary)
      : FilamentTerm(layout, "boundary"), boundary_(boundary) {}
  double evaluate(const Evaluation& e) override;
  bool isContact() const override { return true; }

 private:
  BoundaryConfig boundary_;
};

}  // namespace cortex
