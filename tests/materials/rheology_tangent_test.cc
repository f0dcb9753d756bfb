/**
 * The consistent tangent of the visco-elasto-plastic law
 * (ViscoElastoPlasticRheology::evaluate, doc/equations.md §12–13) against
 * central finite differences of its stress, on one point of a time step
 * (Δt = 1 kyr, backward Euler, T = 1 100 K, a reference pressure of 1 GPa
 * added), for five states:
 * 1. dislocation creep with an activation volume (V = 18e-6 m³/mol): the
 *    creep rate's pressure derivative enters the tangent, which then lacks
 *    the major symmetry (symmetric_tangent() is false);
 * 2. the same law without V: major-symmetric, symmetric_tangent() true;
 * 3. creep with V and Drucker–Prager yield (φ = 30°, C = 1 MPa, ψ = 0; no
 *    reference pressure, so that the rock yields);
 * 4. the same with dilation (ψ = 10°: the pressure moves with the plastic
 *    increment);
 * 5. creep with V held by a Maximum viscosity (the bound removes the
 *    pressure term: the tangent is major-symmetric there, though the law
 *    cannot say so in advance).
 * For each the tangent applied to four strain directions (the three
 * components and a mixed one) equals (σ(ε + h d) − σ(ε − h d))/(2h) with
 * h = 1e-7 |ε| to 1e-6 of |C d| (the difference's truncation is O(h²) of
 * the stress's curvature, its round-off 1e-16 |σ|/h ≈ 1e-8 of |C d|; the
 * term of case 1 is 1e-2 of the tangent, so a tangent without it fails).
 * Prints "FAILED" and exits 1 on any failure.
 */
#include <deal.II/base/parameter_handler.h>

#include <lithostress/materials/creep_strain.h>
#include <lithostress/materials/material.h>
#include <lithostress/materials/visco_elasto_plastic_rheology.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace dealii;
using namespace lithostress;

namespace
{
  bool failed = false;

  void
  check(const bool ok, const std::string &what)
  {
    std::cout << (ok ? "ok   " : "FAILED ") << what << std::endl;
    failed = failed || !ok;
  }

  struct Case
  {
    std::string                                      label;
    std::vector<std::pair<std::string, std::string>> entries;
    bool                                             yielding;
    /** symmetric_tangent(), and whether the tangent has the major symmetry
     * at this state. */
    bool   symmetric, major_symmetric;
    double reference_pressure;
  };

  /** The law of @p c on a rock with E = 70 GPa, ν = 0.25. */
  ViscoElastoPlasticRheology<2>
  law(const Case &c)
  {
    ParameterHandler prm;
    ViscoElastoPlasticRheology<2>::declare_parameters(prm);
    prm.set("Dislocation creep prefactor", "1.1e-16");
    prm.set("Dislocation creep stress exponent", "3.5");
    prm.set("Dislocation creep activation energy", "530e3");
    for (const auto &[entry, value] : c.entries)
      prm.set(entry, value);
    Material material{
      "rock", 0, 7e10, 0.25, 3300, 0, 0, "visco-elasto-plastic"};
    ViscoElastoPlasticRheology<2> result;
    result.parse_parameters(prm, material, PlaneState::plane_strain);
    return result;
  }

  /** The stress (in plane) of @p rheology at the strain @p strain. */
  SymmetricTensor<2, 2>
  stress(const ViscoElastoPlasticRheology<2> &rheology,
         const SymmetricTensor<2, 2>         &strain,
         const double                         reference_pressure,
         RheologyOutputs<2>                  &out)
  {
    const std::vector<double> history(rheology.history_names().size(), 0.);
    RheologyInputs<2>         in;
    in.strain      = strain;
    in.time_step   = 3.15576e10;
    in.weight      = 1;
    in.temperature = 1100;
    in.pressure    = reference_pressure;
    in.history     = make_array_view(history);
    rheology.evaluate(in, out);
    return out.stress.in_plane;
  }

  void
  check_case(const Case &c)
  {
    const ViscoElastoPlasticRheology<2> rheology = law(c);
    SymmetricTensor<2, 2>               strain;
    strain[0][0] = -2.2e-3;
    strain[1][1] = 0.6e-3;
    strain[0][1] = 0.5e-3;
    RheologyOutputs<2> out;
    stress(rheology, strain, c.reference_pressure, out);
    const SymmetricTensor<4, 2>        tangent  = out.tangent;
    const bool                         yielding = out.yielding;
    std::vector<SymmetricTensor<2, 2>> directions(4);
    directions[0][0][0] = 1;
    directions[1][1][1] = 1;
    directions[2][0][1] = 1;
    directions[3][0][0] = 0.3;
    directions[3][1][1] = -0.7;
    directions[3][0][1] = 0.4;
    const double h      = 1e-7 * strain.norm();
    double       worst  = 0;
    for (const SymmetricTensor<2, 2> &d : directions)
      {
        RheologyOutputs<2>          plus, minus;
        const SymmetricTensor<2, 2> difference =
          (stress(rheology, strain + h * d, c.reference_pressure, plus) -
           stress(rheology, strain - h * d, c.reference_pressure, minus)) /
          (2 * h);
        const SymmetricTensor<2, 2> applied = tangent * d;
        worst = std::max(worst, (applied - difference).norm() / applied.norm());
      }
    double asymmetry = 0, size = 0;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int l = 0; l < 2; ++l)
            {
              asymmetry =
                std::max(asymmetry,
                         std::abs(tangent[i][j][k][l] - tangent[k][l][i][j]));
              size = std::max(size, std::abs(tangent[i][j][k][l]));
            }
    std::ostringstream line;
    line << std::setprecision(2) << c.label << ": yielding " << yielding
         << ", tangent = finite differences to " << worst << " (allowed 1e-6)";
    check(yielding == c.yielding && worst <= 1e-6, line.str());
    line.str("");
    line << c.label << ": symmetric_tangent() " << rheology.symmetric_tangent()
         << ", largest |C_ijkl - C_klij| / |C| = " << asymmetry / size
         << (c.major_symmetric ? " (at most 1e-12)" : " (at least 1e-4)");
    check(rheology.symmetric_tangent() == c.symmetric &&
            (c.major_symmetric ? asymmetry <= 1e-12 * size
                               : asymmetry >= 1e-4 * size),
          line.str());
  }
} // namespace

int
main()
{
  const std::pair<std::string, std::string> volume{
    "Dislocation creep activation volume", "18e-6"};
  const std::vector<std::pair<std::string, std::string>> plastic{
    {"Friction angle", "30"}, {"Cohesion", "1e6"}};
  std::vector<Case> cases;
  cases.push_back({"creep with V", {volume}, false, false, false, 1e9});
  cases.push_back({"creep without V", {}, false, true, true, 1e9});
  cases.push_back({"creep with V, yielding (psi = 0)",
                   {volume, plastic[0], plastic[1]},
                   true,
                   false,
                   false,
                   0});
  cases.push_back({"creep with V, yielding (psi = 10)",
                   {volume, plastic[0], plastic[1], {"Dilation angle", "10"}},
                   true,
                   false,
                   false,
                   0});
  cases.push_back({"creep with V at the Maximum viscosity",
                   {volume, {"Maximum viscosity", "1e20"}},
                   false,
                   false,
                   true,
                   1e9});
  for (const Case &c : cases)
    check_case(c);
  if (failed)
    {
      std::cout << "FAILED" << std::endl;
      return 1;
    }
  std::cout << "all checks passed" << std::endl;
  return 0;
}
