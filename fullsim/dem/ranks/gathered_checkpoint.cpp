#include "fullsim/dem/ranks/gathered_checkpoint.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "fullsim/dem/ranks/merged_sink.hpp"
#include "fullsim/dem/ranks/particle_record.hpp"

namespace feedflow {
namespace {

// Per own particle: the particle, its position at the last rebuild, its row (partner id and
// history per entry).
std::vector<double> pack(const DemCheckpoint& c, std::size_t owned) {
  const ParticleStore& p = c.particles;
  const NeighbourList& list = c.neighbours;
  const std::size_t h = list.history_size();
  std::vector<double> out;
  out.push_back(static_cast<double>(owned));
  for (std::size_t k = 0; k < owned; ++k) {
    put_particle(out, p, k);
    put_vec3(out, list.reference_positions()[k]);
    out.push_back(static_cast<double>(list.first[k + 1] - list.first[k]));
    for (std::uint32_t e = list.first[k]; e < list.first[k + 1]; ++e) {
      out.push_back(static_cast<double>(p.id[list.partner[e]]));
      out.insert(out.end(), list.history.begin() + static_cast<std::ptrdiff_t>(e * h),
                 list.history.begin() + static_cast<std::ptrdiff_t>((e + 1) * h));
    }
  }
  return out;
}

}  // namespace

DemCheckpoint gather_checkpoint(DemCheckpoint mine, std::size_t owned, const DemRanks& ranks) {
  const std::size_t h = mine.neighbours.history_size();
  const auto all = ranks.all_gather(pack(mine, owned));
  ParticleStore gathered;
  gathered.set_wall_history_stride(mine.particles.wall_history_stride());
  gathered.set_next_id(mine.particles.next_id());
  std::vector<Vec3> reference;
  struct Entry {
    std::uint32_t row;
    std::uint32_t partner_id;
    std::size_t history;  // offset in the message
    std::size_t from;     // rank
  };
  std::vector<Entry> entries;
  for (std::size_t r = 0; r < all.size(); ++r) {
    const double* q = all[r].data();
    const auto count = static_cast<std::size_t>(*q++);
    for (std::size_t k = 0; k < count; ++k) {
      take_particle(q, gathered);
      reference.push_back(take_vec3(q));
      const auto row = static_cast<std::size_t>(*q++);
      for (std::size_t e = 0; e < row; ++e) {
        entries.push_back({static_cast<std::uint32_t>(gathered.size() - 1),
                           static_cast<std::uint32_t>(*q),
                           static_cast<std::size_t>(q + 1 - all[r].data()), r});
        q += 1 + h;
      }
    }
  }
  if (mine.sink) mine.sink = merge_sink_books(*mine.sink, ranks);

  // The rows in slot order, partners by id.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> slot_of_id(gathered.size());
  for (std::size_t k = 0; k < gathered.size(); ++k)
    slot_of_id[k] = {gathered.id[k], static_cast<std::uint32_t>(k)};
  std::sort(slot_of_id.begin(), slot_of_id.end());
  std::vector<std::uint32_t> first(gathered.size() + 1, 0), partner;
  std::vector<std::uint64_t> keys;
  std::vector<double> history;
  partner.reserve(entries.size());
  keys.reserve(entries.size());
  history.reserve(entries.size() * h);
  std::size_t e = 0;
  for (std::size_t k = 0; k < gathered.size(); ++k) {
    first[k] = static_cast<std::uint32_t>(partner.size());
    for (; e < entries.size() && entries[e].row == k; ++e) {
      const Entry& entry = entries[e];
      auto it = std::lower_bound(slot_of_id.begin(), slot_of_id.end(),
                                 std::make_pair(entry.partner_id, std::uint32_t{0}));
      if (it == slot_of_id.end() || it->first != entry.partner_id)
        throw std::logic_error("gather_checkpoint: the partner " +
                               std::to_string(entry.partner_id) + " of particle " +
                               std::to_string(gathered.id[k]) + " is owned by no rank");
      partner.push_back(it->second);
      keys.push_back(static_cast<std::uint64_t>(gathered.id[k]) << 32 | entry.partner_id);
      const double* v = all[entry.from].data() + entry.history;
      history.insert(history.end(), v, v + h);
    }
  }
  first[gathered.size()] = static_cast<std::uint32_t>(partner.size());

  const NeighbourList& list = mine.neighbours;
  mine.neighbours = NeighbourList::restored(
      list.skin(), h, list.cell_size(), list.rebuild_count(),
      static_cast<std::size_t>(ranks.sum(static_cast<double>(list.carried_over()))),
      std::move(first), std::move(partner), std::move(history), std::move(keys),
      std::move(reference));
  mine.particles = std::move(gathered);
  return mine;
}

}  // namespace feedflow
