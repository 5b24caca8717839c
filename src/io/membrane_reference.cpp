#include "io/membrane_reference.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace cortex {

std::string readClosedMembraneName(const ConfigReader& r, const std::string& key,
                                   const std::vector<MembraneConfig>& membranes) {
  const std::string name = r.string(key, "");
  const auto m = std::find_if(membranes.begin(), membranes.end(), [&](const MembraneConfig& c) { return c.name == name; });
  if (m == membranes.end()) r.fail(key, fmt::format("no membrane is named \"{}\"", name));
  if (m->shape == "plane") r.fail(key, fmt::format("membrane \"{}\" is open and encloses nothing", name));
  return name;
}

}  // namespace cortex
