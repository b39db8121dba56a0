#include "seaflex/hydro/impulse_response_fit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <unsupported/Eigen/MatrixFunctions>

namespace seaflex::hydro {

namespace {

constexpr int kMaxHankel = 120;
// most samples in the least-squares fit of the residues (see the header)
constexpr Eigen::Index kMaxResidueRows = 8192;

struct Pole {
  double sigma;  // real part (1/s)
  double omega;  // imaginary part >= 0 (rad/s); 0 for a real pole
};

}  // namespace

double ImpulseResponseModel::evaluate(double t) const {
  if (order() == 0) return 0.0;
  const Eigen::MatrixXd e = (a * t).exp();
  return c * e * b;
}

ImpulseResponseModel fit_impulse_response(const std::vector<double>& y, double dt,
                                          double relative_tolerance, int max_order) {
  if (!(dt > 0.0))
    throw std::invalid_argument(fmt::format("impulse response fit: dt must be > 0, got {}", dt));
  if (!(relative_tolerance > 0.0))
    throw std::invalid_argument(fmt::format(
        "impulse response fit: relative_tolerance must be > 0, got {}", relative_tolerance));
  if (max_order < 1)
    throw std::invalid_argument(
        fmt::format("impulse response fit: max_order must be >= 1, got {}", max_order));
  ImpulseResponseModel model;
  const auto n_samples = static_cast<Eigen::Index>(y.size());
  double peak = 0.0;
  for (const double v : y) peak = std::max(peak, std::abs(v));
  if (peak == 0.0 || n_samples < 4) {
    model.a.resize(0, 0);
    model.b.resize(0);
    model.c.resize(0);
    return model;
  }

  // the significant length of the response and the decimation stride
  Eigen::Index last = 0;
  for (Eigen::Index k = 0; k < n_samples; ++k)
    if (std::abs(y[static_cast<std::size_t>(k)]) > 1e-4 * peak) last = k;
  last = std::min<Eigen::Index>(n_samples - 1, std::max<Eigen::Index>(last + last / 5, 8));
  const Eigen::Index stride =
      std::max<Eigen::Index>(1, (last + 2 * kMaxHankel - 1) / (2 * kMaxHankel));
  const Eigen::Index m = last / stride + 1;  // decimated samples y[k stride], k < m
  const Eigen::Index size = std::min<Eigen::Index>(kMaxHankel, (m - 1) / 2);
  const double dt_era = dt * static_cast<double>(stride);

  // ERA (Juang & Pappa 1985): Hankel matrices H0 = [y_{i+j}], H1 = [y_{i+j+1}]
  Eigen::MatrixXd h0(size, size), h1(size, size);
  for (Eigen::Index i = 0; i < size; ++i) {
    for (Eigen::Index j = 0; j < size; ++j) {
      h0(i, j) = y[static_cast<std::size_t>((i + j) * stride)];
      h1(i, j) = y[static_cast<std::size_t>((i + j + 1) * stride)];
    }
  }
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(h0, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& sv = svd.singularValues();
  Eigen::Index order = 0;
  while (order < sv.size() && order < max_order && sv(order) > relative_tolerance * sv(0)) ++order;
  order = std::max<Eigen::Index>(order, 1);
  const Eigen::VectorXd s_inv_sqrt = sv.head(order).cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd ad = s_inv_sqrt.asDiagonal() * svd.matrixU().leftCols(order).transpose() *
                             h1 * svd.matrixV().leftCols(order) * s_inv_sqrt.asDiagonal();

  // continuous poles s = log(lambda) / dt_era; keep the stable ones with Im >= 0
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(ad, false);
  std::vector<Pole> poles;
  for (Eigen::Index k = 0; k < order; ++k) {
    const std::complex<double> lambda = eig.eigenvalues()(k);
    const double mag = std::abs(lambda);
    const bool real = std::abs(lambda.imag()) <= 1e-12 * mag;
    if (!(mag < 1.0 - 1e-12) || mag == 0.0 || (real && lambda.real() < 0.0)) {
      ++model.discarded_poles;
      continue;
    }
    if (!real && lambda.imag() < 0.0) continue;  // the conjugate of a kept pair
    const std::complex<double> s = std::log(lambda) / dt_era;
    poles.push_back(Pole{s.real(), real ? 0.0 : s.imag()});
  }

  // residues by least squares on all samples (every fit_stride-th beyond kMaxResidueRows:
  // the memory stays bounded for any kernel length): basis e^{st}, or e^{sigma t} (sin, cos)
  Eigen::Index n_basis = 0;
  for (const auto& p : poles) n_basis += p.omega == 0.0 ? 1 : 2;
  auto basis_row = [&](Eigen::Index k, auto&& row) {
    const double t = dt * static_cast<double>(k);
    Eigen::Index col = 0;
    for (const auto& p : poles) {
      const double e = std::exp(p.sigma * t);
      if (p.omega == 0.0) {
        row(col++) = e;
      } else {
        row(col++) = e * std::sin(p.omega * t);
        row(col++) = e * std::cos(p.omega * t);
      }
    }
  };
  const Eigen::Index fit_stride = (n_samples + kMaxResidueRows - 1) / kMaxResidueRows;
  const Eigen::Index n_rows = (n_samples + fit_stride - 1) / fit_stride;
  Eigen::MatrixXd basis(n_rows, n_basis);
  Eigen::VectorXd target(n_rows);
  for (Eigen::Index r = 0; r < n_rows; ++r) {
    target(r) = y[static_cast<std::size_t>(r * fit_stride)];
    basis_row(r * fit_stride, basis.row(r));
  }
  const Eigen::VectorXd residues =
      n_basis > 0 ? Eigen::VectorXd(basis.colPivHouseholderQr().solve(target)) : Eigen::VectorXd();
  if (fit_stride == 1) {
    model.fit_error =
        (n_basis > 0 ? (basis * residues - target).norm() : target.norm()) / target.norm();
  } else {
    // the error over every sample, one row at a time
    double err2 = 0.0, norm2 = 0.0;
    Eigen::RowVectorXd row(n_basis);
    for (Eigen::Index k = 0; k < n_samples; ++k) {
      const double yk = y[static_cast<std::size_t>(k)];
      double fit = 0.0;
      if (n_basis > 0) {
        basis_row(k, row);
        fit = row.dot(residues);
      }
      err2 += (fit - yk) * (fit - yk);
      norm2 += yk * yk;
    }
    model.fit_error = std::sqrt(err2 / norm2);
  }

  model.a = Eigen::MatrixXd::Zero(n_basis, n_basis);
  model.b = Eigen::VectorXd::Zero(n_basis);
  model.c = Eigen::RowVectorXd::Zero(n_basis);
  Eigen::Index col = 0;
  for (const auto& p : poles) {
    if (p.omega == 0.0) {
      model.a(col, col) = p.sigma;
      model.b(col) = 1.0;
      model.c(col) = residues(col);
      ++col;
    } else {
      // e^{A t} b = e^{sigma t} (sin wt, cos wt) for A = [sigma w; -w sigma], b = (0, 1)
      model.a.block<2, 2>(col, col) << p.sigma, p.omega, -p.omega, p.sigma;
      model.b(col + 1) = 1.0;
      model.c(col) = residues(col);
      model.c(col + 1) = residues(col + 1);
      col += 2;
    }
  }
  return model;
}

}  // namespace seaflex::hydro
