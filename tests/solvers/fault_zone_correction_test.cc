// The fault zone's correction of the two fields' multigrid
// (FaultZoneCorrection, doc/faults.md "Preconditioners") on the 5-point
// Laplacian of a 30 × 30 grid, whose grid row 15 stands for a fault and is
// the seed, grown by 2 layers (grid rows 13 to 17):
// - the zone is those 150 unknowns, each rank owning its own: the ranks own
//   whole grid rows, so on 2 ranks the seed lies on rank 1 (grid rows 15 to
//   29) and the layers grow across the ranks' boundary into rank 0's grid
//   rows 13 and 14, which hold no seed (asserted);
// - after x ← x + R_zᵀ A_zz⁻¹ R_z (b − A x) the residual vanishes on the
//   zone, on every rank (each holds the whole zone's A_zz), to 1e-12 of
//   |b| (an exact solve of 150 unknowns whose condition number is below
//   1e3), and x is unchanged off the zone;
// - a second correction changes nothing (the same 1e-12): a projection;
// - it does not raise the energy norm of the error (A is SPD and the
//   correction A-orthogonal), and the map b ↦ R_zᵀ A_zz⁻¹ R_z b is
//   symmetric (to 1e-12 of the product of the norms), so that the V-cycle
//   that applies it before and after the coarse correction stays symmetric
//   for CG.

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/solvers/fault_zone_correction.h>

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>

using namespace dealii;
using namespace lithostress;

namespace
{
  constexpr unsigned int n = 30, fault_row = 15, layers = 2;
  using TrilinosVector = TrilinosWrappers::MPI::Vector;

  unsigned int failed = 0;

