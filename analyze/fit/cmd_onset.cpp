// gg-fit onset: when m(t) leaves its plateau, and when its local exponent reaches the asymptote.
#include <cmath>
#include <string>
#include <vector>

#include "fit/ensemble.hpp"
#include "fit/onset.hpp"
#include "fit/power_law.hpp"
#include "fit/subcommands.hpp"
#include "gg/errors.hpp"

namespace gg::fit::cli {

int run_onset(const Common& c, const OnsetArgs& a) {
  Files files;
  Loaded in = load_series(files, resolve(a.input, ""));
  double zinf = a.asymptote;
  std::string source = "given (--asymptote)";
  if (!a.window.empty()) {
    PowerLawFit f = fit_power_law(in.series, window_from(a.window, "onset"));
    zinf = f.exponent;
    source = "power-law fit over t in " + fmt_window(window_from(a.window, "onset")) + ": z = " +
             pm(f.exponent, f.exponent_stderr);
  }
  if (!std::isfinite(zinf)) throw UsageError("onset: give the asymptotic exponent, --asymptote Z or --window T1 T2 to fit it");
  const OnsetCriterion& cr = a.criterion;
  PlateauOnset p = plateau_onset(in.series, cr);
  const double ta = asymptote_onset(in.series, zinf, cr);
  double se_p = kNaN, se_a = kNaN;
  const bool jack = use_jackknife(error_mode(a.errors) == ErrorMode::covariance ? ErrorMode::automatic : error_mode(a.errors), {&in});
  if (jack) {
    auto se = jackknife_stderr({*in.runs}, [&](const std::vector<Series>& m) {
      return std::vector<double>{plateau_onset(m[0], cr).time, asymptote_onset(m[0], zinf, cr)};
    });
    se_p = se[0];
    se_a = se[1];
  }
  const std::string errors = jack ? errors_text(true, error_mode(a.errors), in.series, in.runs->size())
                                  : "none (a single series; with >= " + std::to_string(kJackknifeMinRuns) +
                                        " runs averaged by 'gg-fit average' the jackknife over runs gives them)";
  Output out(c.output);
  if (out) {
    out->write_scalar("/onset/plateau", p.plateau);
    write_estimate(*out, "/onset/plateau_time", p.time, se_p);
    out->write_scalar("/onset/asymptote", zinf);
    write_estimate(*out, "/onset/asymptote_time", ta, se_a);
    out->attr("/onset", "criterion_plateau", describe_plateau(cr));
    out->attr("/onset", "criterion_asymptote", describe_asymptote(cr, zinf));
    out->attr("/onset", "asymptote_source", source);
    out->attr("/onset", "input", in.name);
    out->attr("/onset", "errors", errors);
    out->attr("/onset", "note", std::string("NaN time: the criterion is never met in the data"));
  }
  auto when = [](double t, double e) { return std::isnan(t) ? std::string("never") : "t = " + (std::isnan(e) ? fmt(t) : pm(t, e)); };
  out.finish(c.argv, files, "onset: " + in.name + ": leaves the plateau " + fmt(p.plateau) + " at " + when(p.time, se_p) +
      "; local exponent within " + fmt(cr.exponent_tol) + " of " + fmt(zinf) + " from " + when(ta, se_a) + " [" +
      describe_plateau(cr) + "; " + describe_asymptote(cr, zinf) + "; asymptote " + source + "]");
  return 0;
}

}  // namespace gg::fit::cli
