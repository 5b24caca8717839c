#include "io/box_region_config.hpp"

namespace cortex {

std::optional<BoxRegion> readBoxRegion(const ConfigReader& parent, const std::string& key) {
  const std::optional<ConfigReader> r = parent.table(key);
  if (!r) return std::nullopt;
  const auto lo = r->numbers("min", 3, Range{}, "nm"), hi = r->numbers("max", 3, Range{}, "nm");
  r->finish();
  BoxRegion box{Vec3(lo[0], lo[1], lo[2]), Vec3(hi[0], hi[1], hi[2])};
  if (!(box.min.array() < box.max.array()).all()) parent.fail(key, "min must be below max on every axis");
  return box;
}

}  // namespace cortex
