#!/usr/bin/python3
"""Checks of cap_pressure_reference.py against closed forms and against itself.

1. The harmonic operator (7) of a flat clamped plate under uniform radial compression N is
   singular at N a^2 / D = j_{n+1,1}^2 (J_{n+1}(k a) = 0, k^2 = N / D: W = J_n(k r) - J_n(k a)
   (r / a)^n, clamped, gives k J_n'(k) - n J_n(k) = -k J_{n+1}(k) = 0). The zeros are computed
   here from the power series of J, independently of the hard-coded literature values.
2. The small-deflection clamped immovable cap against the exact Kelvin-function solution
   (derived in kelvin_apex_deflection), the flat plate against p a^4 / (64 D), and the nonlinear
   solver at a tiny pressure against the linear solve.
3. The n = 0 singularity of Q_0 and dmu/ds = 0 (two separate monitors) give the same point.
4. Shallow caps (lambda = 2, 3): no limit point and no bifurcation while p/p_cl < 1.5.
5. Literature facts (Budiansky 1959, Huang 1964): the limit point comes first for moderate
   lambda, a bifurcation with n >= 2 beyond lambda of about 5.5 to 6, n growing with lambda
   (only n <= 10 is watched here, to keep the run short; n = 5 is first at lambda = 10).
6. The reduction of the 2-D energy (1)-(4) to the harmonic form (7): Q_n against the second
   derivative of (4), evaluated on a (rho, theta) grid, along a random harmonic perturbation of
   a loaded nonlinear state (n = 0, 1, 2, 4).
Run: /usr/bin/python3 studies/test_cap_pressure_reference.py (about 35 s).
"""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import numpy as np  # noqa: E402

import cap_pressure_reference as ref  # noqa: E402

NU = 1.0 / 3.0
M = 16   # converged to better than 1e-8 for lambda <= 10 (see the module's --table run)


def bessel_j(n, x, terms=60):
    return sum((-1) ** k * (x / 2.0) ** (2 * k + n) / (math.factorial(k) * math.factorial(k + n))
               for k in range(terms))


def first_bessel_zero(n, guess):
    """Newton with J_n' = (J_{n-1} - J_{n+1}) / 2."""
    x = guess
    for _ in range(50):
        step = bessel_j(n, x) / (0.5 * (bessel_j(n - 1, x) - bessel_j(n + 1, x)))
        x -= step
        if abs(step) < 1e-15 * x:
            break
    return x


def kelvin(x, terms=40):
    """ber, bei, ber', bei' by their power series."""
    ber = bei = dber = dbei = 0.0
    for k in range(terms):
        s = (-1) ** k
        a = 1.0 / math.factorial(2 * k) ** 2
        b = 1.0 / math.factorial(2 * k + 1) ** 2
        ber += s * a * (x / 2.0) ** (4 * k)
        bei += s * b * (x / 2.0) ** (4 * k + 2)
        if k:
            dber += s * a * 2.0 * k * (x / 2.0) ** (4 * k - 1)
        dbei += s * b * (2 * k + 1) * (x / 2.0) ** (4 * k + 1)
    return ber, bei, dber, dbei


def kelvin_apex_deflection(lam, nu, p_hat):
    """w(0) / h of the linear clamped immovable shallow cap, a = h = D = 1, pressure p_hat.

    Stress-function form: N_r = F'/r, N_t = F''. Equilibrium D lap^2 w + lap F / R + p = 0,
    compatibility (lap F)' = (E h / R) w', so lap F = (E h / R) w + C. Then
    lap^2 w + lambda^4 w = -(p + C / R) (E h / (D R^2) = lambda^4 / a^4 by (8)), whose regular
    solution is w = A ber(lambda r) + B bei(lambda r) + w_p, w_p = -(p + C / R) / lambda^4.
    Edge: w = w' = 0, and u = r eps_t = 0, i.e. N_t = nu N_r, with N_r(1) = (E h / R) I + C / 2,
    N_t(1) = C - N_r(1), I = int_0^1 w r dr: C = 2 (1 + nu) / (1 - nu) (E h / R) I.
    int_0^1 ber(lam r) r dr = bei'(lam) / lam, int_0^1 bei(lam r) r dr = -ber'(lam) / lam.
    """
    rise = ref.rise_over_thickness(lam, nu)
    inv_r = 2.0 * rise                     # a / R * (a / h) with a = h = 1
    eh = 12.0 * (1.0 - nu * nu)            # E h with D = h = 1
    k = 2.0 * (1.0 + nu) / (1.0 - nu) * eh * inv_r
    ber, bei, dber, dbei = kelvin(lam)
    l4 = lam ** 4
    # unknowns A, B, C
    a = np.array([[ber, bei, -inv_r / l4],
                  [dber, dbei, 0.0],
                  [-k * dbei / lam, k * dber / lam, 1.0 + k * inv_r / (2.0 * l4)]])
    rhs = np.array([p_hat / l4, 0.0, -k * p_hat / (2.0 * l4)])
    A, B, C = np.linalg.solve(a, rhs)
    return A - (p_hat + inv_r * C) / l4


