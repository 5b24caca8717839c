#include "io/xdmf.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>

namespace cortex {
namespace {

// Membrane and species names come from the config, so they may hold characters XML reserves.
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

// The opening of one object's uniform grid at one time step.
void openGrid(std::string& xml, const std::string& name, double time) {
  // "{}" prints the shortest text that reads back as the same double.
  fmt::format_to(std::back_inserter(xml), "        <Grid Name=\"{}\" GridType=\"Uniform\">\n          <Time Value=\"{}\"/>\n",
                 escapeXml(name), time);
}

// A 3-vector per node (point), e.g. a force.
void appendNodeVector(std::string& xml, const char* name, std::int64_t nodes, const std::string& dataset) {
  fmt::format_to(std::back_inserter(xml),
                 R"(          <Attribute Name="{}" AttributeType="Vector" Center="Node">
            <DataItem Format="HDF" NumberType="Float" Precision="8" Dimensions="{} 3">{}</DataItem>
          </Attribute>
)",
                 name, nodes, dataset);
}

void appendMembraneGrid(std::string& xml, const XdmfSnapshot& snapshot, const XdmfMembrane& membrane) {
  // Heavy data stays in the HDF5 files; each DataItem names "file:/dataset".
  const std::string data = escapeXml(fmt::format("{}:/membranes/{}", snapshotFile(snapshot.index), membrane.name));
  openGrid(xml, membrane.name, snapshot.time);
  fmt::format_to(std::back_inserter(xml),
                 R"(          <Topology TopologyType="Triangle" NumberOfElements="{m}">
            <DataItem Format="HDF" NumberType="Int" Precision="4" Dimensions="{m} 3">{data}/triangles</DataItem>
          </Topology>
          <Geometry GeometryType="XYZ">
            <DataItem Format="HDF" NumberType="Float" Precision="8" Dimensions="{n} 3">{data}/vertices</DataItem>
          </Geometry>
          <Attribute Name="mean_curvature" AttributeType="Scalar" Center="Node">
            <DataItem Format="HDF" NumberType="Float" Precision="8" Dimensions="{n}">{data}/mean_curvature</DataItem>
          </Attribute>
)",
                 fmt::arg("m", membrane.triangles), fmt::arg("n", membrane.vertices), fmt::arg("data", data));
  if (membrane.contact_force) appendNodeVector(xml, "contact_force", membrane.vertices, data + "/contact_force");
  // Copies of each membrane species per vertex (ParaView shows them as point data).
  for (const std::string& species : membrane.species)
    fmt::format_to(std::back_inserter(xml),
                   R"(          <Attribute Name="{name}" AttributeType="Scalar" Center="Node">
            <DataItem Format="HDF" NumberType="Int" Precision="4" Dimensions="{n}">{data}/species/{name}</DataItem>
          </Attribute>
)",
                   fmt::arg("name", escapeXml(species)), fmt::arg("n", membrane.vertices), fmt::arg("data", data));
  xml += "        </Grid>\n";
}

// A grid of 2-node line segments: `cells` (n,2) indexes the rows of `points` (k,3). For linkers
// and motors, `points` is the (n,2,3) dataset of end positions read as (2n,3), which the
// C-order layout makes the ends of segment i rows 2i and 2i+1.
struct SegmentGrid {
  std::int64_t segments, points;
  std::string cells, positions;  // dataset paths
  std::vector<std::array<std::string, 4>> cell_attributes;  // name, dataset, NumberType, Precision
  std::vector<std::array<std::string, 2>> node_vectors;     // name, dataset of (points, 3) floats
};

