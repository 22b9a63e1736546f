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

std::vector<std::string> SweepRanks::gather_to_lead(const std::string& text) const {
  if (size_ == 1) return {text};
  // Lengths first, then the characters of all ranks in one buffer.
  int length = static_cast<int>(text.size());
  std::vector<int> lengths(rank_ == 0 ? size_ : 0), offsets(rank_ == 0 ? size_ : 0);
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  int total = 0;
  for (std::size_t r = 0; r < lengths.size(); ++r) {
    offsets[r] = total;
    total += lengths[r];
  }
  std::string buffer(static_cast<std::size_t>(total), '\0');
  MPI_Gatherv(text.data(), length, MPI_CHAR, buffer.data(), lengths.data(), offsets.data(), MPI_CHAR, 0,
              MPI_COMM_WORLD);
  std::vector<std::string> texts;
  for (std::size_t r = 0; r < lengths.size(); ++r) {
    texts.push_back(buffer.substr(static_cast<std::size_t>(offsets[r]), static_cast<std::size_t>(lengths[r])));
  }
  return texts;
}

#else

SweepRanks::SweepRanks() = default;
SweepRanks::~SweepRanks() = default;
void SweepRanks::barrier() const {}
int SweepRanks::broadcast(int value) const { return value; }
std::vector<int> SweepRanks::max_over_ranks(const std::vector<int>& values) const { return values; }
std::vector<std::string> SweepRanks::gather_to_lead(const std::string& text) const { return {text}; }

#endif

}  // namespace limber::app
