#!/usr/bin/python3
"""Independent reference values for tests/unit/test_directional_spreading.cpp (issue 21):
the cos-2s directional distribution (Longuet-Higgins, Cartwright & Smith 1963; DNV-RP-C205
(2021) section 3.5.8)

    D(t) = C(s) cos^{2s}(t / 2),  |t| <= pi,  C(s) = Gamma(s + 1) / (2 sqrt(pi) Gamma(s + 1/2)),

its equal-angle discretization (M bins of width 2 t_max / M centred at (j - (M - 1)/2) Delta,
weight = integral of D over the bin / integral over [-t_max, t_max]) and its moments, by a
different method from seaflex's: scipy's adaptive QUADPACK quadrature in t itself (seaflex:
composite Gauss-Legendre in t/2 with graded pieces), and the closed-form circular moments
E[cos n t] = Gamma(s + 1)^2 / (Gamma(s + 1 - n) Gamma(s + 1 + n)).

Run: /usr/bin/python3 tests/unit/cos2s_moments.py   (prints the numbers the test hard-codes)
"""
import numpy as np
from scipy.integrate import quad
from scipy.special import gammaln


def density(t, s):
    return np.exp(gammaln(s + 1) - gammaln(s + 0.5)) / (2 * np.sqrt(np.pi)) * np.cos(t / 2) ** (2 * s)


def moment(n, s):
    """E[cos n t] in closed form (n < s + 1, or s integer)."""
    return float(np.exp(2 * gammaln(s + 1) - gammaln(s + 1 - n) - gammaln(s + 1 + n)))


def direction_set(s, m, t_max):
    d = 2 * t_max / m
    c = (np.arange(m) - (m - 1) / 2) * d
    w = np.array([quad(density, x - d / 2, x + d / 2, args=(s,), epsabs=1e-16, epsrel=1e-13,
                       limit=200)[0] for x in c])
    return c, w / w.sum(), w.sum()


def main():
    np.set_printoptions(precision=17)
    # the normalization: the integral of D over the circle
    for s in (0.3, 2.0, 8.0, 500.0):
        print(f"s = {s}: integral of D = {quad(density, -np.pi, np.pi, args=(s,), epsabs=1e-14, limit=200)[0]!r}")
    # the closed-form moments against quadrature
    for s in (2.0, 8.0):
        for n in (1, 2):
            q = quad(lambda t: density(t, s) * np.cos(n * t), -np.pi, np.pi, epsabs=1e-15)[0]
            print(f"s = {s}: E[cos {n}t] closed form {moment(n, s)!r}, quadrature {q!r}")
    # weights of the sets the test compares element by element
    for s, m, t_max_deg in ((8.0, 9, 180.0), (8.0, 9, 90.0), (0.3, 9, 180.0), (2.0, 5, 120.0)):
        c, w, total = direction_set(s, m, np.radians(t_max_deg))
        print(f"s = {s}, M = {m}, max_angle = {t_max_deg} deg: mass in range {total!r}")
        print("  weights", ", ".join(repr(float(x)) for x in w))
        print(f"  E[cos] {float((w * np.cos(c)).sum())!r}  E[cos^2] {float((w * np.cos(c) ** 2).sum())!r}")
    # the discretization error of the moments against its leading term (Delta^2/24) int D f''
    for s in (2.0, 8.0):
        e1, c2 = moment(1, s), moment(2, s)
        for m in (9, 19, 39, 79):
            c, w, _ = direction_set(s, m, np.pi)
            d = 2 * np.pi / m
            err1 = (w * np.cos(c)).sum() - e1
            err2 = (w * np.cos(c) ** 2).sum() - (1 + c2) / 2
            lead1 = d * d / 24 * (-e1)       # f = cos t, f'' = -cos t
            lead2 = d * d / 24 * (-2 * c2)   # f = cos^2 t = (1 + cos 2t)/2, f'' = -2 cos 2t
            print(f"s = {s}, M = {m}: E[cos] error {err1:.4e} (leading term {lead1:.4e}, "
                  f"ratio {err1 / lead1:.4f}); E[cos^2] error {err2:.4e} (leading {lead2:.4e}, "
                  f"ratio {err2 / lead2:.4f})")


if __name__ == "__main__":
    main()
