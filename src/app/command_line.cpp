// granule's command line: builds the subcommands (each in its own file under src/app/) and runs one.
// Whatever escapes a subcommand ends here with a one-line message (plain fprintf: it must not
// throw when stderr itself fails) and a documented exit code (README.md), never an abort: 4 for
// I/O failures (std::filesystem and fmt report theirs as std::system_error), 5 for memory, 1 for
// anything else (a bug).
#include <CLI/CLI.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <new>
#include <system_error>

#include "app/analyze/analyze_command.hpp"
#include "app/command_line.hpp"
#include "app/exit_codes.hpp"
#include "app/bench/bench_command.hpp"
#include "app/plot/plot_command.hpp"
#include "app/reproduce/reproduce_command.hpp"
#include "app/run/run_command.hpp"
#include "app/sweep/sweep_command.hpp"
#include "app/theory/theory_command.hpp"
#include "granule/version.hpp"
#include "io/io_error.hpp"

namespace {

using namespace granule::app;

int run_command_line(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& error) {  // the exit codes subcommands throw
    return app.exit(error);
  } catch (const CLI::ParseError& error) {  // help and version (0), or a malformed command line
    const int code = app.exit(error);
    return code == 0 ? kExitSuccess : kExitBadInput;
  } catch (const granule::InputError& error) {  // an input file refused by the layers below
    std::fprintf(stderr, "granule: error: %s\n", error.what());
    return kExitBadInput;
  } catch (const granule::IoError& error) {
    std::fprintf(stderr, "granule: I/O error: %s\n", error.what());
    return kExitIoError;
  } catch (const std::system_error& error) {  // the system refused a file, a directory or the output stream
    std::fprintf(stderr, "granule: I/O error: %s\n", error.what());
    return kExitIoError;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "granule: error: not enough memory\n");
    return kExitOutOfMemory;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "granule: internal error: %s (please report this)\n", error.what());
    return kExitInternalError;
  }
  return 0;
}

}  // namespace

int granule::app::run_granule(int argc, char** argv) {
  CLI::App app{"Granule: event-driven simulation and analysis of rapid granular flows of inelastic hard disks\n"
               "and spheres "
               "(after M.-L. Tan, Microstructures and Macrostructures in Rapid Granular Flows, Princeton 1995)."};
  app.set_version_flag("--version", granule::kVersion);
  app.require_subcommand(1);
  granule::app::add_run_command(app);
  granule::app::add_sweep_command(app);
  granule::app::add_reproduce_command(app);
  granule::app::add_bench_command(app);
  granule::app::add_theory_command(app);
  granule::app::add_analyze_command(app);
  granule::app::add_plot_command(app);
  const int code = run_command_line(app, argc, argv);
  // What stdout still buffers would otherwise be written at exit, where a failure goes unseen.
  if (std::fflush(stdout) != 0 && code == 0) {
    std::fprintf(stderr, "granule: I/O error: cannot write the standard output: %s\n", std::strerror(errno));
    return kExitIoError;
  }
  return code;
}

std::string granule::app::own_executable() { return std::filesystem::read_symlink("/proc/self/exe").string(); }
