// Unit tests of the gg-fit library on synthetic data with known answers.
// Random numbers come from GSL's generators, so every platform draws the same samples.
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "fit/collapse.hpp"
#include "fit/ensemble.hpp"
#include "fit/extrapolate.hpp"
#include "fit/haff.hpp"
#include "fit/onset.hpp"
#include "fit/power_law.hpp"
#include "gg/errors.hpp"
#include "synthetic.hpp"

using namespace gg::fit;
using namespace gg::fit::testing;

namespace {

// y = A t^z (1 + noise * xi), independent xi per sample.
Series noisy_power_law(Rng& rng, const std::vector<double>& t, double A, double z, double noise) {
  Series s;
  s.t = t;
  for (double x : t) s.y.push_back(A * std::pow(x, z) * (1 + noise * rng.normal()));
  return s;
}

// R runs of y = A t^z with multiplicative noise, as an ensemble on one grid.
Ensemble noisy_ensemble(Rng& rng, const std::vector<double>& t, double A, double z, double noise, int R) {
  std::vector<RunData> runs;
  for (int r = 0; r < R; ++r) {
    Series s = noisy_power_law(rng, t, A, z, noise);
    runs.push_back(RunData{s.t, 1, s.y, "run" + std::to_string(r)});
  }
  return common_grid(runs, false);
}

}  // namespace

TEST(PowerLaw, ExactDataGiveExactExponentAndAmplitude) {
  Series s;
  s.t = log_times(1, 1000, 30);
  for (double t : s.t) s.y.push_back(2.5 * std::pow(t, 0.6));
  PowerLawFit f = fit_power_law(s, {1, 1000});
  EXPECT_NEAR(f.exponent, 0.6, 1e-12);
  EXPECT_NEAR(f.amplitude, 2.5, 1e-10);
  EXPECT_EQ(f.points, 30u);
}

TEST(PowerLaw, UnweightedErrorBarsAreHonestOver200Seeds) {
  Coverage z, a;
  for (unsigned long seed = 1; seed <= 200; ++seed) {
    Rng rng(seed);
    Series s = noisy_power_law(rng, log_times(1, 1000, 20), 3.0, 0.6, 0.05);
    PowerLawFit f = fit_power_law(s, {1, 1000});
    z.add(f.exponent, f.exponent_stderr, 0.6);
    a.add(std::log(f.amplitude), f.log_amplitude_stderr, std::log(3.0));
  }
  expect_honest(z, "exponent");
  expect_honest(a, "ln amplitude");
}

TEST(PowerLaw, EnsembleWeightedErrorBarsAreHonestOver200Seeds) {
  Coverage z;
  for (unsigned long seed = 1; seed <= 200; ++seed) {
    Rng rng(1000 + seed);
    Ensemble e = noisy_ensemble(rng, log_times(1, 1000, 20), 3.0, -1.0, 0.1, 10);
    PowerLawFit f = fit_power_law(mean_series(e), {1, 1000});
    ASSERT_TRUE(f.weighted);
    z.add(f.exponent, f.exponent_stderr, -1.0);
  }
  expect_honest(z, "weighted exponent");
}

// Real runs are correlated in time (a run that is ahead stays ahead); here each run has its own
// exponent. Point-wise weights then underestimate the exponent's error; the jackknife over runs does not.
TEST(PowerLaw, JackknifeOverRunsIsHonestForTimeCorrelatedRuns) {
  Coverage jack, cov;
  const auto t = log_times(1, 1000, 20);
  for (unsigned long seed = 1; seed <= 200; ++seed) {
    Rng rng(5000 + seed);
    std::vector<RunData> runs;
    for (int r = 0; r < 20; ++r) {
      const double zr = 0.6 + 0.05 * rng.normal();
      RunData run{t, 1, {}, "run"};
      for (double x : t) run.values.push_back(std::pow(x, zr) * (1 + 0.01 * rng.normal()));
      runs.push_back(run);
    }
    Ensemble e = common_grid(runs, false);
    const Window w{1, 1000};
    PowerLawFit f = fit_power_law(mean_series(e), w);
    auto se = jackknife_stderr({e}, [&](const std::vector<Series>& m) {
      return std::vector<double>{fit_power_law(m[0], w).exponent};
    });
    // The mean of t^{z_r} over runs is not exactly t^{mean z_r}; its exponent is the truth here.
    Series exact;
    exact.t = t;
    for (double x : t) {
      double m = 0;
      for (int k = 0; k < 4000; ++k) m += std::pow(x, 0.6 + 0.05 * gsl_cdf_ugaussian_Pinv((k + 0.5) / 4000));
      exact.y.push_back(m / 4000);
    }
    const double truth = fit_power_law(exact, w).exponent;
    jack.add(f.exponent, se[0], truth);
    cov.add(f.exponent, f.exponent_stderr, truth);
  }
  expect_honest(jack, "jackknife exponent");
  std::printf("  point-wise covariance errors on the same data: within 2 sigma %.1f%%\n", 100 * cov.f2());
  EXPECT_LT(cov.f2(), 0.9) << "point-wise errors were expected to be too small for correlated runs";
}

