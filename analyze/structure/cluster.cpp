#include "cluster.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace gg {

namespace {

// Union-find whose root is always the smallest index of its set, so the result does not depend on
// the order in which cells are joined. Each cell also carries its image of the periodic box relative to
// its parent (the whole-box shifts, per axis, that put it beside its parent when the set is drawn
// unwrapped); find() gives the image relative to the root. A bond between two cells of one set whose
// images disagree closes a loop winding around the box (Newman & Ziff, PRE 64, 016706 (2001), sec. IV;
// Machta et al., PRE 54, 1332 (1996)): the root records the axes where they disagree.
template <int D>
class UnionFind {
 public:
  using Image = std::array<std::int32_t, D>;
  explicit UnionFind(std::size_t n) : parent_(n), image_(n, Image{}), wraps_(n, 0) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  // The root of a's set, and a's image relative to it in `image`.
  std::int32_t find(std::int32_t a, Image& image) {
    image = Image{};
    while (parent_[a] != a) {
      const std::int32_t p = parent_[a];
      for (int k = 0; k < D; ++k) image_[a][k] += image_[p][k];  // now relative to p's parent
      parent_[a] = parent_[p];                                   // path halving
      for (int k = 0; k < D; ++k) image[k] += image_[a][k];
      a = parent_[a];
    }
    return a;
  }
  std::int32_t find(std::int32_t a) {
    Image ignored;
    return find(a, ignored);
  }
  // Joins a and b, neighbours whose bond crosses the box's faces by `shift` (b sits in image a + shift).
  void unite(std::int32_t a, std::int32_t b, const Image& shift) {
    Image ia, ib;
    a = find(a, ia);
    b = find(b, ib);
    Image d;  // b's root's image relative to a's root, if the bond is to hold
    for (int k = 0; k < D; ++k) d[k] = ia[k] + shift[k] - ib[k];
    if (a == b) {
      for (int k = 0; k < D; ++k)
        if (d[k] != 0) wraps_[a] |= static_cast<std::uint8_t>(1u << k);
      return;
    }
    if (b < a) {
      std::swap(a, b);
      for (int k = 0; k < D; ++k) d[k] = -d[k];
    }
    parent_[b] = a;
    image_[b] = d;
    wraps_[a] |= wraps_[b];
  }
  // The axes along which a root's set wraps (bit k: axis k).
  std::uint8_t wraps(std::int32_t root) const { return wraps_[root]; }

 private:
  std::vector<std::int32_t> parent_;
  std::vector<Image> image_;
  std::vector<std::uint8_t> wraps_;
};

// Half of the neighbourhood (offsets whose first non-zero component is positive): visiting every
// cell with these offsets touches every neighbouring pair once.
template <int D>
std::vector<std::array<int, D>> forward_offsets(Connectivity connectivity) {
  std::vector<std::array<int, D>> out;
  if (connectivity == Connectivity::face || D == 1) {
    for (int k = 0; k < D; ++k) {
      std::array<int, D> o{};
      o[k] = 1;
      out.push_back(o);
    }
    return out;
  }
  int total = 1;
  for (int k = 0; k < D; ++k) total *= 3;
  for (int code = 0; code < total; ++code) {
    std::array<int, D> o{};
    for (int k = D - 1, c = code; k >= 0; --k, c /= 3) o[k] = c % 3 - 1;
    const auto first = std::find_if(o.begin(), o.end(), [](int v) { return v != 0; });
    if (first != o.end() && *first > 0) out.push_back(o);
  }
  return out;
}

template <int D>
void unite_neighbours(const DensityGrid& grid, Connectivity connectivity, UnionFind<D>& uf) {
  const auto offsets = forward_offsets<D>(connectivity);
  std::array<int, D> n{}, idx{};
  std::array<std::size_t, D> stride{};
  for (int k = 0; k < D; ++k) {
    n[k] = grid.cells_per_side()[k];
    stride[k] = grid.strides()[k];
  }
  const auto& psi = grid.psi();
  const std::size_t cells = grid.size();
  typename UnionFind<D>::Image shift;
  for (std::size_t c = 0; c < cells; ++c) {
    if (psi[c] > 0) {
      for (const auto& o : offsets) {
        std::size_t nb = 0;
        for (int k = 0; k < D; ++k) {
          int j = idx[k] + o[k];
          shift[k] = 0;
          if (j >= n[k]) {  // periodic; offsets are -1, 0, +1
            j -= n[k];
            shift[k] = 1;
          } else if (j < 0) {
            j += n[k];
            shift[k] = -1;
          }
          nb += static_cast<std::size_t>(j) * stride[k];
        }
        if (psi[nb] > 0) uf.unite(static_cast<std::int32_t>(c), static_cast<std::int32_t>(nb), shift);
      }
    }
    for (int k = D - 1; k >= 0; --k) {  // next row-major multi-index
      if (++idx[k] < n[k]) break;
      idx[k] = 0;
    }
  }
}

// find_clusters of a D-dimensional grid.
template <int D>
ClusterResult label_clusters(const DensityGrid& grid, Connectivity connectivity) {
  const std::size_t cells = grid.size();
  UnionFind<D> uf(cells);
  unite_neighbours<D>(grid, connectivity, uf);

  // Provisional labels in scan order: the first cell met of a set is its root (its smallest index).
  ClusterResult result;
  result.label.assign(cells, -1);
  const auto& psi = grid.psi();
  const auto& count = grid.counts();
  for (std::size_t c = 0; c < cells; ++c) {
    if (psi[c] < 0) continue;
    const auto root = static_cast<std::size_t>(uf.find(static_cast<std::int32_t>(c)));
    std::int32_t id;
    if (root == c) {
      id = static_cast<std::int32_t>(result.clusters.size());
      result.clusters.push_back({0, 0, c, uf.wraps(static_cast<std::int32_t>(c))});
    } else {
      id = result.label[root];
    }
    result.label[c] = id;
    result.clusters[id].mass += count[c];
    result.clusters[id].cells += 1;
  }
  return result;
}

}  // namespace

