// Where a sweep's members run: child processes of the sweep itself (LocalExecutor), or
// MPI worker ranks (mpi_sweep.hpp). The coordinator hands tasks to whichever it has.
#pragma once

#include <filesystem>
#include <list>
#include <string>
#include <vector>

#include "sweep/member_run.hpp"

namespace cortex {

class MemberExecutor {
 public:
  virtual ~MemberExecutor() = default;
  // Whether a task can start now.
  virtual bool hasFreeSlot() = 0;
  virtual void start(const MemberTask& task) = 0;
  // Outcomes of members that ended since the last call (a member that could not even be
  // started counts as failed). Does not block.
  virtual std::vector<MemberOutcome> collect() = 0;
  // Asks every running member to stop gracefully (each checkpoints and exits with code 3).
  virtual void interruptAll() = 0;
  virtual std::size_t running() const = 0;
  // Whether a part of the executor (an MPI rank) was asked to stop by a signal of its own.
  virtual bool stopRequested() const { return false; }
  // Where members run, for the log: "2 local processes", "3 MPI worker ranks".
  virtual std::string describe() const = 0;
};

// Up to `slots` members at a time as child processes of this one.
class LocalExecutor : public MemberExecutor {
 public:
  LocalExecutor(std::filesystem::path program, std::size_t slots) : program_(std::move(program)), slots_(slots) {}
  bool hasFreeSlot() override { return runs_.size() < slots_; }
  void start(const MemberTask& task) override;
  std::vector<MemberOutcome> collect() override;
  void interruptAll() override;
  std::size_t running() const override { return runs_.size(); }
  std::string describe() const override;

 private:
  std::filesystem::path program_;
  std::size_t slots_;
  std::list<MemberRun> runs_;  // a list: a running member never moves
  std::vector<MemberOutcome> unstarted_;  // tasks whose process could not be created
};

// A task's outcome when its process could not be started at all.
MemberOutcome unstartedOutcome(const MemberTask& task, const std::exception& why);

}  // namespace cortex
