// Running one sweep member and telling how it went: the task (what to start, where) and
// its outcome (status, failure message, summary.json), both plain data so that an MPI
// worker can receive the one and send back the other.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "sweep/member_process.hpp"

namespace cortex {

struct MemberTask {
  std::size_t index = 0;
  std::filesystem::path sweep_dir;   // absolute: members run with it as working directory
  std::filesystem::path folder;      // the member's folder, relative to sweep_dir
  std::vector<std::string> args;     // `cortex` arguments: run ... or run --resume ...
};

enum class MemberStatus { kOk, kFailed, kStopped, kPending };
const char* statusName(MemberStatus status);  // "ok", "failed", "stopped", "pending"

struct MemberOutcome {
  std::size_t index = 0;
  MemberStatus status = MemberStatus::kPending;
  std::string message;  // why it failed or stopped; empty when ok
  std::string summary;  // summary.json's text when ok
};

// A started member. Its console (stdout and stderr) is appended to FOLDER/console.log;
// a failure's message is the last "cortex: ..." line this attempt wrote there.
class MemberRun {
 public:
  MemberRun(const std::filesystem::path& program, MemberTask task);
  std::size_t index() const { return task_.index; }
  // The outcome once the member's process has ended; empty while it runs.
  std::optional<MemberOutcome> poll();
  void interrupt() { process_.interrupt(); }

 private:
  MemberOutcome outcomeOf(const ChildExit& exit) const;

  MemberTask task_;
  std::uintmax_t console_start_;  // console.log's size before this attempt
  ChildProcess process_;
};

// The outcome of a member whose folder already holds a finished run.
MemberOutcome finishedOutcome(std::size_t index, const std::filesystem::path& folder);

}  // namespace cortex
