#include <lithostress/faults/sliding_context.h>

namespace lithostress
{
  namespace
  {
    /** The entries of `Faults/Sliding solver` that choose and tune the
     * linear solver of the sliding steps (the caller is in that
     * subsection). */
    void
    declare_linear_solver_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Linear solver",
        "automatic",
        Patterns::Selection("automatic|AMG|direct|multigrid"),
        "The preconditioner of each sliding step's Krylov "
        "solve (CG in exact contact, GMRES with the normal "
        "spring): AMG = the elasticity AMG with the rigid "
        "modes of each block (Chebyshev smoothing in exact "
        "contact; ILU with the stiff spring); direct = a "
        "sparse factorisation of the tangent (its Cholesky "
        "factor in exact contact on one rank, else Amesos "
        "KLU), kept until the iterations it costs beyond its "
        "first solve's outnumber what making it costs in "
        "iterations (a count, so that runs repeat themselves; "
        "the later steps' tangents differ only at the "
        "fault) and across the time steps of one step size; "
        "multigrid = a geometric multigrid V-cycle on the two "
        "fields with Galerkin coarse operators (exact contact), "
        "kept in the same way (made again when the open set "
        "changes, or when kept levels stall); "
        "automatic = in exact contact, direct on one rank up "
        "to Multigrid limit DoFs, above it multigrid, handing "
        "over to direct up to Direct solver limit where the "
        "multigrid is slow (Multigrid limit), and multigrid "
        "on several ranks; with the normal spring direct on "
        "one rank up to Direct solver limit, else AMG. The "
        "goal-oriented dual "
        "problems take the same in exact contact (KLU with "
        "the normal spring).");
      prm.declare_entry("Multigrid smoother degree",
                        "4",
                        Patterns::Integer(1, 20),
                        "Linear solver = multigrid (or automatic choosing "
                        "it): the degree of the Chebyshev smoother on each "
                        "level of the two fields' V-cycle (products with the "
                        "level matrix per smoothing step), preconditioned by "
                        "the inverse of each node's block. From 27 k to "
                        "1.65 M DoFs on the thesis's normal fault, graben and "
                        "thrust the iterations per Newton step change by "
                        "+16, +12 and -16 % with 4; 6 takes about a fifth "
                        "fewer iterations, each dearer (doc/performance.md).");
      prm.declare_entry("Multigrid fault zone layers",
                        "6",
                        Patterns::Integer(0, 100),
                        "Linear solver = multigrid (or automatic choosing "
                        "it): on each level of the two fields' V-cycle, the "
                        "DoFs within this many layers of the level matrix's "
                        "graph from the fault nodes are solved exactly after "
                        "the pre-smoothing and before the post-smoothing "
                        "(0: none). On the plane thrust at 991 k DoFs 6 "
                        "layers take 53 linear iterations in 8 Newton steps "
                        "instead of 78 (doc/performance.md).");
      prm.declare_entry("Direct solver limit",
                        "2e6",
                        Patterns::Double(0),
                        "Linear solver = automatic: the largest number of "
                        "DoFs for which one rank factorises the tangent "
                        "(at 1.65e6 DoFs the run's peak memory was 2.6-3.7 KB "
                        "per DoF; doc/performance.md).");
      prm.declare_entry("Multigrid limit",
                        "2e5",
                        Patterns::Double(0),
                        "Linear solver = automatic on one rank, exact "
                        "contact: above this many DoFs (up to Direct solver "
                        "limit) the sliding steps start with the two fields' "
                        "multigrid, and hand over to the kept factorisation "
                        "if the multigrid's second solve takes more than 8 "
                        "iterations (a Newton step with the factor costs "
                        "about 8 V-cycles on the thesis's layers); below it "
                        "the factorisation. Measured at 416 k and 1.65 M "
                        "DoFs: the multigrid 13-27 % faster than the factor "
                        "on the normal fault and the graben (5 iterations per "
                        "solve), the factor 1.5-2 times faster on the "
                        "low-angle thrust (10-11; doc/performance.md).");
    }
  } // namespace

  template <int dim>
  void
  FrictionalSlidingSolver<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Faults");
    prm.enter_subsection("Sliding solver");
    prm.declare_entry("Method",
                      "newton",
                      Patterns::Selection("newton|thesis"),
                      "How a frictional fault's sliding is found: newton = "
                      "semi-smooth Newton with the consistent tangent and a "
                      "line search; thesis = the thesis's iteration (§5.5, "
                      "FSHEAR): excess shear removed by nodal forces times "
                      "the Convergence factor, re-solved with the elastic "
                      "fault.");
    prm.declare_entry("Maximum iterations",
                      "100",
                      Patterns::Integer(1),
                      "Nonlinear iterations (linear solves) before the run "
                      "stops with the last iterate written out.");
    prm.declare_entry("Residual tolerance",
                      "1e-9",
                      Patterns::Double(0),
                      "Newton stops when the residual norm is below this "
                      "times the norm of the right-hand side (and the excess "
                      "shear below its tolerance).");
    prm.declare_entry("Excess shear tolerance",
                      "1e3",
                      Patterns::Double(0),
                      "[Pa] Both methods stop when the shear traction "
                      "exceeds the friction limit (thesis) or the law the "
                      "iterate was solved with (Newton) by less than this "
                      "everywhere on the fault.");
    prm.declare_entry("Convergence factor",
                      "1",
                      Patterns::Double(0),
                      "Thesis method: the excess-shear forces are multiplied "
                      "by this (the thesis used 15 for k_s = 5e10 N/m).");
    prm.declare_entry("Hold sliding points at the limit",
                      "false",
                      Patterns::Bool(),
                      "Thesis method: true = as FSHEAR (its IIT flag), a "
                      "point whose shear exceeded the friction limit at the "
                      "first iteration has its shear moved to the limit at "
                      "every later iteration, even where it has unloaded "
                      "below it (it may slide back); false = such a point "
                      "sticks again once its shear is below the limit.");
    prm.declare_entry("Thesis stress reading",
                      "interface points",
                      Patterns::Selection("interface points|element centroids"),
                      "Thesis method: where the excess shear is read. "
                      "interface points = the fault's traction at each "
                      "interface point; element centroids = as FSHEAR, one "
                      "value per fault element (face pair): the stresses of "
                      "the two cells beside it at their centroids, with the "
                      "lithostatic stress at each centroid's depth, "
                      "averaged, less the pore pressure at the face's "
                      "midpoint, applied to all of the face's points.");
    prm.declare_entry("Line search",
                      "true",
                      Patterns::Bool(),
                      "Newton: halve the step until the residual norm "
                      "falls (at most 6 times).");
    prm.declare_entry("Linear solver tolerance",
                      "1e-11",
                      Patterns::Double(0),
                      "Relative tolerance of each linear solve of a "
                      "frictional fault (whatever Solver/Type says): the "
                      "residual is brought below this times the right-hand "
                      "side, or below Linear solver reduction times the "
                      "Newton residual, whichever is larger.");
    prm.declare_entry("Linear solver reduction",
                      "1e-3",
                      Patterns::Double(0, 1),
                      "Newton: while the points' states (stuck, sliding, "
                      "open) change, each step's linear solve stops once "
                      "its residual is below this times the current "
                      "nonlinear residual (an inexact Newton method; "
                      "Eisenstat & Walker 1996): those steps are not solved "
                      "to round-off. A step whose states stood still may be "
                      "the last and is solved to the Linear solver "
                      "tolerance, as is the first step from the time loop's "
                      "extrapolation where its states are the last "
                      "solution's (unless friction limits follow contact "
                      "reactions the tangent takes as given: Reaction in "
                      "tangent = false); so is every step with 0.");
    prm.declare_entry("Reaction in tangent",
                      "true",
                      Patterns::Bool(),
                      "Newton in exact normal contact: the tangent includes "
                      "the friction limit's dependence on the contact "
                      "reaction (mu times the tie's reaction, a linear "
                      "function of the displacement; a non-symmetric term, "
                      "solved by GMRES), so that the iteration ends in one "
                      "step once the states stand still. false: the "
                      "reaction is taken as given at each iterate, a fixed "
                      "point with Anderson acceleration (symmetric tangent, "
                      "CG), which contracts by about 0.2 per iteration on "
                      "the thrust fault.");
    declare_linear_solver_parameters(prm);
    prm.leave_subsection();
    prm.leave_subsection();
  }

  template <int dim>
  void
  FrictionalSlidingSolver<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Faults");
    prm.enter_subsection("Sliding solver");
    parameters.method =
      prm.get("Method") == "thesis" ? Method::thesis : Method::newton;
    parameters.max_iterations     = prm.get_integer("Maximum iterations");
    parameters.residual_tolerance = prm.get_double("Residual tolerance");
    parameters.excess_shear_tolerance =
      prm.get_double("Excess shear tolerance");
    parameters.convergence_factor = prm.get_double("Convergence factor");
    parameters.hold_at_limit = prm.get_bool("Hold sliding points at the limit");
    parameters.element_stresses =
      prm.get("Thesis stress reading") == "element centroids";
    parameters.line_search         = prm.get_bool("Line search");
    parameters.linear_tolerance    = prm.get_double("Linear solver tolerance");
    parameters.linear_reduction    = prm.get_double("Linear solver reduction");
    parameters.reaction_in_tangent = prm.get_bool("Reaction in tangent");
    const std::string solver       = prm.get("Linear solver");
    parameters.preconditioner      = solver == "direct" ? Preconditioner::direct
                                     : solver == "AMG"  ? Preconditioner::amg
                                     : solver == "multigrid"
                                       ? Preconditioner::multigrid
                                       : Preconditioner::automatic;
    parameters.direct_limit        = prm.get_double("Direct solver limit");
    parameters.multigrid_limit     = prm.get_double("Multigrid limit");
    parameters.smoother_degree = prm.get_integer("Multigrid smoother degree");
    parameters.fault_zone_layers =
      prm.get_integer("Multigrid fault zone layers");
    if (!(parameters.convergence_factor > 0))
      throw_input_error("Faults/Sliding solver/Convergence factor",
                        "must be positive");
    // The thesis method's readings mean nothing to Newton: say so rather
    // than ignore them.
    if (parameters.method == Method::newton &&
        (parameters.element_stresses || parameters.hold_at_limit))
      throw_input_error(std::string("Faults/Sliding solver/") +
                          (parameters.element_stresses
                             ? "Thesis stress reading"
                             : "Hold sliding points at the limit"),
                        "applies to Method = thesis only (Method is "
                        "newton)");
    for (const auto &[entry, value] :
         {std::make_pair("Residual tolerance", parameters.residual_tolerance),
          std::make_pair("Linear solver tolerance",
                         parameters.linear_tolerance)})
      if (!(value > 0))
        throw_input_error(std::string("Faults/Sliding solver/") + entry,
                          "must be positive (a tolerance of 0 is never "
                          "reached)");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  template void
  FrictionalSlidingSolver<2>::declare_parameters(ParameterHandler &);
  template void
  FrictionalSlidingSolver<2>::parse_parameters(ParameterHandler &);
} // namespace lithostress
