#include "fullsim/cel/remap_phase.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "fullsim/cel/box_walls.hpp"
#include "fullsim/cel/limited_slope.hpp"
#include "fullsim/cel/nodal_forces.hpp"
#include "fullsim/cel/plic_interface.hpp"

namespace feedflow::cel {
namespace {

// A face normal to `axis` (0: x, 1: y) between cell `lo` and cell `hi` (the next one along the
// axis): its two nodes and the two cells. `along` counts node lines along the axis (0..n; the
// box faces 0 and n have one cell outside, kOutside), `across` the cell line.
constexpr std::size_t kOutside = static_cast<std::size_t>(-1);

struct Face {
  std::size_t lo, hi, node_a, node_b;
};

Face face(const CelGrid& g, int axis, int along, int across) {
  const int n_along = axis == 0 ? g.nx : g.ny;
  const auto cell = [&](int k) {
    if (k < 0 || k >= n_along) return kOutside;
    return axis == 0 ? g.cell(k, across) : g.cell(across, k);
  };
  if (axis == 0)
    return {cell(along - 1), cell(along), g.node(along, across), g.node(along, across + 1)};
  return {cell(along - 1), cell(along), g.node(across, along), g.node(across + 1, along)};
}

std::size_t node_on_line(const CelGrid& g, int axis, int along, int across) {
  return axis == 0 ? g.node(along, across) : g.node(across, along);
}

bool is_solid(const CellFields& cells, std::size_t c) { return c != kOutside && cells.solid[c]; }

template <class T>
void zero(std::vector<T>& v, const T& z) {
  std::fill(v.begin(), v.end(), z);
}

}  // namespace

double RemapPhase::transport_volume(const CelGrid& g, const NodeFields& nodes, int axis, int along,
                                    int across, double dt, const CellFields& cells) const {
  const Face f = face(g, axis, along, across);
  // Staircase: a face of a solid cell is shut. Cut cells: a face is open by its aperture.
  const double open = cut_cells_ ? cut_cells_->aperture(axis, along, across)
                                 : (is_solid(cells, f.lo) || is_solid(cells, f.hi) ? 0.0 : 1.0);
  if (open <= 0.0) return 0.0;
  return dt * open * g.face_area(axis, along, across) * 0.5 *
         (nodes.velocity[f.node_a][axis] + nodes.velocity[f.node_b][axis]);
}

void RemapPhase::Contents::resize(std::size_t n) {
  volume.assign(n, 0.0);
  material_volume.assign(n, 0.0);
  mass.assign(n, 0.0);
  void_mass.assign(n, 0.0);
  stress_volume.assign(n, Eigen::Matrix3d::Zero());
}

double DensestState::void_ratio(const Eigen::Matrix3d& stress) const {
  return e_d0 * std::exp(-std::pow(std::max(-stress.trace(), 0.0) / h_s, n));
}

RemapOptions second_order_state(RemapOptions o) {
  o.second_order_stress = o.second_order_void_ratio = o.second_order_density = true;
  return o;
}

void RemapPhase::refresh_cell_state(const CelGrid& g, const CellFields& cells) {
  const std::size_t n = g.cell_count();
  vf_.resize(n);
  rho_.resize(n);
  e_.resize(n);
  stress_.resize(n);
  slope_cell_.resize(n);
  const auto cells_n = static_cast<long>(n);
#pragma omp parallel for schedule(static) if (cells_n > kParallelThreshold)
  for (long k = 0; k < cells_n; ++k) {
    const auto c = static_cast<std::size_t>(k);
    const double vm = now_.material_volume[c];
    const bool filled = vm > 0.0 && now_.mass[c] > 0.0 && now_.volume[c] > 0.0;
    vf_[c] = filled ? vm / now_.volume[c] : 0.0;
    rho_[c] = filled ? now_.mass[c] / vm : 0.0;
    e_[c] = filled ? now_.void_mass[c] / now_.mass[c] : 0.0;
    stress_[c] = filled ? Eigen::Matrix3d(now_.stress_volume[c] / vm) : Eigen::Matrix3d::Zero();
    slope_cell_[c] = filled && !cells.solid[c] && vf_[c] > options_.slope_volume_fraction;
  }
}

double RemapPhase::material_flux(const CelGrid& g, const CellFields& cells, int axis,
                                 std::size_t donor, double dv, double toward) const {
  const double vm = now_.material_volume[donor];
  if (vm <= 0.0) return 0.0;
  const double volume = now_.volume[donor], vf = vf_[donor], slab = std::abs(dv);
  const double donor_cell = std::min(vf * slab, vm);
  if (options_.material_flux == MaterialFlux::donor_cell || vf >= 1.0) return donor_cell;
  const int i = g.cell_i(donor), j = g.cell_j(donor);
  // Whether a neighbour is a wall or beyond the box; the volume fraction of one (walls mirror the
  // donor's).
  const auto is_wall = [&](int di, int dj) {
    const int ii = i + di, jj = j + dj;
    return ii < 0 || jj < 0 || ii >= g.nx || jj >= g.ny || cells.solid[g.cell(ii, jj)] != 0;
  };
  bool isolated = true;  // no neighbour on the grid holds material
  const auto vf_at = [&](int di, int dj) {
    if (is_wall(di, dj)) return vf;
    const std::size_t c = g.cell(i + di, j + dj);
    if (vf_[c] > 0.0 && (di != 0 || dj != 0)) isolated = false;
    return std::min(vf_[c], 1.0);
  };
  if (options_.material_flux == MaterialFlux::limited) {
    const int di = axis == 0 ? 1 : 0, dj = 1 - di;
    const double left = vf - vf_at(-di, -dj), right = vf_at(di, dj) - vf;
    const double face = muscl_face_value(vf, van_leer_difference(left, right), slab / volume, toward);
    return std::clamp(face * slab, 0.0, std::min(slab, vm));
  }
  // A wall right behind the flow is one the material leaves through this face: it does not
  // cling to it, and the walls in that row of the block are empty. (Mirrored, a fragment falling
  // away from the lifted chute gate's lower face was put against it, above the slab leaving
  // through the bottom face, and stayed there while its nodes fell to 44 m/s.)
  const int back_i = axis == 0 ? (toward > 0.0 ? -1 : 1) : 0;
  const int back_j = axis == 1 ? (toward > 0.0 ? -1 : 1) : 0;
  const bool leaves_wall = is_wall(back_i, back_j);
  std::array<double, 9> block{};
  for (int dj = -1; dj <= 1; ++dj)
    for (int di = -1; di <= 1; ++di) {
      const bool behind = axis == 0 ? di == back_i : dj == back_j;
      block[(di + 1) + 3 * (dj + 1)] =
          leaves_wall && behind && is_wall(di, dj) ? 0.0 : vf_at(di, dj);
    }
  const NodeVector n = youngs_normal(block);
  // A fragment with no material around it has no interface to reconstruct: it moves as donor
  // cell. (Beside a wall the mirror would give it one, facing the wall, and put it in the cell's
  // corner there; flowing away from the wall it then never reached the outflow face and its
  // nodes fell without end: a 0.07-full cell under the lifted chute gate reached 50 m/s.)
  if (n.isZero() || isolated) return donor_cell;
  // The intermediate cell as a rectangle in the (x, y) plane: volumes over the donor column's
  // depth (1, or r_c per radian: the cut is planar, its volume weighted at the centre radius).
  const double h = g.cell_size, depth = g.column_depth(i), along = volume / (h * depth);
  const CutRectangle cut = cut_rectangle(along, h, NodeVector(n[axis], n[1 - axis]), vf);
  const double w = std::min(slab / (h * depth), along);
  const double area = toward > 0.0 ? material_area(cut, along - w, along) : material_area(cut, 0.0, w);
  return std::min(area * depth, vm);
}

RemapPhase::SweepResult RemapPhase::sweep(const CelGrid& g, double dt, int axis,
                                          const CellFields& cells, const NodeFields& nodes) {
  const int n_along = axis == 0 ? g.nx : g.ny;
  const int n_across = axis == 0 ? g.ny : g.nx;
  zero(delta_.volume, 0.0);
  zero(delta_.material_volume, 0.0);
  zero(delta_.mass, 0.0);
  zero(delta_.void_mass, 0.0);
  zero(delta_.stress_volume, Eigen::Matrix3d::Zero().eval());
  face_mass_flux_.assign(static_cast<std::size_t>(n_across) * (n_along + 1), 0.0);
  refresh_cell_state(g, cells);
  const int k_first = outflow_lo_[axis] ? 0 : 1;
  const int k_last = outflow_hi_[axis] ? n_along : n_along - 1;
  const bool any_second_order = options_.second_order_stress || options_.second_order_void_ratio ||
                                options_.second_order_density;
  double worst = 0.0, outflow = 0.0;
  // Lines across the sweep direction are independent: each touches its own cells only.
#pragma omp parallel for schedule(static) reduction(max : worst) reduction(+ : outflow) \
    if (g.cell_count() > kParallelThreshold)
  for (int m = 0; m < n_across; ++m) {
    const auto cell_at = [&](int k) {
      if (k < 0 || k >= n_along) return kOutside;
      return axis == 0 ? g.cell(k, m) : g.cell(m, k);
    };
    for (int k = k_first; k <= k_last; ++k) {
      const Face f = face(g, axis, k, m);
      const double dv = transport_volume(g, nodes, axis, k, m, dt, cells);
      if (dv == 0.0) continue;
      const std::size_t donor = dv > 0.0 ? f.lo : f.hi;
      const auto exchange = [&](auto& d, const auto& amount) {
        if (f.lo != kOutside) d[f.lo] -= amount;
        if (f.hi != kOutside) d[f.hi] += amount;
      };
      exchange(delta_.volume, dv);
      if (donor == kOutside) continue;  // void enters through an outflow face
      // A cut cell's share is taken of the whole cell: a sliver gives what it holds (below).
      const double share = std::abs(dv) / (cut_cells_ ? g.cell_volume(donor) : now_.volume[donor]);
      worst = std::max(worst, share);
      const double toward = dv > 0.0 ? 1.0 : -1.0;  // the face on the donor's high/low side
      const double vm = material_flux(g, cells, axis, donor, dv, toward);
      if (vm <= 0.0) continue;
      double rho = rho_[donor], e = e_[donor];
      Eigen::Matrix3d stress = stress_[donor];
      if (any_second_order) {
        const int kd = dv > 0.0 ? k - 1 : k;  // the donor's index along the axis
        const std::size_t below = cell_at(kd - 1), above = cell_at(kd + 1);
        if (below != kOutside && above != kOutside && slope_cell_[below] && slope_cell_[above] &&
            slope_cell_[donor]) {
          const auto face_value = [&](double d, double lo, double hi) {
            return muscl_face_value(d, van_leer_difference(d - lo, hi - d), share, toward);
          };
          // In grain-consistent mode the density follows e: no face value of its own.
          if (options_.second_order_density && grain_density_ <= 0.0)
            rho = face_value(rho, rho_[below], rho_[above]);
          if (options_.second_order_void_ratio) e = face_value(e, e_[below], e_[above]);
          if (options_.second_order_stress)
            for (int r = 0; r < 3; ++r)
              for (int s = 0; s < 3; ++s)
                stress(r, s) = face_value(stress(r, s), stress_[below](r, s), stress_[above](r, s));
        }
      }
      const double dm = grain_density_ > 0.0 ? grain_density_ * vm / (1.0 + e) : rho * vm;
      exchange(delta_.material_volume, toward * vm);
      exchange(delta_.mass, toward * dm);
      exchange(delta_.void_mass, toward * e * dm);
      exchange(delta_.stress_volume, (toward * vm * stress).eval());
      face_mass_flux_[static_cast<std::size_t>(m) * (n_along + 1) + k] = toward * dm;
      if (f.lo == kOutside || f.hi == kOutside) outflow += dm;
    }
  }
  const auto cells_n = static_cast<long>(g.cell_count());
#pragma omp parallel for schedule(static) if (cells_n > kParallelThreshold)
  for (long k = 0; k < cells_n; ++k) {
    const auto c = static_cast<std::size_t>(k);
    now_.volume[c] += delta_.volume[c];
    now_.material_volume[c] += delta_.material_volume[c];
    now_.mass[c] += delta_.mass[c];
    now_.void_mass[c] += delta_.void_mass[c];
    now_.stress_volume[c] += delta_.stress_volume[c];
    if (grain_density_ > 0.0 && now_.mass[c] > 0.0) {
      // The stress integral follows the material volume it was spread over.
      const double vm = grain_volume(c);
      if (now_.material_volume[c] > 0.0) now_.stress_volume[c] *= vm / now_.material_volume[c];
      now_.material_volume[c] = vm;
    }
  }
  return {worst, outflow};
}

NodeVector RemapPhase::sweep_momentum(const CelGrid& g, int axis) {
  const int n_along = axis == 0 ? g.nx : g.ny;    // cells along the axis
  const int n_across = axis == 0 ? g.ny : g.nx;   // cell lines
  zero(node_mass_delta_, 0.0);
  zero(node_momentum_delta_, NodeVector::Zero().eval());
  const auto flux = [&](int m, int k) {
    return face_mass_flux_[static_cast<std::size_t>(m) * (n_along + 1) + k];
  };
  const auto velocity_of = [&](std::size_t a) {
    return node_mass_[a] > 0.0 ? NodeVector(node_momentum_[a] / node_mass_[a]) : NodeVector::Zero();
  };
  // Node line `line` (0..n_across) takes half of cell lines line-1 and line; the dual face at the
  // centre of cell k carries half the sum of cell k's two primal face fluxes.
#pragma omp parallel for schedule(static) if (g.cell_count() > kParallelThreshold)
  for (int line = 0; line <= n_across; ++line) {
    for (int k = 0; k < n_along; ++k) {
      double phi = 0.0;
      for (int m = line - 1; m <= line; ++m)
        if (m >= 0 && m < n_across) phi += 0.25 * (flux(m, k) + flux(m, k + 1));
      if (phi == 0.0) continue;
      const std::size_t lo = node_on_line(g, axis, k, line), hi = node_on_line(g, axis, k + 1, line);
      const std::size_t donor = phi > 0.0 ? lo : hi;
      NodeVector v = velocity_of(donor);
      if (options_.second_order_momentum && node_mass_[donor] > 0.0) {
        const int kd = phi > 0.0 ? k : k + 1;  // the donor's node index along the axis
        if (kd >= 1 && kd + 1 <= n_along) {
          const std::size_t below = node_on_line(g, axis, kd - 1, line);
          const std::size_t above = node_on_line(g, axis, kd + 1, line);
          if (node_mass_[below] > 0.0 && node_mass_[above] > 0.0) {
            const NodeVector vb = velocity_of(below), va = velocity_of(above);
            const double share = std::min(1.0, std::abs(phi) / node_mass_[donor]);
            const double toward = phi > 0.0 ? 1.0 : -1.0;
            for (int r = 0; r < kDimension; ++r)
              v[r] = muscl_face_value(v[r], van_leer_difference(v[r] - vb[r], va[r] - v[r]),
                                      share, toward);
          }
        }
      }
      node_mass_delta_[lo] -= phi;
      node_mass_delta_[hi] += phi;
      node_momentum_delta_[lo] -= phi * v;
      node_momentum_delta_[hi] += phi * v;
    }
  }
  // Outflow faces: a boundary node lumps a quarter of each neighbouring boundary cell, so it gives
  // half of their face fluxes (leaving at its own velocity); only outward fluxes are non-zero.
  NodeVector outflow = NodeVector::Zero();
  for (int line = 0; line <= n_across; ++line) {
    for (int k : {0, n_along}) {
      double phi = 0.0;  // leaving the grid
      for (int m = line - 1; m <= line; ++m)
        if (m >= 0 && m < n_across) phi += 0.5 * (k == 0 ? -flux(m, k) : flux(m, k));
      if (phi == 0.0) continue;
      const std::size_t a = node_on_line(g, axis, k, line);
      const NodeVector p = node_mass_[a] > 0.0 ? NodeVector(phi * node_momentum_[a] / node_mass_[a])
                                               : NodeVector::Zero();
      node_mass_delta_[a] -= phi;
      node_momentum_delta_[a] -= p;
      outflow += p;
    }
  }
  const auto nodes_n = static_cast<long>(g.node_count());
#pragma omp parallel for schedule(static) if (nodes_n > kParallelThreshold)
  for (long k = 0; k < nodes_n; ++k) {
    const auto a = static_cast<std::size_t>(k);
    node_mass_[a] += node_mass_delta_[a];
    node_momentum_[a] += node_momentum_delta_[a];
  }
  return outflow;
}

RemapReport RemapPhase::remap(const CelGrid& g, const BoxWalls& walls, double dt,
                                  bool x_first, double void_node_mass, CellFields& cells,
                                  NodeFields& nodes) {
  outflow_lo_[0] = walls.left == WallCondition::outflow;
  outflow_hi_[0] = walls.right == WallCondition::outflow;
  outflow_lo_[1] = walls.bottom == WallCondition::outflow;
  outflow_hi_[1] = walls.top == WallCondition::outflow;
  const std::size_t n = g.cell_count();
  now_.resize(n);
  delta_.resize(n);
  // The Lagrangian cell: V^L = V + the outward transport volumes of its flux-carrying faces.
  for (std::size_t c = 0; c < n; ++c) now_.volume[c] = cells.open_fraction[c] * g.cell_volume(c);
  for (int axis = 0; axis < kDimension; ++axis) {
    const int n_along = axis == 0 ? g.nx : g.ny, n_across = axis == 0 ? g.ny : g.nx;
    for (int m = 0; m < n_across; ++m)
      for (int k = outflow_lo_[axis] ? 0 : 1; k <= (outflow_hi_[axis] ? n_along : n_along - 1); ++k) {
        const Face f = face(g, axis, k, m);
        const double dv = transport_volume(g, nodes, axis, k, m, dt, cells);
        if (f.lo != kOutside) now_.volume[f.lo] += dv;
        if (f.hi != kOutside) now_.volume[f.hi] -= dv;
      }
  }
  const auto cells_n = static_cast<long>(n);
#pragma omp parallel for schedule(static) if (cells_n > kParallelThreshold)
  for (long k = 0; k < cells_n; ++k) {
    const auto c = static_cast<std::size_t>(k);
    now_.mass[c] = cells.mass[c];
    now_.void_mass[c] = cells.void_ratio[c] * cells.mass[c];
    now_.material_volume[c] = grain_density_ > 0.0 ? grain_volume(c)
                                                   : cells.volume_fraction[c] * now_.volume[c];
    now_.stress_volume[c] = cells.stress[c] * now_.material_volume[c];
  }
  const std::size_t nn = g.node_count();
  node_mass_.assign(nodes.mass.begin(), nodes.mass.end());
  node_momentum_.resize(nn);
  node_mass_delta_.resize(nn);
  node_momentum_delta_.resize(nn);
  for (std::size_t a = 0; a < nn; ++a) node_momentum_[a] = nodes.mass[a] * nodes.velocity[a];

  RemapReport report;
  const int first = x_first ? 0 : 1;
  for (int axis : {first, 1 - first}) {
    const SweepResult r = sweep(g, dt, axis, cells, nodes);
    report.max_outflow_fraction = std::max(report.max_outflow_fraction, r.worst_share);
    report.outflow_mass += r.outflow_mass;
    report.outflow_momentum += sweep_momentum(g, axis);
  }

  // Per cell in parallel; the cut-off mass is summed afterwards in cell order (the same bits
  // on any number of threads).
  double largest = 0.0, smallest = 1.0;
  int compacted = 0, overpacked = 0, wall_overfilled = 0;
  cut_off_.assign(n, 0.0);
#pragma omp parallel for schedule(static) reduction(max : largest) reduction(min : smallest) \
    reduction(+ : compacted, overpacked, wall_overfilled) if (cells_n > kParallelThreshold)
  for (long k = 0; k < cells_n; ++k) {
    const auto c = static_cast<std::size_t>(k);
    const double vm = now_.material_volume[c];
    const double open = cells.open_fraction[c];
    const double v0 = open * g.cell_volume(c);  // the open volume
    const double vf = v0 > 0.0 ? vm / v0 : (vm > 0.0 ? 2.0 : 0.0);
    if (!cells.solid[c]) {
      largest = std::max(largest, vf);
      smallest = std::min(smallest, vf);
    }
    if (vf < cut_ || vm <= 0.0 || now_.mass[c] <= 0.0) {
      cut_off_[c] = now_.mass[c];
      cells.volume_fraction[c] = 0.0;
      cells.mass[c] = 0.0;
      cells.stress[c].setZero();
      cells.void_ratio[c] = 0.0;
      continue;
    }
    cells.volume_fraction[c] = std::min(vf, 1.0) * open;  // overfilled: keep the mass, raise rho
    cells.mass[c] = now_.mass[c];
    cells.stress[c] = now_.stress_volume[c] / vm;
    cells.void_ratio[c] = now_.void_mass[c] / now_.mass[c];
    if (grain_density_ > 0.0 && vf > 1.0 && at_staircase(g, cells, c)) {
      ++wall_overfilled;  // a staircase artefact: keeps its void ratio, exports the excess
    } else if (grain_density_ > 0.0 && vf > 1.0) {  // does not fit: packed to fill the cell
      const double fit = grain_density_ * v0 / now_.mass[c] - 1.0;
      const double densest = densest_.void_ratio(cells.stress[c]);
      cells.void_ratio[c] = std::max(fit, densest);
      ++compacted;
      if (fit < densest) ++overpacked;
    }
  }
  report.largest_volume_fraction = largest;
  report.smallest_volume_fraction = smallest;
  report.compacted_cells = compacted;
  report.overpacked_cells = overpacked;
  report.wall_overfilled_cells = wall_overfilled;
  for (double m : cut_off_) report.removed_mass += m;

  lump_nodal_mass(g, cells, nodes);
  for (std::size_t a = 0; a < nn; ++a) {
    if (nodes.mass[a] > void_node_mass && node_mass_[a] > 0.0) {
      nodes.velocity[a] = node_momentum_[a] / node_mass_[a];
    } else {
      report.lost_momentum += node_momentum_[a];
      nodes.velocity[a].setZero();
    }
  }
  apply_node_constraints(nodes);
  return report;
}

}  // namespace feedflow::cel
