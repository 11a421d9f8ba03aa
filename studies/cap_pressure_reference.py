#!/usr/bin/python3
"""Buckling of a clamped shallow spherical cap under uniform external pressure, by Huang's method.

An independent reference for the finite-element critical points of the clamped cap under
pressure: the axisymmetric nonlinear prebuckling path is followed in the pressure (Budiansky
1959), and along it the tangent operator of each circumferential harmonic n is tested for
singularity (Huang 1964); the first critical point is the first of the axisymmetric limit point
(snap-through, n = 0) and the asymmetric bifurcations (n >= 1). Numpy only.

Theory (shallow shell, Marguerre / Donnell-Mushtari-Vlasov kinematics, isotropic, elastic)
----------------------------------------------------------------------------------------
Cap of base radius a, thickness h, sphere radius R, rise H = a^2 / (2 R); polar coordinates
(r, theta) in the base plane; initial shape z0(r) = H (1 - r^2 / a^2); displacements u (radial),
v (circumferential), w (normal to the base plane, positive away from the sphere's centre, i.e.
upwards, like z0). E, nu, D = E h^3 / (12 (1 - nu^2)), A = E h / (1 - nu^2).

 (1) strains   eps_r  = u_r + z0_r w_r + w_r^2 / 2
               eps_t  = (u + v_t) / r + (w_t / r)^2 / 2
               gam    = u_t / r + v_r - v / r + (z0_r + w_r) w_t / r
 (2) curvature k_r = w_rr,  k_t = w_r / r + w_tt / r^2,  k_rt = (w_t / r)_r
 (3) resultants N_r = A (eps_r + nu eps_t),  N_t = A (eps_t + nu eps_r),  N_rt = A (1 - nu) gam / 2
 (4) potential  Pi = int [ A/2 (eps_r^2 + eps_t^2 + 2 nu eps_r eps_t + (1 - nu)/2 gam^2)
                         + D/2 ((k_r + k_t)^2 - 2 (1 - nu) (k_r k_t - k_rt^2)) + p w ] r dr dtheta
     (p > 0 presses towards the sphere's centre, normal to the base plane: shallow theory, so
     the load is conservative and has no load stiffness).
 (5) axisymmetric equilibrium: dPi/d(u0, w0) = 0 with v0 = 0 (Budiansky 1959's problem, here in
     displacement form rather than with a stress function).
 (6) stability / bifurcation: the second variation of (4) about the axisymmetric state,
     d2Pi = int [ A (de_r^2 + de_t^2 + 2 nu de_r de_t + (1 - nu)/2 dgam^2)
                  + N_r0 dw_r^2 + N_t0 (dw_t / r)^2 + D (bending form of dw) ] r dr dtheta,
     de_r = du_r + phi dw_r,  de_t = (du + dv_t) / r,  dgam = du_t / r + dv_r - dv / r + phi dw_t / r,
     phi = z0_r + w0_r. The state is axisymmetric, so (6) splits into harmonics:
     du = U(r) cos n theta, dv = V(r) sin n theta, dw = W(r) cos n theta, giving per n
 (7) Q_n = int [ A (e_r^2 + e_t^2 + 2 nu e_r e_t + (1 - nu)/2 g^2) + N_r0 W'^2 + N_t0 n^2 W^2 / r^2
                 + D ((k_r + k_t)^2 - 2 (1 - nu) (k_r k_t - k_x^2)) ] r dr,
     e_r = U' + phi W',  e_t = (U + n V) / r,  g = (-n U + r V' - V - n phi W) / r,
     k_r = W'',  k_t = W' / r - n^2 W / r^2,  k_x = n (W' / r - W / r^2).
     Q_0 (without V, the decoupled torsion) is the Jacobian of (5): its singularity is the limit
     point. A point of the path is critical for harmonic n when Q_n becomes singular (Huang 1964,
     who used the stress-function form; Bushnell 1985 ch. 5 for the scheme).

Boundary conditions: at r = a, clamped and immovable, w = w_r = 0 and u = v = 0 (every
harmonic, n >= 1 included: the displacement form makes u_theta = 0 an essential condition, no
stress-function subtlety). At r = 0, regularity: W = r^n E(r^2), U = r^(n-1) A(r^2) and
V = r^(n-1) (-A(r^2) + r^2 C(r^2)) for n >= 1 (a smooth vector field), U = r A(r^2) for n = 0.

Nondimensionalisation: rho = r / a, w^ = w / h, u^ = u a / h^2, H^ = H / h, Pi divided by
D h^2 / a^2 (so A becomes 12 and N a^2 / D = 12 (eps^_r + nu eps^_t)), P^ = p a^4 / (D h).
 (8) lambda = 2 (3 (1 - nu^2))^(1/4) sqrt(H / h),  so H^ = lambda^2 / (4 sqrt(3 (1 - nu^2)))
 (9) p_cl = 2 E h^2 / (R^2 sqrt(3 (1 - nu^2))),  so P^_cl = 2 lambda^4 / sqrt(3 (1 - nu^2))
and p / p_cl depends on lambda and nu only. The load parameter of the path is mu = p / p_cl.

Discretisation: Ritz-Galerkin, spectral. Each radial function is the regularity/edge factor
above times sum_k c_k P_k^(2 edge, power)(2 rho^2 - 1), k < m (m = "resolution"; Jacobi
polynomials, orthogonal in L2(rho drho) with the factor, so the bases stay well conditioned for
every n: Zernike-like); the integrals are Gauss-Legendre
in rho, exact for these polynomial integrands. The basis of each harmonic is orthonormalised in
the unstressed flat plate's energy, so every operator is O(1)-conditioned whatever m (the Ritz
result depends only on the span). Q_0 is then exactly the Jacobian of the discrete (5), so the
n = 0 singularity and dmu/ds = 0 coincide at the discrete level too.

Path and critical points: pseudo-arclength continuation in (state, mu), with a scaled norm; for
each harmonic the smallest eigenvalue of Q_n (n = 0 also dmu/ds) is watched, and a sign change
between two points is located by a bracketed secant (Illinois) on the arclength of the
corrector from the earlier point (arclength to 1e-13 of the step, so mu to about 1e-12).
Reported: the first limit point (mu at dmu/ds = 0); the first bifurcation along the traced
path, flagged before or after that limit point (the path is traced a scaled arclength of 2 past
it; an "after" one lies on the unstable descending branch and is not critical); the critical
point, the earlier of the two. Without a limit point the path is followed to mu_max (1.5).

References
  Budiansky, B. (1959) Buckling of clamped shallow spherical shells. Proc. IUTAM Symp. on the
    Theory of Thin Elastic Shells, Delft, 64-94.
  Huang, N. C. (1964) Unsymmetrical buckling of thin shallow spherical shells. J. Appl. Mech.
    31, 447-457.
  Bushnell, D. (1985) Computerized Buckling Analysis of Shells. Martinus Nijhoff.

Run: studies/cap_pressure_reference.py --lambda 4 6 8 10 [--nu 0.3333333333] [--n-max 12]
     [--resolutions 16 22 28] [--table] [--csv FILE]
"""
import argparse
import csv
import dataclasses
import math
import sys
import time

