#include "membrane/shape_relaxation.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "core/scoped_timer.hpp"
#include "mech/constrained_lbfgs.hpp"
#include "membrane/area_energy.hpp"
#include "membrane/bending_energy.hpp"
#include "membrane/normal_displacement_problem.hpp"
#include "membrane/regularization_energy.hpp"
#include "membrane/sobolev_preconditioner.hpp"
#include "membrane/volume_energy.hpp"
#include "mesh/mesh_quality.hpp"
#include "mesh/vertex_normals.hpp"

namespace cortex {
namespace {

// The method's constants, chosen on the acceptance shapes and the failing cases
// (docs/membrane.md: a scan of the shift over 1-50 and of the strains).
constexpr double kShift = 20.0;           // ε = kShift / R² in the preconditioner, R = sqrt(A / 4π)
constexpr double kStepStrain = 0.5;       // largest move of one iteration (strain)
constexpr double kRefreshStrain = 0.5;    // new normals once a vertex moved this far
constexpr double kSettledStrain = 0.005;  // converged only after an outer step moving less
constexpr double kRemeshStrain = 0.3;     // remesh at convergence if the shape changed this much
constexpr double kRemeshAnyway = 1.0;     // remesh between outer steps beyond this
constexpr double kKeepRigidColumnsStrain = 0.05;  // largest move after which the rigid rows' P^-1 columns are kept
// Tangential relocation between outer steps only after a move larger than this: a
// relocation moves the vertices within the surface, which changes the discrete energy, and
// the next outer step spent 3-8 iterations relaxing that away after every small step
// (docs/membrane.md); a shape that barely moved keeps its mesh, still remeshed on the
// summed strain and the angle bounds below.
constexpr double kTidyStrain = 0.05;
constexpr int kMaxOuter = 400;
constexpr long kMaxInnerIterations = 300;  // per outer step
constexpr int kRefactorInterval = 10;      // outer steps between factorizations
constexpr int kMemory = 10;                // L-BFGS pairs
constexpr double kConstraintTolerance = 1e-10;  // relative
constexpr double kLargestNaturalTolerance = 0.1;  // pN
// Under the natural tolerance a relaxation also goes on until the quasi-Newton step
// predicts no vertex moving more than this fraction of R = sqrt(A/4π): where the forces
// driving a shape are smaller than the membrane's pressure scale (a weak coat on a tense
// patch), the force criterion alone stopped at 60% of the shape (docs/membrane.md).
constexpr double kStepTolerance = 2e-4;


// What the relaxation needs to know of the membrane's terms: κ to scale the metric, and
// the stiffness of global penalties (area, volume) to add them to it exactly.
struct TermScales {
  double kappa = 1.0;
  double area_stiffness = 0.0, volume_stiffness = 0.0;
};

TermScales scalesOf(const Membrane& m, const std::vector<EnergyTerm*>& terms) {
  TermScales s;
  for (EnergyTerm* t : terms) {
    // Terms of the vertices' places within the surface: normal displacements cannot
    // relax them (the config refuses them with this relaxation).
    if (dynamic_cast<const PerVertexAreaEnergy*>(t) || dynamic_cast<const RegularizationEnergy*>(t))
      throw InputError("membrane \"" + m.name() + "\": its " + t->name() +
                       " term acts within the surface; relax it with minimizer = \"cg\" or \"lbfgs\"");
    if (const auto* b = dynamic_cast<const BendingEnergy*>(t); b && b->modulus() > 0) s.kappa = b->modulus();
    if (const auto* a = dynamic_cast<const GlobalAreaEnergy*>(t)) s.area_stiffness = a->stiffness();
    if (const auto* v = dynamic_cast<const VolumeEnergy*>(t)) s.volume_stiffness = v->stiffness();
  }
  return s;
}


// The relaxation's measure of a move, |u_v| k_v with k_v = 2|H_v| + 1/R: a strain, the
// same on any mesh of the same shape.
Eigen::VectorXd strainScale(const MeshGeometry& g, double radius) {
  Eigen::VectorXd k(static_cast<Index>(g.vertex_area.size()));
  for (Index v = 0; v < k.size(); ++v) {
    const double gv = g.volume_gradient[v].norm();
    const double h = gv > 0 ? g.area_gradient[v].norm() / (2.0 * gv) : 0.0;
    k[v] = 2.0 * h + 1.0 / radius;
  }
  return k;
}

// Before a near-sphere (reduced volume over kNearSphere) is deflated: a small
// axisymmetric ellipsoidal mode, x_v += ε R P2(â·r̂_v) n̂_v along a fixed axis â of no
// symmetry of a regular mesh. From a sphere the area and volume gradients are parallel,
// and the deflation follows whatever the mesh's irregularity favours: on an icosphere its
// icosahedral pattern, which the relaxation, keeping the symmetry, carried into an
// icosahedrally buckled stationary shape at about twice the energy of the prolate
// minimum (2.3-2.4 × 8πκ at v = 0.9, exit 0). The mode is the one the deflated sphere's
// lowest shapes grow from (Seifert, Berndl & Lipowsky 1991); it only starts the path, and
// the relaxation then goes to the equilibrium (docs/membrane.md).
constexpr double kNearSphere = 0.995;
constexpr double kKickAmplitude = 0.02;  // ε, of R = sqrt(A/4π)

// g: the geometry at the membrane's positions.
void breakSphericalSymmetry(Membrane& m, const MeshGeometry& g) {
  const double radius = std::sqrt(g.area / (4.0 * constants::kPi));
  const Vec3 axis = Vec3(1.0, 2.0, 3.0).normalized();
  const std::vector<Vec3> normals = vertexNormals(m.mesh());
  std::vector<Vec3>& x = m.mesh().positions();
  Vec3 centroid = Vec3::Zero();
  for (std::size_t v = 0; v < x.size(); ++v) centroid += g.vertex_area[v] * x[v];
  centroid /= g.area;
  for (std::size_t v = 0; v < x.size(); ++v) {
    if (m.fixedVertices()[v]) continue;
    const Vec3 r = x[v] - centroid;
    const double c = r.norm() > 0 ? axis.dot(r) / r.norm() : 0.0;
    x[v] += kKickAmplitude * radius * 0.5 * (3.0 * c * c - 1.0) * normals[v];
  }
}

}  // namespace

double naturalForceTolerance(const Membrane& m, double t) {
  const MeshGeometry g = m.currentGeometry();
  const double radius = std::sqrt(g.area / (4.0 * constants::kPi));
  const double pressure = m.mechanics().bending.modulus.at(t) / (radius * radius * radius) +
                          std::abs(m.mechanics().tension.tension.at(t)) / radius;
  const double mean_vertex_area = g.area / static_cast<double>(m.mesh().numVertices());
  return pressure > 0 ? std::min(kLargestNaturalTolerance, pressure * mean_vertex_area) : kLargestNaturalTolerance;
}

ShapeRelaxationReport relaxMembraneShape(Membrane& m, ForceField& field, double t, const ShapeRelaxationSettings& s) {
  const auto start = SteadyClock::now();
  const BodyAtOffsetZero at_zero(m);
  ShapeRelaxationReport rep;
  rep.force_tolerance = s.force_tolerance > 0 ? s.force_tolerance : naturalForceTolerance(m, t);
  const bool closed = m.isClosed();
  const bool exact_area = m.mechanics().area.model == AreaModel::kExact;
  // With the area held exactly, a reduced volume of 1 asks for the sphere, the largest
  // volume the area allows (and more than a discrete mesh can enclose): no volume
  // constraint is needed for it. Without an exact area the volume is held whatever it
  // is (a tension then meets the pressure of the held volume, as in a tense vesicle).
  const bool sphere_by_area =
      exact_area && m.targetVolume(t) >= sphereVolumeOfArea(m.targetArea(t)) * (1.0 - 1e-12);
  const bool exact_volume = closed && m.mechanics().volume.exact && !sphere_by_area;
  const std::vector<EnergyTerm*> terms = field.termsOf(m.name());
  const TermScales scales = scalesOf(m, terms);
  // Held exactly or by a penalty (a soft penalty also sat at the sphere, a saddle).
  if (exact_volume || (closed && scales.volume_stiffness > 0)) {
    const MeshGeometry g = m.currentGeometry();
    const double v0 = g.volume / sphereVolumeOfArea(g.area);
    if (v0 > kNearSphere && m.targetVolume(t) / sphereVolumeOfArea(m.targetArea(t)) < v0 - 1e-3) {
      breakSphericalSymmetry(m, g);
      spdlog::debug("membrane \"{}\": deflated from a near-sphere (reduced volume {:.6g}): started along a {:g} R "
                    "ellipsoidal mode to break the mesh's symmetry", m.name(), v0, kKickAmplitude);
    }
  }
  const double area_target = m.targetArea(t), volume_target = closed ? m.targetVolume(t) : 0.0;
  MembraneEquilibrium equilibrium = m.equilibrium();
  double& moved_since_remesh = equilibrium.strain_since_remesh;
  const bool can_remesh = m.remeshing().has_value();
  bool final_remesh_done = false;
  long iterations_left = s.max_iterations;
  ConstrainedLbfgsResult last;
  ShapeRelaxationWarmStart own_start;
  ShapeRelaxationWarmStart& warm = s.warm_start ? *s.warm_start : own_start;
  LbfgsMemory& memory = warm.memory;
  SobolevPreconditioner& precond = warm.preconditioner;
  const long solves_before = precond.solves();
  EvaluationMemo memo;  // the last evaluation of each outer step, for the next one and the report

  double continuation = 1.0;  // fraction of the way from the current area and volume to the targets
  for (rep.outer = 0; rep.outer < kMaxOuter; ++rep.outer) {
    const Index n = m.mesh().numVertices();
    const std::vector<double> x0 = flatCoordinates(m.mesh().positions());
    MeshGeometry geo0;
    geo0.compute(m.topology(), x0.data());
    const double radius = std::sqrt(geo0.area / (4.0 * constants::kPi));
    // The metric is refactorized every kRefactorInterval outer steps, across windows:
    // relaxations that barely move the shape share one. Remeshing, the only change of the
    // vertex count, clears it and bumps the connectivity version.
    RelaxationMetric& metric = m.relaxationMetric();
    if (metric.positions.size() != x0.size() || metric.outer_steps >= kRefactorInterval) {
      metric = {x0, scales.kappa, kShift / (radius * radius), 0};
      warm.factored = false;
    }
    if (!warm.factored || warm.connectivity != m.connectivityVersion()) {
      if (warm.connectivity != m.connectivityVersion()) memory.clear();  // pairs of other vertices
      const ScopedTimer timer{rep.factor_seconds};
      precond.build(scalarMeshOperators(metric.positions.data(), n, m.topology().triangles), metric.kappa,
                    metric.shift, m.fixedVertices());
      ++rep.factorizations;
      warm.factored = true;
      warm.forgetRigidColumns();
      warm.connectivity = m.connectivityVersion();
    }
    NormalDisplacementProblem problem(m, field, terms, exact_area, exact_volume, precond, &warm);
    problem.useMemo(&memo);
    if (scales.area_stiffness > 0 || (closed && scales.volume_stiffness > 0)) {
      // Stiff global penalties, k/X0 ∇X ∇Xᵀ, as an exact low-rank part of the metric.
      Eigen::VectorXd c;
      Eigen::MatrixXd jac;
      NormalDisplacementProblem probe(m, field, {}, true, closed, precond);
      probe.constraints(Eigen::VectorXd::Zero(n), c, jac);
      Eigen::MatrixXd u(n, 2);
      Eigen::VectorXd w(2);
      int k = 0;
      if (scales.area_stiffness > 0) u.col(k) = jac.row(0).transpose(), w[k++] = scales.area_stiffness;
      if (closed && scales.volume_stiffness > 0) u.col(k) = jac.row(1).transpose(), w[k++] = scales.volume_stiffness;
      precond.setLowRank(u.leftCols(k), w.head(k));
    }
    ConstrainedLbfgsSettings inner;
    inner.tolerance = rep.force_tolerance;
    if (!(s.force_tolerance > 0)) inner.step_tolerance = kStepTolerance * radius;
    inner.max_iterations = std::min(iterations_left, kMaxInnerIterations);
    inner.memory = kMemory;
    inner.move_scale = strainScale(geo0, radius);
    inner.max_move = kStepStrain;
    inner.max_total_move = kRefreshStrain;
    inner.constraint_tolerance = kConstraintTolerance;
    ++metric.outer_steps;
    Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
    // Continuation: targets the restoration cannot reach from here (a sphere asked for a
    // lower reduced volume: the area and volume gradients are parallel), or only by a
    // large deformation, are approached through intermediate ones, each relaxed roughly.
    for (;;) {
      problem.area_target = geo0.area + continuation * (area_target - geo0.area);
      problem.volume_target = geo0.volume + continuation * (volume_target - geo0.volume);
      ConstrainedLbfgsSettings step = inner;
      if (continuation < 1.0) {
        step.tolerance = 100.0 * inner.tolerance;
        step.max_iterations = std::min<long>(inner.max_iterations, 30);
      }
      last = minimizeConstrained(problem, u, step, memory);
      if (last.stop_reason != kInfeasibleStart || continuation < 1.0 / 1024) break;
      continuation *= 0.25;
      ++rep.continuation_steps;
      rep.constraint_evaluations += last.constraint_evaluations;
      u.setZero();
      memory.clear();
    }
    if (last.stop_reason == kInfeasibleStart) rep.targets_unreachable = true;
    const bool at_targets = continuation >= 1.0;
    continuation = std::min(1.0, 4.0 * continuation);
    rep.iterations += last.iterations;
    iterations_left -= last.iterations;
    rep.force_evaluations += problem.evaluations;
    rep.constraint_evaluations += last.constraint_evaluations;
    rep.force_seconds += problem.force_seconds;
    rep.solve_seconds += problem.solve_seconds;
    problem.remember(u);
    const Eigen::VectorXd& x = problem.positionsAt(u);
    for (Index v = 0; v < n; ++v) m.mesh().positions()[v] = x.segment<3>(3 * v);
    const double moved = u.size() ? u.cwiseProduct(inner.move_scale).cwiseAbs().maxCoeff() : 0.0;
    moved_since_remesh += moved;
    // The kept rigid columns follow the normals they were computed with; after a large
    // move they cost more iterations than their six solves (+14-17% evaluations at 45k
    // vertices in bench/relaxation.cpp when kept regardless).
    if (moved > kKeepRigidColumnsStrain) warm.forgetRigidColumns();
    spdlog::debug("membrane \"{}\" relaxation: outer step {}, {} vertices, {} iterations, {} force evaluations, "
                  "moved {:.3g} (strain), max normal force {:.3g} pN, energy {:.10g} pN nm ({})",
                  m.name(), rep.outer, n, last.iterations, last.evaluations, moved, last.max_residual, last.value,
                  last.converged ? "converged" : last.stop_reason);
    if (s.progress) s.progress({rep.iterations, last.max_residual, rep.force_tolerance});
    // On the way to the targets an outer step ends at an intermediate target: no
    // convergence test, but the mesh is kept in shape like after any other step.
    const bool next_target = !at_targets && (last.converged || last.refresh || last.iterations >= 30);
    if (!next_target && last.converged && moved <= kSettledStrain) {
      if (can_remesh && !final_remesh_done &&
          (moved_since_remesh > kRemeshStrain || measureQuality(m.mesh()).min_angle_deg < 25.0)) {
        // Once more on a fresh mesh for the converged shape, then stop.
        const ScopedTimer timer{rep.remesh_seconds};
        m.remesh(*m.remeshing());
        ++rep.remeshes;
        final_remesh_done = true;
        moved_since_remesh = 0.0;
        memory.clear();
        continue;
      }
      rep.converged = true;
      break;
    }
    if (!next_target && !last.converged && !last.refresh) {
      // An inner loop that hit its iteration cap gets fresh normals and a tidied mesh like
      // a refresh; a failed line search or an exhausted budget ends the relaxation.
      if (last.iterations < kMaxInnerIterations || iterations_left <= 0) {
        rep.stop_reason = last.stop_reason;
        break;
      }
      memory.clear();
    }
    // Mesh maintenance between outer steps.
    if (can_remesh && (moved_since_remesh > kRemeshAnyway || measureQuality(m.mesh()).min_angle_deg < 20.0)) {
      const ScopedTimer timer{rep.remesh_seconds};
      m.remesh(*m.remeshing());
      ++rep.remeshes;
      moved_since_remesh = 0.0;
      memory.clear();
    } else if (moved > kTidyStrain) {
      relocateTangentially(m.mesh(), &m.fixedVertices());
    }
  }
  if (!rep.converged && rep.stop_reason.empty()) rep.stop_reason = "maximum outer steps or iterations reached";

  // The result at the final positions: energy, residual forces, multipliers.
  {
    SobolevPreconditioner unused;
    NormalDisplacementProblem problem(m, field, terms, exact_area, exact_volume, unused);
    problem.useMemo(&memo);  // where the last outer step ended, unless the mesh changed since
    const Index n = m.mesh().numVertices();
    const Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd g;
    rep.energy = problem.valueAndGradient(u, g);
    rep.force_evaluations += problem.evaluations;
    rep.force_seconds += problem.force_seconds;
    // The evaluation's own geometry, if the membrane still holds it: the same positions.
    const MeshGeometry* evaluated = m.cachedGeometry(problem.evaluatedVersion());
    const MeshGeometry geo = evaluated ? *evaluated : m.currentGeometry();
    // The multipliers of the last iterate (the minimizer's, in the Sobolev metric), else
    // least squares on the normal components.
    const int nc = int(exact_area) + int(exact_volume);
    Eigen::VectorXd lambda;
    if (last.multipliers.size() >= nc && nc > 0) {
      lambda = last.multipliers.head(nc);
    } else if (nc > 0) {
      Eigen::MatrixXd jac(n, nc);
      const auto& normals = problem.normals();
      for (Index v = 0; v < n; ++v) {
        int col = 0;
        if (exact_area) jac(v, col++) = normals[v].dot(geo.area_gradient[v]);
        if (exact_volume) jac(v, col) = normals[v].dot(geo.volume_gradient[v]);
      }
      lambda = jac.colPivHouseholderQr().solve(g);
    }
    Eigen::VectorXd lagrangian = problem.fullGradient();
    int col = 0;
    equilibrium.tension = equilibrium.pressure = std::numeric_limits<double>::quiet_NaN();
    // At equilibrium ∇E = λ_A ∇A + λ_V ∇V. A reservoir of tension σ and pressure difference
    // Δp = p_in − p_out would add σ A − Δp V to the energy and balance the same shape, so
    // σ = −λ_A and Δp = λ_V (for a sphere, Laplace's law Δp = 2σ/R).
    if (exact_area) {
      equilibrium.tension = -lambda[col];
      for (Index v = 0; v < n; ++v) lagrangian.segment<3>(3 * v) -= lambda[col] * geo.area_gradient[v];
      ++col;
    }
    if (exact_volume) {
      equilibrium.pressure = lambda[col];
      for (Index v = 0; v < n; ++v) lagrangian.segment<3>(3 * v) -= lambda[col] * geo.volume_gradient[v];
    }
    const auto& normals = problem.normals();
    // The rigid rows hold the membrane where it is; what they hold is no residual of the
    // shape (the inner loop converges with their multipliers too), but it is reported.
    Eigen::VectorXd normal_force(n);
    for (Index v = 0; v < n; ++v)
      normal_force[v] = m.fixedVertices()[v] ? 0.0 : normals[v].dot(lagrangian.segment<3>(3 * v));
    const Eigen::VectorXd held = normal_force.allFinite() ? problem.rigidPart(normal_force) : Eigen::VectorXd::Zero(n);
    const auto& x = m.mesh().positions();
    Vec3 centroid = Vec3::Zero();
    for (Index v = 0; v < n; ++v) centroid += geo.vertex_area[v] * x[v];
    centroid /= geo.area;
    Vec3 held_force = Vec3::Zero(), held_torque = Vec3::Zero();
    for (Index v = 0; v < n; ++v) {
      held_force += held[v] * normals[v];
      held_torque += (x[v] - centroid).cross(held[v] * normals[v]);
    }
    rep.held_force = held_force.norm();
    rep.held_torque = held_torque.norm();
    for (Index v = 0; v < n; ++v) {
      if (m.fixedVertices()[v]) continue;
      const Vec3 f = lagrangian.segment<3>(3 * v) - held[v] * normals[v];
      if (!f.allFinite()) {
        // Not a number is not zero: this must never read as converged.
        rep.max_force = rep.max_normal_force = std::numeric_limits<double>::infinity();
        rep.converged = false;
        rep.stop_reason = fmt::format("the forces on vertex {} are not finite", v);
        break;
      }
      rep.max_force = std::max(rep.max_force, f.norm());
      rep.max_normal_force = std::max(rep.max_normal_force, std::abs(normals[v].dot(f)));
    }
    rep.area_held = exact_area;
    rep.volume_held = exact_volume;
    rep.area_error = exact_area ? geo.area / area_target - 1.0 : 0.0;
    rep.volume_error = exact_volume ? geo.volume / volume_target - 1.0 : 0.0;
    rep.vertices = n;
  }
  m.setEquilibrium(equilibrium);
  field.countForceEvaluations(rep.force_evaluations, rep.force_seconds);
  rep.preconditioner_solves = precond.solves() - solves_before;
  rep.seconds = secondsSince(start);
  return rep;
}

}  // namespace cortex
