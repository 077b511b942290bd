#include "sweep/array_tasks.hpp"

#include <fmt/format.h>

#include <cstdlib>

#include "sweep/sweep_directory.hpp"

namespace granule::sweep {

namespace {

int environment_integer(const char* name) {
  const char* text = std::getenv(name);
  char* end = nullptr;
  const long value = text != nullptr ? std::strtol(text, &end, 10) : 0;
  if (text == nullptr || *text == '\0' || *end != '\0' || value < 0 || value > 1000000) {
    throw BadSweepInput(fmt::format("{} = \"{}\" is not a task number", name, text != nullptr ? text : ""));
  }
  return static_cast<int>(value);
}

}  // namespace

std::vector<std::size_t> ArrayShare::points(std::size_t total) const {
  std::vector<std::size_t> indices;
  for (std::size_t k = 0; k < total; ++k) {
    if (static_cast<int>(k % static_cast<std::size_t>(count)) == task) indices.push_back(k);
  }
  return indices;
}

std::optional<ArrayShare> array_share(std::optional<int> task, std::optional<int> count, bool mpi) {
  ArrayShare share;
  if (task || count) {
    if (!task || !count) throw BadSweepInput("--array-task and --array-count go together");
    share = {*task, *count};
  } else if (std::getenv("SLURM_ARRAY_TASK_ID") != nullptr && !mpi) {
    const int first = std::getenv("SLURM_ARRAY_TASK_MIN") != nullptr ? environment_integer("SLURM_ARRAY_TASK_MIN") : 0;
    share = {environment_integer("SLURM_ARRAY_TASK_ID") - first, environment_integer("SLURM_ARRAY_TASK_COUNT")};
  } else {
    return std::nullopt;
  }
  if (share.count < 1 || share.task < 0 || share.task >= share.count) {
    throw BadSweepInput(fmt::format("array task {} of {}: the task must be in [0, count)", share.task, share.count));
  }
  return share;
}

}  // namespace granule::sweep
