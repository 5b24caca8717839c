// LD_PRELOAD shim for the full-disk tests (tests/app/test_faults.cpp): write(2) on any
// file other than stdin/stdout/stderr fails with ENOSPC once CORTEX_TEST_WRITE_BUDGET
// bytes have been written, as on a file system that fills up.
#include <dlfcn.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdlib>

extern "C" ssize_t write(int fd, const void* buffer, size_t count) {
  using Write = ssize_t (*)(int, const void*, size_t);
  static const Write real = reinterpret_cast<Write>(dlsym(RTLD_NEXT, "write"));
  static long budget = [] {
    const char* text = std::getenv("CORTEX_TEST_WRITE_BUDGET");
    return text ? std::atol(text) : LONG_MAX;
  }();
  if (fd > 2) {
    if (static_cast<long>(count) > budget) {
      errno = ENOSPC;
      return -1;
    }
    budget -= static_cast<long>(count);
  }
  return real(fd, buffer, count);
}
