#ifndef lithostress_postprocessors_point_values_output_h
#define lithostress_postprocessors_point_values_output_h

#include <lithostress/postprocessors/postprocessor.h>

#include <string>
#include <vector>

namespace lithostress
{
  /**
   * Displacement and stress at the points of `Convergence study/Points`:
   * point_values.csv and columns of the convergence table each cycle, and
   * in the visco-elastic loop one row per output time and point of
   * point_history.csv (`time,point,x,y,u_x,u_y,s_xx,s_yy,s_xy,s_zz`, SI).
   */
  template <int dim>
  class PointValuesOutput : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler           &prm,
                     const SimulatorAccess<dim> &access) override;

    void
    cycle_finished(const SimulatorAccess<dim> &access,
                   const unsigned int          cycle,
                   ConvergenceStudy           &study,
                   std::ostream               &progress) override;

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
    /** Rewrite point_history.csv with all rows so far. */
    void
    write_history(const SimulatorAccess<dim> &access) const;

    std::vector<Point<dim>>  points;
    std::vector<std::string> history;
  };
} // namespace lithostress

#endif
