"""Surface displacement of a 2-D elastic half-space (plane strain, surface
y = 0, body y < 0) cut by a straight fault from the surface point (0, 0)
down to depth D, dipping at delta towards +x, with a uniform jump
u(hanging wall) - u(footwall) = b d + a n, d = (cos delta, -sin delta)
down dip, n = (sin delta, cos delta) into the hanging wall.

The fault is an edge dislocation at its tip (xi, -D), xi = D / tan delta,
whose cut runs up the fault to the surface. With the complex potentials of
the dislocation in the full plane and their image terms that free the
surface (Kolosov-Muskhelishvili), the surface displacement reduces to
  u_x + i u_y = (1/pi) [beta Theta + conj(beta) (zeta + i)/(1 + zeta^2)],
  beta = (b + i a) exp(-i delta),  zeta = (x - xi)/D,
  Theta = (pi/2) sgn(x) - atan(zeta),
which is independent of the elastic moduli; the far field decays as D/|x|
on both sides and the step at x = 0 is the jump b d + a n. Checked
independently by the reciprocity (Volterra) integral of the jump against
the Flamant solution of a surface line force, and by finite differences of
the full-plane field (equilibrium, free surface, jump), to round-off.
"""
import math


def surface_displacement(x, b, a, delta, depth):
    """(u_x, u_y) at the surface point x [same unit as depth]; at x = 0 the
    mean of the two sides."""
    xi = depth / math.tan(delta)
    zeta = (x - xi) / depth
    sign = 0.0 if x == 0 else math.copysign(1.0, x)
    theta = 0.5 * math.pi * sign - math.atan(zeta)
    beta = complex(b, a) * complex(math.cos(delta), -math.sin(delta))
    u = (beta * theta + beta.conjugate() * complex(zeta, 1.0) / (1 + zeta * zeta)) / math.pi
    return u.real, u.imag


def buried_surface_displacement(x, b, a, delta, top, bottom):
    """(u_x, u_y) at the surface point x for the same jump on the fault's
    plane between the depths top and bottom only: by superposition, the
    fault from the surface to bottom less the fault from the surface to
    top (the plane meets the surface at x = 0)."""
    deep = surface_displacement(x, b, a, delta, bottom)
    shallow = surface_displacement(x, b, a, delta, top)
    return deep[0] - shallow[0], deep[1] - shallow[1]
