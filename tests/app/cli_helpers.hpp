// Helpers for end-to-end tests of the `cortex` program: a fresh folder per test, config
// files, running the real binary (CORTEX_BINARY) with its exit code and output captured,
// and reading what it wrote (files, summary.json, HDF5 dataset types).
#pragma once

#include <gtest/gtest.h>
#include <fcntl.h>
#include <hdf5.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/hdf5_file.hpp"

extern char** environ;

namespace cortex::cli_test {

namespace fs = std::filesystem;

inline fs::path cortexBinary() { return fs::path(CORTEX_BINARY); }
inline fs::path sourceDir() { return fs::path(CORTEX_SOURCE_DIR); }

// A fresh, empty folder unique to the running test (suite, name, process, counter) under
// the system temp folder. Removed on destruction unless the test failed or the
// environment sets CORTEX_KEEP_TEST_DIRS, so a failure can be inspected.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    std::string name = "notest";
    if (const auto* info = ::testing::UnitTest::GetInstance()->current_test_info())
      name = std::string(info->test_suite_name()) + "_" + info->name();
    for (char& c : name)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') c = '_';
    path_ = fs::temp_directory_path() / ("cortex_cli_" + name + "_" + std::to_string(::getpid()) + "_" +
                                         std::to_string(counter++));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    if (std::getenv("CORTEX_KEEP_TEST_DIRS") || ::testing::Test::HasFailure()) {
      std::cerr << "[ kept     ] " << path_.string() << '\n';
      return;
    }
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

inline void writeFile(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

// Writes a config text to dir/name and returns its path.
inline fs::path writeConfig(const fs::path& dir, const std::string& text,
                            const std::string& name = "config.toml") {
  writeFile(dir / name, text);
  return dir / name;
}

inline std::string readFile(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline nlohmann::json readJson(const fs::path& file) { return nlohmann::json::parse(readFile(file)); }

// summary.json of OUTDIR without the keys that legitimately differ between equal runs.
inline nlohmann::json comparableSummary(const fs::path& outdir,
                                        const std::vector<std::string>& ignore = {"wall_seconds"}) {
  nlohmann::json j = readJson(outdir / "summary.json");
  for (const std::string& k : ignore) j.erase(k);
  return j;
}

inline std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

struct RunResult {
  int exit_code = -1;  // WEXITSTATUS, or 128 + signal
  std::string out, err;
  std::string command;
};

// For failure messages: what was run and what it said.
inline std::string describe(const RunResult& r) {
  return "command: " + r.command + "\nexit code: " + std::to_string(r.exit_code) + "\nstdout:\n" + r.out +
         "\nstderr:\n" + r.err;
}

// Runs `program args...` with stdin from /dev/null; stdout and stderr go to files in
// capture_dir (kept there for inspection) and are returned. `env` holds extra
// "NAME=value" settings for the child only.
inline RunResult runProgram(const fs::path& program, const std::vector<std::string>& args,
                            const fs::path& capture_dir, const std::vector<std::string>& env = {}) {
  static std::atomic<int> counter{0};
  const int n = counter++;
  const fs::path out = capture_dir / ("cortex_stdout_" + std::to_string(n) + ".txt");
  const fs::path err = capture_dir / ("cortex_stderr_" + std::to_string(n) + ".txt");
  RunResult r;
  for (const std::string& e : env) {
    const auto eq = e.find('=');
    r.command += e.substr(0, eq + 1) + shellQuote(e.substr(eq + 1)) + " ";
  }
  r.command += shellQuote(program.string());
  for (const std::string& a : args) r.command += " " + shellQuote(a);
  const std::string shell =
      r.command + " </dev/null >" + shellQuote(out.string()) + " 2>" + shellQuote(err.string());
  const int status = std::system(shell.c_str());
  if (status == -1) {
    r.exit_code = -1;
  } else if (WIFEXITED(status)) {
    r.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    r.exit_code = 128 + WTERMSIG(status);
  }
  if (fs::exists(out)) r.out = readFile(out);
  if (fs::exists(err)) r.err = readFile(err);
  return r;
}

// `cortex args...`, as runProgram runs it.
inline RunResult runCortex(const std::vector<std::string>& args, const fs::path& capture_dir,
                           const std::vector<std::string>& env = {}) {
  return runProgram(cortexBinary(), args, capture_dir, env);
}

// `cortex check` of the config `text` exits 2 with a message naming `key` and saying `words`.
inline void expectCheckFails(const std::string& text, const std::string& key, const std::string& words) {
  TempDir dir;
  const RunResult r = runCortex({"check", writeConfig(dir.path(), text).string()}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << describe(r);
  EXPECT_NE(r.err.find(key), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
}

// `cortex args...` started in the background, its output discarded.
inline pid_t spawnCortex(const std::vector<std::string>& args, const std::vector<std::string>& env = {}) {
  std::vector<std::string> argv_s{cortexBinary().string()};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_s;
  for (char** e = environ; *e; ++e) env_s.emplace_back(*e);
  env_s.insert(env_s.end(), env.begin(), env.end());
  std::vector<char*> envp;
  for (std::string& e : env_s) envp.push_back(e.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  for (int fd : {0, 1, 2}) posix_spawn_file_actions_addopen(&actions, fd, "/dev/null", fd == 0 ? O_RDONLY : O_WRONLY, 0);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

// Exit code as runCortex reports it: the status, or 128 + the signal.
inline int waitFor(pid_t pid) {
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1;
}

// Storage type of an HDF5 dataset, straight from the C API (the h5::File wrapper
// converts on read, so it cannot tell float64 from float32).
struct H5TypeInfo {
  H5T_class_t type_class = H5T_NO_CLASS;
  std::size_t bytes = 0;
  bool is_signed = false;
};

inline H5TypeInfo h5DatasetType(const fs::path& file, const std::string& dataset) {
  H5TypeInfo info;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return info;
  const hid_t d = H5Dopen2(f, dataset.c_str(), H5P_DEFAULT);
  if (d >= 0) {
    const hid_t t = H5Dget_type(d);
    info.type_class = H5Tget_class(t);
    info.bytes = H5Tget_size(t);
    info.is_signed = info.type_class == H5T_INTEGER && H5Tget_sign(t) == H5T_SGN_2;
    H5Tclose(t);
    H5Dclose(d);
  }
  H5Fclose(f);
  return info;
}

// `cortex run CONFIG -o OUTDIR -q extra...`
inline RunResult runConfig(const fs::path& config, const fs::path& outdir, const std::vector<std::string>& extra,
                           const fs::path& capture, const std::vector<std::string>& env = {}) {
  std::vector<std::string> args{"run", config.string(), "-o", outdir.string(), "-q"};
  args.insert(args.end(), extra.begin(), extra.end());
  return runCortex(args, capture, env);
}

// The same run done twice: at once to `end` (dir/A), and to `half` then resumed with
// `--set simulation.end_time=end` (dir/B). `config(t)` gives the config text for end time
// t; `extra` arguments go to all three invocations. Fails the test on a non-zero exit or
// when the half run did not stop at `half`.
inline void runWholeAndResumed(const TempDir& dir, const std::function<std::string(double)>& config, double half,
                               double end, const std::vector<std::string>& extra = {}) {
  RunResult r = runConfig(writeConfig(dir.path(), config(end), "full.toml"), dir / "A", extra, dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  r = runConfig(writeConfig(dir.path(), config(half), "half.toml"), dir / "B", extra, dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
  EXPECT_DOUBLE_EQ(readJson(dir / "B" / "summary.json")["time"].get<double>(), half);
  std::vector<std::string> resume{"run", "--resume", (dir / "B").string(), "--set",
                                  "simulation.end_time=" + std::to_string(end), "-q"};
  resume.insert(resume.end(), extra.begin(), extra.end());
  r = runCortex(resume, dir.path());
  ASSERT_EQ(r.exit_code, 0) << describe(r);
}

// Every snapshot of two trajectories holds the same per-compartment copies of `species`.
inline void expectSameCompartmentCounts(const fs::path& a_h5, const fs::path& b_h5,
                                        const std::vector<std::string>& species) {
  const h5::File a = h5::File::openReadOnly(a_h5), b = h5::File::openReadOnly(b_h5);
  ASSERT_EQ(a.children("/snapshots"), b.children("/snapshots"));
  for (const std::string& s : a.children("/snapshots"))
    for (const std::string& name : species) {
      const std::string path = "/snapshots/" + s + "/compartments/species/" + name;
      EXPECT_EQ(a.readInt32(path), b.readInt32(path)) << path;
    }
}

}  // namespace cortex::cli_test
