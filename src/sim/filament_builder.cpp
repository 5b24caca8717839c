#include "sim/filament_builder.hpp"

#include "core/random.hpp"
#include "filament/filament_placement.hpp"

namespace cortex {

std::unique_ptr<FilamentNetwork> buildFilamentNetwork(const FilamentConfig& config, const Vec3& box_min,
                                                      const Vec3& box_max, std::uint64_t seed,
                                                      const FilamentState* restored) {
  auto network = std::make_unique<FilamentNetwork>(config);
  if (restored) {
    network->restore(restored->filaments, restored->linkers, restored->motors, restored->branches);
    return network;
  }
  RandomStream random(seed, StreamId::kFilamentPlacement);
  for (const FilamentSeed& s : placeFilaments(config, box_min, box_max, random)) {
    const FilamentType& t = config.types[s.type];
    Filament f = makeStraightFilament(s.type, s.minus_end, s.direction, s.monomers, t.cylinder_monomers, t.monomer_size);
    f.minus_anchored = s.fixed_minus_end;
    network->addFilament(std::move(f));
  }
  return network;
}

}  // namespace cortex
