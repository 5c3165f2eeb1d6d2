#pragma once
// Synthetic ensembles with a known truth, and one trial of each verdict gg-fit makes on them, so that
// the rate at which a verdict rejects a true claim (and detects a false one) can be counted over many
// trials. Shared by verdict_calibration_test (the rates CI holds) and calibrate-verdicts (the longer
// run behind the table in docs/PHYSICS.md "Calibration of the verdicts").
//
// A run looks like the study's data: y_r(t) = f(t) a_r exp(eta_r(t)), with a per-run amplitude
// a_r = exp(amplitude xi) and eta_r an AR(1) process along ln t (standard deviation `noise`, correlation
// exp(-|Delta log10 t| / correlation_decades)), sampled kPerDecade times per decade (Noise: the data's
// kind, 5% amplitude and 3% correlated over 0.3 decades; white: 2% independent per sample, no amplitude).
// Every factor is stationary in ln t and multiplicative, so the ensemble mean of f(t / c) is that of f
// at t / c: a shifted truth is exactly a shifted truth of the means.
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "fit/at_equal.hpp"
#include "fit/collapse.hpp"
#include "fit/crossing.hpp"
#include "fit/ensemble.hpp"
#include "fit/extrapolate.hpp"
#include "fit/late_growth.hpp"
#include "fit/shift.hpp"
#include "synthetic.hpp"

namespace gg::fit::calibration {

inline constexpr double kSigmas = 2, kTolerance = 0.1;
inline constexpr int kPerDecade = 12;
struct Noise {
  double amplitude = 0.05, noise = 0.03, correlation_decades = 0.3;
};
inline constexpr Noise kWhite{0, 0.02, 0};

using Curve = std::function<double(double)>;

// Samples from t = 1 to 1e5.
inline std::vector<double> sample_times() { return testing::log_times(1, 1e5, 5 * kPerDecade + 1); }

// One run's multiplicative noise at the sample times.
inline std::vector<double> run_noise(testing::Rng& rng, std::size_t n, const Noise& z = {}) {
  const double phi = z.correlation_decades > 0 ? std::exp(-1.0 / kPerDecade / z.correlation_decades) : 0;
  const double a = z.amplitude * rng.normal();
  std::vector<double> f;
  double eta = z.noise * rng.normal();
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0) eta = phi * eta + z.noise * std::sqrt(1 - phi * phi) * rng.normal();
    f.push_back(std::exp(a + eta));
  }
  return f;
}

inline Ensemble ensemble(testing::Rng& rng, const Curve& f, int runs, const Noise& z = {}) {
  const auto t = sample_times();
  std::vector<RunData> rs;
  for (int r = 0; r < runs; ++r) {
    const auto noise = run_noise(rng, t.size(), z);
    RunData run{t, 1, {}, "run" + std::to_string(r)};
    for (std::size_t k = 0; k < t.size(); ++k) run.values.push_back(f(t[k]) * noise[k]);
    rs.push_back(run);
  }
  return common_grid(rs, false);
}

// A crossover from y ~ t^0.9 to y ~ t^0.4 around t = 100, as m(t) of a cooling gas crosses over.
inline double crossover(double t) { return std::pow(t, 0.9) / std::sqrt(1 + t / 100); }

// ---- gg-fit shift: y_B(t) = y_A(t / c), c = 7 at the middle of B's window, drifting by the factor
// `drift` across it (1: an exact shift). Windows as a study's: A over [10, 3000], B over [30, 3e4].
inline constexpr double kShiftFactor = 7;
struct ShiftTrial {
  bool collapses = false;
  int constant = -1;
  bool covered = false;  // ln 7 within the interval of ln c
  double chi2_per_point = 0;
};
inline ShiftTrial shift_trial(unsigned long seed, int runs, double drift = 1, const Noise& z = {}) {
  testing::Rng rng(seed);
  const double delta = std::log(drift) / std::log(1e3), mid = std::sqrt(30 * 3e4);
  const Ensemble a = ensemble(rng, crossover, runs, z);
  const Ensemble b = ensemble(rng, [&](double t) { return crossover(t / (kShiftFactor * std::pow(t / mid, delta))); }, runs, z);
  const Series ma = mean_series(a), mb = mean_series(b);
  const ShiftSetup s = shift_setup(ma, {10, 3000}, mb, {30, 3e4}, 8);
  const ShiftFit f = fit_shift(ma, mb, s);
  const Jackknife j = jackknife({a, b}, [&](const std::vector<Series>& m) { return shift_parameters(fit_shift(m[0], m[1], s)); });
  const ShiftVerdict v = shift_verdict(f, j, kSigmas);
  return {v.collapses, v.constant, std::abs(f.log_factor - std::log(kShiftFactor)) <= v.log_factor_halfwidth,
          f.chi2_per_point};
}

