#pragma once
// The processes a sweep's full-rung points are shared among: MPI's world when the program was
// started by a launcher (mpirun, mpiexec, srun), else a team of one. MPI is initialised only
// under a launcher, so the same binary runs without one as it always has.
#include <string>
#include <vector>

namespace feedflow {

class RankTeam {
 public:
  // The team of this process (MPI initialised on first use under a launcher; finalised at exit).
  static RankTeam& world();

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool root() const { return rank_ == 0; }
  // Whether a helper thread of rank 0 may talk MPI while its main thread runs points
  // (MPI_THREAD_SERIALIZED or better was granted).
  bool threads_may_call() const { return threads_may_call_; }

  // Every rank's text, in rank order, at rank 0; the others get nothing back.
  std::vector<std::string> gather(const std::string& mine) const;
  // Rank 0's number at every rank.
  long long broadcast(long long value) const;

  RankTeam(const RankTeam&) = delete;
  RankTeam& operator=(const RankTeam&) = delete;
  ~RankTeam();

 private:
  RankTeam();
  int rank_ = 0, size_ = 1;
  bool mpi_ = false, threads_may_call_ = true;
};

}  // namespace feedflow
