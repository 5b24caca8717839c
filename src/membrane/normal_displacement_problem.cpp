#include "membrane/normal_displacement_problem.hpp"

#include <limits>

#include "core/scoped_timer.hpp"
#include "mesh/vertex_normals.hpp"

namespace cortex {

NormalDisplacementProblem::NormalDisplacementProblem(Membrane& m, ForceField& field, std::vector<EnergyTerm*> terms, bool exact_area,
                          bool exact_volume, const SobolevPreconditioner& p,
                          ShapeRelaxationWarmStart* kept_columns)
    : m_(m),
      field_(field),
      terms_(std::move(terms)),
      exact_area_(exact_area),
      exact_volume_(exact_volume),
      p_(p),
      kept_(kept_columns),
      held_(field.newVersion()) {
  const std::vector<double> x0 = flatCoordinates(m.mesh().positions());
  x0_ = Eigen::Map<const Eigen::VectorXd>(x0.data(), static_cast<Eigen::Index>(x0.size()));
  normals_ = vertexNormals(m.mesh());
  fixed_ = m.fixedVertices();
  const Index nf = m.topology().numFaces();
  face_normal0_.resize(nf);
  for (Index f = 0; f < nf; ++f) face_normal0_[f] = faceNormal(x0_, f).normalized();
  x_.resize(x0_.size());
  grad3_.resize(x0_.size());
  buildRigidRows();
}

const Eigen::VectorXd& NormalDisplacementProblem::positionsAt(const Eigen::VectorXd& u) {
  for (Index v = 0; v < size(); ++v) x_.segment<3>(3 * v) = x0_.segment<3>(3 * v) + u[v] * normals_[v];
  return x_;
}

double NormalDisplacementProblem::fullValueAndGradient(const Eigen::VectorXd& u) {
  positionsAt(u);
  evaluated_u_ = u;
  if (memo_ && memo_->valid && memo_->connectivity == m_.connectivityVersion() &&
      memo_->x.size() == x_.size() && memo_->x == x_) {
    grad3_ = memo_->gradient;
    evaluated_version_ = memo_->version;
    return evaluated_energy_ = memo_->energy;
  }
  const ScopedTimer timer{force_seconds};
  ++evaluations;
  grad3_.setZero();
  const Evaluation e{x_.data(), grad3_.data(), field_.newVersion(), &m_, held_};
  evaluated_version_ = e.version;
  double total = 0.0;
  for (EnergyTerm* t : terms_) total += t->evaluate(e);
  return evaluated_energy_ = total;
}

void NormalDisplacementProblem::remember(const Eigen::VectorXd& u) {
  if (!memo_ || evaluated_u_.size() != u.size() || evaluated_u_ != u) return;
  memo_->valid = true;
  memo_->connectivity = m_.connectivityVersion();
  memo_->version = evaluated_version_;
  memo_->x = positionsAt(u);
  memo_->gradient = grad3_;
  memo_->energy = evaluated_energy_;
}

double NormalDisplacementProblem::valueAndGradient(const Eigen::VectorXd& u, Eigen::VectorXd& g) {
  const double total = fullValueAndGradient(u);
  g.resize(size());
  for (Index v = 0; v < size(); ++v) g[v] = fixed_[v] ? 0.0 : normals_[v].dot(grad3_.segment<3>(3 * v));
  // Forces that are not numbers make the point unacceptable, like an infinite energy:
  // line searches back off, and a start there ends the relaxation (shape_relaxation.cpp reports it).
  if (!g.allFinite()) return std::numeric_limits<double>::infinity();
  return total;
}

void NormalDisplacementProblem::constraints(const Eigen::VectorXd& u, Eigen::VectorXd& c, Eigen::MatrixXd& jac) {
  const MeshGeometry* geometry = nullptr;
  if (exact_area_ || exact_volume_) {
    // At the point of the last energy evaluation (an accepted step) its terms computed
    // the geometry already.
    if (u.size() == evaluated_u_.size() && u == evaluated_u_) geometry = m_.cachedGeometry(evaluated_version_);
    if (!geometry) {
      geometry_.compute(m_.topology(), positionsAt(u).data());
      geometry = &geometry_;
    }
  }
  c.resize(numConstraints());
  jac.resize(numConstraints(), size());
  int row = 0;
  auto constraintRow = [&](double value, const std::vector<Vec3>& gradient) {
    c[row] = value;
    for (Index v = 0; v < size(); ++v) jac(row, v) = fixed_[v] ? 0.0 : normals_[v].dot(gradient[v]);
    ++row;
  };
  if (exact_area_) constraintRow(geometry->area - area_target, geometry->area_gradient);
  if (exact_volume_) constraintRow(geometry->volume - volume_target, geometry->volume_gradient);
  if (rigid_.rows() > 0) {
    c.tail(rigid_.rows()) = rigid_ * u;
    jac.bottomRows(rigid_.rows()) = rigid_;
  }
}

void NormalDisplacementProblem::constraintValues(const Eigen::VectorXd& u, Eigen::VectorXd& c) {
  c.resize(numConstraints());
  int row = 0;
  if (exact_area_ || exact_volume_) positionsAt(u);
  if (exact_area_) c[row++] = totalArea(m_.topology(), x_.data()) - area_target;
  if (exact_volume_) c[row++] = signedVolume(m_.topology(), x_.data()) - volume_target;
  if (rigid_.rows() > 0) c.tail(rigid_.rows()) = rigid_ * u;
}

// Kept columns serve only rows that still mean the same modes: as many, each turned
// by less than ~25° (the rows are orthonormal; which degenerate ones were dropped
// depends on the shape).
const Eigen::MatrixXd* NormalDisplacementProblem::keptLinearW() const {
  if (!kept_ || kept_->rigid_w.size() == 0 || kept_->rigid_rows.rows() != rigid_.rows() ||
      kept_->rigid_rows.cols() != rigid_.cols())
    return nullptr;
  for (Index i = 0; i < rigid_.rows(); ++i)
    if (!(kept_->rigid_rows.row(i).dot(rigid_.row(i)) > 0.9)) return nullptr;
  return &kept_->rigid_w;
}

void NormalDisplacementProblem::keepLinearW(const Eigen::MatrixXd& w) {
  if (!kept_) return;
  kept_->rigid_w = w;
  kept_->rigid_rows = rigid_;
}

Eigen::VectorXd NormalDisplacementProblem::constraintScale() const {
  Eigen::VectorXd s = Eigen::VectorXd::Ones(numConstraints());  // rigid rows: nm
  int row = 0;
  if (exact_area_) s[row++] = area_target;
  if (exact_volume_) s[row++] = volume_target;
  return s;
}

Eigen::MatrixXd NormalDisplacementProblem::precondition(const Eigen::MatrixXd& r) {
  const ScopedTimer timer{solve_seconds};
  return p_.apply(r);
}

bool NormalDisplacementProblem::admissible(const Eigen::VectorXd& u) {
  positionsAt(u);
  for (std::size_t f = 0; f < face_normal0_.size(); ++f) {
    const Vec3 n = faceNormal(x_, static_cast<Index>(f));
    if (!(n.dot(face_normal0_[f]) > 0.5 * n.norm())) return false;
  }
  return true;
}

// Rigid motions as normal displacement fields (translations n·e_i, rotations
// n·(e_i × (x − c))) are exact null modes of the energy and the constraints, broken by
// the discretization at round-off level; left free, a minimizer turns a prolate
// vesicle by tens of degrees at great cost. Their area-weighted components are fixed;
// rows are orthonormalized and degenerate ones dropped (rotations about a symmetry
// axis). A membrane with fixed vertices has no rigid modes.
Eigen::VectorXd NormalDisplacementProblem::rigidPart(const Eigen::VectorXd& r) const {
  if (rigid_.rows() == 0) return Eigen::VectorXd::Zero(r.size());
  return rigid_.transpose() * (rigid_ * r);
}

void NormalDisplacementProblem::buildRigidRows() {
  for (char f : fixed_)
    if (f) return;
  const Index n = size();
  Eigen::VectorXd area = Eigen::VectorXd::Zero(n);
  const auto& triangles = m_.topology().triangles;
  for (Index f = 0; f < static_cast<Index>(triangles.size()); ++f)
    for (Index v : triangles[f]) area[v] += faceNormal(x0_, f).norm() / 6.0;
  Vec3 centroid = Vec3::Zero();
  for (Index v = 0; v < n; ++v) centroid += area[v] * x0_.segment<3>(3 * v);
  centroid /= area.sum();
  std::vector<Eigen::VectorXd> rows;
  for (int mode = 0; mode < 6; ++mode) {
    Eigen::VectorXd r(n);
    const Vec3 e = Vec3::Unit(mode % 3);
    for (Index v = 0; v < n; ++v) {
      const Vec3 field = mode < 3 ? e : Vec3(e.cross(Vec3(x0_.segment<3>(3 * v)) - centroid));
      r[v] = area[v] * normals_[v].dot(field);
    }
    const double norm0 = r.norm();
    for (const Eigen::VectorXd& q : rows) r -= q.dot(r) * q;
    if (norm0 > 0 && r.norm() > 1e-3 * norm0) rows.push_back(r / r.norm());
  }
  rigid_.resize(static_cast<Index>(rows.size()), n);
  for (std::size_t i = 0; i < rows.size(); ++i) rigid_.row(static_cast<Index>(i)) = rows[i].transpose();
}

Vec3 NormalDisplacementProblem::faceNormal(const Eigen::VectorXd& x, Index f) const {
  const Tri& t = m_.topology().triangles[f];
  const Vec3 a = x.segment<3>(3 * t[0]), b = x.segment<3>(3 * t[1]), c = x.segment<3>(3 * t[2]);
  return (b - a).cross(c - a);
}

}  // namespace cortex
