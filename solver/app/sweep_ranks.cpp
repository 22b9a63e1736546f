#include "app/sweep_ranks.h"

#include <cstdlib>

#ifdef LIMBER_WITH_MPI
// The C API only: Open MPI's and MPICH's deprecated C++ bindings need their own library.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace limber::app {

#ifdef LIMBER_WITH_MPI

namespace {

// Open MPI's mpirun, and PMI/PMIx launchers (Slurm's srun), set these.
bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"}) {
    if (std::getenv(name)) return true;
  }
  return false;
}

}  // namespace

SweepRanks::SweepRanks() {
  if (!launched_by_mpi()) return;
  int already = 0;
  MPI_Initialized(&already);
  if (!already) MPI_Init(nullptr, nullptr);
  initialised_ = !already;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

SweepRanks::~SweepRanks() {
  if (initialised_) MPI_Finalize();
}

void SweepRanks::barrier() const {
  if (size_ > 1) MPI_Barrier(MPI_COMM_WORLD);
}

int SweepRanks::broadcast(int value) const {
  if (size_ > 1) MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return value;
}

std::vector<int> SweepRanks::max_over_ranks(const std::vector<int>& values) const {
  std::vector<int> result = values;
  if (size_ > 1 && !values.empty()) {
    MPI_Allreduce(values.data(), result.data(), static_cast<int>(values.size()), MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  }
  return result;
}

#else

SweepRanks::SweepRanks() = default;
SweepRanks::~SweepRanks() = default;
void SweepRanks::barrier() const {}
int SweepRanks::broadcast(int value) const { return value; }
std::vector<int> SweepRanks::max_over_ranks(const std::vector<int>& values) const { return values; }

#endif

}  // namespace limber::app
