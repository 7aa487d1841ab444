#pragma once
// Hands a sweep's points to the ranks of a team as they become free: positions 0, 1, 2, ... of
// an order (the longest expected first), each to exactly one rank. Rank 0 runs points too; a
// helper thread of rank 0 answers the other ranks' requests between them (polling, so it takes
// no core). Where MPI grants no threads, the positions are dealt round-robin instead.
#include <atomic>
#include <cstddef>
#include <optional>
#include <thread>

#include "designer/sweep/rank_team.hpp"

namespace feedflow {

class PointQueue {
 public:
  PointQueue(const RankTeam& team, std::size_t count);
  // The next position for this rank; none when every position is handed out or stop() was called.
  std::optional<std::size_t> next();
  // This rank takes no more points (it was interrupted).
  void stop();
  // Positions handed out so far (rank 0's count; other ranks: their own).
  std::size_t handed_out() const { return next_.load(); }
  // Rank 0 waits until every other rank has been told there is no more, or has stopped.
  ~PointQueue();

  PointQueue(const PointQueue&) = delete;
  PointQueue& operator=(const PointQueue&) = delete;

 private:
  void serve();
  const RankTeam& team_;
  std::size_t count_;
  std::atomic<std::size_t> next_{0};
  std::size_t dealt_ = 0;  // round-robin: this rank's positions taken
  bool stopped_ = false, dynamic_ = false;
  std::thread server_;
};

}  // namespace feedflow
