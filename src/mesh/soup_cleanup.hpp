// Clean-up of triangle soups before the half-edge mesh is built from them: generators can
// leave coincident vertices, and files can list vertices no face uses.
#pragma once

#include "mesh/triangle_soup.hpp"

namespace cortex {

// Vertices no triangle uses are dropped; the others keep their relative order and the
// triangles are renumbered to match.
void dropUnreferencedVertices(TriangleSoup& soup);

// Merges vertices closer than tol (a sweep along x), then drops the triangles that
// collapsed and the vertices left unused. The lowest index of a merged group survives,
// so the result does not depend on the sweep order.
void weldCloseVertices(TriangleSoup& soup, double tol);

}  // namespace cortex
