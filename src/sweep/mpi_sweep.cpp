#ifdef CORTEX_HAVE_MPI
#include "sweep/mpi_sweep.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "core/error.hpp"
#include "io/stop_signals.hpp"

namespace cortex {
namespace {

// Worker -> rank 0: {"outcome": null or the last member's outcome, "stop": whether this
// rank caught a stop signal}, meaning "ready for the next member".
constexpr int kToCoordinator = 1;
// Rank 0 -> worker: {"task": ...}, {"interrupt": true} (stop the running member) or
// {"stop": true} (no more members).
constexpr int kToWorker = 2;
// Waiting processes poll rather than block: a blocking MPI receive spins on a core that
// the members need.
constexpr auto kPollInterval = std::chrono::milliseconds(10);

class MpiSession {
 public:
  MpiSession() {
    MPI_Init(nullptr, nullptr);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiSession() { MPI_Finalize(); }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  int shareExitCode(int code) const {
    MPI_Bcast(&code, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return code;
  }

 private:
  int rank_ = 0, size_ = 1;
};

void send(const nlohmann::json& message, int to, int tag) {
  const std::string text = message.dump();
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

// The next message with `tag` from `from` (or any rank), if one has arrived.
std::optional<std::pair<int, nlohmann::json>> tryReceive(int from, int tag) {
  int arrived = 0;
  MPI_Status status;
  MPI_Iprobe(from, tag, MPI_COMM_WORLD, &arrived, &status);
  if (!arrived) return std::nullopt;
  int length = 0;
  MPI_Get_count(&status, MPI_CHAR, &length);
  std::string text(static_cast<std::size_t>(length), '\0');
  MPI_Recv(text.data(), length, MPI_CHAR, status.MPI_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return std::make_pair(status.MPI_SOURCE, nlohmann::json::parse(text));
}

std::pair<int, nlohmann::json> receive(int from, int tag) {
  for (;;) {
    if (auto message = tryReceive(from, tag)) return *message;
    std::this_thread::sleep_for(kPollInterval);
  }
}

nlohmann::json toJson(const MemberTask& t) {
  return {{"index", t.index}, {"sweep_dir", t.sweep_dir.string()}, {"folder", t.folder.string()}, {"args", t.args}};
}
MemberTask taskFrom(const nlohmann::json& j) {
  return {j.at("index").get<std::size_t>(), j.at("sweep_dir").get<std::string>(), j.at("folder").get<std::string>(),
          j.at("args").get<std::vector<std::string>>()};
}
nlohmann::json toJson(const MemberOutcome& o) {
  return {{"index", o.index}, {"status", static_cast<int>(o.status)}, {"message", o.message}, {"summary", o.summary}};
}
MemberOutcome outcomeFrom(const nlohmann::json& j) {
  return {j.at("index").get<std::size_t>(), static_cast<MemberStatus>(j.at("status").get<int>()),
          j.at("message").get<std::string>(), j.at("summary").get<std::string>()};
}

// Rank 0's view of the workers: which wait for a member, which run one.
class RankExecutor : public MemberExecutor {
 public:
  explicit RankExecutor(int size) : workers_(size - 1), unreleased_(size - 1) {}

  // Workers' messages are received by collect(), which the coordinator calls first.
  bool hasFreeSlot() override { return !idle_.empty(); }
  void start(const MemberTask& task) override {
    const int rank = idle_.back();
    idle_.pop_back();
    busy_.push_back(rank);
    send({{"task", toJson(task)}}, rank, kToWorker);
  }
  std::vector<MemberOutcome> collect() override {
    receiveAll();
    return std::exchange(outcomes_, {});
  }
  void interruptAll() override {
    for (const int rank : busy_) send({{"interrupt", true}}, rank, kToWorker);
  }
  std::size_t running() const override { return busy_.size(); }
  bool stopRequested() const override { return stop_requested_; }
  std::string describe() const override { return fmt::format("{} MPI worker ranks", workers_); }

  // Tells every worker there is no more work, once each is idle (running members are
  // asked to stop first). Called on every way out of rank 0, errors included, so that no
  // worker waits forever.
  void release() {
    if (!busy_.empty()) interruptAll();
    while (unreleased_ > 0) {
      for (const int rank : idle_) send({{"stop", true}}, rank, kToWorker);
      unreleased_ -= static_cast<int>(idle_.size());
      idle_.clear();
      if (unreleased_ > 0) {
        std::this_thread::sleep_for(kPollInterval);
        receiveAll();
      }
    }
  }

 private:
  void receiveAll() {
    while (auto message = tryReceive(MPI_ANY_SOURCE, kToCoordinator)) {
      const auto& [rank, body] = *message;
      stop_requested_ = stop_requested_ || body.value("stop", false);
      if (!body.at("outcome").is_null()) outcomes_.push_back(outcomeFrom(body.at("outcome")));
      busy_.erase(std::remove(busy_.begin(), busy_.end(), rank), busy_.end());
      idle_.push_back(rank);
    }
  }

  int workers_, unreleased_;
  std::vector<int> idle_, busy_;
  std::vector<MemberOutcome> outcomes_;
  bool stop_requested_ = false;
};

// One member on a worker: runs it to its end, forwarding one stop request (its own
// signal, or rank 0's interrupt) to it.
MemberOutcome runOnWorker(const std::filesystem::path& program, const MemberTask& task, const StopSignals& stop) {
  try {
    MemberRun run(program, task);
    for (;;) {
      if (std::optional<MemberOutcome> outcome = run.poll()) return *outcome;
      if (stop.requested() || tryReceive(0, kToWorker)) run.interrupt();
      std::this_thread::sleep_for(kPollInterval);
    }
  } catch (const std::exception& e) {
    return unstartedOutcome(task, e);
  }
}

void serveAsWorker() {
  const StopSignals stop;
  const std::filesystem::path program = currentExecutable();
  nlohmann::json last = nullptr;
  for (;;) {
    send({{"outcome", last}, {"stop", stop.requested()}}, 0, kToCoordinator);
    nlohmann::json message;
    do message = receive(0, kToWorker).second;
    while (message.contains("interrupt"));  // for a member that had ended already
    if (message.contains("stop")) return;
    last = toJson(runOnWorker(program, taskFrom(message.at("task")), stop));
  }
}

}  // namespace

int runSweepOnRanks(const SweepRequest& request) {
  const MpiSession mpi;
  if (mpi.rank() > 0) {
    serveAsWorker();
    return mpi.shareExitCode(0);
  }
  RankExecutor workers(mpi.size());
  int code = 0;
  try {
    SweepCoordinator coordinator(request);
    if (request.dry_run)
      std::cout << coordinator.memberList();
    else
      code = coordinator.run(workers);
  } catch (const InputError&) {
    // Every way out of rank 0 releases the workers, which exit with the code main()
    // gives rank 0 for the exception.
    workers.release();
    mpi.shareExitCode(2);
    throw;
  } catch (...) {
    workers.release();
    mpi.shareExitCode(1);
    throw;
  }
  workers.release();
  return mpi.shareExitCode(code);
}

}  // namespace cortex
#endif
