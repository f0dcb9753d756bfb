#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <lithostress/base/input_error.h>
#include <lithostress/reference_solutions/analytic_solutions.h>

#include <cmath>

namespace lithostress
{
  // --------------------------------------------------- lithostatic column
  template <int dim>
  void
  LithostaticColumn<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Lithostatic column");
    prm.declare_entry("Top",
                      "0",
                      Patterns::Double(),
                      "Height y of the free top surface [length unit].");
    prm.declare_entry("Base",
                      "-10",
                      Patterns::Double(),
                      "Height y of the base, fixed vertically [length unit].");
    prm.leave_subsection();
  }

  template <int dim>
  void
  LithostaticColumn<dim>::parse_parameters(ParameterHandler      &prm,
                                           const MaterialLibrary &materials,
                                           const PlaneState       state,
                                           const double           scale)
  {
    prm.enter_subsection("Lithostatic column");
    top            = prm.get_double("Top") * scale;
    base           = prm.get_double("Base") * scale;
    const double g = this->gravity.acceleration;
    prm.leave_subsection();
    const Material          &m = materials.materials().front();
    const ElasticModuli<dim> moduli(m, state);
    rho_g         = m.density * g;
    p_modulus     = moduli.lambda_in_plane + 2 * moduli.mu;
    lateral_ratio = moduli.lambda_in_plane / p_modulus;
  }

  template <int dim>
  Tensor<1, dim>
  LithostaticColumn<dim>::displacement(const Point<dim> &p) const
  {
    const double   z = p[1] - top, H = top - base;
    Tensor<1, dim> u;
    u[1] = rho_g * (z * z - H * H) / (2 * p_modulus);
    return u;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  LithostaticColumn<dim>::stress(const Point<dim> &p) const
  {
    SymmetricTensor<2, dim> s;
    s[1][1] = rho_g * (p[1] - top);
    s[0][0] = lateral_ratio * s[1][1];
    return s;
  }

  // ------------------------------------------------------------ cantilever
  template <int dim>
  void
  TimoshenkoCantilever<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Cantilever");
    prm.declare_entry("End load",
                      "5e4",
                      Patterns::Double(),
                      "Downward end load P per unit thickness [N/m].");
    prm.declare_entry("Length",
                      "10",
                      Patterns::Double(),
                      "Beam length l [length unit].");
    prm.declare_entry("Depth",
                      "2.5",
                      Patterns::Double(),
                      "Beam depth 2c [length unit].");
    prm.leave_subsection();
  }

  template <int dim>
  void
  TimoshenkoCantilever<dim>::parse_parameters(ParameterHandler      &prm,
                                              const MaterialLibrary &materials,
                                              const PlaneState       state,
                                              const double           scale)
  {
    prm.enter_subsection("Cantilever");
    P = prm.get_double("End load");
    l = prm.get_double("Length") * scale;
    c = prm.get_double("Depth") * scale / 2;
    prm.leave_subsection();
    const Material &m = materials.materials().front();
    E                 = m.youngs_modulus;
    nu                = m.poissons_ratio;
    if (state == PlaneState::plane_strain)
      {
        E  = E / (1 - nu * nu);
        nu = nu / (1 - nu);
      }
    G = E / (2 * (1 + nu));
    I = 2 * c * c * c / 3;
  }

  template <int dim>
  Tensor<1, dim>
  TimoshenkoCantilever<dim>::displacement(const Point<dim> &p) const
  {
    const double   x = p[0], y = p[1];
    Tensor<1, dim> u;
    u[0] = P * x * x * y / (2 * E * I) + nu * P * y * y * y / (6 * E * I) -
           P * y * y * y / (6 * I * G) -
           (P * l * l / (2 * E * I) - P * c * c / (2 * I * G)) * y;
    u[1] = -(nu * P * x * y * y / (2 * E * I) + P * x * x * x / (6 * E * I) -
             P * l * l * x / (2 * E * I) + P * l * l * l / (3 * E * I));
    return u;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  TimoshenkoCantilever<dim>::stress(const Point<dim> &p) const
  {
    const double            x = p[0], y = p[1];
    SymmetricTensor<2, dim> s;
    s[0][0] = P * x * y / I;
    s[0][1] = P / (2 * I) * (c * c - y * y);
    return s;
  }

  // ------------------------------------------------------------ Lamé
  template <int dim>
  void
  LameCylinder<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Lame cylinder");
    prm.declare_entry("Internal pressure",
                      "1e3",
                      Patterns::Double(),
                      "Pressure p on r = a [Pa].");
    prm.declare_entry("Inner radius",
                      "2",
                      Patterns::Double(),
                      "a [length unit].");
    prm.declare_entry("Outer radius",
                      "4",
                      Patterns::Double(),
                      "b [length unit].");
    prm.declare_entry("Shell thickness",
                      "0",
                      Patterns::Double(0),
                      "t of the bonded outer shell (material id 1) "
                      "[length unit].");
    prm.leave_subsection();
  }

  template <int dim>
  void
  LameCylinder<dim>::parse_parameters(ParameterHandler      &prm,
                                      const MaterialLibrary &materials,
                                      const PlaneState       state,
                                      const double           scale)
  {
    prm.enter_subsection("Lame cylinder");
    const double p = prm.get_double("Internal pressure");
    a              = prm.get_double("Inner radius") * scale;
    b              = prm.get_double("Outer radius") * scale;
    t              = prm.get_double("Shell thickness") * scale;
    prm.leave_subsection();
    if (t > 0 && materials.materials().size() < 2)
      throw_input_error("Convergence study/Lame cylinder/Shell thickness",
                        "is positive but Materials/Names names no second "
                        "material for the shell");
    for (unsigned int layer = 0; layer < 2; ++layer)
      {
        const Material &material =
          materials.materials()[(layer == 1 && t > 0) ? 1 : 0];
        const ElasticModuli<dim> moduli(material, state);
        lambda[layer] = moduli.lambda_in_plane;
        mu[layer]     = moduli.mu;
      }
    // σ_rr = 2(λ+μ) A − 2μ B / r².  Unknowns (A0, B0, A1, B1).
    auto srr = [&](const unsigned int layer, const double r, double *row) {
      row[2 * layer]     = 2 * (lambda[layer] + mu[layer]);
      row[2 * layer + 1] = -2 * mu[layer] / (r * r);
    };
    FullMatrix<double> M(4, 4);
    Vector<double>     rhs(4), x(4);
    double             row[4];
    std::fill(row, row + 4, 0.0);
    srr(0, a, row);
    for (unsigned int j = 0; j < 4; ++j)
      M(0, j) = row[j];
    rhs(0) = -p;
    if (t > 0)
      {
        // u continuous at b.
        M(1, 0) = b, M(1, 1) = 1 / b, M(1, 2) = -b, M(1, 3) = -1 / b;
        // σ_rr continuous at b.
        std::fill(row, row + 4, 0.0);
        srr(0, b, row);
        double row1[4] = {0, 0, 0, 0};
        srr(1, b, row1);
        for (unsigned int j = 0; j < 4; ++j)
          M(2, j) = row[j] - row1[j];
        std::fill(row, row + 4, 0.0);
        srr(1, b + t, row);
        for (unsigned int j = 0; j < 4; ++j)
          M(3, j) = row[j];
      }
    else
      {
        std::fill(row, row + 4, 0.0);
        srr(0, b, row);
        for (unsigned int j = 0; j < 4; ++j)
          M(1, j) = row[j];
        M(2, 2) = 1;
        M(3, 3) = 1;
      }
    M.gauss_jordan();
    M.vmult(x, rhs);
    A[0] = x(0), B[0] = x(1), A[1] = x(2), B[1] = x(3);
  }

  template <int dim>
  Tensor<1, dim>
  LameCylinder<dim>::displacement(const Point<dim> &p) const
  {
    const double       r     = std::hypot(p[0], p[1]);
    const unsigned int layer = (t > 0 && r > b) ? 1 : 0;
    const double       ur    = A[layer] * r + B[layer] / r;
    Tensor<1, dim>     u;
    u[0] = ur * p[0] / r;
    u[1] = ur * p[1] / r;
    return u;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  LameCylinder<dim>::stress(const Point<dim> &p) const
  {
    const double       r     = std::hypot(p[0], p[1]);
    const unsigned int layer = (t > 0 && r > b) ? 1 : 0;
    const double       srr   = 2 * (lambda[layer] + mu[layer]) * A[layer] -
                       2 * mu[layer] * B[layer] / (r * r);
    const double stt = 2 * (lambda[layer] + mu[layer]) * A[layer] +
                       2 * mu[layer] * B[layer] / (r * r);
    const double            c = p[0] / r, s = p[1] / r;
    SymmetricTensor<2, dim> sigma;
    sigma[0][0] = srr * c * c + stt * s * s;
    sigma[1][1] = srr * s * s + stt * c * c;
    sigma[0][1] = (srr - stt) * c * s;
    return sigma;
  }

  // ------------------------------------------------------------ Williams
  template <int dim>
  void
  WilliamsCornerSolution<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Williams corner");
    prm.declare_entry("Amplitude",
                      "1e6",
                      Patterns::Double(),
                      "Stress intensity A of the mode-I eigen-solution "
                      "[Pa m^(1-lambda)].");
    prm.leave_subsection();
  }

  template <int dim>
  void
  WilliamsCornerSolution<dim>::parse_parameters(
    ParameterHandler      &prm,
    const MaterialLibrary &materials,
    const PlaneState       state,
    const double)
  {
    prm.enter_subsection("Williams corner");
    amplitude = prm.get_double("Amplitude");
    prm.leave_subsection();
    omega = 3 * numbers::PI / 4;
    // Smallest positive root of sin(2λω) + λ sin(2ω) = 0 in (0.5, 0.6).
    double lo = 0.5, hi = 0.6;
    auto   f = [&](const double l) {
      return std::sin(2 * l * omega) + l * std::sin(2 * omega);
    };
    for (unsigned int i = 0; i < 200; ++i)
      {
        const double mid = 0.5 * (lo + hi);
        if (f(lo) * f(mid) <= 0)
          hi = mid;
        else
          lo = mid;
      }
    lambda = 0.5 * (lo + hi);
    Q      = -std::cos((lambda - 1) * omega) / std::cos((lambda + 1) * omega);
    const Material &m = materials.materials().front();
    G                 = m.shear_modulus();
    kappa             = (state == PlaneState::plane_strain)
                          ? 3 - 4 * m.poissons_ratio
                          : (3 - m.poissons_ratio) / (1 + m.poissons_ratio);
  }

  template <int dim>
  void
  WilliamsCornerSolution<dim>::local_coordinates(const Point<dim> &p,
                                                 double           &r,
                                                 double           &theta) const
  {
    r = std::hypot(p[0], p[1]);
    // Angle from the bisector of the material wedge (direction 225°).
    theta = std::atan2(p[1], p[0]) - 1.25 * numbers::PI;
    while (theta < -numbers::PI)
      theta += 2 * numbers::PI;
    while (theta > numbers::PI)
      theta -= 2 * numbers::PI;
  }

  template <int dim>
  Tensor<1, dim>
  WilliamsCornerSolution<dim>::displacement(const Point<dim> &p) const
  {
    double r, th;
    local_coordinates(p, r, th);
    const double l  = lambda;
    const double f  = amplitude * std::pow(r, l) / (2 * G);
    const double ux = f * ((kappa - Q * (l + 1)) * std::cos(l * th) -
                           l * std::cos((l - 2) * th));
    const double uy = f * ((kappa + Q * (l + 1)) * std::sin(l * th) +
                           l * std::sin((l - 2) * th));
    // Rotate from the bisector frame (e1 at 225°) to x, y.
    const double c = std::cos(1.25 * numbers::PI),
                 s = std::sin(1.25 * numbers::PI);
    Tensor<1, dim> u;
    u[0] = c * ux - s * uy;
    u[1] = s * ux + c * uy;
    return u;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  WilliamsCornerSolution<dim>::stress(const Point<dim> &p) const
  {
    double r, th;
    local_coordinates(p, r, th);
    const double   l   = lambda;
    const double   f   = amplitude * l * std::pow(r, l - 1);
    const double   sx  = f * ((2 - Q * (l + 1)) * std::cos((l - 1) * th) -
                           (l - 1) * std::cos((l - 3) * th));
    const double   sy  = f * ((2 + Q * (l + 1)) * std::cos((l - 1) * th) +
                           (l - 1) * std::cos((l - 3) * th));
    const double   txy = f * ((l - 1) * std::sin((l - 3) * th) +
                            Q * (l + 1) * std::sin((l - 1) * th));
    Tensor<2, dim> local, R;
    local[0][0] = sx, local[1][1] = sy, local[0][1] = local[1][0] = txy;
    const double c = std::cos(1.25 * numbers::PI),
                 s = std::sin(1.25 * numbers::PI);
    R[0][0] = c, R[0][1] = -s, R[1][0] = s, R[1][1] = c;
    return symmetrize(Tensor<2, dim>(R * local * transpose(R)));
  }

  // ------------------------------------------------------------ selector
  template <int dim>
  void
  ReferenceSolutionSelector<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Reference solution",
                      "none",
                      Patterns::Selection("none|lithostatic column|cantilever|"
                                          "Lame cylinder|Williams corner"),
                      "An exact solution to measure errors against; `none` "
                      "reports functionals and their change between cycles.");
    LithostaticColumn<dim>::declare_parameters(prm);
    TimoshenkoCantilever<dim>::declare_parameters(prm);
    LameCylinder<dim>::declare_parameters(prm);
    WilliamsCornerSolution<dim>::declare_parameters(prm);
  }

  template <int dim>
  std::unique_ptr<ReferenceSolution<dim>>
  ReferenceSolutionSelector<dim>::create(ParameterHandler      &prm,
                                         const MaterialLibrary &materials,
                                         const PlaneState       state,
                                         const double           scale,
                                         const GravityField    &gravity)
  {
    const std::string name = prm.get("Reference solution");
    std::unique_ptr<ReferenceSolution<dim>> solution;
    if (name == "lithostatic column")
      solution = std::make_unique<LithostaticColumn<dim>>();
    else if (name == "cantilever")
      solution = std::make_unique<TimoshenkoCantilever<dim>>();
    else if (name == "Lame cylinder")
      solution = std::make_unique<LameCylinder<dim>>();
    else if (name == "Williams corner")
      solution = std::make_unique<WilliamsCornerSolution<dim>>();
    else
      return solution;
    solution->gravity = gravity;
    solution->parse_parameters(prm, materials, state, scale);
    return solution;
  }

  template <int dim>
  ReferenceDisplacement<dim>::ReferenceDisplacement(
    const ReferenceSolution<dim> &solution,
    const unsigned int            n_fields)
      : Function<dim>(dim * n_fields)
      , solution(solution)
  {
  }

  template <int dim>
  double
  ReferenceDisplacement<dim>::value(const Point<dim>  &p,
                                    const unsigned int component) const
  {
    return solution.displacement(p)[component % dim];
  }

  template <int dim>
  void
  ReferenceDisplacement<dim>::vector_value(const Point<dim> &p,
                                           Vector<double>   &values) const
  {
    const Tensor<1, dim> u = solution.displacement(p);
    for (unsigned int c = 0; c < values.size(); ++c)
      values[c] = u[c % dim];
  }

  template class LithostaticColumn<2>;
  template class TimoshenkoCantilever<2>;
  template class LameCylinder<2>;
  template class WilliamsCornerSolution<2>;
  template class ReferenceSolutionSelector<2>;
  template class ReferenceDisplacement<2>;
} // namespace lithostress
