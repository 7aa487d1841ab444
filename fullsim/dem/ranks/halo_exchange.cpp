#include "fullsim/dem/ranks/halo_exchange.hpp"

#include <algorithm>
#include <numeric>

#include "fullsim/dem/ranks/particle_record.hpp"

namespace feedflow {
namespace {

// Message tags: one per exchange of a step or a rebuild (exchange() uses tag and tag + 1).
constexpr int kForwardTag = 100, kReverseTag = 200, kMigrateTag = 300, kGhostTag = 400;

constexpr std::size_t kGhostRecord = 13;   // id, x, v, w, radius, mass, inertia
constexpr std::size_t kForwardRecord = 9;  // x, v, w
constexpr std::size_t kReverseRecord = 6;  // force, torque


}  // namespace

void HaloExchange::drop_ghosts(ParticleStore& p) {
  if (!initialised_) owned_ = p.size();
  p.resize(owned_);
  ghosts_ = 0;
}

std::size_t HaloExchange::migrate(ParticleStore& p, NeighbourList& list, const RankDomains& domains,
                                  const DemRanks& ranks) {
  drop_ghosts(p);
  const std::size_t n = p.size();
  const std::size_t h = list.history_size();
  std::vector<int> others;
  for (int r = 0; r < ranks.size(); ++r)
    if (r != ranks.rank()) others.push_back(r);
  std::vector<std::vector<double>> out(others.size());
  std::vector<int> owner(n);
  std::size_t left = 0;
  for (std::size_t k = 0; k < n; ++k) {
    owner[k] = domains.owner(p.position[k]);
    left += owner[k] != ranks.rank();
  }
  // The contacts with history (when any particle leaves), by id pair, to find those listed under a
  // leaving particle.
  const std::vector<std::uint64_t>& keys = list.entry_keys();
  std::vector<std::uint32_t> with_history;
  for (std::size_t e = 0; left > 0 && e < keys.size(); ++e) {
    const double* v = list.history.data() + e * h;
    if (std::any_of(v, v + h, [](double x) { return x != 0.0; }))
      with_history.push_back(static_cast<std::uint32_t>(e));
  }
  std::sort(with_history.begin(), with_history.end(),
            [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });

  std::vector<char> leaving(n, 0);
  for (std::size_t k = 0; k < n; ++k) {
    if (owner[k] == ranks.rank()) continue;
    leaving[k] = 1;
    auto& o = out[static_cast<std::size_t>(owner[k] < ranks.rank() ? owner[k] : owner[k] - 1)];
    put_particle(o, p, k);
    const std::uint64_t lowest = static_cast<std::uint64_t>(p.id[k]) << 32;
    auto it = std::lower_bound(with_history.begin(), with_history.end(), lowest,
                               [&](std::uint32_t e, std::uint64_t key) { return keys[e] < key; });
    auto end = it;
    while (end != with_history.end() && (keys[*end] >> 32) == p.id[k]) ++end;
    o.push_back(static_cast<double>(end - it));
    for (; it != end; ++it) {
      o.push_back(static_cast<double>(keys[*it] & 0xffffffffu));
      o.insert(o.end(), list.history.begin() + static_cast<std::ptrdiff_t>(*it * h),
               list.history.begin() + static_cast<std::ptrdiff_t>((*it + 1) * h));
    }
  }
  if (left > 0) p.remove_flagged(leaving);
  for (const auto& o : out) rebuild_doubles_ += static_cast<double>(o.size());
  const auto in = ranks.exchange(others, out, kMigrateTag);
  for (const auto& from : in) {
    const double* q = from.data();
    const double* end = q + from.size();
    while (q < end) {
      take_particle(q, p);
      const std::uint32_t id = p.id.back();
      const auto contacts = static_cast<std::size_t>(*q++);
      for (std::size_t c = 0; c < contacts; ++c) {
        const auto partner = static_cast<std::uint64_t>(*q++);
        list.import_history(static_cast<std::uint64_t>(id) << 32 | partner, q);
        q += h;
      }
    }
  }
  owned_ = p.size();
  initialised_ = true;
  return left;
}

void HaloExchange::build_ghosts(ParticleStore& p, const RankDomains& domains, double reach,
                                const DemRanks& ranks) {
  drop_ghosts(p);
  initialised_ = true;
  neighbours_ = domains.neighbours(ranks.rank(), reach);
  const std::size_t m = neighbours_.size();
  sent_.assign(m, {});
  std::vector<std::vector<double>> out(m);
  const double reach2 = reach * reach;
  for (std::size_t s = 0; s < m; ++s)
    for (std::size_t k = 0; k < owned_; ++k) {
      if (!(domains.distance2(p.position[k], neighbours_[s]) < reach2)) continue;
      sent_[s].push_back(static_cast<std::uint32_t>(k));
      auto& o = out[s];
      o.push_back(static_cast<double>(p.id[k]));
      put_vec3(o, p.position[k]);
      put_vec3(o, p.velocity[k]);
      put_vec3(o, p.angular_velocity[k]);
      o.insert(o.end(), {p.radius[k], p.mass[k], p.inertia[k]});
      rebuild_doubles_ += kGhostRecord;
    }
  const auto in = ranks.exchange(neighbours_, out, kGhostTag);
  ghost_first_.assign(m, 0);
  ghost_count_.assign(m, 0);
  std::size_t total = owned_;
  for (std::size_t s = 0; s < m; ++s) {
    ghost_first_[s] = total;
    ghost_count_[s] = in[s].size() / kGhostRecord;
    total += ghost_count_[s];
  }
  p.resize(total);
  for (std::size_t s = 0; s < m; ++s) {
    const double* q = in[s].data();
    for (std::size_t g = 0; g < ghost_count_[s]; ++g) {
      const std::size_t k = ghost_first_[s] + g;
      p.id[k] = static_cast<std::uint32_t>(*q++);
      p.position[k] = take_vec3(q);
      p.velocity[k] = take_vec3(q);
      p.angular_velocity[k] = take_vec3(q);
      p.radius[k] = *q++;
      p.mass[k] = *q++;
      p.inertia[k] = *q++;
    }
  }
  ghosts_ = total - owned_;
  out_.assign(m, {});
  in_.assign(m, {});
}

void HaloExchange::forward(ParticleStore& p, const DemRanks& ranks) {
  const std::size_t m = neighbours_.size();
  for (std::size_t s = 0; s < m; ++s) {
    auto& o = out_[s];
    o.resize(sent_[s].size() * kForwardRecord);
    double* q = o.data();
    for (std::uint32_t k : sent_[s]) {
      for (const Vec3* v : {&p.position[k], &p.velocity[k], &p.angular_velocity[k]}) {
        q[0] = v->x();
        q[1] = v->y();
        q[2] = v->z();
        q += 3;
      }
    }
    in_[s].resize(ghost_count_[s] * kForwardRecord);
    step_doubles_ += static_cast<double>(o.size());
  }
  ranks.exchange_into(neighbours_, out_, in_, kForwardTag);
  for (std::size_t s = 0; s < m; ++s) {
    const double* q = in_[s].data();
    for (std::size_t g = 0; g < ghost_count_[s]; ++g) {
      const std::size_t k = ghost_first_[s] + g;
      p.position[k] = take_vec3(q);
      p.velocity[k] = take_vec3(q);
      p.angular_velocity[k] = take_vec3(q);
    }
  }
}

void HaloExchange::reverse(ParticleStore& p, const DemRanks& ranks) {
  const std::size_t m = neighbours_.size();
  for (std::size_t s = 0; s < m; ++s) {
    auto& o = out_[s];
    o.resize(ghost_count_[s] * kReverseRecord);
    double* q = o.data();
    for (std::size_t g = 0; g < ghost_count_[s]; ++g) {
      const std::size_t k = ghost_first_[s] + g;
      for (Vec3* v : {&p.force[k], &p.torque[k]}) {
        q[0] = v->x();
        q[1] = v->y();
        q[2] = v->z();
        q += 3;
        v->setZero();
      }
    }
    in_[s].resize(sent_[s].size() * kReverseRecord);
    step_doubles_ += static_cast<double>(o.size());
  }
  ranks.exchange_into(neighbours_, out_, in_, kReverseTag);
  for (std::size_t s = 0; s < m; ++s) {
    const double* q = in_[s].data();
    for (std::uint32_t k : sent_[s]) {
      p.force[k] += take_vec3(q);
      p.torque[k] += take_vec3(q);
    }
  }
}

}  // namespace feedflow
