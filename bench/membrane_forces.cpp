// Membrane force-field throughput on a ~10,000-vertex vesicle, and minimization cost.
//
// Scenario: MEDYAN's `vesicle` example parameters (docs/benchmarks.md): bending
// 100 pN·nm, area modulus 400 pN/nm, tension 0.02 pN/nm, volume modulus 0.8 pN/nm², on a
// sphere of radius 1000 nm meshed two ways: icosphere level 5 (10,242 vertices, perfectly
// regular) and marching tetrahedra + smoothing (what `shape = "sphere"` configs produce,
// irregular valences). Filaments are absent: this measures the membrane alone.
//
// Every evaluation bumps Evaluation::version, as the minimizer does, so the shared
// geometry cache (Membrane::geometry) is recomputed on every call and is part of the time.
// Throughput is reported as vertex_evals_per_s = vertices × calls / wall second.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <memory>
#include <random>
#include <string>

#include "mech/minimizer.hpp"
#include "membrane/area_energy.hpp"
#include "membrane/bending_energy.hpp"
#include "membrane/regularization_energy.hpp"
#include "membrane/volume_energy.hpp"
#include "mesh/icosphere.hpp"
#include "mesh/marching_tetrahedra.hpp"
#include "sim/system.hpp"

namespace cortex {
namespace {

constexpr double kRadius = 1000.0;  // nm
// Marching-tetrahedra edge giving a mesh of similar size to icosphere level 5 (11,390
// vertices; the `vertices` counter reports it). Throughput is per vertex, so the exact
// count does not matter.
constexpr double kMtEdge = 37.0;  // nm

MembraneMechanics vesicleMechanics(bool with_regularization,
                                   CurvatureEstimator estimator = CurvatureEstimator::kUnsigned) {
  MembraneMechanics m;
  // Unsigned: what a config with spontaneous_curvature = 0 gets by default (io/config.cpp).
  m.bending = {Schedule(100.0), Schedule(0.0), estimator};
  m.area.modulus = Schedule(400.0);
  m.tension.tension = Schedule(0.02);
  m.volume.modulus = Schedule(0.8);
  // Only for the regularization term's own benchmark; a typical vesicle runs without it.
  if (with_regularization) m.regularization.strength = Schedule(0.1);  // pN·nm per triangle
  return m;
}

enum class MeshKind { kIcosphere, kMarchingTetrahedra };

// Built once per kind: Google Benchmark calls each benchmark function several times
// (iteration-count search, repetitions) and marching tetrahedra takes a while.
const TriangleSoup& sphereSoup(MeshKind kind) {
  if (kind == MeshKind::kIcosphere) {
    static const TriangleSoup ico = icosphere(Vec3::Zero(), kRadius, 5);
    return ico;
  }
  static const TriangleSoup mt = meshImplicitSurface(implicitSphere(Vec3::Zero(), kRadius), kMtEdge);
  return mt;
}

const char* meshName(MeshKind kind) { return kind == MeshKind::kIcosphere ? "ico" : "mt"; }

std::unique_ptr<Membrane> makeMembrane(MeshKind kind, bool with_regularization,
                                       CurvatureEstimator estimator = CurvatureEstimator::kUnsigned) {
  return std::make_unique<Membrane>("vesicle",
                                    SurfaceMesh::fromSoup(sphereSoup(kind), "bench sphere"),
                                    vesicleMechanics(with_regularization, estimator), std::vector<char>{});
}

// A System of one vesicle with the given mesh, as a run assembles it.
Config vesicleConfig(const TriangleSoup& soup) {
  Config c;
  c.source = "benchmark";
  MembraneConfig m;
  m.name = "vesicle";
  m.shape = "mesh";
  m.soup = soup;
  m.mechanics = vesicleMechanics(false);
  c.membranes.push_back(m);
  return c;
}

// Every coordinate moved by up to `amplitude` nm: breaks the sphere's symmetry so no
// term's gradient is trivially zero, and gives the minimizer something to relax.
Eigen::VectorXd perturbed(Eigen::VectorXd x, double amplitude) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  for (Eigen::Index i = 0; i < x.size(); ++i) x[i] += u(rng);
  return x;
}

Eigen::VectorXd coordinatesOf(const Membrane& m) {
  Eigen::VectorXd x(3 * m.mesh().numVertices());
  for (Index v = 0; v < m.mesh().numVertices(); ++v) x.segment<3>(3 * v) = m.mesh().positions()[v];
  return x;
}

void setThroughput(benchmark::State& state, Index vertices) {
  state.counters["vertices"] = static_cast<double>(vertices);
  state.counters["vertex_evals_per_s"] = benchmark::Counter(
      static_cast<double>(vertices) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// The shared geometry cache alone: what every term pays once per coordinate update.
void geometryBench(benchmark::State& state, MeshKind kind) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const auto membrane = makeMembrane(kind, false);
  const Eigen::VectorXd x = perturbed(coordinatesOf(*membrane), 2.0);
  MeshGeometry g;
  for (auto _ : state) {
    g.compute(membrane->topology(), x.data());
    benchmark::DoNotOptimize(g.area);
  }
  setThroughput(state, membrane->mesh().numVertices());
}

// One term alone. Its time includes the geometry recomputation (the version bump makes
// the cache stale on each call): when a term is the only one in a force field, that is
// what it costs; in the full field the geometry is shared, so per-term times do not add up
// to the full field's. The gradient is zeroed every call, as ForceField does.
template <class Term, class Parameters>
void termBench(benchmark::State& state, MeshKind kind, CurvatureEstimator estimator,
               Parameters MembraneMechanics::*parameters) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const auto membrane = makeMembrane(kind, true, estimator);
  const Eigen::VectorXd x = perturbed(coordinatesOf(*membrane), 2.0);
  Eigen::VectorXd gradient(x.size());
  Term term(*membrane, membrane->mechanics().*parameters);
  std::uint64_t version = 0;
  for (auto _ : state) {
    gradient.setZero();
    benchmark::DoNotOptimize(term.evaluate(Evaluation{x.data(), gradient.data(), ++version}));
    benchmark::ClobberMemory();
  }
  setThroughput(state, membrane->mesh().numVertices());
}

// A typical vesicle's force field as System builds it: bending + global area + tension +
// volume, sharing one geometry computation per call.
void fieldBench(benchmark::State& state, MeshKind kind, bool with_gradient) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  System system(vesicleConfig(sphereSoup(kind)));
  const Eigen::VectorXd x = perturbed(system.coordinates(), 2.0);
  Eigen::VectorXd gradient(x.size());
  ForceField& field = system.forceField();
  for (auto _ : state) {
    benchmark::DoNotOptimize(with_gradient ? field.valueAndGradient(x, gradient) : field.value(x));
    benchmark::ClobberMemory();
  }
  setThroughput(state, system.numVertices());
}

