// Writing a file so that a crash at any moment, a full disk or any other I/O error leaves
// either the previous file or the whole new one, never a torn one: the bytes go to a
// temporary file beside the target, every write and the close are checked, then the
// temporary file is renamed over the target (an atomic step on POSIX file systems).
// Protects against the process dying (kill, crash); not against power loss (no fsync).
#pragma once

#include <filesystem>
#include <string_view>

namespace cortex {

// On any failure the temporary file is removed and a RunError names the file and the
// cause ("No space left on device", ...); the target is then untouched.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

// The whole content of a file; throws InputError naming it if it cannot be read, is not
// a regular file, or is larger than `max_bytes`.
std::string readWholeFile(const std::filesystem::path& path, std::size_t max_bytes);

}  // namespace cortex