import numpy as np

MEMBRANE = 12.0  # A h^2 / D in the scaled energy (4)
DEFAULT_RESOLUTIONS = (16, 22, 28)


# ----------------------------------------------------------------------------- parameters
def root_c(nu):
    """sqrt(3 (1 - nu^2)), the constant of (8) and (9)."""
    return math.sqrt(3.0 * (1.0 - nu * nu))


def rise_over_thickness(lam, nu):
    """H / h from lambda, (8)."""
    return lam * lam / (4.0 * root_c(nu))


def classical_pressure(lam, nu):
    """p_cl a^4 / (D h), (9)."""
    return 2.0 * lam ** 4 / root_c(nu)


# ----------------------------------------------------------------------------- quadrature
@dataclasses.dataclass(frozen=True)
class Quadrature:
    rho: np.ndarray
    weight: np.ndarray  # includes the area factor rho


def gauss_rho(points):
    x, w = np.polynomial.legendre.leggauss(points)
    rho = 0.5 * (x + 1.0)
    return Quadrature(rho=rho, weight=0.5 * w * rho)


# ----------------------------------------------------------------------------- radial basis
@dataclasses.dataclass(frozen=True)
class Radial:
    """Values and rho-derivatives at the nodes of rho^power (1 - rho^2)^edge P_k(2 rho^2 - 1)."""
    f: np.ndarray
    d1: np.ndarray
    d2: np.ndarray


