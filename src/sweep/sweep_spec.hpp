// What a sweep file says (docs/sweep.md): a base run config, the settings to vary (a
// full-factorial [grid] or an explicit list of [[members]]) and the seeds, expanded into
// the sweep's members in a fixed order. Each member is the base config with its settings
// applied as `--set key.path=value` overrides.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cortex {

// One swept setting's value, as `--set` takes it and as the sweep table shows it.
struct SweptValue {
  std::string toml;              // the value as TOML text: 10.0, 5, true, "text"
  std::optional<double> number;  // numbers, and booleans as 0/1; empty for strings
  std::string text;              // strings: the string itself
};

struct SweepMember {
  std::size_t index = 0;
  // One entry per SweepSpec::keys; empty where a [[members]] entry leaves the key out
  // (the base config's value applies).
  std::vector<std::optional<SweptValue>> values;
  std::optional<std::int64_t> seed;  // from `seeds`; empty: the base config's own seed
};

struct SweepSpec {
  std::filesystem::path file;  // the sweep file
  std::string text;            // its content
  std::filesystem::path base;  // the base config (relative paths resolved against the sweep file's folder)
  std::vector<std::string> keys;       // swept key paths, in the order written
  std::vector<bool> key_is_string;     // per key: its values are strings (else numbers or booleans)
  std::optional<int> parallel;         // local worker processes; empty: one per core
  std::vector<SweepMember> members;    // grid points in row-major order of the keys, seeds innermost
};

// Reads and validates a sweep file; throws InputError naming the file, line, key and
// problem (unknown keys, wrong types, empty lists, mixed kinds of values, ...).
SweepSpec readSweepFile(const std::filesystem::path& file);

// Whether `file` is meant as a sweep file (a TOML table with a top-level `base` key)
// rather than a run config; false for anything unreadable.
bool isSweepFile(const std::filesystem::path& file);

// The `--set` overrides that make `member` out of the base config.
std::vector<std::string> memberOverrides(const SweepSpec& spec, const SweepMember& member);

// The member's output folder relative to the sweep's: members/0003 (4 digits, more for
// sweeps of 10000 members or more).
std::filesystem::path memberFolder(const SweepSpec& spec, std::size_t index);

}  // namespace cortex
