// The force on a filament end from bodies that stand still during a chemistry window
// (membranes, walls, the other filaments), asked again after every event that moves an
// end: the load of the Brownian ratchet otherwise comes from the last relaxation and
// would miss that an end has just grown into a membrane or another filament (a second
// growth step within the same window could then carry it through).
#pragma once

#include <vector>

#include "core/types.hpp"

namespace cortex {

class EndLoadProbe {
 public:
  virtual ~EndLoadProbe() = default;
  // After every relaxation: the bodies as they now stand.
  virtual void update() {}
  // Force (pN) those bodies, as they stand, put on the plus (or minus) end bead of
  // filament `filament`, now at `point`.
  virtual Vec3 forceAt(Index filament, const Vec3& point, bool plus_end) const = 0;
  // What the ratchet adds to forceAt for the end's next growth step, from `point` to
  // `point + step` (one monomer along the growth direction): along the step, the mean
  // force over it, −ΔU/|step|, minus the force at `point`, so that the step's rate
  // carries its energy change (detailed balance). Bodies whose force barely changes over
  // a step need not say: zero. (A wall of the default screening length, 2.7 nm, one
  // monomer, grows e-fold over a step; weighed at `point` its stalled ends pushed at
  // 1.6 x the ratchet's stall force.)
  virtual Vec3 stepCorrection(Index /*filament*/, const Vec3& /*point*/, bool /*plus_end*/,
                              const Vec3& /*step*/) const {
    return Vec3::Zero();
  }
};

// Several probes as one: their forces add (not owned; they must outlive it).
class EndLoadSum final : public EndLoadProbe {
 public:
  explicit EndLoadSum(std::vector<EndLoadProbe*> parts) : parts_(std::move(parts)) {}
  void update() override {
    for (EndLoadProbe* p : parts_) p->update();
  }
  Vec3 forceAt(Index filament, const Vec3& point, bool plus_end) const override {
    Vec3 force = Vec3::Zero();
    for (const EndLoadProbe* p : parts_) force += p->forceAt(filament, point, plus_end);
    return force;
  }
  Vec3 stepCorrection(Index filament, const Vec3& point, bool plus_end, const Vec3& step) const override {
    Vec3 correction = Vec3::Zero();
    for (const EndLoadProbe* p : parts_) correction += p->stepCorrection(filament, point, plus_end, step);
    return correction;
  }

 private:
  std::vector<EndLoadProbe*> parts_;
};

}  // namespace cortex
