// Reading a run's snapshots back (through trajectory.h5, the index of the snapshot
// files) for end-to-end tests.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "app/cli_helpers.hpp"
#include "io/hdf5_file.hpp"

namespace cortex::cli_test {

struct Snapshot {
  std::string group;
  double time = 0.0;
  std::int64_t step = 0;
  std::vector<double> vertices;
  h5::Shape vertices_shape;
  std::vector<std::int32_t> triangles;
  h5::Shape triangles_shape;
  std::vector<double> mean_curvature;
  h5::Shape curvature_shape;
};

inline std::vector<Snapshot> readSnapshots(const fs::path& h5file, const std::string& membrane = "vesicle") {
  const h5::File f = h5::File::openReadOnly(h5file);
  std::vector<Snapshot> out;
  for (const std::string& name : f.children("/snapshots")) {
    Snapshot s;
    s.group = "/snapshots/" + name;
    s.time = f.attributeDouble(s.group, "time");
    s.step = f.attributeInt64(s.group, "step");
    const std::string m = s.group + "/membranes/" + membrane;
    s.vertices = f.readDoubles(m + "/vertices", &s.vertices_shape);
    s.triangles = f.readInt32(m + "/triangles", &s.triangles_shape);
    s.mean_curvature = f.readDoubles(m + "/mean_curvature", &s.curvature_shape);
    out.push_back(std::move(s));
  }
  return out;
}

// Area and enclosed (signed) volume of a snapshot's triangle mesh.
inline std::array<double, 2> areaAndVolume(const Snapshot& s) {
  double area = 0.0, volume = 0.0;
  auto p = [&](std::int32_t v) {
    return std::array<double, 3>{s.vertices[3 * v], s.vertices[3 * v + 1], s.vertices[3 * v + 2]};
  };
  for (std::size_t t = 0; t + 2 < s.triangles.size(); t += 3) {
    const auto a = p(s.triangles[t]), b = p(s.triangles[t + 1]), c = p(s.triangles[t + 2]);
    const std::array<double, 3> u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const std::array<double, 3> n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    // a . (b x c) / 6
    volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
               a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0;
  }
  return {area, volume};
}

}  // namespace cortex::cli_test
