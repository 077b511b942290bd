#include "sweep/mpi_points.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <chrono>
#include <numeric>
#include <thread>

namespace granule::sweep {

namespace {

constexpr int kReportTag = 1;  // worker → rank 0: {point run (−1: none yet), stopping (0/1)}
constexpr int kAssignTag = 2;  // rank 0 → worker: the next point, −1: no more

void coordinate(const SweepRun& run, const MpiWorld& world) {
  const auto points = static_cast<int>(run.spec->points.size());
  int next = 0;
  int active = world.size - 1;
  while (active > 0) {
    // MPI_Recv spins a core while it waits in OpenMPI; the workers' runs need the cores.
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kReportTag, MPI_COMM_WORLD, &arrived, &status);
    if (arrived == 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      continue;
    }
    int report[2] = {-1, 0};
    MPI_Recv(report, 2, MPI_INT, status.MPI_SOURCE, kReportTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (report[0] >= 0) {
      const SweepPoint& point = run.spec->points[static_cast<std::size_t>(report[0])];
      fmt::print("{}\n", progress_line(point, current_record(run.dir, point), false));
      std::fflush(stdout);
    }
    if (report[1] != 0) {
      --active;
      continue;
    }
    // Points done before are skipped here, so that they neither occupy a worker nor print twice.
    for (; next < points; ++next) {
      const SweepPoint& candidate = run.spec->points[static_cast<std::size_t>(next)];
      const PointRecord earlier = current_record(run.dir, candidate);
      if (!is_done(earlier)) break;
      fmt::print("{}\n", progress_line(candidate, earlier, true));
    }
    int assignment = *run.interrupt == 0 && next < points ? next++ : -1;
    MPI_Send(&assignment, 1, MPI_INT, status.MPI_SOURCE, kAssignTag, MPI_COMM_WORLD);
    if (assignment < 0) --active;
  }
}

void work(const SweepRun& run) {
  int report[2] = {-1, 0};
  while (true) {
    MPI_Send(report, 2, MPI_INT, 0, kReportTag, MPI_COMM_WORLD);
    if (report[1] != 0) return;
    int assignment = -1;
    MPI_Recv(&assignment, 1, MPI_INT, 0, kAssignTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (assignment < 0) return;
    run_points(run, {static_cast<std::size_t>(assignment)}, 1, false);
    report[0] = assignment;
    report[1] = *run.interrupt != 0 ? 1 : 0;
  }
}

}  // namespace

MpiSession::MpiSession() {
  MPI_Init(nullptr, nullptr);
  MPI_Comm_rank(MPI_COMM_WORLD, &world_.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &world_.size);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

int MpiSession::broadcast(int value) const {
  MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return value;
}

void run_points_over_mpi(const SweepRun& run, const MpiWorld& world) {
  if (world.size == 1) {
    std::vector<std::size_t> all(run.spec->points.size());
    std::iota(all.begin(), all.end(), std::size_t{0});
    run_points(run, all, 1, true);
  } else if (world.rank == 0) {
    coordinate(run, world);
  } else {
    work(run);
  }
}

}  // namespace granule::sweep
