#include "sweep/sweep_directory.hpp"

#include <fmt/format.h>

#include <fstream>
#include <iterator>
#include <optional>

#include "io/atomic_file.hpp"
#include "io/io_error.hpp"

namespace granule::sweep {

namespace fs = std::filesystem;

namespace {

std::optional<std::string> file_text(const fs::path& path) {
  std::ifstream file(path);
  if (!file) return std::nullopt;
  return std::string{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// Writes `content` unless the file already holds it.  Array tasks start together and may all
// write the same file: whoever loses the race finds it written.
void write_shared_file(const fs::path& path, const std::string& content) {
  if (file_text(path) == content) return;
  try {
    write_file_atomically(path.string(), content);
  } catch (const IoError&) {
    if (file_text(path) != content) throw;
  }
}

}  // namespace

void prepare_sweep_directory(const SweepDirectory& dir, const SweepSpec& spec) {
  std::error_code error;
  if (fs::exists(dir.root, error) && !fs::is_directory(dir.root, error)) {
    throw BadSweepInput(fmt::format("--out {} exists and is not a directory", dir.root.string()));
  }
  if (fs::exists(dir.root, error) && !fs::is_empty(dir.root, error)) {
    const std::optional<std::string> earlier = file_text(dir.spec());
    if (!earlier) {
      throw BadSweepInput(fmt::format(
          "--out {} is not empty and holds no sweep (no sweep.toml): choose another directory", dir.root.string()));
    }
    if (*earlier != spec.canonical_toml) {
      throw BadSweepInput(
          fmt::format("--out {} holds another sweep: its sweep.toml differs from this spec (a restart "
                      "must give the same spec; choose another directory for a new sweep)",
                      dir.root.string()));
    }
  }
  for (const fs::path& folder : {dir.root, dir.root / "runs", dir.root / "points"}) {
    fs::create_directories(folder, error);
    if (error) throw io_error("cannot create " + folder.string(), error.value());
  }
  write_shared_file(dir.base_config(), spec.base_toml);
  write_shared_file(dir.spec(), spec.canonical_toml);
}

SweepSpec sweep_in_directory(const SweepDirectory& dir) {
  const std::optional<std::string> text = file_text(dir.spec());
  if (!text) throw BadSweepInput(fmt::format("{} holds no sweep (no sweep.toml)", dir.root.string()));
  SweepSpecResult parsed = parse_sweep_spec(*text);
  if (!parsed.spec) throw BadSweepInput(fmt::format("{}: {}", dir.spec().string(), parsed.error));
  return std::move(*parsed.spec);
}

}  // namespace granule::sweep
