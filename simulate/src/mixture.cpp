#include "ggsim/mixture.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numeric>

#include "gg/errors.hpp"
#include "gg/particle_volume.hpp"

namespace ggsim {

namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw gg::UsageError(message);
}

// "a,b,c" as numbers, each finite; `flag` names the option in the error.
std::vector<double> numbers(const std::string& text, const std::string& flag) {
  std::vector<double> out;
  std::size_t from = 0;
  for (;;) {
    const std::size_t to = std::min(text.find_first_of(",:", from), text.size());
    double x = 0;
    const char* first = text.data() + from;
    const auto [end, err] = std::from_chars(first, text.data() + to, x);
    require(err == std::errc() && end == text.data() + to && std::isfinite(x),
            flag + " '" + text + "' is not a list of numbers; give e.g. " + flag + " 0.5,0.7");
    out.push_back(x);
    if (to == text.size()) return out;
    from = to + 1;
  }
}

}  // namespace

MixtureSpec MixtureSpec::parse(const std::string& radii, const std::string& masses, const std::string& fractions) {
  MixtureSpec m;
  const std::string kUniform = "uniform:";
  m.uniform = radii.rfind(kUniform, 0) == 0;
  if (m.uniform) {
    m.radius = numbers(radii.substr(kUniform.size()), "--radii uniform:");
    require(m.radius.size() == 2 && m.radius[0] <= m.radius[1],
            "--radii '" + radii + "' needs two bounds, lowest first: --radii uniform:0.4:0.6");
    require(fractions.empty(), "--fractions belongs to a mixture of species; --radii uniform: draws every radius from "
                               "one distribution; drop --fractions");
  } else if (!radii.empty()) {
    m.radius = numbers(radii, "--radii");
  }
  for (double r : m.radius)
    require(r > 0, "--radii must be positive (got " + radii + "); the default particle has radius 0.5");
  if (!masses.empty()) m.mass = numbers(masses, "--masses");
  for (double x : m.mass) require(x > 0, "--masses must be positive (got " + masses + ")");
  const std::size_t k = m.uniform ? 1 : std::max(m.radius.size(), m.mass.size());
  if (m.uniform) {
    require(m.mass.size() <= 1, "--masses with --radii uniform: gives one mass for every particle (or none: by "
                                "volume); got " + masses);
  } else {
    if (m.radius.empty()) m.radius.assign(k, 0.5);
    require(m.mass.empty() || m.mass.size() == k,
            "--radii gives " + std::to_string(m.radius.size()) + " species but --masses " +
                std::to_string(m.mass.size()) + "; give one mass per species, in the same order");
  }
  if (fractions.empty()) {
    m.fraction.assign(k, 1.0 / static_cast<double>(k));
  } else {
    m.fraction = numbers(fractions, "--fractions");
    require(m.fraction.size() == k, "--fractions gives " + std::to_string(m.fraction.size()) +
                                        " fractions for " + std::to_string(k) + " species; give one per species");
    for (double f : m.fraction) require(f >= 0, "--fractions must be >= 0 (got " + fractions + ")");
    const double sum = std::accumulate(m.fraction.begin(), m.fraction.end(), 0.0);
    require(std::abs(sum - 1) < 1e-9, "--fractions " + fractions + " sum to " + std::to_string(sum) +
                                          ", not 1; give the number fraction of each species");
  }
  return m;
}

double MixtureSpec::mean_volume(int dim) const {
  if (uniform) {  // <r^d> of a uniform r in [lo, hi], times the volume of a unit radius
    const double lo = radius[0], hi = radius[1];
    const double mean = hi > lo ? (std::pow(hi, dim + 1) - std::pow(lo, dim + 1)) / ((dim + 1) * (hi - lo))
                                : std::pow(lo, dim);
    return gg::particle_volume(1, dim) * mean;
  }
  double v = 0;
  for (std::size_t s = 0; s < fraction.size(); ++s) v += fraction[s] * gg::particle_volume(radius[s], dim);
  return v;
}

void Sizes::permute(const std::vector<std::size_t>& order) {
  const auto apply = [&](auto& a) {
    auto b = a;
    for (std::size_t k = 0; k < order.size(); ++k) b[k] = a[order[k]];
    a.swap(b);
  };
  apply(radius), apply(mass), apply(species);
}

Sizes draw_sizes(const MixtureSpec& spec, std::size_t n, int dim, Random& rng) {
  Sizes s;
  s.species_count = static_cast<std::uint32_t>(spec.species());
  // Mass by volume at the material density of a default particle (mass 1, diameter 1).
  const auto mass_of = [&](double r, std::size_t species) {
    return spec.mass.empty() ? std::pow(2 * r, dim) : spec.mass[spec.uniform ? 0 : species];
  };
  if (spec.uniform) {
    s.radius.resize(n);
    for (double& r : s.radius) r = spec.radius[0] + (spec.radius[1] - spec.radius[0]) * rng.uniform();
    std::sort(s.radius.begin(), s.radius.end(), std::greater<>());
    s.species.assign(n, 0);
  } else {
    // Species s gets round(n F_s) - round(n F_{s-1}) particles (F the cumulative fractions): the
    // counts sum to n exactly. The larger radii come first.
    std::vector<std::size_t> count(spec.fraction.size());
    double cumulative = 0;
    std::size_t given = 0;
    for (std::size_t k = 0; k < count.size(); ++k) {
      cumulative += spec.fraction[k];
      const auto upto = k + 1 == count.size() ? n : static_cast<std::size_t>(std::llround(cumulative * n));
      count[k] = upto - std::min(upto, given);
      given = std::max(given, upto);
    }
    std::vector<std::size_t> by_size(count.size());
    std::iota(by_size.begin(), by_size.end(), 0);
    std::stable_sort(by_size.begin(), by_size.end(),
                     [&](std::size_t a, std::size_t b) { return spec.radius[a] > spec.radius[b]; });
    for (std::size_t k : by_size) {
      s.radius.insert(s.radius.end(), count[k], spec.radius[k]);
      s.species.insert(s.species.end(), count[k], static_cast<std::uint32_t>(k));
    }
  }
  s.mass.resize(n);
  for (std::size_t i = 0; i < n; ++i) s.mass[i] = mass_of(s.radius[i], s.species[i]);
  return s;
}

}  // namespace ggsim
