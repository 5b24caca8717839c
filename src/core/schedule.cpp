#include "core/schedule.hpp"

#include <algorithm>

namespace cortex {

double Schedule::at(double t) const {
  if (points_.empty()) return 0.0;
  if (t <= points_.front().first) return points_.front().second;
  if (t >= points_.back().first) return points_.back().second;
  const auto hi = std::upper_bound(points_.begin(), points_.end(), t,
                                   [](double time, const auto& p) { return time < p.first; });
  const auto lo = hi - 1;
  const double s = (t - lo->first) / (hi->first - lo->first);
  return lo->second + s * (hi->second - lo->second);
}

bool Schedule::isZero() const {
  return std::all_of(points_.begin(), points_.end(), [](const auto& p) { return p.second == 0.0; });
}

}  // namespace cortex
