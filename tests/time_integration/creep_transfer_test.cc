/**
 * The history field of the rock laws at the cell quadrature points
 * (CellHistory), here with five named components (a creep strain and one
 * more, as a law that creeps and yields would keep), under mesh changes,
 * on any number of ranks (issues 15 and 50, verification 4):
 * 1. A field that is a polynomial of degree 2 in each coordinate (what a
 *    DG field on 3 x 3 Gauss nodes represents exactly) survives ten cycles
 *    of random refinement and coarsening to round-off (1e-12 relative) at
 *    every node of the final mesh.
 * 2. For a smooth field that is not such a polynomial, a coarsen-then-
 *    refine cycle (projection onto the parents, evaluation at the
 *    children's nodes) loses accuracy at the projection's rate: the error
 *    falls as h^3 under global refinement (rate > 2.7 between the two
 *    finest meshes), the interpolation error of Q2 nodes.
 * Prints "FAILED" and exits 1 on any failure.
 */
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>

#include <lithostress/materials/cell_history.h>

#include <cmath>
#include <iostream>

using namespace dealii;
using namespace lithostress;

namespace
{
  constexpr unsigned int         n_points_1d = 3;
  const std::vector<std::string> names       = {"creep_xx",
                                                "creep_yy",
                                                "creep_xy",
                                                "creep_zz",
                                                "plastic_strain"};
  const MappingQ1<2>             mapping;
  const FE_Q<2>                  linear(1);

  /** Component c of a field at x: a polynomial of degree 2 per coordinate
   * (@p smooth false), or a smooth non-polynomial one. */
  double
  field_value(const Point<2>    &x,
              const unsigned int component,
              const bool         smooth)
  {
    const double c = component;
    if (smooth)
      return std::sin(3 * x[0] + c) * std::cos(2 * x[1] - c);
    return 1 + c + (2 - c) * x[0] - 3 * x[1] + x[0] * x[1] * (c + 1) +
           0.5 * x[0] * x[0] * x[1] * x[1] - c * x[1] * x[1];
  }

