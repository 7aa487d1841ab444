#include "designer/sweep/point_queue.hpp"

#include <mpi.h>

#include <chrono>

namespace feedflow {
namespace {

constexpr int kAskTag = 7301, kReplyTag = 7302;
constexpr long long kAsk = 0, kQuit = 1, kNoMore = -1;

}  // namespace

PointQueue::PointQueue(const RankTeam& team, std::size_t count) : team_(team), count_(count) {
  dynamic_ = team.size() > 1 && team.threads_may_call();
  if (dynamic_ && team.root()) server_ = std::thread([this] { serve(); });
}

void PointQueue::serve() {
  int remaining = team_.size() - 1;  // ranks not yet told "no more" nor stopped
  while (remaining > 0) {
    int waiting = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kAskTag, MPI_COMM_WORLD, &waiting, &status);
    if (!waiting) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      continue;
    }
    long long message = 0;
    MPI_Recv(&message, 1, MPI_LONG_LONG, status.MPI_SOURCE, kAskTag, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    if (message == kQuit) {
      --remaining;
      continue;
    }
    const std::size_t position = next_++;
    long long reply = position < count_ ? static_cast<long long>(position) : kNoMore;
    MPI_Send(&reply, 1, MPI_LONG_LONG, status.MPI_SOURCE, kReplyTag, MPI_COMM_WORLD);
    if (reply == kNoMore) --remaining;
  }
}

std::optional<std::size_t> PointQueue::next() {
  if (stopped_) return std::nullopt;
  if (team_.size() == 1 || (dynamic_ && team_.root())) {
    const std::size_t position = next_++;
    if (position < count_) return position;
    stopped_ = true;
    return std::nullopt;
  }
  if (!dynamic_) {  // round-robin: this rank's k-th position
    const std::size_t position = dealt_++ * team_.size() + team_.rank();
    next_ = dealt_;
    if (position < count_) return position;
    stopped_ = true;
    return std::nullopt;
  }
  long long reply = kNoMore;
  MPI_Send(&kAsk, 1, MPI_LONG_LONG, 0, kAskTag, MPI_COMM_WORLD);
  MPI_Recv(&reply, 1, MPI_LONG_LONG, 0, kReplyTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  if (reply == kNoMore) {
    stopped_ = true;  // the root counted this rank out
    return std::nullopt;
  }
  ++next_;
  return static_cast<std::size_t>(reply);
}

void PointQueue::stop() {
  if (stopped_) return;
  stopped_ = true;
  if (dynamic_ && !team_.root()) MPI_Send(&kQuit, 1, MPI_LONG_LONG, 0, kAskTag, MPI_COMM_WORLD);
}

PointQueue::~PointQueue() {
  if (server_.joinable()) server_.join();
  // A remote rank that never asked again still has to be counted out: it does so in stop().
}

}  // namespace feedflow
