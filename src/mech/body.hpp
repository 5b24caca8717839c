// Anything with coordinates the minimizer moves: a membrane's vertices, a filament
// network's beads, later a rod's centreline. System lays its bodies out one after another
// in one coordinate vector, in a fixed order that checkpoints record; a body's points are
// the coordinates [3 offset(), 3 (offset() + numPoints())).
#pragma once

#include <string>

#include "core/types.hpp"

namespace cortex {

class Body {
 public:
  virtual ~Body() = default;
  virtual const std::string& name() const = 0;
  virtual Index numPoints() const = 0;
  // Its points into / out of `x`, which points at its own first coordinate.
  virtual void gather(double* x) const = 0;
  virtual void scatter(const double* x) = 0;
  // Per point: 1 where the point never moves (a fixed boundary, an anchored end), else 0.
  virtual void frozen(char* mask) const = 0;

  Index offset() const { return offset_; }
  // Where its points start; a body whose terms keep indices into the coordinate vector
  // rebuilds them here.
  virtual void setOffset(Index offset) { offset_ = offset; }

 private:
  Index offset_ = 0;
};

}  // namespace cortex
