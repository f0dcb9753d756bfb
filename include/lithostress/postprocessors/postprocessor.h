#ifndef lithostress_postprocessors_postprocessor_h
#define lithostress_postprocessors_postprocessor_h

#include <deal.II/base/parameter_handler.h>

#include <lithostress/base/plugin_registry.h>
#include <lithostress/postprocessors/simulator_access.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * One result of a run, computed from the solution and written into the
   * output directory: point values, the surface profile, fault output,
   * force balance, figures, statistics and so on (in the spirit of
   * ASPECT's postprocessor plugins). Each postprocessor declares and parses
   * its own parameters and is called at the moments of a run below (each
   * with an empty default); it reads the
   * run only through SimulatorAccess. Adding one is its own files and one
   * line, LITHOSTRESS_REGISTER_POSTPROCESSOR, in its source file.
   */
  template <int dim>
  class Postprocessor
  {
  public:
    virtual ~Postprocessor() = default;

    /** Read the parameters once the model is known (the mesh exists, no
     * DoFs yet); throws InputError naming the entry. */
    virtual void
    parse_parameters(ParameterHandler &, const SimulatorAccess<dim> &)
    {
    }

    /**
     * After the solve of refinement cycle @p cycle. Columns of the
     * convergence table go into the current row of @p study, report text
     * for the cycle's progress line into @p progress.
     */
    virtual void
    cycle_finished(const SimulatorAccess<dim> &,
                   const unsigned int,
                   ConvergenceStudy &,
                   std::ostream &)
    {
    }

    /**
     * After cycle @p cycle's report, once it is known whether it is the
     * last cycle (@p last): files written per refinement cycle. Not called
     * for the cycles that start a visco-elastic run.
     */
    virtual void
    cycle_output(const SimulatorAccess<dim> &, const unsigned int, const bool)
    {
    }

    /** At output time number @p index (model time @p time [s]) of the
     * visco-elastic loop. */
    virtual void
    output_time(const SimulatorAccess<dim> &, const unsigned int, const double)
    {
    }

    /** After a solve that stopped with an error, with its last iterate as
     * the solution: what lets the user see where it went wrong. */
    virtual void
    solve_failed(const SimulatorAccess<dim> &)
    {
    }

    /** After the last cycle or time step. */
    virtual void
    finish(const SimulatorAccess<dim> &)
    {
    }

    /** The run was stopped at a safe point (Ctrl-C, SIGTERM): write what
     * describes the run so far. */
    virtual void
    interrupted(const SimulatorAccess<dim> &)
    {
    }

    /** State kept in a checkpoint of the visco-elastic loop (rows written
     * so far), as named strings. */
    virtual void
    save(std::map<std::string, std::string> &) const
    {
    }

    /** Restore the state of save() on resuming; rewrite its files. */
    virtual void
    load(const SimulatorAccess<dim> &,
         const std::map<std::string, std::string> &)
    {
    }
  };

  /** The postprocessors, in calling order (their registered positions). */
  template <int dim>
  using PostprocessorRegistry = PluginRegistry<Postprocessor<dim>>;

  /**
   * The run's postprocessors, in the order they are called (which is the
   * order of the convergence table's columns and of the log's lines).
   */
  template <int dim>
  class PostprocessorList
  {
  public:
    /** Declare the parameters of every registered postprocessor. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Create every registered postprocessor and parse its parameters. */
    void
    parse_parameters(ParameterHandler &prm, const SimulatorAccess<dim> &access);

    /** Call the moment of the same name of every postprocessor. */
    void
    cycle_finished(const SimulatorAccess<dim> &access,
                   const unsigned int          cycle,
                   ConvergenceStudy           &study,
                   std::ostream               &progress);
    void
    cycle_output(const SimulatorAccess<dim> &access,
                 const unsigned int          cycle,
                 const bool                  last);
    void
    output_time(const SimulatorAccess<dim> &access,
                const unsigned int          index,
                const double                time);
    void
    interrupted(const SimulatorAccess<dim> &access);
    void
    solve_failed(const SimulatorAccess<dim> &access);
    void
    finish(const SimulatorAccess<dim> &access);
    void
    save(std::map<std::string, std::string> &state) const;
    void
    load(const SimulatorAccess<dim>               &access,
         const std::map<std::string, std::string> &state);

  private:
    std::vector<std::unique_ptr<Postprocessor<dim>>> postprocessors;
  };
} // namespace lithostress

/**
 * Register the postprocessor class template @p classname (with a static
 * `declare_parameters(ParameterHandler &)`) under @p name, called at
 * @p position among the others (the convergence table's columns and the
 * log's lines come out in this order); one line in its source file.
 */
#define LITHOSTRESS_REGISTER_POSTPROCESSOR(classname,           \
                                           name,                \
                                           description,         \
                                           position)            \
  LITHOSTRESS_REGISTER_PLUGIN(                                  \
    ::lithostress::PostprocessorRegistry<2>,                    \
    {name,                                                      \
     description,                                               \
     [](ParameterHandler &prm, ParameterHandler *) {            \
       classname<2>::declare_parameters(prm);                   \
     },                                                         \
     []() -> std::unique_ptr<::lithostress::Postprocessor<2>> { \
       return std::make_unique<classname<2>>();                 \
     },                                                         \
     position})

#endif
