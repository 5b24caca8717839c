#include "mesh/geometry.hpp"

#include "core/parallel.hpp"

namespace cortex {

namespace {

double faceArea(const double* x, const Tri& t) {
  return 0.5 * (vertexAt(x, t[1]) - vertexAt(x, t[0])).cross(vertexAt(x, t[2]) - vertexAt(x, t[0])).norm();
}

}  // namespace

double totalArea(const MeshTopology& topo, const double* x) {
  return deterministicSum(topo.numFaces(), [&](Index f) { return faceArea(x, topo.triangles[f]); });
}

// 1/6 sum (a-p).((b-p)x(c-p)) with p the first vertex: the reference point keeps the sum
// well conditioned far from the origin.
double signedVolume(const MeshTopology& topo, const double* x) {
  const Vec3 p = vertexAt(x, 0);
  return deterministicSum(topo.numFaces(),
                          [&](Index f) {
                            const Tri& t = topo.triangles[f];
                            const Vec3 a = vertexAt(x, t[0]) - p, b = vertexAt(x, t[1]) - p, c = vertexAt(x, t[2]) - p;
                            return a.dot(b.cross(c));
                          }) /
         6.0;
}

void MeshGeometry::compute(const MeshTopology& topo, const double* x) {
  const Index nf = topo.numFaces();
  const Index nv = topo.numVertices();
  face_unit_normal.resize(nf);
  face_area.resize(nf);
  vertex_area.resize(nv);
  area_gradient.resize(nv);
  volume_gradient.resize(nv);

  parallelFor(nf, [&](Index f) {
    const Tri& t = topo.triangles[f];
    const Vec3 n = (vertexAt(x, t[1]) - vertexAt(x, t[0])).cross(vertexAt(x, t[2]) - vertexAt(x, t[0]));
    const double len = n.norm();
    face_area[f] = 0.5 * len;
    face_unit_normal[f] = n / len;
  });

  parallelFor(nv, [&](Index v) {
    double a = 0.0;
    Vec3 ga = Vec3::Zero(), gv = Vec3::Zero();
    for (Index c = topo.corner_offsets[v]; c < topo.corner_offsets[v + 1]; ++c) {
      const Index f = topo.corner_ids[c] / 3;
      const int k = topo.corner_ids[c] % 3;
      const Tri& t = topo.triangles[f];
      const Vec3 opposite = vertexAt(x, t[(k + 2) % 3]) - vertexAt(x, t[(k + 1) % 3]);
      a += face_area[f];
      ga += face_unit_normal[f].cross(opposite);
      gv += face_area[f] * face_unit_normal[f];
    }
    vertex_area[v] = a / 3.0;
    area_gradient[v] = 0.5 * ga;
    volume_gradient[v] = gv / 3.0;  // 1/6 sum n_t = 1/3 sum A_t n̂_t
  });

  area = deterministicSum(nf, [&](Index f) { return face_area[f]; });
  volume = signedVolume(topo, x);
}

}  // namespace cortex
