#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace cortex {

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
  const std::filesystem::path tmp = path.string() + ".tmp";
  auto fail = [&](const char* what, int error) {
    ::unlink(tmp.c_str());
    throw RunError(fmt::format("cannot {} '{}': {}", what, path.string(), std::strerror(error)));
  };
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail("create a temporary file for", errno);
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : EIO;
      ::close(fd);
      fail("write", error);
    }
    done += static_cast<std::size_t>(n);
  }
  // Some file systems report a full disk only when the data is flushed at close.
  if (::close(fd) != 0) fail("write (at close)", errno);
  if (::rename(tmp.c_str(), path.c_str()) != 0) fail("rename the temporary file to", errno);
}

std::string readWholeFile(const std::filesystem::path& path, std::size_t max_bytes) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status))
    throw InputError(fmt::format("{}: no such file", path.string()));
  if (!std::filesystem::is_regular_file(status))
    throw InputError(fmt::format("{}: not a regular file", path.string()));
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(fmt::format("{}: cannot read: {}", path.string(), ec.message()));
  if (size > max_bytes)
    throw InputError(fmt::format("{}: {} bytes, more than the {} this file can hold", path.string(), size, max_bytes));
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  if (!in) throw InputError(fmt::format("{}: cannot read", path.string()));
  return s.str();
}

}  // namespace cortex
