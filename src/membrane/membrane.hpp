// One membrane: its mesh (a Body: its vertices are coordinates of the minimizer), the
// parameters of its energy terms (possibly scheduled in time), the material reference
// state, and the geometry cache its energy terms share.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/schedule.hpp"
#include "mech/body.hpp"
#include "mech/energy_term.hpp"
#include "membrane/curvature.hpp"
#include "mesh/geometry.hpp"
#include "mesh/mesh_topology.hpp"
#include "membrane/protein_coat.hpp"
#include "mesh/remesh.hpp"
#include "mesh/surface_mesh.hpp"

namespace cortex {

// Helfrich bending (bending_energy.hpp).
struct BendingParameters {
  Schedule modulus{0.0};                // κ, pN·nm
  Schedule spontaneous_curvature{0.0};  // H0, 1/nm
  CurvatureEstimator estimator = CurvatureEstimator::kSigned;
};

// kExact: the total area is held at the target exactly (a constraint of the relaxation,
// its multiplier the tension); kGlobal, kPerVertex: the penalty terms of area_energy.hpp.
enum class AreaModel { kExact, kGlobal, kPerVertex, kNone };

// Area elasticity (area_energy.hpp); its reference area is the membrane's target area.
struct AreaParameters {
  AreaModel model = AreaModel::kGlobal;
  Schedule modulus{0.0};  // pN/nm
};

// Surface tension (area_energy.hpp).
struct TensionParameters {
  Schedule tension{0.0};  // pN/nm
};

// The enclosed volume (closed membranes only): held at its target exactly (a constraint
// of the relaxation, its multiplier the pressure difference), or the osmotic penalty
// term of volume_energy.hpp with a modulus.
struct VolumeParameters {
  bool exact = false;
  Schedule modulus{0.0};  // pN/nm^2 (penalty)
  Schedule target_volume; // nm^3; default: reduced_volume, else the initial volume
  Schedule reduced_volume;
  bool isSet() const { return exact || !modulus.isZero() || target_volume.isSet() || reduced_volume.isSet(); }
};

// Mesh regularization (regularization_energy.hpp), a numerical term.
struct RegularizationParameters {
  Schedule strength{0.0};  // pN·nm per triangle
};

// The parameters of every term a membrane can have (membrane_terms.cpp lists the terms).
struct MembraneMechanics {
  BendingParameters bending;
  AreaParameters area;
  TensionParameters tension;
  VolumeParameters volume;
  RegularizationParameters regularization;
  // The membrane's amount of lipid, nm^2 (default: its initial area): the area terms'
  // reference and the area whose sphere the reduced volume refers to.
  Schedule target_area;
};

// What the latest relaxation found, beyond the shape: the Lagrange multipliers of exact
// constraints as physical quantities (NaN without the constraint), and the strain the
// shape accumulated since the mesh was last remeshed (the relaxation's remeshing policy).
struct MembraneEquilibrium {
  double tension = std::numeric_limits<double>::quiet_NaN();   // pN/nm, of the exact area
  double pressure = std::numeric_limits<double>::quiet_NaN();  // pN/nm^2, p_in - p_out, of the exact volume
  double strain_since_remesh = 0.0;
};

// The Sobolev metric the shape relaxation last factorized (shape_relaxation.cpp): the
// positions it was built at, its scale κ and shift ε, and the outer steps relaxed under
// it since. Kept from window to window and in checkpoints, so a resumed run factorizes
// the same metric, not one at its own positions; remeshing clears it.
struct RelaxationMetric {
  std::vector<double> positions;  // x, y, z per vertex, nm; empty: none factorized
  double kappa = 0.0;             // pN nm
  double shift = 0.0;             // 1/nm^2
  std::int64_t outer_steps = 0;
};

// Reference state fixed when the membrane is created (and restored from checkpoints).
struct MembraneMaterial {
  double initial_area = 0.0;
  double initial_volume = 0.0;
  std::vector<double> vertex_area0;  // per-vertex material areas (per_vertex area model)
};

class Membrane final : public Body {
 public:
  // Throws InputError (naming `where`) when volume parameters are given for an open mesh.
  Membrane(std::string name, SurfaceMesh mesh, MembraneMechanics mechanics, std::vector<char> fixed_vertices,
           const std::string& where = "");
  // Replaces the reference state measured at construction (used when resuming).
  void setMaterial(MembraneMaterial material) { material_ = std::move(material); }

  // Body: its vertices.
  const std::string& name() const override { return name_; }
  Index numPoints() const override { return mesh_.numVertices(); }
  void gather(double* x) const override;
  void scatter(const double* x) override;
  void frozen(char* mask) const override;

  const SurfaceMesh& mesh() const { return mesh_; }
  SurfaceMesh& mesh() { return mesh_; }
  const MeshTopology& topology() const { return topology_; }
  const MembraneMechanics& mechanics() const { return mechanics_; }
  const MembraneMaterial& material() const { return material_; }
  const std::vector<char>& fixedVertices() const { return fixed_; }
  bool isClosed() const { return mesh_.isClosed(); }

