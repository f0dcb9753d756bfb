// Unit test of fault identification and two-colouring (FaultInterface;
// thesis chapters 5–6, doc/faults.md): a 100 × 20 km layered box cut by
// two normal faults dipping 63.43° towards each other (a graben), refined
// with hanging nodes on one fault. Checks that the blocks get two fields
// alternately (the graben one field, both shoulders the other), that every
// interface point lies on its fault with a unit normal into the hanging
// wall and the shear direction turned clockwise from it, that the depth
// is the depth below the top, and that the interface quadrature measures
// each fault's length exactly; on 1 or more ranks. Prints one "ok ..." or
// "FAIL ..." line per check and returns non-zero on a failure.

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>

#include <lithostress/base/gravity_field.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/faults/fault_interface.h>
#include <lithostress/geometry/geometry_model.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <set>
#include <string>

using namespace lithostress;

namespace
{
  unsigned int n_failed = 0;
  bool         root     = true;

  void
  check(const bool ok, const std::string &what)
  {
    if (root)
      std::cout << (ok ? "ok " : "FAIL ") << what << std::endl;
    if (!ok)
      ++n_failed;
  }

  /** The faults' surface traces [m] and their horizontal offset per metre
   * of depth (1/tan 63.43° = 1/2). */
  constexpr double west_x = 30e3, east_x = 70e3, run = 0.5;

  /** x of fault @p k (0 west, dipping right; 1 east, dipping left) at
   * height @p y (≤ 0). */
  double
  fault_x(const unsigned int k, const double y)
  {
    return k == 0 ? west_x - run * y : east_x + run * y;
  }

