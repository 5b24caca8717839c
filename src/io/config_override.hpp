// `--set key.path=value`: edits a parsed TOML table before validation. Arrays of tables
// are indexed by number (membrane.0.radius=500); the value is TOML (500, "x", [1, 2]),
// and a bare word that is not valid TOML is taken as a string.
#pragma once

#include <toml++/toml.h>

#include <string>

namespace cortex {

void applyOverride(toml::table& root, const std::string& assignment);

}  // namespace cortex