// ---- late exponents of two ensembles agree (answer.sh statement 1): y = t^0.5 and 2 t^(0.5 + dz), each
// over the last 0.5 decades before t = 1e5, compared by Welch's test of the difference.
inline bool exponents_agree_trial(unsigned long seed, int runs, double dz = 0) {
  testing::Rng rng(seed);
  const Ensemble a = ensemble(rng, [](double t) { return std::pow(t, 0.5); }, runs);
  const Ensemble b = ensemble(rng, [&](double t) { return 2 * std::pow(t, 0.5 + dz); }, runs);
  const auto late = [](const Ensemble& e) {
    const auto est = [](const std::vector<Series>& m) { return late_exponent_parameters(late_exponent(m[0], 1e5, 0.5)); };
    const Jackknife j = jackknife({e}, est);
    return Estimate{est({mean_series(e)})[0], j.se[0], j.dof[0]};
  };
  return within(difference(late(b), late(a)), 0, kSigmas);
}

// ---- the late exponent has settled (late-exponent): y = t^0.5 (settled), or with a local exponent
// that changes by `dz` per decade over the last decade.
inline bool settled_trial(unsigned long seed, int runs, double dz = 0) {
  testing::Rng rng(seed);
  const Ensemble e = ensemble(rng, [&](double t) {
    const double x = std::max(0.0, std::log10(t) - 4);  // decades past 1e4
    return std::pow(t, 0.5) * std::pow(10.0, 0.5 * dz * x * x);
  }, runs);
  const auto est = [](const std::vector<Series>& m) { return late_exponent_parameters(late_exponent(m[0], 1e5, 0.5)); };
  const Jackknife j = jackknife({e}, est);
  return within({est({mean_series(e)})[2], j.se[2], j.dof[2]}, 0, kSigmas);
}

// ---- amplitudes agree at one common exponent (gg-fit collapse with jackknife errors, as fig8.sh runs
// it): y = 3 t^0.5 and ratio 3 t^0.5 over [300, 3000].
inline bool amplitudes_agree_trial(unsigned long seed, int runs, double ratio = 1) {
  testing::Rng rng(seed);
  const Ensemble a = ensemble(rng, [](double t) { return 3 * std::sqrt(t); }, runs);
  const Ensemble b = ensemble(rng, [&](double t) { return ratio * 3 * std::sqrt(t); }, runs);
  const std::vector<Window> w{{300, 3000}, {300, 3000}};
  CollapseFit f = fit_collapse({mean_series(a), mean_series(b)}, w, kSigmas);
  set_collapse_errors(f, jackknife({a, b}, [&](const std::vector<Series>& m) { return collapse_parameters(fit_collapse(m, w, kSigmas)); }));
  return f.all_agree;
}

// ---- ratio at equal times = 1 (gg-fit ratio): y_B = ratio y_A over [3162, 31623].
inline Verdict ratio_trial(unsigned long seed, int runs, double ratio = 1) {
  testing::Rng rng(seed);
  const Ensemble a = ensemble(rng, crossover, runs);
  const Ensemble b = ensemble(rng, [&](double t) { return ratio * crossover(t); }, runs);
  const Window w{1e4 / std::sqrt(10.0), 1e4 * std::sqrt(10.0)};
  const auto est = [&](const std::vector<Series>& m) { return std::vector<double>{equal_time_ratio(m[0], m[1], w).log_ratio}; };
  const Jackknife j = jackknife({a, b}, est);
  return ratio_verdict(est({mean_series(a), mean_series(b)})[0], j.se[0], j.dof[0], kSigmas, kTolerance);
}

// ---- y at equal x (gg-fit at-equal): the energy E(t) = (1 + t / tau)^-2 decays three times more slowly
// in B (tau = 30 against 10), y = ratio E^-0.4 (ratio = 1: y depends on t only through E); each run's E
// and y carry their own noise (E's 1%). Compared at E = 1e-3 .. 1e-5.
inline Verdict at_equal_trial(unsigned long seed, int runs, double ratio = 1) {
  testing::Rng rng(seed);
  const auto t = sample_times();
  const auto make = [&](double tau, double amp, Ensemble& x, Ensemble& y) {
    std::vector<RunData> xs, ys;
    for (int r = 0; r < runs; ++r) {
      const auto nx = run_noise(rng, t.size(), {0.01, 0.01, 0.3}), ny = run_noise(rng, t.size());
      RunData rx{t, 1, {}, "E" + std::to_string(r)}, ry{t, 1, {}, "y" + std::to_string(r)};
      for (std::size_t k = 0; k < t.size(); ++k) {
        const double E = std::pow(1 + t[k] / tau, -2.0);
        rx.values.push_back(E * nx[k]), ry.values.push_back(amp * std::pow(E, -0.4) * ny[k]);
      }
      xs.push_back(rx), ys.push_back(ry);
    }
    x = common_grid(xs, false), y = common_grid(ys, false);
  };
  Ensemble xa, ya, xb, yb;
  make(10, 1, xa, ya);
  make(30, ratio, xb, yb);
  const std::vector<double> levels{1e-3, 1e-3 / std::sqrt(10.0) , 1e-4, 1e-4 / std::sqrt(10.0), 1e-5};
  const auto est = [&](const std::vector<Series>& m) { return at_equal_parameters(at_equal(m[0], m[1], m[2], m[3], levels)); };
  const Jackknife j = jackknife_linked({{xa, ya}, {xb, yb}}, est);
  const double v = est({mean_series(xa), mean_series(ya), mean_series(xb), mean_series(yb)})[0];
  return ratio_verdict(v, j.se[0], j.dof[0], kSigmas, kTolerance);
}

