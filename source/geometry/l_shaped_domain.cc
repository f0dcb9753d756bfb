#include <deal.II/grid/grid_generator.h>

#include <lithostress/base/input_error.h>
#include <lithostress/geometry/l_shaped_domain.h>

namespace lithostress
{
  template <int dim>
  void
  LShapedDomain<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("L-shaped domain");
    prm.declare_entry("Half size",
                      "1",
                      Patterns::Double(),
                      "Half the side s of the square [-s, s]^2 [length unit].");
    prm.leave_subsection();
  }

  template <int dim>
  void
  LShapedDomain<dim>::parse_parameters(ParameterHandler &prm,
                                       const double      scale)
  {
    prm.enter_subsection("L-shaped domain");
    half_size = prm.get_double("Half size") * scale;
    prm.leave_subsection();
    if (!(half_size > 0))
      throw_input_error("Geometry/L-shaped domain/Half size",
                        "must be positive");
  }

  template <int dim>
  void
  LShapedDomain<dim>::create_coarse_mesh(
    parallel::distributed::Triangulation<dim> &tria) const
  {
    GridGenerator::hyper_L(tria, -half_size, half_size, false);
    const double tol = 1e-10 * half_size;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const Point<2> c        = face->center();
            const bool     on_notch = (std::abs(c[0]) < tol && c[1] > 0) ||
                                  (std::abs(c[1]) < tol && c[0] > 0);
            face->set_boundary_id(on_notch ? 1 : 0);
          }
  }

  template <int dim>
  std::map<std::string, types::boundary_id>
  LShapedDomain<dim>::boundary_parts() const
  {
    return {{"outer", 0}, {"notch", 1}};
  }

  template class LShapedDomain<2>;

  LITHOSTRESS_REGISTER_GEOMETRY(LShapedDomain,
                                "L-shaped domain",
                                "the L-shaped domain with a re-entrant corner")
} // namespace lithostress
