// The membrane's energy as a function of normal displacements u about a shape x0,
// x_v = x0_v + u_v n_v, with its exact area and volume constraints and the rigid-body
// modes fixed: the problem shape_relaxation.cpp hands to the constrained L-BFGS
// (mech/constrained_lbfgs.hpp) in each outer step.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "mech/constrained_lbfgs.hpp"
#include "mech/force_field.hpp"
#include "membrane/membrane.hpp"
#include "membrane/shape_relaxation.hpp"
#include "membrane/sobolev_preconditioner.hpp"
#include "mesh/geometry.hpp"

namespace cortex {

// One evaluation of a membrane's terms kept for the next problem of the same relaxation:
// an outer step starts where the last one ended, and the final report evaluates there
// again, each at the same positions with the other bodies held where they were. Valid
// for one relaxation only (between relaxations the other bodies and the time move).
struct EvaluationMemo {
  bool valid = false;
  std::uint64_t connectivity = 0;  // Membrane::connectivityVersion() (a flip keeps the positions)
  std::uint64_t version = 0;       // Evaluation::version, for the membrane's cached geometry
  Eigen::VectorXd x, gradient;     // positions and full gradient, 3 per vertex
  double energy = 0.0;
};

class NormalDisplacementProblem final : public ConstrainedProblem {
 public:
  // `kept_columns`: where P^-1 of the rigid rows is kept between outer steps (optional).
  // No body's stored positions may change while it is evaluated (Evaluation::held): the
  // membrane's are written back once its evaluations are done.
  NormalDisplacementProblem(Membrane& m, ForceField& field, std::vector<EnergyTerm*> terms, bool exact_area,
                            bool exact_volume, const SobolevPreconditioner& p,
                            ShapeRelaxationWarmStart* kept_columns = nullptr);

  // Constraint targets (intermediate ones during continuation).
  double area_target = 0.0, volume_target = 0.0;
  double force_seconds = 0.0, solve_seconds = 0.0;
  long evaluations = 0;  // of the terms; an evaluation served by the memo is not one

  // An evaluation at bit-identical positions on the same connectivity is served from
  // `memo` instead of the terms (bit-identical, as the terms are pure functions of the
  // positions while the other bodies are held).
  void useMemo(EvaluationMemo* memo) { memo_ = memo; }
  // Keeps the last evaluation in the memo if it was at u.
  void remember(const Eigen::VectorXd& u);
  // Evaluation::version of the last evaluation (Membrane::cachedGeometry).
  std::uint64_t evaluatedVersion() const { return evaluated_version_; }

  Index size() const override { return static_cast<Index>(normals_.size()); }
  int numConstraints() const override { return int(exact_area_) + int(exact_volume_) + static_cast<int>(rigid_.rows()); }
  const std::vector<Vec3>& normals() const { return normals_; }
  // The part of a residual r (one normal force per vertex) along the rigid-body rows,
  // Rᵀ R r: what the rows hold (zero for a membrane without them).
  Eigen::VectorXd rigidPart(const Eigen::VectorXd& r) const;

  const Eigen::VectorXd& positionsAt(const Eigen::VectorXd& u);
  // The energy and its full gradient (3 per vertex) at u.
  double fullValueAndGradient(const Eigen::VectorXd& u);
  const Eigen::VectorXd& fullGradient() const { return grad3_; }

  double valueAndGradient(const Eigen::VectorXd& u, Eigen::VectorXd& g) override;
  void constraints(const Eigen::VectorXd& u, Eigen::VectorXd& c, Eigen::MatrixXd& jac) override;
  void constraintValues(const Eigen::VectorXd& u, Eigen::VectorXd& c) override;
  int numLinearConstraints() const override { return static_cast<int>(rigid_.rows()); }
  const Eigen::MatrixXd* keptLinearW() const override;
  void keepLinearW(const Eigen::MatrixXd& w) override;
  Eigen::VectorXd constraintScale() const override;
  Eigen::MatrixXd precondition(const Eigen::MatrixXd& r) override;
  // No trial step may turn a face by more than 60° from where the outer step began.
  bool admissible(const Eigen::VectorXd& u) override;

 private:
  void buildRigidRows();
  Vec3 faceNormal(const Eigen::VectorXd& x, Index f) const;

  Membrane& m_;
  ForceField& field_;
  std::vector<EnergyTerm*> terms_;
  bool exact_area_, exact_volume_;
  const SobolevPreconditioner& p_;
  ShapeRelaxationWarmStart* kept_;
  Eigen::VectorXd x0_, x_, grad3_;
  Eigen::VectorXd evaluated_u_;  // where the last energy evaluation was, and its version
  std::uint64_t evaluated_version_ = 0;
  double evaluated_energy_ = 0.0;
  EvaluationMemo* memo_ = nullptr;
  std::uint64_t held_;  // Evaluation::held of every evaluation
  std::vector<Vec3> normals_, face_normal0_;
  std::vector<char> fixed_;
  MeshGeometry geometry_;
  Eigen::MatrixXd rigid_;  // orthonormal rows fixing the rigid-body modes
};

}  // namespace cortex