def jacobi(s, m, alpha, beta):
    """P_k^(alpha, beta)(s), k < m, by the three-term recurrence."""
    p = np.zeros((s.size, m))
    p[:, 0] = 1.0
    if m > 1:
        p[:, 1] = 0.5 * (alpha - beta) + 0.5 * (alpha + beta + 2.0) * s
    for k in range(1, m - 1):
        c = 2 * k + alpha + beta
        a1 = 2.0 * (k + 1) * (k + alpha + beta + 1) * c
        a2 = (c + 1.0) * (alpha * alpha - beta * beta)
        a3 = c * (c + 1.0) * (c + 2.0)
        a4 = 2.0 * (k + alpha) * (k + beta) * (c + 2.0)
        p[:, k + 1] = ((a2 + a3 * s) * p[:, k] - a4 * p[:, k - 1]) / a1
    return p


def jacobi_in_s(rho, m, alpha, beta):
    """P_k^(alpha, beta)(2 rho^2 - 1) and its first two rho-derivatives, k < m.

    With alpha = 2 edge and beta = power, rho^power (1 - rho^2)^edge P_k are orthogonal in
    L2(rho drho) (Zernike-like), which keeps the energy Gram matrices well conditioned for
    every harmonic; Chebyshev polynomials in s lose about n decades at harmonic n.
    """
    s = 2.0 * rho * rho - 1.0
    t = jacobi(s, m, alpha, beta)
    ts = np.zeros_like(t)
    tss = np.zeros_like(t)
    k = np.arange(m)
    if m > 1:
        ts[:, 1:] = jacobi(s, m - 1, alpha + 1, beta + 1) * (k[1:] + alpha + beta + 1) / 2.0
    if m > 2:
        tss[:, 2:] = (jacobi(s, m - 2, alpha + 2, beta + 2)
                      * (k[2:] + alpha + beta + 1) * (k[2:] + alpha + beta + 2) / 4.0)
    # s = 2 rho^2 - 1: ds/drho = 4 rho, d2s/drho2 = 4
    r = rho[:, None]
    return t, 4.0 * r * ts, 16.0 * r * r * tss + 4.0 * ts


def radial(rho, m, power, edge):
    t, t1, t2 = jacobi_in_s(rho, m, 2 * edge, power)
    q = 1.0 - rho * rho
    f = rho ** power * q ** edge
    f1 = (power * rho ** (power - 1) * q ** edge if power else 0.0) \
        - 2.0 * edge * rho ** (power + 1) * q ** (edge - 1)
    f2 = (power * (power - 1) * rho ** (power - 2) * q ** edge if power > 1 else 0.0) \
        - 2.0 * edge * (2 * power + 1) * rho ** power * q ** (edge - 1) \
        + (4.0 * edge * (edge - 1) * rho ** (power + 2) * q ** (edge - 2) if edge > 1 else 0.0)
    f, f1, f2 = (np.broadcast_to(np.asarray(g, dtype=float), rho.shape)[:, None]
                 for g in (f, f1, f2))
    return Radial(f=f * t, d1=f1 * t + f * t1, d2=f2 * t + 2.0 * f1 * t1 + f * t2)


# ----------------------------------------------------------------------------- harmonic basis
def _membrane(e_r, e_t, g, nu, wq):
    """A-part of (7) divided by A: the quadratic form of (e_r, e_t, g) rows."""
    q = _gram(e_r, e_r, wq) + _gram(e_t, e_t, wq) + 0.5 * (1.0 - nu) * _gram(g, g, wq)
    cross = _gram(e_r, e_t, wq)
    return q + nu * (cross + cross.T)


def _bending(k_r, k_t, k_x, nu, wq):
    """D-part of (7) divided by D."""
    kk = k_r + k_t
    cross = _gram(k_r, k_t, wq)
    return _gram(kk, kk, wq) - (1.0 - nu) * (cross + cross.T) + 2.0 * (1.0 - nu) * _gram(k_x, k_x, wq)


def _gram(a, b, wq):
    return a.T @ (wq[:, None] * b)


def _orthonormaliser(gram):
    """T with T' gram T = I; the diagonal scaling first keeps eigh's relative accuracy."""
    d = 1.0 / np.sqrt(np.diag(gram))
    vals, vecs = np.linalg.eigh(d[:, None] * gram * d[None, :])
    if vals[0] <= vals[-1] * 1e-13:
        raise ValueError("basis numerically dependent: lower the resolution")
    return d[:, None] * vecs / np.sqrt(vals)


def _in_plane_raw(n, m, rho):
    """(U, U', V, V') of the regular in-plane functions of harmonic n, before orthonormalising."""
    if n == 0:
        a = radial(rho, m, 1, 1)
        zero = np.zeros_like(a.f)
        return a.f, a.d1, zero, zero
    a = radial(rho, m, n - 1, 1)
    c = radial(rho, m, n + 1, 1)
    zero = np.zeros_like(a.f)
    return (np.hstack([a.f, zero]), np.hstack([a.d1, zero]),
            np.hstack([-a.f, c.f]), np.hstack([-a.d1, c.d1]))


