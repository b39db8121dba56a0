#!/usr/bin/python3
"""The analytic elastic catenary of a mooring line from an anchor on a flat seabed to a
fairlead, with a laid length and seabed friction, and a second, independent solution of
the same problem by shooting; both written from the physics for seaflex's verification
(issue 18), independent of seaflex's implementation.

The problem. A line of unstretched length L, submerged weight w per unit unstretched
length and axial stiffness EA runs from an anchor on a flat rigid seabed, at (0, 0), to a
fairlead at (X, h): X the horizontal span, h the height above the seabed. No bending
stiffness, no current. H and V are the horizontal and vertical components of the tension at
the fairlead; T is the (effective) tension, s the unstretched arc length from the anchor.

Method 1, the closed form (`solve`): the classic elastic catenary with seabed contact and
friction of Jonkman (2007), "Dynamics Modeling and Loads Analysis of an Offshore Floating
Wind Turbine", NREL/TP-500-41958, section 4.2 (the catenary routine of FAST v7, the same
equations as MAP++ and MoorDyn's/MoorPy's `catenary`):

  fully suspended line (V >= w L), anchor force (H, V - w L):
    X = H/w [asinh(V/H) - asinh((V - w L)/H)] + H L / EA
    h = H/w [sqrt(1 + (V/H)^2) - sqrt(1 + ((V - w L)/H)^2)] + (V L - w L^2 / 2) / EA

  part of the line laid on the seabed (V < w L), laid length L_B = L - V/w:
    X = L_B + H/w asinh(V/H) + H L / EA
          + C_B w / (2 EA) [ -L_B^2 + (L_B - H/(C_B w)) max(L_B - H/(C_B w), 0) ]
    h = H/w [sqrt(1 + (V/H)^2) - 1] + V^2 / (2 EA w)
    anchor tension H_A = max(H - C_B w L_B, 0)   (vertical 0)

  The friction (coefficient C_B, along the line) is taken fully mobilized against the pull
  of the fairlead: along the laid part the tension falls from H at the touchdown point by
  C_B w per metre towards the anchor, down to zero (the last term of X is the stretch of the
  laid part, integral of T/EA, minus the H L_B / EA of a frictionless laid part). Solved by
  Newton on (H, V) (the two equations' residuals, a finite-difference Jacobian, a damped
  step that keeps H > 0), from the first guess of the FAST routine.

  With a floor T0 (`solve(..., floor=T0)`; an extension of Jonkman's equations, not in
  them): a line first in equilibrium without friction at laid tension T0, then pulled out
  monotonically, slides only where the pull raises its tension above T0, so T(s) =
  max(T0, H - C_B w (L_B - s)) along the laid part, the anchor tension is
  max(T0, H - C_B w L_B), and the last term of X becomes the laid part's stretch with
  that profile, minus H L_B / EA. With T0 = 0 it is Jonkman's equation.

Method 2, shooting (`solve_shooting`): the line's equilibrium ODE integrated by classical
RK4 in s from the fairlead down to the anchor, for a trial (H, V) at the fairlead:
  suspended:  dTx/ds = 0, dTz/ds = w, dx/ds = lambda(T) Tx/T, dz/ds = lambda(T) Tz/T
  laid (from the arc length where Tz reaches 0 on down):
              dT/ds = C_B w while T > T0 (0 once it reaches T0, default 0: the step that
              reaches it is split there), dx/ds = lambda(T), z = 0
with the stretch lambda(T) of a stress-strain law: Hooke's, lambda = 1 + T/EA (the law of
the classic equations), or the Green-Lagrange law of seaflex's `axial_model: exact`
(docs/results-format.md: T = EA eps |r'|, eps = (|r'|^2 - 1)/2, i.e. EA lambda (lambda^2 -
1)/2 = T). Newton on (H, V) drives the anchor's position to (0, 0) relative to the fairlead
at (X, h). The stretch law is the only thing method 2 can change, so its difference between
the two laws is the error of comparing seaflex with the classic equations (O((T/EA)^2)).

    elastic_catenary.py            runs the unit tests of this file (method 1 against 2)
"""
import math
import sys
import unittest

import numpy as np