TEST(PowerLaw, OffsetModelRecoversPlateauAmplitudeAndExponent) {
  Coverage z;
  for (unsigned long seed = 1; seed <= 50; ++seed) {
    Rng rng(seed);
    Series s;
    s.t = log_times(0.1, 1000, 60);
    for (double t : s.t) s.y.push_back((4.0 + 0.5 * std::pow(t, 0.6)) * (1 + 0.01 * rng.normal()));
    PowerLawFit f = fit_power_law_offset(s, {0.1, 1000});
    EXPECT_TRUE(f.with_offset);
    EXPECT_NEAR(f.offset, 4.0, 5 * f.offset_stderr);
    EXPECT_NEAR(f.amplitude, 0.5, 5 * f.amplitude_stderr);
    z.add(f.exponent, f.exponent_stderr, 0.6);
  }
  EXPECT_GE(z.f2(), 0.86);
}

TEST(LocalExponent, ExactPowerLawGivesItsExponentEverywhere) {
  Series s;
  s.t = log_times(1, 1e4, 81);
  for (double t : s.t) s.y.push_back(7 * std::pow(t, 0.66));
  LocalExponent z = local_exponent(s, 0.5);
  ASSERT_FALSE(z.t.empty());
  EXPECT_GE(z.t.front(), std::pow(10.0, 0.25) * (1 - 1e-9));  // no one-sided windows at the ends
  EXPECT_LE(z.t.back(), 1e4 / std::pow(10.0, 0.25) * (1 + 1e-9));
  for (double v : z.exponent) EXPECT_NEAR(v, 0.66, 1e-10);
}

TEST(Onset, PlateauThenPowerLawGivesTheOnset) {
  // m = m0 for t < ton, m0 (t/ton)^z after: m exceeds m0 (1 + tol) at ton (1 + tol)^(1/z).
  const double m0 = 2.0, ton = 3.0, z = 2.0;
  for (unsigned long seed = 1; seed <= 20; ++seed) {
    Rng rng(seed);
    Series s;
    s.t = log_times(0.01, 1000, 101);  // 20 samples per decade
    for (double t : s.t) s.y.push_back(m0 * std::max(1.0, std::pow(t / ton, z)) * (1 + 0.005 * rng.normal()));
    OnsetCriterion c;
    PlateauOnset p = plateau_onset(s, c);
    EXPECT_NEAR(p.plateau, m0, 0.02);
    EXPECT_NEAR(p.time, ton * std::pow(1.1, 1 / z), 0.03 * ton) << "seed " << seed;
  }
}

TEST(Onset, LocalExponentReachesItsAsymptoteWhenThePlateauFades) {
  // m = m0 + A t^z: d ln m / d ln t = z A t^z / (m0 + A t^z) is within tol of z once
  // A t^z = m0 (z / tol - 1).
  const double m0 = 2.0, A = 0.01, z = 0.6;
  Series s;
  s.t = log_times(0.01, 1e7, 181);
  for (double t : s.t) s.y.push_back(m0 + A * std::pow(t, z));
  OnsetCriterion c;
  c.decades = 0.2;
  c.exponent_tol = 0.1;
  const double expected = std::pow(m0 * (z / c.exponent_tol - 1) / A, 1 / z);
  EXPECT_NEAR(asymptote_onset(s, z, c), expected, 0.05 * expected);
  // Never reached: an asymptote the data do not approach.
  EXPECT_TRUE(std::isnan(asymptote_onset(s, 2.0, c)));
  // Never leaves a flat plateau.
  Series flat{log_times(1, 100, 30), std::vector<double>(30, 5.0), {}};
  EXPECT_TRUE(std::isnan(plateau_onset(flat, c).time));
}