void appendSegmentGrid(std::string& xml, const SegmentGrid& grid) {
  const std::int64_t m = grid.segments;
  fmt::format_to(std::back_inserter(xml),
                 R"(          <Topology TopologyType="Polyline" NodesPerElement="2" NumberOfElements="{m}">
            <DataItem Format="HDF" NumberType="Int" Precision="4" Dimensions="{m} 2">{cells}</DataItem>
          </Topology>
          <Geometry GeometryType="XYZ">
            <DataItem Format="HDF" NumberType="Float" Precision="8" Dimensions="{n} 3">{positions}</DataItem>
          </Geometry>
)",
                 fmt::arg("m", m), fmt::arg("n", grid.points), fmt::arg("cells", grid.cells),
                 fmt::arg("positions", grid.positions));
  for (const auto& [name, dataset, type, precision] : grid.cell_attributes) {
    fmt::format_to(std::back_inserter(xml),
                   R"(        <Attribute Name="{}" AttributeType="Scalar" Center="Cell">
            <DataItem Format="HDF" NumberType="{}" Precision="{}" Dimensions="{}">{}</DataItem>
          </Attribute>
)",
                   name, type, precision, m, dataset);
  }
  for (const auto& [name, dataset] : grid.node_vectors) appendNodeVector(xml, name.c_str(), grid.points, dataset);
  xml += "        </Grid>\n";
}

// The filament objects, in the order they appear in the document.
enum class FilamentPart { kCylinders, kLinkers, kMotors, kBranchPoints };
constexpr std::array<std::pair<FilamentPart, const char*>, 4> kFilamentParts{{{FilamentPart::kCylinders, "filaments"},
                                                                             {FilamentPart::kLinkers, "linkers"},
                                                                             {FilamentPart::kMotors, "motors"},
                                                                             {FilamentPart::kBranchPoints, "branch_points"}}};

std::int64_t elements(const XdmfFilaments& f, FilamentPart part) {
  switch (part) {
    case FilamentPart::kCylinders: return f.cylinders;
    case FilamentPart::kLinkers: return f.linkers;
    case FilamentPart::kMotors: return f.motors;
    case FilamentPart::kBranchPoints: return f.branch_points;
  }
  return 0;
}

void appendFilamentGrid(std::string& xml, const XdmfSnapshot& snapshot, FilamentPart part, const char* name) {
  const XdmfFilaments& f = *snapshot.filaments;
  const std::string data = escapeXml(fmt::format("{}:/filaments/", snapshotFile(snapshot.index)));
  openGrid(xml, name, snapshot.time);
  const auto binders = [&](const char* kind, std::int64_t n) {
    appendSegmentGrid(xml, {n, 2 * n, data + kind + "_cells", data + kind + "s",
                            {{"type", data + kind + "_types", "Int", "4"},
                             {"tension", data + kind + "_tensions", "Float", "8"}},
                            {}});
  };
  switch (part) {
    case FilamentPart::kCylinders:
      appendSegmentGrid(xml, {f.cylinders, f.beads, data + "cylinders", data + "beads",
                              {{"filament", data + "cylinder_filament", "Int", "4"}},
                              f.contact_force ? std::vector<std::array<std::string, 2>>{{"contact_force",
                                                                                         data + "contact_force"}}
                                              : std::vector<std::array<std::string, 2>>{}});
      break;
    case FilamentPart::kLinkers: binders("linker", f.linkers); break;
    case FilamentPart::kMotors: binders("motor", f.motors); break;
    case FilamentPart::kBranchPoints:
      // One vertex per branch point; Polyvertex needs no connectivity.
      fmt::format_to(std::back_inserter(xml),
                     R"(          <Topology TopologyType="Polyvertex" NodesPerElement="1" NumberOfElements="{b}"/>
          <Geometry GeometryType="XYZ">
            <DataItem Format="HDF" NumberType="Float" Precision="8" Dimensions="{b} 3">{data}branch_points</DataItem>
          </Geometry>
        </Grid>
)",
                     fmt::arg("b", f.branch_points), fmt::arg("data", data));
      break;
  }
}

