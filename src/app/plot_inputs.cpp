#include "app/plot_inputs.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>

#include <filesystem>

extern char** environ;

namespace granule::app {

namespace fs = std::filesystem;

std::string locate_run_file(const std::string& run_dir_or_file, const std::string& name) {
  if (!fs::exists(run_dir_or_file)) throw BadPlotInput(fmt::format("{} does not exist (give a run directory or a file)", run_dir_or_file));
  if (!fs::is_directory(run_dir_or_file)) return run_dir_or_file;
  for (const std::string& candidate : {name, name + ".partial"}) {
    const fs::path path = fs::path(run_dir_or_file) / candidate;
    if (fs::exists(path)) return path.string();
  }
  throw BadPlotInput(fmt::format("{} has no {}", run_dir_or_file, name));
}

std::string output_beside(const std::string& run_dir_or_file, const std::string& name) {
  const fs::path base(run_dir_or_file);
  return ((fs::is_directory(base) ? base : base.parent_path()) / name).string();
}

std::int64_t resolve_frame(std::int64_t frame, std::int64_t frames) {
  if (frame < -frames || frame >= frames) {
    throw BadPlotInput(fmt::format("--frame {} is out of range: the file has {} frames (allowed {} … {})", frame, frames,
                                   -frames, frames - 1));
  }
  return frame < 0 ? frames + frame : frame;
}

int run_program(const std::vector<std::string>& argv) {
  std::vector<char*> pointers;
  for (const std::string& a : argv) pointers.push_back(const_cast<char*>(a.c_str()));
  pointers.push_back(nullptr);
  pid_t child = 0;
  if (posix_spawnp(&child, pointers[0], nullptr, nullptr, pointers.data(), environ) != 0) return 127;
  int status = 0;
  if (waitpid(child, &status, 0) < 0) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

int run_plot_script(const std::string& script, const std::vector<std::string>& arguments) {
  const fs::path path = fs::path(GRANULE_PYTHON_DIR) / "granule_plots" / (script + ".py");
  if (!fs::exists(path)) throw std::runtime_error(fmt::format("the plot script {} is missing", path.string()));
  std::vector<std::string> argv{GRANULE_SYSTEM_PYTHON, path.string()};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  return run_program(argv);
}

void finish_plot_command(const std::string& kind, const std::function<int()>& body) {
  int code = 0;
  try {
    code = body();
  } catch (const BadPlotInput& error) {
    fmt::print(stderr, "granule plot {}: error: {}\n", kind, error.what());
    code = 2;
  } catch (const std::exception& error) {
    fmt::print(stderr, "granule plot {}: error: {}\n", kind, error.what());
    code = 1;
  }
  throw CLI::RuntimeError(code);
}

}  // namespace granule::app