TEST(Haff, FitGivesBackT0) {
  Coverage c;
  const double E0 = 1.0, t0 = 9.258;
  for (unsigned long seed = 1; seed <= 100; ++seed) {
    Rng rng(seed);
    Series s;
    for (int i = 0; i <= 40; ++i) s.t.push_back(0.5 * i);
    for (double t : s.t) s.y.push_back(E0 / std::pow(1 + t / t0, 2) * (1 + 0.01 * rng.normal()));
    HaffFit f = fit_haff(s, {0, 20});
    EXPECT_NEAR(f.t0, t0, 0.05 * t0);
    EXPECT_NEAR(f.E0, E0, 0.02);
    c.add(f.t0, f.t0_stderr, t0);
  }
  EXPECT_GE(c.f2(), 0.9);
  EXPECT_LE(c.f1(), 0.85);
}

TEST(Haff, EnskogPredictionMatchesReferenceNumbers) {
  // docs/PHYSICS.md: phi(0.37) = 0.29060, Henderson g = 1.73445, Luding g = 1.73369, omega = 2.2739,
  // t0 = 2.345 (e = 0.5), 3.449 (0.7), 9.258 (0.9) at rho = 0.37, T0 = 1.
  HaffPrediction h = enskog_haff(2, 0.37, 0.5, 1.0, Contact::henderson);
  EXPECT_NEAR(h.phi, 0.29060, 1e-5);
  EXPECT_NEAR(h.g, 1.73445, 1e-5);
  EXPECT_NEAR(h.E0, 1.0, 1e-15);
  HaffPrediction l = enskog_haff(2, 0.37, 0.5, 1.0, Contact::luding);
  EXPECT_NEAR(l.g, 1.73369, 1e-5);
  EXPECT_NEAR(l.omega0, 2.2739, 1e-4);
  EXPECT_NEAR(l.t0, 2.345, 1e-3);
  EXPECT_NEAR(enskog_haff(2, 0.37, 0.7, 1.0, Contact::luding).t0, 3.449, 1e-3);
  EXPECT_NEAR(enskog_haff(2, 0.37, 0.9, 1.0, Contact::luding).t0, 9.258, 1e-3);
  EXPECT_NEAR(h.t0 / l.t0, l.g / h.g, 1e-12);
  // t0 scales as 1/sqrt(T0).
  EXPECT_NEAR(enskog_haff(2, 0.37, 0.9, 4.0).t0, enskog_haff(2, 0.37, 0.9, 1.0).t0 / 2, 1e-12);
  // 1D: omega0 = (2/sqrt(pi)) rho sqrt(T0)/(1 - rho), t0 = 2/((1-e^2) omega0); E = T/2.
  HaffPrediction d1 = enskog_haff(1, 0.3, 0.5, 1.0);
  EXPECT_NEAR(d1.omega0, 2 / std::sqrt(M_PI) * 0.3 / 0.7, 1e-12);
  EXPECT_NEAR(d1.t0, 2 / (0.75 * d1.omega0), 1e-12);
  EXPECT_NEAR(d1.E0, 0.5, 1e-15);
  // 3D (docs/PHYSICS.md "Hard spheres"): at eta = 0.2 the Carnahan-Starling g = 1.7578 and Enskog
  // omega = 4.7603; t0 = 6/((1-e^2) omega0), i.e. Brilliantov & Poeschel's 1/t0 = (2/3)(1-e^2) g rho sqrt(pi T0).
  const double rho3 = 6 * 0.2 / M_PI;
  HaffPrediction d3 = enskog_haff(3, rho3, 0.9, 1.0);
  EXPECT_NEAR(d3.phi, 0.2, 1e-12);
  EXPECT_NEAR(d3.g, 1.7578, 1e-4);
  EXPECT_NEAR(d3.omega0, 4.7603, 1e-4);
  EXPECT_NEAR(d3.t0, 6 / (0.19 * 4.7603), 1e-3);
  EXPECT_NEAR(1 / d3.t0, 2.0 / 3 * 0.19 * d3.g * rho3 * std::sqrt(M_PI), 1e-12);
  EXPECT_NEAR(d3.E0, 1.5, 1e-15);
  EXPECT_THROW(enskog_haff(3, 6 * 0.75 / M_PI, 0.5, 1.0), gg::UsageError);  // beyond close packing
  EXPECT_THROW(enskog_haff(2, 0.37, 1.0, 1.0), gg::UsageError);
  EXPECT_THROW(enskog_haff(4, 0.37, 0.5, 1.0), gg::UsageError);
}

