#ifndef lithostress_time_integration_checkpoint_h
#define lithostress_time_integration_checkpoint_h

#include <deal.II/base/parameter_handler.h>

#include <boost/serialization/version.hpp>

#include <mpi.h>

#include <map>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /** What one accepted time step did: a row of time_steps.csv. */
  struct StepRecord
  {
    unsigned int       step = 0;
    double             time = 0, dt = 0;
    unsigned long long dofs = 0, cells = 0;
    unsigned int       linear_iterations = 0, nonlinear_iterations = 0;
    unsigned int       rejected = 0;
    /** max ‖Δc‖ and the step's relative local error estimate. */
    double creep_increment = 0, error_estimate = 0;
    double wall_time = 0;
    /** Newton's iteration of a non-linear step: the last relative
     * residual, and all of them (for the progress line). */
    double      newton_residual = 0;
    std::string newton_residuals;

    /** boost::serialization of the record. */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &step &time &dt &dofs &cells &linear_iterations
        &nonlinear_iterations &rejected &creep_increment &error_estimate
          &wall_time &newton_residual &newton_residuals;
    }
  };

  /**
   * The visco-elastic loop's state besides the mesh and the fields: the
   * time, the step control, the rows written so far, the faults' history
   * along them (FaultHistory::gather()'s records), the components of the
   * cell history attached to the mesh (HistoryLayout::names()) and the
   * postprocessors' named state.
   */
  struct LoopState
  {
    unsigned int step = 0, linear_solves = 0;
    double       time = 0, dt = 0, strain_scale = 0, stress_scale = 0;
    /** The length of the last accepted step (BDF2's c_{n-1}). */
    double                             previous_dt = 0;
    std::vector<StepRecord>            steps;
    std::vector<double>                fault_history;
    std::vector<std::string>           cell_history;
    std::map<std::string, std::string> postprocessors;
    /** The times of the solutions the SolutionPredictor knew, whose
     * vectors are attached to the mesh after the displacement (version 1;
     * a version-0 checkpoint has none). */
    std::vector<double> predictor_times;

    /** boost::serialization of the state. */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int version)
    {
      archive &step &linear_solves &time &dt &strain_scale &stress_scale
        &previous_dt &steps &fault_history &cell_history &postprocessors;
      if (version > 0)
        archive &predictor_times;
    }
  };

  /**
   * Where the checkpoints of a visco-elastic run live and how one is
   * chosen (issue 15, doc/architecture.md). Each checkpoint is a directory
   * `checkpoint-<step>` in the output directory, with the mesh and the
   * fields (p4est's save, the creep strain c_n and c_{n-1}, the start rate
   * and the displacement attached: readable on any number of ranks), the
   * loop's state (`state.txt`: LoopState as a boost::serialization text
   * archive) and the model it belongs to (`model.prm`). The file
   * `checkpoint.current` names the last complete one and is replaced
   * atomically after the directory is complete, so a run killed at any
   * moment leaves the previous checkpoint valid.
   */
  class Checkpoint
  {
  public:
    /** Write @p state and the model @p model_text into @p directory
     * (rank 0; every file written under a temporary name and renamed). */
    static void
    write_state(const std::string &directory,
                const LoopState   &state,
                const std::string &model_text);

    /** Read the state of write_state() from @p directory; a
     * ComputationError if it is damaged or of another format. */
    static LoopState
    read_state(const std::string &directory);

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

BOOST_CLASS_VERSION(lithostress::LoopState, 1)

#endif
