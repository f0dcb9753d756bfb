#ifndef lithostress_faults_fault_interface_h
#define lithostress_faults_fault_interface_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <lithostress/base/gravity_field.h>
#include <lithostress/boundary_conditions/rigid_body_support.h>
#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/faults/coulomb_friction.h>
#include <lithostress/faults/interface_law.h>
#include <lithostress/geometry/fault_trace.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The faults of a model (thesis chapter 5) as interfaces between two
   * displacement fields (FiniteElementSpace with two fields, FE_Nothing on
   * the other side; doc/faults.md), so the displacement may jump across
   * the faults' faces, and each fault's interface law ties its two sides
   * together.
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
   * interface law, an InterfaceLaw plug-in (faults/interface_law.h) chosen
   * by `Interface law`; the built-in ones: `elastic`: the traction K w with K =
   * diag(k_s, k_n) per unit fault area [Pa/m] in the fault's (shear, normal)
   * frame, a face term ∫ [v]·K [u] ds between the two fields (assemble()),
   * integrated at the Gauss-Lobatto points of whichever side is finer.
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
   * for_each_interface_point().
   *
   * A fault that ends inside the body (FaultTrace::begin_s, end_s: a
   * buried tip) keeps its whole trace as the cut between the two fields,
   * and the faces of the trace beyond its ends are a welded extension:
   * their two sides are tied by the locked law's constraints whatever the
   * fault's law, before any other fault constraint, so the jump is zero
   * at a tip's node, and they have no face terms and no interface points.
   * The fault's own faces keep its law. Since the welded displacement is
   * continuous, the solution is that of a body cut by the fault's own
   * part only.
   *
   * The members are defined by concern: parameters and queries in
   * fault_interface.cc, the topology (identification, two-colouring, FE
   * indices, face pairs, cliques) in fault_topology.cc, the constraints in
   * fault_constraints.cc, and the interface quadrature with its face terms
   * in fault_assembly.cc.
   */
  template <int dim>
  class FaultInterface
  {
  public:
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
       * its upper end (the surface trace or a buried tip) [m]. */
      double depth = 0, distance = 0;
      /** The depth d of the friction law's overburden (ρ_l − ρ_w) g d
       * [m]: `depth`, or below y = 0 (`Overburden depth from = sea
       * level`). */
      double overburden_depth = 0;
      /** Whether the point is a buried end of its fault (a tip): its node
       * is welded, the jump there is zero and the law does not act. */
      bool at_tip = false;
    };

    /**
     * What for_each_interface_point() shows its visitor at an interface
     * point (thesis chapter 5: the fault's two nodes at a point, here the
     * two fields' traces), valid during the call: the point, the jump of
     * the solution there, and the face pair's DoFs with the jump of each
     * one's shape function, which is all a law's face terms need.
     */
    struct PointValues
    {
      /** The point's number on this rank (the order of
       * interface_quadrature(); FaultHistory's index). */
      unsigned int index;
      /** The point, its fault and the fault's frame there. */
      const InterfacePoint &point;
      /** w = u(hanging wall) − u(footwall) of the solution (zero without
       * one). */
      const Tensor<1, dim> &jump;
      /** The face pair's DoFs: the field-0 cell's, then the field-1
       * cell's. */
      const std::vector<types::global_dof_index> &dofs;
      /** [φ_i] = φ_i(hanging wall) − φ_i(footwall) at the point, for each
       * of those DoFs. */
      const std::vector<Tensor<1, dim>> &shape_jumps;
      /** Whether this is the face pair's last point: what a visitor summed
       * over the pair's points is complete and can be added to global
       * objects. */
      bool last_of_pair;
      /** The DoFs (x, y) of the node at this point on the side that exact
       * contact constrains: field 1 where it has a node here, else field
       * 0 (the finer side of a hanging face). node[0] is the node's key
       * (ContactState). */
      const std::array<types::global_dof_index, dim> &node;
      /** [φ]·e_d of that node's DoF of component d: +1 if its side is the
       * hanging wall, −1 if the footwall. */
      double node_sign;
      /** Where that node is (its side's mapped point; on a curved hanging
       * face the coarser side's mapping puts `point` O(h³) away). */
      const Point<dim> &node_position;
      /** The DoFs (x, y) of the finer side's node at this point (field 1's
       * on faces of equal level) and the sign of their jumps: the node
       * whose reaction is the contact traction times its Lobatto weight
       * (NormalContact), which the constrained node's is not where it is
       * the coarser side's. */
      const std::array<types::global_dof_index, dim> &reaction_node;
      double                                          reaction_sign;
      /** The face pair's field-0 and field-1 cells (for a law that reads
       * the bulk beside the fault, as FSHEAR's element stresses). */
      const typename DoFHandler<dim>::active_cell_iterator &minus_cell,
        &plus_cell;
    };

    /** A visitor of the interface points (for_each_interface_point()). */
    using PointVisitor = std::function<void(const PointValues &values)>;

    /** Exact normal contact: whether the node with the key @p node
     * (PointValues::node[0]) is open (its normal jump free). */
    using ContactState = std::function<bool(types::global_dof_index node)>;

    /**
     * The face terms of an interface law on one face pair, summed over its
     * points by an assembling visitor (thesis chapter 5's fault element
     * stiffness and forces, here integrated over the finer side's face):
     * at the pair's last point the visitor adds them through the
     * constraints to its global matrix or vectors (with
     * PointValues::dofs) and clears them. The linearisation of a law at
     * the jump w, t(w') ≈ t + D (w' − w) = D w' + c, makes the tangent
     * ∫ [v]·D [u] ds, the affine part −∫ [v]·c ds on the right-hand side
     * and the internal force ∫ [v]·t ds.
     */
    class FaceTerms
    {
    public:
      /** Zero terms for the face pairs of @p fe_space's two fields. */
      explicit FaceTerms(const FiniteElementSpace<dim> &fe_space);

      /** matrix(i, j) += [φ_i]·D [φ_j] JxW at the point @p values with
       * the law's tangent @p tangent = D. */
      void
      add_tangent(const PointValues &values, const Tensor<2, dim> &tangent);

      /** rhs(i) −= [φ_i]·c JxW at the point @p values with the affine
       * part @p affine = c = t − D w of the law's linearisation. */
      void
      add_affine(const PointValues &values, const Tensor<1, dim> &affine);

      /** force(i) += [φ_i]·t JxW at the point @p values with the law's
       * traction @p traction = t. */
      void
      add_traction(const PointValues &values, const Tensor<1, dim> &traction);

      /** Zero the terms, for the next face pair. */
      void
      clear();

      FullMatrix<double> matrix;
      Vector<double>     rhs, force;
    };

    /** Declare `Faults` with a subsection per name of `Faults/Names` in
     * @p first_pass. */
    static void
    declare_parameters(ParameterHandler &prm, ParameterHandler *first_pass);

    /** Read the section for the faults @p traces of the geometry: each must
     * be named in `Faults/Names`, and each name must be a fault of the
     * geometry; lengths are in units of @p length_scale metres; the
     * frictional law's lithostatic and pore pressures take g from the
     * model's @p gravity. Throws InputError naming the entry. */
    void
    parse_parameters(ParameterHandler              &prm,
                     const std::vector<FaultTrace> &traces,
                     const GravityField            &gravity,
                     const double                   length_scale);

    /** Find each fault's faces on the coarse mesh of @p triangulation
     * (its level 0, the same on every rank), with those of the welded
     * extensions beyond buried tips, cut the body along them into blocks
     * and give each block a field. Throws InputError if a fault has no
     * faces of its own in the mesh, its trace does not split the body
     * (its two sides are connected around an end inside the body), meets
     * or crosses another fault, or the blocks cannot be given two
     * fields. */
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

    /**
     * Exact normal contact of the elastic and frictional faults with
     * `Normal stiffness = exact`: add to @p constraints, at every node of
     * their faces that @p is_open does not call open, n·w = 0 (the normal
     * jump is zero), as one constraint on the node's component along which
     * n is largest, of the side PointValues::node names; the nodes' other
     * DoFs and a component constrained already (a boundary condition) are
     * left alone.
     */
    void
    add_contact_constraints(const DoFHandler<dim>         &dof_handler,
                            const FiniteElementSpace<dim> &fe_space,
                            AffineConstraints<double>     &constraints,
                            const ContactState            &is_open) const;

    /** Whether an elastic or frictional fault has exact normal contact
     * (its normal traction is a constraint's reaction). */
    bool
    contact() const;

    /** Whether the faults need FrictionalSlidingSolver: a frictional law
     * (nonlinear) or exact normal contact (constraints with an active set,
     * reactions as normal tractions). */
    bool
    needs_sliding_solver() const
    {
      return frictional() || contact();
    }

    /** The depth d of fault @p k's overburden (ρ_l − ρ_w) g d at
     * @p position [m]: below the fault's upper end, or below y = 0 with
     * `Overburden depth from = sea level`. */
    double
    overburden_depth(const unsigned int k, const Point<dim> &position) const
    {
      return faults[k].law->overburden_from_sea_level()
               ? -position[1]
               : faults[k].trace.depth(position);
    }

    /** Whether fault @p k has exact normal contact (no normal spring). */
    bool
    exact_contact(const unsigned int k) const
    {
      return faults[k].law->exact_contact();
    }

    /** Whether a fault adds face terms to the matrix (an elastic or
     * frictional law). */
    bool
    has_face_terms() const;

    /** Whether fault @p k adds face terms (an elastic or frictional law). */
    bool
    has_face_terms(const unsigned int k) const
    {
      return faults[k].law->has_face_terms();
    }

    /** Whether a fault's law is nonlinear (slides). */
    bool
    frictional() const;

    /** The interface law of fault @p k. */
    const InterfaceLaw<dim> &
    law(const unsigned int k) const
    {
      return *faults[k].law;
    }

    /** The names of the history each fault's law keeps, by fault
     * (FaultHistory::reinit()). */
    std::vector<std::vector<std::string>>
    history_names() const;

    /** The Coulomb friction of fault @p k (an elastic or frictional law),
     * for the thesis's iteration and FSHEAR's element stresses (thesis
     * §5.5), which are defined for it alone; a ComputationError for
     * another law. */
    const CoulombFriction &
    coulomb_friction(const unsigned int k) const;

    /** The stiffness of the law at @p point while it sticks (the elastic
     * law): D = k_s s⊗s + k_n n⊗n, in the (x, y) frame; k_s s⊗s alone in
     * exact contact, where constraints hold the normal jump. */
    Tensor<2, dim>
    stuck_tangent(const InterfacePoint &point) const
    {
      const Tensor<2, 2> K = faults[point.fault].law->stuck_stiffness();
      return K[0][0] * outer_product(point.shear, point.shear) +
             K[1][1] * outer_product(point.normal, point.normal);
    }

    /** The inputs of fault @p point's law at @p point with the jump
     * @p jump (in the (x, y) frame), the history @p history and the step
     * @p time_step [s]. */
    static InterfaceLawInputs
    law_inputs(const InterfacePoint          &point,
               const Tensor<1, dim>          &jump,
               const ArrayView<const double> &history,
               const double                   time_step = 0)
    {
      InterfaceLawInputs in;
      in.shear_jump       = jump * point.shear;
      in.normal_jump      = jump * point.normal;
      in.overburden_depth = point.overburden_depth;
      in.welded           = point.at_tip;
      in.history          = history;
      in.time_step        = time_step;
      return in;
    }

    /** The trace of fault @p k. */
    const FaultTrace &
    trace(const unsigned int k) const
    {
      return faults[k].trace;
    }

    /** "fault <a>" or "faults <a>, <b>": the faults the sliding solver
     * solves (frictional, or elastic in exact contact), for messages. */
    std::string
    frictional_names() const;

    /** The DoFs of each locally owned footwall cell together with those of
     * its hanging-wall neighbours across fault faces with face terms: the
     * extra couplings of the matrix's sparsity. */
    std::vector<std::vector<types::global_dof_index>>
    interface_cliques(const DoFHandler<dim> &dof_handler) const;

    /** The blocks the faults cut the body into (identify()), whose
     * rigid-body motions RigidBodySupport tests: one without faults. */
    RigidBodies<dim>
    blocks() const;

    /** The two blocks on either side of fault @p k (each fault runs from
     * boundary to boundary and meets no other inside the body, so it has
     * one block on each side). */
    std::pair<unsigned int, unsigned int>
    blocks_of_fault(const unsigned int k) const
    {
      return fault_blocks[k];
    }

    /** The quadrature points of the fault faces with face terms whose
     * footwall cell is locally owned, each holding its fault's two blocks
     * together with the identity stiffness: how every elastic or
     * frictional fault holds before anything slides (the elastic
     * predictor; RigidBodySupport::check). */
    std::vector<BodyCoupling<dim>>
    interface_points(const DoFHandler<dim>         &dof_handler,
                     const FiniteElementSpace<dim> &fe_space) const;

    /** Add the face terms of elastic faults to @p matrix (if given;
     * compressed again afterwards) and what prescribed displacements on
     * their DoFs contribute through them to @p rhs, via @p constraints
     * (thesis chapter 5's fault element springs, per unit area). */
    void
    assemble(const DoFHandler<dim>           &dof_handler,
             const FiniteElementSpace<dim>   &fe_space,
             const AffineConstraints<double> &constraints,
             TrilinosWrappers::SparseMatrix  *matrix,
             TrilinosWrappers::MPI::Vector   &rhs) const;

    /**
     * Call @p visitor at every interface point of this rank, in the order
     * of interface_quadrature(), face pair by face pair, with the jump of
     * @p solution (ghosted; nullptr = zero jump) there: the one loop over
     * the faults' faces that assembles their terms (with FaceTerms),
     * evaluates their tractions and samples them (thesis chapter 5 and
     * §5.5's FSHEAR, which visits the fault's node pairs likewise). The
     * points are the Gauss-Lobatto points of the finer side's face of
     * each face pair with face terms whose field-0 cell is locally owned,
     * in the fault's exact frame.
     */
    void
    for_each_interface_point(const DoFHandler<dim>               &dof_handler,
                             const FiniteElementSpace<dim>       &fe_space,
                             const TrilinosWrappers::MPI::Vector *solution,
                             const PointVisitor &visitor) const;

    /** This rank's interface points, in the order in which
     * for_each_interface_point() numbers them (FaultHistory's
     * points; thesis §5.5). */
    std::vector<InterfacePoint>
    interface_quadrature(const DoFHandler<dim>         &dof_handler,
                         const FiniteElementSpace<dim> &fe_space) const;

  private:
    struct Fault
    {
      FaultTrace trace;
      /** Its interface law (`Interface law`). */
      std::shared_ptr<InterfaceLaw<dim>> law;
      /** The law's name, for messages. */
      std::string law_name;
    };

    /** What for_each_face_pair() calls per face pair: (fault, minus cell,
     * face, subface, plus cell, plus face, subface; the subface of the
     * coarser side or invalid). */
    using FacePairVisitor = std::function<
      void(const unsigned int                                    fault,
           const typename DoFHandler<dim>::active_cell_iterator &minus,
           const unsigned int                                    minus_face,
           const unsigned int                                    minus_subface,
           const typename DoFHandler<dim>::active_cell_iterator &plus,
           const unsigned int                                    plus_face,
           const unsigned int                                    plus_subface)>;

    /** Call @p pair for every face pair of a fault with face terms whose
     * field-0 ("minus") cell is locally owned; the finer side's face is
     * the one integrated over. */
    void
    for_each_face_pair(const DoFHandler<dim> &dof_handler,
                       const FacePairVisitor &pair) const;

    /** The interface point of fault @p fault at @p position with the
     * weight @p JxW: the fault's exact frame, depth and distance there. */
    InterfacePoint
    interface_point(const unsigned int fault,
                    const Point<dim>  &position,
                    const double       JxW) const;

    /** The constraints of the faults that @p which selects: every
     * component of the jump tied (to the prescribed jump at @p time), or
     * with @p contact only the normal one at the nodes it does not call
     * open. */
    void
    tie_faces(const DoFHandler<dim>                    &dof_handler,
              const FiniteElementSpace<dim>            &fe_space,
              AffineConstraints<double>                &constraints,
              const double                              time,
              const std::function<bool(const Fault &)> &which,
              const ContactState                       *contact) const;

    /** identify()'s second half: the blocks between the faults' coarse
     * faces (coarse_face_fault), their fields (a two-colouring) and
     * numbers, and each fault's two blocks. */
    void
    cut_into_blocks(const Triangulation<dim> &triangulation);

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
    /** Each coarse cell's block (0, 1, ...), and each fault's two
     * blocks. */
    std::vector<unsigned int>                          coarse_block;
    std::vector<std::pair<unsigned int, unsigned int>> fault_blocks;
    std::vector<std::array<int, GeometryInfo<dim>::faces_per_cell>>
      coarse_face_fault;
    /** Whether each coarse face on a fault lies on its welded extension
     * beyond a buried tip (FaultTrace::on_fault_part). */
    std::vector<std::array<bool, GeometryInfo<dim>::faces_per_cell>>
      coarse_face_welded;

    /** Whether face @p face of @p cell lies on a fault's welded
     * extension. */
    template <class Iterator>
    bool
    welded(const Iterator &cell, const unsigned int face) const
    {
      return coarse_face_welded[coarse_index(cell)][face];
    }
  };
} // namespace lithostress

#endif