@dataclasses.dataclass(frozen=True)
class Harmonic:
    """Basis of harmonic n at the quadrature nodes; columns: in-plane coordinates, then W ones.

    Rows of (7) that do not depend on the state (e_t, g without phi, curvatures) are stored;
    e_r and g are completed with phi in harmonic_operator.
    """
    n: int
    m: int
    quad: Quadrature
    in_transform: np.ndarray  # raw in-plane coefficients (_in_plane_raw) per orthonormal coordinate
    w_transform: np.ndarray   # raw W coefficients (radial(.., n, 2)) per orthonormal coordinate
    U: np.ndarray
    U1: np.ndarray
    W: np.ndarray
    W1: np.ndarray
    e_t: np.ndarray
    g0: np.ndarray
    gw: np.ndarray
    k_r: np.ndarray
    k_t: np.ndarray
    k_x: np.ndarray

    @property
    def n_in_plane(self):
        return self.U.shape[1] - self.m


def harmonic_basis(n, m, quad, nu):
    """The basis of harmonic n, each block orthonormal in the unstressed flat plate's Q_n (7).

    The flat form has no membrane-bending coupling, so the in-plane and W blocks are made
    orthonormal separately and the state-dependent coupling stays visible in harmonic_operator.
    """
    rho = quad.rho
    r = rho[:, None]
    wq = quad.weight
    U, U1, V, V1 = _in_plane_raw(n, m, rho)
    e_t = (U + n * V) / r
    g0 = (-n * U + r * V1 - V) / r
    t_in = _orthonormaliser(MEMBRANE * _membrane(U1, e_t, g0, nu, wq))
    w = radial(rho, m, n, 2)
    k_r = w.d2
    k_t = w.d1 / r - n * n * w.f / (r * r)
    k_x = n * (w.d1 / r - w.f / (r * r))
    t_w = _orthonormaliser(_bending(k_r, k_t, k_x, nu, wq))
    pad_in = np.zeros((rho.size, m))
    pad_w = np.zeros((rho.size, t_in.shape[1]))

    def in_plane(a):
        return np.hstack([a @ t_in, pad_in])

    def bending(a):
        return np.hstack([pad_w, a @ t_w])

    return Harmonic(n=n, m=m, quad=quad, in_transform=t_in, w_transform=t_w,
                    U=in_plane(U), U1=in_plane(U1), W=bending(w.f), W1=bending(w.d1),
                    e_t=in_plane(e_t), g0=in_plane(g0), gw=bending(-n * w.f / r),
                    k_r=bending(k_r), k_t=bending(k_t), k_x=bending(k_x))


def harmonic_operator(basis, nu, phi, n_r, n_t):
    """Q_n (7) about a state given at the nodes: phi = z0' + w0', N_r0 a^2 / D, N_t0 a^2 / D."""
    b = basis
    wq = b.quad.weight
    e_r = b.U1 + phi[:, None] * b.W1
    g = b.g0 + phi[:, None] * b.gw
    q = (MEMBRANE * _membrane(e_r, b.e_t, g, nu, wq) + _bending(b.k_r, b.k_t, b.k_x, nu, wq)
         + _gram(b.W1, b.W1, n_r * wq))
    if b.n:
        q = q + b.n * b.n * _gram(b.W, b.W, n_t * wq / b.quad.rho ** 2)
    return 0.5 * (q + q.T)


# ----------------------------------------------------------------------------- axisymmetric state
@dataclasses.dataclass(frozen=True)
class CapProblem:
    """The scaled axisymmetric problem (5) on the n = 0 basis; every harmonic shares the nodes."""
    nu: float
    rise: float          # H / h
    p_cl: float          # p_cl a^4 / (D h)
    basis: Harmonic
    load: np.ndarray     # d(int w rho drho)/dx


def quadrature_for(resolution, n_max):
    # Integrand degree in rho: a product of two second derivatives of degree 2 m + n + 4 with the
    # state's resultants (degree about 4 m + 6); Gauss-Legendre is exact to degree 2 q - 1.
    return gauss_rho(4 * resolution + n_max + 24)