// Relaxation of a perturbed vesicle to 0.1 pN, the mechanical step of a simulation.
// Radius 800 nm and icosphere level 4 (2,562 vertices) match MEDYAN's vesicle example
// (R = 800 nm, 2,860 vertices). Reference area and volume are the unperturbed sphere's.
// Two starts: "noise" moves every coordinate by up to 2 nm (short-wavelength modes, which
// bending makes stiff and quick to relax); "ellipsoid" also stretches x by 10%, a
// long-wavelength mode, the slow kind for CG and L-BFGS.
void minimizeBench(benchmark::State& state, MinimizerKind kind, double stretch) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  System system(vesicleConfig(icosphere(Vec3::Zero(), 800.0, 4)));
  Eigen::VectorXd start = perturbed(system.coordinates(), 2.0);
  for (Eigen::Index i = 0; i < start.size(); i += 3) start[i] *= stretch;
  ForceField& field = system.forceField();
  Eigen::VectorXd g(start.size());
  field.valueAndGradient(start, g);
  state.counters["start_max_force_pN"] = detail::maxAbs(g);
  MinimizerSettings settings;
  settings.kind = kind;
  settings.force_tolerance = 0.1;  // pN
  const std::int64_t force0 = field.forceEvaluations(), energy0 = field.energyEvaluations();
  long iterations = 0;
  bool all_converged = true;
  for (auto _ : state) {
    Eigen::VectorXd x = start;
    const MinimizationResult r = minimize(field, x, settings);
    iterations += r.iterations;
    all_converged = all_converged && r.converged;
    if (!r.converged) state.SetLabel(r.stop_reason);
  }
  const auto per_run = benchmark::Counter::kAvgIterations;
  state.counters["vertices"] = static_cast<double>(system.numVertices());
  state.counters["force_evals"] = benchmark::Counter(static_cast<double>(field.forceEvaluations() - force0), per_run);
  state.counters["energy_evals"] = benchmark::Counter(static_cast<double>(field.energyEvaluations() - energy0), per_run);
  state.counters["iterations"] = benchmark::Counter(static_cast<double>(iterations), per_run);
  state.counters["converged"] = all_converged ? 1.0 : 0.0;
}

