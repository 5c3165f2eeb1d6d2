#include "fit/least_squares.hpp"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit.h>
#include <gsl/gsl_multifit_nlinear.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "gg/errors.hpp"

namespace gg::fit {
namespace {

// GSL's default handler aborts the process; we check every status ourselves instead.
void gsl_errors_are_returned() {
  static const bool once = [] {
    gsl_set_error_handler_off();
    return true;
  }();
  (void)once;
}

struct MatrixDel {
  void operator()(gsl_matrix* m) const { gsl_matrix_free(m); }
};
struct VectorDel {
  void operator()(gsl_vector* v) const { gsl_vector_free(v); }
};
using Matrix = std::unique_ptr<gsl_matrix, MatrixDel>;
using Vector = std::unique_ptr<gsl_vector, VectorDel>;

void copy_cov(const gsl_matrix* c, std::size_t p, double scale, LsqResult& r) {
  r.cov.assign(p * p, 0);
  for (std::size_t i = 0; i < p; ++i)
    for (std::size_t j = 0; j < p; ++j) r.cov[i * p + j] = gsl_matrix_get(c, i, j) * scale;
}

}  // namespace

double LsqResult::stderr_of(std::size_t k) const {
  const std::size_t p = coef.size();
  return std::sqrt(std::max(0.0, cov[k * p + k]));
}

void FitQuality::record(const LsqResult& r, const Series& s, const std::vector<std::size_t>& idx, bool with_weights) {
  chi2_dof = r.chi2_dof();
  points = idx.size();
  t_first = s.t[idx.front()];
  t_last = s.t[idx.back()];
  weighted = with_weights;
}

double covariance_scale(bool weighted, double chi2, std::size_t dof) {
  const double c = chi2 / static_cast<double>(dof);
  return weighted ? std::max(1.0, c) : c;
}

LsqResult linear_lsq(const std::vector<double>& X, std::size_t p, const std::vector<double>& y,
                     const std::vector<double>& sigma) {
  gsl_errors_are_returned();
  const std::size_t n = y.size();
  if (n <= p) throw RuntimeError("least squares: " + std::to_string(n) + " points for " + std::to_string(p) + " parameters");
  Matrix A(gsl_matrix_alloc(n, p)), C(gsl_matrix_alloc(p, p));
  Vector b(gsl_vector_alloc(n)), w(gsl_vector_alloc(n)), c(gsl_vector_alloc(p));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < p; ++j) gsl_matrix_set(A.get(), i, j, X[i * p + j]);
    gsl_vector_set(b.get(), i, y[i]);
    gsl_vector_set(w.get(), i, sigma.empty() ? 1.0 : 1.0 / (sigma[i] * sigma[i]));
  }
  std::unique_ptr<gsl_multifit_linear_workspace, decltype(&gsl_multifit_linear_free)> ws(
      gsl_multifit_linear_alloc(n, p), &gsl_multifit_linear_free);
  double chi2 = 0;
  int status = gsl_multifit_wlinear(A.get(), w.get(), b.get(), c.get(), C.get(), &chi2, ws.get());
  if (status != GSL_SUCCESS) throw RuntimeError(std::string("least squares failed: ") + gsl_strerror(status));
  LsqResult r;
  r.coef.resize(p);
  for (std::size_t j = 0; j < p; ++j) r.coef[j] = gsl_vector_get(c.get(), j);
  r.chi2 = chi2;
  r.dof = n - p;
  r.scale = covariance_scale(!sigma.empty(), chi2, r.dof);
  copy_cov(C.get(), p, r.scale, r);
  return r;
}

namespace {
struct NlData {
  const ModelFn* f;
  const std::vector<double>* x;
  const std::vector<double>* y;
  const std::vector<double>* sigma;
  std::vector<double> grad;
};

int nl_f(const gsl_vector* c, void* params, gsl_vector* out) {
  auto* d = static_cast<NlData*>(params);
  for (std::size_t i = 0; i < d->x->size(); ++i) {
    const double s = d->sigma->empty() ? 1.0 : (*d->sigma)[i];
    gsl_vector_set(out, i, ((*d->f)((*d->x)[i], c->data, d->grad.data()) - (*d->y)[i]) / s);
  }
  return GSL_SUCCESS;
}

int nl_df(const gsl_vector* c, void* params, gsl_matrix* J) {
  auto* d = static_cast<NlData*>(params);
  for (std::size_t i = 0; i < d->x->size(); ++i) {
    const double s = d->sigma->empty() ? 1.0 : (*d->sigma)[i];
    (*d->f)((*d->x)[i], c->data, d->grad.data());
    for (std::size_t k = 0; k < d->grad.size(); ++k) gsl_matrix_set(J, i, k, d->grad[k] / s);
  }
  return GSL_SUCCESS;
}
}  // namespace

LsqResult nonlinear_lsq(const ModelFn& f, std::size_t p, const std::vector<double>& x,
                        const std::vector<double>& y, const std::vector<double>& sigma,
                        const std::vector<double>& start) {
  gsl_errors_are_returned();
  const std::size_t n = y.size();
  if (n <= p) throw RuntimeError("least squares: " + std::to_string(n) + " points for " + std::to_string(p) + " parameters");
  NlData data{&f, &x, &y, &sigma, std::vector<double>(p)};
  gsl_multifit_nlinear_fdf fdf{};
  fdf.f = nl_f;
  fdf.df = nl_df;
  fdf.fvv = nullptr;
  fdf.n = n;
  fdf.p = p;
  fdf.params = &data;
  gsl_multifit_nlinear_parameters par = gsl_multifit_nlinear_default_parameters();
  std::unique_ptr<gsl_multifit_nlinear_workspace, decltype(&gsl_multifit_nlinear_free)> ws(
      gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &par, n, p), &gsl_multifit_nlinear_free);
  Vector c0(gsl_vector_alloc(p));
  for (std::size_t k = 0; k < p; ++k) gsl_vector_set(c0.get(), k, start[k]);
  int status = gsl_multifit_nlinear_init(c0.get(), &fdf, ws.get());
  int info = 0;
  if (status == GSL_SUCCESS)
    status = gsl_multifit_nlinear_driver(500, 1e-12, 1e-12, 0.0, nullptr, nullptr, &info, ws.get());
  if (status != GSL_SUCCESS)
    throw RuntimeError(std::string("nonlinear fit did not converge (") + gsl_strerror(status) +
                       "); try another window");
  LsqResult r;
  const gsl_vector* c = gsl_multifit_nlinear_position(ws.get());
  r.coef.resize(p);
  for (std::size_t k = 0; k < p; ++k) {
    r.coef[k] = gsl_vector_get(c, k);
    if (!std::isfinite(r.coef[k])) throw RuntimeError("nonlinear fit diverged; try another window");
  }
  const gsl_vector* res = gsl_multifit_nlinear_residual(ws.get());
  gsl_blas_ddot(res, res, &r.chi2);
  r.dof = n - p;
  Matrix C(gsl_matrix_alloc(p, p));
  status = gsl_multifit_nlinear_covar(gsl_multifit_nlinear_jac(ws.get()), 0.0, C.get());
  if (status != GSL_SUCCESS) throw RuntimeError("nonlinear fit: singular Jacobian; the parameters are not determined by the data in this window");
  r.scale = covariance_scale(!sigma.empty(), r.chi2, r.dof);
  copy_cov(C.get(), p, r.scale, r);
  return r;
}

}  // namespace gg::fit
