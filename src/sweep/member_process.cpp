#include "sweep/member_process.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.hpp"

namespace cortex {
namespace {

// Between fork and exec only async-signal-safe calls: on any failure the child exits
// with 127, which the sweep reports like a member that failed to start.
[[noreturn]] void execChild(pid_t parent, const char* program, char* const argv[], const char* workdir,
                            const char* console) {
  setpgid(0, 0);
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(127);  // the parent died before prctl took effect
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  if (chdir(workdir) != 0) _exit(127);
  const int in = open("/dev/null", O_RDONLY);
  const int out = open(console, O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (in < 0 || out < 0 || dup2(in, STDIN_FILENO) < 0 || dup2(out, STDOUT_FILENO) < 0 ||
      dup2(out, STDERR_FILENO) < 0)
    _exit(127);
  // Descriptors of the sweep (its log, MPI's sockets and shared memory) are not the member's.
  close_range(3, ~0U, 0);
  execv(program, argv);
  _exit(127);
}

}  // namespace

std::string ChildExit::describe() const {
  if (signal != 0) return fmt::format("killed by signal {} ({})", signal, strsignal(signal));
  return fmt::format("exit code {}", code);
}

ChildProcess::ChildProcess(const std::filesystem::path& program, const std::vector<std::string>& args,
                           const std::filesystem::path& workdir, const std::filesystem::path& console) {
  // Everything the child needs is prepared before fork: it may not allocate afterwards.
  const std::string program_text = program.string(), workdir_text = workdir.string(),
                    console_text = console.string();
  std::vector<std::string> argv_text{program_text};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t parent = getpid();
  pid_ = fork();
  if (pid_ < 0) throw RunError(fmt::format("cannot start a member process: {}", std::strerror(errno)));
  if (pid_ == 0) execChild(parent, program_text.c_str(), argv.data(), workdir_text.c_str(), console_text.c_str());
}

ChildProcess::~ChildProcess() {
  if (pid_ <= 0) return;
  kill(pid_, SIGKILL);
  while (waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {
  }
}

std::optional<ChildExit> ChildProcess::poll() {
  if (pid_ <= 0) return std::nullopt;
  int status = 0;
  const pid_t done = waitpid(pid_, &status, WNOHANG);
  if (done == 0 || (done < 0 && errno == EINTR)) return std::nullopt;
  pid_ = -1;
  ChildExit exit;
  if (done < 0) {
    exit.code = 127;  // not our child any more: cannot happen unless SIGCHLD is ignored
  } else if (WIFSIGNALED(status)) {
    exit.signal = WTERMSIG(status);
  } else {
    exit.code = WEXITSTATUS(status);
  }
  return exit;
}

void ChildProcess::interrupt() {
  if (pid_ <= 0 || interrupted_) return;
  interrupted_ = true;
  kill(pid_, SIGTERM);
}

std::filesystem::path currentExecutable() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw RunError(fmt::format("cannot find the running program (/proc/self/exe): {}", ec.message()));
  return exe;
}

}  // namespace cortex