def energy_2d(nu, rise, quad, base, pert, n, eps):
    """Scaled potential (4) without the load, straight from (1)-(2) on a (rho, theta) grid.

    base: u0, u0', w0', w0'' at the nodes; pert: U, U', V, V', W, W', W''; the displacement is
    base + eps (U cos, V sin, W cos)(n theta). The trapezoid rule in theta is exact for the
    trigonometric polynomials (degree <= 4 n) involved.
    """
    count = 4 * n + 8
    th = 2.0 * math.pi * np.arange(count) / count
    c, s = np.cos(n * th)[None, :], np.sin(n * th)[None, :]
    r = quad.rho[:, None]
    u0, du0, dw0, d2w0 = (b[:, None] for b in base)
    U, dU, V, dV, W, dW, d2W = (eps * f[:, None] for f in pert)
    u, u_r, u_t = u0 + U * c, du0 + dU * c, -n * U * s
    v, v_r, v_t = V * s, dV * s, n * V * c
    w_r, w_t = dw0 + dW * c, -n * W * s
    w_rr, w_rt, w_tt = d2w0 + d2W * c, -n * dW * s, -n * n * W * c
    z_r = -2.0 * rise * r
    eps_r = u_r + z_r * w_r + 0.5 * w_r ** 2
    eps_t = (u + v_t) / r + 0.5 * (w_t / r) ** 2
    gam = u_t / r + v_r - v / r + (z_r + w_r) * w_t / r
    k_r, k_t, k_rt = w_rr, w_r / r + w_tt / r ** 2, w_rt / r - w_t / r ** 2
    density = (0.5 * ref.MEMBRANE * (eps_r ** 2 + eps_t ** 2 + 2.0 * nu * eps_r * eps_t
                                     + 0.5 * (1.0 - nu) * gam ** 2)
               + 0.5 * ((k_r + k_t) ** 2 - 2.0 * (1.0 - nu) * (k_r * k_t - k_rt ** 2)))
    return float(quad.weight @ density.sum(axis=1)) * 2.0 * math.pi / count


class Traces:
    """The paths the tests share, traced once (each takes a few seconds)."""
    cache = {}

    @classmethod
    def get(cls, lam, n_max=10):
        key = (lam, n_max)
        if key not in cls.cache:
            cls.cache[key] = ref.trace(lam, NU, M, n_max=n_max, mu_max=1.5)
        return cls.cache[key]


class PlateBuckling(unittest.TestCase):
    LITERATURE = {0: 3.8317059702075123, 1: 5.1356223018406826, 2: 6.3801618959239835}

    def test_bessel_zeros_independent(self):
        for n, j in self.LITERATURE.items():
            self.assertAlmostEqual(first_bessel_zero(n + 1, j + 0.1), j, delta=1e-12)

    def test_clamped_plate_radial_compression(self):
        for n, guess in ((0, 3.9), (1, 5.2), (2, 6.4)):
            exact = first_bessel_zero(n + 1, guess) ** 2
            got = ref.plate_buckling_load(n, 12, NU)
            self.assertLess(abs(got / exact - 1.0), 1e-6, (n, got, exact))


class LinearResponse(unittest.TestCase):
    def test_flat_plate(self):
        prob = ref.cap_problem(4.0, NU, 12, rise=0.0)
        w0 = ref.apex_deflection(prob, ref.linear_state(prob, 1.0))
        self.assertLess(abs(w0 / (-prob.p_cl / 64.0) - 1.0), 1e-10)

    def test_cap_against_kelvin_functions(self):
        for lam in (4.0, 8.0):
            prob = ref.cap_problem(lam, NU, 20)
            got = ref.apex_deflection(prob, ref.linear_state(prob, 1.0))
            exact = kelvin_apex_deflection(lam, NU, prob.p_cl)
            self.assertLess(abs(got / exact - 1.0), 1e-8, (lam, got, exact))

    def test_nonlinear_tends_to_linear(self):
        prob = ref.cap_problem(6.0, NU, M)
        mu = 1e-9
        nonlinear = ref.apex_deflection(prob, ref.solve_state(prob, mu))
        linear = ref.apex_deflection(prob, ref.linear_state(prob, mu))
        self.assertLess(abs(nonlinear / linear - 1.0), 1e-8)


