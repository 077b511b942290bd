#include "app/plot/plot_inputs.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <spawn.h>
#include <unistd.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "io/hdf5_util.hpp"
#include "io/io_error.hpp"

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

std::string hdf5_format(const std::string& path) {
  try {
    h5::Handle file = h5::open_file(path);
    const std::string format = H5Aexists(file.get(), "format") > 0 ? h5::read_string_attribute(file.get(), "format") : "";
    file.close();
    return format;
  } catch (const IoError& error) {
    throw BadPlotInput(fmt::format("cannot read {} as HDF5: {}", path, error.what()));
  }
}

std::vector<std::string> given_options(const CLI::App& command) {
  std::vector<std::string> given;
  for (const CLI::Option* option : command.get_options()) {
    if (option->count() > 0) given.push_back(option->get_name());
  }
  return given;
}

int hdf5_dimension(const std::string& path) {
  try {
    h5::Handle file = h5::open_file(path);
    const int dimension = H5Aexists(file.get(), "dimension") > 0 ? h5::read_attribute<int>(file.get(), "dimension", H5T_NATIVE_INT) : 2;
    file.close();
    return dimension;
  } catch (const IoError& error) {
    throw BadPlotInput(fmt::format("cannot read {} as HDF5: {}", path, error.what()));
  }
}

void require_hdf5_format(const std::string& path, const char* format, const char* producer) {
  if (hdf5_format(path) != format) throw BadPlotInput(fmt::format("{} is not a {} file (written by {})", path, format, producer));
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

bool program_in_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::istringstream folders(path != nullptr ? path : "");
  for (std::string folder; std::getline(folders, folder, ':');) {
    const fs::path candidate = fs::path(folder.empty() ? "." : folder) / name;
    std::error_code ignored;
    if (fs::is_regular_file(candidate, ignored) && access(candidate.c_str(), X_OK) == 0) return true;
  }
  return false;
}

// Where python/granule_plots is: $GRANULE_PYTHON_DIR; else beside an installed binary
// (<prefix>/bin/granule → <prefix>/share/granule/python); else, for a developer's build, the
// source tree it was built from.
fs::path plot_scripts_root() {
  if (const char* chosen = std::getenv("GRANULE_PYTHON_DIR"); chosen != nullptr && *chosen != '\0') return chosen;
  std::error_code ignored;
  const fs::path installed = fs::read_symlink("/proc/self/exe", ignored).parent_path().parent_path() / GRANULE_INSTALLED_PYTHON_DIR;
  if (fs::is_directory(installed / "granule_plots", ignored)) return installed;
  return GRANULE_SOURCE_PYTHON_DIR;
}

int run_plot_script(const std::string& script, const std::vector<std::string>& arguments) {
  const fs::path path = plot_scripts_root() / "granule_plots" / (script + ".py");
  if (!fs::exists(path)) throw std::runtime_error(fmt::format("the plot script {} is missing", path.string()));
  std::vector<std::string> argv{GRANULE_SYSTEM_PYTHON, path.string()};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  return run_program(argv);
}

void finish_plot_command(const std::string& kind, const std::function<int()>& body) {
  int code = 0;
  std::string message;
  try {
    code = body();
  } catch (const BadPlotInput& error) {
    code = 2;
    message = error.what();
  } catch (const IoError& error) {
    code = 4;
    message = error.what();
  } catch (const std::exception& error) {
    code = 1;
    message = error.what();
  }
  if (!message.empty()) fmt::print(stderr, "granule plot {}: error: {}\n", kind, message);
  throw CLI::RuntimeError(code);
}

}  // namespace granule::app
