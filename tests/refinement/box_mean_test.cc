// Unit test of the regional stress means of Mesh refinement/Goals
// (StressGoals, doc/equations.md §6): the mean of a stress component over
// the part of the body inside a box, integrated on the cells the box cuts
// by a quadrature clipped to the box. On straight cells the clipped region
// is exact, so the mean of a stress that is linear in x and y is its value
// at the centroid of the box ∩ body polygon, to round-off. Checked on a
// sheared (parallelogram) body with hanging nodes, for a box inside the
// body, one cut by a slanted edge and one cut by two edges, on 1 or more
// ranks. Prints one "ok ..." or "FAIL ..." line per check and returns
// non-zero on a failure.

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/materials/material.h>
#include <lithostress/materials/stress_model.h>
#include <lithostress/reference_solutions/reference_solution.h>
#include <lithostress/refinement/stress_goals.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace lithostress;

namespace
{
  unsigned int n_failed = 0;

  void
  check(const bool ok, const std::string &what)
  {
    std::cout << (ok ? "ok " : "FAIL ") << what << std::endl;
    if (!ok)
      ++n_failed;
  }

  /** The body: the rectangle [0, 3] × [0, 2] sheared by x' = x + 0.3 y. */
  constexpr double shear = 0.3;

  /** A stress field linear in x and y (the displacement is not needed). */
  class LinearStress : public ReferenceSolution<2>
  {
  public:
    void
    parse_parameters(ParameterHandler &,
                     const MaterialLibrary &,
                     const PlaneState,
                     const double) override
    {
    }

    Tensor<1, 2>
    displacement(const Point<2> &) const override
    {
      return {};
    }

    SymmetricTensor<2, 2>
    stress(const Point<2> &p) const override
    {
      SymmetricTensor<2, 2> s;
      s[0][0] = 1 + 2 * p[0] + 3 * p[1];
      s[1][1] = 4 - p[0] + 0.5 * p[1];
      s[0][1] = -2 + 0.25 * p[0] - p[1];
      return s;
    }
  };

