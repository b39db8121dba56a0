#include "seaflex/elements/catenary_shape.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace seaflex {

namespace {

// a (cosh(x / a) - 1) without the cancellation of a large a: 2 a sinh^2(x / (2 a))
double sag(double a, double x) {
  const double s = std::sinh(x / (2.0 * a));
  return 2.0 * a * s * s;
}

// a (sqrt(1 + (sigma / a)^2) - 1) = the height above the vertex at arc length sigma from it
double rise_at_arc(double a, double sigma) {
  const double y = sigma / a;
  return a * y * y / (std::sqrt(1.0 + y * y) + 1.0);
}

// the root u > 0 of sinh(u) / u = r (r > 1), by bisection: sinh(u) / u grows from 1
double solve_sinh_ratio(double r) {
  double hi = 1.0;
  while (std::sinh(hi) / hi < r) {
    hi *= 2.0;
    if (hi > 700.0)
      throw std::invalid_argument(
          "the line is so much longer than the distance between its ends that its catenary "
          "cannot be computed; give a polyline as the first guess");
  }
  double lo = 0.0;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mid > 0.0 && std::sinh(mid) / mid < r ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// touchdown catenary: F(a) = L - L_s + x_s - X, L_s = sqrt(h^2 + 2 a h), x_s = a asinh(L_s / a)
double touchdown_mismatch(double a, double L, double X, double h) {
  const double Ls = std::sqrt(h * h + 2.0 * a * h);
  return L - Ls + a * std::asinh(Ls / a) - X;
}

}  // namespace

BeamGeometry catenary_geometry(const Vec3& start, const Vec3& end, double length, int elements,
                               std::optional<double> seabed_z, CatenaryShape* shape) {
  if (elements < 1) throw std::invalid_argument("catenary: need at least one element");
  return catenary_geometry(start, end, std::vector<double>(elements, length / elements), seabed_z,
                           shape);
}

BeamGeometry catenary_geometry(const Vec3& start, const Vec3& end,
                               const std::vector<double>& element_lengths,
                               std::optional<double> seabed_z, CatenaryShape* shape) {
  const int elements = static_cast<int>(element_lengths.size());
  if (elements < 1) throw std::invalid_argument("catenary: need at least one element");
  double length = 0.0;
  for (double l : element_lengths) length += l;
  // work from the lower end P towards the upper end U
  const bool reversed = end.z() < start.z();
  const Vec3 P = reversed ? end : start, U = reversed ? start : end;
  const double chord = (U - P).norm();
  const double L = length;
  if (!(L > chord))
    throw std::invalid_argument(fmt::format(
        "a catenary needs a line longer than the distance between its ends ({:g} m)", chord));
  Vec3 e(U.x() - P.x(), U.y() - P.y(), 0.0);
  const double X = e.norm();
  const double h = U.z() - P.z();  // >= 0
  if (!(X > 1e-9 * L))
    throw std::invalid_argument(
        "the ends are one above the other: a slack line between them has no catenary; give "
        "a polyline as the first guess");
  e /= X;
  const Vec3 ez(0.0, 0.0, 1.0);

  CatenaryShape c;
  // free-hanging: sqrt(L^2 - h^2) = 2 a sinh(X / (2 a)) (Irvine 1981, sec. 1.2)
  const double u = solve_sinh_ratio(std::sqrt(L * L - h * h) / X);
  double a = X / (2.0 * u);
  const double xv = X / 2.0 - a * std::asinh(h / (2.0 * a * std::sinh(u)));
  const double zv = P.z() - sag(a, xv);
  if (seabed_z && xv > 0.0 && zv < *seabed_z) {
    // it would dip below the seabed: lay it from P (touchdown catenary)
    if (!(L < X + h))
      throw std::invalid_argument(fmt::format(
          "the line ({:g} m) is longer than the path along the seabed and straight up to the "
          "other end ({:g} m + {:g} m): it would pile up on the seabed; shorten it or give a "
          "polyline as the first guess",
          L, X, h));
    // F(a) < 0 as a -> 0 (F -> L - X - h) and F > 0 for large a (F -> L - X): bisection
    // on log a
    double lo = 1e-12 * (X + h), hi = X + h;
    while (touchdown_mismatch(hi, L, X, h) < 0.0) hi *= 2.0;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
      const double mid = std::sqrt(lo * hi);
      (touchdown_mismatch(mid, L, X, h) < 0.0 ? lo : hi) = mid;
    }
    const double at = 0.5 * (lo + hi);
    const double laid = L - std::sqrt(h * h + 2.0 * at * h);
    if (laid >= 0.0) {
      a = at;
      c.touchdown = true;
      c.laid_length = laid;
    }
  }
  c.a = a;

  BeamGeometry g;
  const int n = elements;
  g.positions.resize(n + 1);
  g.slopes.resize(n + 1);
  g.element_lengths = element_lengths;
  std::vector<double> arc(n + 1, 0.0);  // node arc lengths from start
  for (int k = 0; k < n; ++k) arc[k + 1] = arc[k] + element_lengths[k];
  // arc length from P's vertex reference: sigma = s - laid (touchdown), s + s_P (free)
  const double s_P = -a * std::sinh(xv / a);
  for (int k = 0; k <= n; ++k) {
    const int j = reversed ? n - k : k;  // node k of the beam is at arc length s from P
    // arc length from P: from start, or from end when reversed
    const double s = reversed ? L - arc[k] : arc[k];
    Vec3 p, t;
    if (c.touchdown && s <= c.laid_length) {
      p = P + s * e;
      t = e;
    } else {
      const double sigma = c.touchdown ? s - c.laid_length : s + s_P;
      const double x0 = c.touchdown ? c.laid_length : xv;
      const double z0 = c.touchdown ? P.z() : zv;
      const double x = x0 + a * std::asinh(sigma / a);
      p = P + x * e;
      p.z() = z0 + rise_at_arc(a, sigma);
      t = (a * e + sigma * ez) / std::hypot(a, sigma);
    }
    if (j == 0) p = P;
    if (j == n) p = U;
    g.positions[k] = p;
    g.slopes[k] = reversed ? Vec3(-t) : t;
  }
  if (shape) *shape = c;
  return g;
}

}  // namespace seaflex
