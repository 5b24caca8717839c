#include "filament/filament_preconditioner.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace cortex {

namespace {

using Mat3 = Eigen::Matrix3d;

// Accumulates 3x3 blocks between beads; frozen beads keep an identity block alone. Every
// term couples beads of one filament at most two apart (a hinge's ends), and beads are
// numbered filament by filament, so the blocks live in a band: band_[3 b + k] is block
// (b + k, b), k = 0, 1, 2. Written straight into the lower triangle CHOLMOD reads (a
// triplet list of the same matrix for 12,000 beads cost ~100 ms in allocation alone).
class BlockAssembly {
 public:
  BlockAssembly(const std::vector<char>& frozen, Index beads)
      : frozen_(frozen), beads_(beads), band_(3 * static_cast<std::size_t>(beads), Mat3::Zero()) {}

  // Adds c_i c_j K to block (bead_i, bead_j) for every pair of the listed beads: the
  // Gauss-Newton term of an energy of the point sum_i c_i x_i with stiffness K.
  template <std::size_t N>
  void add(const std::array<Index, N>& beads, const std::array<double, N>& c, const Mat3& k) {
    for (std::size_t i = 0; i < N; ++i) {
      if (frozen_[beads[i]] || c[i] == 0.0) continue;
      for (std::size_t j = 0; j < N; ++j) {
        if (frozen_[beads[j]] || c[j] == 0.0 || beads[i] < beads[j]) continue;  // lower triangle
        const Index apart = beads[i] - beads[j];
        if (apart > 2) throw std::logic_error("filament preconditioner: a term couples beads more than two apart");
        band_[3 * static_cast<std::size_t>(beads[j]) + apart] += c[i] * c[j] * k;
      }
    }
  }

  // A spring from a point of a cylinder to a held point: its stiffness on that cylinder.
  void addHeldEnd(const CylinderPoint& p, const Mat3& k) { add<2>({p.bead0, p.bead1}, {1.0 - p.w, p.w}, k); }

  // The lower triangle, column by column.
  Eigen::SparseMatrix<double> matrix(double shift) const {
    const Eigen::Index n = 3 * static_cast<Eigen::Index>(beads_);
    Eigen::SparseMatrix<double> h(n, n);
    h.reserve(Eigen::VectorXi::Constant(n, 9));
    for (Index b = 0; b < beads_; ++b)
      for (int a = 0; a < 3; ++a) {
        const Eigen::Index column = 3 * b + a;
        for (Index k = 0; k < 3 && b + k < beads_; ++k) {
          const Mat3& block = band_[3 * static_cast<std::size_t>(b) + k];
          for (int r = k == 0 ? a : 0; r < 3; ++r) {
            double v = block(r, a);
            if (k == 0 && r == a) v += frozen_[b] ? 1.0 : shift;
            if (v != 0.0 || (k == 0 && r == a)) h.insert(3 * (b + k) + r, column) = v;
          }
        }
      }
    h.makeCompressed();
    return h;
  }

 private:
  const std::vector<char>& frozen_;
  Index beads_;
  std::vector<Mat3> band_;
};

// Stiffness of a spring E = k/2 (d - l0)^2 along d: k e e^T, plus T/d (I - e e^T) under
// tension (compression's negative part is left out: the model must stay positive).
Mat3 springBlock(const Vec3& d, double k, double rest_length) {
  const double length = d.norm();
  if (!(length > 0.0)) return k * Mat3::Identity();
  const Vec3 e = d / length;
  const Mat3 axial = e * e.transpose();
  const double tension = std::max(0.0, k * (length - rest_length));
  return k * axial + (tension / length) * (Mat3::Identity() - axial);
}

}  // namespace

bool FilamentPreconditioner::build(const FilamentLayout& layout, const std::vector<FilamentType>& types,
                                   const Eigen::VectorXd& x, const std::vector<char>& frozen) {
  first_ = 3 * static_cast<Eigen::Index>(layout.bead_offset);
  count_ = 3 * static_cast<Eigen::Index>(layout.num_beads);
  const auto bead = [&](Index b) { return Eigen::Map<const Vec3>(x.data() + first_ + 3 * b); };
  const auto point = [&](const CylinderPoint& p) { return ((1.0 - p.w) * bead(p.bead0) + p.w * bead(p.bead1)).eval(); };
  BlockAssembly h(frozen, layout.num_beads);
  double stiffest = 0.0;
  for (const Cylinder& c : layout.cylinders) {
    const double k = types[c.type].stretching_stiffness;
    stiffest = std::max(stiffest, k);
    h.add<2>({c.bead0, c.bead1}, {1.0, -1.0}, springBlock(bead(c.bead1) - bead(c.bead0), k, c.rest_length));
  }
  for (const Hinge& g : layout.hinges) {
    const Vec3 t1 = bead(g.bead1) - bead(g.bead0), t2 = bead(g.bead2) - bead(g.bead1);
    const double l1 = t1.norm(), l2 = t2.norm();
    if (!(l1 > 0.0 && l2 > 0.0)) continue;  // no axis to bend about
    const Vec3 mean = t1 / l1 + t2 / l2;
    const Vec3 u = mean.norm() > 1e-12 ? Vec3(mean.normalized()) : Vec3(t2 / l2);
    h.add<3>({g.bead0, g.bead1, g.bead2}, {1.0 / l1, -1.0 / l1 - 1.0 / l2, 1.0 / l2},
             types[g.type].bending_stiffness * (Mat3::Identity() - u * u.transpose()));
  }
  for (const auto* springs : {&layout.linkers, &layout.motors})
    for (const Spring& s : *springs) {
      const Mat3 k = springBlock(point(s.b) - point(s.a), s.stiffness, s.rest_length);
      h.addHeldEnd(s.a, k);
      h.addHeldEnd(s.b, k);
    }
  for (const BranchJoint& j : layout.branches) {
    const Mat3 k = j.position_stiffness * Mat3::Identity();
    h.add<1>({j.daughter0}, {1.0}, k);
    h.addHeldEnd(j.mother, k);
  }
  matrix_ = h.matrix(kShiftFraction * stiffest);
  llt_.compute(matrix_);
  return llt_.info() == Eigen::Success;
}

void FilamentPreconditioner::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  z = r;
  z.segment(first_, count_) = llt_.solve(r.segment(first_, count_));
}

}  // namespace cortex
