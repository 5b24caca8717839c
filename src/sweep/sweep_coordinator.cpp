#include "sweep/sweep_coordinator.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <map>
#include <thread>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/stop_signals.hpp"
#include "sweep/member_folder.hpp"
#include "sweep/sweep_table.hpp"

namespace cortex {
namespace {

using Clock = std::chrono::steady_clock;

void prepareSweepFolder(const std::filesystem::path& outdir) {
  std::error_code ec;
  if (std::filesystem::exists(outdir, ec) && !std::filesystem::is_directory(outdir, ec))
    throw InputError(fmt::format("{}: the output folder is a file; give another -o", outdir.string()));
  std::filesystem::create_directories(outdir / "members", ec);
  if (ec) throw InputError(fmt::format("{}: cannot create the output folder: {}", outdir.string(), ec.message()));
  if (::access(outdir.c_str(), W_OK | X_OK) != 0 || ::access((outdir / "members").c_str(), W_OK | X_OK) != 0)
    throw InputError(fmt::format("{}: cannot write into the output folder (permissions)", outdir.string()));
}

// One sweep per folder at a time: two would run the same members into the same folders.
class SweepLock {
 public:
  explicit SweepLock(const std::filesystem::path& outdir) {
    const std::filesystem::path file = outdir / "sweep.lock";
    fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw InputError(fmt::format("{}: cannot create the lock file", file.string()));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      ::close(fd_);
      throw InputError(fmt::format("{}: another cortex sweep is running in this folder", outdir.string()));
    }
  }
  ~SweepLock() { ::close(fd_); }
  SweepLock(const SweepLock&) = delete;
  SweepLock& operator=(const SweepLock&) = delete;