// Threads 1 and 2 (the machine class has 2 cores). Wall-clock time, because Google
// Benchmark's CPU time covers only the calling thread, not OpenMP's workers.
void threaded(benchmark::internal::Benchmark* b) {
  b->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMicrosecond);
}

template <class Term, class Parameters>
void registerTerm(const std::string& name, MeshKind kind, Parameters MembraneMechanics::*parameters,
                  CurvatureEstimator estimator = CurvatureEstimator::kUnsigned) {
  threaded(benchmark::RegisterBenchmark(
      ("term/" + name + "/" + meshName(kind)).c_str(),
      [kind, estimator, parameters](benchmark::State& s) { termBench<Term>(s, kind, estimator, parameters); }));
}

void registerAll() {
  for (MeshKind kind : {MeshKind::kIcosphere, MeshKind::kMarchingTetrahedra}) {
    const std::string mesh = meshName(kind);
    threaded(benchmark::RegisterBenchmark(("geometry/" + mesh).c_str(),
                                          [kind](benchmark::State& s) { geometryBench(s, kind); }));
    registerTerm<BendingEnergy>("bending", kind, &MembraneMechanics::bending);
    registerTerm<BendingEnergy>("bending_signed", kind, &MembraneMechanics::bending, CurvatureEstimator::kSigned);
    registerTerm<GlobalAreaEnergy>("area_global", kind, &MembraneMechanics::area);
    registerTerm<PerVertexAreaEnergy>("area_per_vertex", kind, &MembraneMechanics::area);
    registerTerm<TensionEnergy>("tension", kind, &MembraneMechanics::tension);
    registerTerm<VolumeEnergy>("volume", kind, &MembraneMechanics::volume);
    registerTerm<RegularizationEnergy>("regularization", kind, &MembraneMechanics::regularization);
    threaded(benchmark::RegisterBenchmark(("field/energy+gradient/" + mesh).c_str(),
                                          [kind](benchmark::State& s) { fieldBench(s, kind, true); }));
    threaded(benchmark::RegisterBenchmark(("field/energy_only/" + mesh).c_str(),
                                          [kind](benchmark::State& s) { fieldBench(s, kind, false); }));
  }
  for (MinimizerKind kind : {MinimizerKind::kConjugateGradient, MinimizerKind::kLbfgs}) {
    for (const auto& [start, stretch] : {std::pair{"noise", 1.0}, std::pair{"ellipsoid", 1.1}}) {
      const std::string name = std::string("minimize/") + (kind == MinimizerKind::kLbfgs ? "lbfgs" : "cg") +
                               "/ico2562_" + start;
      benchmark::RegisterBenchmark(name.c_str(), [kind, stretch = stretch](benchmark::State& s) {
        minimizeBench(s, kind, stretch);
      })->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace
}  // namespace cortex

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  cortex::registerAll();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
