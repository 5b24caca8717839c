// Integer copies (proteins on the membrane) riding the lipid through mesh edits.
//
// A copy lives on a vertex, which stands for its dual cell (a third of the area of the
// triangles around it). An edit (split, collapse, flip, relocation) re-partitions the
// surface near it: some cells shrink, others grow or appear, the lipid stays where it
// was. The carrier moves copies the way the lipid went, within the edit's stencil: each
// copy of a cell that shrank from A to A' leaves with probability (A - A')/A, and the
// leavers settle in the cells that grew, each with probability proportional to its
// growth. A density uniform per unit area stays uniform in expectation, and copies spread
// by the multinomial thinning of a Poisson field stay Poisson; totals are exact.
// Leaving the copies in place instead (or a fixed share rule) piles them up where the
// remesher refines: a split's new cell is a third of its neighbours' size.
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "core/random.hpp"
#include "mesh/dual_cells.hpp"
#include "mesh/surface_mesh.hpp"

namespace cortex {

struct FaceArea {
  Tri vertices;
  double area;  // nm^2
};

class CopyCarrier {
 public:
  // Copies of each species per vertex, all of the mesh's vertex count. An empty list, or
  // no copies at all, makes the carrier inactive (every call returns at once).
  CopyCarrier(std::vector<std::vector<int>*> counts, RandomStream random);
  // A carrier with streamKeyedByState's stream; measures the cells if there are copies.
  static CopyCarrier keyedByState(const SurfaceMesh& mesh, std::vector<std::vector<int>*> counts);

  bool active() const { return active_; }
  // Re-reads every cell's area from the mesh (after compaction or a batch of moves).
  void measure(const SurfaceMesh& mesh);
  // A vertex was appended (its count arrays too, with 0 copies): its cell starts empty.
  void addVertex();
  // An edit replaced the triangles `removed` (with their areas before it) by `added`
  // (areas after it): updates the cell areas and moves copies between the cells whose
  // area changed. A cell reduced to nothing (a collapsed vertex) gives all its copies.
  void replaced(std::span<const FaceArea> removed, std::span<const FaceArea> added);

 private:
  std::vector<std::vector<int>*> counts_;
  RandomStream random_;
  bool active_ = false;
  std::vector<double> cell_area_;
  struct Cell {
    Index vertex;
    double before, after;  // area, nm^2
  };
  std::vector<Cell> cells_;                            // of the edit at hand
  std::vector<std::pair<Index, double>> receivers_;    // vertex, weight
};

// A random stream (StreamId::kCopyTransport) keyed by the mesh's positions and the copies
// as they are now: a pure function of the run's state, so runs and resumed runs draw the
// same numbers without a stream to checkpoint.
RandomStream streamKeyedByState(const SurfaceMesh& mesh, const std::vector<std::vector<int>*>& counts);

// The triangles around v as they are now, with their areas.
std::vector<FaceArea> facesAround(const SurfaceMesh& mesh, Index v);
// True if any of the arrays holds a copy.
bool anyCopies(const std::vector<std::vector<int>*>& counts);

}  // namespace cortex