 private:
  int fd_ = -1;
};

std::shared_ptr<spdlog::logger> sweepLogger(const std::filesystem::path& file, bool quiet) {
  auto console = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
  console->set_pattern("%^%l%$: %v");
  console->set_level(quiet ? spdlog::level::warn : spdlog::level::info);
  auto log_file = std::make_shared<spdlog::sinks::basic_file_sink_mt>(file.string(), false);
  log_file->set_pattern("[%Y-%m-%d %H:%M:%S.%e] %l: %v");
  auto logger = std::make_shared<spdlog::logger>("sweep", spdlog::sinks_init_list{console, log_file});
  logger->set_level(spdlog::level::info);
  logger->flush_on(spdlog::level::info);
  return logger;
}

// Hands tasks out in member order as slots free up and records every outcome. After a
// stop signal (to the sweep or, under MPI, to any rank) nothing more starts and the
// running members are asked once to stop; the tasks never started stay pending.
// Each task is made when it starts (its arguments hold the member's overrides: made all
// at once, 10⁶ members' would take hundreds of MB).
void dispatch(MemberExecutor& executor, const std::vector<std::size_t>& pending,
              const std::function<MemberTask(std::size_t)>& makeTask, std::vector<MemberOutcome>& outcomes,
              spdlog::logger& log) {
  const StopSignals stop;
  std::size_t next = 0, ended = 0;
  bool stopping = false;
  struct Started {
    std::string folder;
    Clock::time_point when;
  };
  std::map<std::size_t, Started> started;
  while ((!stopping && next < pending.size()) || executor.running() > 0) {
    std::vector<MemberOutcome> done = executor.collect();
    for (MemberOutcome& outcome : done) {
      const Started& s = started.at(outcome.index);
      const double seconds = std::chrono::duration<double>(Clock::now() - s.when).count();
      ++ended;
      const auto level = outcome.status == MemberStatus::kOk ? spdlog::level::info : spdlog::level::warn;
      log.log(level, "member {} {} after {:.2f} s [{}/{}]{}", s.folder, statusName(outcome.status), seconds, ended,
              pending.size(), outcome.message.empty() ? "" : ": " + outcome.message);
      started.erase(outcome.index);
      outcomes[outcome.index] = std::move(outcome);
    }
    if (!stopping && (stop.requested() || executor.stopRequested())) {
      stopping = true;
      log.warn("stop requested: no more members start; the {} running are asked to stop after a checkpoint",
               executor.running());
      executor.interruptAll();
    }
    while (!stopping && next < pending.size() && executor.hasFreeSlot()) {
      const MemberTask task = makeTask(pending[next++]);
      log.info("member {} {}", task.folder.string(), task.args.at(1) == "--resume" ? "resumes" : "starts");
      started[task.index] = {task.folder.string(), Clock::now()};
      executor.start(task);
    }
    if (done.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

}  // namespace

SweepCoordinator::SweepCoordinator(SweepRequest request)
    : request_(std::move(request)), spec_(readSweepFile(request_.file)), checked_(checkMembers(spec_)) {}

std::string SweepCoordinator::memberList() const {
  std::string list;
  for (const SweepMember& m : spec_.members)
    list += fmt::format("{}  seed {}  {}\n", memberFolder(spec_, m.index).string(), checked_[m.index].seed,
                        fmt::join(memberOverrides(spec_, m), " "));
  return list;
}

std::size_t SweepCoordinator::localSlots() const {
  if (request_.parallel) return static_cast<std::size_t>(*request_.parallel);
  if (spec_.parallel) return static_cast<std::size_t>(*spec_.parallel);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  return std::max<std::size_t>(1, cores / static_cast<unsigned>(std::max(1, request_.threads)));
}

int SweepCoordinator::run(MemberExecutor& executor) {
  const std::filesystem::path outdir = std::filesystem::absolute(
      request_.output_dir.empty() ? std::filesystem::path(spec_.file.stem().string() + "_out") : request_.output_dir);
  prepareSweepFolder(outdir);
  const SweepLock lock(outdir);
  const std::size_t n = spec_.members.size();
  std::vector<MemberState> states;
  for (std::size_t i = 0; i < n; ++i)
    states.push_back(memberState(outdir / memberFolder(spec_, i), checked_[i].config_hash));

  const auto log = sweepLogger(outdir / "sweep.log", request_.quiet);
  const std::string base = std::filesystem::absolute(spec_.base).string();
  const std::string threads = std::to_string(request_.threads);
  std::vector<MemberOutcome> outcomes(n);
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < n; ++i) {
    outcomes[i].index = i;
    if (states[i] == MemberState::kFinished) {
      const std::filesystem::path folder = memberFolder(spec_, i);
      outcomes[i] = finishedOutcome(i, outdir / folder);
      log->info("member {} finished before: skipped", folder.string());
      continue;
    }
    pending.push_back(i);
  }
  const auto makeTask = [&](std::size_t i) {
    MemberTask task{i, outdir, memberFolder(spec_, i), {}};
    if (states[i] == MemberState::kResumable) {
      task.args = {"run", "--resume", task.folder.string(), "-q", "--threads", threads};
    } else {
      // --overwrite: a start killed before its first checkpoint may have left a log.
      task.args = {"run", base, "-o", task.folder.string(), "--overwrite", "-q", "--threads", threads};
      for (const std::string& o : memberOverrides(spec_, spec_.members[i])) task.args.insert(task.args.end(), {"--set", o});
    }
    return task;
  };
  const std::size_t resumed = static_cast<std::size_t>(std::count(states.begin(), states.end(), MemberState::kResumable));
  log->info("cortex {} sweep {} over {}: {} members; {} finished before, {} to resume, {} to start; on {}",
            CORTEX_VERSION, spec_.file.string(), base, n, n - pending.size(), resumed, pending.size() - resumed,
            executor.describe());

  dispatch(executor, pending, makeTask, outcomes, *log);

  std::vector<std::int64_t> seeds;
  for (const CheckedMember& c : checked_) seeds.push_back(c.seed);
  const SweepTable table = sweepTable(spec_, seeds, outcomes);
  writeFileAtomically(outdir / "sweep.csv", sweepCsv(table));
  writeFileAtomically(outdir / "sweep.h5", sweepHdf5Image(table, spec_));

  std::map<MemberStatus, std::size_t> count;
  for (const MemberOutcome& o : outcomes) ++count[o.status];
  log->info("{} ok, {} failed, {} stopped, {} not started; table in {}", count[MemberStatus::kOk],
            count[MemberStatus::kFailed], count[MemberStatus::kStopped], count[MemberStatus::kPending],
            (outdir / "sweep.csv").string());
  if (count[MemberStatus::kStopped] + count[MemberStatus::kPending] > 0) {
    log->warn("the sweep stopped before every member ended; run the same command again to continue it");
    return 3;
  }
  return count[MemberStatus::kFailed] > 0 ? 1 : 0;
}

}  // namespace cortex
