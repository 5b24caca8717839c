// TrajectoryWriter, its XDMF index and the h5::File wrapper underneath, on real files.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5_file.hpp"
#include "io/trajectory_writer.hpp"
#include "io/xdmf.hpp"
#include "test_text.hpp"

namespace cortex {
namespace {

namespace fs = std::filesystem;
using testing::countOccurrences;

// A fresh directory per test, removed afterwards.
class TrajectoryWriterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           fmt::format("cortex_{}_{}_{}", test->test_suite_name(), test->name(), ::getpid());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string readXdmf() const {
    std::ifstream in(dir_ / "trajectory.xdmf");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  fs::path dir_;
};

MembraneFrame makeMembrane(const std::string& name, int n, int m, double offset) {
  MembraneFrame membrane;
  membrane.name = name;
  for (int i = 0; i < 3 * n; ++i) membrane.vertices.push_back(offset + 0.1 * i);
  for (int i = 0; i < 3 * m; ++i) membrane.triangles.push_back((7 * i) % n);
  for (int i = 0; i < n; ++i) membrane.mean_curvature.push_back(-offset / (i + 3.0));
  return membrane;
}

// Vertex counts change from frame to frame, as they do after remeshing.
Frame makeFrame(int k) {
  Frame frame;
  frame.time = (k + 1) / 3.0e3;  // not round in binary, so exactness is tested
  frame.step = 10 * k + 1;
  frame.membranes = {makeMembrane("cell", 4 + k, 2 + k, k + 0.5),
                     makeMembrane("nucleus", 6 + 2 * k, 5 + k, 100.0 + k)};
  return frame;
}

void expectSnapshot(const h5::File& file, std::int64_t index, const Frame& frame) {
  const std::string group = snapshotGroup(index);
  EXPECT_EQ(file.attributeDouble(group, "time"), frame.time);
  EXPECT_EQ(file.attributeInt64(group, "step"), frame.step);
  EXPECT_EQ(file.children(group + "/membranes"), (std::vector<std::string>{"cell", "nucleus"}));
  for (const MembraneFrame& membrane : frame.membranes) {
    const std::string path = group + "/membranes/" + membrane.name;
    const hsize_t n = membrane.mean_curvature.size();
    const hsize_t m = membrane.triangles.size() / 3;
    h5::Shape shape;
    EXPECT_EQ(file.readDoubles(path + "/vertices", &shape), membrane.vertices);
    EXPECT_EQ(shape, (h5::Shape{n, 3}));
    EXPECT_EQ(file.readInt32(path + "/triangles", &shape), membrane.triangles);
    EXPECT_EQ(shape, (h5::Shape{m, 3}));
    EXPECT_EQ(file.readDoubles(path + "/mean_curvature", &shape), membrane.mean_curvature);
    EXPECT_EQ(shape, (h5::Shape{n}));
  }
}

TEST_F(TrajectoryWriterTest, WritesEverySnapshotReadableBack) {
  TrajectoryWriter writer(dir_, 0, false, "run", "");
  for (int k = 0; k < 3; ++k) writer.write(makeFrame(k));
  EXPECT_EQ(writer.nextIndex(), 3);

  const h5::File file = h5::File::openReadOnly(dir_ / "trajectory.h5");
  EXPECT_EQ(file.children("/snapshots"),
            (std::vector<std::string>{"000000", "000001", "000002"}));
  for (int k = 0; k < 3; ++k) expectSnapshot(file, k, makeFrame(k));
}

TEST_F(TrajectoryWriterTest, XdmfListsEverySnapshotByRelativePath) {
  TrajectoryWriter writer(dir_, 0, false, "run", "");
  for (int k = 0; k < 3; ++k) writer.write(makeFrame(k));

  const std::string xml = readXdmf();
  EXPECT_NE(xml.find("<Xdmf Version=\"2.0\">"), std::string::npos);
  EXPECT_EQ(countOccurrences(xml, "<Grid "), 1u + 2 + 2 * 3);  // the run, a series per membrane, 3 snapshots each
  EXPECT_EQ(countOccurrences(xml, "<Grid "), countOccurrences(xml, "</Grid>"));
  for (int k = 0; k < 3; ++k) {
    const Frame frame = makeFrame(k);
    EXPECT_NE(xml.find(fmt::format("<Time Value=\"{}\"/>", frame.time)), std::string::npos);
    for (const MembraneFrame& membrane : frame.membranes) {
      const std::string data = fmt::format(">snapshots/{:06d}.h5:/membranes/{}/", k, membrane.name);
      const std::size_t n = membrane.mean_curvature.size();
      const std::size_t m = membrane.triangles.size() / 3;
      EXPECT_NE(xml.find(fmt::format("Dimensions=\"{} 3\"{}vertices<", n, data)), std::string::npos);
      EXPECT_NE(xml.find(fmt::format("Dimensions=\"{} 3\"{}triangles<", m, data)), std::string::npos);
      EXPECT_NE(xml.find(fmt::format("Dimensions=\"{}\"{}mean_curvature<", n, data)),
                std::string::npos);
    }
  }
  EXPECT_EQ(xml.find(dir_.string()), std::string::npos);  // the folder can be moved
  EXPECT_FALSE(fs::exists(dir_ / "trajectory.xdmf.tmp"));
}

TEST(Xdmf, EscapesNamesAndHandlesNoSnapshots) {
  const std::string xml = trajectoryXdmf({{7, 0.5, {{"a&b", 3, 1, false, {}}}, std::nullopt, std::nullopt}});
  EXPECT_NE(xml.find("Name=\"a&amp;b\""), std::string::npos);
  EXPECT_NE(xml.find(">snapshots/000007.h5:/membranes/a&amp;b/mean_curvature<"), std::string::npos);
  EXPECT_EQ(countOccurrences(trajectoryXdmf({}), "<Grid "), 1u);
}

TEST_F(TrajectoryWriterTest, AppendDropsSnapshotsFromFirstIndexAndContinues) {
  {
    TrajectoryWriter writer(dir_, 0, false, "run", "");
    for (int k = 0; k < 3; ++k) writer.write(makeFrame(k));
  }
  // What a crash can leave: a snapshot file not yet in the index, temporary files.
  fs::copy_file(dir_ / "snapshots/000002.h5", dir_ / "snapshots/000003.h5");
  std::ofstream(dir_ / "snapshots/000004.h5.tmp") << "torn";
  TrajectoryWriter resumed(dir_, 2, true, "run", "");
  EXPECT_FALSE(fs::exists(dir_ / "snapshots/000003.h5"));
  EXPECT_FALSE(fs::exists(dir_ / "snapshots/000004.h5.tmp"));
  EXPECT_EQ(resumed.nextIndex(), 2);
  {
    const h5::File file = h5::File::openReadOnly(dir_ / "trajectory.h5");
    EXPECT_EQ(file.children("/snapshots"), (std::vector<std::string>{"000000", "000001"}));
  }
  EXPECT_EQ(readXdmf().find("snapshot_000002"), std::string::npos);

  const Frame replacement = makeFrame(5);
  resumed.write(replacement);
  EXPECT_EQ(resumed.nextIndex(), 3);
  const h5::File file = h5::File::openReadOnly(dir_ / "trajectory.h5");
  expectSnapshot(file, 0, makeFrame(0));
  expectSnapshot(file, 1, makeFrame(1));
  expectSnapshot(file, 2, replacement);

  // The rebuilt XDMF still describes the retained snapshots with their own sizes.
  const std::string xml = readXdmf();
  EXPECT_EQ(countOccurrences(xml, "<Grid "), 1u + 2 + 2 * 3);
  EXPECT_NE(xml.find("Dimensions=\"5 3\">snapshots/000001.h5:/membranes/cell/vertices<"), std::string::npos);
  EXPECT_NE(xml.find("Dimensions=\"9 3\">snapshots/000002.h5:/membranes/cell/vertices<"), std::string::npos);
  EXPECT_EQ(trajectoryRunId(dir_), "run");
}

TEST_F(TrajectoryWriterTest, MissingFilesAreInputErrors) {
  EXPECT_THROW(h5::File::openReadOnly(dir_ / "missing.h5"), InputError);
  EXPECT_EQ(trajectoryRunId(dir_ / "missing"), "");
}

TEST_F(TrajectoryWriterTest, InconsistentFrameIsRunError) {
  TrajectoryWriter writer(dir_, 0, false, "run", "");
  Frame frame = makeFrame(0);
  frame.membranes[0].mean_curvature.pop_back();
  EXPECT_THROW(writer.write(frame), RunError);
}

TEST_F(TrajectoryWriterTest, FileRoundTripsTypesAndAttributes) {
  {
    h5::File file = h5::File::createInMemory(dir_ / "t.h5");
    file.write("/a/b/int64", std::vector<std::int64_t>{-1, 1LL << 40});
    file.write("/a/int8", std::vector<std::int8_t>{-128, 127}, {2, 1});
    file.write("/a/uint8", std::vector<std::uint8_t>{0, 255});
    file.write("/a/empty", std::vector<double>{}, {0, 3});
    file.write("/a/int8", std::vector<std::int8_t>{5});  // replaces the dataset
    file.setAttribute("/a", "label", std::string("membrane µ"));
    file.setAttribute("/a/b/int64", "count", std::int64_t{42});
    file.setAttribute("/a/b/int64", "count", std::int64_t{43});  // replaces the attribute
    file.createGroups("/x/y/z");
    file.remove("/x/y");
    EXPECT_THROW(file.write("/bad", std::vector<double>{1, 2, 3}, {2, 2}), RunError);
    writeFileAtomically(dir_ / "t.h5", file.image());
  }
  const h5::File file = h5::File::openReadOnly(dir_ / "t.h5");
  EXPECT_EQ(file.readInt64("/a/b/int64"), (std::vector<std::int64_t>{-1, 1LL << 40}));
  EXPECT_EQ(file.readInt8("/a/int8"), (std::vector<std::int8_t>{5}));
  EXPECT_EQ(file.readUInt8("/a/uint8"), (std::vector<std::uint8_t>{0, 255}));
  EXPECT_EQ(file.readDoubles("/a/b/int64"), (std::vector<double>{-1.0, 1099511627776.0}));
  h5::Shape shape;
  EXPECT_TRUE(file.readDoubles("/a/empty", &shape).empty());
  EXPECT_EQ(shape, (h5::Shape{0, 3}));
  EXPECT_EQ(file.attributeString("/a", "label"), "membrane µ");
  EXPECT_EQ(file.attributeInt64("/a/b/int64", "count"), 43);
  EXPECT_EQ(file.children("/a"), (std::vector<std::string>{"b", "empty", "int8", "uint8"}));
  EXPECT_TRUE(file.exists("/x"));
  EXPECT_FALSE(file.exists("/x/y/z"));
  EXPECT_FALSE(file.exists("/nowhere/deep/path"));
  EXPECT_THROW(file.readDoubles("/nowhere"), RunError);
  EXPECT_THROW(file.attributeDouble("/a", "nothing"), RunError);
}

}  // namespace
}  // namespace cortex
