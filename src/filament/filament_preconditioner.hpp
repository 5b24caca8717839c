// A sparse model of the filament network's Hessian, factorized once per relaxation and
// used as the initial inverse Hessian of L-BFGS (docs/filaments.md, "Relaxation").
//
// Why: a filament is stiff along its cylinders (k_s = 100 pN/nm) and soft across them
// (bending K/l^2 ~ 0.06 pN/nm for a full cylinder), and a bead held by the membrane or a
// neighbour feels contact stiffnesses of 1-20 pN/nm. Plain conjugate gradients took
// hundreds of iterations per relaxation on that spread. The model holds, per filament,
// each term's Gauss-Newton part at the current positions:
//   - stretching: k_s u u^T per cylinder (u its unit axis), plus T/l (I - u u^T) when it
//     is under tension T > 0;
//   - bending: K b b^T (x) (I - u u^T) per hinge, b = (1/l1, -1/l1 - 1/l2, 1/l2) over its
//     three beads (the small-angle form of K (1 - cos theta); exact for a straight,
//     unstressed filament);
//   - linkers, motors and a branch's position spring: their stiffness on each end's own
//     beads, as if the other end were held, so that filaments stay uncoupled and every
//     solve is a set of short banded chains (and the matrix a band, built in place);
//   - eps I on every bead, eps = kShiftFraction * the stiffest k_s (10 pN/nm for actin):
//     the contacts (excluded volume, walls, membranes) change between evaluations and
//     are not in the model; eps stands for their scale and gives free filaments' rigid
//     motions finite steps.
// Only the speed depends on the model: convergence is judged on the true forces.
#pragma once

#include <Eigen/CholmodSupport>
#include <Eigen/Core>
#include <Eigen/Sparse>
#include <vector>

#include "filament/filament_layout.hpp"
#include "filament/filament_params.hpp"

namespace cortex {

class FilamentPreconditioner {
 public:
  // Of the stiffest k_s. Filament force evaluations measured against it (docs/filaments.md,
  // Relaxation): 0.01 / 0.03 / 0.1 / 0.3 / 1 gave 8,378 / 4,698 / 2,034 / 2,530 / 4,499 on
  // the MEDYAN vesicle from t = 3 s to 3.1 s, 8,882 / 6,403 / 6,931 / 9,835 / 18,306 on
  // vesicle_bundles to 1 s, 30,808 / 21,798 / 11,033 / 7,624 / 11,018 on
  // actomyosin_contraction to 2 s.
  static constexpr double kShiftFraction = 0.1;

  // x: the minimizer's coordinate vector (the network's beads from layout.bead_offset);
  // frozen: one entry per bead of the layout, non-zero for beads that never move.
  // Returns false when the model could not be factorized (then apply() must not be used).
  bool build(const FilamentLayout& layout, const std::vector<FilamentType>& types, const Eigen::VectorXd& x,
             const std::vector<char>& frozen);
  // z = P^-1 r on the network's coordinates; z is r elsewhere (there r is zero: the
  // other bodies are held).
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
  // The model's lower triangle (for tests).
  const Eigen::SparseMatrix<double>& matrix() const { return matrix_; }

 private:
  Eigen::SparseMatrix<double> matrix_;
  // CHOLMOD's simplicial solves: 0.55x the time of Eigen's own (docs/benchmarks.md).
  Eigen::CholmodSimplicialLLT<Eigen::SparseMatrix<double>> llt_;
  Eigen::Index first_ = 0, count_ = 0;  // the network's coordinates in the vector
};

}  // namespace cortex
