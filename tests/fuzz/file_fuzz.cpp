// The file fuzzer: mutants of a real Granule file given to the reader that `granule` uses for it,
// in one process (thousands of mutants a minute, under ASan/UBSan in the sanitizer tier).  Every
// mutant must be read cleanly or refused with an InputError (exit 2 of the command); anything
// else is a failure: another exception, a crash (the process dies, ASan reports it), or a hang
// (no result within the time limit: the process exits with code 3 naming the mutant).
//
//   granule_file_fuzz READER ORIGINAL MUTANTS SEED WORK_DIR
//   granule_file_fuzz mutate ORIGINAL MUTANT SEED INDEX        (one mutant, for the CLI fuzz test)
//   granule_file_fuzz mutate-text ORIGINAL MUTANT SEED INDEX   (one mutant of a text file)
//   granule_file_fuzz reseal CHECKPOINT                         (digests recomputed after a hand edit)
//
// READER: snapshots (a snapshots.h5), fields (a fields.h5), resume (ORIGINAL is a run directory;
// its checkpoint.h5 is mutated and the run is set up for resuming as `granule run --resume` does),
// collisions, spectra, f1, spins (the measurement files figure scripts read: the schema check `granule
// plot` makes before it starts the script; the indices of the mutants it accepts are written to
// WORK_DIR/accepted.txt, for tests/fuzz/figure_fuzz.py to give to the script itself),
// and the text readers of text_readers.hpp (sweep-record, timeseries; `mutate-text` writes one of
// their mutants).
// Prints "READER: N mutants, C clean, R refused, F failed" and exits 1 when F > 0.  The mutant
// being read is described in WORK_DIR/current_mutant.txt (a crash leaves it there).
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <typeinfo>
#include <unistd.h>

#include "driver/run_session.hpp"
#include "driver/run_start.hpp"
#include "fuzz/hdf5_mutator.hpp"
#include "fuzz/text_mutator.hpp"
#include "fuzz/text_readers.hpp"
#include "io/checkpoint_file.hpp"
#include "io/config.hpp"
#include "io/export_field_source.hpp"
#include "io/file_schema.hpp"
#include "io/hdf5_util.hpp"
#include "io/io_error.hpp"
#include "io/snapshot_file.hpp"
#include "io/spacetime_file.hpp"
#include "reproduce/density_layers.hpp"
#include "reproduce/streamwise_profiles.hpp"

