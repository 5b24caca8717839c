#include "sweep/member_folder.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/hash.hpp"
#include "io/hdf5_file.hpp"

namespace cortex {

MemberState memberState(const std::filesystem::path& folder, std::uint64_t config_hash) {
  std::error_code ec;
  // trajectory.h5 is written with the first snapshot, before the first checkpoint, and
  // names the run's effective config: without it there is nothing to resume or keep.
  if (!std::filesystem::exists(folder / "trajectory.h5", ec)) return MemberState::kNotStarted;
  std::string stored;
  try {
    stored = h5::File::openReadOnly(folder / "trajectory.h5").attributeString("/", "config");
  } catch (const std::exception& e) {
    throw InputError(fmt::format("{}: cannot read the member's trajectory.h5 ({}); remove the folder to run the "
                                 "member again",
                                 folder.string(), e.what()));
  }
  if (fnv1a64(stored) != config_hash)
    throw InputError(fmt::format("{}: holds a run of another config than this member's (the sweep file or the base "
                                 "config changed since it ran): give another -o, or remove the folder to run the "
                                 "member again",
                                 folder.string()));
  if (std::filesystem::exists(folder / "summary.json", ec)) return MemberState::kFinished;
  if (std::filesystem::exists(folder / "checkpoint.h5", ec)) return MemberState::kResumable;
  return MemberState::kNotStarted;
}

}  // namespace cortex
