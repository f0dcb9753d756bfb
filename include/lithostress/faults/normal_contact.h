#ifndef lithostress_faults_normal_contact_h
#define lithostress_faults_normal_contact_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/faults/coulomb_friction.h>
#include <lithostress/faults/fault_interface.h>
#include <lithostress/solvers/linear_solver.h>

#include <array>
#include <deque>
#include <set>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * Exact normal contact on the faults with `Normal stiffness = exact`,
   * instead of the thesis's stiff normal spring (thesis §5.4, k = 1e15
   * N/m per element, thousands of times the stiffness of the rock next to
   * it; doc/faults.md, "Exact normal contact").
   *
   * At a closed node the normal jump is zero, by one constraint per node
   * (FaultInterface::add_contact_constraints()), and the normal traction is
   * that constraint's reaction: the normal part of the residual of the
   * equations without it at the constrained node, divided by the node's
   * share of the fault's area (the Gauss-Lobatto weights of its faces, so
   * that the reaction is the traction the face terms integrate). An open
   * node has a free normal jump and carries no total normal traction.
   * Which nodes are open is an active set, updated between the sliding
   * solver's Newton iterations as in deal.II's step-42: a closed node of a
   * frictional fault opens where its effective normal stress is tensile,
   * an open one closes where its two sides interpenetrate. An elastic
   * fault's nodes stay closed. The open set is the same on every rank.
   *
   * The per-point data follow FaultInterface::for_each_interface_point()'s
   * numbering (FaultHistory's points).
   */
  template <int dim>
  class NormalContact
  {
  public:
    /** The contact of @p faults on this mesh: every node closed. */
    NormalContact(const FaultInterface<dim>     &faults,
                  const DoFHandler<dim>         &dof_handler,
                  const FiniteElementSpace<dim> &fe_space,
                  const IndexSet                &locally_owned,
                  const IndexSet                &locally_relevant);

    /** Whether interface point @p i lies on a fault with exact contact. */
    bool
    exact(const unsigned int i) const
    {
      return in_contact[i];
    }

    /** Whether point @p i is closed (its normal jump held at zero). */
    bool
    closed(const unsigned int i) const
    {
      return open.count(keys[i]) == 0;
    }

    /** The normal traction t_n at point @p i [Pa] (tension positive): the
     * reaction of its node's constraint at the last compute_tractions(). */
    double
    normal_traction(const unsigned int i) const
    {
      return tractions[i];
    }

    /** The normal traction at point @p i that @p residual's entries at
     * its node make (−s n·r / W; ghosted @p residual): compute_tractions()
     * for one point, and the reaction's derivative for a direction. */
    double
    reaction(const TrilinosWrappers::MPI::Vector &residual,
             const unsigned int                   i) const
    {
      double r_n = 0;
      for (unsigned int d = 0; d < dim; ++d)
        r_n += residual[nodes[i][d]] * normals[i][d];
      return -signs[i] * r_n / weight[nodes[i][0]];
    }

    /** The DoFs (x, y) whose residual reaction() reads at point @p i. */
    const std::array<types::global_dof_index, dim> &
    reaction_dofs(const unsigned int i) const
    {
      return nodes[i];
    }

    /** The fault's normal at point @p i's node (its tie's normal). */
    const Tensor<1, dim> &
    normal(const unsigned int i) const
    {
      return normals[i];
    }


    /** The number of open nodes (the same on every rank). */
    unsigned int
    n_open() const
    {
      return open.size();
    }

    /** A count of the changes of the open nodes: the active constraints
     * are the same while it is. */
    unsigned int
    open_set_version() const
    {
      return version;
    }


    /** The bulk of @p problem (cells and loads, with the laws' history)
     * into @p system with the problem's constraints and the closed nodes'
     * ties; the ties and the matrix's sparsity are made again only if the
     * open nodes changed since the last call. */
    void
    assemble_bulk(const DiscreteProblem<dim> &problem,
                  LinearSystem<dim>          &system);

    /** The right-hand side of @p problem alone into @p system, whose
     * matrix and ties assemble_bulk() made for the present open nodes (a
     * new time step on the same operator). */
    void
    assemble_bulk_rhs(const DiscreteProblem<dim> &problem,
                      LinearSystem<dim>          &system) const;


    /** The normal tractions of the closed points from @p residual (ghosted:
     * K u − f plus the faults' forces other than the contact's, condensed
     * with the problem's constraints only). */
    void
    compute_tractions(const TrilinosWrappers::MPI::Vector &residual);

    /** The active-set update from the return mapping's @p responses at the
     * points and their normal jumps @p normal_jumps: frictional points
     * with σ_n,eff > 0 open, open points with w_n < 0 close. Returns
     * whether the set changed (the same on every rank). */
    bool
    update(const std::vector<InterfaceResponse> &responses,
           const std::vector<double>            &normal_jumps);

    /**
     * Before the first linearisation from a given iterate (a coarser
     * mesh's solution: nested iteration), on a contact made for this mesh:
     * the nodes where the iterate's faces are apart (w_n > @p gap at one of
     * the node's points, @p normal_jumps) open, the others closed;
     * @p constraints := @p base with the closed nodes' ties.
     */
    void
    start_from(const std::vector<double>       &normal_jumps,
               const double                     gap,
               const AffineConstraints<double> &base,
               AffineConstraints<double>       &constraints);

    /**
     * The normal tractions for the next linearisation: the friction limit
     * of a sliding point depends on its reaction, which the linearised
     * system takes as given, so the Newton iteration is a fixed point
     * λ ↦ (the reaction of the solution with λ), affine while the states
     * do not change, converging linearly (about 0.2 per iteration on the
     * thesis's thrust fault). Anderson acceleration (depth 4; Walker & Ni
     * 2011) of that fixed point: from the reactions of the last iterates
     * and the tractions their linearisations used, the combination whose
     * residual is least. @p restart forgets the history (the states or
     * the active set changed, so the map did).
     */
    void
    accelerate(const bool restart);

  private:
    /** @p constraints := the problem's @p base constraints with the ties
     * of the closed nodes, closed. */
    void
    make_constraints(const AffineConstraints<double> &base,
                     AffineConstraints<double>       &constraints) const;

    const FaultInterface<dim>     &faults;
    const DoFHandler<dim>         &dof_handler;
    const FiniteElementSpace<dim> &fe_space;
    const IndexSet                 locally_owned, locally_relevant;
    const MPI_Comm                 communicator;
    /** Per point: on a fault with exact contact and sliding; the node's
     * key and DoFs, the sign of their jumps, the fault's normal. */
    std::vector<bool>                                     in_contact, slides;
    std::vector<types::global_dof_index>                  keys;
    std::vector<std::array<types::global_dof_index, dim>> nodes;
    std::vector<double>                                   signs;
    std::vector<Tensor<1, dim>>                           normals;
    /** Σ JxW of the points at each node (indexed by the x DoF of the
     * finer side's node, whose reaction is read). */
    TrilinosWrappers::MPI::Vector weight;
    std::vector<double>           tractions;
    /** The keys of the open nodes, and a count of their changes. */
    std::set<types::global_dof_index> open;
    unsigned int                      version = 0;
    /** The version assemble_bulk() last made constraints for. */
    unsigned int constraints_made_for = numbers::invalid_unsigned_int;
    /** accelerate()'s state: the tractions the last linearisation used
     * (empty: none yet), the last reactions and residuals, and the
     * differences of the last iterates' reactions and residuals. */
    std::vector<double>             input, last_g, last_f;
    std::deque<std::vector<double>> dG, dF;
    /** The acceleration's iterates since its last restart, -1 before the
     * first (the same on every rank, also on one without points). */
    int accelerated = -1;
  };

  /**
   * @p r := Cᵀ @p r for exact contact's ties: each tied row's entry added
   * to the DoFs its tie in @p ties takes it from, with the tie's weights,
   * and the tied row zeroed. Rows constrained by the problem's own
   * @p constraints (which @p ties contains) are left as they are.
   */
  void
  condense_ties(const AffineConstraints<double> &ties,
                const AffineConstraints<double> &constraints,
                const IndexSet                  &locally_owned,
                const IndexSet                  &locally_relevant,
                TrilinosWrappers::MPI::Vector   &r);
} // namespace lithostress

#endif
