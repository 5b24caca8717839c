// Better triangles for a soup lying on an implicit surface, connectivity unchanged: raw
// marching tetrahedra has minimum angles near 0°, too poor to simulate.
#pragma once

#include <cstddef>

#include "mesh/implicit_shapes.hpp"
#include "mesh/triangle_soup.hpp"

namespace cortex {

// `iterations` Jacobi sweeps (results independent of vertex order) moving every vertex to
// the area-weighted centroid of its 1-ring, tangentially, then back onto the surface.
// `edge` is the typical edge length; rings of negligible area against it leave their
// vertex in place, as do moves that would leave a non-finite point.
void smoothOnSurface(TriangleSoup& soup, const ImplicitSurface& surface, double edge,
                     int iterations);

// Triangles facing against the function's gradient: where the shape is thinner than
// the grid resolves, one triangle can join both sheets and projection turns it over.
std::size_t countInvertedTriangles(const TriangleSoup& soup, const ImplicitSurface& surface);

}  // namespace cortex
