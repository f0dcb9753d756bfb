#ifndef lithostress_postprocessors_paraview_output_h
#define lithostress_postprocessors_paraview_output_h

#include <lithostress/postprocessors/solution_output.h>
#include <lithostress/postprocessors/postprocessor.h>

namespace lithostress
{
  /** The ParaView series solution.pvd (SolutionOutput): one step per
   * refinement cycle, or per output time of the visco-elastic loop. */
  template <int dim>
  class ParaviewOutput : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler           &prm,
                     const SimulatorAccess<dim> &access) override;

    void
    cycle_output(const SimulatorAccess<dim> &access,
                 const unsigned int          cycle,
                 const bool                  last) override;

    void
    output_time(const SimulatorAccess<dim> &access,
                const unsigned int          index,
                const double                time) override;

    void
    save(std::map<std::string, std::string> &state) const override;

    void
    load(const SimulatorAccess<dim>                &access,
         const std::map<std::string, std::string> &state) override;

  private:
    SolutionOutput<dim> output;
  };
} // namespace lithostress

#endif