  void
  check(const bool ok, const std::string &what)
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << (ok ? "PASS: " : "FAIL: ") << what << std::endl;
    failed += ok ? 0 : 1;
  }

  /** @p value in scientific notation, 3 digits. */
  std::string
  sci(const double value)
  {
    std::ostringstream out;
    out << std::scientific << std::setprecision(2) << value;
    return out.str();
  }

  /** Rows of the grid (row-major) in contiguous ranges of whole grid
   * rows. */
  IndexSet
  owned_rows()
  {
    const unsigned int size = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const unsigned int rank = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    IndexSet           owned(n * n);
    owned.add_range(n * (n * rank / size), n * (n * (rank + 1) / size));
    return owned;
  }

  void
  laplacian(const IndexSet &owned, TrilinosWrappers::SparseMatrix &a)
  {
    TrilinosWrappers::SparsityPattern pattern(owned, MPI_COMM_WORLD);
    const auto                        neighbours = [](const unsigned int row) {
      std::vector<unsigned int> out{row};
      const unsigned int        i = row / n, j = row % n;
      if (i > 0)
        out.push_back(row - n);
      if (i + 1 < n)
        out.push_back(row + n);
      if (j > 0)
        out.push_back(row - 1);
      if (j + 1 < n)
        out.push_back(row + 1);
      return out;
    };
    for (const auto row : owned)
      for (const auto column : neighbours(row))
        pattern.add(row, column);
    pattern.compress();
    a.reinit(pattern);
    for (const auto row : owned)
      for (const auto column : neighbours(row))
        a.set(row, column, column == row ? 4. : -1.);
    a.compress(VectorOperation::insert);
  }

  void
  fill_random(TrilinosVector &v, std::mt19937 &random)
  {
    std::uniform_real_distribution<double> value(-1, 1);
    for (const auto i : v.locally_owned_elements())
      v[i] = value(random);
    v.compress(VectorOperation::insert);
  }

  /** The energy norm |v|_A. */
  double
  energy(const TrilinosWrappers::SparseMatrix &a, const TrilinosVector &v)
  {
    TrilinosVector av(v);
    a.vmult(av, v);
    return std::sqrt(av * v);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const IndexSet                   owned = owned_rows();
  TrilinosWrappers::SparseMatrix   a;
  laplacian(owned, a);
  std::vector<unsigned int> seeds;
  const auto                first = *owned.begin();
  for (const auto row : owned)
    if (row / n == fault_row)
      seeds.push_back(row - first);
  // The zone is 2 layers + 1 of the n grid rows: made under a largest
  // fraction just above that, not made under one just below.
  const double        zone_fraction = (2. * layers + 1) / n;
  FaultZoneCorrection zone;
  check(zone.initialize(a, seeds, layers, zone_fraction + 0.5 / n),
        "the zone is made where it holds no more than the largest fraction");
  FaultZoneCorrection too_large;
  check(!too_large.initialize(a, seeds, layers, zone_fraction - 0.5 / n) &&
          Utilities::MPI::sum(too_large.size(), MPI_COMM_WORLD) == 0,
        "no zone where it would hold more than the largest fraction");
  const auto in_zone = [](const types::global_dof_index row) {
    const unsigned int i = row / n;
    return i + layers >= fault_row && i <= fault_row + layers;
  };
  unsigned int expected = 0;
  for (const auto row : owned)
    expected += in_zone(row) ? 1 : 0;
  check(Utilities::MPI::sum(zone.size() == expected ? 0 : 1, MPI_COMM_WORLD) ==
          0,
        "the zone is this rank's unknowns within 2 layers of the seed row (" +
          std::to_string(zone.size()) + " here, " + std::to_string(expected) +
          " expected)");
  // On several ranks a rank without a seed holds part of the zone: the
  // layers crossed the ranks' boundary.
  if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    check(Utilities::MPI::sum(seeds.empty() && zone.size() > 0 ? 1 : 0,
                              MPI_COMM_WORLD) >= 1,
          "the layers grow across the ranks' boundary onto a rank with no "
          "seed");
  std::mt19937   random(7);
  TrilinosVector b(owned, MPI_COMM_WORLD), x(b), r(b);
  fill_random(b, random);
  fill_random(x, random);
  const TrilinosVector start(x);
  zone.correct(x, b);
  a.vmult(r, x);
  r.sadd(-1., 1., b);
  double       on_zone = 0;
  unsigned int changed = 0, outside = 0;
  for (const auto row : owned)
    if (x[row] != start[row])
      {
        ++changed;
        outside += in_zone(row) ? 0 : 1;
        on_zone = std::max(on_zone, std::abs(r[row]));
      }
  on_zone = Utilities::MPI::max(on_zone, MPI_COMM_WORLD) / b.l2_norm();
  check(Utilities::MPI::sum(changed == zone.size() && outside == 0 ? 0 : 1,
                            MPI_COMM_WORLD) == 0,
        "x changes on the zone's rows and nowhere else");
  check(on_zone < 1e-12,
        "the residual on the zone after the correction: " + sci(on_zone) +
          " of |b| (< 1e-12)");

  TrilinosVector again(x);
  zone.correct(again, b);
  again -= x;
  check(again.linfty_norm() < 1e-12 * x.linfty_norm(),
        "a second correction changes x by " +
          sci(again.linfty_norm() / x.linfty_norm()) +
          " of |x| (< 1e-12): a projection");

  // The energy norm of the error x* − x, x* from CG on A (1e-14 of |b|).
  TrilinosVector exact(b);
  exact = 0;
  SolverControl            control(2000, 1e-14 * b.l2_norm());
  SolverCG<TrilinosVector> cg(control);
  cg.solve(a, exact, b, PreconditionIdentity());
  TrilinosVector before(exact), after(exact);
  before -= start;
  after -= x;
  const double e0 = energy(a, before), e1 = energy(a, after);
  check(e1 <= e0 * (1 + 1e-12),
        "the error's energy norm goes from " + sci(e0) + " to " + sci(e1) +
          " (not up)");

  TrilinosVector b1(owned, MPI_COMM_WORLD), b2(b1), z1(b1), z2(b1);
  fill_random(b1, random);
  fill_random(b2, random);
  z1 = 0;
  z2 = 0;
  zone.correct(z1, b1);
  zone.correct(z2, b2);
  const double asymmetry =
    std::abs(b1 * z2 - b2 * z1) / (b1.l2_norm() * b2.l2_norm());
  check(asymmetry < 1e-12,
        "b1·Z b2 − b2·Z b1 = " + sci(asymmetry) +
          " of |b1||b2| (< 1e-12): symmetric");
  return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
