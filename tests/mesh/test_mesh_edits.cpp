// Local edits of the half-edge mesh keep every connectivity invariant, on closed and open
// meshes, including in long random sequences.
#include <gtest/gtest.h>

#include <random>

#include "test_meshes.hpp"

namespace cortex {
namespace {

Index liveVertices(const SurfaceMesh& m) {
  Index n = 0;
  for (Index v = 0; v < m.numVertices(); ++v) n += !m.isDeletedVertex(v);
  return n;
}

TEST(MeshEdits, SplitKeepsAClosedMeshValid) {
  SurfaceMesh m = testing::sphereMesh(10.0, 1);
  const Index v0 = m.numVertices(), f0 = m.numFaces();
  const Index h = 0;
  const Vec3 mid = 0.5 * (m.positions()[m.tail(h)] + m.positions()[m.tip(h)]);
  const Index v = m.split(h, mid);
  EXPECT_NO_THROW(m.validate());
  EXPECT_EQ(m.numVertices(), v0 + 1);
  EXPECT_EQ(m.numFaces(), f0 + 2);
  EXPECT_EQ(m.valence(v), 4);
  EXPECT_EQ(m.eulerCharacteristic(), 2);
}

TEST(MeshEdits, SplitOnABoundaryMakesABoundaryVertex) {
  SurfaceMesh m = testing::patchMesh(100.0, 20.0);
  Index h = 0;
  while (!m.isBoundaryHalfedge(h)) ++h;
  const Index v = m.split(h, 0.5 * (m.positions()[m.tail(h)] + m.positions()[m.tip(h)]));
  EXPECT_NO_THROW(m.validate());
  EXPECT_TRUE(m.isBoundaryVertex(v));
  EXPECT_EQ(m.valence(v), 3);
  EXPECT_EQ(m.eulerCharacteristic(), 1);
}

TEST(MeshEdits, CollapseRemovesOneVertexTwoFacesAndThreeEdges) {
  SurfaceMesh m = testing::sphereMesh(10.0, 2);
  const Index v0 = m.numVertices(), f0 = m.numFaces(), e0 = m.numEdges();
  Index h = 0;
  while (!m.isCollapsible(h)) ++h;
  ASSERT_TRUE(m.collapse(h));
  const std::vector<Index> map = m.garbageCollect();
  EXPECT_NO_THROW(m.validate());
  EXPECT_EQ(m.numVertices(), v0 - 1);
  EXPECT_EQ(m.numFaces(), f0 - 2);
  EXPECT_EQ(m.numEdges(), e0 - 3);
  EXPECT_EQ(m.eulerCharacteristic(), 2);
  EXPECT_EQ(std::count(map.begin(), map.end(), kNone), 1);
}

TEST(MeshEdits, CollapseRefusesBoundaryTailsAndBrokenLinks) {
  SurfaceMesh m = testing::patchMesh(100.0, 20.0);
  for (Index h = 0; h < m.numHalfedges(); ++h)
    if (m.isBoundaryVertex(m.tail(h))) {
      EXPECT_FALSE(m.isCollapsible(h));
    }
  // A tetrahedron cannot lose a vertex and stay a closed surface.
  TriangleSoup tet{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
  SurfaceMesh t = SurfaceMesh::fromSoup(tet, "tet");
  for (Index h = 0; h < t.numHalfedges(); ++h) EXPECT_FALSE(t.collapse(h));
}

// Thousands of random flips, splits and collapses: the mesh stays a valid closed (or
// open) 2-manifold with unchanged Euler characteristic.
TEST(MeshEdits, RandomEditSequencesKeepInvariants) {
  for (bool closed : {true, false}) {
    SurfaceMesh m = closed ? testing::sphereMesh(10.0, 2) : testing::patchMesh(100.0, 15.0);
    const Index chi = m.eulerCharacteristic();
    std::mt19937 rng(closed ? 3 : 4);
    for (int step = 0; step < 3000; ++step) {
      std::uniform_int_distribution<Index> pick(0, m.numHalfedges() - 1);
      Index h = pick(rng);
      if (m.isDeletedHalfedge(h)) continue;
      switch (step % 3) {
        case 0: m.flip(h); break;
        case 1:
          if (liveVertices(m) < 400)
            m.split(h, 0.5 * (m.positions()[m.tail(h)] + m.positions()[m.tip(h)]));
          break;
        default: m.collapse(h);
      }
      if (m.hasGarbage()) m.garbageCollect();
      ASSERT_NO_THROW(m.validate()) << "step " << step;
      ASSERT_EQ(m.eulerCharacteristic(), chi) << "step " << step;
    }
    m.garbageCollect();
    EXPECT_NO_THROW(m.validate());
    EXPECT_EQ(m.eulerCharacteristic(), chi);
    EXPECT_EQ(m.isClosed(), closed);
  }
}

}  // namespace
}  // namespace cortex
