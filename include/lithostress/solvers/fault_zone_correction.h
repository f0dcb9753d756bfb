#ifndef lithostress_solvers_fault_zone_correction_h
#define lithostress_solvers_fault_zone_correction_h

#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

class Epetra_Import;
class Epetra_Map;
class Epetra_Vector;

namespace lithostress
{
  using namespace dealii;

  /**
   * A multiplicative subdomain correction on the zone around a level's
   * fault nodes, for the two fields' multigrid (TwoFieldMultigrid,
   * doc/faults.md "Preconditioners"):
   *
   *   x ← x + R_zᵀ A_zz⁻¹ R_z (b − A x),
   *
   * z the rows within a number of layers of the matrix graph from the
   * seed rows (the DoFs of the nodes that carry both fields), A_zz the
   * principal submatrix on them, factorised (UMFPACK). It is the exact
   * solve of the residual equation on the zone: with a symmetric A it is
   * an A-orthogonal projection, so that smoothing, this correction, the
   * coarse correction, this correction again and the adjoint smoothing is
   * a symmetric V-cycle.
   *
   * Why: a sliding or opening fault leaves its two sides' tangential
   * motion free, and the coarser levels' Galerkin operators couple the
   * DoFs at a fault node by a stiffness that grows with every coarsening
   * (a coarse function that breaks exact contact's tie is condensed into
   * a boundary layer one fine cell wide). The errors along the fault are
   * then neither smooth nor local to a node, which the nodal block
   * Chebyshev smoother does not reach; a few layers' exact solve does.
   *
   * On several ranks every rank holds the whole zone's A_zz (the zone is
   * a few thousand rows) and factorises it; the residual on the zone is
   * summed over the ranks (each its own rows, reading the other ranks'
   * columns from x) and each rank takes the solution on its rows: the same
   * correction as on one rank. (A block Jacobi over the ranks' parts of
   * the zone took a third more iterations on 2 ranks.)
   */
  class FaultZoneCorrection
  {
  public:
    FaultZoneCorrection();
    ~FaultZoneCorrection();

    /**
     * The zone of @p a's local rows within @p layers layers of the matrix
     * graph from the local rows @p seeds, and its factorisation; or,
     * where the whole zone holds more than @p largest_fraction of @p a's
     * rows, nothing (returns false; collective either way). Such a zone
     * is in effect a direct solve of the level in every V-cycle: on the
     * chapter-7 models, whose meshes are refined towards the plate
     * boundary, the zones hold 80-88 % of every level and made the time
     * loop three times slower for a third of the iterations, where on the
     * uniform meshes of the fault experiments (to 1.65 M DoFs) they hold
     * 2-16 % and save a third of the iterations.
     */
    bool
    initialize(const TrilinosWrappers::SparseMatrix &a,
               const std::vector<unsigned int>      &seeds,
               const unsigned int                    layers,
               const double                          largest_fraction = 1.);

    /** @p x += R_zᵀ A_zz⁻¹ R_z (@p b − A @p x). */
    void
    correct(TrilinosWrappers::MPI::Vector       &x,
            const TrilinosWrappers::MPI::Vector &b) const;

    /** Number of rows of the zone this rank owns. */
    unsigned int
    size() const
    {
      return rows.size();
    }

    /** Bytes of the zone's rows and factorisation (the factors
     * estimated by A_zz's size). */
    std::size_t
    memory_consumption() const;

  private:
    /** The zone's local rows, increasing. */
    std::vector<unsigned int> rows;
    /** The zone rows' entries of A: row i's at offsets[i] to
     * offsets[i + 1], columns as indices into column_values. */
    std::vector<std::size_t>  offsets{0};
    std::vector<unsigned int> columns;
    std::vector<double>       values;
    /** The zone rows' columns (this rank's and others'), their import
     * from the level's vectors and their values. */
    std::unique_ptr<Epetra_Map>    column_map;
    std::unique_ptr<Epetra_Import> import;
    std::unique_ptr<Epetra_Vector> column_values;
    /** The LU factors of the whole zone's A_zz (none for an empty or
     * unmade zone: initialize() releases an earlier zone's), and the bytes
     * of A_zz (the factors' size is at least that). */
    std::unique_ptr<SparseDirectUMFPACK> factor;
    std::size_t                          factor_bytes = 0;
    /** This rank's first row in the whole zone's numbering. */
    unsigned int first = 0;
    /** The whole zone's residual, then its correction. */
    mutable Vector<double> local;
  };
} // namespace lithostress

#endif
