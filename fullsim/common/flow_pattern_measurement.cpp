#include "fullsim/common/flow_pattern_measurement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>

namespace feedflow {

WallSpeedRatio wall_to_centre_speed_ratio(const SpeedProfile& line) {
  WallSpeedRatio r;
  // A line with fewer points than kMinProfilePoints has no wall and centre to compare (a funnel
  // that emptied the centre of the line leaves a point or two at the wall: read as its own
  // centre, it gave a ratio of exactly 1, "mass").
  if (line.speed.size() < kMinProfilePoints || !(line.speed.front() > 0.0)) return r;
  r.ratio = line.speed.back() / line.speed.front();
  r.measured = true;
  const double moving = kMassFlowSpeedRatio * line.speed.front();
  std::size_t k = line.speed.size() - 1;
  while (k > 0 && !(line.speed[k] > moving)) --k;
  r.stagnant_width = line.offset.back() - line.offset[k];
  return r;
}

void SpeedProfileSeries::add(double time, const SpeedProfile& line) {
  time_.push_back(time);
  first_.push_back(offset_.size());
  offset_.insert(offset_.end(), line.offset.begin(), line.offset.end());
  speed_.insert(speed_.end(), line.speed.begin(), line.speed.end());
}

WallSpeedRatio SpeedProfileSeries::ratio(double from, double to) const {
  std::map<long, std::pair<double, std::size_t>> points;  // offset (um) -> speed sum, samples
  std::size_t samples = 0;
  for (std::size_t k = 0; k < time_.size(); ++k) {
    if (time_[k] < from || time_[k] > to) continue;
    ++samples;
    for (std::size_t i = first_[k]; i < end_of(k); ++i) {
      auto& p = points[std::lround(offset_[i] * 1e6)];
      p.first += speed_[i];
      ++p.second;
    }
  }
  SpeedProfile mean;
  for (const auto& [offset, p] : points)
    if (2 * p.second >= samples) {
      mean.offset.push_back(static_cast<double>(offset) * 1e-6);
      mean.speed.push_back(p.first / static_cast<double>(p.second));
    }
  return wall_to_centre_speed_ratio(mean);
}

double SpeedProfileSeries::covered_until(double from, double to) const {
  auto points = [this](std::size_t k) { return end_of(k) - first_[k]; };
  std::size_t fullest = 0;
  for (std::size_t k = 0; k < time_.size(); ++k)
    if (time_[k] >= from && time_[k] <= to) fullest = std::max(fullest, points(k));
  double until = from;
  for (std::size_t k = 0; k < time_.size(); ++k) {
    if (time_[k] < from || time_[k] > to) continue;
    if (2 * points(k) < fullest) return until;
    until = time_[k];
  }
  return to;
}

void SpeedProfileSeries::save(Hdf5File& f, const std::string& group) const {
  f.create_group(group);
  f.write(group + "/time", time_, {time_.size()}, "s");
  std::vector<std::uint64_t> first(first_.begin(), first_.end());
  f.write(group + "/first", first, {first.size()}, "1");
  f.write(group + "/offset", offset_, {offset_.size()}, "m");
  f.write(group + "/speed", speed_, {speed_.size()}, "m/s");
}

void SpeedProfileSeries::restore(const Hdf5File& f, const std::string& group) {
  time_ = f.read<double>(group + "/time");
  const auto first = f.read<std::uint64_t>(group + "/first", {time_.size()});
  first_.assign(first.begin(), first.end());
  offset_ = f.read<double>(group + "/offset");
  speed_ = f.read<double>(group + "/speed", {offset_.size()});
}

}  // namespace feedflow
