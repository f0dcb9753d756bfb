#ifndef lithostress_temperature_steady_conduction_h
#define lithostress_temperature_steady_conduction_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/temperature/temperature_model.h>

#include <boost/signals2/connection.hpp>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace lithostress
{
  /**
   * `Temperature/Model = steady conduction`: the steady geotherm of a
   * section that conducts heat and produces it radiogenically (Turcotte &
   * Schubert 2014, §4.6–4.8), solved on the run's own mesh with its
   * mapping:
   *   −∇·(k ∇T) = H in the section,
   *   T = T_top on the `Top boundary`, T = T_base on the `Base boundary`,
   *   k ∂T/∂n = 0 on the other boundaries (no lateral heat flow),
   * with the `Thermal conductivity` k and the `Radiogenic heat production`
   * H constant in each material. Continuous Q2 elements (the degree of the
   * displacement), CG with AMG to 1e-12 of the right-hand side; the field is
   * solved again after every refinement, coarsening, repartition or load of
   * the mesh, so that the temperature is always that of the present mesh. A
   * horizontally layered section whose layer interfaces are cell faces has
   * a piecewise quadratic geotherm, which the elements hold exactly.
   */
  template <int dim>
  class SteadyConductionTemperature : public TemperatureModel<dim>
  {
  public:
    ~SteadyConductionTemperature() override;

    /** Declare the subsection `Steady conduction`. */
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm, const double length_scale) override;

    void
    values(const typename Triangulation<dim>::active_cell_iterator &cell,
           const std::vector<Point<dim>>                           &points,
           std::vector<double> &temperatures) const override;

    /** Resolve the material and boundary names, solve, and solve again on
     * every change of the mesh. */
    void
    attach_mesh(const TemperatureMesh<dim> &mesh) override;

    /** The CG iterations of the last solve. */
    unsigned int
    last_iterations() const
    {
      return iterations;
    }

  private:
    /** A per-material entry: one number for all materials or `name:
     * value, ...` naming each; the value of every material in @p mesh. */
    static std::map<types::material_id, double>
    per_material(const std::string          &text,
                 const std::string          &entry,
                 const TemperatureMesh<dim> &mesh);

    /** Assemble and solve on the present mesh (collective). */
    void
    solve();

    std::string              conductivity_text, heat_production_text;
    std::vector<std::string> top_names, base_names;
    double                   top_temperature = 0, base_temperature = 0;

    TemperatureMesh<dim>                     mesh;
    std::map<types::material_id, double>     conductivity, heat_production;
    std::set<types::boundary_id>             top_ids, base_ids;
    FE_Q<dim>                                fe{2};
    std::unique_ptr<DoFHandler<dim>>         dof_handler;
    TrilinosWrappers::MPI::Vector            temperature;
    unsigned int                             iterations = 0;
    std::vector<boost::signals2::connection> connections;
  };
} // namespace lithostress

#endif
