// gg-fit power-law and local-exponent: y = A t^z (or y0 + A t^z) over one window, and d ln y / d ln t
// from sliding fits.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "fit/ensemble.hpp"
#include "fit/power_law.hpp"
#include "fit/subcommands.hpp"

namespace gg::fit::cli {

int run_power_law(const Common& c, const PowerLawArgs& a) {
  Files files;
  Loaded in = load_series(files, resolve(a.input, ""));
  const Window w = window_from(a.window, "power-law");
  PowerLawFit f = a.offset ? fit_power_law_offset(in.series, w) : fit_power_law(in.series, w);
  const bool jack = use_jackknife(error_mode(a.errors), {&in});
  if (jack) {
    auto se = jackknife_stderr({*in.runs}, [&](const std::vector<Series>& m) {
      if (a.offset) {
        PowerLawFit g = fit_power_law_offset(m[0], w);
        return std::vector<double>{g.exponent, g.amplitude, g.offset};
      }
      PowerLawFit g = fit_power_law(m[0], w);
      return std::vector<double>{g.exponent, std::log(g.amplitude)};
    });
    f.exponent_stderr = se[0];
    if (a.offset) {
      f.amplitude_stderr = se[1];
      f.log_amplitude_stderr = se[1] / std::abs(f.amplitude);
      f.offset_stderr = se[2];
    } else {
      f.log_amplitude_stderr = se[1];
      f.amplitude_stderr = f.amplitude * se[1];
    }
  }
  const std::string model = a.offset ? "y = y0 + A t^z" : "y = A t^z";
  const std::string method =
      a.offset ? "power-law with offset: nonlinear least squares of ln y = ln(y0 + A t^z) (GSL multifit_nlinear)"
               : "power-law: weighted least squares of ln y on ln t (GSL multifit_wlinear)";
  const std::string errors = errors_text(jack, error_mode(a.errors), in.series, in.runs ? in.runs->size() : 0);
  Output out(c.output);
  if (out) {
    write_estimate(*out, "/fit/exponent", f.exponent, f.exponent_stderr);
    write_estimate(*out, "/fit/amplitude", f.amplitude, f.amplitude_stderr);
    if (a.offset) {
      write_estimate(*out, "/fit/offset", f.offset, f.offset_stderr);
    }
    write_fit_quality(*out, in, f, w, method, model, errors);
    out->attr("/fit", "samples_used", std::vector<double>{f.t_first, f.t_last});
  }
  out.finish(c.argv, files, "power-law: " + in.name + ": " + model + " over t in " + fmt_window(w) + " (" + std::to_string(f.points) +
      " samples): z = " + pm(f.exponent, f.exponent_stderr) + ", A = " + pm(f.amplitude, f.amplitude_stderr) +
      (a.offset ? ", y0 = " + pm(f.offset, f.offset_stderr) : std::string()) + ", " + chi2_text(f.weighted, f.chi2_dof) +
      "; errors: " + errors);
  return 0;
}

int run_local_exponent(const Common& c, const LocalArgs& a) {
  Files files;
  Loaded in = load_series(files, resolve(a.input, ""));
  LocalExponent z = local_exponent(in.series, a.decades);
  const bool jack = use_jackknife(error_mode(a.errors), {&in});
  if (jack)
    z.err = jackknife_stderr({*in.runs}, [&](const std::vector<Series>& m) { return local_exponent(m[0], a.decades).exponent; });
  const std::string errors = jack ? errors_text(true, error_mode(a.errors), in.series, in.runs->size())
                                  : "covariance of each sliding fit (" + errors_text(false, error_mode(a.errors), in.series, in.runs ? in.runs->size() : 0) + ")";
  Output out(c.output);
  if (out) {
    out->write("/local_exponent/time", z.t);
    out->write("/local_exponent/exponent", z.exponent);
    out->write("/local_exponent/stderr", z.err);
    out->attr("/local_exponent", "method",
              "d ln y / d ln t from least squares of ln y on ln t over +-" + fmt(a.decades / 2) +
                  " decades around each time (only times whose whole window lies inside the data)");
    out->attr("/local_exponent", "input", in.name);
    out->attr("/local_exponent", "window_decades", a.decades);
    out->attr("/local_exponent", "errors", errors);
  }
  const auto [lo, hi] = std::minmax_element(z.exponent.begin(), z.exponent.end());
  out.finish(c.argv, files, "local-exponent: " + in.name + ": " + std::to_string(z.t.size()) + " times in [" + fmt(z.t.front()) + ", " +
      fmt(z.t.back()) + "], window " + fmt(a.decades) + " decades: z from " + fmt(*lo) + " to " + fmt(*hi) +
      ", last z(" + fmt(z.t.back()) + ") = " + pm(z.exponent.back(), z.err.back()) + "; errors: " + errors);
  return 0;
}

}  // namespace gg::fit::cli
