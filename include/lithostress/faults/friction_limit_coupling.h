#ifndef lithostress_faults_friction_limit_coupling_h
#define lithostress_faults_friction_limit_coupling_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/faults/coulomb_friction.h>
#include <lithostress/faults/fault_interface.h>
#include <lithostress/faults/normal_contact.h>

#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The Newton tangent's term for the friction limit's dependence on the
   * contact reaction, in exact normal contact (doc/faults.md, "Exact
   * normal contact"): a closed point that slides carries the shear
   * traction t_s = ∓μ σ_n,eff with σ_n,eff = λ − (ρ_l − ρ_w) g d, and λ
   * is the reaction of its node's tie, a linear function of the
   * displacement, λ(u) = −s n·(K u − f)_node / W (NormalContact). The
   * linearised shear force of the point is then
   *
   *   F(x) = F(u) + g (∂t_s/∂λ) (λ(x) − λ(u)),
   *
   * g the point's force per unit shear traction (∫[φ]·s ds), and the
   * tangent gains M = Cᵀ G A Λ C: Λ the rows n·K at the points' nodes
   * over W, A the slopes ∓μ, G the force columns, C the active ties.
   * M is not symmetric; with it the states' fixed point in the reactions
   * (the friction limit taken at the last reaction) becomes Newton's
   * method, which ends in one step once the states stand still.
   *
   * M is applied as a product: the rows of K C at the sliding points'
   * nodes (a matrix with no other rows, C without inhomogeneities, made
   * once per linearisation), the reactions they give, and the points'
   * force columns through the ties.
   */
  template <int dim>
  class FrictionLimitCoupling
  {
  public:
    /**
     * The term at the linearisation whose return mapping gave
     * @p responses (one per interface point, in the order of
     * FaultInterface::for_each_interface_point()), with @p contact's ties
     * @p ties (the problem's constraints with the closed nodes' ties) and
     * the bulk matrix @p bulk (K, condensed with the problem's constraints
     * only).
     */
    void
    reinit(const FaultInterface<dim>            &faults,
           const DoFHandler<dim>                &dof_handler,
           const FiniteElementSpace<dim>        &fe_space,
           const NormalContact<dim>             &contact,
           const std::vector<InterfaceResponse> &responses,
           const TrilinosWrappers::SparseMatrix &bulk,
           const AffineConstraints<double>      &ties,
           const IndexSet                       &locally_owned,
           const IndexSet                       &locally_relevant);

    /** No term (no point slides in contact, or the tangent takes the
     * reactions as given). */
    void
    clear()
    {
      columns.clear();
      slopes.clear();
      any = false;
    }

    /** Whether a point slides in contact on any rank: M ≠ 0. */
    bool
    active() const
    {
      return any;
    }

    /** The shear traction the term adds at point @p i where its node's
     * reaction is @p reaction: ∂t_s/∂λ (λ − λ at the linearisation); 0 at
     * a point that does not slide in contact. */
    double
    shear_change(const unsigned int i, const double reaction) const
    {
      return any && i < slopes.size()
               ? slopes[i] * (reaction - linearised_reactions[i])
               : 0.;
    }

    /** @p dst += M @p src. */
    void
    vmult_add(TrilinosWrappers::MPI::Vector       &dst,
              const TrilinosWrappers::MPI::Vector &src) const;

  private:
    /** A sliding point's force column: the face pair's DoFs, g times the
     * slope ∂t_s/∂λ, and the point's index in @p contact. */
    struct Column
    {
      unsigned int                         point;
      std::vector<types::global_dof_index> dofs;
      Vector<double>                       force;
    };

    std::vector<Column> columns;
    /** Per point: ∂t_s/∂λ (0 unless it slides in contact) and the
     * reaction at the linearisation. */
    std::vector<double>              slopes, linearised_reactions;
    bool                             any     = false;
    const NormalContact<dim>        *contact = nullptr;
    const AffineConstraints<double> *ties    = nullptr;
    /** A row of K C: (column, value), K's entries with a constrained
     * column's moved onto its masters. */
    struct Row
    {
      types::global_dof_index                                 row;
      std::vector<std::pair<types::global_dof_index, double>> entries;
    };
    /** The rows of K C this rank owns at the nodes whose reactions the
     * columns read. */
    std::vector<Row> reaction_rows;
    /** Work vectors: K C x (owned, then the forces; and ghosted). */
    mutable TrilinosWrappers::MPI::Vector product, ghosted;

    /** reaction_rows from @p bulk and the homogeneous @p ties. */
    void
    make_reaction_rows(const TrilinosWrappers::SparseMatrix &bulk,
                       const AffineConstraints<double>      &ties,
                       const IndexSet                       &locally_owned);
  };

  /** The Newton tangent with the friction limits' coupling to the
   * reactions: L x + M x, L the assembled (symmetric) linearisation. */
  template <int dim>
  struct CoupledTangent
  {
    const TrilinosWrappers::SparseMatrix &linearised;
    const FrictionLimitCoupling<dim>     &coupling;

    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const
    {
      linearised.vmult(dst, src);
      coupling.vmult_add(dst, src);
    }
  };
} // namespace lithostress

#endif
