#ifndef lithostress_time_integration_checkpoint_h
#define lithostress_time_integration_checkpoint_h

#include <deal.II/base/parameter_handler.h>

#include <mpi.h>

#include <string>

namespace lithostress
{
  using namespace dealii;

  /**
   * Where the checkpoints of a visco-elastic run live and how one is
   * chosen (issue 15, doc/architecture.md). Each checkpoint is a directory
   * `checkpoint-<step>` in the output directory, with the mesh and the
   * fields (p4est's save, the creep strain, start rate and displacement
   * attached: readable on any number of ranks), the loop's state
   * (`state.txt`) and the model it belongs to (`model.prm`). The file
   * `checkpoint.current` names the last complete one and is replaced
   * atomically after the directory is complete, so a run killed at any
   * moment leaves the previous checkpoint valid.
   */
  class Checkpoint
  {
  public:
    /** The model of @p prm as text: every entry except those that may
     * change on resuming (output, solver, resources, time stepping). */
    static std::string
    model_text(ParameterHandler &prm);

    /** The directory of the current checkpoint in @p output_directory, or
     * an empty string if there is none. */
    static std::string
    current(const std::string &output_directory);

    /**
     * Check before anything is written that a run with @p prm can resume
     * from @p output_directory: a current checkpoint exists and belongs to
     * the same model. Throws InputError naming Time stepping/Resume.
     */
    static void
    check_resumable(const std::string &output_directory,
                    ParameterHandler  &prm,
                    const MPI_Comm     communicator);

    /** Make @p directory the current checkpoint (rank 0; atomic) and remove
     * the older checkpoint directories. */
    static void
    make_current(const std::string &output_directory,
                 const std::string &directory);
  };
} // namespace lithostress

#endif
