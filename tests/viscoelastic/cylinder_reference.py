"""Exact reference solution for the visco-elastic cylinder of the thesis, §4.5
(Lee, Radok & Woodward 1959), for the model as the thesis specifies it
(§4.5.2 and table 4.2; the Maxwell law of §2.6 and §3.9).

Model (plane strain, small strain, quasi-static, axisymmetric):

* body a <= r <= b: Maxwell visco-elastic, elastic bulk modulus K (no
  volumetric creep), deviatoric law  de'/dt = (ds/dt)/(2G) + s/(2 eta)  on the
  3-D deviator (sigma_zz included, eps_zz = 0);  K = E/(3(1-2nu)),
  G = E/(2(1+nu)), tau = eta/G;
* bonded at r = b to a thin elastic shell of thickness h (E_s, nu_s), either
    variant "ring":  a radial spring  sigma_r(b) = -k u_r(b),
                     k = E_s h / ((1 - nu_s^2) b^2)          (plane-strain ring)
    variant "shell": an elastic annulus b <= r <= c = b + h in plane strain,
                     outer surface traction free; seen from the body it is the
                     exact spring
                     k = 2 (c^2 - b^2) / (b [b^2/(lam_s + G_s) + c^2/G_s]);
* internal pressure p applied at t = 0 (Heaviside step, then constant).

Every field keeps the Lame form at all times (equilibrium and the Maxwell law
are satisfied by a creep strain of the same form, see __doc__ of
``integrate_ode``):

    u_r      = A(t) r + B(t)/r
    sigma_r  = C(t) - D(t)/r^2,   sigma_theta = C(t) + D(t)/r^2
    sigma_zz = Z(t)                                  (independent of r)

i.e. in the thesis notation  sigma_r = -p (f + (b/r)^2 g),
sigma_theta = -p (f - (b/r)^2 g)  with  f = -C/p,  g = D/(p b^2).

Correspondence principle (Carson transform F*(s) = s L[F](s)): the elastic
solution with G replaced by  G*(s) = G s tau/(1 + s tau)  and K* = K.  With
M(g) = 2K + 2g/3 = 2(lambda* + G*) and c1 = 1/a^2 - 1/b^2 the two boundary
conditions  sigma_r(a) = -p,  sigma_r(b) = -k u(b)  give, writing g for G*,

    Delta(g) = M(g) (2 c1 g + k/b) + 2 k b g / a^2
             = Q2 g^2 + Q1 g + Q0,
               Q2 = 4 c1 / 3,  Q1 = 4 K c1 + 2k/(3b) + 2 k b/a^2,  Q0 = 2 K k/b
    A* = N_A/Delta,  N_A(g) = -(p/b)(k - 2g/b)
    B* = N_B/Delta,  N_B(g) = p (2K + k b + 2g/3)
    C* = N_C/Delta,  N_C(g) = M(g) N_A(g)
    D* = N_D/Delta,  N_D(g) = 2 g N_B(g)
    Z* = N_Z/Delta,  N_Z(g) = 2 (K - 2g/3) N_A(g)

All numerators have degree <= 2 in g, so each of A..Z is

    F(t) = F_inf + sum_{i=1,2} c_i exp(-t / T_i),          t > 0

with g_i the two (negative) roots of Delta(g) = 0 and, because
s_i = g_i / (tau (G - g_i)),

    T_i   = tau (G - g_i) / (-g_i)          (relaxation times, tau/T_i in (0, 1))
    F_inf = N(0) / Delta(0)                 (G* -> 0: the body carries only pressure)
    c_i   = N(g_i) / (Delta'(g_i) g_i (1 - g_i/G)).

Equivalently s_i tau are the roots of  Delta(G) x^2 + (2 Q0 + Q1 G) x + Q0 = 0.
At t = 0+ the sum F_inf + c_1 + c_2 equals N(G)/Delta(G) (elastic composite).

In the shell (variant "shell", b < r <= c), loaded by q(t) = -sigma_r(b, t):
sigma_r = q b^2/(c^2 - b^2) (1 - c^2/r^2), sigma_theta = q b^2/(c^2 - b^2)
(1 + c^2/r^2), sigma_zz = 2 nu_s q b^2/(c^2 - b^2), u_r = q b^2/(c^2 - b^2)
[(1 + nu_s)(1 - 2 nu_s) r + (1 + nu_s) c^2/r]/E_s.  For the ring the hoop
stress is q b/h.

Time t is physical (the time unit of eta); the thesis measures t in units of
tau = eta/G (tau = 0.999975 for nu = 0.3333, exactly 1 for nu = 1/3).

Thesis curves (§4.5.2, sign of the 0.1583 term corrected: the printed
-0.1583 violates sigma_r(a) = -p, i.e. f + (b/a)^2 g = 1):
f(t) = 1 - 0.005363 e^{-0.9849 t} - 0.6331 e^{-0.3528 t},
g(t) = 0.001341 e^{-0.9849 t} + 0.1583 e^{-0.3528 t}.
They are reproduced to all printed digits by the "ring" variant with
nu = 1/3 exactly (then tau = 1); with nu = 0.3333 the slow rate is 0.35273
(printed 0.3528), see doc/viscoelastic_cylinder_derivation.md.

Standard library only.  Run the file for the self-checks and the tables.
"""
import math
import os
import sys
from functools import lru_cache

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import solve_dense  # noqa: E402

