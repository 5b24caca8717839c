// Filament grids in the XDMF index and the filament datasets TrajectoryWriter writes,
// including empty ones and the description a resumed writer rebuilds from the file.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/hdf5_file.hpp"
#include "io/trajectory_writer.hpp"
#include "io/xdmf.hpp"
#include "test_text.hpp"

namespace cortex {
namespace {

namespace fs = std::filesystem;
using testing::countOccurrences;

TEST(XdmfFilaments, GridsWithElementsOnly) {
  XdmfSnapshot s{3, 0.5, {}, XdmfFilaments{12, 9, 0, 4, 0}, std::nullopt};
  const std::string xml = trajectoryXdmf({s});
  EXPECT_NE(xml.find(R"(<Grid Name="filaments" GridType="Collection" CollectionType="Temporal">)"), std::string::npos);
  EXPECT_NE(xml.find(R"(<Grid Name="filaments" GridType="Uniform">)"), std::string::npos);
  EXPECT_NE(xml.find(R"(NodesPerElement="2" NumberOfElements="9")"), std::string::npos);
  EXPECT_NE(xml.find(R"(Dimensions="9 2">snapshots/000003.h5:/filaments/cylinders<)"), std::string::npos);
  EXPECT_NE(xml.find(R"(Dimensions="12 3">snapshots/000003.h5:/filaments/beads<)"), std::string::npos);
  EXPECT_EQ(xml.find("Name=\"linkers\""), std::string::npos);  // none bound: no empty grid
  // Motor ends: the (4,2,3) dataset read as 8 points.
  EXPECT_NE(xml.find(R"(Dimensions="8 3">snapshots/000003.h5:/filaments/motors<)"), std::string::npos);
  EXPECT_NE(xml.find(R"(Dimensions="4 2">snapshots/000003.h5:/filaments/motor_cells<)"), std::string::npos);

  EXPECT_EQ(xml.find("branch_points"), std::string::npos);

  const std::string empty = trajectoryXdmf({XdmfSnapshot{0, 0.0, {}, XdmfFilaments{}, std::nullopt}});
  EXPECT_EQ(empty.find("filaments/"), std::string::npos);
  EXPECT_EQ(countOccurrences(empty, "<Grid "), 1u);  // the run's collection: no object has elements
}

TEST(XdmfFilaments, WriterWritesEmptyDatasetsAndRebuildsOnResume) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("cortex_xdmf_filaments_{}", ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  Frame empty;
  empty.filaments = FilamentFrame{};
  Frame full;
  full.time = 0.25;
  full.step = 5;
  FilamentFrame& f = full.filaments.emplace();
  f.beads = {0, 0, 0, 10, 0, 0, 20, 0, 0, 0, 5, 0, 0, 15, 0};
  f.offsets = {0, 3, 5};
  f.ids = {0, 1};
  f.types = {0, 0};
  f.lengths = {20.0, 10.0};
  f.monomers = {8, 4};
  f.cylinders = {0, 1, 1, 2, 3, 4};
  f.cylinder_filament = {0, 0, 1};
  f.linkers = {5, 0, 0, 0, 10, 0};
  f.linker_types = {0};
  f.linker_tensions = {1.5};
  {
    TrajectoryWriter writer(dir, 0, false, "run", "");
    writer.write(empty);
    writer.write(full);
  }
  {
    const h5::File file = h5::File::openReadOnly(dir / "trajectory.h5");
    EXPECT_EQ(file.shape("/snapshots/000000/filaments/beads"), (h5::Shape{0, 3}));
    EXPECT_EQ(file.shape("/snapshots/000000/filaments/offsets"), (h5::Shape{1}));
    EXPECT_EQ(file.shape("/snapshots/000000/filaments/linkers"), (h5::Shape{0, 2, 3}));
    EXPECT_EQ(file.shape("/snapshots/000000/filaments/branch_points"), (h5::Shape{0, 3}));
    EXPECT_EQ(file.readInt64("/snapshots/000000/filaments/offsets"), (std::vector<std::int64_t>{0}));
    EXPECT_EQ(file.shape("/snapshots/000001/filaments/beads"), (h5::Shape{5, 3}));
    EXPECT_EQ(file.shape("/snapshots/000001/filaments/cylinders"), (h5::Shape{3, 2}));
    EXPECT_EQ(file.shape("/snapshots/000001/filaments/linkers"), (h5::Shape{1, 2, 3}));
    EXPECT_EQ(file.readInt32("/snapshots/000001/filaments/linker_cells"), (std::vector<std::int32_t>{0, 1}));
    EXPECT_EQ(file.readDoubles("/snapshots/000001/filaments/linkers"), f.linkers);
  }
  std::string before;
  {
    std::ifstream in(dir / "trajectory.xdmf");
    std::stringstream text;
    text << in.rdbuf();
    before = text.str();
  }
  EXPECT_NE(before.find("Name=\"linkers\""), std::string::npos);
  {
    TrajectoryWriter resumed(dir, 2, true, "run", "");  // keeps both snapshots, describes them from the file
  }
  std::ifstream in(dir / "trajectory.xdmf");
  std::stringstream after;
  after << in.rdbuf();
  EXPECT_EQ(after.str(), before);
  fs::remove_all(dir);
}

// A frame whose arrays disagree is a bug upstream, reported rather than written.
TEST(XdmfFilaments, InconsistentFrameIsRejected) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("cortex_xdmf_filaments_bad_{}", ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  Frame frame;
  FilamentFrame& f = frame.filaments.emplace();
  f.beads = {0, 0, 0, 1, 0, 0};
  f.offsets = {0, 3};  // claims three beads
  f.ids = {0};
  f.types = {0};
  f.lengths = {1.0};
  f.monomers = {1};
  f.cylinders = {0, 1};
  f.cylinder_filament = {0};
  TrajectoryWriter writer(dir, 0, false, "run", "");
  EXPECT_THROW(writer.write(frame), std::exception);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cortex
