#include "filament/boundary_energy.hpp"

#include <cmath>

namespace cortex {
namespace {

// Beyond this many screening lengths a wall's term (force < 2e-22 F0, i.e. ~1e-20 pN) is
// dropped: most beads are far from most walls, and the exp() calls dominated the cost.
constexpr double kMaxDecay = 50.0;

// F0 exp(-d/λ), the force of one wall on a bead at distance d.
double wallForce(double f0, double lambda, double d) {
  const double decay = d / lambda;
  return decay > kMaxDecay ? 0.0 : f0 * std::exp(-decay);
}

// Energy and -dE/dx of one bead.
double wallTerms(const BoundaryConfig& b, const Vec3& x, Vec3* force) {
  const double f0 = b.repulsion, lambda = b.screening_length;
  double energy = 0.0;
  if (force) force->setZero();
  if (b.shape == BoundaryConfig::Shape::kBox) {
    for (int k = 0; k < 3; ++k) {
      const double lo = wallForce(f0, lambda, x[k] - b.min[k]);  // force of the min wall
      const double hi = wallForce(f0, lambda, b.max[k] - x[k]);  // force of the max wall
      energy += lambda * (lo + hi);
      if (force) (*force)[k] = lo - hi;
    }
    return energy;
  }
  const Vec3 r = x - b.center;
  const double distance = r.norm();
  const double magnitude = wallForce(f0, lambda, b.radius - distance);
  // At the centre the direction is undefined, and the force negligible for any R >> λ.
  if (force && distance > 0.0) *force = (-magnitude / distance) * r;
  return lambda * magnitude;
}

}  // namespace

double boundaryEnergy(const BoundaryConfig& b, const Vec3& x) { return wallTerms(b, x, nullptr); }

Vec3 boundaryForce(const BoundaryConfig& b, const Vec3& x) {
  Vec3 f;
  wallTerms(b, x, &f);
  return f;
}

Vec3 WallEndLoads::stepCorrection(Index /*filament*/, const Vec3& point, bool /*plus_end*/, const Vec3& step) const {
  const double length2 = step.squaredNorm();
  if (!(length2 > 0.0)) return Vec3::Zero();
  const double rise = boundaryEnergy(boundary_, point + step) - boundaryEnergy(boundary_, point);
  // Far past a wall the energies overflow (inf − inf): the force at the point says more.
  if (!std::isfinite(rise)) return Vec3::Zero();
  return (-rise - boundaryForce(boundary_, point).dot(step)) / length2 * step;
}

double BoundaryRepulsionEnergy::evaluate(const Evaluation& e) {
  const std::size_t offset = 3 * static_cast<std::size_t>(layout_.bead_offset);
  const double* x = e.x + offset;
  double* g = e.gradient ? e.gradient + offset : nullptr;
  double energy = 0.0;
  Vec3 f;
  for (Index b = 0; b < layout_.num_beads; ++b) {
    energy += wallTerms(boundary_, Eigen::Map<const Vec3>(x + 3 * b), g ? &f : nullptr);
    if (g) Eigen::Map<Vec3>(g + 3 * b) -= f;
  }
  return energy;
}

}  // namespace cortex
