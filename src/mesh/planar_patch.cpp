#include "mesh/planar_patch.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"

namespace cortex {
namespace {

void requirePositive(const char* what, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(fmt::format("planarPatch: {} must be finite and > 0 (got {})", what, value));
  }
}

// Fractions of the width where a row has points: n + 1 evenly spaced ones on even rows;
// on odd rows the half-shifted points plus both ends.
std::vector<double> rowStations(int n, bool shifted) {
  std::vector<double> s;
  if (!shifted) {
    for (int i = 0; i <= n; ++i) s.push_back(double(i) / n);
    return s;
  }
  s.push_back(0.0);
  for (int i = 0; i < n; ++i) s.push_back((i + 0.5) / n);
  s.push_back(1.0);
  return s;
}

}  // namespace

TriangleSoup planarPatch(const Vec3& center, double Lx, double Ly, double target_edge) {
  requirePositive("Lx", Lx);
  requirePositive("Ly", Ly);
  requirePositive("target edge", target_edge);
  const int columns = std::max(1, int(std::ceil(Lx / target_edge)));
  const int rows = std::max(1, int(std::ceil(Ly / (target_edge * std::sqrt(3.0) / 2.0))));
  const Vec3 corner = center - Vec3(Lx / 2.0, Ly / 2.0, 0.0);

  TriangleSoup soup;
  std::vector<Index> row_start;  // index of each row's first point
  std::vector<std::vector<double>> stations;
  for (int r = 0; r <= rows; ++r) {
    row_start.push_back(Index(soup.positions.size()));
    stations.push_back(rowStations(columns, r % 2 == 1));
    // Fractions times the length put the last point exactly on the far side.
    const double y = Ly * (double(r) / rows);
    for (double s : stations.back()) soup.positions.push_back(corner + Vec3(Lx * s, y, 0.0));
  }

  // Zip each pair of rows left to right; the next triangle is the one whose new side
  // (between a row's current and next point) is centred further left. Comparing the next
  // points alone would tie at the right end and sometimes emit a sliver there.
  for (int r = 0; r < rows; ++r) {
    const std::vector<double>& lo = stations[r];
    const std::vector<double>& up = stations[r + 1];
    const Index a0 = row_start[r], b0 = row_start[r + 1];
    std::size_t i = 0, j = 0;
    while (i + 1 < lo.size() || j + 1 < up.size()) {
      const bool advance_lower =
          j + 1 == up.size() || (i + 1 < lo.size() && lo[i] + lo[i + 1] <= up[j] + up[j + 1]);
      if (advance_lower) {
        soup.triangles.push_back({a0 + Index(i), a0 + Index(i + 1), b0 + Index(j)});
        ++i;
      } else {
        soup.triangles.push_back({a0 + Index(i), b0 + Index(j + 1), b0 + Index(j)});
        ++j;
      }
    }
  }
  return soup;
}

}  // namespace cortex
