// One membrane: its mesh, its mechanical parameters (possibly scheduled in time), the
// material reference state, and the geometry cache its energy terms share.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/schedule.hpp"
#include "mech/energy_term.hpp"
#include "membrane/curvature.hpp"
#include "mesh/geometry.hpp"
#include "mesh/mesh_topology.hpp"
#include "mesh/remesh.hpp"
#include "mesh/surface_mesh.hpp"

namespace cortex {

enum class AreaModel { kGlobal, kPerVertex, kNone };

// Mechanical parameters as the user gave them; unset schedules take the defaults below.
struct MembraneMechanics {
  Schedule bending_modulus{0.0};        // pN·nm
  Schedule spontaneous_curvature{0.0};  // 1/nm
  Schedule area_modulus{0.0};           // pN/nm
  Schedule tension{0.0};                // pN/nm
  Schedule volume_modulus{0.0};         // pN/nm^2
  Schedule regularization{0.0};         // pN·nm per triangle, mesh regularization (regularization_energy.hpp)
  Schedule target_area;                 // nm^2; default: the initial area
  Schedule target_volume;               // nm^3; default: reduced_volume, else the initial volume
  Schedule reduced_volume;              // dimensionless
  CurvatureEstimator curvature = CurvatureEstimator::kSigned;
  AreaModel area_model = AreaModel::kGlobal;
};

// Reference state fixed when the membrane is created (and restored from checkpoints).
struct MembraneMaterial {
  double initial_area = 0.0;
  double initial_volume = 0.0;
  std::vector<double> vertex_area0;  // per-vertex material areas (per_vertex area model)
};

// The scheduled parameters evaluated at the current time.
struct MembraneCoefficients {
  double kappa = 0, h0 = 0, k_area = 0, area0 = 0, gamma = 0, k_volume = 0, volume0 = 0;
  double k_regularization = 0;
};

class Membrane {
 public:
  Membrane(std::string name, SurfaceMesh mesh, MembraneMechanics mechanics,
           std::vector<char> fixed_vertices);
  // Replaces the reference state measured at construction (used when resuming).
  void setMaterial(MembraneMaterial material) { material_ = std::move(material); }

  const std::string& name() const { return name_; }
  const SurfaceMesh& mesh() const { return mesh_; }
  SurfaceMesh& mesh() { return mesh_; }
  const MeshTopology& topology() const { return topology_; }
  const MembraneMechanics& mechanics() const { return mechanics_; }
  const MembraneMaterial& material() const { return material_; }
  const std::vector<char>& fixedVertices() const { return fixed_; }
  bool isClosed() const { return mesh_.isClosed(); }

  void setTime(double t);
  const MembraneCoefficients& now() const { return now_; }
  // Target vertex areas at the current time (per-vertex area model).
  double vertexArea0(Index v) const { return material_.vertex_area0[v] * vertex_area0_scale_; }

  // Offset of this membrane's first coordinate in the global coordinate vector.
  Index dofOffset() const { return dof_offset_; }
  void setDofOffset(Index offset) { dof_offset_ = offset; }

  // Remeshes (remesh.hpp), carrying fixed flags and material areas along, and
  // accumulates the operation counts. Connectivity and vertex count change: the caller
  // must lay out the coordinates again (System::layOut).
  RemeshStats remesh(const RemeshSettings& settings);
  // Remeshing after every minimization, if set (config remesh = true).
  const std::optional<RemeshSettings>& remeshing() const { return remeshing_; }
  void setRemeshing(std::optional<RemeshSettings> settings) { remeshing_ = std::move(settings); }
  const RemeshStats& remeshTotals() const { return remesh_totals_; }
  void setRemeshTotals(const RemeshStats& totals) { remesh_totals_ = totals; }

  // Geometry at the coordinates of `e`, recomputed only when e.version changes.
  const MeshGeometry& geometry(const Evaluation& e);
  // Geometry at the mesh's own positions.
  MeshGeometry currentGeometry() const;

 private:
  std::string name_;
  SurfaceMesh mesh_;
  MeshTopology topology_;
  MembraneMechanics mechanics_;
  MembraneMaterial material_;
  std::vector<char> fixed_;
  MembraneCoefficients now_;
  double vertex_area0_scale_ = 1.0;
  Index dof_offset_ = 0;
  std::optional<RemeshSettings> remeshing_;
  RemeshStats remesh_totals_;
  MeshGeometry cache_;
  std::uint64_t cache_version_ = 0;
  bool cache_valid_ = false;
};

// Volume of the sphere with area A: the denominator of the reduced volume.
double sphereVolumeOfArea(double area);

}  // namespace cortex
