#include "sweep/member_run.hpp"

#include <fmt/format.h>

#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace cortex {
namespace {

// Large enough for any summary of a run cortex can hold in memory.
constexpr std::size_t kMaxSummaryBytes = std::size_t{1} << 28;
// Only the end of a member's console is read for its failure message.
constexpr std::streamoff kConsoleTail = 1 << 16;
constexpr std::size_t kMaxMessage = 2000;

std::uintmax_t prepareFolder(const MemberTask& task) {
  std::error_code ec;
  std::filesystem::create_directories(task.sweep_dir / task.folder, ec);
  if (ec) throw RunError(fmt::format("cannot create {}: {}", (task.sweep_dir / task.folder).string(), ec.message()));
  const auto size = std::filesystem::file_size(task.sweep_dir / task.folder / "console.log", ec);
  return ec ? 0 : size;
}

// What the member said last: its final "cortex: ..." line (the error or failure the
// program reports before exiting), else its last line of any kind (a stop's warning),
// without the "cortex: " or level prefix.
std::string lastWords(const std::filesystem::path& console, std::uintmax_t from) {
  std::ifstream in(console, std::ios::binary);
  if (!in) return "";
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  const std::streamoff start = std::max<std::streamoff>(static_cast<std::streamoff>(from), end - kConsoleTail);
  if (end <= start) return "";
  std::string text(static_cast<std::size_t>(end - start), '\0');
  in.seekg(start);
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  std::string last, last_cortex;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t eol = std::min(text.find('\n', pos), text.size());
    const std::string line = text.substr(pos, eol - pos);
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
    if (line.rfind("cortex: ", 0) == 0) last_cortex = line.substr(8);
    pos = eol + 1;
  }
  std::string words = last_cortex.empty() ? last : last_cortex;
  for (const char* prefix : {"warning: ", "error: "})
    if (words.rfind(prefix, 0) == 0) words = words.substr(std::strlen(prefix));
  if (words.size() > kMaxMessage) words = words.substr(0, kMaxMessage) + "...";
  return words;
}

}  // namespace

const char* statusName(MemberStatus status) {
  switch (status) {
    case MemberStatus::kOk: return "ok";
    case MemberStatus::kFailed: return "failed";
    case MemberStatus::kStopped: return "stopped";
    case MemberStatus::kPending: return "pending";
  }
  return "pending";
}

MemberRun::MemberRun(const std::filesystem::path& program, MemberTask task)
    : task_(std::move(task)),
      console_start_(prepareFolder(task_)),
      process_(program, task_.args, task_.sweep_dir, task_.folder / "console.log") {}

std::optional<MemberOutcome> MemberRun::poll() {
  const std::optional<ChildExit> exit = process_.poll();
  if (!exit) return std::nullopt;
  return outcomeOf(*exit);
}

MemberOutcome MemberRun::outcomeOf(const ChildExit& exit) const {
  if (exit.code == 0) return finishedOutcome(task_.index, task_.sweep_dir / task_.folder);
  MemberOutcome outcome{task_.index, exit.code == 3 ? MemberStatus::kStopped : MemberStatus::kFailed, "", ""};
  const std::string words = lastWords(task_.sweep_dir / task_.folder / "console.log", console_start_);
  if (outcome.status == MemberStatus::kStopped && !words.empty())
    outcome.message = words;  // "stopped by signal 15 at t = ... after writing a checkpoint; ..."
  else
    outcome.message = exit.describe() + (words.empty() ? "" : ": " + words);
  return outcome;
}

MemberOutcome finishedOutcome(std::size_t index, const std::filesystem::path& folder) {
  MemberOutcome outcome{index, MemberStatus::kOk, "", ""};
  try {
    outcome.summary = readWholeFile(folder / "summary.json", kMaxSummaryBytes);
    if (!nlohmann::json::parse(outcome.summary).is_object()) throw InputError("not a JSON object");
  } catch (const std::exception& e) {
    outcome = {index, MemberStatus::kFailed, fmt::format("the run finished but its summary.json is unusable: {}", e.what()),
               ""};
  }
  return outcome;
}

}  // namespace cortex
