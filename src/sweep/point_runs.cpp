#include "sweep/point_runs.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <deque>
#include <filesystem>
#include <thread>

#include "io/io_error.hpp"

extern char** environ;

namespace granule::sweep {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

// Skipped: done before (its run finished or collapsed); resumed: from its checkpoint; else a
// fresh run, which replaces what a failed attempt left in its run directory.
enum class Start { kSkip, kResume, kFresh };

Start next_start(const SweepDirectory& dir, const SweepPoint& point) {
  const std::optional<PointRecord> record = read_record(dir, point);
  if (record_from_summary(dir, point) && (!record || is_done(*record))) return Start::kSkip;
  return fs::exists(dir.run(point) / "checkpoint.h5") ? Start::kResume : Start::kFresh;
}

std::vector<std::string> run_arguments(const SweepRun& run, const SweepPoint& point, Start start) {
  const std::string out = run.dir.run(point).string();
  if (start == Start::kResume) return {run.granule, "run", "--resume", out};
  std::vector<std::string> argv{run.granule, "run", run.dir.base_config().string(), "--out", out};
  for (const std::string& assignment : point.overrides()) argv.insert(argv.end(), {"--set", assignment});
  if (fs::exists(out)) argv.emplace_back("--force");
  return argv;
}

// Starts `granule run` for the point, its output and errors appended to the point's log.
pid_t launch(const SweepRun& run, const SweepPoint& point, Start start) {
  std::vector<std::string> argv = run_arguments(run, point, start);
  std::vector<char*> pointers;
  for (std::string& a : argv) pointers.push_back(a.data());
  pointers.push_back(nullptr);
  const std::string log = run.dir.log(point).string();
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  const int mode = O_WRONLY | O_CREAT | (start == Start::kResume ? O_APPEND : O_TRUNC);
  posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, log.c_str(), mode, 0644);
  posix_spawn_file_actions_adddup2(&files, STDOUT_FILENO, STDERR_FILENO);
  pid_t child = 0;
  const int error = posix_spawn(&child, pointers[0], &files, nullptr, pointers.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  if (error != 0) throw io_error(fmt::format("cannot start {} for point {}", run.granule, point.name), error);
  return child;
}

struct Running {
  std::size_t slot;  // position in `indices`
  pid_t pid;
  Clock::time_point started;
};

}  // namespace

std::string progress_line(const SweepPoint& point, const PointRecord& record, bool skipped) {
  if (skipped) return fmt::format("{}: skipped ({} before)", point.name, record.status);
  if (record.status == "failed") {
    return fmt::format("{}: failed (exit {}) in {:.3g} s: {}", point.name, record.exit_code, record.seconds,
                       record.error);
  }
  return fmt::format("{}: {} in {:.3g} s", point.name, record.status, record.seconds);
}

std::vector<PointRecord> run_points(const SweepRun& run, const std::vector<std::size_t>& indices, int jobs,
                                    bool print_progress) {
  check_point_files(run.dir, *run.spec, indices);  // a damaged one refuses the sweep while nothing runs
  std::vector<PointRecord> records(indices.size());
  std::deque<std::size_t> waiting;
  for (std::size_t slot = 0; slot < indices.size(); ++slot) waiting.push_back(slot);
  std::vector<Running> running;
  while (!waiting.empty() || !running.empty()) {
    const int signal = *run.interrupt;
    if (signal == 0 && !waiting.empty() && static_cast<int>(running.size()) < jobs) {
      const std::size_t slot = waiting.front();
      waiting.pop_front();
      const SweepPoint& point = run.spec->points[indices[slot]];
      const Start start = next_start(run.dir, point);
      if (start == Start::kSkip) {
        records[slot] = current_record(run.dir, point);
        if (!read_record(run.dir, point)) write_record(run.dir, point, records[slot]);
        if (print_progress) fmt::print("{}\n", progress_line(point, records[slot], true));
        continue;
      }
      running.push_back({slot, launch(run, point, start), Clock::now()});
      continue;
    }
    if (signal != 0) waiting.clear();  // those never started stay pending
    // Poll rather than block in waitpid, so that a signal stops new starts at once.
    bool reaped = false;
    for (auto it = running.begin(); it != running.end();) {
      int status = 0;
      if (waitpid(it->pid, &status, WNOHANG) != it->pid) {
        ++it;
        continue;
      }
      const SweepPoint& point = run.spec->points[indices[it->slot]];
      const double seconds = std::chrono::duration<double>(Clock::now() - it->started).count();
      records[it->slot] = record_of_exit(status, seconds, run.dir.log(point).string());
      write_record(run.dir, point, records[it->slot]);
      if (print_progress) fmt::print("{}\n", progress_line(point, records[it->slot], false));
      std::fflush(stdout);
      it = running.erase(it);
      reaped = true;
    }
    if (!reaped) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return records;
}

}  // namespace granule::sweep
