#include <deal.II/base/data_out_base.h>
#include <deal.II/numerics/data_out.h>

#include <lithostress/analysis/stress_postprocessor.h>
#include <lithostress/base/input_error.h>
#include <lithostress/base/output_file.h>
#include <lithostress/postprocessors/solution_output.h>

#include <fstream>

namespace lithostress
{
  template <int dim>
  void
  SolutionOutput<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Write ParaView files",
                      "true",
                      Patterns::Bool(),
                      "Write .pvtu/.vtu files per cycle and a .pvd record.");
    prm.declare_entry("ParaView cycles",
                      "all",
                      Patterns::Selection("all|last"),
                      "Write ParaView files for every refinement cycle or "
                      "only for the last.");
    prm.declare_entry("Subdivisions",
                      "0",
                      Patterns::Integer(0, 8),
                      "Patch subdivisions per cell; 0 = the polynomial "
                      "degree (higher-order Lagrange cells).");
    prm.leave_subsection();
  }

  template <int dim>
  void
  SolutionOutput<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    enabled      = prm.get_bool("Write ParaView files");
    last_only    = prm.get("ParaView cycles") == "last";
    subdivisions = prm.get_integer("Subdivisions");
    prm.leave_subsection();
  }

  template <int dim>
  void
  SolutionOutput<dim>::write(const std::string                   &directory,
                             const unsigned int                   index,
                             const double                         time,
                             const DoFHandler<dim>               &dof_handler,
                             const FiniteElementSpace<dim>       &fe_space,
                             const StressModel<dim>              &stress_model,
                             const GriffithFailure               &griffith,
                             const TrilinosWrappers::MPI::Vector &solution)
  {
    if (!enabled)
      return;
    const StressPostprocessor<dim> postprocessor(stress_model,
                                                 fe_space.mapping(),
                                                 fe_space.n_fields(),
                                                 griffith);
    DataOut<dim>                   data_out;
    DataOutBase::VtkFlags          flags;
    flags.write_higher_order_cells = true;
    flags.compression_level        = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(solution, postprocessor);

    const auto   &tria = dof_handler.get_triangulation();
    Vector<float> material_id(tria.n_active_cells());
    Vector<float> rank(tria.n_active_cells());
    unsigned int  cell_index = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        if (cell->is_locally_owned())
          {
            material_id(cell_index) = cell->material_id();
            rank(cell_index)        = cell->subdomain_id();
          }
        ++cell_index;
      }
    data_out.add_data_vector(material_id, "material_id");
    data_out.add_data_vector(rank, "mpi_rank");
    const CellHistory<dim> *history = stress_model.attached_cell_history();
    Vector<float>           maxwell_time(tria.n_active_cells());
    if (history != nullptr)
      {
        // The components the laws name (MaxwellRheology: creep_xx,
        // creep_yy, creep_xy, creep_zz); none where no law keeps a history.
        if (history->n_components() > 0)
          data_out.add_data_vector(history->dof_handler(),
                                   history->values(),
                                   history->names());
        cell_index = 0;
        for (const auto &cell : tria.active_cell_iterators())
          {
            if (cell->is_locally_owned())
              maxwell_time(cell_index) =
                stress_model.rheology(cell->material_id()).relaxation_time();
            ++cell_index;
          }
        data_out.add_data_vector(maxwell_time, "maxwell_time");
      }
    // The non-linear laws' effective viscosity, strain rate and yielding.
    const CellHistory<dim> *flow = stress_model.attached_flow_state();
    if (flow != nullptr && flow->n_components() > 0)
      data_out.add_data_vector(flow->dof_handler(),
                               flow->values(),
                               flow->names());
    data_out.build_patches(fe_space.mapping(),
                           subdivisions == 0 ? fe_space.degree() : subdivisions,
                           DataOut<dim>::curved_inner_cells);
    // Each rank writes its piece, rank 0 the .pvtu listing them and then
    // the .pvd: every file appears complete (OutputFile), and a record only
    // once the pieces it lists are there.
    const MPI_Comm     comm    = dof_handler.get_communicator();
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int my_rank = Utilities::MPI::this_mpi_process(comm);
    const std::string  base  = "solution_" + Utilities::int_to_string(index, 3);
    const auto         piece = [&](const unsigned int r) {
      return base + "." +
             Utilities::int_to_string(r,
                                      Utilities::needed_digits(n_ranks - 1)) +
             ".vtu";
    };
    on_all_ranks(comm, [&]() {
      OutputFile vtu(directory + "/" + piece(my_rank), OutputFile::binary);
      data_out.write_vtu(vtu);
      vtu.commit();
    });
    on_all_ranks(comm, [&]() {
      if (my_rank != 0)
        return;
      std::vector<std::string> pieces;
      for (unsigned int r = 0; r < n_ranks; ++r)
        pieces.push_back(piece(r));
      OutputFile pvtu(directory + "/" + base + ".pvtu");
      data_out.write_pvtu_record(pvtu, pieces);
      pvtu.commit();
      records.emplace_back(time, base + ".pvtu");
      OutputFile pvd(directory + "/solution.pvd");
      DataOutBase::write_pvd_record(pvd, records);
      pvd.commit();
    });
  }

  template class SolutionOutput<2>;
} // namespace lithostress