class Catenary:
    """A solution: fairlead forces H, V (N), laid length L_B (m, unstretched), anchor forces
    HA, VA (N), and the line's data."""

    def __init__(self, H, V, LB, HA, VA, X, h, L, w, EA, CB, floor, iterations):
        self.H, self.V, self.LB, self.HA, self.VA = H, V, LB, HA, VA
        self.X, self.h, self.L, self.w, self.EA, self.CB = X, h, L, w, EA, CB
        self.floor, self.iterations = floor, iterations

    @property
    def fairlead_tension(self):
        return math.hypot(self.H, self.V)

    @property
    def anchor_tension(self):
        return math.hypot(self.HA, self.VA)

    def __repr__(self):
        return ("Catenary(H=%.9g N, V=%.9g N, T_fairlead=%.9g N, L_B=%.9g m, T_anchor=%.9g N)"
                % (self.H, self.V, self.fairlead_tension, self.LB, self.anchor_tension))

    def tension(self, s):
        """The tension (N) at unstretched arc length s from the anchor."""
        H, w, LB, CB = self.H, self.w, self.LB, self.CB
        if s >= LB:
            return math.hypot(H, w * (s - LB) + self.VA)
        if CB == 0.0:
            return H
        return min(H, max(H - CB * w * (LB - s), self.floor))

    def position(self, s):
        """(x, z) of the point at unstretched arc length s from the anchor (Hooke's law),
        the anchor at (0, 0)."""
        H, w, EA, LB, CB = self.H, self.w, self.EA, self.LB, self.CB
        # the laid part: x = s + integral of T/EA
        sl = min(s, LB)
        if CB == 0.0 or LB == 0.0 or H <= self.floor:
            stretch = H * sl / EA
        else:
            # where the tension rises from the floor (zero, or the tension before the pull)
            s0 = min(max(0.0, LB - (H - self.floor) / (CB * w)), sl)
            stretch = (self.floor * s0
                       + 0.5 * (self.tension(s0) + self.tension(sl)) * (sl - s0)) / EA
        if s <= LB:
            return sl + stretch, 0.0
        # the suspended part from the touchdown point (vertical force VA there)
        va = self.VA
        vs = va + w * (s - LB)
        x = sl + stretch + H / w * (math.asinh(vs / H) - math.asinh(va / H)) + H * (s - LB) / EA
        z = (H / w * (math.sqrt(1 + (vs / H) ** 2) - math.sqrt(1 + (va / H) ** 2))
             + (va * (s - LB) + 0.5 * w * (s - LB) ** 2) / EA)
        return x, z


def _equations(H, V, X, h, L, w, EA, CB, floor=0.0):
    """The residuals of the closed-form equations (method 1) for the trial (H, V)."""
    if V >= w * L:     # fully suspended
        va = V - w * L
        x = H / w * (math.asinh(V / H) - math.asinh(va / H)) + H * L / EA
        z = (H / w * (math.sqrt(1 + (V / H) ** 2) - math.sqrt(1 + (va / H) ** 2))
             + (V * L - 0.5 * w * L * L) / EA)
    else:
        LB = L - V / w
        x = LB + H / w * math.asinh(V / H) + H * L / EA
        if CB > 0.0 and floor == 0.0:      # Jonkman's equation
            a = LB - H / (CB * w)
            x += CB * w / (2 * EA) * (-LB * LB + a * max(a, 0.0))
        elif CB > 0.0 and H > floor:      # the same with the floor: the laid part's stretch
            d = min((H - floor) / (CB * w), LB)     # the length that has slid
            x += (floor * (LB - d) + 0.5 * (H + max(H - CB * w * d, floor)) * d - H * LB) / EA
        z = H / w * (math.sqrt(1 + (V / H) ** 2) - 1) + V * V / (2 * EA * w)
    return np.array([x - X, z - h])


def _first_guess(X, h, L, w):
    """Jonkman's (FAST v7) first guess of (H, V)."""
    if X == 0.0:
        lam = 1.0e6
    elif math.hypot(X, h) >= L:
        lam = 0.2
    else:
        lam = math.sqrt(3 * ((L * L - h * h) / (X * X) - 1))
    H = max(abs(0.5 * w * X / lam), 1e-3 * w * L)
    V = 0.5 * w * (h / math.tanh(lam) + L)
    return H, V


def _newton(residual, H, V, scale, tol=1e-13, max_iterations=200):
    """Newton on (H, V) with a central finite-difference Jacobian and a damped step that
    keeps H > 0 and does not let the residual grow. Returns (H, V, iterations)."""
    r = residual(H, V)
    for it in range(1, max_iterations + 1):
        J = np.empty((2, 2))
        for j in range(2):
            dH = 1e-6 * max(abs(H), 1e-3 * scale) if j == 0 else 0.0
            dV = 1e-6 * max(abs(V), 1e-3 * scale) if j == 1 else 0.0
            J[:, j] = (residual(H + dH, V + dV) - residual(H - dH, V - dV)) / (2 * (dH + dV))
        step = np.linalg.solve(J, -r)
        t = 1.0
        while True:
            Hn, Vn = H + t * step[0], V + t * step[1]
            if Hn > 0.0:
                rn = residual(Hn, Vn)
                if np.linalg.norm(rn) < np.linalg.norm(r) or t < 1e-6:
                    break
            t *= 0.5
        H, V, r = Hn, Vn, rn
        if abs(step[0]) * t <= tol * scale and abs(step[1]) * t <= tol * scale:
            return H, V, it
    raise RuntimeError("catenary Newton did not converge: residual %s" % r)


