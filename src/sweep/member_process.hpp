// One sweep member as a child process: `cortex run ...` started by fork and exec, so a
// crash, an exit(1) or a runaway allocation in one member never takes the sweep down.
// The child runs in its own process group (a Ctrl-C at the terminal reaches only the
// sweep, which forwards one SIGTERM: a second signal would kill the member without its
// checkpoint) and dies with its parent (PR_SET_PDEATHSIG), so killing the sweep leaves no
// member running on in its folder.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cortex {

// How a child ended: its exit code, or the signal that killed it.
struct ChildExit {
  int code = -1;    // exit code, -1 when killed by a signal
  int signal = 0;   // the killing signal, 0 when it exited
  std::string describe() const;  // "exit code 1", "killed by signal 9 (Killed)"
};

class ChildProcess {
 public:
  // Runs `program args...` with `workdir` as its working directory, stdin from /dev/null
  // and stdout and stderr appended to `console` (a path relative to workdir or absolute).
  // Throws RunError when the process cannot be created.
  ChildProcess(const std::filesystem::path& program, const std::vector<std::string>& args,
               const std::filesystem::path& workdir, const std::filesystem::path& console);
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  // A child still running when its owner goes (an exception unwinding) is killed and reaped.
  ~ChildProcess();

  // The exit once the child has ended; empty while it runs. Does not block.
  std::optional<ChildExit> poll();
  // Asks the child to stop gracefully (SIGTERM), once: a second request does nothing.
  void interrupt();

 private:
  pid_t pid_ = -1;
  bool interrupted_ = false;
};

// The path of the running program (/proc/self/exe), to start members with the same binary.
std::filesystem::path currentExecutable();

}  // namespace cortex
