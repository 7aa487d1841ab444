#include "fullsim/dem/ranks/dem_ranks.hpp"

#include <mpi.h>

#include <algorithm>

namespace feedflow {

DemRanks DemRanks::world() {
  DemRanks r;
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  if (!initialised || finalised) return r;
  MPI_Comm_rank(MPI_COMM_WORLD, &r.rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &r.size_);
  r.mpi_ = r.size_ > 1;
  return r;
}

void DemRanks::sum(std::vector<double>& values) const {
  if (mpi_)
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM,
                  MPI_COMM_WORLD);
}

void DemRanks::max(std::vector<double>& values) const {
  if (mpi_)
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MAX,
                  MPI_COMM_WORLD);
}

double DemRanks::sum(double value) const {
  if (mpi_) MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  return value;
}

double DemRanks::max(double value) const {
  if (mpi_) MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return value;
}

double DemRanks::min(double value) const {
  if (mpi_) MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  return value;
}

namespace {

// MPI's reduction of two sets of per-bin lists (a bin's list is the datatype: k doubles in
// descending order): `inout` gets the k largest of both.
void merge_highest(void* in, void* inout, int* bins, MPI_Datatype* list) {
  int bytes = 0;
  MPI_Type_size(*list, &bytes);
  const std::size_t k = static_cast<std::size_t>(bytes) / sizeof(double);
  const double* a = static_cast<const double*>(in);
  double* b = static_cast<double*>(inout);
  std::vector<double> merged(k);
  for (int bin = 0; bin < *bins; ++bin, a += k, b += k) {
    std::size_t i = 0, j = 0;
    for (double& m : merged) m = (j == k || (i < k && a[i] >= b[j])) ? a[i++] : b[j++];
    std::copy(merged.begin(), merged.end(), b);
  }
}

}  // namespace

void DemRanks::highest(std::vector<double>& tops, std::size_t k) const {
  if (!mpi_ || k == 0 || tops.empty()) return;
  MPI_Datatype list;
  MPI_Type_contiguous(static_cast<int>(k), MPI_DOUBLE, &list);
  MPI_Type_commit(&list);
  MPI_Op op;
  MPI_Op_create(&merge_highest, 1, &op);
  MPI_Allreduce(MPI_IN_PLACE, tops.data(), static_cast<int>(tops.size() / k), list, op,
                MPI_COMM_WORLD);
  MPI_Op_free(&op);
  MPI_Type_free(&list);
}

void DemRanks::exchange_into(const std::vector<int>& ranks,
                             const std::vector<std::vector<double>>& send,
                             std::vector<std::vector<double>>& recv, int tag) const {
  if (ranks.empty()) return;
  std::vector<MPI_Request> requests(2 * ranks.size());
  for (std::size_t k = 0; k < ranks.size(); ++k)
    MPI_Irecv(recv[k].data(), static_cast<int>(recv[k].size()), MPI_DOUBLE, ranks[k], tag,
              MPI_COMM_WORLD, &requests[2 * k]);
  for (std::size_t k = 0; k < ranks.size(); ++k)
    MPI_Isend(send[k].data(), static_cast<int>(send[k].size()), MPI_DOUBLE, ranks[k], tag,
              MPI_COMM_WORLD, &requests[2 * k + 1]);
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
}

std::vector<std::vector<double>> DemRanks::exchange(const std::vector<int>& ranks,
                                                    const std::vector<std::vector<double>>& send,
                                                    int tag) const {
  // The sizes first, then the records.
  std::vector<std::vector<double>> sizes_out(ranks.size()),
      sizes_in(ranks.size(), std::vector<double>(1));
  for (std::size_t k = 0; k < ranks.size(); ++k)
    sizes_out[k] = {static_cast<double>(send[k].size())};
  exchange_into(ranks, sizes_out, sizes_in, tag);
  std::vector<std::vector<double>> recv(ranks.size());
  for (std::size_t k = 0; k < ranks.size(); ++k)
    recv[k].resize(static_cast<std::size_t>(sizes_in[k][0]));
  exchange_into(ranks, send, recv, tag + 1);
  return recv;
}

namespace {

// Splits the concatenated vectors of every rank.
std::vector<std::vector<double>> split(const std::vector<double>& all, const std::vector<int>& lengths,
                                       const std::vector<int>& offsets) {
  std::vector<std::vector<double>> out;
  for (std::size_t r = 0; r < lengths.size(); ++r)
    out.emplace_back(all.begin() + offsets[r], all.begin() + offsets[r] + lengths[r]);
  return out;
}

// The offsets of vectors of these lengths laid end to end; returns the total.
int lay_out(const std::vector<int>& lengths, std::vector<int>& offsets) {
  offsets.assign(lengths.size(), 0);
  int total = 0;
  for (std::size_t r = 0; r < lengths.size(); ++r) {
    offsets[r] = total;
    total += lengths[r];
  }
  return total;
}

}  // namespace

std::vector<std::vector<double>> DemRanks::all_gather(const std::vector<double>& mine) const {
  if (!mpi_) return {mine};
  const int length = static_cast<int>(mine.size());
  std::vector<int> lengths(static_cast<std::size_t>(size_)), offsets;
  MPI_Allgather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, MPI_COMM_WORLD);
  std::vector<double> all(static_cast<std::size_t>(lay_out(lengths, offsets)));
  MPI_Allgatherv(mine.data(), length, MPI_DOUBLE, all.data(), lengths.data(), offsets.data(),
                 MPI_DOUBLE, MPI_COMM_WORLD);
  return split(all, lengths, offsets);
}

std::vector<std::vector<double>> DemRanks::gather(const std::vector<double>& mine) const {
  if (!mpi_) return {mine};
  const int length = static_cast<int>(mine.size());
  std::vector<int> lengths(static_cast<std::size_t>(size_)), offsets;
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<double> all(rank_ == 0 ? static_cast<std::size_t>(lay_out(lengths, offsets)) : 0);
  MPI_Gatherv(mine.data(), length, MPI_DOUBLE, all.data(), lengths.data(), offsets.data(),
              MPI_DOUBLE, 0, MPI_COMM_WORLD);
  if (rank_ != 0) return {};
  return split(all, lengths, offsets);
}

std::optional<std::string> DemRanks::agree_on_failure(
    const std::optional<std::string>& mine) const {
  if (!mpi_) return mine;
  int failing = mine ? rank_ : size_;
  MPI_Allreduce(MPI_IN_PLACE, &failing, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (failing == size_) return std::nullopt;
  int length = failing == rank_ ? static_cast<int>(mine->size()) : 0;
  MPI_Bcast(&length, 1, MPI_INT, failing, MPI_COMM_WORLD);
  std::string text = failing == rank_ ? *mine : std::string(static_cast<std::size_t>(length), ' ');
  MPI_Bcast(text.data(), length, MPI_CHAR, failing, MPI_COMM_WORLD);
  if (failing != rank_) text = "on rank " + std::to_string(failing) + ": " + text;
  return text;
}

}  // namespace feedflow
