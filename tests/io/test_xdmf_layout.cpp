// The XDMF layout ParaView needs (issue 12): one temporal collection per object so each
// keeps one name at every time step, time steps without elements left out, branch points
// as vertices, and the compartments as cells of a structured grid whose corner points
// (compartments.h5) follow the species datasets' C order. The index's root attributes
// name the grid, the species and the types, also after a resume.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "io/hdf5_file.hpp"
#include "io/trajectory_writer.hpp"
#include "io/xdmf.hpp"
#include "test_text.hpp"

namespace cortex {
namespace {

namespace fs = std::filesystem;
using testing::countOccurrences;

// The text between the opening of object `name`'s temporal collection and its end.
std::string collection(const std::string& xml, const std::string& name) {
  const std::string open = fmt::format(R"(<Grid Name="{}" GridType="Collection" CollectionType="Temporal">)", name);
  const std::size_t begin = xml.find(open);
  if (begin == std::string::npos) return "";
  return xml.substr(begin, xml.find("\n      </Grid>", begin) - begin);
}

TEST(XdmfLayout, OneCollectionPerObjectWithItsStepsOnly) {
  const XdmfSnapshot first{0, 0.0, {{"cell", 10, 16, false, {}}}, XdmfFilaments{4, 3, 0, 0, 0}, std::nullopt};
  const XdmfSnapshot second{1, 0.5, {{"cell", 12, 20, false, {}}, {"nucleus", 6, 8, false, {}}}, XdmfFilaments{6, 4, 2, 0, 1},
                            XdmfCompartments{{2, 3, 4}, {"A", "B"}}};
  const XdmfSnapshot third{2, 1.0, {{"cell", 12, 20, false, {}}}, XdmfFilaments{6, 4, 0, 0, 1}, XdmfCompartments{{2, 3, 4}, {"A", "B"}}};
  const std::string xml = trajectoryXdmf({first, second, third});
  // Objects in a fixed order: membranes as they first appear, then the filament parts, then compartments.
  std::size_t last = 0;
  for (const char* name : {"cell", "nucleus", "filaments", "linkers", "branch_points", "compartments"}) {
    const std::size_t at = xml.find(fmt::format(R"(<Grid Name="{}" GridType="Collection")", name));
    ASSERT_NE(at, std::string::npos) << name;
    EXPECT_GT(at, last) << name;
    last = at;
  }
  EXPECT_EQ(xml.find(R"(Name="motors")"), std::string::npos);  // never any
  // Each uniform grid carries the object's own name and its time.
  const std::string cell = collection(xml, "cell");
  EXPECT_EQ(countOccurrences(cell, R"(<Grid Name="cell" GridType="Uniform">)"), 3u);
  EXPECT_EQ(countOccurrences(cell, "<Time "), 3u);
  EXPECT_EQ(countOccurrences(collection(xml, "nucleus"), "<Time "), 1u);
  const std::string linkers = collection(xml, "linkers");
  EXPECT_EQ(countOccurrences(linkers, "<Time "), 1u);  // steps without linkers left out
  EXPECT_NE(linkers.find(R"(<Time Value="0.5"/>)"), std::string::npos);
  const std::string branches = collection(xml, "branch_points");
  EXPECT_EQ(countOccurrences(branches, "<Time "), 2u);
  EXPECT_NE(branches.find(R"(TopologyType="Polyvertex" NodesPerElement="1" NumberOfElements="1")"), std::string::npos);
  EXPECT_NE(branches.find(R"(Dimensions="1 3">snapshots/000002.h5:/filaments/branch_points<)"), std::string::npos);
  // Compartments: a 3 x 4 x 5 point structured grid, one cell field per species.
  const std::string grid = collection(xml, "compartments");
  EXPECT_EQ(countOccurrences(grid, "<Time "), 2u);
  EXPECT_NE(grid.find(R"(<Topology TopologyType="3DSMesh" Dimensions="3 4 5"/>)"), std::string::npos);
  EXPECT_NE(grid.find(R"(Dimensions="60 3">compartments.h5:/points<)"), std::string::npos);
  EXPECT_NE(grid.find(R"(<Attribute Name="B" AttributeType="Scalar" Center="Cell">)"), std::string::npos);
  EXPECT_NE(grid.find(R"(Dimensions="2 3 4">snapshots/000001.h5:/compartments/species/A<)"), std::string::npos);
}

Frame gridFrame(double time) {
  Frame frame;
  frame.time = time;
  frame.grid_shape = {2, 1, 3};
  frame.grid_spacing = 250.0;
  frame.compartment_species = {{"A", {0, 1, 2, 3, 4, 5}}, {"B", {6, 7, 8, 9, 10, 11}}};
  FilamentFrame& f = frame.filaments.emplace();
  f.type_names = {"actin"};
  f.linker_type_names = {"alpha-actinin", "fascin"};
  f.motor_type_names = {"myosin"};
  return frame;
}

TEST(XdmfLayout, ContactForcesArePointVectorsWhereASnapshotHasThem) {
  // A run where membranes and filaments interact writes contact_force for the membrane
  // and the beads; an older snapshot (a resume across versions) has none, and its grids
  // must not point at datasets that are not there.
  const XdmfSnapshot without{0, 0.0, {{"cell", 10, 16, false, {}}}, XdmfFilaments{4, 3, 0, 0, 0}, std::nullopt};
  const XdmfSnapshot with{1, 0.5, {{"cell", 12, 20, true, {}}}, XdmfFilaments{6, 4, 0, 0, 0, true}, std::nullopt};
  const std::string xml = trajectoryXdmf({without, with});
  const std::string cell = collection(xml, "cell");
  EXPECT_EQ(countOccurrences(cell, R"(<Attribute Name="contact_force" AttributeType="Vector" Center="Node">)"), 1u);
  EXPECT_NE(cell.find(R"(Dimensions="12 3">snapshots/000001.h5:/membranes/cell/contact_force<)"), std::string::npos);
  const std::string filaments = collection(xml, "filaments");
  EXPECT_EQ(countOccurrences(filaments, R"(<Attribute Name="contact_force" AttributeType="Vector" Center="Node">)"), 1u);
  EXPECT_NE(filaments.find(R"(Dimensions="6 3">snapshots/000001.h5:/filaments/contact_force<)"), std::string::npos);
}

TEST(XdmfLayout, CompartmentPointsAndIndexAttributesSurviveAResume) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("cortex_xdmf_layout_{}", ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto expectAttributes = [&] {
    const h5::File index = h5::File::openReadOnly(dir / "trajectory.h5");
    EXPECT_EQ(index.attributeDouble("/", "compartment_size"), 250.0);
    EXPECT_EQ(index.attributeString("/", "species"), "A,B");
    EXPECT_EQ(index.attributeString("/", "filament_types"), "actin");
    EXPECT_EQ(index.attributeString("/", "linker_types"), "alpha-actinin,fascin");
    EXPECT_EQ(index.attributeString("/", "motor_types"), "myosin");
  };
  {
    TrajectoryWriter writer(dir, 0, false, "run", "");
    writer.write(gridFrame(0.0));
    writer.write(gridFrame(0.5));
  }
  expectAttributes();
  // Corner (i, j, k) at 250 (i, j, k) nm, k fastest, as the (2, 1, 3) species data.
  const h5::File points = h5::File::openReadOnly(dir / kCompartmentPointsFile);
  h5::Shape shape;
  const std::vector<double> p = points.readDoubles("/points", &shape);
  ASSERT_EQ(shape, (h5::Shape{3 * 2 * 4, 3}));
  std::size_t row = 0;
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 1; ++j)
      for (int k = 0; k <= 3; ++k, ++row) {
        EXPECT_EQ(p[3 * row], 250.0 * i);
        EXPECT_EQ(p[3 * row + 1], 250.0 * j);
        EXPECT_EQ(p[3 * row + 2], 250.0 * k);
      }
  { TrajectoryWriter resumed(dir, 2, true, "run", ""); }  // rebuilds the index from the files
  expectAttributes();
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cortex
