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
  // The same with nothing else rebuilt: for evaluating the body on its own coordinates
  // and putting it back (BodyAtOffsetZero).
  virtual void moveOffset(Index offset) { offset_ = offset; }

 private:
  Index offset_ = 0;
};

// The body's terms read its coordinates at its offset in the System's vector; a relaxation
// of the body alone (Evaluation::alone) evaluates them on its own coordinates, at offset 0.
class BodyAtOffsetZero {
 public:
  explicit BodyAtOffsetZero(Body& b) : b_(b), offset_(b.offset()) { b_.moveOffset(0); }
  ~BodyAtOffsetZero() { b_.moveOffset(offset_); }
  BodyAtOffsetZero(const BodyAtOffsetZero&) = delete;
  BodyAtOffsetZero& operator=(const BodyAtOffsetZero&) = delete;

 private:
  Body& b_;
  Index offset_;
};

}  // namespace cortex
