// The force on a filament end from bodies that stand still during a chemistry window
// (membranes, walls), asked again after every event that moves an end: the load of the Brownian
// ratchet otherwise comes from the last relaxation and would miss that an end has just
// grown into a membrane (a second growth step within the same window could then carry
// it through).
#pragma once

#include <vector>

#include "core/types.hpp"

namespace cortex {

class EndLoadProbe {
 public:
  virtual ~EndLoadProbe() = default;
  // Force (pN) those bodies, as they stand, put on a filament's plus (or minus) end bead
  // at `point`.
  virtual Vec3 forceAt(const Vec3& point, bool plus_end) const = 0;
};

// Several probes as one: their forces add (not owned; they must outlive it).
class EndLoadSum final : public EndLoadProbe {
 public:
  explicit EndLoadSum(std::vector<const EndLoadProbe*> parts) : parts_(std::move(parts)) {}
  Vec3 forceAt(const Vec3& point, bool plus_end) const override {
    Vec3 force = Vec3::Zero();
    for (const EndLoadProbe* p : parts_) force += p->forceAt(point, plus_end);
    return force;
  }

 private:
  std::vector<const EndLoadProbe*> parts_;
};

}  // namespace cortex