def cap_problem(lam, nu, resolution, n_max=12, rise=None):
    """The n = 0 problem; rise (H / h) overrides lambda's (rise = 0: the flat plate)."""
    quad = quadrature_for(resolution, n_max)
    basis = harmonic_basis(0, resolution, quad, nu)
    rise = rise_over_thickness(lam, nu) if rise is None else rise
    return CapProblem(nu=nu, rise=rise, p_cl=classical_pressure(lam, nu), basis=basis,
                      load=basis.W.T @ quad.weight)


@dataclasses.dataclass(frozen=True)
class StateFields:
    phi: np.ndarray
    n_r: np.ndarray
    n_t: np.ndarray


def state_fields(prob, x):
    """phi = z0' + w0', N_r a^2 / D, N_t a^2 / D at the nodes, from (1) and (3)."""
    b = prob.basis
    z1 = -2.0 * prob.rise * b.quad.rho
    w1 = b.W1 @ x
    eps_r = b.U1 @ x + z1 * w1 + 0.5 * w1 * w1
    eps_t = b.e_t @ x
    nu = prob.nu
    return StateFields(phi=z1 + w1, n_r=MEMBRANE * (eps_r + nu * eps_t),
                       n_t=MEMBRANE * (eps_t + nu * eps_r))


def residual(prob, x, mu):
    """dPi/dx, (4)-(5) in the scaled units; mu = p / p_cl."""
    b = prob.basis
    s = state_fields(prob, x)
    wq = b.quad.weight
    e_r = b.U1 + s.phi[:, None] * b.W1
    kr, kt = b.k_r @ x, b.k_t @ x
    nu = prob.nu
    internal = (e_r.T @ (wq * s.n_r) + b.e_t.T @ (wq * s.n_t)
                + b.k_r.T @ (wq * (kr + nu * kt)) + b.k_t.T @ (wq * (kt + nu * kr)))
    return internal + mu * prob.p_cl * prob.load


def jacobian(prob, x):
    """dresidual/dx: Q_0 of (7) about x (the torsion V decouples and is left out)."""
    s = state_fields(prob, x)
    return harmonic_operator(prob.basis, prob.nu, s.phi, s.n_r, s.n_t)


def apex_deflection(prob, x):
    """w(0) / h."""
    b = prob.basis
    raw = radial(np.zeros(1), b.m, 0, 2).f[0]
    return float(raw @ b.w_transform @ x[b.n_in_plane:])


def solve_state(prob, mu, x0=None, tol=1e-13, max_iter=40):
    """Newton at fixed mu, for loads well below the limit point."""
    x = np.zeros(prob.load.size) if x0 is None else x0.copy()
    for _ in range(max_iter):
        dx = np.linalg.solve(jacobian(prob, x), -residual(prob, x, mu))
        x += dx
        if np.linalg.norm(dx) <= tol * max(1.0, np.linalg.norm(x)):
            return x
    raise RuntimeError("Newton did not converge at mu = %g" % mu)


def linear_state(prob, mu):
    """The small-deflection response: Q_0 of the unloaded cap, one solve."""
    return np.linalg.solve(jacobian(prob, np.zeros(prob.load.size)), -mu * prob.p_cl * prob.load)


# ----------------------------------------------------------------------------- continuation
@dataclasses.dataclass(frozen=True)
class PathPoint:
    x: np.ndarray
    mu: float
    tangent: np.ndarray   # unit (dx, dmu) in the scaled norm, oriented along the path
    iterations: int = 0


class Path:
    """Pseudo-arclength continuation of (5) in (x, mu).

    x is scaled by the norm of the linear response at mu = 1 so that a step moves x and mu
    comparably on the near-linear part of the path.
    """

    def __init__(self, prob):
        self.prob = prob
        scale = float(np.linalg.norm(linear_state(prob, 1.0)))
        self.weights = np.append(np.full(prob.load.size, scale ** -2), 1.0)

    def _bordered(self, x, row):
        k = self.prob.load.size
        a = np.empty((k + 1, k + 1))
        a[:k, :k] = jacobian(self.prob, x)
        a[:k, k] = self.prob.p_cl * self.prob.load
        a[k] = row
        return a

    def _unit(self, t):
        return t / math.sqrt(t @ (self.weights * t))

    def tangent(self, x, previous):
        rhs = np.zeros(previous.size)
        rhs[-1] = 1.0
        return self._unit(np.linalg.solve(self._bordered(x, self.weights * previous), rhs))

    def start(self):
        k = self.prob.load.size
        up = np.zeros(k + 1)
        up[k] = 1.0
        return PathPoint(x=np.zeros(k), mu=0.0, tangent=self.tangent(np.zeros(k), up))

    def correct(self, point, ds, tol=1e-12, max_iter=20):
        """Newton on the hyperplane normal to point.tangent at arclength ds; None if it fails."""
        prob = self.prob
        k = prob.load.size
        row = self.weights * point.tangent
        y0 = np.append(point.x, point.mu) + ds * point.tangent
        y = y0.copy()
        for it in range(1, max_iter + 1):
            r = np.append(residual(prob, y[:k], y[k]), row @ (y - y0))
            dy = np.linalg.solve(self._bordered(y[:k], row), -r)
            y += dy
            if not np.all(np.isfinite(y)):
                return None
            if math.sqrt(dy @ (self.weights * dy)) <= tol * (1.0 + abs(ds)):
                t = self.tangent(y[:k], point.tangent)
                return PathPoint(x=y[:k], mu=float(y[k]), tangent=t, iterations=it)
        return None