namespace {
// Three ensembles (different e): the same late-time law A t^z, each seen over its own window.
CollapseFit collapse_trial(unsigned long seed, double A1_over_A0) {
  Rng rng(seed);
  const std::vector<Window> w{{100, 1000}, {200, 1000}, {300, 1000}};
  std::vector<Series> means;
  for (int j = 0; j < 3; ++j) {
    const double A = j == 1 ? 1.5 * A1_over_A0 : 1.5;
    means.push_back(mean_series(noisy_ensemble(rng, log_times(w[j].t1, w[j].t2, 15), A, 0.6, 0.05, 8)));
  }
  return fit_collapse(means, w);
}
}  // namespace

TEST(Collapse, EqualAmplitudesAreReportedEqual) {
  int agree = 0;
  Coverage z;
  for (unsigned long seed = 1; seed <= 100; ++seed) {
    CollapseFit f = collapse_trial(seed, 1.0);
    agree += f.all_agree;
    z.add(f.exponent, f.exponent_stderr, 0.6);
    EXPECT_EQ(f.ratio[0], 1.0);
  }
  // Two comparisons at 2 sigma each: about 91% of trials agree on both when nothing differs.
  EXPECT_GE(agree, 85) << "equal amplitudes reported different too often";
  EXPECT_GE(z.f2(), 0.9);
}

TEST(Collapse, AmplitudesDifferingBy20PercentAreReportedDifferent) {
  for (unsigned long seed = 1; seed <= 100; ++seed) {
    CollapseFit f = collapse_trial(seed, 1.2);
    EXPECT_FALSE(f.all_agree) << "seed " << seed;
    EXPECT_EQ(f.agree[1], 0) << "seed " << seed;
    EXPECT_NEAR(f.ratio[1], 1.2, 4 * f.ratio_stderr[1]);
  }
}

// The finite-size study quotes A(e)/A(0.5) with a 2-sigma interval: against a synthetic power law with a
// known amplitude ratio the interval must hold it as often as it claims.
TEST(Collapse, AmplitudeRatioIntervalCoversTheKnownRatio) {
  Coverage r;
  for (unsigned long seed = 1; seed <= 200; ++seed) {
    CollapseFit f = collapse_trial(seed, 0.7);
    r.add(f.ratio[1], f.ratio_stderr[1], 0.7);
  }
  expect_honest(r, "A_1/A_0 = 0.7");
}

TEST(Collapse, JackknifeErrorsReplaceCovarianceErrors) {
  CollapseFit f = collapse_trial(7, 1.0);
  auto p = collapse_parameters(f);
  ASSERT_EQ(p.size(), 1u + 3u + 2u);
  Jackknife huge{std::vector<double>(p.size(), 10.0), std::vector<double>(p.size(), 3.0)};
  set_collapse_errors(f, huge);
  EXPECT_TRUE(f.all_agree);
  EXPECT_DOUBLE_EQ(f.exponent_stderr, 10.0);
  EXPECT_DOUBLE_EQ(f.log_ratio_dof[1], 3.0);
  // A difference of 2.5 standard errors: beyond the normal's 2 sigma, within Student's t for 3 dof (3.31).
  Jackknife tight{std::vector<double>(p.size(), 0.0), std::vector<double>(p.size(), 3.0)};
  const double d = f.log_amplitude[1] - f.log_amplitude[0];
  tight.se[4] = std::abs(d) / 2.5;
  set_collapse_errors(f, tight);
  EXPECT_EQ(f.agree[1], 1);
  tight.dof[4] = std::numeric_limits<double>::infinity();
  set_collapse_errors(f, tight);
  EXPECT_EQ(f.agree[1], 0);
}