  const char *model = R"(subsection Geometry
  set Model = layered box
  set Length unit = km
  subsection Layered box
    set Width = 100
    set Layer interfaces = 0, -20
    set Layer names = plate
    set Cells per layer = 2
    set Cells across = 10
    set Fault names = west, east
    set Fault surface x = 30, 70
    set Fault dip = 63.43494882292201
    set Fault dips towards = right, left
  end
end
subsection Faults
  set Names = west, east
  subsection west
    set Interface law = elastic
    set Shear stiffness = 1e9
    set Normal stiffness = 1e9
  end
  subsection east
    set Interface law = elastic
    set Shear stiffness = 1e9
    set Normal stiffness = 1e9
  end
end
)";
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  root = Utilities::MPI::this_mpi_process(comm) == 0;

  // The model, read as the program reads it (two passes, strict).
  const std::string file =
    "fault_identification_" +
    std::to_string(Utilities::MPI::this_mpi_process(comm)) + ".prm";
  std::ofstream(file) << model;
  ParameterHandler prm;
  ParameterFile::read(
    file,
    {},
    [](ParameterHandler &p, ParameterHandler *first_pass) {
      GeometrySelector<2>::declare_parameters(p);
      FaultInterface<2>::declare_parameters(p, first_pass);
    },
    prm);
  std::remove(file.c_str());
  const auto   geometry     = GeometrySelector<2>::create(prm);
  const double length_scale = GeometrySelector<2>::length_scale(prm);

  parallel::distributed::Triangulation<2> tria(
    comm, Triangulation<2>::limit_level_difference_at_vertices);
  geometry->create_coarse_mesh(tria);
  FaultInterface<2> faults;
  faults.parse_parameters(prm,
                          geometry->fault_traces(),
                          GravityField(),
                          length_scale);
  faults.identify(tria);
  check(faults.n_faults() == 2, "two faults identified");

  // Refine once, then the footwall cells along the west fault once more:
  // hanging nodes on the fault from the footwall side.
  tria.refine_global(1);
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned())
      {
        const Point<2> c = cell->center();
        if (c[0] < fault_x(0, c[1]) && c[0] > fault_x(0, c[1]) - 6e3)
          cell->set_refine_flag();
      }
  tria.execute_coarsening_and_refinement();

  const FiniteElementSpace<2> fe_space(2, 1, 2);
  DoFHandler<2>               dof_handler(tria);
  faults.set_active_fe_indices(dof_handler);
  dof_handler.distribute_dofs(fe_space.fe_collection());

  // Two-colouring: the field of every cell is that of its block; the
  // graben (between the faults) has one field, both shoulders the other.
  unsigned int lowest[3] = {2, 2, 2}, highest[3] = {0, 0, 0};
  for (const auto &cell : dof_handler.active_cell_iterators())
    if (cell->is_locally_owned())
      {
        const Point<2>     c     = cell->center();
        const unsigned int block = c[0] < fault_x(0, c[1])   ? 0
                                   : c[0] < fault_x(1, c[1]) ? 1
                                                             : 2;
        const unsigned int field = fe_space.field_of(cell->active_fe_index());
        lowest[block]            = std::min(lowest[block], field);
        highest[block]           = std::max(highest[block], field);
      }
  for (unsigned int b = 0; b < 3; ++b)
    {
      lowest[b]  = Utilities::MPI::min(lowest[b], comm);
      highest[b] = Utilities::MPI::max(highest[b], comm);
    }
  const char *block_name[] = {"west shoulder", "graben", "east shoulder"};
  for (unsigned int b = 0; b < 3; ++b)
    check(lowest[b] == highest[b] && lowest[b] < 2,
          std::string("one field in the ") + block_name[b]);
  check(lowest[0] == lowest[2] && lowest[1] != lowest[0],
        "the graben's field differs from both shoulders'");

  // The blocks (RigidBodySupport's bodies): three, one per region, where
  // the fields are two; each fault between the graben and its shoulder.
  const RigidBodies<2> blocks             = faults.blocks();
  unsigned int         block_of_region[3] = {0, 0, 0};
  bool                 one_block[3] = {true, true, true}, seen[3] = {};
  for (const auto &cell : dof_handler.active_cell_iterators())
    if (cell->is_locally_owned())
      {
        const Point<2>     c      = cell->center();
        const unsigned int region = c[0] < fault_x(0, c[1])   ? 0
                                    : c[0] < fault_x(1, c[1]) ? 1
                                                              : 2;
        const unsigned int b      = blocks.of(cell);
        one_block[region] =
          one_block[region] && (!seen[region] || b == block_of_region[region]);
        block_of_region[region] = b;
        seen[region]            = true;
      }
  // The ranks that own cells of a region must agree on its block.
  bool blocks_ok = blocks.n == 3;
  for (unsigned int r = 0; r < 3; ++r)
    {
      const unsigned int lo =
        Utilities::MPI::min(seen[r] ? block_of_region[r] : 3U, comm);
      const unsigned int hi =
        Utilities::MPI::max(seen[r] ? block_of_region[r] : 0U, comm);
      blocks_ok          = blocks_ok && one_block[r] && lo == hi;
      block_of_region[r] = lo;
    }
  blocks_ok       = Utilities::MPI::min(blocks_ok ? 1 : 0, comm) == 1;
  const auto west = faults.blocks_of_fault(0), east = faults.blocks_of_fault(1);
  check(blocks_ok && block_of_region[0] != block_of_region[2] &&
          std::set<unsigned int>{west.first, west.second} ==
            std::set<unsigned int>{block_of_region[0], block_of_region[1]} &&
          std::set<unsigned int>{east.first, east.second} ==
            std::set<unsigned int>{block_of_region[1], block_of_region[2]},
        "three blocks where there are two fields, each fault between the "
        "graben and its shoulder");

  // The interface points: on their fault, normal into the hanging wall
  // (the graben for both faults), shear = normal turned clockwise.
  const auto points    = faults.interface_quadrature(dof_handler, fe_space);
  double     length[2] = {0, 0}, off_fault = 0, frame = 0, depth = 0;
  bool       into_graben = true;
  for (const auto &p : points)
    {
      const unsigned int k = p.fault;
      const Point<2>    &x = p.position;
      // Distance to the line x = fault_x(k, y): |Δx| sin(dip).
      off_fault = std::max(off_fault,
                           std::abs(x[0] - fault_x(k, x[1])) / std::sqrt(1.25));
      // Down the fault: the west one moves right with depth, the east one
      // left.
      Tensor<1, 2> along;
      along[0] = k == 0 ? run : -run;
      along[1] = -1;
      frame    = std::max({frame,
                           std::abs(p.normal.norm() - 1),
                           std::abs(p.shear.norm() - 1),
                           std::abs(p.normal * along) / along.norm(),
                           std::abs(p.shear[0] - p.normal[1]),
                           std::abs(p.shear[1] + p.normal[0])});
      into_graben =
        into_graben && (k == 0 ? p.normal[0] > 0.8 : p.normal[0] < -0.8);
      depth = std::max(depth, std::abs(p.depth + x[1]));
      length[k] += p.JxW;
    }
  off_fault   = Utilities::MPI::max(off_fault, comm);
  frame       = Utilities::MPI::max(frame, comm);
  depth       = Utilities::MPI::max(depth, comm);
  into_graben = Utilities::MPI::min(into_graben ? 1 : 0, comm) == 1;
  Utilities::MPI::sum(length, comm, length);
  const unsigned long long n_points =
    Utilities::MPI::sum<unsigned long long>(points.size(), comm);
  if (root)
    std::cout << "  " << n_points << " interface points; largest distance "
              << off_fault << " m, frame error " << frame << ", depth error "
              << depth << " m; lengths " << length[0] << ", " << length[1]
              << " m" << std::endl;
  check(n_points > 0, "interface points on the faults");
  // Straight faults in straight cells: exact up to round-off of
  // coordinates of 1e5 m.
  check(off_fault < 1e-6, "every interface point lies on its fault");
  check(frame < 1e-12,
        "unit normal and shear, normal across the fault, "
        "shear turned clockwise");
  check(into_graben, "the normal points into the hanging wall (the graben)");
  check(depth < 1e-6, "depth = depth below the top surface");
  const double exact = 20e3 * std::sqrt(1.25);
  for (unsigned int k = 0; k < 2; ++k)
    check(std::abs(length[k] - exact) < 1e-12 * exact,
          std::string("the quadrature measures the ") +
            (k == 0 ? "west" : "east") + " fault's length 20 km/sin(dip)");

  if (root)
    std::cout << (n_failed == 0 ? "all checks passed"
                                : std::to_string(n_failed) + " check(s) failed")
              << std::endl;
  return n_failed == 0 ? 0 : 1;
}
