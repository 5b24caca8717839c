// What a member's folder holds when a sweep starts, so that a rerun of an interrupted
// sweep skips finished members, resumes those with a checkpoint and starts the rest.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace cortex {

enum class MemberState {
  kNotStarted,  // nothing to keep: run from the start (with --overwrite: a killed start may have left a log)
  kResumable,   // a checkpoint of this member's run: `cortex run --resume`
  kFinished,    // summary.json of this member's run: skip
};

// Throws InputError when the folder holds a run of another config than the one whose
// text hashes to `config_hash` (fnv1a64; the sweep file or the base config changed
// since): cortex never mixes such results into one table, nor resumes another run.
MemberState memberState(const std::filesystem::path& folder, std::uint64_t config_hash);

}  // namespace cortex