// A structured grid over the corner points of compartments.h5, whose C order (z fastest)
// matches the species datasets', so cell (i, j, k) is compartment (i, j, k). A uniform
// XDMF mesh would need the data x fastest.
void appendCompartmentGrid(std::string& xml, const XdmfSnapshot& snapshot) {
  const XdmfCompartments& c = *snapshot.compartments;
  const auto [nx, ny, nz] = c.shape;
  openGrid(xml, "compartments", snapshot.time);
  fmt::format_to(std::back_inserter(xml),
                 R"(          <Topology TopologyType="3DSMesh" Dimensions="{} {} {}"/>
          <Geometry GeometryType="XYZ">
            <DataItem Format="HDF" NumberType="Float" Precision="8" Dimensions="{} 3">{}:/points</DataItem>
          </Geometry>
)",
                 nx + 1, ny + 1, nz + 1, (nx + 1) * (ny + 1) * (nz + 1), kCompartmentPointsFile);
  for (const std::string& species : c.species) {
    fmt::format_to(std::back_inserter(xml),
                   R"(        <Attribute Name="{name}" AttributeType="Scalar" Center="Cell">
            <DataItem Format="HDF" NumberType="Int" Precision="4" Dimensions="{nx} {ny} {nz}">{file}:/compartments/species/{name}</DataItem>
          </Attribute>
)",
                   fmt::arg("name", escapeXml(species)), fmt::arg("nx", nx), fmt::arg("ny", ny), fmt::arg("nz", nz),
                   fmt::arg("file", snapshotFile(snapshot.index)));
  }
  xml += "        </Grid>\n";
}

// One temporal collection holding `grid` for every snapshot where `present` says the
// object has elements; nothing at all when it never has.
template <class Present, class Grid>
void appendObject(std::string& xml, const std::string& name, const std::vector<XdmfSnapshot>& snapshots,
                  Present present, Grid grid) {
  if (std::none_of(snapshots.begin(), snapshots.end(), present)) return;
  fmt::format_to(std::back_inserter(xml), "      <Grid Name=\"{}\" GridType=\"Collection\" CollectionType=\"Temporal\">\n",
                 escapeXml(name));
  for (const XdmfSnapshot& snapshot : snapshots)
    if (present(snapshot)) grid(snapshot);
  xml += "      </Grid>\n";
}

}  // namespace

std::string snapshotGroup(std::int64_t index) { return fmt::format("/snapshots/{:06d}", index); }
std::string snapshotFile(std::int64_t index) { return fmt::format("snapshots/{:06d}.h5", index); }

std::string trajectoryXdmf(const std::vector<XdmfSnapshot>& snapshots) {
  // Xdmf 2 rather than 3: ParaView's "Xdmf Reader" keeps the grid names as block names.
  // The spatial collection around the objects makes the data a multiblock set even with
  // one object, so a pipeline that selects blocks by name works for every run.
  std::string xml = R"(<?xml version="1.0" ?>
<!DOCTYPE Xdmf SYSTEM "Xdmf.dtd" []>
<Xdmf Version="2.0">
  <Domain>
    <Grid Name="trajectory" GridType="Collection" CollectionType="Spatial">
)";
  // Membranes in order of first appearance.
  std::vector<std::string> membranes;
  for (const XdmfSnapshot& snapshot : snapshots)
    for (const XdmfMembrane& m : snapshot.membranes)
      if (std::find(membranes.begin(), membranes.end(), m.name) == membranes.end()) membranes.push_back(m.name);
  for (const std::string& name : membranes) {
    const auto find = [&](const XdmfSnapshot& s) {
      return std::find_if(s.membranes.begin(), s.membranes.end(), [&](const XdmfMembrane& m) { return m.name == name; });
    };
    appendObject(
        xml, name, snapshots, [&](const XdmfSnapshot& s) { return find(s) != s.membranes.end(); },
        [&](const XdmfSnapshot& s) { appendMembraneGrid(xml, s, *find(s)); });
  }
  for (const auto& [part, name] : kFilamentParts) {
    appendObject(
        xml, name, snapshots, [&](const XdmfSnapshot& s) { return s.filaments && elements(*s.filaments, part) > 0; },
        [&](const XdmfSnapshot& s) { appendFilamentGrid(xml, s, part, name); });
  }
  appendObject(
      xml, "compartments", snapshots,
      [](const XdmfSnapshot& s) { return s.compartments && !s.compartments->species.empty(); },
      [&](const XdmfSnapshot& s) { appendCompartmentGrid(xml, s); });
  xml += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return xml;
}

}  // namespace cortex
