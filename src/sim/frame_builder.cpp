#include "sim/frame_builder.hpp"

#include "membrane/curvature.hpp"

namespace cortex {
namespace {

void appendPoint(std::vector<double>& out, const Vec3& p) { out.insert(out.end(), {p.x(), p.y(), p.z()}); }

void appendBindings(const FilamentNetwork& net, BinderKind kind, std::vector<double>& ends,
                    std::vector<std::int32_t>& types, std::vector<double>& tensions) {
  for (const Binding& b : net.bound(kind)) {
    for (int e = 0; e < 2; ++e) appendPoint(ends, net.sitePosition(kind, b.type, b.filament[e], b.site[e]));
    types.push_back(static_cast<std::int32_t>(b.type));
    tensions.push_back(b.tension);
  }
}

FilamentFrame filamentFrame(const FilamentNetwork& net) {
  FilamentFrame ff;
  const auto& filaments = net.filaments();
  for (std::size_t i = 0; i < filaments.size(); ++i) {
    const Filament& f = filaments[i];
    const auto first = static_cast<std::int32_t>(ff.offsets.back());
    for (const Vec3& p : f.beads) appendPoint(ff.beads, p);
    for (Index c = 0; c < f.numCylinders(); ++c) {
      ff.cylinders.insert(ff.cylinders.end(), {first + c, first + c + 1});
      ff.cylinder_filament.push_back(static_cast<std::int32_t>(i));
    }
    ff.offsets.push_back(ff.offsets.back() + static_cast<std::int64_t>(f.beads.size()));
    ff.ids.push_back(static_cast<std::int64_t>(i));
    ff.types.push_back(static_cast<std::int32_t>(f.type));
    ff.lengths.push_back(f.length());
    ff.monomers.push_back(f.monomers());
  }
  appendBindings(net, BinderKind::kLinker, ff.linkers, ff.linker_types, ff.linker_tensions);
  appendBindings(net, BinderKind::kMotor, ff.motors, ff.motor_types, ff.motor_tensions);
  for (const Branch& b : net.branches()) appendPoint(ff.branch_points, filaments[b.daughter].beads.front());
  for (const FilamentType& t : net.config().types) ff.type_names.push_back(t.name);
  for (const LinkerType& t : net.config().linkers) ff.linker_type_names.push_back(t.name);
  for (const MotorType& t : net.config().motors) ff.motor_type_names.push_back(t.name);
  return ff;
}

}  // namespace

Frame makeFrame(System& system) {
  Frame frame;
  frame.time = system.time();
  frame.step = system.step;
  for (const auto& m : system.membranes()) {
    MembraneFrame mf;
    mf.name = m->name();
    for (const Vec3& p : m->mesh().positions()) mf.vertices.insert(mf.vertices.end(), {p.x(), p.y(), p.z()});
    for (const Tri& t : m->topology().triangles) mf.triangles.insert(mf.triangles.end(), t.begin(), t.end());
    mf.mean_curvature = vertexMeanCurvature(m->currentGeometry(), m->topology(), m->mechanics().bending.estimator);
    for (std::size_t s = 0; s < m->speciesNames().size(); ++s)
      mf.species.push_back({m->speciesNames()[s], {m->speciesCopies()[s].begin(), m->speciesCopies()[s].end()}});
    frame.membranes.push_back(std::move(mf));
  }
  if (const ChemistryEngine* chem = system.chemistry()) {
    const CompartmentGrid& g = system.grid();
    frame.grid_shape = {g.shape[0], g.shape[1], g.shape[2]};
    frame.grid_spacing = g.size;
    for (Index s = 0; s < static_cast<Index>(system.chemistryModel().species.size()); ++s) {
      if (system.chemistryModel().species[s].surface >= 0) continue;  // on a membrane's vertices
      SpeciesField field{system.chemistryModel().species[s].name, {}};
      field.copies.reserve(g.count());
      // C order over (x, y, z): z varies fastest, unlike the engine's x-fastest index.
      for (int i = 0; i < g.shape[0]; ++i)
        for (int j = 0; j < g.shape[1]; ++j)
          for (int k = 0; k < g.shape[2]; ++k) field.copies.push_back(chem->copies(g.index(i, j, k), s));
      frame.compartment_species.push_back(std::move(field));
    }
  }
  if (const FilamentNetwork* net = system.filaments()) frame.filaments = filamentFrame(*net);
  if (!system.couplingTerms().empty()) {
    // Where bodies push on each other: the contact terms' forces on every point.
    const Eigen::VectorXd force = system.forceField().contactForces(system.coordinates());
    const auto slice = [&](const Body& body) {
      const double* begin = force.data() + 3 * body.offset();
      return std::vector<double>(begin, begin + 3 * body.numPoints());
    };
    for (std::size_t i = 0; i < frame.membranes.size(); ++i)
      frame.membranes[i].contact_force = slice(*system.membranes()[i]);
    if (frame.filaments) frame.filaments->contact_force = slice(*system.filaments());
  }
  return frame;
}

}  // namespace cortex