class HarmonicReduction(unittest.TestCase):
    def test_second_variation_of_the_2d_energy(self):
        """Q_n (7) equals d2/deps2 of (4) in the direction of a random cos(n theta) perturbation.

        Checks the reduction of (1)-(4) to (7), the in-plane coupling (U, V and phi terms) and
        the theta factors (2 pi for n = 0, pi otherwise) about a loaded nonlinear state.
        """
        lam, m = 8.0, 10
        prob = ref.cap_problem(lam, NU, m, n_max=4)
        x = ref.solve_state(prob, 0.5)
        b0, rho = prob.basis, prob.basis.quad.rho
        base = (b0.U @ x, b0.U1 @ x, b0.W1 @ x, b0.k_r @ x)
        rng = np.random.default_rng(7)
        for n in (0, 1, 2, 4):
            basis = prob.basis if n == 0 else ref.harmonic_basis(n, m, prob.basis.quad, NU)
            v = rng.standard_normal(basis.U.shape[1])
            k = basis.n_in_plane
            U, dU, V, dV = (f @ (basis.in_transform @ v[:k]) for f in ref._in_plane_raw(n, m, rho))
            w = ref.radial(rho, m, n, 2)
            cw = basis.w_transform @ v[k:]
            pert = (U, dU, V, dV, w.f @ cw, w.d1 @ cw, w.d2 @ cw)
            pi_of = {e: energy_2d(NU, prob.rise, prob.basis.quad, base, pert, n, e)
                     for e in (-0.2, -0.1, 0.0, 0.1, 0.2)}
            # five-point second difference: exact for the quartic eps -> Pi(eps)
            second = (16.0 * (pi_of[0.1] + pi_of[-0.1]) - (pi_of[0.2] + pi_of[-0.2])
                      - 30.0 * pi_of[0.0]) / (12.0 * 0.01)
            s = ref.state_fields(prob, x)
            q = ref.harmonic_operator(basis, NU, s.phi, s.n_r, s.n_t)
            expected = (2.0 if n == 0 else 1.0) * math.pi * (v @ q @ v)
            self.assertLess(abs(second / expected - 1.0), 1e-9, (n, second, expected))


class LimitPoint(unittest.TestCase):
    def test_harmonic_zero_is_the_limit_point(self):
        for lam in (4.0, 8.0):
            r = Traces.get(lam)
            self.assertIn("dmu", r.crossings)
            self.assertLess(abs(r.crossings[0].mu / r.crossings["dmu"].mu - 1.0), 1e-6)
            self.assertLess(abs(r.crossings[0].arclength - r.crossings["dmu"].arclength), 1e-6)


class NoFalseCriticalPoint(unittest.TestCase):
    def test_shallow_caps_have_none(self):
        for lam in (2.0, 3.0):
            r = Traces.get(lam)
            self.assertEqual(r.crossings, {}, lam)
            self.assertGreater(r.mu_end, 1.5)


class LiteratureFacts(unittest.TestCase):
    def critical(self, lam):
        c = Traces.get(lam).critical()
        return (0 if c.key == "dmu" else c.key), c.mu

    def test_limit_point_first_for_moderate_lambda(self):
        for lam in (4.0, 5.0):
            self.assertEqual(self.critical(lam)[0], 0, lam)

    def test_lambda_4_limit_pressure(self):
        n, mu = self.critical(4.0)
        self.assertTrue(0.55 <= mu <= 0.60, mu)

    def test_bifurcation_first_for_larger_lambda_n_growing(self):
        modes = []
        for lam in (6.0, 8.0, 10.0):
            n, mu = self.critical(lam)
            self.assertGreaterEqual(n, 2, lam)
            self.assertLess(mu, Traces.get(lam).limit.mu)
            modes.append(n)
        self.assertEqual(modes, sorted(modes))
        self.assertLess(modes[0], modes[-1])


if __name__ == "__main__":
    unittest.main(verbosity=2)
