#ifndef lithostress_solvers_two_field_multigrid_h
#define lithostress_solvers_two_field_multigrid_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <lithostress/solvers/fault_zone_correction.h>
#include <lithostress/solvers/sparse_cholesky.h>

#include <memory>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * A geometric multigrid V-cycle for the assembled matrix of a faulted
   * model: two displacement fields, each FE_Nothing on the other side of
   * the faults (doc/faults.md), the space deal.II's level DoFs and
   * geometric transfers do not handle (hp DoF handlers).
   *
   * Each level's mesh is the next finer one coarsened globally once
   * (every cell whose siblings are all active, where the one-irregular
   * rule allows it: on a uniform mesh a whole level, on an adaptive one
   * the finest cells everywhere), down to the coarse mesh, with the same
   * two fields, so that a coarse function of either side
   * is a fine function of the same side: the spaces are nested across the fault
   * as well. The prolongation P_l is the coarse cells' interpolation,
   * continuous through each level's hanging-node constraints and onto the fine
   * level's unconstrained DoFs. The level operators are Galerkin
   * products A_l = P_lᵀ A_{l+1} P_l of the finest matrix, so that every
   * coarse level carries the fault's state as the fine tangent has it:
   * sliding, stuck, open, and exact contact's ties, which the condensed
   * fine matrix has eliminated. Without the stiff normal springs of the
   * thesis's law (exact contact) the fine matrix has no stiff pairs, and
   * Chebyshev smoothing damps the oscillatory error as on an unfaulted
   * body. Its preconditioner is the inverse of each node's block (the
   * DoFs at one support point, of both fields at the fault): a coarse
   * function that breaks a tie is condensed into a boundary layer one
   * fine cell wide, so the coarser operators couple the two fields' DoFs
   * at a fault node stiffly, by a factor that doubles with every level.
   * Around the faults each level adds an exact solve on a few layers of
   * the matrix graph about the fault nodes, after the pre-smoothing and
   * before the post-smoothing (FaultZoneCorrection): the errors along a
   * sliding fault are neither smooth nor local to a node.
   * The coarsest mesh is solved by a sparse Cholesky factorisation where
   * its operator is symmetric (exact contact, the spring law, locked
   * faults), by UMFPACK where it is not (the Newton tangent with the
   * contact reaction).
   *
   * On several ranks the coarser levels' meshes and DoFs are whole on
   * every rank (built from the refined cells of all ranks), their
   * operators distributed in contiguous ranges, and the coarsest operator
   * gathered and factorised on each rank; the finest prolongation's rows
   * come from each rank's own cells.
   */
  template <int dim>
  class TwoFieldMultigrid
  {
  public:
    /** Smoother of every level but the coarsest. */
    struct Settings
    {
      unsigned int smoother_degree = 4;
      double       smoothing_range = 20;
      /** Layers of the matrix graph around each level's fault nodes
       * solved exactly after the pre-smoothing and before the
       * post-smoothing (FaultZoneCorrection); 0: none. */
      unsigned int fault_zone_layers = 6;
      /** A level whose zone would hold more than this fraction of its
       * rows gets none (FaultZoneCorrection::initialize()). */
      double fault_zone_largest_fraction = 0.5;
    };

    /**
     * Builds the levels of @p dof_handler's mesh, each
     * coarser level's DoFs with the field (active FE index) of the cells
     * it covers, and the prolongations between the coarser levels. Kept
     * while the mesh is; the finest prolongation depends on the
     * constraints and is completed by initialize().
     */
    void
    make_hierarchy(const DoFHandler<dim>       &dof_handler,
                   const hp::FECollection<dim> &fe);

    /**
     * The level operators from @p matrix, the finest level's condensed
     * with @p constraints, their smoothers and the coarsest level's
     * factorisation.
     */
    void
    initialize(const TrilinosWrappers::SparseMatrix &matrix,
               const AffineConstraints<double>      &constraints,
               const Settings                       &settings);

    /** One V-cycle from a zero guess: @p dst ≈ A⁻¹ @p src. Symmetric, so
     * that it preconditions CG. */
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

    /** Number of levels, the finest included. */
    unsigned int
    n_levels() const
    {
      return level_dofs.size();
    }

    /** Bytes of the level matrices, prolongations and the coarse
     * factorisation (not the finest matrix, which is the caller's). */
    std::size_t
    memory_consumption() const;

  private:
    using Vector = TrilinosWrappers::MPI::Vector;

    /** The DoFs this rank owns on a level grouped by support point: the
     * local indices of node k at dofs[offsets[k]] to dofs[offsets[k + 1]],
     * the nodes in the order of their first DoF. */
    struct Nodes
    {
      std::vector<unsigned int> offsets, dofs;
    };

    /**
     * Nodal block Jacobi: the inverse of the matrix block of all DoFs at
     * one support point (both components, and both fields where a fault
     * passes), 0 on a zero row. At a fault node exact contact ties the
     * two fields' normal displacements, which the coarser levels' Galerkin
     * operators carry as a stiff coupling of the node's DoFs: a point
     * Jacobi smoother damps it poorly, the node's block takes it together.
     */
    struct NodalBlockInverse
    {
      /** The level's nodes (TwoFieldMultigrid::nodes). */
      const Nodes *nodes = nullptr;
      /** Each node's inverse block, row by row, one after the other. */
      std::vector<double> inverses;

      void
      vmult(Vector &dst, const Vector &src) const;
    };

    using Smoother = PreconditionChebyshev<TrilinosWrappers::SparseMatrix,
                                           Vector,
                                           NodalBlockInverse>;
    using Matrix   = TrilinosWrappers::SparseMatrix;
    /** Rows of a prolongation: row r's (coarse DoF, weight) pairs are
     * coarse[e], weights[e] for e from offsets[r] to offsets[r + 1]. Kept
     * for the finest level, in one block rather than a vector per row
     * (half the memory: 21 MB instead of 41 MB at 416 k DoFs). */
    struct Transfers
    {
      std::vector<std::size_t>             offsets{0};
      std::vector<types::global_dof_index> coarse;
      std::vector<double>                  weights;
    };

    /** The prolongation from level @p level - 1 to @p level as rows of
     * (coarse DoF, weight), one per DoF of @p level this rank owns (in
     * the order of owned[level]), through the coarser level's
     * hanging-node constraints. */
    Transfers
    interpolation_rows(const unsigned int level) const;

    /** The matrix of @p rows, without the rows of DoFs in
     * @p fine_constraints. */
    void
    make_prolongation(const unsigned int               level,
                      const Transfers                 &rows,
                      const AffineConstraints<double> &fine_constraints);

    /** The DoFs this rank owns on @p level grouped by support point. */
    Nodes
    group_nodes(const unsigned int level) const;

    /** The smoother's blocks of level matrix @p a on @p level. */
    NodalBlockInverse
    block_inverse(const unsigned int level, const Matrix &a) const;

    /** The local rows of @p level on the faults: the DoFs on faces
     * between cells of the two fields, and those of every node that
     * carries both (on several ranks a fault node's two fields may be
     * owned by two ranks, each seeing a node of one field). */
    std::vector<unsigned int>
    fault_dofs(const unsigned int level) const;

    /** The correction on the zone of Settings::fault_zone_layers layers
     * around the fault rows of @p level (zone_seeds), whose matrix is
     * @p a; none without fault rows on any rank, with 0 layers or where
     * the zone would hold more than Settings::fault_zone_largest_fraction
     * of the level. */
    std::unique_ptr<FaultZoneCorrection>
    fault_zone(const unsigned int level,
               const Matrix      &a,
               const Settings    &settings) const;

    void
    v_cycle(const unsigned int level, Vector &x, const Vector &b) const;

    std::vector<std::unique_ptr<Triangulation<dim>>> triangulations;
    std::vector<std::unique_ptr<DoFHandler<dim>>>    coarser_dofs;
    std::vector<const DoFHandler<dim> *>             level_dofs;
    std::vector<AffineConstraints<double>>           hanging_nodes;
    /** Each level's owned DoFs by support point (group_nodes()). */
    std::vector<Nodes> nodes;
    /** Each level's local rows on the faults (fault_dofs()). */
    std::vector<std::vector<unsigned int>> zone_seeds;
    /** The DoFs of each level a rank owns in the level operators: the
     * finest level's own, a contiguous range of each coarser one (whole
     * on every rank). */
    std::vector<IndexSet> owned;
    /** The finest prolongation's rows before the constraints. */
    Transfers finest_rows;
    /** The finest level's constrained DoFs its prolongation leaves out. */
    std::vector<types::global_dof_index> finest_constrained;
    /** prolongations[l]: level l - 1 to level l (l ≥ 1). */
    std::vector<std::unique_ptr<Matrix>> prolongations;
    /** level_matrices[l], l below the finest (the caller's matrix). */
    std::vector<std::unique_ptr<Matrix>>   level_matrices;
    const Matrix                          *finest_matrix = nullptr;
    std::vector<std::unique_ptr<Smoother>> smoothers;
    /** zones[l]: the fault zone's correction on level l ≥ 1 (empty
     * without faults or with Settings::fault_zone_layers = 0). */
    std::vector<std::unique_ptr<FaultZoneCorrection>> zones;
    SparsityPattern                                   coarse_pattern;
    SparseMatrix<double>                              coarse_matrix;
    /** The coarsest operator's factorisation: Cholesky (CHOLMOD) where it
     * is symmetric positive definite, which solves without UMFPACK's
     * iterative refinement in a fraction of its time, else LU. */
    SparseCholesky      coarse_cholesky;
    SparseDirectUMFPACK coarse_lu;
    bool                coarse_by_cholesky = false;
    /** The coarsest level's right-hand side and solution, whole. */
    mutable dealii::Vector<double> coarse_values;
    mutable std::vector<Vector>    residuals, corrections, coarse_rhs;
  };
} // namespace lithostress

#endif
