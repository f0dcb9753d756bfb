#ifndef lithostress_faults_fault_interface_h
#define lithostress_faults_fault_interface_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/faults/coulomb_friction.h>
#include <lithostress/faults/fault_trace.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The faults of a model (SPEC §3.4, thesis chapter 5) as interfaces
   * between two displacement fields (FiniteElementSpace with two fields,
   * FE_Nothing on the other side; DEALII-9.4.1-NOTES.md), so the
   * displacement may jump across the faults' faces, and each fault's
   * interface law ties its two sides together.
   *
   * Several faults: identify() finds each fault's faces on the coarse mesh,
   * cuts the body along them into blocks and gives neighbouring blocks
   * different fields (a two-colouring), so field 0 is a fault's footwall
   * on one fault and its hanging wall on another; every law is written in
   * the fault's own terms, w = u(hanging wall) − u(footwall) and the normal
   * n into the hanging wall, and the face terms and constraints orient it
   * per face. A fault that does not split the body, faults that meet or
   * cross, and blocks that two fields cannot separate are input errors.
   *
   * The `Faults` section names each fault of the geometry and gives its
   * interface law. `elastic`: the traction K w with K = diag(k_s, k_n) per
   * unit fault area [Pa/m] in the fault's (shear, normal) frame, a face
   * term ∫ [v]·K [u] ds between the two fields (assemble()), integrated at
   * the Gauss-Lobatto points of whichever side is finer.
   * `locked`: exact continuity by constraints
   * (never a penalty): on fault faces of equal level the field-1 side's
   * DoFs equal the field-0 side's; where one side is finer, its trace is
   * constrained to the coarse side's polynomial (faces whose field-0 side
   * is finer: the coarse field-1 DoFs equal the coinciding field-0
   * nodes, the field-0 side's other nodes the coarse trace's
   * interpolation), so that every constraint points from field 1, or from
   * inside a fine field-0 face, towards field-0 nodes: no cycles, and the
   * same constraints on every rank.
   * `prescribed slip`: the jump is given, w = slip(s, t) d + opening(s, t)
   * n (kinematic, as PyLith's faults), exact through the locked
   * constraints with inhomogeneities: the nodes of each side satisfy
   * u⁺ = u⁻ + w at the node.
   * `frictional`: the elastic law with Coulomb sliding (CoulombFriction),
   * a nonlinear law solved by FrictionalSlidingSolver through
   * assemble_interface().
   */
  template <int dim>
  class FaultInterface
  {
  public:
    /** The interface law of a fault. */
    enum class Law
    {
      locked,
      elastic,
      frictional,
      prescribed_slip
    };

    /** A point of the interface quadrature (on the finer side's face). */
    struct InterfacePoint
    {
      /** The fault it lies on (index into the geometry's faults). */
      unsigned int fault = 0;
      Point<dim>   position;
      double       JxW = 0;
      /** n: the fault's normal into the hanging wall; s: n turned
       * clockwise, the law's shear direction. */
      Tensor<1, dim> normal, shear;
      /** Depth below the top surface and distance along the fault from
       * its surface trace [m]. */
      double depth = 0, distance = 0;
    };

    /**
     * An interface law at the point number @p index of this rank (in the
     * order of interface_quadrature()): for the jump @p jump = u(hanging
     * wall) − u(footwall) it sets the traction @p traction = σ n on the
     * footwall's face and its derivative @p tangent = ∂t/∂w, in the
     * (x, y) frame.
     */
    using PointLaw = std::function<void(const unsigned int    index,
                                        const InterfacePoint &point,
                                        const Tensor<1, dim> &jump,
                                        Tensor<1, dim>       &traction,
                                        Tensor<2, dim>       &tangent)>;

    /** Declare `Faults` with a subsection per name of `Faults/Names` in
     * @p first_pass. */
    static void
    declare_parameters(ParameterHandler &prm, ParameterHandler *first_pass);

    /** Read the section for the faults @p traces of the geometry: each must
     * be named in `Faults/Names`, and each name must be a fault of the
     * geometry; lengths are in units of @p length_scale metres. Throws
     * InputError naming the entry. */
    void
    parse_parameters(ParameterHandler              &prm,
                     const std::vector<FaultTrace> &traces,
                     const double                   length_scale);

    /** Find each fault's faces on the coarse mesh of @p triangulation
     * (its level 0, the same on every rank), cut the body along them into
     * blocks and give each block a field. Throws InputError if a fault has
     * no faces in the mesh, does not split the body (its two sides are
     * connected around an end inside the body), meets or crosses another
     * fault, or the blocks cannot be given two fields. */
    void
    identify(const Triangulation<dim> &triangulation);

    /** Whether the model has a fault (two displacement fields). */
    bool
    active() const
    {
      return !faults.empty();
    }

    /** The number of faults. */
    unsigned int
    n_faults() const
    {
      return faults.size();
    }

    /** Set each locally owned active cell's FE index: its block's field
     * (before DoFHandler::distribute_dofs). */
    void
    set_active_fe_indices(DoFHandler<dim> &dof_handler) const;

    /** Add the interface constraints of locked faults, and of faults with
     * prescribed slip at time @p time [s], to @p constraints (after the
     * hanging-node and boundary constraints: a DoF that is already
     * constrained keeps its constraint). */
    void
    add_constraints(const DoFHandler<dim>         &dof_handler,
                    const FiniteElementSpace<dim> &fe_space,
                    AffineConstraints<double>     &constraints,
                    const double                   time = 0) const;

    /** Whether a fault adds face terms to the matrix (an elastic or
     * frictional law). */
    bool
    has_face_terms() const;

    /** Whether fault @p k adds face terms (an elastic or frictional law). */
    bool
    has_face_terms(const unsigned int k) const
    {
      return faults[k].law == Law::elastic || faults[k].law == Law::frictional;
    }

    /** Whether a fault slides by Coulomb friction (a nonlinear law). */
    bool
    frictional() const;

    /** The interface law of fault @p k as a CoulombFriction (an elastic
     * fault's never slides). */
    const CoulombFriction &
    friction(const unsigned int k) const
    {
      return faults[k].friction;
    }

    /** The stiffness of the law at @p point while it sticks (the elastic
     * law): D = k_s s⊗s + k_n n⊗n, in the (x, y) frame. */
    Tensor<2, dim>
    stuck_tangent(const InterfacePoint &point) const
    {
      const CoulombFriction &law = friction(point.fault);
      return law.shear_stiffness * outer_product(point.shear, point.shear) +
             law.normal_stiffness * outer_product(point.normal, point.normal);
    }

    /** The trace of fault @p k. */
    const FaultTrace &
    trace(const unsigned int k) const
    {
      return faults[k].trace;
    }

    /** "fault <a>" or "faults <a>, <b>": the frictional faults, for
     * messages. */
    std::string
    frictional_names() const;

    /** The DoFs of each locally owned footwall cell together with those of
     * its hanging-wall neighbours across fault faces with face terms: the
     * extra couplings of the matrix's sparsity. */
    std::vector<std::vector<types::global_dof_index>>
    interface_cliques(const DoFHandler<dim> &dof_handler) const;

    /** Quadrature points (with their JxW) of the fault faces with face
     * terms whose footwall cell is locally owned: where an elastic fault
     * holds one side against the other (RigidBodySupport). */
    std::vector<std::pair<Point<dim>, double>>
    interface_points(const DoFHandler<dim>         &dof_handler,
                     const FiniteElementSpace<dim> &fe_space) const;

    /** Add the face terms of elastic faults to @p matrix (if given;
     * compressed again afterwards) and what prescribed displacements on
     * their DoFs contribute through them to @p rhs, via @p constraints. */
    void
    assemble(const DoFHandler<dim>           &dof_handler,
             const FiniteElementSpace<dim>   &fe_space,
             const AffineConstraints<double> &constraints,
             TrilinosWrappers::SparseMatrix  *matrix,
             TrilinosWrappers::MPI::Vector   &rhs) const;

    /**
     * The interface law @p law at every interface point, for the jump of
     * @p solution (ghosted; nullptr = zero jump), added through
     * @p constraints to whichever of these is given: @p matrix gets
     * ∫ [v]·D [u] ds; @p rhs gets −∫ [v]·(t − D w) ds, so that the
     * law's linearisation at w, t(w') ≈ t + D (w' − w), is an affine law
     * of the next solution (with the inhomogeneities of @p constraints);
     * @p force gets ∫ [v]·t ds, the interface's internal force
     * (condensed, without inhomogeneities). [v] = v⁺ − v⁻. Compresses
     * what it adds to.
     */
    void
    assemble_interface(const DoFHandler<dim>               &dof_handler,
                       const FiniteElementSpace<dim>       &fe_space,
                       const AffineConstraints<double>     &constraints,
                       const TrilinosWrappers::MPI::Vector *solution,
                       const PointLaw                      &law,
                       TrilinosWrappers::SparseMatrix      *matrix,
                       TrilinosWrappers::MPI::Vector       *rhs,
                       TrilinosWrappers::MPI::Vector       *force) const;

    /** This rank's interface points, in the order in which
     * assemble_interface() numbers them. */
    std::vector<InterfacePoint>
    interface_quadrature(const DoFHandler<dim>         &dof_handler,
                         const FiniteElementSpace<dim> &fe_space) const;

  private:
    struct Fault
    {
      FaultTrace trace;
      Law        law = Law::locked;
      /** k_s, k_n per unit fault area [Pa/m] (elastic and frictional
       * laws), μ and the effective normal stress's terms (frictional). */
      CoulombFriction friction;
      /** Prescribed slip: slip and opening [m] as functions of the
       * distance s along the fault [m] and the time t [s]. */
      std::shared_ptr<FunctionParser<1>> slip, opening;
    };

    /** Call @p pair(fault, minus cell, face, subface, plus cell, plus
     * face, subface; the subface of the coarser side or invalid) for every
     * face pair of a fault with face terms whose field-0 ("minus") cell is
     * locally owned; the finer side's face is the one integrated over. */
    void
    for_each_face_pair(
      const DoFHandler<dim> &dof_handler,
      const std::function<
        void(const unsigned int                                    fault,
             const typename DoFHandler<dim>::active_cell_iterator &minus,
             const unsigned int                                    minus_face,
             const unsigned int minus_subface,
             const typename DoFHandler<dim>::active_cell_iterator &plus,
             const unsigned int                                    plus_face,
             const unsigned int plus_subface)> &pair) const;

    /** The coarse cell (level 0) that @p cell descends from. */
    template <class Iterator>
    unsigned int
    coarse_index(const Iterator &cell) const
    {
      typename Triangulation<dim>::cell_iterator ancestor = cell;
      while (ancestor->level() > 0)
        ancestor = ancestor->parent();
      return ancestor->index();
    }

    /** The fault that face @p face of @p cell lies on (-1: none). A
     * fault face of an active cell lies on the same face of its coarse
     * ancestor, since the fields are constant on coarse cells. */
    template <class Iterator>
    int
    fault_of(const Iterator &cell, const unsigned int face) const
    {
      return coarse_face_fault[coarse_index(cell)][face];
    }

    std::vector<Fault> faults;
    /** identify()'s results: each coarse cell's field, and the fault of
     * each of its faces (-1: none). */
    std::vector<unsigned char> coarse_field;
    std::vector<std::array<int, GeometryInfo<dim>::faces_per_cell>>
      coarse_face_fault;
  };
} // namespace lithostress

#endif
