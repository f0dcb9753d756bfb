#ifndef lithostress_loads_load_h
#define lithostress_loads_load_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <lithostress/base/gravity_field.h>
#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/materials/elastic_moduli.h>
#include <lithostress/materials/initial_stress_source.h>
#include <lithostress/materials/material.h>
#include <lithostress/temperature/temperature_model.h>

#include <map>
#include <string>

namespace lithostress
{
  using namespace dealii;

  template <int dim>
  class ReferenceSolution;

  /**
   * What a load needs to know about the model when it is configured: the
   * named boundary parts, the unit of input lengths, and the reference
   * solution if the experiment has one (boundary data can be taken from it).
   */
  template <int dim>
  struct ModelDescription
  {
    std::map<std::string, types::boundary_id> boundary_parts;
    double                                    length_scale = 1.0;
    const ReferenceSolution<dim>             *reference    = nullptr;
    /** g and the height of zero depth of every gravity term. */
    GravityField gravity;
    /** The section's temperature (`Temperature/Model`; null: none), for a
     * load that reads it (a thermal strain from the temperature). */
    const TemperatureModel<dim> *temperature = nullptr;

    /** The id of boundary part @p name; InputError naming @p entry if the
     * mesh has no such part. */
    types::boundary_id
    boundary_id(const std::string &name, const std::string &entry) const;
  };

  template <int dim>
  class ParsedExpression;

  /**
   * The integral ∫ w ds of the weight @p profile over boundary part @p id,
   * with the assembly's @p mapping and @p face_quadrature, summed over all
   * ranks: what a resultant force F is divided by to spread it as the
   * traction t = F w / ∫ w ds (slab pull, thesis §7.4). InputError naming
   * @p entry if w is negative or not finite on the part, or integrates to
   * zero.
   */
  template <int dim>
  double
  boundary_profile_integral(const Triangulation<dim>    &tria,
                            const Mapping<dim>          &mapping,
                            const Quadrature<dim - 1>   &face_quadrature,
                            const types::boundary_id     id,
                            const ParsedExpression<dim> &profile,
                            const std::string           &entry);

  /** Whether @p p lies in the coarse mesh of @p tria (through @p mapping). */
  template <int dim>
  bool
  point_in_mesh(const Triangulation<dim> &tria,
                const Mapping<dim>       &mapping,
                const Point<dim>         &p);

  /**
   * A load on the model: contributions to the right-hand side, and possibly
   * to the stiffness (a Winkler foundation), from cell and boundary
   * integrals. One class per physical load, each declaring and parsing its
   * own parameters under `Loads`; LoadCollection wires them.
   */
  template <int dim>
  class Load : public InitialStressSource<dim>
  {
  public:
    virtual ~Load() = default;

    /** Read this load's parameters (its subsection of `Loads`); returns
     * whether it acts on the model (false: gravity disabled, no traction
     * parts, no line forces, ...). Throws InputError naming the entry. */
    virtual bool
    parse_parameters(ParameterHandler            &prm,
                     const ModelDescription<dim> &model) = 0;

    /** Whether this load is the model's body force (gravity, or its
     * density-stripped form); a model has at most one. */
    virtual bool
    is_body_force() const
    {
      return false;
    }

    /** Whether this body force strips the densities (stresses relative to
     * a reference column). */
    virtual bool
    strips_densities() const
    {
      return false;
    }

    /** Whether this load is set by the balance of the others' vertical
     * forces (the slab pull's `Vertical force = balance`), so that
     * balance() must be called on every mesh. */
    virtual bool
    balances_vertical_loads() const
    {
      return false;
    }

    /** Balance @p upthrust, the net vertical force [N/m] of the loads
     * that do not balance (only called if balances_vertical_loads()). */
    virtual void
    balance(const double /*upthrust*/)
    {
    }

    /** Add this load's cell integrals for a cell of @p material. */
    virtual void
    add_cell_terms(const FEValues<dim>              &fe_values,
                   const FEValuesExtractors::Vector &displacement,
                   const Material                   &material,
                   const ElasticModuli<dim>         &moduli,
                   FullMatrix<double>               &cell_matrix,
                   Vector<double>                   &cell_rhs) const;

