#!/usr/bin/env python3
"""The static bow of the benchmark riser (bench/riser) in a uniform current, by finite
differences in numpy: an independent check of seaflex (which uses ANCF finite elements,
Gauss-integrated Morison loads and Newton on the full nonlinear strain energy).

The riser is a tensioned beam, its lateral deflection w(z) over the height z:
    (EI w'')'' - (V(z) w')' = q(z)
(Sparks, "Fundamentals of marine riser mechanics", 2007, eq. 7.1; the effective-tension
form with V the vertical component of the effective tension, w' = tan(theta)), with the
quadratic drag of the current at rest, 0.5 rho Cd D |u_n| u_n per unstretched length on the
normal component u_n of the current U (Morison; DNV-RP-C205 eq. 6.1.1). For a riser at an
angle theta to the vertical, |u_n| = U cos(theta) and per unit height (ds/dz = 1/cos):
    q(z)  = 0.5 rho Cd D U^2 cos^2(theta) / (1 + eps)        (horizontal)
    fv(z) = 0.5 rho Cd D U^2 cos(theta) sin(theta) / (1 + eps) (downward)
    V(z)  = F_top - int_z^top [ w_s / (cos(theta) (1 + eps)) + fv ] dz
w_s = (rho_s A - rho_w A_o) g the submerged weight per unstretched length, eps = T/EA the
axial strain (T = V / cos). Ends pinned: w = 0 and w'' = 0 at the seabed and at the top.
The height of the riser follows from its unstretched length:
    int sqrt(1 + w'^2) / (1 + eps) dz = L.
Central differences on M intervals (O(h^2)) in the mixed form (w and m = EI w'', two
second-order equations: better conditioned than the 5-point stencil of the 4th
derivative); the nonlinear terms (cos, eps, V) by fixed-point iteration. solve().
Left out: terms of order theta^2 times the bending share of the load (the curvature's
nonlinearity kappa = w''/(1+w'^2)^1.5, the shear's horizontal projection; theta is up to
4.7 deg at the seabed): 3.9e-4 of the bow against the exact rod.
The exact rod, solve_rod(): the same riser without the small-angle approximation, by
collocation over the arc length (see its docstring).
    /usr/bin/python3 bench/riser/riser_bow_fd.py [--current 3.0] [--intervals 3000]
prints z, w at 11 stations and the top angle (finite differences, two grids)."""
import argparse
import math

import numpy as np
from scipy import sparse
from scipy.sparse.linalg import spsolve

g = 9.81
rho_w, rho_s = 1025.0, 7850.0
od, idia, length, E = 0.7, 0.4, 300.0, 210e9
A = math.pi / 4 * (od**2 - idia**2)
Ao = math.pi / 4 * od**2
I = math.pi / 64 * (od**4 - idia**4)
EI, EA = E * I, E * A
w_s = (rho_s * A - rho_w * Ao) * g
F_top = w_s * length + 2.0e6  # the benchmark's top force (bench/riser/riser_n*.yaml)
Cd = 0.65


def solve(U=3.0, M=3000, tol=1e-12, max_iter=200):
    """The static bow: returns (z, w, V) on M + 1 equally spaced points from the seabed
    (z = -300) to the top, the top's height solved for."""
    qd = 0.5 * rho_w * Cd * od * U * U
    z_b = -length
    H = length
    w = np.zeros(M + 1)
    for _ in range(max_iter):
        h = H / M
        z = z_b + h * np.arange(M + 1)
        wp = np.gradient(w, h, edge_order=2)
        c = 1.0 / np.sqrt(1.0 + wp * wp)
        s = wp * c
        # V from the top down: trapezoidal rule, with eps from the previous iterate
        V = np.full(M + 1, F_top)
        eps = F_top / EA * np.ones(M + 1)
        for _k in range(3):
            dens = w_s / (c * (1 + eps)) + qd * c * s / (1 + eps)
            cum = np.concatenate(([0.0], np.cumsum(0.5 * (dens[1:] + dens[:-1]) * h)))
            V = F_top - (cum[-1] - cum)
            eps = V / c / EA
        q = qd * c * c / (1 + eps)
        # the mixed form (better conditioned than the 5-point stencil of the 4th
        # derivative): unknowns w_i and m_i = EI w''(z_i) at i = 1..M-1 (w = m = 0 at both
        # ends), the equations
        #   (w_{i-1} - 2 w_i + w_{i+1}) / h^2 - m_i / EI = 0
        #   (m_{i-1} - 2 m_i + m_{i+1}) / h^2
        #       - [V_{i+1/2} (w_{i+1} - w_i) - V_{i-1/2} (w_i - w_{i-1})] / h^2 = q_i
        n = M - 1
        Vh = 0.5 * (V[1:] + V[:-1])  # V at the half points i + 1/2, i = 0..M-1
        rows, cols, vals = [], [], []
        rhs = np.zeros(2 * n)
        for k in range(n):  # node i = k + 1
            iw, im = 2 * k, 2 * k + 1
            for dk, cw in ((-1, 1.0), (0, -2.0), (1, 1.0)):
                if 0 <= k + dk < n:
                    rows += [iw, im]
                    cols += [2 * (k + dk), 2 * (k + dk) + 1]
                    vals += [cw / h**2, cw / h**2]
            rows += [iw, im]
            cols += [im, iw]
            vals += [-1.0 / EI, (Vh[k + 1] + Vh[k]) / h**2]
            if k + 1 < n:
                rows.append(im)
                cols.append(2 * (k + 1))
                vals.append(-Vh[k + 1] / h**2)
            if k >= 1:
                rows.append(im)
                cols.append(2 * (k - 1))
                vals.append(-Vh[k] / h**2)
            rhs[im] = q[k + 1]
        K = sparse.csc_matrix((vals, (rows, cols)), shape=(2 * n, 2 * n))
        sol = spsolve(K, rhs)
        w_new = np.zeros(M + 1)
        w_new[1:-1] = sol[0::2]
        # the height from the unstretched length
        wp_new = np.gradient(w_new, h, edge_order=2)
        stretch = np.sqrt(1 + wp_new**2) / (1 + eps)
        L_now = np.sum(0.5 * (stretch[1:] + stretch[:-1])) * h
        H_new = H * length / L_now
        change = max(np.max(np.abs(w_new - w)), abs(H_new - H))
        w, H = w_new, H_new
        if change < tol * length:
            break
    else:
        raise RuntimeError(f"fixed point not converged in {max_iter} iterations: {change:.2e} m")
    z = z_b + (H / M) * np.arange(M + 1)
    return z, w, V


