// gg-fit haff: E(t) = E0/(1+t/t0)^2 over an early window, t0 compared with the Enskog prediction.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fit/ensemble.hpp"
#include "fit/haff.hpp"
#include "fit/subcommands.hpp"
#include "gg/errors.hpp"

namespace gg::fit::cli {

int run_haff(const Common& c, const HaffArgs& a) {
  Files files;
  Loaded in = load_series(files, resolve(a.input, ""));
  const H5Input& f = *in.file;
  std::vector<std::string> notes;
  // Flags override the file's /parameters (as flags override a scene).
  auto pick = [&](double flag, const char* key) -> std::optional<double> {
    if (std::isfinite(flag)) return flag;
    if (auto v = param(f, key)) {
      notes.push_back(std::string(key) + " from /parameters");
      return v;
    }
    return std::nullopt;
  };
  int dim = a.dim;
  if (!dim) {
    if (auto d = param(f, "dim")) {
      dim = static_cast<int>(*d);
      notes.push_back("dim from /parameters");
    } else if (f.exists("/particles/all/box")) {
      if (auto d = f.attr_double("/particles/all/box", "dimension")) {
        dim = static_cast<int>(*d);
        notes.push_back("dim from /particles/all/box");
      }
    }
  }
  if (!dim) {
    dim = 2;
    notes.push_back("dim not in the file: assumed 2 (--dim)");
  }
  std::optional<double> rho = pick(a.rho, "rho");
  if (!rho) {
    auto N = param(f, "N"), L = param(f, "L");
    if (N && L && *L > 0) {
      rho = *N / std::pow(*L, dim);
      notes.push_back("rho = N/L^d from /parameters");
    }
  }
  std::optional<double> e = pick(a.e, "e");
  std::optional<double> T0 = pick(a.T0, "T0");
  if (!T0) {
    T0 = 2 * in.series.y.front() / dim;
    notes.push_back("T0 = 2 E/d at the first sample (not in the file; --T0)");
  }
  const Contact contact = a.contact == "luding" ? Contact::luding : Contact::henderson;
  std::optional<HaffPrediction> pred;
  if (rho && e) pred = enskog_haff(dim, *rho, *e, *T0, contact);
  Window w;
  std::string window_note;
  if (!a.window.empty()) {
    w = window_from(a.window, "haff");
  } else if (pred) {
    // Early times only: by t = t0 clustering and the Sonine correction already move T by 4-15%
    // (docs/PHYSICS.md), so the default window ends at half the predicted t0.
    w = {*std::min_element(in.series.t.begin(), in.series.t.end()), 0.5 * pred->t0};
    window_note = " (default: up to half the Enskog t0)";
  } else {
    throw UsageError("haff: no --window given and no rho and e found in " + f.path() +
                     " /parameters to predict t0 from; give --window T1 T2 (or --rho and --e)");
  }
  HaffFit h = fit_haff(in.series, w);
  const bool jack = use_jackknife(error_mode(a.errors), {&in});
  if (jack) {
    auto se = jackknife_stderr({*in.runs}, [&](const std::vector<Series>& m) {
      HaffFit g = fit_haff(m[0], w);
      return std::vector<double>{g.t0, g.E0};
    });
    h.t0_stderr = se[0];
    h.E0_stderr = se[1];
  }
  const std::string errors = errors_text(jack, error_mode(a.errors), in.series, in.runs ? in.runs->size() : 0);
  std::string sources;
  for (const auto& n : notes) sources += (sources.empty() ? "" : "; ") + n;
  Output out(c.output);
  if (out) {
    write_estimate(*out, "/fit/E0", h.E0, h.E0_stderr);
    write_estimate(*out, "/fit/t0", h.t0, h.t0_stderr);
    write_fit_quality(*out, in, h, w,
                      "haff: nonlinear least squares of ln E = ln E0 - 2 ln(1 + t/t0) (GSL multifit_nlinear)",
                      "E(t) = E0 / (1 + t/t0)^2", errors);
    out->attr("/fit", "parameter_sources", sources);
    if (pred) {
      out->write_scalar("/fit/t0_enskog", pred->t0);
      write_estimate(*out, "/fit/t0_ratio", h.t0 / pred->t0, h.t0_stderr / pred->t0);
      out->write_scalar("/fit/E0_expected", pred->E0);
      out->attr("/fit", "enskog", std::string("t0 = 2d/((1 - e^2) omega0), omega0 = 2 pi^((d-1)/2)/Gamma(d/2) rho g sqrt(T0)"));
      out->attr("/fit", "contact_value", pred->g_name);
      out->attr("/fit", "dim", static_cast<std::int64_t>(pred->dim));
      out->attr("/fit", "rho", pred->rho);
      out->attr("/fit", "e", pred->e);
      out->attr("/fit", "T0", pred->T0);
      out->attr("/fit", "phi", pred->phi);
      out->attr("/fit", "g", pred->g);
      out->attr("/fit", "omega0", pred->omega0);
    }
  }
  std::string line = "haff: " + in.name + ": E = E0/(1+t/t0)^2 over t in " + fmt_window(w) + window_note + " (" +
                     std::to_string(h.points) + " samples): t0 = " + pm(h.t0, h.t0_stderr) + ", E0 = " +
                     pm(h.E0, h.E0_stderr) + ", " + chi2_text(h.weighted, h.chi2_dof);
  if (pred)
    line += "; Enskog t0 = " + fmt(pred->t0) + " (d = " + std::to_string(dim) + ", rho = " + fmt(pred->rho) +
            ", e = " + fmt(pred->e) + ", T0 = " + fmt(pred->T0) + ", " + pred->g_name + " = " + fmt(pred->g) +
            ", omega0 = " + fmt(pred->omega0) + "), fit/Enskog = " + pm(h.t0 / pred->t0, h.t0_stderr / pred->t0);
  else
    line += "; no Enskog prediction (give --rho and --e)";
  line += "; errors: " + errors + (sources.empty() ? "" : "; " + sources);
  out.finish(c.argv, files, line);
  return 0;
}

}  // namespace gg::fit::cli