DEFAULTS = dict(a=2.0, b=4.0, h=4.0 / 33.0, E=1e5, nu=0.3333, eta=0.375e5,
                E_s=3e7, nu_s=0.3015, p=1e3)
VARIANTS = ("ring", "shell")
THESIS_RATES = (0.9849, 0.3528)          # per unit of tau = eta/G
THESIS_F = (1.0, -0.005363, -0.6331)     # f = F0 + F1 e^{-r1 t} + F2 e^{-r2 t}
THESIS_G = (0.0, 0.001341, 0.1583)       # corrected sign of 0.1583 (see above)
THESIS_G_PRINTED = (0.0, 0.001341, -0.1583)


def _params(params):
    unknown = set(params) - set(DEFAULTS)
    if unknown:
        raise TypeError("unknown parameter(s): %s" % ", ".join(sorted(unknown)))
    q = dict(DEFAULTS)
    q.update(params)
    return q


def shell_spring(variant, b, h, E_s, nu_s):
    """Radial stiffness per unit area k [stress/length] of the outer shell,
    sigma_r(b) = -k u_r(b)."""
    if variant == "ring":
        return E_s * h / ((1.0 - nu_s ** 2) * b * b)
    if variant == "shell":
        c = b + h
        lam_s = E_s * nu_s / ((1 + nu_s) * (1 - 2 * nu_s))
        G_s = E_s / (2 * (1 + nu_s))
        return 2 * (c * c - b * b) / (b * (b * b / (lam_s + G_s) + c * c / G_s))
    raise ValueError("variant must be 'ring' or 'shell', not %r" % (variant,))


class _ExpSum:
    """F(t) = inf + sum c_i exp(-t/T_i) for t >= 0 (t = 0 means 0+)."""

    def __init__(self, inf, coeffs, times):
        self.inf, self.coeffs, self.times = inf, tuple(coeffs), tuple(times)

    def __call__(self, t):
        if t < 0:
            return 0.0
        return self.inf + sum(c * math.exp(-t / T) for c, T in zip(self.coeffs, self.times))