# ----------------------------------------------------------------------------- critical points
def monitors(prob, bases, point, keys):
    """For each key: smallest eigenvalue of Q_key about point, or dmu/ds for key 'dmu'."""
    s = state_fields(prob, point.x)
    out = {}
    for key in keys:
        if key == "dmu":
            out[key] = float(point.tangent[-1])
        else:
            q = harmonic_operator(bases[key], prob.nu, s.phi, s.n_r, s.n_t)
            out[key] = float(np.linalg.eigvalsh(q)[0])
    return out


def locate(path, bases, point, ds, f0, f1, key, tol=1e-13):
    """The arclength in [0, ds] from point where the monitor changes sign (Illinois secant)."""
    a, fa, b, fb = 0.0, f0, ds, f1
    best = None
    for _ in range(200):
        c = b - fb * (b - a) / (fb - fa)
        q = path.correct(point, c)
        if q is None:
            raise RuntimeError("corrector failed while locating %s" % key)
        fc = monitors(path.prob, bases, q, [key])[key]
        best = q
        if fc == 0.0:
            break
        if fc * fb < 0.0:
            a, fa = b, fb
        else:
            fa *= 0.5
        b, fb = c, fc
        if abs(b - a) <= tol * abs(ds):
            break
    return best, b


@dataclasses.dataclass
class Crossing:
    key: object          # harmonic n, or 'dmu' for the limit point
    mu: float
    arclength: float
    apex: float          # w(0) / h at the point


@dataclasses.dataclass
class PathResult:
    lam: float
    nu: float
    resolution: int
    crossings: dict      # key -> first Crossing along the traced path
    mu_end: float
    arclength_end: float

    @property
    def limit(self):
        return self.crossings.get("dmu")

    def bifurcations(self):
        return sorted((c for k, c in self.crossings.items() if k not in ("dmu", 0)),
                      key=lambda c: c.arclength)

    def first_bifurcation(self):
        b = self.bifurcations()
        return b[0] if b else None

    def critical(self):
        """The first of the limit point and the bifurcations along the path (None if neither)."""
        cands = [c for c in (self.limit, self.first_bifurcation()) if c is not None]
        return min(cands, key=lambda c: c.arclength) if cands else None


def trace(lam, nu, resolution, n_max=12, mu_max=1.5, after_limit=2.0, ds_max=0.05,
          max_steps=4000, rise=None):
    """Follow the axisymmetric path from p = 0 and record each monitor's first sign change.

    Stops when mu exceeds mu_max with no limit point, or after_limit (scaled arclength) past
    the limit point, so that bifurcations just beyond the snap are seen too.
    """
    prob = cap_problem(lam, nu, resolution, n_max, rise=rise)
    bases = {0: prob.basis}
    bases.update({n: harmonic_basis(n, resolution, prob.basis.quad, nu) for n in range(1, n_max + 1)})
    keys = ["dmu"] + list(range(n_max + 1))
    path = Path(prob)
    point = path.start()
    values = monitors(prob, bases, point, keys)
    if min(values.values()) <= 0.0:
        raise RuntimeError("the unloaded cap is not stable: %r" % values)
    crossings, s, ds = {}, 0.0, 0.01
    for _ in range(max_steps):
        nxt = path.correct(point, ds)
        if nxt is None or nxt.iterations > 8:
            ds *= 0.5
            if ds < 1e-10:
                raise RuntimeError("continuation stalled at mu = %g" % point.mu)
            continue
        new = monitors(prob, bases, nxt, keys)
        for k in keys:
            if k not in crossings and values[k] * new[k] <= 0.0:
                q, sigma = locate(path, bases, point, ds, values[k], new[k], k)
                crossings[k] = Crossing(key=k, mu=q.mu, arclength=s + sigma,
                                        apex=apex_deflection(prob, q.x))
        point, values, s = nxt, new, s + ds
        ds = min(ds_max, ds * (1.5 if nxt.iterations <= 4 else 1.0))
        limit = crossings.get("dmu")
        if limit is None and point.mu > mu_max:
            break
        if limit is not None and s > limit.arclength + after_limit:
            break
    return PathResult(lam=lam, nu=nu, resolution=resolution, crossings=crossings,
                      mu_end=point.mu, arclength_end=s)


