#include "fullsim/dem/ranks/merged_sink.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace feedflow {

OutletSink merge_sink_books(const OutletSink& mine, const DemRanks& ranks) {
  // Removed mass, then (time, id, mass, layer) per event.
  std::vector<double> books{mine.removed_mass()};
  for (const SinkEvent& e : mine.events())
    books.insert(books.end(), {e.time, static_cast<double>(e.id), e.mass, e.layer});
  double removed_mass = 0.0;
  std::vector<SinkEvent> events;
  for (const std::vector<double>& from : ranks.all_gather(books)) {
    removed_mass += from[0];
    for (std::size_t k = 1; k + 4 <= from.size(); k += 4)
      events.push_back({from[k], static_cast<std::uint32_t>(from[k + 1]), from[k + 2], from[k + 3]});
  }
  std::sort(events.begin(), events.end(), [](const SinkEvent& a, const SinkEvent& b) {
    return a.time != b.time ? a.time < b.time : a.id < b.id;
  });
  return OutletSink::restored(mine.is_box(), mine.lower_or_point(), mine.upper_or_outward(),
                              removed_mass, std::move(events));
}

}  // namespace feedflow
