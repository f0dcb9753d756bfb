#ifndef lithostress_reference_solutions_reference_solution_h
#define lithostress_reference_solutions_reference_solution_h

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <lithostress/base/gravity_field.h>
#include <lithostress/materials/elastic_moduli.h>
#include <lithostress/materials/material.h>

#include <memory>
#include <string>

namespace lithostress
{
  /**
   * An exact solution of an elasticity problem, for convergence studies and
   * as boundary data ("use the reference solution" on a boundary part): the
   * displacement and the in-plane stress at any point. Each solution reads
   * its own parameters (loads, dimensions) from a subsection of
   * `Convergence study`, and its elastic constants from the model's
   * materials, so that the reference and the model cannot disagree on them.
   */
  template <int dim>
  class ReferenceSolution
  {
  public:
    virtual ~ReferenceSolution() = default;

    /** Read the parameters; @p materials are resolved. */
    virtual void
    parse_parameters(ParameterHandler      &prm,
                     const MaterialLibrary &materials,
                     const PlaneState       plane_state,
                     const double           length_scale) = 0;

    /** The exact displacement [m]. */
    virtual Tensor<1, dim>
    displacement(const Point<dim> &p) const = 0;

    /** The exact in-plane stress [Pa], tension positive. */
    virtual SymmetricTensor<2, dim>
    stress(const Point<dim> &p) const = 0;

    /** The model's gravity (set before parse_parameters()). */
    GravityField gravity;
  };

  /**
   * `Convergence study/Reference solution`: selects an exact solution.
   */
  template <int dim>
  class ReferenceSolutionSelector
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    /** The selected solution, or null for "none". */
    static std::unique_ptr<ReferenceSolution<dim>>
    create(ParameterHandler      &prm,
           const MaterialLibrary &materials,
           const PlaneState       plane_state,
           const double           length_scale,
           const GravityField    &gravity);
  };

  /**
   * The displacement of a reference solution as a deal.II Function with
   * @p n_fields copies of the displacement (one per displacement field of
   * the finite element).
   */
  template <int dim>
  class ReferenceDisplacement : public Function<dim>
  {
  public:
    ReferenceDisplacement(const ReferenceSolution<dim> &solution,
                          const unsigned int            n_fields);
    double
    value(const Point<dim> &p, const unsigned int component) const override;
    void
    vector_value(const Point<dim> &p, Vector<double> &values) const override;

  private:
    const ReferenceSolution<dim> &solution;
  };
} // namespace lithostress

#endif