// The jackknife of a mean is s / sqrt(R) with R - 1 degrees of freedom; two groups add their variances
// and take Welch-Satterthwaite's degrees of freedom; the normal's quantile is Student's at infinity.
TEST(Jackknife, ErrorOfAMeanAndItsDegreesOfFreedom) {
  const auto group = [](std::vector<double> v) {
    std::vector<RunData> runs;
    for (double x : v) runs.push_back(RunData{{1, 2}, 1, {x, x}, "run"});
    return common_grid(runs, false);
  };
  const Ensemble a = group({1, 2, 3, 6}), flat = group({5, 5, 5}), b = group({0, 4, 8});
  const Estimator last = [](const std::vector<Series>& m) {
    std::vector<double> p;
    for (const Series& s : m) p.push_back(s.y[1]);
    return p;
  };
  const Jackknife one = jackknife({a}, last);
  EXPECT_NEAR(one.se[0], std::sqrt(14.0 / 3 / 4), 1e-12);  // s^2 = 14/3 over 4 runs
  EXPECT_NEAR(one.dof[0], 3, 1e-12);
  // The difference of two means: var = 14/12 + 16/3; dof = var^2 / ((14/12)^2 / 3 + (16/3)^2 / 2).
  const Jackknife two = jackknife({a, b}, [&](const std::vector<Series>& m) { return std::vector<double>{m[1].y[1] - m[0].y[1]}; });
  const double va = 14.0 / 12, vb = 16.0 / 3;
  EXPECT_NEAR(two.se[0], std::sqrt(va + vb), 1e-12);
  EXPECT_NEAR(two.dof[0], (va + vb) * (va + vb) / (va * va / 3 + vb * vb / 2), 1e-9);
  // A group without scatter adds nothing: the other's dof.
  EXPECT_NEAR(jackknife({a, flat}, [&](const std::vector<Series>& m) { return std::vector<double>{m[1].y[1] - m[0].y[1]}; }).dof[0], 3, 1e-9);
  EXPECT_NEAR(student_quantile(2, 3), 3.307, 1e-3);
  EXPECT_NEAR(student_quantile(2, 6), 2.517, 1e-3);
  EXPECT_DOUBLE_EQ(student_quantile(2, std::numeric_limits<double>::infinity()), 2);
  EXPECT_TRUE(std::isnan(student_quantile(2, 0)));
  // Welch's difference of two estimates.
  const Estimate d = difference({1.0, 0.3, 3}, {0.5, 0.4, 3});
  EXPECT_NEAR(d.value, 0.5, 1e-15);
  EXPECT_NEAR(d.se, 0.5, 1e-15);
  EXPECT_NEAR(d.dof, 0.0625 / ((0.0081 + 0.0256) / 3), 1e-9);
  EXPECT_TRUE(within(d, 0, 2));   // 1 se, t ~ 3
  EXPECT_FALSE(within({2.0, 0.5, 100}, 0, 2));
}

TEST(Average, MeanAndStandardErrorFrameByFrame) {
  // Two runs of a [T=2][C=3] dataset (e.g. C(r,t)).
  RunData a{{1, 2}, 3, {1, 2, 3, 4, 5, 6}, "a"};
  RunData b{{1, 2}, 3, {3, 2, 1, 4, 7, 8}, "b"};
  Average m = average(common_grid({a, b}, false));
  ASSERT_EQ(m.mean.size(), 6u);
  EXPECT_EQ(m.cols, 3u);
  const std::vector<double> mean{2, 2, 2, 4, 6, 7}, err{1, 0, 1, 0, 1, 1};
  for (int k = 0; k < 6; ++k) {
    EXPECT_DOUBLE_EQ(m.mean[k], mean[k]);
    EXPECT_DOUBLE_EQ(m.err[k], err[k]);  // s / sqrt(2) with s = |a - b| / sqrt(2)
  }
}