  // Target area (nm^2) at time t: target_area, else the initial area.
  double targetArea(double t) const {
    return mechanics_.target_area.isSet() ? mechanics_.target_area.at(t) : material_.initial_area;
  }
  // Target volume (nm^3) at time t: target_volume, else reduced_volume times the volume of
  // the sphere of the target area, else the initial volume.
  double targetVolume(double t) const;

  // InputError when, with the area held exactly, target_volume asks for more than the
  // sphere of the target area encloses.
  void checkVolumeTarget(const std::string& where) const;

  RelaxationMetric& relaxationMetric() { return relaxation_metric_; }
  const RelaxationMetric& relaxationMetric() const { return relaxation_metric_; }
  const MembraneEquilibrium& equilibrium() const { return equilibrium_; }
  void setEquilibrium(const MembraneEquilibrium& e) { equilibrium_ = e; }

  // Remeshes (remesh.hpp), carrying fixed flags, material areas and species copies
  // along, and accumulates the operation counts. Connectivity and vertex count change:
  // the caller must lay out the coordinates again (System::layOut).
  RemeshStats remesh(const RemeshSettings& settings);
  // The species copies ride the lipid's tangential flow (mesh/lipid_flow.hpp) through
  // the deformation between beginLipidFlow() and endLipidFlow() (one relaxation): the
  // cells' areas are recorded at the beginning, and at the end (and before every remesh
  // in between, which carries the copies itself) the copies move for the change. Nothing
  // to do without copies.
  void beginLipidFlow();
  void endLipidFlow();
  // Remeshing after every minimization, if set (config remesh = true).
  const std::optional<RemeshSettings>& remeshing() const { return remeshing_; }
  void setRemeshing(std::optional<RemeshSettings> settings) { remeshing_ = std::move(settings); }
  const RemeshStats& remeshTotals() const { return remesh_totals_; }
  // Changes whenever the connectivity does (every remesh): terms that keep lists of
  // triangles rebuild them.
  std::uint64_t connectivityVersion() const { return connectivity_version_; }
  void setRemeshTotals(const RemeshStats& totals) { remesh_totals_ = totals; }

  // Proteins living on the membrane (thesis chapter 3): copies per vertex of each species
  // (`names`, in the config's order), riding the lipid through remeshing. Throws
  // std::invalid_argument unless there is one non-negative count per vertex.
  void setSpecies(std::vector<std::string> names, std::vector<std::vector<int>> copies);
  const std::vector<std::string>& speciesNames() const { return species_names_; }
  // The species whose copies change the bending energy, if any (ProteinCoat).
  const std::optional<ProteinCoat>& coat() const { return coat_; }
  void setCoat(std::optional<ProteinCoat> coat) { coat_ = coat; }
  // The coat's mean coverage over its copies, Σ n_v φ_v / Σ n_v with φ_v = min(n_v a/A_v, 1)
  // at the current positions; NaN without a coat or copies. Copies stay on their vertices
  // while the relaxation moves them, so a relaxation that stretches coated cells thins
  // the coat (docs/proteins.md): this measures by how much.
  double coatCoverage() const;
  const std::vector<std::vector<int>>& speciesCopies() const { return species_copies_; }
  std::vector<int>& speciesCopies(Index species) { return species_copies_[species]; }

  // Geometry at the coordinates of `e`, recomputed only when e.version changes.
  const MeshGeometry& geometry(const Evaluation& e);
  // The geometry an evaluation of `version` computed, if it is still the cached one.
  const MeshGeometry* cachedGeometry(std::uint64_t version) const {
    return cache_valid_ && cache_version_ == version ? &cache_ : nullptr;
  }
  // Geometry at the mesh's own positions.
  MeshGeometry currentGeometry() const;

 private:
  std::string name_;
  SurfaceMesh mesh_;
  MeshTopology topology_;
  MembraneMechanics mechanics_;
  MembraneMaterial material_;
  std::vector<char> fixed_;
  std::optional<RemeshSettings> remeshing_;
  RemeshStats remesh_totals_;
  std::vector<std::string> species_names_;
  std::vector<std::vector<int>> species_copies_;  // [species][vertex]
  std::vector<double> lipid_area_before_;  // cell areas at beginLipidFlow (or the last remesh)
  std::vector<std::vector<int>*> speciesCountPointers();  // one per species, for the mesh's carriers
  std::optional<ProteinCoat> coat_;
  MembraneEquilibrium equilibrium_;
  RelaxationMetric relaxation_metric_;
  MeshGeometry cache_;
  std::uint64_t cache_version_ = 0;
  bool cache_valid_ = false;
  std::uint64_t connectivity_version_ = 0;
};

// Volume of the sphere with area A: the denominator of the reduced volume.
double sphereVolumeOfArea(double area);

}  // namespace cortex