  /** The part of the convex polygon @p polygon where a x + b y ≤ c
   * (Sutherland–Hodgman, one edge). */
  std::vector<Point<2>>
  clip(const std::vector<Point<2>> &polygon,
       const double                 a,
       const double                 b,
       const double                 c)
  {
    std::vector<Point<2>> result;
    for (unsigned int i = 0; i < polygon.size(); ++i)
      {
        const Point<2> &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
        const double    fp = a * p[0] + b * p[1] - c;
        const double    fq = a * q[0] + b * q[1] - c;
        if (fp <= 0)
          result.push_back(p);
        if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0))
          result.push_back(p + (fp / (fp - fq)) * (q - p));
      }
    return result;
  }

  /** The centroid of the box [x0, x1] × [y0, y1] ∩ body. */
  Point<2>
  centroid_in_body(const double x0,
                   const double x1,
                   const double y0,
                   const double y1)
  {
    std::vector<Point<2>> p = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    p                       = clip(p, 0, -1, 0);     // y ≥ 0
    p                       = clip(p, 0, 1, 2);      // y ≤ 2
    p                       = clip(p, -1, shear, 0); // x ≥ 0.3 y
    p                       = clip(p, 1, -shear, 3); // x ≤ 3 + 0.3 y
    double   area           = 0;
    Point<2> c;
    for (unsigned int i = 0; i < p.size(); ++i)
      {
        const Point<2> &a = p[i], &b = p[(i + 1) % p.size()];
        const double    cross = a[0] * b[1] - b[0] * a[1];
        area += cross / 2;
        c[0] += (a[0] + b[0]) * cross / 6;
        c[1] += (a[1] + b[1]) * cross / 6;
      }
    return Point<2>(c[0] / area, c[1] / area);
  }

  /** A material library with one material of id 0, read from @p prm
   * (which StressModel reads the material's law from). */
  MaterialLibrary
  rock(ParameterHandler &prm)
  {
    MaterialLibrary::declare_parameters(prm, nullptr);
    prm.parse_input_from_string("subsection Materials\n"
                                "  set Names = rock\n"
                                "  subsection rock\n"
                                "    set Material id = 0\n"
                                "    set Young's modulus = 1e10\n"
                                "    set Poisson's ratio = 0.25\n"
                                "  end\n"
                                "end\n");
    MaterialLibrary materials;
    materials.parse_parameters(prm);
    materials.resolve({}, {0});
    return materials;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
  GridGenerator::subdivided_hyper_rectangle(tria,
                                            {3, 2},
                                            Point<2>(0, 0),
                                            Point<2>(3, 2));
  GridTools::transform(
    [](const Point<2> &p) { return Point<2>(p[0] + shear * p[1], p[1]); },
    tria);
  tria.refine_global(1);
  // Hanging nodes: refine the left half once more.
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned() && cell->center()[0] < 1.7)
      cell->set_refine_flag();
  tria.execute_coarsening_and_refinement();

  const FiniteElementSpace<2> fe_space(2, 1);
  DoFHandler<2>               dof_handler(tria);
  dof_handler.distribute_dofs(fe_space.fe_collection());

  ParameterHandler      material_prm;
  const MaterialLibrary materials = rock(material_prm);
  const StressModel<2>  stress_model(material_prm,
                                    materials,
                                    PlaneState::plane_strain,
                                    {});

  // name: component, x_min, x_max, y_min, y_max
  struct Box
  {
    std::string  name;
    double       x0, x1, y0, y1;
    unsigned int component; // 0 xx, 1 yy, 2 xy
  };
  const std::vector<Box> boxes = {{"inside", 1.2, 2.1, 0.4, 1.3, 0},
                                  {"slanted_edge", 2.5, 4.0, 0.2, 1.8, 1},
                                  {"corner", -1.0, 0.8, 1.0, 2.5, 2}};
  const char *component_name[] = {"sigma_xx", "sigma_yy", "sigma_xy"};
  std::string text;
  for (const Box &b : boxes)
    text += (text.empty() ? "" : "; ") + b.name + ": " +
            component_name[b.component] + ", " + std::to_string(b.x0) + ", " +
            std::to_string(b.x1) + ", " + std::to_string(b.y0) + ", " +
            std::to_string(b.y1);
  ParameterHandler prm;
  StressGoals<2>::declare_parameters(prm);
  prm.enter_subsection("Mesh refinement");
  prm.enter_subsection("Goals");
  prm.set("Stress averages", text);
  prm.leave_subsection();
  prm.leave_subsection();
  StressGoals<2> goals;
  goals.parse_parameters(prm, 1.0);
  goals.check_regions(dof_handler, fe_space);

  const LinearStress        reference;
  const std::vector<double> means =
    goals.reference_values(dof_handler, fe_space, stress_model, reference);
  for (unsigned int k = 0; k < boxes.size(); ++k)
    {
      const Box     &b     = boxes[k];
      const Point<2> c     = centroid_in_body(b.x0, b.x1, b.y0, b.y1);
      const auto     s     = reference.stress(c);
      const double   exact = b.component == 0   ? s[0][0]
                             : b.component == 1 ? s[1][1]
                                                : s[0][1];
      const double   error = std::abs(means[k] - exact);
      if (root)
        std::cout << "  " << b.name << ": mean " << means[k] << ", exact "
                  << exact << ", error " << error << std::endl;
      // Round-off of the sums over some 10^4 quadrature points (each
      // relative 1e-16): well below 1e-11 of the value.
      if (root)
        check(error <= 1e-11 * std::max(1.0, std::abs(exact)),
              "mean over box " + b.name + " is the value at the centroid");
    }
  if (root)
    std::cout << (n_failed == 0 ? "all checks passed"
                                : std::to_string(n_failed) + " check(s) failed")
              << std::endl;
  return n_failed == 0 ? 0 : 1;
}
