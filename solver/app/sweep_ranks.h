// The ranks of an MPI job for `limber sweep` (docs/sweep.md, "On a cluster"): under `mpirun -n
// N limber sweep ...` (or Slurm's srun) every rank runs its share of the grid and rank 0
// gathers the rows and writes the table. Built with MPI when CMake's LIMBER_WITH_MPI is on (the default where MPI
// is found); MPI is initialised only when the process was started by an MPI launcher (its
// environment says so), so a plain `limber sweep` never touches MPI. Without MPI: one rank.
#pragma once

#include <string>
#include <vector>

namespace limber::app {

class SweepRanks {
 public:
  SweepRanks();   // MPI_Init when launched by mpirun / srun
  ~SweepRanks();  // MPI_Finalize when initialised
  SweepRanks(const SweepRanks&) = delete;
  SweepRanks& operator=(const SweepRanks&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

  void barrier() const;
  // Rank 0's value on every rank.
  int broadcast(int value) const;
  // The element-wise maximum over the ranks, on every rank.
  std::vector<int> max_over_ranks(const std::vector<int>& values) const;
  // Every rank's `text`, on rank 0 in rank order; empty on the other ranks.
  std::vector<std::string> gather_to_lead(const std::string& text) const;

 private:
  bool initialised_ = false;
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace limber::app
