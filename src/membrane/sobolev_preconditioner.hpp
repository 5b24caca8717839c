// Sobolev (H2-like) preconditioner for scalar per-vertex fields on a triangle mesh: the
// metric in which membranes are relaxed (shape_relaxation.hpp).
//
// The Hessian of the Helfrich energy with respect to normal vertex displacements u is,
// at short wavelengths, kappa * bi-Laplacian: E ~ kappa/2 * int (Laplace u)^2 dA, whose
// discrete form is kappa * u^T L M^-1 L u with L the cotan stiffness matrix and M the
// lumped mass (vertex areas). Preconditioning gradient methods with
//
//     P = kappa (L + eps M) M^-1 (L + eps M) + U diag(w) U^T
//
// makes their iteration counts independent of the mesh size (the condition number of
// P^-1 H stays bounded as h -> 0, while that of H grows like h^-4). eps (1/nm^2) shifts
// the spectrum so that P is positive definite and adds a tension-like 2 kappa eps L;
// U diag(w) U^T is an optional low-rank part (e.g. stiff global penalty terms
// k/A0 gradA gradA^T), applied exactly with the Woodbury identity.
// Only K = L + eps M is factorized (sparse Cholesky, one-ring stencil, cheap); P^-1 r =
// K^-1 M K^-1 r / kappa.
#pragma once

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <vector>

#include "core/types.hpp"

namespace cortex {

struct ScalarMeshOperators {
  Eigen::SparseMatrix<double> stiffness;  // cotan Laplacian (positive semi-definite), dimensionless
  Eigen::VectorXd mass;                   // lumped vertex areas (1/3 of the one-ring), nm^2
};

// x: 3 coordinates per vertex (x0, y0, z0, x1, ...).
ScalarMeshOperators scalarMeshOperators(const double* x, Index num_vertices, const std::vector<Tri>& triangles);

class SobolevPreconditioner {
 public:
  // Dofs with fixed[i] != 0 are decoupled (identity rows); their residual must be zero.
  void build(const ScalarMeshOperators& ops, double kappa, double eps, const std::vector<char>& fixed);
  // Low-rank addition U diag(w) U^T (columns of U are per-vertex fields); w >= 0.
  void setLowRank(Eigen::MatrixXd u, Eigen::VectorXd w);
  // Solves P z = r for each column.
  Eigen::MatrixXd apply(const Eigen::MatrixXd& r) const;
  Eigen::VectorXd apply(const Eigen::VectorXd& r) const;
  bool ok() const { return ok_; }
  long solves() const { return solves_; }

 private:
  Eigen::MatrixXd applyBase(const Eigen::MatrixXd& r) const;
  // CHOLMOD (SuiteSparse): its simplicial triangular solves take ~0.55x the time of
  // Eigen's own SimplicialLLT on the same factor (docs/benchmarks.md).
  Eigen::CholmodSimplicialLLT<Eigen::SparseMatrix<double>> llt_;
  std::vector<int> pattern_outer_, pattern_inner_;  // the pattern llt_ was analyzed for
  Eigen::VectorXd mass_;
  double kappa_ = 1.0;
  Eigen::MatrixXd low_u_, low_pu_;  // U and P0^-1 U
  Eigen::MatrixXd low_core_;        // (diag(w)^-1 + U^T P0^-1 U)^-1
  bool ok_ = false;
  mutable long solves_ = 0;
};

}  // namespace cortex
