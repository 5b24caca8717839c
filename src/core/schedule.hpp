// A scalar parameter that may change in time: a constant, or [time, value] points
// linearly interpolated and held constant before the first and after the last point.
#pragma once

#include <utility>
#include <vector>

namespace cortex {

class Schedule {
 public:
  Schedule() = default;
  explicit Schedule(double constant) : points_{{0.0, constant}} {}
  // Points must be sorted by strictly increasing time (the config layer checks this).
  explicit Schedule(std::vector<std::pair<double, double>> points) : points_(std::move(points)) {}

  double at(double t) const;
  bool isConstant() const { return points_.size() <= 1; }
  bool isSet() const { return !points_.empty(); }
  // True when the value is zero at every time (so a term can be left out).
  bool isZero() const;
  const std::vector<std::pair<double, double>>& points() const { return points_; }

 private:
  std::vector<std::pair<double, double>> points_;
};

}  // namespace cortex
