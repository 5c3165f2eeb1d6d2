#pragma once
// Onset of clustering from m(t): when m leaves its homogeneous plateau, and when the local
// exponent reaches its asymptote. The paper states no criterion (docs/PHYSICS.md "Comparing with the
// paper"), so both are explicit and printed with every number (describe()).
#include <cstddef>
#include <string>

#include "fit/series.hpp"

namespace gg::fit {

struct OnsetCriterion {
  std::size_t plateau_samples = 5;  // K: plateau = median of the first K samples
  double plateau_tol = 0.1;         // leaves the plateau when y > plateau * (1 + tol)
  std::size_t persist = 3;          // ... for P consecutive samples (noise does not trigger it)
  double decades = 0.5;             // window of the local exponent, in decades of t
  double exponent_tol = 0.1;        // reaches the asymptote when |z_loc - z_inf| <= tol, P samples
};

// One sentence each, for --help, the output attributes and the printed line.
std::string describe_plateau(const OnsetCriterion& c);
std::string describe_asymptote(const OnsetCriterion& c, double asymptote);

struct PlateauOnset {
  double plateau = 0;  // median of the first K samples
  double time = 0;     // crossing time (NaN if y never leaves the plateau)
};

// First sample k with y > plateau (1 + tol) at k, k+1, ..., k+P-1 (or to the end of the data); the
// time is where the straight line between samples k-1 and k (y linear in ln t, or in t from t = 0)
// crosses the threshold.
PlateauOnset plateau_onset(const Series& s, const OnsetCriterion& c);

// First time the local exponent (local_exponent(s, c.decades)) stays within c.exponent_tol of
// `asymptote` for P consecutive samples, interpolated like plateau_onset. NaN if never.
double asymptote_onset(const Series& s, double asymptote, const OnsetCriterion& c);

}  // namespace gg::fit
