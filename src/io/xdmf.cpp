#include "io/xdmf.hpp"

#include <fmt/format.h>

#include <array>
#include <iterator>

namespace cortex {
namespace {

// Membrane names come from the config, so they may hold characters XML reserves.
std::string escapeXml(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    switch (c) {
      case '&': escaped += "&amp;"; break;
      case '<': escaped += "&lt;"; break;
      case '>': escaped += "&gt;"; break;
      case '"': escaped += "&quot;"; break;
      case '\'': escaped += "&apos;"; break;
      default: escaped += c;
    }
  }
  return escaped;
}

void appendMembraneGrid(std::string& xml, const XdmfSnapshot& snapshot, const XdmfMembrane& membrane) {
  // Heavy data stays in the HDF5 files; each DataItem names "file:/dataset".
  const std::string data = escapeXml(fmt::format("{}:/membranes/{}", snapshotFile(snapshot.index), membrane.name));
  const std::int64_t n = membrane.vertices;
  const std::int64_t m = membrane.triangles;
  fmt::format_to(std::back_inserter(xml),
                 R"(        <Grid Name="{name}" GridType="Uniform">
          <Topology TopologyType="Triangle" NumberOfElements="{m}">
            <DataItem Format="HDF" NumberType="Int" Precision="4" Dimensions="{m} 3">{data}/triangles</DataItem>
          </Topology>
          <Geometry GeometryType="XYZ">
            <DataItem Format="HDF" NumberType="Float" Precision="8" Dimensions="{n} 3">{data}/vertices</DataItem>
          </Geometry>
          <Attribute Name="mean_curvature" AttributeType="Scalar" Center="Node">
            <DataItem Format="HDF" NumberType="Float" Precision="8" Dimensions="{n}">{data}/mean_curvature</DataItem>
          </Attribute>
        </Grid>
)",
                 fmt::arg("name", escapeXml(membrane.name)), fmt::arg("m", m), fmt::arg("n", n),
                 fmt::arg("data", data));
}

// A grid of 2-node line segments: `cells` (n,2) indexes the rows of `points` (k,3). For linkers
// and motors, `points` is the (n,2,3) dataset of end positions read as (2n,3), which the
// C-order layout makes the ends of segment i rows 2i and 2i+1.
struct SegmentGrid {
  const char* name;
  std::int64_t segments, points;
  std::string cells, positions;  // dataset paths
  std::vector<std::array<std::string, 4>> cell_attributes;  // name, dataset, NumberType, Precision
};

void appendSegmentGrid(std::string& xml, const SegmentGrid& grid) {
  const std::int64_t m = grid.segments;
  fmt::format_to(std::back_inserter(xml),
                 R"(        <Grid Name="{name}" GridType="Uniform">
          <Topology TopologyType="Polyline" NodesPerElement="2" NumberOfElements="{m}">
            <DataItem Format="HDF" NumberType="Int" Precision="4" Dimensions="{m} 2">{cells}</DataItem>
          </Topology>
          <Geometry GeometryType="XYZ">
            <DataItem Format="HDF" NumberType="Float" Precision="8" Dimensions="{n} 3">{positions}</DataItem>
          </Geometry>
)",
                 fmt::arg("name", grid.name), fmt::arg("m", m), fmt::arg("n", grid.points),
                 fmt::arg("cells", grid.cells), fmt::arg("positions", grid.positions));
  for (const auto& [name, dataset, type, precision] : grid.cell_attributes) {
    fmt::format_to(std::back_inserter(xml),
                   R"(          <Attribute Name="{}" AttributeType="Scalar" Center="Cell">
            <DataItem Format="HDF" NumberType="{}" Precision="{}" Dimensions="{}">{}</DataItem>
          </Attribute>
)",
                   name, type, precision, m, dataset);
  }
  xml += "        </Grid>\n";
}

void appendFilamentGrids(std::string& xml, const XdmfSnapshot& snapshot, const XdmfFilaments& f) {
  const std::string data = escapeXml(fmt::format("{}:/filaments/", snapshotFile(snapshot.index)));
  if (f.cylinders > 0) {
    appendSegmentGrid(xml, {"filaments", f.cylinders, f.beads, data + "cylinders", data + "beads",
                            {{"filament", data + "cylinder_filament", "Int", "4"}}});
  }
  if (f.linkers > 0) {
    appendSegmentGrid(xml, {"linkers", f.linkers, 2 * f.linkers, data + "linker_cells", data + "linkers",
                            {{"type", data + "linker_types", "Int", "4"},
                             {"tension", data + "linker_tensions", "Float", "8"}}});
  }
  if (f.motors > 0) {
    appendSegmentGrid(xml, {"motors", f.motors, 2 * f.motors, data + "motor_cells", data + "motors",
                            {{"type", data + "motor_types", "Int", "4"},
                             {"tension", data + "motor_tensions", "Float", "8"}}});
  }
}

}  // namespace

std::string snapshotGroup(std::int64_t index) { return fmt::format("/snapshots/{:06d}", index); }
std::string snapshotFile(std::int64_t index) { return fmt::format("snapshots/{:06d}.h5", index); }

std::string trajectoryXdmf(const std::vector<XdmfSnapshot>& snapshots) {
  // Xdmf 2 rather than 3: ParaView's default XDMF reader handles it most reliably.
  std::string xml = R"(<?xml version="1.0" ?>
<!DOCTYPE Xdmf SYSTEM "Xdmf.dtd" []>
<Xdmf Version="2.0">
  <Domain>
    <Grid Name="trajectory" GridType="Collection" CollectionType="Temporal">
)";
  for (const XdmfSnapshot& snapshot : snapshots) {
    // "{}" prints the shortest text that reads back as the same double.
    fmt::format_to(std::back_inserter(xml),
                   "      <Grid Name=\"snapshot_{:06d}\" GridType=\"Collection\" "
                   "CollectionType=\"Spatial\">\n        <Time Value=\"{}\"/>\n",
                   snapshot.index, snapshot.time);
    for (const XdmfMembrane& membrane : snapshot.membranes) {
      appendMembraneGrid(xml, snapshot, membrane);
    }
    if (snapshot.filaments) appendFilamentGrids(xml, snapshot, *snapshot.filaments);
    xml += "      </Grid>\n";
  }
  xml += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return xml;
}

}  // namespace cortex