def at(z, w, zq):
    """w at heights zq by cubic interpolation (the grid is fine: linear would do to 1e-7)."""
    from scipy.interpolate import CubicSpline
    return CubicSpline(z, w)(zq)


def top_angle_deg(z, w):
    h = z[1] - z[0]
    slope = (3 * w[-1] - 4 * w[-2] + w[-3]) / (2 * h)
    return math.degrees(math.atan(abs(slope)))


def solve_rod(U=3.0, nodes=601, tol=1e-6):
    """The same riser as a geometrically exact planar rod (no small-angle approximation),
    solved by collocation (scipy.integrate.solve_bvp, 4th order) over the unstretched arc
    length s from the seabed: x' = (1+e) sin(th), z' = (1+e) cos(th), th' = M/EI,
    H' = -fx, V' = -fz, M' = x' V - z' H, with (H, V) the force of the part above s on the
    part below, fx = qd cos^3, fz = -w_s - qd cos^2 sin (the drag on the normal component
    of the current, per unstretched length), M = EI th' (the curvature per unstretched
    length: model-format 5.1, bending_model exact) and e the stretch from the effective
    tension N = H sin + V cos = EA (e + e^2/2)(1 + e) (seaflex's T_eff = EA eps |r'| with
    the Green-Lagrange eps: results-format.md). Ends: x = 0, z = -300, M = 0 at s = 0;
    x = 0, V = F_top, M = 0 at s = L. Returns (s, x, z, theta) at `nodes` points."""
    from scipy.integrate import solve_bvp

    qd = 0.5 * rho_w * Cd * od * U * U

    def stretch(N):
        e = N / EA
        for _ in range(4):  # EA (e + e^2/2)(1 + e) = N by fixed point (e ~ 3e-5)
            e = N / (EA * (1 + 0.5 * e) * (1 + e))
        return e

    def rhs(s, y):
        x, z, th, H, V, M = y
        c, sn = np.cos(th), np.sin(th)
        e = stretch(H * sn + V * c)
        xp, zp = (1 + e) * sn, (1 + e) * c
        fx = qd * c**3
        fz = -w_s - qd * c * c * sn
        return np.vstack((xp, zp, M / EI, -fx, -fz, xp * V - zp * H))

    def bc(ya, yb):
        return np.array([ya[0], ya[1] + length, ya[5], yb[0], yb[4] - F_top, yb[5]])

    s = np.linspace(0.0, length, nodes)
    y = np.zeros((6, nodes))
    y[1] = -length + s
    y[4] = F_top - w_s * (length - s)
    y[3] = -qd * length / 2 + qd * s
    y[2] = 0.05 * np.cos(np.pi * s / length)
    y[0] = 0.05 * length / np.pi * np.sin(np.pi * s / length)
    sol = solve_bvp(rhs, bc, s, y, tol=tol, max_nodes=200000)
    if not sol.success:
        raise RuntimeError(sol.message)
    return sol



if __name__ == "__main__":
    p = argparse.ArgumentParser()
    p.add_argument("--current", type=float, default=3.0)
    p.add_argument("--intervals", type=int, default=3000)
    a = p.parse_args()
    for M in (a.intervals // 2, a.intervals):
        z, w, V = solve(a.current, M)
        zq = -300 + 30 * np.arange(11)
        print(f"M = {M}: top z = {z[-1]:.6f} m, max w = {w.max():.8f} m at z = {z[w.argmax()]:.2f},"
              f" top angle {top_angle_deg(z, w):.6f} deg, bottom V {V[0]:.6e} N")
        print("  w at z = -300, -270, ... 0:", " ".join(f"{x:.6f}" for x in at(z, w, zq)))
    rod = solve_rod(a.current)
    xs = rod.sol(np.linspace(0.0, length, 3001))[0]
    print(f"exact rod: max x = {xs.max():.8f} m, top z = {rod.sol(length)[1]:.6f} m, top angle "
          f"{math.degrees(abs(rod.sol(length)[2])):.6f} deg, seabed angle "
          f"{math.degrees(abs(rod.sol(0.0)[2])):.6f} deg")