ClusterResult find_clusters(const DensityGrid& grid, Connectivity connectivity) {
  ClusterResult result;
  switch (grid.dim()) {
    case 1: result = label_clusters<1>(grid, connectivity); break;
    case 2: result = label_clusters<2>(grid, connectivity); break;
    case 3: result = label_clusters<3>(grid, connectivity); break;
  }

  // Final order: heaviest first, ties by smallest cell index.
  std::vector<std::int32_t> order(result.clusters.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) {
    const Cluster& x = result.clusters[a];
    const Cluster& y = result.clusters[b];
    return x.mass != y.mass ? x.mass > y.mass : x.first_cell < y.first_cell;
  });
  std::vector<std::int32_t> rank(order.size());
  std::vector<Cluster> sorted(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    rank[order[i]] = static_cast<std::int32_t>(i);
    sorted[i] = result.clusters[order[i]];
  }
  result.clusters = std::move(sorted);
  for (auto& l : result.label)
    if (l >= 0) l = rank[l];
  return result;
}

ClusterStats summarize(const std::vector<Cluster>& clusters, std::int64_t min_size) {
  ClusterStats s;
  double sum = 0, sum2 = 0;
  for (const Cluster& c : clusters) {
    if (c.mass < min_size) continue;
    ++s.count;
    sum += static_cast<double>(c.mass);
    sum2 += static_cast<double>(c.mass) * static_cast<double>(c.mass);
    s.largest = std::max(s.largest, c.mass);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  s.mean_mass = s.count > 0 ? sum / static_cast<double>(s.count) : nan;
  s.weight_mass = sum > 0 ? sum2 / sum : nan;
  return s;
}

std::vector<std::int32_t> particle_clusters(const DensityGrid& grid, const ClusterResult& result,
                                            const double* positions, std::size_t n_particles) {
  std::vector<std::int32_t> out(n_particles);
  const auto d = static_cast<std::size_t>(grid.dim());
  for (std::size_t i = 0; i < n_particles; ++i) out[i] = result.label[grid.cell_of(positions + i * d)];
  return out;
}

GiantCluster giant_cluster(const std::vector<Cluster>& clusters, std::int64_t n_particles, std::int64_t min_size) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  GiantCluster g{n_particles > 0 ? 0.0 : nan, nan, nan, 0};
  // clusters is sorted heaviest first: the counted ones are a prefix.
  if (clusters.empty() || clusters.front().mass < min_size) return g;
  const Cluster& largest = clusters.front();
  std::int64_t clustered = 0, rest = 0;
  for (const Cluster& c : clusters) {
    if (c.mass < min_size) break;
    clustered += c.mass;
    ++rest;
  }
  --rest;
  const auto m = static_cast<double>(largest.mass);
  if (n_particles > 0) g.share = m / static_cast<double>(n_particles);
  if (clustered > 0) g.share_of_clustered = m / static_cast<double>(clustered);
  if (rest > 0) g.rest_mean_mass = static_cast<double>(clustered - largest.mass) / static_cast<double>(rest);
  g.wraps = largest.wraps;
  return g;
}

std::vector<double> mass_bin_edges(std::int64_t max_mass) {
  std::vector<double> edges{1.0};
  while (edges.back() <= static_cast<double>(max_mass)) edges.push_back(2 * edges.back());
  if (edges.size() < 2) edges.push_back(2.0);
  return edges;
}

std::vector<double> mass_histogram(const std::vector<Cluster>& clusters, std::int64_t min_size,
                                   const std::vector<double>& edges) {
  std::vector<double> h(edges.size() - 1, 0.0);
  for (const Cluster& c : clusters) {
    if (c.mass < min_size || c.mass < 1) continue;
    const auto m = static_cast<double>(c.mass);
    const auto it = std::upper_bound(edges.begin(), edges.end(), m);  // first edge > m
    if (it == edges.end()) continue;                                  // beyond the last edge
    h[static_cast<std::size_t>(it - edges.begin()) - 1] += 1;
  }
  return h;
}

}  // namespace gg
