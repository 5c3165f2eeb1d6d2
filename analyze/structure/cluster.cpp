#include "cluster.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace gg {

namespace {

// Union-find whose root is always the smallest index of its set, so the result does not depend on
// the order in which cells are joined.
class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::int32_t find(std::int32_t a) {
    while (parent_[a] != a) {
      parent_[a] = parent_[parent_[a]];  // path halving
      a = parent_[a];
    }
    return a;
  }
  void unite(std::int32_t a, std::int32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (a < b)
      parent_[b] = a;
    else
      parent_[a] = b;
  }

 private:
  std::vector<std::int32_t> parent_;
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
void unite_neighbours(const DensityGrid& grid, Connectivity connectivity, UnionFind& uf) {
  const auto offsets = forward_offsets<D>(connectivity);
  std::array<int, D> n{}, idx{};
  std::array<std::size_t, D> stride{};
  for (int k = 0; k < D; ++k) {
    n[k] = grid.cells_per_side()[k];
    stride[k] = grid.strides()[k];
  }
  const auto& psi = grid.psi();
  const std::size_t cells = grid.size();
  for (std::size_t c = 0; c < cells; ++c) {
    if (psi[c] > 0) {
      for (const auto& o : offsets) {
        std::size_t nb = 0;
        for (int k = 0; k < D; ++k) {
          int j = idx[k] + o[k];
          if (j >= n[k]) j -= n[k];  // periodic; offsets are -1, 0, +1
          else if (j < 0) j += n[k];
          nb += static_cast<std::size_t>(j) * stride[k];
        }
        if (psi[nb] > 0) uf.unite(static_cast<std::int32_t>(c), static_cast<std::int32_t>(nb));
      }
    }
    for (int k = D - 1; k >= 0; --k) {  // next row-major multi-index
      if (++idx[k] < n[k]) break;
      idx[k] = 0;
    }
  }
}

}  // namespace

ClusterResult find_clusters(const DensityGrid& grid, Connectivity connectivity) {
  const std::size_t cells = grid.size();
  UnionFind uf(cells);
  switch (grid.dim()) {
    case 1: unite_neighbours<1>(grid, connectivity, uf); break;
    case 2: unite_neighbours<2>(grid, connectivity, uf); break;
    case 3: unite_neighbours<3>(grid, connectivity, uf); break;
  }

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
      result.clusters.push_back({0, 0, c});
    } else {
      id = result.label[root];
    }
    result.label[c] = id;
    result.clusters[id].mass += count[c];
    result.clusters[id].cells += 1;
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