class Solution:
    """Closed-form solution for one variant and parameter set.

    Attributes: K, G, tau, k (shell spring), g_roots, times (T_1 < T_2, physical
    time), rates_tau (tau/T_i, i.e. rates per unit of tau), and the exp sums
    A, B, C, D, Z (see the module docstring)."""

    def __init__(self, variant="ring", **params):
        q = _params(params)
        self.variant, self.params = variant, q
        a, b, p = q["a"], q["b"], q["p"]
        self.a, self.b, self.h, self.p = a, b, q["h"], p
        self.K = q["E"] / (3 * (1 - 2 * q["nu"]))
        self.G = q["E"] / (2 * (1 + q["nu"]))
        self.tau = q["eta"] / self.G
        self.k = k = shell_spring(variant, b, q["h"], q["E_s"], q["nu_s"])
        K, G = self.K, self.G
        c1 = 1 / a ** 2 - 1 / b ** 2
        Q2, Q1, Q0 = 4 * c1 / 3, 4 * K * c1 + 2 * k / (3 * b) + 2 * k * b / a ** 2, 2 * K * k / b
        self.Q = (Q0, Q1, Q2)
        disc = Q1 * Q1 - 4 * Q2 * Q0
        if disc <= 0:
            raise ValueError("double or complex poles; not expected for a Maxwell body")
        w = -0.5 * (Q1 + math.sqrt(disc))               # stable quadratic roots
        g_roots = sorted((w / Q2, Q0 / w))              # most negative first
        self.g_roots = tuple(g_roots)
        # s_i = g_i/(tau (G - g_i)) < 0;  T_i = -1/s_i
        self.times = tuple(self.tau * (G - g) / (-g) for g in g_roots)
        self.rates_tau = tuple(self.tau / T for T in self.times)
        Delta = lambda g: Q0 + Q1 * g + Q2 * g * g
        dDelta = lambda g: Q1 + 2 * Q2 * g
        M = lambda g: 2 * K + 2 * g / 3
        N_A = lambda g: -(p / b) * (k - 2 * g / b)
        N_B = lambda g: p * (2 * K + k * b + 2 * g / 3)
        numer = dict(A=N_A, B=N_B,
                     C=lambda g: M(g) * N_A(g),
                     D=lambda g: 2 * g * N_B(g),
                     Z=lambda g: 2 * (K - 2 * g / 3) * N_A(g))
        self.numerators, self.Delta = numer, Delta
        for name, N in numer.items():
            inf = N(0.0) / Delta(0.0)
            cs = [N(g) / (dDelta(g) * g * (1 - g / G)) for g in g_roots]
            setattr(self, name, _ExpSum(inf, cs, self.times))

    # --- thesis-form functions -------------------------------------------
    def f(self, t):
        """f(t) = -C(t)/p."""
        return -self.C(t) / self.p

    def g(self, t):
        """g(t) = D(t)/(p b^2)."""
        return self.D(t) / (self.p * self.b ** 2)

    def contact_pressure(self, t):
        """q(t) = -sigma_r(b, t), the pressure on the shell / ring."""
        return -(self.C(t) - self.D(t) / self.b ** 2)

    def stresses(self, r, t):
        """(sigma_r, sigma_theta, sigma_zz, u_r) at radius r, time t."""
        a, b = self.a, self.b
        eps = 1e-12 * b
        if a - eps <= r <= b + eps:
            C, D = self.C(t), self.D(t)
            return (C - D / r ** 2, C + D / r ** 2, self.Z(t), self.A(t) * r + self.B(t) / r)
        c = b + self.h
        if self.variant == "shell" and b < r <= c + eps:
            q = self.params
            E_s, nu_s = q["E_s"], q["nu_s"]
            L = self.contact_pressure(t) * b * b / (c * c - b * b)
            return (L * (1 - c * c / r ** 2), L * (1 + c * c / r ** 2), 2 * nu_s * L,
                    L * ((1 + nu_s) * (1 - 2 * nu_s) * r + (1 + nu_s) * c * c / r) / E_s)
        raise ValueError("r = %g outside the model (%s variant)" % (r, self.variant))

    def coefficients(self):
        """{'f': (inf, c1, c2), 'g': ..., 'A': ..., ...} with rates tau/T_i."""
        out = {}
        for name in "ABCDZ":
            F = getattr(self, name)
            out[name] = (F.inf,) + F.coeffs
        out["f"] = tuple(-x / self.p for x in out["C"])
        out["g"] = tuple(x / (self.p * self.b ** 2) for x in out["D"])
        return out


@lru_cache(maxsize=None)
def _solution(variant, items):
    return Solution(variant, **dict(items))


def solution(variant="ring", **params):
    """Cached Solution object."""
    return _solution(variant, tuple(sorted(params.items())))


