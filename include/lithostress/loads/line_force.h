#ifndef lithostress_loads_line_force_h
#define lithostress_loads_line_force_h

#include <lithostress/loads/load.h>
#include <lithostress/loads/time_factor.h>

#include <vector>

namespace lithostress
{
  /**
   * Line forces [N per metre out of plane] at points (thesis card 6, nodal
   * forces), applied at the mesh vertex nearest to each point. A line load
   * is a logarithmic singularity of 2-D elasticity: the displacement under
   * it grows without bound under refinement, so results are compared away
   * from it.
   */
  template <int dim>
  class LineForce : public Load<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm, ParameterHandler *first_pass);
    /** Returns whether any part or point is given. */
    bool
    parse_parameters(ParameterHandler            &prm,
                     const ModelDescription<dim> &model) override
    {
      read_parameters(prm, model);
      return !empty();
    }

    bool
    empty() const
    {
      return points.empty();
    }

    void
    add_point_terms(const DoFHandler<dim>           &dof_handler,
                    const FiniteElementSpace<dim>   &fe_space,
                    const AffineConstraints<double> &constraints,
                    TrilinosWrappers::MPI::Vector   &rhs) const override;

    void
    check_against_mesh(const Triangulation<dim> &tria,
                       const Mapping<dim>       &mapping) const override;

    std::string
    description() const override;

  private:
    /** Read the subsection (the parts or points given). */
    void
    read_parameters(ParameterHandler &prm, const ModelDescription<dim> &model);

    std::vector<Point<dim>>     points;
    std::vector<Tensor<1, dim>> forces;
    /** f(t) on all of them. */
    TimeFactor time_factor;
  };
} // namespace lithostress

#endif
