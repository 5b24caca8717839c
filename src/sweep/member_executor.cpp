#include "sweep/member_executor.hpp"

#include <fmt/format.h>

namespace cortex {

MemberOutcome unstartedOutcome(const MemberTask& task, const std::exception& why) {
  return {task.index, MemberStatus::kFailed, fmt::format("could not be started: {}", why.what()), ""};
}

void LocalExecutor::start(const MemberTask& task) {
  try {
    runs_.emplace_back(program_, task);
  } catch (const std::exception& e) {
    unstarted_.push_back(unstartedOutcome(task, e));
  }
}

std::vector<MemberOutcome> LocalExecutor::collect() {
  std::vector<MemberOutcome> done = std::move(unstarted_);
  unstarted_.clear();
  for (auto it = runs_.begin(); it != runs_.end();) {
    if (std::optional<MemberOutcome> outcome = it->poll()) {
      done.push_back(std::move(*outcome));
      it = runs_.erase(it);
    } else {
      ++it;
    }
  }
  return done;
}

std::string LocalExecutor::describe() const {
  return fmt::format("{} local process{}", slots_, slots_ == 1 ? "" : "es");
}

void LocalExecutor::interruptAll() {
  for (MemberRun& run : runs_) run.interrupt();
}

}  // namespace cortex