  /** Call @p f(cell, exact) for every owned cell with the field's exact
   * values at the cell's nodes. */
  template <typename Operation>
  void
  for_owned_cells(const CellHistory<2>   &creep,
                  const Triangulation<2> &tria,
                  const bool              smooth,
                  const Operation        &f)
  {
    FEValues<2>                 values(mapping,
                       linear,
                       creep.quadrature(),
                       update_quadrature_points);
    std::vector<Vector<double>> exact(creep.quadrature().size(),
                                      Vector<double>(creep.n_components()));
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          for (unsigned int q = 0; q < exact.size(); ++q)
            for (unsigned int c = 0; c < creep.n_components(); ++c)
              exact[q][c] = field_value(values.quadrature_point(q), c, smooth);
          f(cell, exact);
        }
  }

  void
  set_field(CellHistory<2>         &creep,
            const Triangulation<2> &tria,
            const bool              smooth)
  {
    for_owned_cells(creep,
                    tria,
                    smooth,
                    [&](const auto &cell, const auto &exact) {
                      creep.set(cell, exact);
                    });
    creep.update_ghost_values();
  }

  /** Largest |stored − exact| at the nodes, over all ranks. */
  double
  node_error(const CellHistory<2>   &creep,
             const Triangulation<2> &tria,
             const bool              smooth)
  {
    std::vector<Vector<double>> stored;
    double                      error = 0;
    for_owned_cells(
      creep, tria, smooth, [&](const auto &cell, const auto &exact) {
        creep.get(cell, stored);
        for (unsigned int q = 0; q < stored.size(); ++q)
          for (unsigned int c = 0; c < creep.n_components(); ++c)
            error = std::max(error, std::abs(stored[q][c] - exact[q][c]));
      });
    return Utilities::MPI::max(error, tria.get_communicator());
  }

  /** Flags from the cell's centre only, so that the mesh does not depend
   * on the partition. */
  void
  mark_randomly(parallel::distributed::Triangulation<2> &tria,
                const unsigned int                       round)
  {
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const Point<2> c = cell->center();
          const double   r = std::fmod(std::abs(std::sin(12.9898 * c[0] +
                                                       78.233 * c[1] + round) *
                                              43758.5453),
                                     1.0);
          if (r < 0.3 && cell->level() < 6)
            cell->set_refine_flag();
          else if (r > 0.6 && cell->level() > 1)
            cell->set_coarsen_flag();
        }
  }
  /** The mesh of the checkpoint test: refined twice, then three rounds
   * of mark_randomly(). */
  void
  make_checkpoint_mesh(parallel::distributed::Triangulation<2> &tria)
  {
    tria.refine_global(2);
    for (unsigned int round = 0; round < 3; ++round)
      {
        mark_randomly(tria, round);
        tria.execute_coarsening_and_refinement();
      }
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
  bool       ok   = true;
  const auto report =
    [&](const bool condition, const std::string &what, const double value) {
      if (root)
        std::cout << (condition ? "ok   " : "FAIL ") << what << ": " << value
                  << std::endl;
      ok = ok && condition;
    };

  // 1. Exactness for the representable field under random adaptivity.
  {
    parallel::distributed::Triangulation<2> tria(comm);
    GridGenerator::hyper_cube(tria, -1, 1);
    tria.refine_global(3);
    CellHistory<2> creep(tria, n_points_1d, names);
    creep.setup();
    set_field(creep, tria, false);
    unsigned int coarsened_cells = 0;
    for (unsigned int round = 0; round < 10; ++round)
      {
        mark_randomly(tria, round);
        tria.prepare_coarsening_and_refinement();
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned() && cell->coarsen_flag_set())
            ++coarsened_cells;
        creep.prepare_for_mesh_change();
        tria.execute_coarsening_and_refinement();
        creep.finish_mesh_change();
      }
    coarsened_cells = Utilities::MPI::sum(coarsened_cells, comm);
    report(coarsened_cells > 100,
           "cells coarsened over the ten rounds",
           coarsened_cells);
    report(tria.n_global_levels() > 4,
           "levels of the final mesh",
           tria.n_global_levels());
    const double error = node_error(creep, tria, false);
    report(error < 1e-12 * 10,
           "degree-2 field after 10 refine/coarsen rounds, largest nodal "
           "error (field of size ~10)",
           error);
  }

  // 2. A smooth field: one coarsen-then-refine cycle, on meshes of
  // decreasing h.
  std::vector<double> errors;
  for (unsigned int level = 3; level <= 5; ++level)
    {
      parallel::distributed::Triangulation<2> tria(comm);
      GridGenerator::hyper_cube(tria, -1, 1);
      tria.refine_global(level);
      CellHistory<2> creep(tria, n_points_1d, names);
      creep.setup();
      set_field(creep, tria, true);
      for (const bool coarsen : {true, false})
        {
          for (const auto &cell : tria.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                if (coarsen)
                  cell->set_coarsen_flag();
                else
                  cell->set_refine_flag();
              }
          creep.prepare_for_mesh_change();
          tria.execute_coarsening_and_refinement();
          creep.finish_mesh_change();
        }
      report(tria.n_global_active_cells() == (1u << (2 * level)),
             "smooth field: back on the mesh of level",
             level);
      errors.push_back(node_error(creep, tria, true));
      report(true,
             "smooth field: nodal error after coarsen + refine",
             errors.back());
    }
  const double rate = std::log2(errors[1] / errors[2]);
  report(rate > 2.7,
         "smooth field: rate in h between the two finest meshes",
         rate);

  // 3. A checkpoint written on this number of ranks and read back on the
  // number given as the second argument's rank count: the same values at
  // every node (with the partition changed by p4est). Usage:
  // creep_transfer_test save <file> | load <file>.
  if (argc == 3)
    {
      const std::string                       mode = argv[1], file = argv[2];
      parallel::distributed::Triangulation<2> tria(comm);
      GridGenerator::hyper_cube(tria, -1, 1);
      if (mode == "save")
        {
          make_checkpoint_mesh(tria);
          CellHistory<2> creep(tria, n_points_1d, names);
          creep.setup();
          set_field(creep, tria, true);
          creep.prepare_for_checkpoint();
          tria.save(file);
          report(true,
                 "checkpoint written, cells",
                 tria.n_global_active_cells());
        }
      else
        {
          tria.load(file);
          CellHistory<2> creep(tria, n_points_1d, names);
          creep.load_from_checkpoint();
          const double error = node_error(creep, tria, true);
          report(error == 0,
                 "checkpoint read on " +
                   std::to_string(Utilities::MPI::n_mpi_processes(comm)) +
                   " rank(s): largest difference at the nodes",
                 error);
          // The same mesh made anew on this number of ranks.
          parallel::distributed::Triangulation<2> again(comm);
          GridGenerator::hyper_cube(again, -1, 1);
          make_checkpoint_mesh(again);
          report(tria.n_global_active_cells() ==
                     again.n_global_active_cells() &&
                   tria.n_global_levels() == again.n_global_levels(),
                 "cells of the loaded mesh, the same as the saved one's",
                 tria.n_global_active_cells());
        }
    }

  return ok ? 0 : (root ? (std::cout << "FAILED" << std::endl, 1) : 1);
}
