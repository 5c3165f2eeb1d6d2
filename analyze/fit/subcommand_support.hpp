#pragma once
// The plumbing every gg-fit subcommand (fit/subcommands.hpp) shares: opening the named files once,
// reading a dataset into a Series with its time axis, error bars and runs, choosing and wording the
// error bars, and writing -o (with provenance) before the one result line on stderr. Private to
// the gg-fit command line; the numerics live in the ggfit library.
#include <cstddef>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fit/ensemble.hpp"
#include "fit/least_squares.hpp"
#include "fit/series.hpp"
#include "gg/dataset_ref.hpp"
#include "gg/h5file.hpp"
#include "gg/provenance.hpp"

namespace gg::fit::cli {

inline constexpr const char* kProgram = "gg-fit";
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The jackknife's own variance has R - 1 degrees of freedom; below this many runs `--errors auto`
// keeps the covariance of the weighted fit instead.
inline constexpr std::size_t kJackknifeMinRuns = 5;
// CLI11 takes any argument that starts with '-' for an option, so "-:/average/mean" (a dataset on
// stdin) is rewritten to "<stdin>:/average/mean" before parsing; Files maps the name back to "-".
inline constexpr const char* kStdinName = "<stdin>";

// ------------------------------------------------------------------------------------------------
// Inputs

// Every file is opened once (stdin can only be read once), in the order first named.
class Files {
 public:
  const H5Input& open(const std::string& given) {
    const std::string path = given == kStdinName ? "-" : given;
    auto it = files_.find(path);
    if (it != files_.end()) return *it->second;
    auto& f = files_[path];
    f = std::make_unique<H5Input>(path);
    order_.push_back(f.get());
    return *f;
  }
  const std::vector<const H5Input*>& all() const { return order_; }

 private:
  std::map<std::string, std::unique_ptr<H5Input>> files_;
  std::vector<const H5Input*> order_;
};

// "file.h5:/g/ds", or a bare file name completed by `--dataset`.
DatasetRef resolve(const std::string& arg, const std::string& default_dataset);

// How a dataset is named in messages and attributes: FILE:/group/dataset, stdin as <stdin>.
std::string label(const DatasetRef& r);

// The group of an HDF5 path ("" at the root), and its last component.
std::string parent(const std::string& path);
std::string basename(const std::string& path);

// A 1-D dataset with its time axis, its `stderr` sibling as error bars, and the per-run `samples`
// sibling (written by `gg-fit average`) when those average to the dataset.
struct Loaded {
  std::string name;
  const H5Input* file = nullptr;
  std::string dataset;
  Series series;
  std::optional<Ensemble> runs;
};

// The time axis paired with `dataset` (gg/dataset_ref.hpp), checked to hold its `n` samples.
std::vector<double> read_time(const H5Input& in, const std::string& dataset, std::size_t n, const std::string& name);

// Reads `ref` and its siblings; RuntimeError unless it is a 1-D series of finite values whose
// time axis has its length.
Loaded load_series(Files& files, const DatasetRef& ref);

// A number among the attributes of /parameters (stored as a number or as a string), if there.
std::optional<double> param(const H5Input& in, const std::string& name);

// ------------------------------------------------------------------------------------------------
// Error bars: covariance of the fit, or jackknife over the runs behind an ensemble average.

enum class ErrorMode { automatic, covariance, jackknife };

// --errors auto|covariance|jackknife.
ErrorMode error_mode(const std::string& name);

// Whether the error bars come from the jackknife over runs: always for `jackknife` (UsageError
// unless every input carries its runs), for `auto` when every input carries at least
// kJackknifeMinRuns of them, never for `covariance`.
bool use_jackknife(ErrorMode mode, const std::vector<const Loaded*>& in);

// How a fit was weighted and where its error bars come from: the `weights` and `errors`
// attributes of the output, and the end of the printed line.
std::string weights_text(const Series& s, std::size_t raised);
std::string errors_text(bool jack, ErrorMode mode, const Series& s, std::size_t runs);

// chi2/dof as printed: for an unweighted fit it is the residual variance of ln y, so say so.
std::string chi2_text(bool weighted, double chi2_dof);

// "value +/- error", as printed.
std::string pm(double v, double e);

// ------------------------------------------------------------------------------------------------
// Output

class Output {
 public:
  explicit Output(const std::string& path) {
    if (!path.empty()) out_ = std::make_unique<H5Output>(path);
  }
  explicit operator bool() const { return static_cast<bool>(out_); }
  H5Output& operator*() { return *out_; }
  H5Output* operator->() { return out_.get(); }
  // Writes -o, then prints the result line: a failure writing -o is then the one line on stderr.
  void finish(const std::vector<std::string>& argv, const Files& files, const std::string& result_line) {
    if (out_) {
      write_provenance(*out_, Provenance{kProgram, argv, std::nullopt}, files.all());
      out_->commit();
    }
    std::cerr << kProgram << " " << result_line << '\n';
  }

 private:
  std::unique_ptr<H5Output> out_;
};

// An estimate and its standard error, as datasets `path` and `path`_stderr.
void write_estimate(H5Output& out, const std::string& path, double value, double stderr_);

// What every fit of one series over a window writes beside its parameters: /fit/chi2_dof, /fit/window,
// and how the fit was made as attributes of /fit.
void write_fit_quality(H5Output& out, const Loaded& in, const FitQuality& q, const Window& w, const std::string& method,
                       const std::string& model, const std::string& errors);

// --window T1 T2 as a Window (UsageError naming the subcommand `what` unless two times).
Window window_from(const std::vector<double>& w, const std::string& what);
// Repeated --window T1 T2: one window for every input, or one each in order (else UsageError).
std::vector<Window> windows_per_input(const std::vector<double>& times, std::size_t inputs, const std::string& what);

}  // namespace gg::fit::cli
