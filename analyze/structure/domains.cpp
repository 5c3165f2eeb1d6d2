#include "domains.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gg/errors.hpp"

namespace gg {

Phase parse_phase(const std::string& text) {
  if (text == "both") return Phase::both;
  if (text == "rich") return Phase::rich;
  if (text == "poor") return Phase::poor;
  throw UsageError("--phase " + text + " is not one of both, rich, poor");
}

const char* to_string(Phase phase) {
  switch (phase) {
    case Phase::rich: return "rich";
    case Phase::poor: return "poor";
    default: return "both";
  }
}

namespace {
double finest_spacing(const DensityGrid& grid) {
  const auto& sp = grid.spacing();
  return *std::min_element(sp.begin(), sp.end());
}
}  // namespace

std::vector<double> domain_bin_edges(const DensityGrid& grid) {
  const double h = finest_spacing(grid);
  long bins = 1;
  for (int k = 0; k < grid.dim(); ++k)
    bins = std::max(bins, std::lround((grid.cells_per_side()[k] - 1) * grid.spacing()[k] / h));
  std::vector<double> edges(static_cast<std::size_t>(bins) + 1);
  for (std::size_t j = 0; j < edges.size(); ++j) edges[j] = (static_cast<double>(j) + 0.5) * h;
  return edges;
}

DomainResult measure_domains(const DensityGrid& grid, Phase phase) {
  DomainResult out;
  out.bin_edges = domain_bin_edges(grid);
  const std::size_t bins = out.bin_edges.size() - 1;
  const double h = finest_spacing(grid);
  std::vector<std::int64_t> hist(bins, 0);
  double sum = 0;
  const bool want_rich = phase != Phase::poor, want_poor = phase != Phase::rich;

  const auto& psi = grid.psi();
  std::vector<std::int8_t> line;
  std::vector<int> interface;
  for (int k = 0; k < grid.dim(); ++k) {
    const int n = grid.cells_per_side()[k];
    const std::size_t stride = grid.strides()[k];
    const double hk = grid.spacing()[k];
    std::size_t outer = 1;
    for (int j = 0; j < k; ++j) outer *= static_cast<std::size_t>(grid.cells_per_side()[j]);
    line.resize(n);
    for (std::size_t o = 0; o < outer; ++o) {
      for (std::size_t m = 0; m < stride; ++m) {
        const std::int8_t* start = psi.data() + o * n * stride + m;
        for (int i = 0; i < n; ++i) line[i] = start[i * stride];
        // Interface at i: psi changes between cells i-1 and i (periodic).
        interface.clear();
        for (int i = 0; i < n; ++i)
          if (line[i] != line[i == 0 ? n - 1 : i - 1]) interface.push_back(i);
        const std::size_t nf = interface.size();  // even on a periodic line; 0 = no domain
        for (std::size_t f = 0; f < nf; ++f) {
          const int begin = interface[f];
          const int end = f + 1 < nf ? interface[f + 1] : interface[0] + n;
          const bool rich = line[begin] > 0;
          if (rich ? !want_rich : !want_poor) continue;
          const double length = (end - begin) * hk;
          const auto j = static_cast<std::size_t>(std::lround(length / h)) - 1;
          ++hist[std::min(j, bins - 1)];
          sum += length;
          ++out.count;
        }
      }
    }
  }

  out.histogram.assign(bins, 0.0);
  if (out.count > 0) {
    const double norm = 1.0 / (static_cast<double>(out.count) * h);
    for (std::size_t j = 0; j < bins; ++j) out.histogram[j] = static_cast<double>(hist[j]) * norm;
    out.length = sum / static_cast<double>(out.count);
  } else {
    out.length = std::numeric_limits<double>::quiet_NaN();
  }
  return out;
}

}  // namespace gg