def plate_buckling_load(n, resolution, nu=1.0 / 3.0, tol=1e-14):
    """N a^2 / D at which Q_n of the flat clamped plate under uniform compression N is singular.

    The same operator (7) as along the path, with phi = 0 and N_r0 = N_t0 = -N; the sign change
    of its smallest eigenvalue is bracketed and located by the Illinois secant.
    """
    quad = quadrature_for(resolution, n)
    basis = harmonic_basis(n, resolution, quad, nu)
    zero = np.zeros(quad.rho.size)

    def smallest(load):
        return float(np.linalg.eigvalsh(harmonic_operator(basis, nu, zero, -load + zero,
                                                         -load + zero))[0])

    a, fa, b = 0.0, smallest(0.0), 1.0
    fb = smallest(b)
    while fb > 0.0:
        a, fa, b = b, fb, 2.0 * b
        fb = smallest(b)
    for _ in range(200):
        c = b - fb * (b - a) / (fb - fa)
        fc = smallest(c)
        if fc * fb < 0.0:
            a, fa = b, fb
        else:
            fa *= 0.5
        b, fb = c, fc
        if abs(b - a) <= tol * abs(b) or fc == 0.0:
            break
    return b


# ----------------------------------------------------------------------------- summary and CLI
@dataclasses.dataclass
class Summary:
    """One lambda on several resolutions (ascending); per-resolution values are lists."""
    lam: float
    nu: float
    resolutions: list
    limit: list            # mu of the axisymmetric limit point (None: none up to mu_max)
    bifurcation: list      # (n, mu, before_limit) of the first bifurcation (n >= 1), or None
    critical: list         # (n, mu) of the first critical point (n = 0: limit point), or None
    seconds: float

    @staticmethod
    def _error(values):
        if any(v is None for v in values[-2:]):
            return None
        return abs(values[-1] - values[-2]) / abs(values[-1])

    def limit_error(self):
        """|finest - next| / finest: spectral convergence makes it an upper bound of the error."""
        return self._error(self.limit)

    def bifurcation_error(self):
        return self._error([None if b is None else b[1] for b in self.bifurcation])

    def critical_error(self):
        return self._error([None if c is None else c[1] for c in self.critical])

    def consistent_modes(self):
        """True when every resolution finds the same n for the first bifurcation and critical point."""
        return (len({None if b is None else b[0] for b in self.bifurcation}) == 1
                and len({None if c is None else c[0] for c in self.critical}) == 1)


def first_critical_point(lam, nu=1.0 / 3.0, n_max=12, resolution=DEFAULT_RESOLUTIONS[-1],
                         mu_max=1.5):
    """(n, p / p_cl) of the first critical point along the axisymmetric path, or None.

    n = 0 is the axisymmetric limit point; n >= 1 a bifurcation into cos(n theta) before it.
    """
    crit = trace(lam, nu, resolution, n_max=n_max, mu_max=mu_max).critical()
    return None if crit is None else (0 if crit.key == "dmu" else crit.key, crit.mu)


def summarise(lam, nu=1.0 / 3.0, n_max=12, resolutions=DEFAULT_RESOLUTIONS, mu_max=1.5):
    start = time.perf_counter()
    limit, bif, crit = [], [], []
    for m in sorted(resolutions):
        r = trace(lam, nu, m, n_max=n_max, mu_max=mu_max)
        limit.append(None if r.limit is None else r.limit.mu)
        b = r.first_bifurcation()
        bif.append(None if b is None else
                   (b.key, b.mu, r.limit is None or b.arclength < r.limit.arclength))
        c = r.critical()
        crit.append(None if c is None else (0 if c.key == "dmu" else c.key, c.mu))
    return Summary(lam=lam, nu=nu, resolutions=sorted(resolutions), limit=limit,
                   bifurcation=bif, critical=crit, seconds=time.perf_counter() - start)


