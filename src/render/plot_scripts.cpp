#include "render/plot_scripts.hpp"

#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "io/file_schema.hpp"
#include "io/hdf5_util.hpp"

extern char** environ;

namespace granule::render {

namespace {

namespace fs = std::filesystem;

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

// The measurement file a figure script draws, if it draws one.
std::optional<h5::Measurement> measurement_drawn_by(const std::string& script) {
  if (script == "collisions") return h5::Measurement::kCollisionStatistics;
  if (script == "spectra") return h5::Measurement::kSpectra;
  if (script == "f1") return h5::Measurement::kF1;
  if (script == "spins") return h5::Measurement::kSpins;
  return std::nullopt;
}

}  // namespace

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

int run_plot_script(const std::string& script, const std::vector<std::string>& arguments) {
  // An HDF5 input is opened through Granule's reading layer first: a file whose structure crashes
  // or hangs the HDF5 library is refused there (io/hdf5_util.hpp, open_file), never met by h5py,
  // and a measurement file that does not hold what its schema says is refused before the script
  // meets it half way through a figure (io/file_schema.hpp).
  if (!arguments.empty() && fs::path(arguments[0]).extension() == ".h5" && fs::is_regular_file(arguments[0])) {
    if (const std::optional<h5::Measurement> kind = measurement_drawn_by(script)) {
      h5::check_measurement_file(arguments[0], *kind);
    } else {
      h5::open_file(arguments[0]).close();
    }
  }
  const fs::path path = plot_scripts_root() / "granule_plots" / (script + ".py");
  if (!fs::exists(path)) throw std::runtime_error(fmt::format("the plot script {} is missing", path.string()));
  std::vector<std::string> argv{GRANULE_SYSTEM_PYTHON, path.string()};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  return run_program(argv);
}

}  // namespace granule::render