TEST(Average, InterpolatesInLogTimeOnlyWhenAsked) {
  RunData a{{0, 1, 10, 100}, 1, {5, 1, 2, 3}, "a.h5:/g/m"};
  RunData b{{0, 1, 100}, 1, {5, 1, 3}, "b.h5:/g/m"};
  try {
    common_grid({a, b}, false);
    FAIL() << "runs of different length must be refused";
  } catch (const gg::RuntimeError& e) {
    EXPECT_NE(std::string(e.what()).find("--interpolate"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("different length"), std::string::npos) << e.what();
  }
  RunData c{{0, 1, 10, 101}, 1, {5, 1, 2, 3}, "c"};
  EXPECT_THROW(common_grid({a, c}, false), gg::RuntimeError);  // same length, different times
  Ensemble e = common_grid({a, b}, true);
  EXPECT_TRUE(e.interpolated);
  ASSERT_EQ(e.t.size(), 4u);  // t = 0 is shared exactly; t = 10 interpolated in ln t
  EXPECT_DOUBLE_EQ(e.runs[1][2], 2.0);  // halfway between ln 1 and ln 100
  RunData late{{10, 1000}, 1, {1, 1}, "late"};
  Ensemble f = common_grid({a, late}, true);  // grid: a's times inside [10, 100]
  EXPECT_EQ(f.t, (std::vector<double>{10, 100}));
  EXPECT_EQ(f.dropped, 2u);
  EXPECT_THROW(common_grid({a}, false), gg::UsageError);
}

TEST(BadInput, EmptyWindowFewPointsNonPositiveValues) {
  Series s;
  s.t = log_times(1, 100, 10);
  for (double t : s.t) s.y.push_back(t);
  auto message = [&](const Window& w) -> std::string {
    try {
      fit_power_law(s, w);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_THROW(fit_power_law(s, {10, 10}), gg::UsageError);  // empty by construction
  EXPECT_THROW(fit_power_law(s, {10, 5}), gg::UsageError);
  EXPECT_NE(message({10, 5}).find("empty window"), std::string::npos);
  EXPECT_THROW(fit_power_law(s, {200, 300}), gg::RuntimeError);  // no samples there
  EXPECT_NE(message({200, 300}).find("no samples in the window"), std::string::npos) << message({200, 300});
  EXPECT_THROW(fit_power_law(s, {1, 2}), gg::RuntimeError);  // 2 samples in [1, 2]
  EXPECT_NE(message({1, 2}).find("need at least 3"), std::string::npos) << message({1, 2});
  s.y[4] = 0;
  EXPECT_THROW(fit_power_law(s, {1, 100}), gg::RuntimeError);
  EXPECT_NE(message({1, 100}).find("non-positive"), std::string::npos) << message({1, 100});
  s.y[4] = -1;
  EXPECT_THROW(local_exponent(s, 1.0), gg::RuntimeError);
  EXPECT_THROW(fit_collapse({s, s}, {{1, 100}, {1, 100}}), gg::RuntimeError);
  s.y[4] = std::nan("");
  EXPECT_THROW(fit_power_law(s, {1, 100}), gg::RuntimeError);
  Series tiny{{1, 2, 3}, {1, 2, 3}, {}};
  EXPECT_THROW(fit_power_law_offset(tiny, {1, 3}), gg::RuntimeError);  // 4 needed for 3 parameters
  EXPECT_THROW(fit_haff(Series{{0, 1}, {1, 0.5}, {}}, {0, 1}), gg::RuntimeError);
  EXPECT_THROW(fit_collapse({tiny}, {{1, 3}}), gg::UsageError);
}

// ------------------------------------------------------------------------------------------------
// Finite-size extrapolation y(L) = y_inf + b / L and the equality verdict (fit/extrapolate.hpp).

TEST(Extrapolate, ExactLineInInverseSizeGivesItsLimit) {
  const std::vector<double> L{128, 256, 512, 1024};
  std::vector<double> y, e;
  for (double l : L) {
    y.push_back(0.8 + 50 / l);
    e.push_back(0.01);
  }
  const SizeExtrapolation x = extrapolate_in_inverse_size(L, y, e);
  EXPECT_NEAR(x.limit, 0.8, 1e-12);
  EXPECT_NEAR(x.slope, 50, 1e-9);
  EXPECT_EQ(x.points, 4u);
  EXPECT_GT(x.limit_stderr, 0);
}

TEST(Extrapolate, TwoSizesGiveTheLineThroughBothWithPropagatedErrors) {
  // x = 1/L = 0.01, 0.005; y = 1.0 +- 0.02, 0.9 +- 0.01: slope 20, limit 0.8, and
  // limit = (x1 y0 - x0 y1)/(x1 - x0) has stderr sqrt((x1 s0)^2 + (x0 s1)^2) / |x1 - x0| = 0.02 sqrt 2.
  const SizeExtrapolation x = extrapolate_in_inverse_size({100, 200}, {1.0, 0.9}, {0.02, 0.01});
  EXPECT_NEAR(x.slope, 20, 1e-12);
  EXPECT_NEAR(x.limit, 0.8, 1e-12);
  EXPECT_NEAR(x.limit_stderr, 0.02 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(x.slope_stderr, std::hypot(0.02, 0.01) / 0.005, 1e-9);
  EXPECT_TRUE(std::isnan(x.chi2_dof));
}

TEST(Extrapolate, SizesWithoutAValueAreLeftOutAndTooFewAreAnError) {
  const double nan = std::nan("");
  const SizeExtrapolation x = extrapolate_in_inverse_size({64, 128, 256}, {nan, 1.0, 0.9}, {0.1, 0.02, 0.01});
  EXPECT_EQ(x.points, 2u);
  EXPECT_NEAR(x.limit, 0.8, 1e-12);
  EXPECT_THROW(extrapolate_in_inverse_size({64, 128}, {nan, 1.0}, {0.1, 0.02}), gg::RuntimeError);
  EXPECT_THROW(extrapolate_in_inverse_size({0, 128}, {1.0, 1.0}, {0.1, 0.02}), gg::RuntimeError);
}

TEST(Extrapolate, LimitIntervalCoversTheTruthOverNoisyTrials) {
  Rng rng(11);
  const std::vector<double> L{256, 512, 1024, 2048}, s{0.04, 0.03, 0.02, 0.015};
  Coverage c;
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<double> y;
    for (std::size_t i = 0; i < L.size(); ++i) y.push_back(0.6 + 40 / L[i] + s[i] * rng.normal());
    const SizeExtrapolation x = extrapolate_in_inverse_size(L, y, s);
    c.add(x.limit, x.limit_stderr, 0.6);
  }
  // The covariance is only ever inflated (max(1, chi2/dof)), so the coverage may exceed 68/95%,
  // but not by much with two degrees of freedom; a wrong error formula misses these bounds.
  EXPECT_GE(c.f2(), 0.93);
  EXPECT_GE(c.f1(), 0.66);
  EXPECT_LE(c.f1(), 0.85);
}

TEST(Verdict, EquivalenceRuleAtTwoSigma) {
  // value, stderr -> 2-sigma interval; expected 1 within 10%.
  EXPECT_EQ(equality_verdict(1.00, 0.02, 1, 2, 0.1), Verdict::supported);  // [0.96, 1.04] inside [0.9, 1.1]
  EXPECT_EQ(equality_verdict(0.62, 0.05, 1, 2, 0.1), Verdict::rejected);   // [0.52, 0.72] excludes 1
  EXPECT_EQ(equality_verdict(1.30, 0.10, 1, 2, 0.1), Verdict::rejected);   // [1.10, 1.50] excludes 1
  EXPECT_EQ(equality_verdict(0.95, 0.06, 1, 2, 0.1), Verdict::undecided);  // [0.83, 1.07]: holds 1, too wide
  EXPECT_EQ(equality_verdict(1.10, 0.05, 1, 2, 0.1), Verdict::undecided);  // [1.00, 1.20]: 1 on its edge
  EXPECT_EQ(equality_verdict(0.93, 0.015, 1, 2, 0.1), Verdict::rejected);  // small but significant deviation
  EXPECT_EQ(equality_verdict(std::nan(""), 0.01, 1, 2, 0.1), Verdict::undecided);
  EXPECT_EQ(equality_verdict(1.0, std::nan(""), 1, 2, 0.1), Verdict::undecided);
  // A wider tolerance or fewer sigmas turn "undecided" into "supported".
  EXPECT_EQ(equality_verdict(0.95, 0.06, 1, 2, 0.2), Verdict::supported);
  EXPECT_EQ(equality_verdict(0.97, 0.06, 1, 2, 0.1), Verdict::undecided);  // [0.85, 1.09]
  EXPECT_EQ(equality_verdict(0.97, 0.06, 1, 1, 0.1), Verdict::supported);  // [0.91, 1.03]
}

TEST(Verdict, CombinedOverSeveralRatios) {
  using V = Verdict;
  EXPECT_EQ(combined_verdict({V::supported, V::supported}), V::supported);
  EXPECT_EQ(combined_verdict({V::supported, V::undecided}), V::undecided);
  EXPECT_EQ(combined_verdict({V::undecided, V::rejected}), V::rejected);
  EXPECT_EQ(combined_verdict({}), V::undecided);
  EXPECT_EQ(verdict_name(V::rejected), "rejected");
}