namespace {

namespace fs = std::filesystem;
using namespace granule;

constexpr unsigned kSecondsPerMutant = 30;
char g_current[512] = {};

void on_alarm(int) {
  static const char message[] = "granule_file_fuzz: HANG: no result within the time limit for mutant ";
  ssize_t ignored = write(2, message, sizeof message - 1);
  ignored = write(2, g_current, strnlen(g_current, sizeof g_current));
  ignored = write(2, "\n", 1);
  (void)ignored;
  _exit(3);
}

void read_snapshots(const std::string& path) {
  read_snapshot(path, 0);
  read_snapshot(path, -1);
  h5::read_frame_series(path, "shear_velocity");
}

void read_fields(const std::string& path) {
  read_field_file_frame(path, -1);
  spacetime_from_fields(path, "instant");
  reproduce::read_density_layers(path);
  reproduce::read_streamwise_profiles(path, 0.0, 1e300);
}

// What `granule run --resume` does before its first event: the configuration of the run
// directory, its grid, the checkpoint, and the session built from them (which reopens the run's
// files and checks the checkpoint against the configuration and the engine's invariants).
template <int D>
void resume(const RunConfig& config, const std::string& dir) {
  const CellGrid grid = driver::run_cell_grid(config);
  const StateArchive checkpoint = read_checkpoint(dir + "/checkpoint.h5");
  driver::RunSession<D> session(config, grid, dir, checkpoint);
}

const std::map<std::string, h5::Measurement> kMeasurementReaders{{"collisions", h5::Measurement::kCollisionStatistics},
                                                                 {"spectra", h5::Measurement::kSpectra},
                                                                 {"f1", h5::Measurement::kF1},
                                                                 {"spins", h5::Measurement::kSpins}};

struct Tally {
  long clean = 0, refused = 0, failed = 0;
};

// Whether the mutant was read cleanly.
bool try_one(const std::function<void()>& read, const std::string& what, Tally& tally) {
  try {
    read();
    ++tally.clean;
    if (std::getenv("GRANULE_FUZZ_SHOW_CLEAN") != nullptr) std::printf("clean: %s\n", what.c_str());
    return true;
  } catch (const InputError&) {
    ++tally.refused;
  } catch (const std::runtime_error& error) {
    // The engine's checkpoint checks (core has no I/O types) and the run's own refusals: the
    // command maps them to exit 2 too (app/run/run_command.cpp).
    if (dynamic_cast<const IoError*>(&error) != nullptr) {
      ++tally.failed;
      std::fprintf(stderr, "FAIL (I/O error, exit 4) %s: %s\n", what.c_str(), error.what());
    } else {
      ++tally.refused;
    }
  } catch (const std::exception& error) {
    ++tally.failed;
    std::fprintf(stderr, "FAIL (%s) %s: %s\n", typeid(error).name(), what.c_str(), error.what());
  }
  return false;
}

int run_fuzzer(const std::string& reader, const std::string& original, long mutants, std::uint64_t seed, const std::string& work) {
  fs::create_directories(work);
  std::signal(SIGALRM, on_alarm);
  Tally tally;
  const bool resuming = reader == "resume";
  const std::string source = resuming ? original + "/checkpoint.h5" : original;
  const std::string mutant = resuming ? work + "/run/checkpoint.h5" : work + "/mutant.h5";
  fuzz::MutationOptions options;
  const auto measurement = kMeasurementReaders.find(reader);
  std::FILE* accepted = measurement != kMeasurementReaders.end() ? std::fopen((work + "/accepted.txt").c_str(), "w") : nullptr;
  for (long k = 0; k < mutants; ++k) {
    if (resuming) {
      fs::remove_all(work + "/run");
      fs::copy(original, work + "/run", fs::copy_options::recursive);
      options.reseal_digests = k % 2 == 1;
    }
    const std::string what = fuzz::is_text_reader(reader)
                                 ? fuzz::prepare_text_mutant(reader, original, work, seed, static_cast<std::uint64_t>(k))
                                 : fuzz::write_mutant(source, mutant, seed, static_cast<std::uint64_t>(k), options);
    std::snprintf(g_current, sizeof g_current, "%s seed %llu index %ld: %s", reader.c_str(),
                  static_cast<unsigned long long>(seed), k, what.c_str());
    {  // what a crash leaves behind: the mutant being read, by its seed and index
      std::FILE* current = std::fopen((work + "/current_mutant.txt").c_str(), "w");
      if (current) {
        std::fprintf(current, "%s\n", g_current);
        std::fclose(current);
      }
    }
    alarm(kSecondsPerMutant);
    if (reader == "snapshots") {
      try_one([&] { read_snapshots(mutant); }, g_current, tally);
    } else if (reader == "fields") {
      try_one([&] { read_fields(mutant); }, g_current, tally);
    } else if (measurement != kMeasurementReaders.end()) {
      if (try_one([&] { h5::check_measurement_file(mutant, measurement->second); }, g_current, tally) && accepted) {
        std::fprintf(accepted, "%ld\n", k);
      }
    } else if (fuzz::is_text_reader(reader)) {
      try_one([&] { fuzz::read_text_mutant(reader, original, work); }, g_current, tally);
    } else {
      try_one([&] {
        const ConfigResult parsed = load_config_file(work + "/run/config.toml", {});
        if (!parsed.config) throw std::logic_error("the run directory's config.toml does not parse: " + parsed.error);
        if (parsed.config->system.dimension == 3) {
          resume<3>(*parsed.config, work + "/run");
        } else {
          resume<2>(*parsed.config, work + "/run");
        }
      }, g_current, tally);
    }
    alarm(0);
  }
  if (accepted) std::fclose(accepted);
  std::printf("%s: %ld mutants, %ld clean, %ld refused, %ld failed\n", reader.c_str(), mutants, tally.clean, tally.refused,
              tally.failed);
  return tally.failed == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 6 && std::string(argv[1]) == "mutate") {
    std::puts(fuzz::write_mutant(argv[2], argv[3], std::stoull(argv[4]), std::stoull(argv[5]), {}).c_str());
    return 0;
  }
  if (argc == 6 && std::string(argv[1]) == "mutate-text") {
    std::puts(fuzz::write_text_mutant(argv[2], argv[3], std::stoull(argv[4]), std::stoull(argv[5])).c_str());
    return 0;
  }
  if (argc == 3 && std::string(argv[1]) == "reseal") {
    fuzz::reseal_digests(argv[2]);
    return 0;
  }
  if (argc != 6) {
    std::fprintf(stderr, "usage: granule_file_fuzz snapshots|fields|resume|collisions|spectra|f1|spins|sweep-record|timeseries ORIGINAL MUTANTS SEED WORK_DIR\n"
                         "       granule_file_fuzz mutate ORIGINAL MUTANT SEED INDEX\n"
                         "       granule_file_fuzz mutate-text ORIGINAL MUTANT SEED INDEX\n"
                         "       granule_file_fuzz reseal CHECKPOINT\n");
    return 2;
  }
  const std::string reader = argv[1];
  if (reader != "snapshots" && reader != "fields" && reader != "resume" && kMeasurementReaders.count(reader) == 0 &&
      !fuzz::is_text_reader(reader)) {
    std::fprintf(stderr, "granule_file_fuzz: unknown reader %s\n", reader.c_str());
    return 2;
  }
  return run_fuzzer(reader, argv[2], std::stol(argv[3]), std::stoull(argv[4]), argv[5]);
}
