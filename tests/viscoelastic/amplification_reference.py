"""Exact stress history of prm/stress_amplification.prm (Kusznir & Bott
1977): an elastic layer (thickness h_e) over a Maxwell layer (h_v), plane
strain, pushed by a rigid edge with a constant force F per unit length,
free top, free-slip base, no gravity.

Away from nothing: the solution is laterally uniform. Each layer has a
uniform strain (eps_x shared by both, eps_z = 0 in plane strain) and
sigma_y = 0 (a free top and no body force). The elastic layer carries
sigma_x = E'_e eps_x with E' = E/(1 - nu^2). In the Maxwell layer, with
m = (sigma_x + sigma_z)/3 and the deviator s, the elastic volume change
eps_x + eps_y = m/K and the deviatoric law de/dt = ds/dt/(2G) + s/(2 eta)
for the x and z rows give, with the force balance
h_e E'_e eps_x + h_v sigma_x = -F (so d eps_x/dt = -c d sigma_x/dt,
c = h_v/(h_e E'_e)), a linear system A dy/dt = B y for y = (sigma_x,
sigma_z) of the Maxwell layer. Its solution is the sum of two decaying
exponentials (the eigenpairs of A^-1 B, found here in closed form); the
initial value is the elastic solution of both layers.
"""
import math


def model(E_e=0.85e11, nu_e=0.25, h_e=30e3, E_v=1.9e11, nu_v=0.25, eta=1e23, h_v=70e3,
          F=3e12):
    """The constants of the .prm, in SI."""
    return dict(E_e=E_e, nu_e=nu_e, h_e=h_e, E_v=E_v, nu_v=nu_v, eta=eta, h_v=h_v, F=F)


def history(m):
    """A function t -> (elastic sigma_x, sigma_z; Maxwell sigma_x, sigma_z) [Pa]."""
    Ep_e = m["E_e"] / (1 - m["nu_e"] ** 2)
    Ep_v = m["E_v"] / (1 - m["nu_v"] ** 2)
    G = m["E_v"] / (2 * (1 + m["nu_v"]))
    K = m["E_v"] / (3 * (1 - 2 * m["nu_v"]))
    c = m["h_v"] / (m["h_e"] * Ep_e)
    k, g, v = 1 / (9 * K), 1 / (2 * G), 1 / (2 * m["eta"])
    # Rows x and z of A dy/dt = B y.
    A = [[-c - k - 2 * g / 3, -k + g / 3], [-k + g / 3, -k - 2 * g / 3]]
    B = [[2 * v / 3, -v / 3], [-v / 3, 2 * v / 3]]
    det = A[0][0] * A[1][1] - A[0][1] * A[1][0]
    Ainv = [[A[1][1] / det, -A[0][1] / det], [-A[1][0] / det, A[0][0] / det]]
    M = [[sum(Ainv[i][l] * B[l][j] for l in range(2)) for j in range(2)] for i in range(2)]
    # Eigenpairs of the 2 x 2 matrix M.
    tr, dt = M[0][0] + M[1][1], M[0][0] * M[1][1] - M[0][1] * M[1][0]
    disc = math.sqrt(tr * tr / 4 - dt)
    lam = (tr / 2 - disc, tr / 2 + disc)
    vec = []
    for l in lam:
        # (M - l I) v = 0: v = (M01, l - M00) unless that vanishes.
        a, b = M[0][1], l - M[0][0]
        if abs(a) + abs(b) < 1e-300:
            a, b = l - M[1][1], M[1][0]
        vec.append((a, b))
    eps0 = -m["F"] / (m["h_e"] * Ep_e + m["h_v"] * Ep_v)
    y0 = (Ep_v * eps0, m["nu_v"] * Ep_v * eps0)
    d = vec[0][0] * vec[1][1] - vec[1][0] * vec[0][1]
    c0 = (y0[0] * vec[1][1] - vec[1][0] * y0[1]) / d
    c1 = (vec[0][0] * y0[1] - y0[0] * vec[0][1]) / d

    def at(t):
        e0, e1 = math.exp(lam[0] * t), math.exp(lam[1] * t)
        sx = c0 * vec[0][0] * e0 + c1 * vec[1][0] * e1
        sz = c0 * vec[0][1] * e0 + c1 * vec[1][1] * e1
        eps = (-m["F"] - m["h_v"] * sx) / (m["h_e"] * Ep_e)
        return (Ep_e * eps, m["nu_e"] * Ep_e * eps, sx, sz)

    at.rates = lam
    return at


if __name__ == "__main__":
    h = history(model())
    print("rates [1/s]:", h.rates, " Maxwell time eta/G:", 1e23 / (1.9e11 / 2.5))
    for t_myr in (0, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2, 5):
        print(t_myr, ["%.6e" % s for s in h(t_myr * 3.15576e13)])
