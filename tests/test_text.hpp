// Text helpers shared by tests that inspect what cortex writes (XDMF, logs).
#pragma once

#include <cstddef>
#include <string>

namespace cortex::testing {

// How often `what` occurs in `text`, overlapping occurrences included.
inline std::size_t countOccurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace cortex::testing