def _fmt(value, digits=8):
    return "none" if value is None else "%.*f" % (digits, value)


def _fmt_err(value):
    return "n/a" if value is None else "%.1e" % value


def _bifurcation_cell(b):
    if b is None:
        return "none"
    return "%.8f (n = %d, %s)" % (b[1], b[0], "before limit" if b[2] else "after limit")


def _critical_cell(c):
    if c is None:
        return "none"
    return "%.8f (%s)" % (c[1], "limit point, n = 0" if c[0] == 0 else "bifurcation, n = %d" % c[0])


def markdown_table(summaries, mu_max=1.5):
    lines = ["| lambda | limit point p/p_cl | first bifurcation p/p_cl (n) | critical p/p_cl |"
             " est. rel. error (limit / bif.) |",
             "|---|---|---|---|---|"]
    for s in summaries:
        lines.append("| %g | %s | %s | %s | %s / %s%s |" % (
            s.lam, _fmt(s.limit[-1]), _bifurcation_cell(s.bifurcation[-1]),
            _critical_cell(s.critical[-1]), _fmt_err(s.limit_error()),
            _fmt_err(s.bifurcation_error()), "" if s.consistent_modes() else " (n differs!)"))
    lines.append("")
    lines.append("'none': not found while p/p_cl < %g (no limit point) or within the traced "
                 "post-limit arc." % mu_max)
    return "\n".join(lines)


def resolution_table(summaries):
    lines = ["| lambda | m | limit point p/p_cl | first bifurcation p/p_cl (n) |", "|---|---|---|---|"]
    for s in summaries:
        for m, lim, b in zip(s.resolutions, s.limit, s.bifurcation):
            lines.append("| %g | %d | %s | %s |" % (s.lam, m, _fmt(lim, 11),
                                                   "none" if b is None else
                                                   "%.11f (n = %d)" % (b[1], b[0])))
    return "\n".join(lines)


def write_csv(path, summaries):
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["lambda", "nu", "resolution", "limit_p_over_pcl", "bifurcation_p_over_pcl",
                      "bifurcation_n", "bifurcation_before_limit", "critical_p_over_pcl",
                      "critical_n", "limit_rel_error", "bifurcation_rel_error"])
        for s in summaries:
            for i, m in enumerate(s.resolutions):
                b, c = s.bifurcation[i], s.critical[i]
                last = i == len(s.resolutions) - 1
                out.writerow([s.lam, s.nu, m, _csv(s.limit[i]), _csv(b and b[1]), _csv(b and b[0]),
                              _csv(b and b[2]), _csv(c and c[1]), _csv(c and c[0]),
                              _csv(s.limit_error() if last else None),
                              _csv(s.bifurcation_error() if last else None)])


def _csv(value):
    if value is None:
        return ""
    return "%.12g" % value if isinstance(value, float) else str(value)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--lambda", dest="lams", type=float, nargs="+", required=True)
    ap.add_argument("--nu", type=float, default=1.0 / 3.0)
    ap.add_argument("--n-max", type=int, default=12)
    ap.add_argument("--resolutions", type=int, nargs=3, default=list(DEFAULT_RESOLUTIONS),
                    help="three basis sizes m per field (ascending)")
    ap.add_argument("--mu-max", type=float, default=1.5,
                    help="stop a path without limit point at this p/p_cl")
    ap.add_argument("--table", action="store_true", help="print the Markdown tables")
    ap.add_argument("--csv", help="write every resolution's values to this file")
    args = ap.parse_args(argv)
    start = time.perf_counter()
    summaries = []
    for lam in args.lams:
        summaries.append(summarise(lam, args.nu, args.n_max, args.resolutions, args.mu_max))
        if not args.table:
            s = summaries[-1]
            print("lambda %g: limit %s, first bifurcation %s, critical %s (%.1f s)" % (
                lam, _fmt(s.limit[-1]), _bifurcation_cell(s.bifurcation[-1]),
                _critical_cell(s.critical[-1]), s.seconds), flush=True)
    if args.table:
        print("nu = %.10g, n = 1..%d, resolutions m = %s\n" % (args.nu, args.n_max,
                                                               " ".join(map(str, args.resolutions))))
        print(markdown_table(summaries, args.mu_max))
        print()
        print(resolution_table(summaries))
    if args.csv:
        write_csv(args.csv, summaries)
    print("\nrun time %.1f s" % (time.perf_counter() - start), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
