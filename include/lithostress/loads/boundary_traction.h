#ifndef lithostress_loads_boundary_traction_h
#define lithostress_loads_boundary_traction_h

#include <lithostress/base/parsed_expression.h>
#include <lithostress/loads/load.h>

#include <functional>
#include <memory>
#include <vector>

namespace lithostress
{
  /**
   * Distributed tractions on named boundary parts (thesis cards 7–8; edge
   * tension and compression §6, slab pull §7.4, basal shear §7.6.1): a normal
   * component σ_n (positive = tension, pulling outward) and a shear
   * component τ along s = (n_y, −n_x) (the outward normal turned clockwise),
   * each a function of position, or the traction σ_exact·n of the reference
   * solution. Weak form ∫ (σ_n n + τ s)·v ds.
   *
   * A traction can instead be set by force, as the thesis sets slab pull
   * (§7.4): a resultant F [N/m] spread over the part by a profile w(x, y) ≥ 0,
   * t = F w / ∫ w ds, so that ∫ t ds = F exactly (the integral is taken
   * with the assembly's quadrature and mapping on every new mesh).
   */
  template <int dim>
  class BoundaryTraction : public Load<dim>
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

    /** Whether any traction is given. */
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

    /** Integrate the resultant profiles over the new mesh. */
    void
    prepare_for_mesh(const Triangulation<dim>  &tria,
                     const Mapping<dim>        &mapping,
                     const Quadrature<dim - 1> &face_quadrature) override;

    std::string
    description() const override;

    /** Add ∫ t · v ds over the face of @p fe_face_values to @p cell_rhs,
     * with the traction t at each quadrature point q given by
     * @p traction_at(q) [Pa]: the right-hand side of every traction load
     * (this one, SlabPull). */
    static void
    add_traction_terms(
      const FEFaceValues<dim>                           &fe_face_values,
      const FEValuesExtractors::Vector                  &displacement,
      const std::function<Tensor<1, dim>(unsigned int)> &traction_at,
      Vector<double>                                    &cell_rhs);

    /** The traction vector on part @p id at @p p with outward normal @p n. */
    Tensor<1, dim>
    traction(const types::boundary_id id,
             const Point<dim>        &p,
             const Tensor<1, dim>    &n) const;

  private:
    /** Read the subsection (the parts or points given). */
    void
    read_parameters(ParameterHandler &prm, const ModelDescription<dim> &model);

    struct Part
    {
      types::boundary_id                     id;
      bool                                   from_reference;
      std::string                            name;
      std::unique_ptr<ParsedExpression<dim>> normal, shear;
      /** Set by force: the resultant [N/m], its profile and ∫ w ds. */
      bool                                   by_resultant = false;
      Tensor<1, dim>                         resultant;
      std::unique_ptr<ParsedExpression<dim>> profile;
      double                                 profile_integral = 0;
    };
    std::vector<Part>             parts;
    const ReferenceSolution<dim> *reference = nullptr;
  };
} // namespace lithostress

#endif