def stresses(r, t, variant="ring", **params):
    """Exact (sigma_r, sigma_theta, sigma_zz, u_r) at radius r and time t
    (t >= 0; t = 0 is 0+, the instantaneous elastic response; t < 0 gives 0).
    variant: "ring" (spring at r = b) or "shell" (elastic annulus b..b+h; r may
    lie in the shell).  Parameters override DEFAULTS (a, b, h, E, nu, eta, E_s,
    nu_s, p).  Compressive stresses are negative."""
    return solution(variant, **params).stresses(r, t)


def relaxation_times(variant="ring", **params):
    """(T_1, T_2), T_1 < T_2: the relaxation times of the composite in physical
    time units (the thesis's rates are tau/T_i with tau = eta/G)."""
    return solution(variant, **params).times


def exact_f_g(t, variant="ring", **params):
    """Exact (f(t), g(t)) in the thesis form sigma_r = -p (f + (b/r)^2 g)."""
    s = solution(variant, **params)
    return s.f(t), s.g(t)


def thesis_f_g(t, tau=None, as_printed=False):
    """The thesis's f(t), g(t) (§4.5.2) at physical time t, the thesis's time
    being t/tau (tau = eta/G of the default parameters unless given).
    as_printed=True uses the garbled sign of the 0.1583 term."""
    if tau is None:
        tau = solution("ring").tau
    if t < 0:
        return 0.0, 0.0
    x = t / tau
    e = [1.0] + [math.exp(-rt * x) for rt in THESIS_RATES]
    G = THESIS_G_PRINTED if as_printed else THESIS_G
    return sum(c * v for c, v in zip(THESIS_F, e)), sum(c * v for c, v in zip(G, e))


def thesis_stresses(r, t, p=DEFAULTS["p"], b=DEFAULTS["b"], tau=None, as_printed=False):
    """The thesis's analytic curves: (sigma_r, sigma_theta) =
    (-p (f + (b/r)^2 g), -p (f - (b/r)^2 g)); see thesis_f_g for t."""
    f, g = thesis_f_g(t, tau, as_printed)
    x = (b / r) ** 2
    return -p * (f + x * g), -p * (f - x * g)


# ---------------------------------------------------------------------------
# Independent checks
# ---------------------------------------------------------------------------
def elastic_composite(r, variant="ring", **params):
    """Check 1: the elastic Lame composite with the instantaneous moduli, in the
    textbook (E, nu) form sigma_r = P - R/r^2, sigma_theta = P + R/r^2,
    sigma_zz = 2 nu P, u = (1+nu)/E ((1-2nu) P r + R/r) in each layer; the shell
    is resolved as its own layer (4 x 4 system), the ring as
    sigma_r(b) = -E_s h u(b)/((1-nu_s^2) b^2).  Returns (s_r, s_t, s_zz, u)."""
    q = _params(params)
    a, b, h, p, E, nu, Es, nus = (q[x] for x in ("a", "b", "h", "p", "E", "nu", "E_s", "nu_s"))
    ub = lambda E_, nu_, r_: ((1 + nu_) * (1 - 2 * nu_) * r_ / E_, (1 + nu_) / (E_ * r_))
    if variant == "ring":
        kr = Es * h / ((1 - nus ** 2) * b * b)
        uP, uR = ub(E, nu, b)
        P, R = solve_dense([[1, -1 / a ** 2], [1 + kr * uP, -1 / b ** 2 + kr * uR]], [-p, 0])
        layer = (P, R, E, nu)
        if r > b * (1 + 1e-12):
            raise ValueError("r outside the body")
    else:
        c = b + h
        uP, uR = ub(E, nu, b)
        vP, vR = ub(Es, nus, b)
        P, R, Ps, Rs = solve_dense([[1, -1 / a ** 2, 0, 0],
                               [1, -1 / b ** 2, -1, 1 / b ** 2],
                               [uP, uR, -vP, -vR],
                               [0, 0, 1, -1 / c ** 2]], [-p, 0, 0, 0])
        layer = (P, R, E, nu) if r <= b * (1 + 1e-12) else (Ps, Rs, Es, nus)
    P, R, E_, nu_ = layer
    uP, uR = ub(E_, nu_, r)
    return P - R / r ** 2, P + R / r ** 2, 2 * nu_ * P, uP * P + uR * R


