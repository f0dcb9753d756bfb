// Unit test of FaultHistory (faults/fault_history.h): the faults' named
// history, any number of components per interface point, carried from one
// mesh's points to another's (refinement, coarsening, repartitioning: the
// points of all ranks are gathered) and through a checkpoint's records.
//
// Three faults whose laws keep 2, 0 and 1 components. On the first "mesh"
// each rank r of n holds the points s = 10 (r + k n) / 3, k = 0..3 on
// fault 0 (so the ranks' points interleave) and s = r + 0.5 on faults 1
// and 2; fault 0's history is (2 s + 1, −s), fault 2's is s². The second
// mesh gives each rank other points (those of rank n − 1 − r, shifted by a
// third of a spacing, and one point beyond each end), as a repartitioned,
// refined mesh would. Asserted:
// - fault 0's components are linear in s, so the linear interpolation
//   along the fault reproduces them to round-off (1e-13 relative) at every
//   point between the old ones, and beyond the ends takes the end point's
//   values (the profile is held, not extrapolated);
// - fault 1's points have no components, fault 2's one, interpolated
//   linearly between its old points (checked against the interpolant);
// - gather(), restore() into a new history and reinit() on the same points
//   give the same values bit for bit (a checkpoint read back);
// - records restored with another number of components for a fault (a
//   checkpoint of another law) are refused with a ComputationError naming
//   the law; set_trial() with the wrong number of components likewise.
// Run on 1 and 2 ranks. Prints one "ok ..." or "FAIL ..." line per check
// (rank 0) and returns non-zero on a failure.

#include <deal.II/base/mpi.h>

#include <lithostress/base/input_error.h>
#include <lithostress/faults/fault_history.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace lithostress;

namespace
{
  unsigned int n_failed = 0;

  void
  check(const bool ok, const std::string &what)
  {
    const bool all = Utilities::MPI::min(ok ? 1 : 0, MPI_COMM_WORLD) == 1;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << (all ? "ok " : "FAIL ") << what << std::endl;
    if (!all)
      ++n_failed;
  }

  const std::vector<std::vector<std::string>> names = {{"a", "b"}, {}, {"c"}};

  /** The points of one mesh: their faults and distances. */
  struct Points
  {
    std::vector<unsigned int> faults;
    std::vector<double>       s;

    void
    add(const unsigned int fault, const double distance)
    {
      faults.push_back(fault);
      s.push_back(distance);
    }
  };

  /** Fault 0's points of rank @p r of @p n on the first mesh. */
  double
  first_s(const unsigned int r, const unsigned int n, const unsigned int k)
  {
    return 10.0 * (r + k * n) / 3;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const unsigned int               r = Utilities::MPI::this_mpi_process(comm);
  const unsigned int               n = Utilities::MPI::n_mpi_processes(comm);

  // The first mesh and its history.
  Points first;
  for (unsigned int k = 0; k < 4; ++k)
    first.add(0, first_s(r, n, k));
  first.add(1, r + 0.5);
  first.add(2, r + 0.5);
  FaultHistory history;
  history.reinit(first.faults, first.s, names, 1, comm);
  bool sizes = true;
  for (unsigned int i = 0; i < first.s.size(); ++i)
    {
      const double s = first.s[i];
      sizes =
        sizes && history.committed(i).size() == names[first.faults[i]].size();
      if (first.faults[i] == 0)
        history.set_trial(i, {2 * s + 1, -s});
      else if (first.faults[i] == 2)
        history.set_trial(i, {s * s});
    }
  history.commit();
  check(sizes, "each point has as many components as its fault's law names");

  // The second mesh: rank n-1-r's points shifted by a third of a spacing,
  // and one point beyond each end of fault 0.
  const unsigned int other = n - 1 - r;
  Points             second;
  const double       spacing = 10.0 / 3;
  for (unsigned int k = 0; k < 4; ++k)
    second.add(0, first_s(other, n, k) + spacing / 3);
  second.add(0, -1.0);
  second.add(0, 1e3);
  second.add(1, other + 0.25);
  second.add(2, other + 0.25);
  second.add(2, 0.0);
  const double last_s = first_s(n - 1, n, 3);
  history.reinit(second.faults, second.s, names, 2, comm);
  double linear = 0, ends = 0, quadratic = 0;
  bool   shapes = true;
  for (unsigned int i = 0; i < second.s.size(); ++i)
    {
      const auto   h = history.committed(i);
      const double s = second.s[i];
      shapes         = shapes && h.size() == names[second.faults[i]].size();
      if (second.faults[i] == 0 && h.size() == 2)
        {
          // Held at the end points beyond them.
          const double at = s < 0 ? 0. : s > last_s ? last_s : s;
          const double e =
            std::max(std::abs(h[0] - (2 * at + 1)), std::abs(h[1] + at)) /
            (2 * last_s + 1);
          (s < 0 || s > last_s ? ends : linear) =
            std::max(s < 0 || s > last_s ? ends : linear, e);
        }
      if (second.faults[i] == 2 && h.size() == 1)
        {
          // Fault 2's old points are at 0.5, 1.5, ... (n of them).
          const double lo = std::floor(s - 0.5) + 0.5;
          double       expected;
          if (s <= 0.5)
            expected = 0.25;
          else if (lo + 1 > n - 0.5)
            expected = (n - 0.5) * (n - 0.5);
          else
            {
              const double w = s - lo;
              expected       = (1 - w) * lo * lo + w * (lo + 1) * (lo + 1);
            }
          quadratic = std::max(quadratic, std::abs(h[0] - expected));
        }
    }
  check(shapes, "the new mesh's points have their laws' numbers of components");
  std::ostringstream largest;
  largest << std::scientific << std::setprecision(1)
          << Utilities::MPI::max(linear, comm);
  check(Utilities::MPI::max(linear, comm) < 1e-13,
        "a linear profile is carried exactly between the old points of all "
        "ranks (largest relative error " +
          largest.str() + ")");
  check(Utilities::MPI::max(ends, comm) < 1e-13,
        "beyond the ends the end point's values are held");
  check(Utilities::MPI::max(quadratic, comm) < 1e-13,
        "a component of another fault is its linear interpolant");

  // A checkpoint: gathered, restored into a new history, on these points.
  const std::vector<double> records = history.gather(comm);
  FaultHistory              restored;
  restored.restore(records);
  restored.reinit(second.faults, second.s, names, 7, comm);
  bool same = true;
  for (unsigned int i = 0; i < second.s.size(); ++i)
    {
      const auto a = history.committed(i), b = restored.committed(i);
      same = same && a.size() == b.size();
      for (unsigned int c = 0; same && c < a.size(); ++c)
        same = a[c] == b[c];
    }
  check(same, "gather, restore and reinit give the same values bit for bit");

  // Records of another law: fault 2 with two components.
  std::vector<std::vector<std::string>> other_names = names;
  other_names[2]                                    = {"c", "d"};
  FaultHistory wrong;
  wrong.restore(records);
  std::string message;
  try
    {
      wrong.reinit(second.faults, second.s, other_names, 8, comm);
    }
  catch (const ComputationError &e)
    {
      message = e.what();
    }
  check(message.find("written with another law") != std::string::npos,
        "records with another number of components are refused: <" + message +
          ">");
  message.clear();
  try
    {
      history.set_trial(0, {1.0});
    }
  catch (const ComputationError &e)
    {
      message = e.what();
    }
  check(message.find("returned 1 history components") != std::string::npos,
        "a law's history of the wrong size is refused: <" + message + ">");
  return n_failed == 0 ? 0 : 1;
}
