#ifndef lithostress_loads_gravity_h
#define lithostress_loads_gravity_h

#include <lithostress/loads/load.h>

namespace lithostress
{
  /**
   * Gravity: the body force −ρ g ŷ of every material (thesis §3.7.1),
   * weak form ∫ −ρ g v_y dx.
   */
  template <int dim>
  class Gravity : public Load<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm, ParameterHandler *first_pass);
    /** Returns whether gravity is switched on. */
    bool
    parse_parameters(ParameterHandler            &prm,
                     const ModelDescription<dim> &model) override;

    bool
    is_body_force() const override
    {
      return true;
    }

    void
    add_cell_terms(const FEValues<dim>              &fe_values,
                   const FEValuesExtractors::Vector &displacement,
                   const Material                   &material,
                   const ElasticModuli<dim>         &moduli,
                   FullMatrix<double>               &cell_matrix,
                   Vector<double>                   &cell_rhs) const override;

    std::string
    description() const override;

    /** g [m s⁻²]. */
    double acceleration = 9.81;
  };
} // namespace lithostress

#endif
