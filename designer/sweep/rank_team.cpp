#include "designer/sweep/rank_team.hpp"

#include <mpi.h>

#include <cstdlib>

namespace feedflow {
namespace {

// A launcher leaves its rank in the environment: Open MPI's mpirun, PMIx (srun, prterun), PMI.
bool started_by_launcher() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(v)) return true;
  return false;
}

}  // namespace

RankTeam& RankTeam::world() {
  static RankTeam team;
  return team;
}

RankTeam::RankTeam() {
  if (!started_by_launcher()) return;
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised) {
    int provided = MPI_THREAD_SINGLE;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_MULTIPLE, &provided);
    threads_may_call_ = provided >= MPI_THREAD_SERIALIZED;
    mpi_ = true;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

RankTeam::~RankTeam() {
  int finalised = 0;
  MPI_Finalized(&finalised);
  if (mpi_ && !finalised) MPI_Finalize();
}

std::vector<std::string> RankTeam::gather(const std::string& mine) const {
  if (size_ == 1) return {mine};
  const int length = static_cast<int>(mine.size());
  std::vector<int> lengths(rank_ == 0 ? size_ : 0), offsets(lengths.size());
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::string all;
  if (rank_ == 0) {
    long long total = 0;
    for (int r = 0; r < size_; ++r) {
      offsets[r] = static_cast<int>(total);
      total += lengths[r];
    }
    all.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(mine.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR,
              0, MPI_COMM_WORLD);
  std::vector<std::string> texts;
  for (int r = 0; rank_ == 0 && r < size_; ++r) texts.push_back(all.substr(offsets[r], lengths[r]));
  return texts;
}

long long RankTeam::broadcast(long long value) const {
  if (size_ > 1) MPI_Bcast(&value, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  return value;
}

}  // namespace feedflow
