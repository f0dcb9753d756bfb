#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/base/time_units.h>
#include <lithostress/time_integration/time_stepping.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace lithostress
{
  namespace
  {
    const std::string section = "Time stepping/";
  } // namespace

  void
  TimeStepping::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time stepping");
    prm.declare_entry("Enabled",
                      "false",
                      Patterns::Bool(),
                      "Run the visco-elastic time loop (thesis §3.9): the "
                      "elastic response at t = 0, then Maxwell creep of every "
                      "material with a viscosity to the end time. false = one "
                      "elastic solve per refinement cycle.");
    prm.declare_entry("Time unit",
                      "s",
                      Patterns::Selection("s|years|kyr|Myr"),
                      "Unit of every time entry of this section (a year is "
                      "365.25 days); all output is in seconds.");
    prm.declare_entry("End time",
                      "0",
                      Patterns::Double(),
                      "End of the run [time unit]; must be positive.");
    prm.declare_entry("First time step",
                      "0",
                      Patterns::Double(),
                      "Length of the first step [time unit]; 0 = sqrt(2 "
                      "tolerance) times the shortest Maxwell time eta/G.");
    prm.declare_entry("Minimum time step",
                      "0",
                      Patterns::Double(0),
                      "A step that would have to be shorter ends the run "
                      "with an error [time unit]; 0 = 1e-9 of the end time.");
    prm.declare_entry("Maximum time step",
                      "0",
                      Patterns::Double(0),
                      "Upper bound of the step [time unit]; 0 = none.");
    prm.declare_entry("Adaptive time steps",
                      "true",
                      Patterns::Bool(),
                      "Control the step by an estimate of its local error: "
                      "repeat a step whose estimate exceeds the Creep strain "
                      "tolerance with a shorter one, double the step while "
                      "the estimate stays below a quarter (BDF2: an eighth) "
                      "of it. false = constant First time step (a step "
                      "halved for Newton's iteration grows back to it by "
                      "doublings).");
    prm.declare_entry("Creep strain tolerance",
                      "1e-3",
                      Patterns::Double(0),
                      "Largest estimated local error of a step's creep-strain "
                      "increment relative to the largest elastic deviatoric "
                      "strain max|s/(2G)| of the Maxwell materials: "
                      "(dt/2) max|dc/dt(end) - dc/dt(start)| for a "
                      "first-order step (dt^2/(2 tau^2) for a relaxing "
                      "Maxwell element), (8/5) max|c(end) - c(start) - "
                      "(dt/2)(dc/dt(start) + dc/dt(end))| for BDF2.");
    prm.declare_entry("Output times",
                      "",
                      Patterns::Anything(),
                      "Times at which results are written [time unit], comma "
                      "separated, ascending, within [0, End time]; steps land "
                      "on them exactly. The end time is always an output "
                      "time; 0 writes the elastic response.");
    prm.declare_entry("Scheme",
                      "BDF2",
                      Patterns::Selection("BDF2|generalized midpoint|thesis"),
                      "BDF2 = the variable-step second-order backward "
                      "difference formula with the relaxed tangent (L-stable, "
                      "one linear solve per step; its first step is "
                      "trapezoidal); generalized midpoint = the rule with "
                      "weight Theta, one linear solve per step; thesis = the "
                      "initial-strain scheme of thesis §3.9 (creep from the "
                      "average of start- and end-of-step stress, the "
                      "elastic operator, fixed-point iteration; it converges "
                      "only for steps below about 2 eta/G: bound them with "
                      "Maximum time step).");
    prm.declare_entry("Theta",
                      "1",
                      Patterns::Double(0.5, 1),
                      "Weight of the end-of-step stress in the generalized "
                      "midpoint scheme: 1 = backward Euler (first order, "
                      "L-stable), 0.5 = trapezoidal rule (second order).");
    prm.declare_entry("Fixed point tolerance",
                      "1e-6",
                      Patterns::Double(0),
                      "Thesis scheme: iterate until the largest change of the "
                      "deviatoric stress between two iterations, relative to "
                      "the largest deviatoric stress of the run so far, is "
                      "below this.");
    prm.declare_entry("Maximum fixed point iterations",
                      "50",
                      Patterns::Integer(1),
                      "Thesis scheme: a step that needs more iterations ends "
                      "the run with an error.");
    prm.declare_entry("Newton tolerance",
                      "1e-8",
                      Patterns::Double(0),
                      "Steps with a non-linear rheology (visco-elasto-"
                      "plastic): Newton's iteration of a step stops when the "
                      "largest stress its last linearisation missed, relative "
                      "to the largest deviatoric stress, is below this "
                      "(doc/equations.md section 12).");
    prm.declare_entry("Maximum Newton iterations",
                      "12",
                      Patterns::Integer(1),
                      "Steps with a non-linear rheology: a step whose Newton "
                      "iteration has not converged after this many "
                      "iterations is tried again with half the length.");
    prm.declare_entry("Newton start",
                      "extrapolation",
                      Patterns::Selection("extrapolation|step start"),
                      "Steps with a non-linear rheology: the first iterate of "
                      "a step's Newton iteration. extrapolation: the last "
                      "solutions extrapolated to the step's end (the start "
                      "on a new mesh); step start: the solution at the start "
                      "of the step (longer iterations, from farther away).");
    prm.declare_entry("Refinement interval",
                      "0",
                      Patterns::Integer(0),
                      "Refine and coarsen the mesh (Mesh refinement section, "
                      "adaptive) every this many steps, transferring the "
                      "creep strain; 0 = keep the mesh of cycle 0.");
    prm.declare_entry("Checkpoint interval",
                      "0",
                      Patterns::Integer(0),
                      "Write a checkpoint every this many steps (and always "
                      "at the end); 0 = only at the end.");
    prm.declare_entry("Resume",
                      "false",
                      Patterns::Bool(),
                      "Continue from the checkpoint in the output directory "
                      "(also: the command-line flag --resume).");
    prm.leave_subsection();
  }

  void
  TimeStepping::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time stepping");
    enabled                       = prm.get_bool("Enabled");
    unit_name                     = prm.get("Time unit");
    unit                          = unit_name == "s"       ? 1.0
                                    : unit_name == "years" ? seconds_per_year
                                    : unit_name == "kyr" ? 1e3 * seconds_per_year
                                                         : 1e6 * seconds_per_year;
    end_time                      = prm.get_double("End time") * unit;
    first_step                    = prm.get_double("First time step") * unit;
    minimum_step                  = prm.get_double("Minimum time step") * unit;
    maximum_step                  = prm.get_double("Maximum time step") * unit;
    adaptive                      = prm.get_bool("Adaptive time steps");
    tolerance                     = prm.get_double("Creep strain tolerance");
    const std::string scheme_name = prm.get("Scheme");
    scheme                        = scheme_name == "thesis" ? Scheme::thesis
                                    : scheme_name == "BDF2" ? Scheme::bdf2
                                                            : Scheme::midpoint;
    theta                         = prm.get_double("Theta");
    fixed_point_tolerance         = prm.get_double("Fixed point tolerance");
    fixed_point_max_iterations =
      prm.get_integer("Maximum fixed point iterations");
    newton_tolerance          = prm.get_double("Newton tolerance");
    newton_max_iterations     = prm.get_integer("Maximum Newton iterations");
    newton_from_extrapolation = prm.get("Newton start") == "extrapolation";
    refinement_interval       = prm.get_integer("Refinement interval");
    checkpoint_interval       = prm.get_integer("Checkpoint interval");
    resume                    = prm.get_bool("Resume");
    const std::string times   = prm.get("Output times");
    prm.leave_subsection();

    output_times.clear();
    output_at_zero = false;
    if (!enabled)
      return;
    if (!(end_time > 0))
      throw_input_error(section + "End time", "must be positive");
    if (first_step < 0)
      throw_input_error(section + "First time step", "must not be negative");
    if (first_step > end_time)
      throw_input_error(section + "First time step",
                        "is longer than the End time");
    if (maximum_step > 0 && maximum_step < minimum_step)
      throw_input_error(section + "Maximum time step",
                        "is shorter than the Minimum time step");
    if (adaptive && !(tolerance > 0))
      throw_input_error(section + "Creep strain tolerance",
                        "must be positive with adaptive time steps");
    if (!adaptive && !(first_step > 0))
      throw_input_error(section + "First time step",
                        "must be positive without adaptive time steps");
    if (minimum_step == 0)
      minimum_step = 1e-9 * end_time;
    double previous = -1;
    for (const std::string &item : split_list(times))
      {
        const double t = parse_number(item, section + "Output times") * unit;
        if (t < 0 || t > end_time * (1 + 1e-12))
          throw_input_error(section + "Output times",
                            "the time " + item + " " + unit_name +
                              " is outside [0, End time]");
        if (!(t > previous))
          throw_input_error(section + "Output times",
                            "the times must be ascending (" + item + " " +
                              unit_name + ")");
        previous = t;
        if (t == 0)
          output_at_zero = true;
        else
          output_times.push_back(std::min(t, end_time));
      }
    if (output_times.empty() || output_times.back() < end_time)
      output_times.push_back(end_time);
  }

  double
  TimeStepping::next_time(const double t, const double proposed) const
  {
    double step = proposed;
    if (maximum_step > 0)
      step = std::min(step, maximum_step);
    const auto next =
      std::upper_bound(output_times.begin(), output_times.end(), t);
    Assert(next != output_times.end(), ExcInternalError());
    // Land on the next output time exactly; stretch the step by up to 1 %
    // rather than leave a sliver.
    if (t + 1.01 * step >= *next)
      return *next;
    return t + step;
  }

  int
  TimeStepping::output_index(const double t) const
  {
    if (t == 0)
      return output_at_zero ? 0 : -1;
    const auto at = std::find(output_times.begin(), output_times.end(), t);
    return at == output_times.end()
             ? -1
             : static_cast<int>(at - output_times.begin()) + 1;
  }

  std::string
  TimeStepping::format(const double seconds) const
  {
    std::ostringstream out;
    out << std::setprecision(6) << seconds / unit << ' ' << unit_name;
    return out.str();
  }
} // namespace lithostress