def _result(H, V, X, h, L, w, EA, CB, floor, iterations):
    if V >= w * L:
        LB, HA, VA = 0.0, H, V - w * L
    else:
        LB = L - V / w
        HA, VA = (min(H, max(H - CB * w * LB, floor)) if CB > 0.0 else H), 0.0
    return Catenary(H, V, LB, HA, VA, X, h, L, w, EA, CB, floor, iterations)


def solve(X, h, L, w, EA, CB=0.0, floor=0.0):
    """Method 1: the closed-form elastic catenary with seabed contact and friction.

    floor (N, default 0: Jonkman's equations): a tension that friction cannot take away
    from the laid line. A line in equilibrium without friction at tension T0, then pulled
    out monotonically, slides only where the pull raises its tension above T0; the part near
    the anchor keeps T0: T(s) = max(T0, H - C_B w (L_B - s)), and the anchor tension is
    max(T0, H - C_B w L_B) (the laid part's stretch, the integral of T/EA, follows)."""
    H, V = _first_guess(X, h, L, w)
    H, V, it = _newton(lambda a, b: _equations(a, b, X, h, L, w, EA, CB, floor), H, V, w * L)
    return _result(H, V, X, h, L, w, EA, CB, floor, it)


# --- method 2: shooting ------------------------------------------------------------------

def stretch_hooke(T, EA):
    return 1.0 + T / EA


def stretch_green_lagrange(T, EA):
    """lambda with EA lambda (lambda^2 - 1) / 2 = T (Newton from Hooke's value)."""
    lam = 1.0 + T / EA
    for _ in range(50):
        f = 0.5 * EA * lam * (lam * lam - 1) - T
        d = 0.5 * EA * (3 * lam * lam - 1)
        dl = f / d
        lam -= dl
        if abs(dl) < 1e-16:
            break
    return lam


def _rk4(f, y, s0, s1, n):
    h = (s1 - s0) / n
    s = s0
    for _ in range(n):
        k1 = f(s, y)
        k2 = f(s + h / 2, y + h / 2 * k1)
        k3 = f(s + h / 2, y + h / 2 * k2)
        k4 = f(s + h, y + h * k3)
        y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        s += h
    return y


def shoot(H, V, L, w, EA, CB=0.0, stretch=stretch_hooke, steps=200, floor=0.0):
    """Integrate the line from the fairlead (at (0, 0), s = L) down to the anchor (s = 0)
    for the fairlead forces (H, V); returns the anchor's (x, z) relative to the fairlead
    and the anchor's horizontal tension."""
    s_td = max(L - V / w, 0.0)          # where the vertical force Tz = V - w (L - s) is 0

    def suspended(s, y):                # y = x, z, Tx, Tz
        T = math.hypot(y[2], y[3])
        lam = stretch(T, EA)
        return np.array([lam * y[2] / T, lam * y[3] / T, 0.0, w])

    y = _rk4(suspended, np.array([0.0, 0.0, H, V]), L, s_td, steps)
    if s_td == 0.0:
        return y[0], y[1], y[2]

    def laid(s, y):                     # y = x, T; z stays at the touchdown point's
        return np.array([stretch(max(y[1], 0.0), EA), CB * w if y[1] > floor else 0.0])

    # RK4 steps; a step in which T reaches the floor is split there (the event located by
    # the secant of T over the step, exact while dT/ds is constant), so that T stops at it
    yl, s, ds = np.array([y[0], y[2]]), s_td, -s_td / steps
    for _ in range(steps):
        y1 = _rk4(laid, yl, s, s + ds, 1)
        if yl[1] > floor and y1[1] < floor:
            theta = (yl[1] - floor) / (yl[1] - y1[1])
            ym = _rk4(laid, yl, s, s + theta * ds, 1)
            ym[1] = floor
            y1 = _rk4(laid, ym, s + theta * ds, s + ds, 1)
        yl, s = y1, s + ds
    return yl[0], y[1], max(yl[1], 0.0)


