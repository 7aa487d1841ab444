#pragma once
// The ranks a DEM run is shared among (an MPI communicator), and the few collective operations
// the engine needs: sums and maxima of a handful of numbers per step, the exchange of particle
// records with the neighbouring ranks, and agreeing on a failure. A run given no ranks runs on
// one (DemRanks::one()): every operation is then local, and MPI need not be initialised.
// fullsim never initialises MPI; the program does (designer/), so the same binary runs alone.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace feedflow {

class DemRanks {
 public:
  // One rank: no MPI.
  static DemRanks one() { return DemRanks(); }
  // Every rank of MPI's world when MPI is initialised (by the program, under a launcher), else
  // one rank.
  static DemRanks world();

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool shared() const { return size_ > 1; }

  // Element-wise sums and maxima over the ranks, in place.
  void sum(std::vector<double>& values) const;
  void max(std::vector<double>& values) const;
  double sum(double value) const;
  double max(double value) const;
  double min(double value) const;
  // Per bin, the `k` largest values over the ranks: `tops` holds the bins' lists end to end,
  // k values each in descending order, padded with -infinity; on return each list is the k
  // largest of every rank's lists for that bin (exact: a merge, no arithmetic).
  void highest(std::vector<double>& tops, std::size_t k) const;

  // Sends send[k] to ranks[k] and returns what each of them sent back, in the order of `ranks`
  // (every rank of the list must list this one: the exchange is symmetric). Messages are tagged
  // by `tag` so two exchanges of one step cannot cross.
  std::vector<std::vector<double>> exchange(const std::vector<int>& ranks,
                                            const std::vector<std::vector<double>>& send,
                                            int tag) const;
  // In place: each of recv[k] (of the size the caller expects) is filled from ranks[k]; the
  // buffers of a step are reused, so the per-step exchanges allocate nothing.
  void exchange_into(const std::vector<int>& ranks, const std::vector<std::vector<double>>& send,
                     std::vector<std::vector<double>>& recv, int tag) const;

  // Every rank's vector, in rank order.
  std::vector<std::vector<double>> all_gather(const std::vector<double>& mine) const;
  // Every rank's vector, in rank order, on the first rank; nothing on the others.
  std::vector<std::vector<double>> gather(const std::vector<double>& mine) const;

  // A failure on any rank is one on every rank: each passes its own message (or none); all
  // get the lowest failing rank's message, prefixed with the rank when that is not theirs.
  std::optional<std::string> agree_on_failure(const std::optional<std::string>& mine) const;

 private:
  DemRanks() = default;
  int rank_ = 0, size_ = 1;
  bool mpi_ = false;
};

}  // namespace feedflow
