// Shared plumbing of `granule plot ...`: finding a run's files, default output names, running
// helper programs (Debian's Python for matplotlib, ffmpeg) and mapping errors to exit codes.
#pragma once

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace granule::app {

// Bad input (exit code 2, nothing written): the message names the option and the allowed range.
struct BadPlotInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// RUN_DIR_or_FILE → the file: a directory gives `<dir>/<name>` (or `<name>.partial` while the run
// is still going), a file is itself.  Throws BadPlotInput when there is no such file.
std::string locate_run_file(const std::string& run_dir_or_file, const std::string& name);

// Default output: `<dir>/<name>` for a run directory, `<file's folder>/<name>` for a file.
std::string output_beside(const std::string& run_dir_or_file, const std::string& name);

// Resolve a frame index (negative counts from the end) among `frames`; throws BadPlotInput naming --frame.
std::int64_t resolve_frame(std::int64_t frame, std::int64_t frames);

// The root attribute `format` of an HDF5 file ("" without one); throws BadPlotInput when `path` is not HDF5.
std::string hdf5_format(const std::string& path);
// The root attribute `dimension` of a snapshot or fields file: 3 for a run of spheres, 2 (also when
// absent: 2D files need not carry it) for disks.  Throws BadPlotInput when `path` is not HDF5.
int hdf5_dimension(const std::string& path);
// Throws BadPlotInput unless `path` is an HDF5 file whose root attribute `format` is `format`.
void require_hdf5_format(const std::string& path, const char* format, const char* producer);

// The options given on a parsed command line ("--width", ...): options that apply to one
// dimension only are refused for the other.
std::vector<std::string> given_options(const CLI::App& command);

// Runs a program (argv[0] is looked up in PATH) and returns its exit code (127 if it cannot start).
int run_program(const std::vector<std::string>& argv);

// Whether an executable `name` is in one of the folders of PATH.
bool program_in_path(const std::string& name);

// A temporary file or folder (a `.partial` output, scratch frames), removed whatever happens once
// the command ends, with the journal of a flush HDF5 did not finish (io/journaled_file_driver.hpp);
// a published output no longer exists under this name, so nothing is lost.
struct RemovedAtExit {
  std::filesystem::path path;
  ~RemovedAtExit() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
    for (const char* journal : {".journal", ".journal.tmp"}) std::filesystem::remove(path.string() + journal, ignored);
  }
};

// Runs a script of python/granule_plots with Debian's Python; returns its exit code.
int run_plot_script(const std::string& script, const std::vector<std::string>& arguments);

// Runs a plot command's body and ends the program with its exit code: 2 on BadPlotInput, 4 on
// IoError (an output that cannot be written), 1 on any other error (messages prefixed with "granule plot <kind>: error:").
[[noreturn]] void finish_plot_command(const std::string& kind, const std::function<int()>& body);

}  // namespace granule::app