    /** Whether this load integrates over boundary part @p id. */
    virtual bool
    acts_on_boundary(const types::boundary_id id) const;

    /** Add this load's integrals over a face on boundary part @p id. */
    virtual void
    add_boundary_terms(const FEFaceValues<dim>          &fe_face_values,
                       const types::boundary_id          id,
                       const FEValuesExtractors::Vector &displacement,
                       FullMatrix<double>               &cell_matrix,
                       Vector<double>                   &cell_rhs) const;

    /** Add concentrated (point) contributions to the global right-hand side,
     * through @p constraints; called once per assembly on every rank. */
    virtual void
    add_point_terms(const DoFHandler<dim>           &dof_handler,
                    const FiniteElementSpace<dim>   &fe_space,
                    const AffineConstraints<double> &constraints,
                    TrilinosWrappers::MPI::Vector   &rhs) const;

    /** Check the load against the coarse mesh (points inside the body);
     * throws InputError. */
    virtual void
    check_against_mesh(const Triangulation<dim> &tria,
                       const Mapping<dim>       &mapping) const;

    /**
     * Prepare for a new mesh: loads that depend on integrals over the mesh
     * (a traction spread to a prescribed resultant) compute them here.
     * Called after every refinement, before assembly, on every rank.
     */
    virtual void
    prepare_for_mesh(const Triangulation<dim>  &tria,
                     const Mapping<dim>        &mapping,
                     const Quadrature<dim - 1> &face_quadrature);

    /**
     * Whether the load carries an initial strain (thesis eq. 3.38:
     * σ = C(ε − ε0)), so that the stress at a given strain depends on it.
     */
    bool
    has_initial_stress() const override
    {
      return false;
    }

    /**
     * Add the stress −C ε0 of this load's initial strain at @p p in a cell
     * of @p material to the in-plane @p stress and to @p sigma_zz. Used by
     * StressModel for every reported stress, and by the load itself for its
     * right-hand side −∫ σ0 : ε(v) dx.
     */
    void
    add_initial_stress(const Point<dim>         &p,
                       const Material           &material,
                       const ElasticModuli<dim> &moduli,
                       SymmetricTensor<2, dim>  &stress,
                       double                   &sigma_zz) const override;

    /** Evaluate the load's functions of time t at @p time [s] from now
     * on; the visco-elastic loop sets it before each assembly. */
    void
    set_time(const double time)
    {
      current_time = time;
    }

    /** The time [s] the load is evaluated at. */
    double
    time() const
    {
      return current_time;
    }

    /** A one-line description for the log (what acts where). */
    virtual std::string
    description() const = 0;

    /** Whether the load changes the stiffness matrix. */
    virtual bool
    changes_stiffness() const
    {
      return false;
    }

    /**
     * The stiffness k [Pa/m] of the vertical spring this load puts on
     * boundary part @p id — the traction −k |n_y| u_y e_y of the isostatic
     * restoring force — or 0. The matrix-free operator builds its boundary
     * term from it; add_boundary_terms() adds the same term to the matrix.
     */
    virtual double
    vertical_spring_stiffness(const types::boundary_id) const
    {
      return 0;
    }

    /**
     * Add the matrix of a vertical spring of stiffness @p k on the face of
     * @p fe_face_values, ∫ k |n_y| φ_i,y φ_j,y ds, to @p cell_matrix: the
     * term vertical_spring_stiffness() stands for, shared by the assembly
     * and the multigrid's coarse matrix.
     */
    static void
    add_vertical_spring_terms(const FEFaceValues<dim>          &fe_face_values,
                              const double                      k,
                              const FEValuesExtractors::Vector &displacement,
                              FullMatrix<double>               &cell_matrix);

    /** Whether all of this load's stiffness is vertical_spring_stiffness()
     * (so that a matrix-free operator can represent it). */
    virtual bool
    stiffness_is_vertical_spring() const
    {
      return !changes_stiffness();
    }

  private:
    double current_time = 0;
  };
} // namespace lithostress

#endif
