#ifndef lithostress_loads_isostatic_restoring_force_h
#define lithostress_loads_isostatic_restoring_force_h

#include <lithostress/loads/load.h>

#include <vector>

namespace lithostress
{
  /**
   * The isostatic restoring force of a fluid of density ρ_f in contact with
   * a boundary part (thesis §3.7.2.3, doc/equations.md §3.4): a vertical force
   * ρ_f g u_y per unit horizontal length opposing the vertical displacement.
   * Weak form ∫ ρ_f g u_y v_y |n_y| ds — symmetric, an exact Winkler foundation
   * of stiffness ρ_f g on horizontal boundaries and the right total force on
   * sloping and curved ones. It adds a boundary term to the stiffness.
   */
  template <int dim>
  class IsostaticRestoringForce : public Load<dim>
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
      return parts.empty();
    }

    bool
    acts_on_boundary(const types::boundary_id id) const override;
    void
    add_boundary_terms(const FEFaceValues<dim>          &fe_face_values,
                       const types::boundary_id          id,
                       const FEValuesExtractors::Vector &displacement,
                       FullMatrix<double>               &cell_matrix,
                       Vector<double> &cell_rhs) const override;
    bool
    changes_stiffness() const override
    {
      return true;
    }

    /** The foundation stiffness ρ_f g [Pa/m] on part @p id (0 if none). */
    double
    stiffness(const types::boundary_id id) const;

    double
    vertical_spring_stiffness(const types::boundary_id id) const override
    {
      return stiffness(id);
    }

    bool
    stiffness_is_vertical_spring() const override
    {
      return true;
    }

    std::string
    description() const override;

  private:
    /** Read the subsection (the parts or points given). */
    void
    read_parameters(ParameterHandler &prm, const ModelDescription<dim> &model);

    std::vector<std::pair<types::boundary_id, double>> parts;
    std::vector<std::string>                           names;
  };
} // namespace lithostress

#endif
