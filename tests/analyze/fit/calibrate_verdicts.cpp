// calibrate-verdicts [TRIALS [SEED]]: the calibration table of gg-fit's verdicts (docs/PHYSICS.md
// "Calibration of the verdicts"). For each verdict and 4 and 8 runs a side (the crossing time's slope:
// 8, 8 and 4 runs at three box sizes): the rate at which it rejects a true claim at 2 sigma (to lie
// within 2.5-10%), and the rate at which it detects a departure of the size the study's data show (its
// power), over TRIALS synthetic trials each
// (calibration.hpp; default 200), seeds SEED + trial (default 1). Prints a Markdown table on stdout.
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>

#include "calibration.hpp"

using namespace gg::fit;
using namespace gg::fit::calibration;

namespace {

double rate(int trials, unsigned long seed, const std::function<bool(unsigned long)>& hit) {
  int n = 0;
  for (int i = 0; i < trials; ++i) n += hit(seed + static_cast<unsigned long>(i));
  return 100.0 * n / trials;
}

// power < 0: none (a verdict without a departure to detect).
void row(const char* verdict, const std::string& runs, double false_rate, double power, const char* departure, int trials) {
  char p[32] = "-";
  if (power >= 0) std::snprintf(p, sizeof p, "%.1f%%", power);
  std::printf("| %s | %s | %.1f%% | %s | %s | %d |\n", verdict, runs.c_str(), false_rate, p, departure, trials);
}

}  // namespace

int main(int argc, char** argv) {
  const int trials = argc > 1 ? std::atoi(argv[1]) : 200;
  const unsigned long seed = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 1;
  if (trials < 1) {
    std::fprintf(stderr, "calibrate-verdicts: TRIALS must be a positive integer (got '%s')\n", argv[1]);
    return 2;
  }
  std::printf("| verdict | runs a side | false rejection at 2 sigma | power | departure | trials |\n|---|---|---|---|---|---|\n");
  for (int R : {4, 8}) {
    const std::string runs = std::to_string(R);
    row("shift: collapses", runs, rate(trials, seed, [&](unsigned long s) { return !shift_trial(s, R).collapses; }),
        rate(trials, seed, [&](unsigned long s) { return !shift_trial(s, R, 1.2).collapses; }),
        "c drifting by 20% across the window", trials);
    row("shift: c constant", runs, rate(trials, seed, [&](unsigned long s) { return shift_trial(s, R).constant != 1; }),
        rate(trials, seed, [&](unsigned long s) { return shift_trial(s, R, 1.2).constant != 1; }),
        "c drifting by 20% across the window", trials);
    row("shift: the 2-sigma interval of c misses the truth (nominal 4.6%)", runs,
        rate(trials, seed, [&](unsigned long s) { return !shift_trial(s, R).covered; }), -1, "-", trials);
    row("shift: collapses, white noise 2% per sample", runs,
        rate(trials, seed, [&](unsigned long s) { return !shift_trial(s, R, 1, kWhite).collapses; }),
        rate(trials, seed, [&](unsigned long s) { return !shift_trial(s, R, 1.2, kWhite).collapses; }),
        "c drifting by 20% across the window", trials);
    row("shift: the interval of c misses the truth, white noise", runs,
        rate(trials, seed, [&](unsigned long s) { return !shift_trial(s, R, 1, kWhite).covered; }), -1, "-", trials);
    row("late exponents agree", runs, rate(trials, seed, [&](unsigned long s) { return !exponents_agree_trial(s, R); }),
        rate(trials, seed, [&](unsigned long s) { return !exponents_agree_trial(s, R, 0.08); }),
        "exponents differing by 0.08", trials);
    row("late exponent settled", runs, rate(trials, seed, [&](unsigned long s) { return !settled_trial(s, R); }),
        rate(trials, seed, [&](unsigned long s) { return !settled_trial(s, R, 0.1); }),
        "local exponent changing by 0.1 per decade", trials);
    row("amplitudes agree at one common exponent (collapse)", runs,
        rate(trials, seed, [&](unsigned long s) { return !amplitudes_agree_trial(s, R); }),
        rate(trials, seed, [&](unsigned long s) { return !amplitudes_agree_trial(s, R, 1.2); }), "ratio 1.2", trials);
    row("ratio at equal times = 1", runs,
        rate(trials, seed, [&](unsigned long s) { return ratio_trial(s, R) == Verdict::rejected; }),
        rate(trials, seed, [&](unsigned long s) { return ratio_trial(s, R, 1.2) == Verdict::rejected; }),
        "ratio 1.2", trials);
    row("ratio at equal energy = 1", runs,
        rate(trials, seed, [&](unsigned long s) { return at_equal_trial(s, R) == Verdict::rejected; }),
        rate(trials, seed, [&](unsigned long s) { return at_equal_trial(s, R, 1.2) == Verdict::rejected; }),
        "ratio 1.2", trials);
  }
  // The crossing time against the box size: 8, 8 and 4 runs at three sizes (calibration.hpp); the
  // intervals of each ln t* are counted over the 3 x TRIALS inputs.
  const auto missed = [&](bool step, bool per_run = false) {
    double n = 0;
    for (int i = 0; i < trials; ++i) n += crossing_trial(seed + static_cast<unsigned long>(i), 0, step, per_run).inputs_missed;
    return 100 * n / (3.0 * trials);
  };
  row("crossing: the 2-sigma interval of ln t* misses the truth (nominal 4.6%), smooth share", "8, 8, 4", missed(false), -1, "-", trials);
  row("crossing: the interval of ln t* misses the truth, 0/1 wrapping", "8, 8, 4", missed(true), -1, "-", trials);
  row("crossing: slope = 0, smooth share", "8, 8, 4", rate(trials, seed, [](unsigned long s) { return crossing_rejects_zero(s, 0); }),
      rate(trials, seed, [](unsigned long s) { return crossing_trial(s, 0.5).verdict == "grows with x"; }),
      "kappa = 0.5", trials);
  row("crossing: slope = 0, 0/1 wrapping (a step per run)", "8, 8, 4",
      rate(trials, seed, [](unsigned long s) { return crossing_rejects_zero(s, 0, true); }),
      rate(trials, seed, [](unsigned long s) { return crossing_trial(s, 0.5, true).verdict == "grows with x"; }),
      "kappa = 0.5", trials);
  row("crossing --per-run: the interval of ln t* misses the truth, 0/1 wrapping", "8, 8, 4", missed(true, true), -1, "-", trials);
  row("crossing --per-run: slope = 0, 0/1 wrapping", "8, 8, 4",
      rate(trials, seed, [](unsigned long s) { return crossing_rejects_zero(s, 0, true, true); }),
      rate(trials, seed, [](unsigned long s) { return crossing_trial(s, 0.5, true, true).verdict == "grows with x"; }),
      "kappa = 0.5", trials);
  return 0;
}
