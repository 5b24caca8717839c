#include "sweep/member_check.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.hpp"
#include "core/hash.hpp"
#include "io/config.hpp"
#include "io/run_driver.hpp"

namespace cortex {

std::string describeMember(const SweepSpec& spec, std::size_t index) {
  const std::vector<std::string> overrides = memberOverrides(spec, spec.members[index]);
  return fmt::format("member {}{}", index, overrides.empty() ? "" : fmt::format(" ({})", fmt::join(overrides, ", ")));
}

std::vector<CheckedMember> checkMembers(const SweepSpec& spec) {
  std::vector<CheckedMember> checked;
  checked.reserve(spec.members.size());
  for (const SweepMember& member : spec.members) {
    CheckedMember c;
    try {
      const Config config = loadConfig(spec.base, memberOverrides(spec, member));
      checkLoadedConfig(config, spec.base);
      c.seed = config.simulation.seed;
      c.config_hash = fnv1a64(config.effective_toml);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}: {}", spec.file.string(), describeMember(spec, member.index), e.what()));
    }
    checked.push_back(std::move(c));
  }
  return checked;
}

std::string checkSweep(const std::filesystem::path& file) {
  const SweepSpec spec = readSweepFile(file);
  checkMembers(spec);
  return fmt::format("{}: ok ({} member{} over {}{})", file.string(), spec.members.size(),
                     spec.members.size() == 1 ? "" : "s", spec.base.string(),
                     spec.keys.empty() ? "" : fmt::format(", varying {}", fmt::join(spec.keys, ", ")));
}

}  // namespace cortex