def solve_shooting(X, h, L, w, EA, CB=0.0, stretch=stretch_hooke, steps=200, guess=None,
                   floor=0.0):
    """Method 2: (H, V) such that the integrated line ends at the anchor."""
    H, V = guess if guess is not None else _first_guess(X, h, L, w)

    def residual(a, b):
        xa, za, _ = shoot(a, b, L, w, EA, CB, stretch, steps, floor)
        return np.array([-xa - X, -za - h])

    H, V, it = _newton(residual, H, V, w * L, tol=1e-12)
    c = _result(H, V, X, h, L, w, EA, CB, floor, it)
    c.HA = shoot(H, V, L, w, EA, CB, stretch, steps, floor)[2]
    return c


# --- the touchdown point on an elastic seabed ------------------------------------------------

def touchdown_boundary_layer(w, H, EI, k):
    """How a line with bending stiffness EI on a seabed of stiffness k (N/m per m of line,
    tensionless) differs from the classic catenary on a rigid seabed near its touchdown
    point: small slopes, the horizontal tension H. Vertical equilibrium of the line,
    z the height above the seabed, x along the line towards the fairlead (z4, z2 the fourth
    and second derivatives):

      in contact (z < 0):   EI z4 - H z2 + k z = -w     (far from it z = -w/k, the sinkage)
      suspended (z > 0):    EI z4 - H z2       = -w

    The contact ends at x0 (z = 0 there), where z and its first three derivatives are
    continuous. Taking x0 = 0: in contact z = -w/k + A1 e^{r1 x} + A2 e^{r2 x} (r the roots
    with positive real part of EI r^4 - H r^2 + k = 0), suspended z = w/(2H) x^2 + a x + b +
    c e^{-x/lam}, lam = sqrt(EI/H); five linear conditions give A1, A2, a, b, c. Away from
    the touchdown the suspended line is the parabola (catenary) w/(2H) (x - x_v)^2 + z_v: the
    catenary of a rigid seabed at height z_v whose touchdown point is at x_v = -a H/w.

    Returns (extra, z_v): the contact extends extra = -x_v beyond that catenary's touchdown
    (the laid length is the rigid one plus extra), and z_v (< 0) is where its seabed lies.
    Limits: EI -> 0 gives extra = sqrt(H/k), z_v = -w/(2k) (a string on an elastic
    foundation); k -> infinity gives extra = -lam, z_v = w lam^2 / (2H) (a beam lifts off
    lam before a cable would)."""
    if EI <= 0.0:
        return math.sqrt(H / k), -w / (2 * k)
    lam = math.sqrt(EI / H)
    roots = [r for r in np.roots([EI, 0.0, -H, 0.0, k]) if r.real > 0.0]
    r1, r2 = roots[0], roots[1]
    M = np.array([[1, 1, 0, 0, 0],
                  [1, 1, 0, -1, -1],
                  [r1, r2, -1, 0, 1 / lam],
                  [r1 ** 2, r2 ** 2, 0, 0, -1 / lam ** 2],
                  [r1 ** 3, r2 ** 3, 0, 0, 1 / lam ** 3]], dtype=complex)
    rhs = np.array([w / k, w / k, 0, w / H, 0], dtype=complex)
    _, _, a, b, _ = np.linalg.solve(M, rhs)
    xv = -a.real * H / w
    return -xv, b.real - w / (2 * H) * xv * xv


# --- unit tests: method 1 against method 2 -------------------------------------------------

LINE = dict(L=500.0, w=525.73, EA=7.854e8)     # 0.1 m wire-like line (the seaflex tests')