def long_time_limit(r, variant="ring", **params):
    """Check 2: t -> infinity (G* -> 0, K kept).  The body carries only the
    pressure: sigma_r = sigma_theta = sigma_zz = -p, so 2 K A = -p; the shell
    (ring spring, or the annulus solved on its own under inner pressure p)
    fixes u(b), and B = b (u(b) - A b).  Returns (s_r, s_t, s_zz, u) in the body."""
    q = _params(params)
    a, b, h, p, E, nu, Es, nus = (q[x] for x in ("a", "b", "h", "p", "E", "nu", "E_s", "nu_s"))
    K = E / (3 * (1 - 2 * nu))
    if variant == "ring":
        u_b = p * (1 - nus ** 2) * b * b / (Es * h)
    else:
        c = b + h
        P, R = solve_dense([[1, -1 / b ** 2], [1, -1 / c ** 2]], [-p, 0])
        u_b = (1 + nus) / Es * ((1 - 2 * nus) * P * b + R / b)
    A = -p / (2 * K)
    B = b * (u_b - A * b)
    return -p, -p, -p, A * r + B / r


def integrate_ode(t_out, variant="ring", dt=1e-3, richardson=True, **params):
    """Check 3: direct time integration, independent of the Laplace transform.

    The deviatoric creep strain has the Lame form
        eps_c = P(t) (1, 1, -2)/3 + Q(t)/r^2 (-1, 1, 0)        (r, theta, z)
    (the total deviatoric strain is A (1,1,-2)/3 + B/r^2 (-1,1,0)), so the
    stress sigma = 2 K A I + 2 G [(A-P)(1,1,-2)/3 + (B-Q)/r^2 (-1,1,0)] satisfies
    equilibrium identically and the Maxwell law de_c/dt = s/(2 eta) reads
        dP/dt = (A - P)/tau,   dQ/dt = (B - Q)/tau,   P(0) = Q(0) = 0,
    with A, B (and, for the shell, the annulus constants, resolved explicitly)
    given at each time by the boundary conditions (a linear solve).  Implicit
    trapezoidal rule (the linear step is one 2 x 2 solve), optionally
    Richardson-extrapolated with dt/2 (fourth order).
    Returns a list of (t, C, D, Z, A, B) at the requested times t_out."""
    q = _params(params)
    a, b, h, p, E, nu, eta, Es, nus = (q[x] for x in ("a", "b", "h", "p", "E", "nu", "eta", "E_s", "nu_s"))
    K, G = E / (3 * (1 - 2 * nu)), E / (2 * (1 + nu))
    tau = eta / G
    c = b + h
    lam_s, G_s = Es * nus / ((1 + nus) * (1 - 2 * nus)), Es / (2 * (1 + nus))

    def AB(P, Q):
        # sigma_r(r) = 2KA + (2G/3)(A - P) - 2G (B - Q)/r^2
        row_a = [2 * K + 2 * G / 3, -2 * G / a ** 2]
        rhs_a = -p + 2 * G / 3 * P - 2 * G * Q / a ** 2
        row_b = [2 * K + 2 * G / 3, -2 * G / b ** 2]
        rhs_b = 2 * G / 3 * P - 2 * G * Q / b ** 2
        if variant == "ring":
            kr = Es * h / ((1 - nus ** 2) * b * b)
            A, B = solve_dense([row_a, [row_b[0] + kr * b, row_b[1] + kr / b]], [rhs_a, rhs_b])
            return A, B
        # unknowns A, B, As, Bs: sigma_r continuous and u continuous at b,
        # sigma_r(c) = 0 in the elastic annulus
        A, B, As, Bs = solve_dense([row_a + [0, 0],
                               row_b + [-2 * (lam_s + G_s), 2 * G_s / b ** 2],
                               [b, 1 / b, -b, -1 / b],
                               [0, 0, 2 * (lam_s + G_s), -2 * G_s / c ** 2]],
                              [rhs_a, rhs_b, 0, 0])
        return A, B

    # A, B are affine in (P, Q): A = A0 + J00 P + J01 Q, ...
    A0, B0 = AB(0.0, 0.0)
    A1, B1 = AB(1.0, 0.0)
    A2, B2 = AB(0.0, 1.0)
    J = [[A1 - A0, A2 - A0], [B1 - B0, B2 - B0]]

    def fields(P, Q):
        A, B = A0 + J[0][0] * P + J[0][1] * Q, B0 + J[1][0] * P + J[1][1] * Q
        C = 2 * K * A + 2 * G / 3 * (A - P)
        D = 2 * G * (B - Q)
        Z = 2 * K * A - 4 * G / 3 * (A - P)
        return C, D, Z, A, B

    def run(step):
        # y' = (L y + m)/tau, L = J - I, m = (A0, B0)
        L = [[J[0][0] - 1, J[0][1]], [J[1][0], J[1][1] - 1]]
        w = step / (2 * tau)
        Mi = [[1 - w * L[0][0], -w * L[0][1]], [-w * L[1][0], 1 - w * L[1][1]]]
        det = Mi[0][0] * Mi[1][1] - Mi[0][1] * Mi[1][0]
        P = Q = 0.0
        t = 0.0
        res = []
        for target in t_out:
            n = int(round((target - t) / step))
            for _ in range(n):
                rP = P + w * (L[0][0] * P + L[0][1] * Q + 2 * A0)
                rQ = Q + w * (L[1][0] * P + L[1][1] * Q + 2 * B0)
                P, Q = ((Mi[1][1] * rP - Mi[0][1] * rQ) / det,
                        (-Mi[1][0] * rP + Mi[0][0] * rQ) / det)
            t += n * step
            if abs(t - target) > 1e-9 * max(1.0, target):
                raise ValueError("output times must be multiples of dt")
            res.append((P, Q))
        return res

    y1 = run(dt)
    if richardson:
        y2 = run(dt / 2)
        ys = [((4 * P2 - P1) / 3, (4 * Q2 - Q1) / 3) for (P1, Q1), (P2, Q2) in zip(y1, y2)]
    else:
        ys = y1
    return [(t,) + fields(P, Q) for t, (P, Q) in zip(t_out, ys)]