// ---- the crossing time's slope against the box size (gg-fit crossing --x): three box edges x = 512, 1024,
// 2048 with 8, 8 and 4 runs, sampled 8 times per decade over t = 10-1e5 as the study's snapshots are. A run's
// share of the clustered particles in its largest cluster is a logistic in ln t, 1 / (1 + exp(-ln(t / t_r) /
// 0.5)) (from 0.1 to 0.9 over a decade), with additive noise of 0.03 correlated over 0.3 decades; its
// crossing time t_r = 1000 (x / 512)^kappa exp(0.2 xi) scatters log-normally by 20% between runs. With
// `step`, a run's series is instead 0 before t_r and 1 from it on (its largest cluster wraps at t_r and
// stays wrapped), so the mean is the fraction of runs wrapping. The level is 1/2. `per_run`: t* is the mean of
// the runs' own ln t_r (gg-fit crossing --per-run), not the mean's crossing.
inline constexpr int kCrossingPerDecade = 8;
struct CrossingTrial {
  CrossingSlope slope;
  std::string verdict;
  bool covered = false;     // kappa within the slope's interval
  int inputs_missed = 0;    // of the three, how many intervals of ln t* miss the truth ln t_c
};
inline CrossingTrial crossing_trial(unsigned long seed, double kappa = 0, bool step = false, bool per_run = false) {
  testing::Rng rng(seed);
  const auto t = testing::log_times(10, 1e5, 4 * kCrossingPerDecade + 1);
  const double phi = std::exp(-1.0 / kCrossingPerDecade / 0.3);
  const std::vector<double> x{512, 1024, 2048};
  const std::vector<int> runs{8, 8, 4};
  std::vector<double> lt, var, dof, weight(runs.begin(), runs.end());
  int missed = 0;
  for (std::size_t j = 0; j < x.size(); ++j) {
    const double tc = 1000 * std::pow(x[j] / 512, kappa);  // where the mean of infinitely many runs crosses 1/2
    std::vector<RunData> rs;
    for (int r = 0; r < runs[j]; ++r) {
      const double tr = tc * std::exp(0.2 * rng.normal());
      RunData run{t, 1, {}, "run" + std::to_string(r)};
      double eta = 0.03 * rng.normal();
      for (std::size_t k = 0; k < t.size(); ++k) {
        if (k > 0) eta = phi * eta + 0.03 * std::sqrt(1 - phi * phi) * rng.normal();
        run.values.push_back(step ? (t[k] >= tr ? 1.0 : 0.0) : 1 / (1 + std::exp(-std::log(t[k] / tr) / 0.5)) + eta);
      }
      rs.push_back(run);
    }
    const Ensemble e = common_grid(rs, false);
    const CrossingEstimate c = per_run ? mean_of_crossings(e, 0.5, CrossingRule::first) : crossing_of_mean(e, 0.5, CrossingRule::first);
    lt.push_back(c.log_time), var.push_back(c.log_time_stderr * c.log_time_stderr), dof.push_back(c.log_time_dof);
    missed += !(std::abs(c.log_time - std::log(tc)) <= student_quantile(kSigmas, c.log_time_dof) * c.log_time_stderr);
  }
  const CrossingSlope s = crossing_slope(x, weight, lt, var, dof);
  return {s, slope_verdict(s, kSigmas, kTolerance),
          std::abs(s.slope - kappa) <= student_quantile(kSigmas, s.slope_dof) * s.slope_stderr, missed};
}
// Whether the crossing trial rejects slope = 0 (says it grows or falls).
inline bool crossing_rejects_zero(unsigned long seed, double kappa = 0, bool step = false, bool per_run = false) {
  const std::string v = crossing_trial(seed, kappa, step, per_run).verdict;
  return v == "grows with x" || v == "falls with x";
}

}  // namespace gg::fit::calibration