class ElasticCatenary(unittest.TestCase):
    def agree(self, a, b, tol=1e-6):
        scale = a.w * a.L
        for name in ("H", "V", "HA", "VA"):
            self.assertLess(abs(getattr(a, name) - getattr(b, name)), tol * scale,
                            "%s: %r vs %r" % (name, a, b))
        self.assertLess(abs(a.LB - b.LB), tol * a.L, "L_B: %r vs %r" % (a, b))

    def test_laid_length_without_friction(self):
        a = solve(440.0, 140.0, **LINE)
        b = solve_shooting(440.0, 140.0, **LINE)
        print("no friction: closed form %r\n             shooting    %r" % (a, b))
        self.assertGreater(a.LB, 50.0)
        self.agree(a, b)
        self.assertEqual(a.HA, a.H)

    def test_laid_length_with_friction_anchor_tension_positive(self):
        a = solve(440.0, 140.0, CB=0.3, **LINE)
        b = solve_shooting(440.0, 140.0, CB=0.3, **LINE)
        print("C_B = 0.3: closed form %r\n           shooting    %r" % (a, b))
        self.assertGreater(a.HA, 0.0)
        self.agree(a, b)

    def test_laid_length_with_friction_anchor_slack(self):
        # C_B w L_B > H: the tension falls to zero before the anchor
        a = solve(440.0, 140.0, CB=0.5, **LINE)
        b = solve_shooting(440.0, 140.0, CB=0.5, **LINE)
        print("C_B = 0.5: closed form %r\n           shooting    %r" % (a, b))
        self.assertEqual(a.HA, 0.0)
        self.assertLess(a.H, a.CB * a.w * a.LB)
        self.agree(a, b)

    def test_friction_with_a_floor(self):
        """The line pulled out from its frictionless state (tension T0 = 50 kN laid): the
        part near the anchor has not slid (partly slid), or all of it has (fully slid)."""
        for X, what in ((445.0, "partly slid"), (465.0, "fully slid")):
            a = solve(X, 140.0, CB=0.3, floor=5.0e4, **LINE)
            b = solve_shooting(X, 140.0, CB=0.3, floor=5.0e4, **LINE)
            print("floor 50 kN, %s: closed form %r\n            shooting    %r" % (what, a, b))
            self.agree(a, b)
            self.assertEqual(a.HA > 5.0e4, what == "fully slid")
            x, z = a.position(a.L)
            self.assertAlmostEqual(x, X, delta=1e-8)
            self.assertAlmostEqual(z, 140.0, delta=1e-8)

    def test_fully_suspended(self):
        a = solve(475.0, 140.0, **LINE)
        b = solve_shooting(475.0, 140.0, **LINE)
        print("suspended: closed form %r\n           shooting    %r" % (a, b))
        self.assertEqual(a.LB, 0.0)
        self.assertGreater(a.VA, 0.0)
        self.agree(a, b)

    def test_soft_line_large_stretch(self):
        # EA small enough that the stretch terms matter (strain about 2 %)
        a = solve(440.0, 140.0, L=500.0, w=525.73, EA=5.0e6, CB=0.3)
        b = solve_shooting(440.0, 140.0, L=500.0, w=525.73, EA=5.0e6, CB=0.3)
        print("soft line: closed form %r\n           shooting    %r" % (a, b))
        self.agree(a, b)

    def test_profile_ends_at_the_fairlead(self):
        for cb in (0.0, 0.5):
            a = solve(440.0, 140.0, CB=cb, **LINE)
            x, z = a.position(a.L)
            self.assertAlmostEqual(x, 440.0, delta=1e-8)
            self.assertAlmostEqual(z, 140.0, delta=1e-8)
            x, z = a.position(a.LB)
            self.assertEqual(z, 0.0)

    def test_touchdown_boundary_layer_limits(self):
        w, H = 525.67, 67628.0
        extra, zv = touchdown_boundary_layer(w, H, 1e-9, 1e6)   # a string on a soft seabed
        self.assertAlmostEqual(extra / math.sqrt(H / 1e6), 1.0, delta=1e-6)
        self.assertAlmostEqual(zv / (-w / 2e6), 1.0, delta=1e-6)
        lam = math.sqrt(1e3 / H)
        extra, zv = touchdown_boundary_layer(w, H, 1e3, 1e20)   # a beam on a rigid seabed
        self.assertAlmostEqual(extra / -lam, 1.0, delta=1e-3)
        self.assertAlmostEqual(zv / (w * lam * lam / (2 * H)), 1.0, delta=1e-6)
        extra, zv = touchdown_boundary_layer(w, H, 1e3, 1e6)    # both
        print("boundary layer, EI = 1e3 N m^2, k = 1e6 N/m^2: contact %.4f m beyond the "
              "rigid catenary's touchdown, its seabed %.3g m below the surface" % (extra, -zv))
        self.assertTrue(-lam < extra < math.sqrt(H / 1e6))

    def test_green_lagrange_law_differs_by_the_square_of_the_strain(self):
        """seaflex's strain law against Hooke's: lambda - 1 differs by 1.5 (T/EA)^2, which
        changes H by 4e-7 here: comparing seaflex with the classic (Hooke) equations costs
        below 1e-6."""
        a = solve_shooting(440.0, 140.0, **LINE)
        b = solve_shooting(440.0, 140.0, stretch=stretch_green_lagrange, **LINE)
        print("Green-Lagrange law: %r (H %.3g relative to Hooke's)" % (b, b.H / a.H - 1))
        self.assertLess(abs(b.H / a.H - 1), 1e-6)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
