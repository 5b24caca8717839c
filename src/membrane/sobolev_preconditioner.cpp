#include "membrane/sobolev_preconditioner.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace cortex {

ScalarMeshOperators scalarMeshOperators(const double* x, Index nv, const std::vector<Tri>& triangles) {
  ScalarMeshOperators ops;
  ops.mass = Eigen::VectorXd::Zero(nv);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(triangles.size() * 12);
  auto at = [&](Index v) { return Vec3(x[3 * v], x[3 * v + 1], x[3 * v + 2]); };
  for (const Tri& t : triangles) {
    const Vec3 p[3] = {at(t[0]), at(t[1]), at(t[2])};
    const double area2 = (p[1] - p[0]).cross(p[2] - p[0]).norm();
    for (int k = 0; k < 3; ++k) ops.mass[t[k]] += area2 / 6.0;
    if (!(area2 > 0)) continue;
    for (int k = 0; k < 3; ++k) {
      // Angle at corner k is opposite edge (k+1, k+2): weight 1/2 cot.
      const Vec3 u = p[(k + 1) % 3] - p[k], v = p[(k + 2) % 3] - p[k];
      double cot = u.dot(v) / area2;
      cot = std::clamp(cot, -1e3, 1e3);  // degenerate triangles must not poison the factorization
      const Index i = t[(k + 1) % 3], j = t[(k + 2) % 3];
      const double w = 0.5 * cot;
      entries.emplace_back(i, j, -w);
      entries.emplace_back(j, i, -w);
      entries.emplace_back(i, i, w);
      entries.emplace_back(j, j, w);
    }
  }
  ops.stiffness.resize(nv, nv);
  ops.stiffness.setFromTriplets(entries.begin(), entries.end());
  return ops;
}

void SobolevPreconditioner::build(const ScalarMeshOperators& ops, double kappa, double eps,
                                  const std::vector<char>& fixed) {
  const Index n = static_cast<Index>(ops.mass.size());
  kappa_ = kappa;
  mass_ = ops.mass;
  Eigen::SparseMatrix<double> k = ops.stiffness;
  for (Index i = 0; i < n; ++i) k.coeffRef(i, i) += eps * ops.mass[i];
  if (!fixed.empty()) {
    for (int c = 0; c < k.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(k, c); it; ++it)
        if (fixed[it.row()] || fixed[it.col()]) it.valueRef() = it.row() == it.col() ? 1.0 : 0.0;
    for (Index i = 0; i < n; ++i)
      if (fixed[i]) mass_[i] = 1.0;
  }
  k.prune(0.0);
  k.makeCompressed();
  // The fill-reducing ordering depends on the pattern alone: kept while it does not change.
  const bool same_pattern =
      pattern_outer_.size() == static_cast<std::size_t>(k.outerSize() + 1) &&
      pattern_inner_.size() == static_cast<std::size_t>(k.nonZeros()) &&
      std::equal(pattern_outer_.begin(), pattern_outer_.end(), k.outerIndexPtr()) &&
      std::equal(pattern_inner_.begin(), pattern_inner_.end(), k.innerIndexPtr());
  if (!same_pattern) {
    llt_.analyzePattern(k);
    pattern_outer_.assign(k.outerIndexPtr(), k.outerIndexPtr() + k.outerSize() + 1);
    pattern_inner_.assign(k.innerIndexPtr(), k.innerIndexPtr() + k.nonZeros());
  }
  llt_.factorize(k);
  ok_ = llt_.info() == Eigen::Success;
  low_u_.resize(0, 0);
}

Eigen::MatrixXd SobolevPreconditioner::applyBase(const Eigen::MatrixXd& r) const {
  solves_ += r.cols();
  Eigen::MatrixXd z = llt_.solve(r);
  z = mass_.asDiagonal() * z;
  return llt_.solve(z) / kappa_;
}

void SobolevPreconditioner::setLowRank(Eigen::MatrixXd u, Eigen::VectorXd w) {
  low_u_ = std::move(u);
  if (low_u_.cols() == 0) return;
  low_pu_ = applyBase(low_u_);
  Eigen::MatrixXd core = low_u_.transpose() * low_pu_;
  for (Index i = 0; i < w.size(); ++i) core(i, i) += 1.0 / w[i];
  low_core_ = core.inverse();
}

Eigen::MatrixXd SobolevPreconditioner::apply(const Eigen::MatrixXd& r) const {
  Eigen::MatrixXd z = applyBase(r);
  if (low_u_.cols() > 0) z -= low_pu_ * (low_core_ * (low_u_.transpose() * z));
  return z;
}

Eigen::VectorXd SobolevPreconditioner::apply(const Eigen::VectorXd& r) const {
  return apply(Eigen::MatrixXd(r)).col(0);
}

}  // namespace cortex
