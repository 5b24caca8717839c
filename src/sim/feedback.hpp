// What follows from positions and must be recomputed after every relaxation (and when a
// System is built or restored): the mechanochemical feedback. Each implementation reads
// the System and writes rates or fractions into its own part of the chemistry.
#pragma once

namespace cortex {

class System;

class Feedback {
 public:
  virtual ~Feedback() = default;
  virtual void update(System& system) = 0;
};

}  // namespace cortex
