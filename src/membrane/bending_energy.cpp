#include "membrane/bending_energy.hpp"

#include "core/parallel.hpp"
#include "membrane/curvature.hpp"
#include "mesh/corner_gather.hpp"

namespace cortex {

// Gradient derivation (docs/membrane.md): with E_v = 2 kappa (H_v - H0)^2 A_v,
//   dE/dx_p = sum_v [ c_v dA_v/dx_p + s_v dH_v/dx_p ],  c_v = 2 kappa (H_v-H0)^2,
//   s_v = 4 kappa (H_v-H0) A_v,  dH_v/dx_p = J_A^T alpha_v + J_V^T beta_v.
// For one triangle with unit normal n, |n| = 2 A_t and edges e_k, corner k of vertex v
// contributes alpha_k, beta_k (already scaled by s_v); its three corners receive
//   g_p = 1/2 C n x e_p - e_p x (W/2 + B/6) + 1/2 n x (alpha_{p-1} - alpha_{p+1})
// where C = (c_a + c_b + c_c)/3, B = sum_k beta_k and
// W = sum_k (I - n n^T)(e_k x alpha_k) / |n|.
//
// With a coat, E_v = A_v e(phi_v) with e(phi) = 2 kappa(phi) (H_v - H0 - H_c phi)^2 and
// phi_v = n_v a / A_v: dE_v/dA_v = e - phi e'(phi) (0 for the phi term once phi is capped
// at 1) and dE_v/dH_v = 4 kappa(phi) (H_v - H0 - H_c phi) A_v.
double BendingEnergy::evaluate(const Evaluation& e) {
  const MeshGeometry& g = membrane_.geometry(e);
  const std::optional<ProteinCoat>& coat = membrane_.coat();
  const std::vector<int>* coat_copies = coat ? &membrane_.speciesCopies()[coat->species] : nullptr;
  const MeshTopology& topo = membrane_.topology();
  const CurvatureEstimator estimator = p_.estimator;
  const Index nv = topo.numVertices();
  const bool want_gradient = e.gradient != nullptr;
  if (want_gradient) {
    area_coefficient_.resize(nv);
    alpha_.resize(nv);
    beta_.resize(nv);
  }

  const double energy = deterministicSum(nv, [&](Index v) {
    if (topo.on_boundary[v]) {
      if (want_gradient) {
        area_coefficient_[v] = 0.0;
        alpha_[v].setZero();
        beta_[v].setZero();
      }
      return 0.0;
    }
    const CurvatureAndDerivative c =
        meanCurvature(g.area_gradient[v], g.volume_gradient[v], estimator);
    double kappa = kappa_, dh = c.H - h0_, area_coefficient;
    if (coat && (*coat_copies)[v] > 0) {
      const double phi = coveredFraction((*coat_copies)[v], coat->area, g.vertex_area[v]);
      const CoatedLipid lipid = coatedLipid(kappa_, coat->bending_modulus, coat->spontaneous_curvature, dh, phi);
      kappa = lipid.kappa;
      dh = lipid.offset;
      // phi capped at 1 no longer follows A_v.
      area_coefficient = lipid.density - (phi < 1.0 ? phi * lipid.derivative : 0.0);
    } else {
      area_coefficient = 2.0 * kappa * dh * dh;
    }
    if (want_gradient) {
      const double s = 4.0 * kappa * dh * g.vertex_area[v];
      area_coefficient_[v] = area_coefficient;
      alpha_[v] = s * c.alpha;
      beta_[v] = s * c.beta;
    }
    return 2.0 * kappa * dh * dh * g.vertex_area[v];
  });
  if (!want_gradient) return energy;

  const double* x = e.x + 3 * membrane_.offset();
  const Index nf = topo.numFaces();
  corner_gradient_.resize(3 * static_cast<std::size_t>(nf));
  parallelFor(nf, [&](Index f) {
    const Tri& t = topo.triangles[f];
    const TriangleEdges edges(vertexAt(x, t[0]), vertexAt(x, t[1]), vertexAt(x, t[2]));
    const Vec3& n = g.face_unit_normal[f];
    const double inv_len = 1.0 / (2.0 * g.face_area[f]);
    const double c = (area_coefficient_[t[0]] + area_coefficient_[t[1]] + area_coefficient_[t[2]]) / 3.0;
    Vec3 w = Vec3::Zero(), b = Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
      const Vec3 wk = edges.e[k].cross(alpha_[t[k]]);
      w += wk - n * n.dot(wk);
      b += beta_[t[k]];
    }
    const Vec3 m = 0.5 * inv_len * w + b / 6.0;
    for (int p = 0; p < 3; ++p) {
      const Vec3& alpha_prev = alpha_[t[(p + 2) % 3]];
      const Vec3& alpha_next = alpha_[t[(p + 1) % 3]];
      corner_gradient_[3 * f + p] =
          n.cross(0.5 * c * edges.e[p] + 0.5 * (alpha_prev - alpha_next)) - edges.e[p].cross(m);
    }
  });
  gatherCorners(topo, corner_gradient_, gradientOf(e));
  return energy;
}

}  // namespace cortex