RADII = (2.0, 2.5, 3.0, 3.5, 4.0)
TIMES = (0.0, 0.5, 1.0, 2.0, 5.0, 10.0)


def self_check(verbose=True):
    """Runs the three verifications and the thesis comparison; returns a dict
    of the maximum errors (stresses relative to p, u relative to max |u|)."""
    out = {}
    say = print if verbose else (lambda *x, **y: None)
    p = DEFAULTS["p"]
    for v in VARIANTS:
        s = solution(v)
        say("variant %-5s: k = %.6f, K = %.4f, G = %.4f, tau = eta/G = %.6f" % (v, s.k, s.K, s.G, s.tau))
        say("   relaxation times T_i = %.8f, %.8f; rates tau/T_i = %.7f, %.7f"
            % (s.times + s.rates_tau))
        co = s.coefficients()
        say("   f = %.7f %+.7f e^(-%.7f t/tau) %+.7f e^(-%.7f t/tau)"
            % (co["f"][0], co["f"][1], s.rates_tau[0], co["f"][2], s.rates_tau[1]))
        say("   g = %.7f %+.7f e^(-%.7f t/tau) %+.7f e^(-%.7f t/tau)"
            % (co["g"][0], co["g"][1], s.rates_tau[0], co["g"][2], s.rates_tau[1]))
        rs = list(RADII) + ([4.0 + 0.5 * DEFAULTS["h"], 4.0 + DEFAULTS["h"]] if v == "shell" else [])
        u_scale = max(abs(s.stresses(r, 0.0)[3]) for r in rs)
        # 1. t = 0+
        e1 = 0.0
        for r in rs:
            x, y = s.stresses(r, 0.0), elastic_composite(r, v)
            e1 = max(e1, max(abs(x[i] - y[i]) / p for i in range(3)), abs(x[3] - y[3]) / u_scale)
        # 2. t -> infinity (evaluate the closed form at t = 1e3 tau)
        e2 = 0.0
        for r in RADII:
            x, y = s.stresses(r, 1e3 * s.tau), long_time_limit(r, v)
            e2 = max(e2, max(abs(x[i] - y[i]) / p for i in range(3)), abs(x[3] - y[3]) / u_scale)
        # 3. time integration
        t_out = [0.0, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0]
        e3 = 0.0
        for (t, C, D, Z, A, B) in integrate_ode(t_out, v, dt=2e-3):
            for r in RADII:
                x = s.stresses(r, t)
                y = (C - D / r ** 2, C + D / r ** 2, Z, A * r + B / r)
                e3 = max(e3, max(abs(x[i] - y[i]) / p for i in range(3)), abs(x[3] - y[3]) / u_scale)
        say("   check 1 (t = 0+ vs elastic composite):      max rel. error %.2e" % e1)
        say("   check 2 (t -> inf vs G -> 0 limit):         max rel. error %.2e" % e2)
        say("   check 3 (vs implicit time integration):     max rel. error %.2e" % e3)
        out[v] = (e1, e2, e3)
    # thesis reading: ring with nu = 1/3
    s3 = solution("ring", nu=1.0 / 3.0)
    co = s3.coefficients()
    say("ring, nu = 1/3 (tau = %.6f): rates %.6f %.6f; f: %.6f %.6f; g: %.6f %.6f"
        % (s3.tau, s3.rates_tau[0], s3.rates_tau[1], co["f"][1], co["f"][2], co["g"][1], co["g"][2]))
    say("thesis:                              rates %.4f %.4f; f: %.6f %.4f; g: %.6f %.4f"
        % (THESIS_RATES + THESIS_F[1:] + THESIS_G[1:]))
    # table
    say()
    say("sigma_r/p and sigma_theta/p: exact ring | exact shell | thesis (t in units of tau)")
    say("%5s %5s | %9s %9s %9s | %9s %9s %9s" % ("r", "t", "sr ring", "sr shell", "sr thes",
                                                 "st ring", "st shell", "st thes"))
    tau = solution("ring").tau
    for r in RADII:
        for tt in TIMES:
            t = tt * tau
            x, y, z = stresses(r, t, "ring"), stresses(r, t, "shell"), thesis_stresses(r, t)
            say("%5.2f %5.1f | %9.5f %9.5f %9.5f | %9.5f %9.5f %9.5f"
                % (r, tt, x[0] / p, y[0] / p, z[0] / p, x[1] / p, y[1] / p, z[1] / p))
    # max differences over t in [0, 10] tau
    say()
    grid = [i * 0.01 for i in range(1001)]
    cases = [("ring  nu=0.3333", "ring", {}), ("shell nu=0.3333", "shell", {}),
             ("ring  nu=1/3   ", "ring", {"nu": 1.0 / 3.0}), ("shell nu=1/3   ", "shell", {"nu": 1.0 / 3.0})]
    for label, v, kw in cases:
        sol = solution(v, **kw)
        dr = dt_ = 0.0
        for r in RADII:
            for tt in grid:
                x = sol.stresses(r, tt * sol.tau)
                z = thesis_stresses(r, tt, tau=1.0)
                dr, dt_ = max(dr, abs(x[0] - z[0]) / p), max(dt_, abs(x[1] - z[1]) / p)
        say("max |exact - thesis|/p, t in [0, 10] tau, r = 2..4, %s: sigma_r %.2e  sigma_theta %.2e"
            % (label, dr, dt_))
        out["thesis " + label.strip()] = (dr, dt_)
    dr = dt_ = 0.0
    for r in RADII:
        for tt in grid:
            x, y = stresses(r, tt * tau, "ring"), stresses(r, tt * tau, "shell")
            dr, dt_ = max(dr, abs(x[0] - y[0]) / p), max(dt_, abs(x[1] - y[1]) / p)
    say("max |ring - shell|/p, same grid: sigma_r %.2e  sigma_theta %.2e" % (dr, dt_))
    out["ring-shell"] = (dr, dt_)
    return out


if __name__ == "__main__":
    import sys
    res = self_check()
    ok = all(max(res[v]) < 1e-8 for v in VARIANTS)
    print("self-check %s (closed form vs checks 1-3 below 1e-8)" % ("PASSED" if ok else "FAILED"))
    sys.exit(0 if ok else 1)
