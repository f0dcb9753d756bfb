#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/faults/fault_interface.h>

#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace lithostress
{
  template <int dim>
  void
  FaultInterface<dim>::declare_parameters(ParameterHandler &prm,
                                          ParameterHandler *first_pass)
  {
    const std::vector<std::string> names =
      ParameterFile::names_from(first_pass, {"Faults"}, "Names", {"fault"});
    prm.enter_subsection("Faults");
    prm.declare_entry("Names",
                      "",
                      Patterns::Anything(),
                      "Comma separated names of the geometry's faults (a "
                      "layered box with `Fault surface x` has one, `fault`); "
                      "each gets a subsection with its interface law.");
    for (const std::string &name : names)
      {
        prm.enter_subsection(name);
        prm.declare_entry("Interface law",
                          "locked",
                          Patterns::Selection(
                            "locked|elastic|frictional|prescribed slip"),
                          "locked = the displacement is continuous across "
                          "the fault (exact constraints, thesis §5's "
                          "k = 1e15 N/m without its penalty); elastic = the "
                          "traction is K w, w = u(hanging wall) - "
                          "u(footwall), K = diag(Shear stiffness, Normal "
                          "stiffness) in the fault's (shear, normal) frame; "
                          "frictional = elastic until the shear traction "
                          "reaches mu |sigma_n,eff|, then Coulomb sliding "
                          "(thesis §5.5; solved by the Sliding solver); "
                          "prescribed slip = the jump is Slip along the dip "
                          "plus Opening along the normal (kinematic, exact "
                          "constraints).");
        prm.declare_entry("Slip",
                          "0",
                          Patterns::Anything(),
                          "Prescribed slip: the slip [m] down the dip "
                          "(positive = normal sense, hanging wall down) as a "
                          "function of s, the distance along the fault from "
                          "its surface trace [m], and t [s].");
        prm.declare_entry("Opening",
                          "0",
                          Patterns::Anything(),
                          "Prescribed slip: the opening [m] along the normal "
                          "(into the hanging wall) as a function of s [m] and "
                          "t [s].");
        prm.declare_entry("Shear stiffness",
                          "",
                          Patterns::Anything(),
                          "k_s per unit fault area [Pa/m] (elastic law): "
                          "the shear traction per metre of slip. The "
                          "thesis's element stiffness [N/m] is k_s times "
                          "its fault element's length (SPEC §3.4).");
        prm.declare_entry("Normal stiffness",
                          "",
                          Patterns::Anything(),
                          "k_n per unit fault area [Pa/m] (elastic law): "
                          "the normal traction per metre of opening.");
        prm.declare_entry("Thesis element length",
                          "",
                          Patterns::Anything(),
                          "For the thesis's input (SPEC §3.4): if set, the "
                          "two stiffnesses are the thesis's element "
                          "stiffnesses [N/m] of fault elements of this "
                          "length l [length unit], and the stiffness per "
                          "unit area is k/l. Empty = per unit area.");
        prm.declare_entry("Friction coefficient",
                          "0.1",
                          Patterns::Anything(),
                          "mu of the frictional law (thesis: 0.1).");
        prm.declare_entry(
          "Lithostatic density",
          "2911",
          Patterns::Anything(),
          "rho_l [kg/m^3] of the lithostatic normal stress rho_l g depth "
          "that the frictional law adds to the model's normal traction "
          "(FSHEAR's 2911, for models without body forces); 0 = none, for "
          "models whose stresses include gravity.");
        prm.declare_entry("Pore fluid density",
                          "1000",
                          Patterns::Anything(),
                          "rho_w [kg/m^3] of the hydrostatic pore pressure "
                          "rho_w g depth subtracted from the compression "
                          "(FSHEAR's 1000); 0 = dry.");
        prm.declare_entry("Gravity",
                          "9.81",
                          Patterns::Anything(),
                          "g [m/s^2] of those two terms.");
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }

  template <int dim>
  void
  FaultInterface<dim>::parse_parameters(ParameterHandler              &prm,
                                        const std::vector<FaultTrace> &traces,
                                        const double length_scale)
  {
    faults.clear();
    prm.enter_subsection("Faults");
    const std::vector<std::string> names = split_list(prm.get("Names"));
    std::string                    trace_names;
    for (const FaultTrace &trace : traces)
      trace_names += (trace_names.empty() ? "<" : ", <") + trace.name + ">";
    for (const std::string &name : names)
      {
        bool known = false;
        for (const FaultTrace &trace : traces)
          known = known || trace.name == name;
        if (!known)
          throw_input_error("Faults/Names",
                            "<" + name + "> is not a fault of the geometry" +
                              (traces.empty()
                                 ? std::string(" (it has none)")
                                 : " (its faults: " + trace_names + ")"));
      }
    for (const FaultTrace &trace : traces)
      {
        if (std::find(names.begin(), names.end(), trace.name) == names.end())
          throw_input_error("Faults/Names",
                            "the geometry has the fault <" + trace.name +
                              ">: name it here and give its Interface law");
        prm.enter_subsection(trace.name);
        Fault fault;
        fault.trace           = trace;
        const std::string law = prm.get("Interface law");
        fault.law             = law == "elastic"           ? Law::elastic
                                : law == "frictional"      ? Law::frictional
                                : law == "prescribed slip" ? Law::prescribed_slip
                                                           : Law::locked;
        if (fault.law == Law::prescribed_slip)
          {
            const auto function = [&](const std::string &name) {
              auto f = std::make_shared<FunctionParser<1>>(1, 0.0);
              try
                {
                  f->initialize("s,t",
                                prm.get(name),
                                std::map<std::string, double>(),
                                true);
                }
              catch (const std::exception &e)
                {
                  throw_input_error("Faults/" + trace.name + "/" + name,
                                    "<" + prm.get(name) +
                                      "> is not an expression of s and t");
                }
              return f;
            };
            fault.slip    = function("Slip");
            fault.opening = function("Opening");
          }
        const auto entry = [&](const std::string &name) {
          return "Faults/" + trace.name + "/" + name;
        };
        const auto number = [&](const std::string &name,
                                const double       lowest,
                                const bool         inclusive) {
          const std::string text = Utilities::trim(prm.get(name));
          if (text.empty())
            throw_input_error(entry(name), "is needed by the " + law + " law");
          const double value = parse_number(text, entry(name));
          if (inclusive ? !(value >= lowest) : !(value > lowest))
            throw_input_error(entry(name),
                              std::string("must be ") +
                                (inclusive ? "at least " : "greater than ") +
                                (lowest == 0 ? "0" : std::to_string(lowest)) +
                                ", got " + text);
          return value;
        };
        if (fault.law == Law::elastic || fault.law == Law::frictional)
          {
            CoulombFriction &f = fault.friction;
            f.shear_stiffness  = number("Shear stiffness", 0, false);
            f.normal_stiffness = number("Normal stiffness", 0, false);
            const std::string length =
              Utilities::trim(prm.get("Thesis element length"));
            if (!length.empty())
              {
                const double l =
                  number("Thesis element length", 0, false) * length_scale;
                f.shear_stiffness /= l;
                f.normal_stiffness /= l;
              }
          }
        fault.friction.slides = fault.law == Law::frictional;
        if (fault.law == Law::frictional)
          {
            CoulombFriction &f     = fault.friction;
            f.friction_coefficient = number("Friction coefficient", 0, true);
            f.lithostatic_density  = number("Lithostatic density", 0, true);
            f.pore_fluid_density   = number("Pore fluid density", 0, true);
            f.gravity              = number("Gravity", 0, true);
          }
        prm.leave_subsection();
        faults.push_back(fault);
      }
    prm.leave_subsection();
  }

  template <int dim>
  bool
  FaultInterface<dim>::has_face_terms() const
  {
    for (const Fault &fault : faults)
      if (fault.law == Law::elastic || fault.law == Law::frictional)
        return true;
    return false;
  }

  template <int dim>
  bool
  FaultInterface<dim>::frictional() const
  {
    for (const Fault &fault : faults)
      if (fault.law == Law::frictional)
        return true;
    return false;
  }

  template <int dim>
  std::string
  FaultInterface<dim>::frictional_names() const
  {
    std::string  names;
    unsigned int n = 0;
    for (const Fault &fault : faults)
      if (fault.law == Law::frictional)
        {
          names += (n++ == 0 ? "<" : ", <") + fault.trace.name + ">";
        }
    return (n > 1 ? "faults " : "fault ") + names;
  }

  template <int dim>
  void
  FaultInterface<dim>::identify(const Triangulation<dim> &triangulation)
  {
    const unsigned int n_coarse = triangulation.n_cells(0);
    coarse_field.assign(n_coarse, 0);
    coarse_face_fault.assign(n_coarse, {});
    for (auto &faces : coarse_face_fault)
      faces.fill(-1);
    if (faults.empty())
      return;
    double size = 0;
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      size = std::max(size, cell->diameter());
    const double tolerance = 1e-8 * size;

    // The faces on each fault: both vertices and the midpoint (on the
    // face's manifold) on the trace.
    std::vector<unsigned int>                      faces_on(faults.size(), 0);
    std::map<unsigned int, std::set<unsigned int>> faults_at_vertex;
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const unsigned int f : cell->face_indices())
        {
          if (cell->at_boundary(f))
            continue;
          const auto face = cell->face(f);
          for (unsigned int k = 0; k < faults.size(); ++k)
            {
              const FaultTrace &trace = faults[k].trace;
              if (trace.distance_to(face->vertex(0)) > tolerance ||
                  trace.distance_to(face->vertex(1)) > tolerance ||
                  trace.distance_to(face->center(true)) > tolerance)
                continue;
              int &entry = coarse_face_fault[cell->index()][f];
              if (entry >= 0 && entry != static_cast<int>(k))
                throw_input_error("Faults/Names",
                                  "the faults <" + faults[entry].trace.name +
                                    "> and <" + trace.name +
                                    "> run along the same cell faces");
              entry = k;
              ++faces_on[k];
              for (const unsigned int v : face->vertex_indices())
                faults_at_vertex[face->vertex_index(v)].insert(k);
            }
        }
    for (unsigned int k = 0; k < faults.size(); ++k)
      if (faces_on[k] == 0)
        throw_input_error("Faults/Names",
                          "no cell faces of the mesh lie on the fault <" +
                            faults[k].trace.name + ">");

    // Faults may share a vertex only on the boundary.
    std::set<unsigned int> boundary_vertices;
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f))
          for (const unsigned int v : cell->face(f)->vertex_indices())
            boundary_vertices.insert(cell->face(f)->vertex_index(v));
    const auto &vertices = triangulation.get_vertices();
    for (const auto &[vertex, on] : faults_at_vertex)
      if (on.size() > 1 && boundary_vertices.count(vertex) == 0)
        {
          std::ostringstream where;
          where << "the faults <" << faults[*on.begin()].trace.name << "> and <"
                << faults[*std::next(on.begin())].trace.name
                << "> meet or cross inside the body, at (" << vertices[vertex]
                << ") m";
          throw_input_error("Faults/Names", where.str());
        }

    // Blocks: the coarse cells connected across faces that are no fault's.
    std::vector<unsigned int> block(n_coarse);
    std::iota(block.begin(), block.end(), 0u);
    const std::function<unsigned int(unsigned int)> root = [&](unsigned int c) {
      while (block[c] != c)
        c = block[c] = block[block[c]];
      return c;
    };
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const unsigned int f : cell->face_indices())
        if (!cell->at_boundary(f) && coarse_face_fault[cell->index()][f] < 0)
          block[root(cell->index())] = root(cell->neighbor(f)->index());
    // Each fault must separate two blocks; neighbouring blocks get
    // different fields (breadth first over the blocks).
    std::map<unsigned int, std::vector<std::pair<unsigned int, int>>> across;
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const unsigned int f : cell->face_indices())
        {
          const int k =
            cell->at_boundary(f) ? -1 : coarse_face_fault[cell->index()][f];
          if (k < 0)
            continue;
          const unsigned int a = root(cell->index()),
                             b = root(cell->neighbor(f)->index());
          if (a == b)
            throw_input_error(
              "Faults/Names",
              "the fault <" + faults[k].trace.name +
                "> does not split the body: its two sides are connected "
                "around an end inside the body (a fault must run from "
                "boundary to boundary)");
          across[a].emplace_back(b, k);
        }
    std::map<unsigned int, unsigned char> field_of_block;
    for (unsigned int c = 0; c < n_coarse; ++c)
      {
        const unsigned int start = root(c);
        if (field_of_block.count(start) != 0)
          continue;
        field_of_block[start]           = 0;
        std::vector<unsigned int> queue = {start};
        while (!queue.empty())
          {
            const unsigned int b = queue.back();
            queue.pop_back();
            for (const auto &[next, k] : across[b])
              {
                const unsigned char want = 1 - field_of_block[b];
                const auto          it   = field_of_block.find(next);
                if (it == field_of_block.end())
                  {
                    field_of_block[next] = want;
                    queue.push_back(next);
                  }
                else if (it->second != want)
                  throw_input_error(
                    "Faults/Names",
                    "the faults split the body into blocks that two "
                    "displacement fields cannot tell apart (an odd ring of "
                    "blocks around the fault <" +
                      faults[k].trace.name + ">)");
              }
          }
      }
    for (unsigned int c = 0; c < n_coarse; ++c)
      coarse_field[c] = field_of_block[root(c)];
  }

  template <int dim>
  void
  FaultInterface<dim>::for_each_face_pair(
    const DoFHandler<dim> &dof_handler,
    const std::function<
      void(const unsigned int                                    fault,
           const typename DoFHandler<dim>::active_cell_iterator &minus,
           const unsigned int                                    minus_face,
           const unsigned int                                    minus_subface,
           const typename DoFHandler<dim>::active_cell_iterator &plus,
           const unsigned int                                    plus_face,
           const unsigned int plus_subface)> &pair_of_fault) const
  {
    const unsigned int none = numbers::invalid_unsigned_int;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned() || cell->active_fe_index() != 0)
          continue;
        for (const unsigned int f : cell->face_indices())
          {
            if (cell->at_boundary(f))
              continue;
            const int k = fault_of(cell, f);
            if (k < 0 || !has_face_terms(k))
              continue;
            const auto pair = [&](const auto &...arguments) {
              pair_of_fault(k, arguments...);
            };
            const auto neighbor = cell->neighbor(f);
            if (neighbor->has_children())
              {
                // Finer hanging wall: integrate over each child's face.
                for (unsigned int sf = 0; sf < cell->face(f)->n_children();
                     ++sf)
                  {
                    const auto child = cell->neighbor_child_on_subface(f, sf);
                    if (child->active_fe_index() == 1)
                      pair(cell,
                           f,
                           sf,
                           child,
                           cell->neighbor_of_neighbor(f),
                           none);
                  }
              }
            else if (neighbor->active_fe_index() == 1)
              {
                if (cell->neighbor_is_coarser(f))
                  {
                    const auto [nf, sf] = cell->neighbor_of_coarser_neighbor(f);
                    pair(cell, f, none, neighbor, nf, sf);
                  }
                else
                  pair(cell,
                       f,
                       none,
                       neighbor,
                       cell->neighbor_of_neighbor(f),
                       none);
              }
          }
      }
  }

  template <int dim>
  std::vector<std::vector<types::global_dof_index>>
  FaultInterface<dim>::interface_cliques(
    const DoFHandler<dim> &dof_handler) const
  {
    std::vector<std::vector<types::global_dof_index>> cliques;
    for_each_face_pair(dof_handler,
                       [&](const unsigned int,
                           const auto &minus,
                           const unsigned int,
                           const unsigned int,
                           const auto &plus,
                           const unsigned int,
                           const unsigned int) {
                         std::vector<types::global_dof_index> a(
                           minus->get_fe().n_dofs_per_cell()),
                           b(plus->get_fe().n_dofs_per_cell());
                         minus->get_dof_indices(a);
                         plus->get_dof_indices(b);
                         a.insert(a.end(), b.begin(), b.end());
                         cliques.push_back(std::move(a));
                       });
    return cliques;
  }

  template <int dim>
  std::vector<std::pair<Point<dim>, double>>
  FaultInterface<dim>::interface_points(
    const DoFHandler<dim>         &dof_handler,
    const FiniteElementSpace<dim> &fe_space) const
  {
    std::vector<std::pair<Point<dim>, double>> points;
    if (!has_face_terms())
      return points;
    for (const InterfacePoint &p : interface_quadrature(dof_handler, fe_space))
      points.emplace_back(p.position, p.JxW);
    return points;
  }

  template <int dim>
  std::vector<typename FaultInterface<dim>::InterfacePoint>
  FaultInterface<dim>::interface_quadrature(
    const DoFHandler<dim>         &dof_handler,
    const FiniteElementSpace<dim> &fe_space) const
  {
    std::vector<InterfacePoint> points;
    assemble_interface(
      dof_handler,
      fe_space,
      AffineConstraints<double>(),
      nullptr,
      [&](const unsigned int,
          const InterfacePoint &point,
          const Tensor<1, dim> &,
          Tensor<1, dim> &,
          Tensor<2, dim> &) { points.push_back(point); },
      nullptr,
      nullptr,
      nullptr);
    return points;
  }

  template <int dim>
  void
  FaultInterface<dim>::assemble(const DoFHandler<dim>           &dof_handler,
                                const FiniteElementSpace<dim>   &fe_space,
                                const AffineConstraints<double> &constraints,
                                TrilinosWrappers::SparseMatrix  *matrix,
                                TrilinosWrappers::MPI::Vector   &rhs) const
  {
    // With a frictional fault the sliding solver adds every face term.
    if (!has_face_terms() || frictional())
      return;
    assemble_interface(
      dof_handler,
      fe_space,
      constraints,
      nullptr,
      [&](const unsigned int,
          const InterfacePoint &point,
          const Tensor<1, dim> &jump,
          Tensor<1, dim>       &traction,
          Tensor<2, dim>       &tangent) {
        tangent  = stuck_tangent(point);
        traction = tangent * jump;
      },
      matrix,
      &rhs,
      nullptr);
  }

  template <int dim>
  void
  FaultInterface<dim>::assemble_interface(
    const DoFHandler<dim>               &dof_handler,
    const FiniteElementSpace<dim>       &fe_space,
    const AffineConstraints<double>     &constraints,
    const TrilinosWrappers::MPI::Vector *solution,
    const PointLaw                      &law,
    TrilinosWrappers::SparseMatrix      *matrix,
    TrilinosWrappers::MPI::Vector       *rhs,
    TrilinosWrappers::MPI::Vector       *force) const
  {
    if (!has_face_terms())
      return;
    const auto &collection = fe_space.fe_collection();
    // Gauss-Lobatto points (the face's nodes for Q2: Simpson's rule): a stiff
    // interface integrated at Gauss points gives tractions that oscillate
    // from point to point near a kink or a change of state (the known
    // defect of interface elements, cured by nodal integration; Schellekens
    // & de Borst 1993); the rule is still exact for a constant traction.
    const QGaussLobatto<dim - 1> quadrature(fe_space.degree() + 1);
    const UpdateFlags            flags = update_values | update_JxW_values |
                              update_normal_vectors | update_quadrature_points;
    FEFaceValues<dim>                minus_face(fe_space.mapping(),
                                 collection[0],
                                 quadrature,
                                 flags);
    FESubfaceValues<dim>             minus_subface(fe_space.mapping(),
                                       collection[0],
                                       quadrature,
                                       flags);
    FEFaceValues<dim>                plus_face(fe_space.mapping(),
                                collection[1],
                                quadrature,
                                flags);
    FESubfaceValues<dim>             plus_subface(fe_space.mapping(),
                                      collection[1],
                                      quadrature,
                                      flags);
    const FEValuesExtractors::Vector u_minus = fe_space.displacement(0),
                                     u_plus  = fe_space.displacement(1);
    const unsigned int n_minus               = collection[0].n_dofs_per_cell(),
                       n_plus                = collection[1].n_dofs_per_cell(),
                       n                     = n_minus + n_plus;
    FullMatrix<double>                   local_matrix(n, n);
    Vector<double>                       local_rhs(n), local_force(n);
    Vector<double>                       values(n);
    std::vector<types::global_dof_index> dofs(n), minus_dofs(n_minus),
      plus_dofs(n_plus);
    std::vector<Tensor<1, dim>> jump(n);
    const unsigned int          none  = numbers::invalid_unsigned_int;
    unsigned int                index = 0;

    for_each_face_pair(
      dof_handler,
      [&](const unsigned int fault,
          const auto        &minus,
          const unsigned int minus_face_no,
          const unsigned int minus_subface_no,
          const auto        &plus,
          const unsigned int plus_face_no,
          const unsigned int plus_subface_no) {
        // The finer side's whole face, the coarser side's subface.
        const auto reinit = [none](auto              &face,
                                   auto              &subface,
                                   const auto        &cell,
                                   const unsigned int face_no,
                                   const unsigned int subface_no)
          -> const FEFaceValuesBase<dim> * {
          if (subface_no == none)
            {
              face.reinit(cell, face_no);
              return &face;
            }
          subface.reinit(cell, face_no, subface_no);
          return &subface;
        };
        const FEFaceValuesBase<dim> *m = reinit(
          minus_face, minus_subface, minus, minus_face_no, minus_subface_no);
        const FEFaceValuesBase<dim> *p =
          reinit(plus_face, plus_subface, plus, plus_face_no, plus_subface_no);
        minus->get_dof_indices(minus_dofs);
        plus->get_dof_indices(plus_dofs);
        std::copy(minus_dofs.begin(), minus_dofs.end(), dofs.begin());
        std::copy(plus_dofs.begin(), plus_dofs.end(), dofs.begin() + n_minus);
        values = 0;
        if (solution)
          for (unsigned int i = 0; i < n; ++i)
            values[i] = (*solution)[dofs[i]];
        local_matrix = 0;
        local_rhs    = 0;
        local_force  = 0;
        for (const unsigned int q : m->quadrature_point_indices())
          {
            // The two sides' points coincide (up to the mappings' O(h^3)
            // on curved hanging faces); the footwall's points lie in
            // reversed order on the hanging wall's face of a straight
            // fault if the faces' orientations differ.
            // The closer of the two orders: on curved hanging faces the
            // coarser side's mapping puts its points O(h^3) off the finer
            // side's.
            const unsigned int reversed = m->n_quadrature_points - 1 - q;
            const unsigned int qp =
              m->quadrature_point(q).distance(p->quadrature_point(q)) <=
                  m->quadrature_point(q).distance(p->quadrature_point(reversed))
                ? q
                : reversed;
            Assert(m->quadrature_point(q).distance(p->quadrature_point(qp)) <=
                     1e-2 * minus->diameter(),
                   ExcMessage("the two sides of a fault face do not match"));
            const FaultTrace &trace = faults[fault].trace;
            InterfacePoint    point;
            point.fault    = fault;
            point.position = m->quadrature_point(q);
            point.JxW      = m->JxW(q);
            // The fault's exact normal (into the hanging wall) rather than
            // the mapped face's: faces that meet at a node of a curved
            // fault then project the same jump the same way (their mapped
            // normals differ by O(h^2) there, which the stiff normal
            // spring would turn into spurious tractions).
            point.normal   = trace.hanging_wall_normal(point.position);
            point.shear[0] = point.normal[1];
            point.shear[1] = -point.normal[0];
            point.depth    = trace.depth(point.position);
            point.distance = trace.distance_along(point.position);
            // w = u(hanging wall) - u(footwall): the field-1 side is the
            // hanging wall where field 0's outward normal points into it.
            const double sign =
              point.normal * m->normal_vector(q) > 0 ? 1. : -1.;
            for (unsigned int i = 0; i < n_minus; ++i)
              jump[i] = -sign * (*m)[u_minus].value(i, q);
            for (unsigned int i = 0; i < n_plus; ++i)
              jump[n_minus + i] = sign * (*p)[u_plus].value(i, qp);
            Tensor<1, dim> w;
            for (unsigned int i = 0; i < n; ++i)
              w += values[i] * jump[i];
            Tensor<1, dim> t;
            Tensor<2, dim> D;
            law(index++, point, w, t, D);
            const Tensor<1, dim> affine = t - D * w;
            for (unsigned int i = 0; i < n; ++i)
              {
                if (jump[i].norm_square() == 0)
                  continue;
                local_rhs[i] -= jump[i] * affine * point.JxW;
                local_force[i] += jump[i] * t * point.JxW;
                const Tensor<1, dim> Dt_vi = transpose(D) * jump[i];
                for (unsigned int j = 0; j < n; ++j)
                  local_matrix(i, j) += Dt_vi * jump[j] * point.JxW;
              }
          }
        // The integral over the finer side's face: the coarser side's
        // subface is the same segment.
        if (matrix && rhs)
          constraints.distribute_local_to_global(
            local_matrix, local_rhs, dofs, *matrix, *rhs);
        else if (matrix)
          constraints.distribute_local_to_global(local_matrix, dofs, *matrix);
        else if (rhs)
          constraints.distribute_local_to_global(local_rhs,
                                                 dofs,
                                                 *rhs,
                                                 local_matrix);
        if (force)
          constraints.distribute_local_to_global(local_force, dofs, *force);
      });
    if (matrix)
      matrix->compress(VectorOperation::add);
    if (rhs)
      rhs->compress(VectorOperation::add);
    if (force)
      force->compress(VectorOperation::add);
  }

  template <int dim>
  void
  FaultInterface<dim>::set_active_fe_indices(DoFHandler<dim> &dof_handler) const
  {
    if (faults.empty())
      return;
    Assert(coarse_field.size() == dof_handler.get_triangulation().n_cells(0),
           ExcMessage("call identify() on this mesh first"));
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        cell->set_active_fe_index(coarse_field[coarse_index(cell)]);
  }

  namespace
  {
    /** face_dof[d][k]: the face-local index of the DoF of displacement
     * component d at scalar face node k, for a cell whose active element
     * is @p fe (one displacement field, FE_Nothing elsewhere). */
    template <int dim>
    std::array<std::vector<unsigned int>, dim>
    face_dof_table(const FiniteElement<dim> &fe, const unsigned int n_nodes)
    {
      std::array<std::vector<unsigned int>, dim> table;
      for (auto &column : table)
        column.assign(n_nodes, numbers::invalid_unsigned_int);
      for (unsigned int i = 0; i < fe.n_dofs_per_face(); ++i)
        {
          const auto [component, node] = fe.face_system_to_component_index(i);
          table[component % dim][node] = i;
        }
      return table;
    }

    /** True if row @p j of @p m is the unit vector e_i (the subface's
     * node j is the coarse face's node i); sets @p i. */
    bool
    unit_row(const FullMatrix<double> &m, const unsigned int j, unsigned int &i)
    {
      unsigned int ones = 0;
      for (unsigned int c = 0; c < m.n(); ++c)
        {
          if (std::abs(m(j, c) - 1) < 1e-12)
            {
              i = c;
              ++ones;
            }
          else if (std::abs(m(j, c)) > 1e-12)
            return false;
        }
      return ones == 1;
    }
  } // namespace

  template <int dim>
  void
  FaultInterface<dim>::add_constraints(const DoFHandler<dim> &dof_handler,
                                       const FiniteElementSpace<dim> &fe_space,
                                       AffineConstraints<double> &constraints,
                                       const double               time) const
  {
    bool with_constraints = false;
    for (const Fault &fault : faults)
      with_constraints = with_constraints || fault.law == Law::locked ||
                         fault.law == Law::prescribed_slip;
    if (!with_constraints)
      return;
    // The prescribed jump u(hanging wall) - u(footwall) of fault @p fault,
    // component d, at a node x of one of its faces whose normal into the
    // hanging wall is n (zero for a locked fault).
    const auto jump = [&](const Fault          &fault,
                          const Point<dim>     &x,
                          const Tensor<1, dim> &normal,
                          const unsigned int    d) {
      if (fault.law != Law::prescribed_slip)
        return 0.0;
      const Point<1> s(fault.trace.distance_along(x));
      fault.slip->set_time(time);
      fault.opening->set_time(time);
      return fault.slip->value(s) * fault.trace.down_dip(x)[d] +
             fault.opening->value(s) * normal[d];
    };
    // The nodes of a face in the order of the scalar element's face DoFs:
    // the vertices, then (Q2) the midpoint on the face's manifold.
    const auto node_positions = [&](const auto &face) {
      std::vector<Point<dim>> x;
      for (const unsigned int v : face->vertex_indices())
        x.push_back(face->vertex(v));
      if (fe_space.degree() == 2)
        x.push_back(face->center(true));
      return x;
    };
    // +1 if the field-1 side of face f of @p cell is the fault's hanging
    // wall, -1 if it is the footwall.
    const auto field_1_sign = [&](const auto        &cell,
                                  const unsigned int f,
                                  const FaultTrace  &trace) {
      const auto         face = cell->face(f);
      const Tensor<1, 2> t    = face->vertex(1) - face->vertex(0);
      Tensor<1, dim>     out;
      out[0] = t[1];
      out[1] = -t[0];
      if (out * (face->center() - cell->center()) < 0)
        out = -out;
      if (cell->active_fe_index() == 1)
        out = -out;
      return trace.hanging_wall_normal(face->center(true)) * out > 0 ? 1. : -1.;
    };
    const auto        &collection = fe_space.fe_collection();
    const FE_Q<dim>    scalar(fe_space.degree());
    const unsigned int n_nodes = scalar.n_dofs_per_face();
    const std::array<std::array<std::vector<unsigned int>, dim>, 2> table = {
      {face_dof_table(collection[0], n_nodes),
       face_dof_table(collection[1], n_nodes)}};
    std::array<FullMatrix<double>, GeometryInfo<dim>::max_children_per_face>
      subface;
    for (unsigned int s = 0; s < subface.size(); ++s)
      {
        subface[s].reinit(n_nodes, n_nodes);
        // (j, i): the coarse face's basis function i at the subface's node
        // j (measured: deal.II 9.4.1's FE_Q fills it by rows of the
        // subface's nodes).
        scalar.get_subface_interpolation_matrix(scalar, s, subface[s]);
      }

    auto constrain =
      [&](
        const types::global_dof_index                                  target,
        const std::vector<std::pair<types::global_dof_index, double>> &entries,
        const double inhomogeneity) {
        if (!constraints.can_store_line(target) ||
            constraints.is_constrained(target))
          return;
        constraints.add_line(target);
        constraints.add_entries(target, entries);
        if (inhomogeneity != 0)
          constraints.set_inhomogeneity(target, inhomogeneity);
      };

    std::vector<types::global_dof_index> dofs_0(
      collection[0].n_dofs_per_face()),
      dofs_1(collection[1].n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        const unsigned int side = cell->active_fe_index();
        for (const unsigned int f : cell->face_indices())
          {
            if (cell->at_boundary(f))
              continue;
            const auto neighbor = cell->neighbor(f);
            if (neighbor->has_children() || neighbor->is_artificial() ||
                neighbor->active_fe_index() == side)
              continue;
            const int k = fault_of(cell, f);
            if (k < 0 || (faults[k].law != Law::locked &&
                          faults[k].law != Law::prescribed_slip))
              continue;
            const Fault &fault = faults[k];
            // The jump of the fields, u(field 1) - u(field 0).
            const double sign = field_1_sign(cell, f, fault.trace);
            const auto   n =
              fault.trace.hanging_wall_normal(cell->face(f)->center(true));
            const auto field_jump = [&](const Point<dim>  &x,
                                        const unsigned int d) {
              return sign * jump(fault, x, n, d);
            };
            if (!cell->neighbor_is_coarser(f))
              {
                // Equal levels, seen from the footwall: hanging wall :=
                // footwall at every node.
                if (side != 0)
                  continue;
                cell->face(f)->get_dof_indices(dofs_0, 0);
                cell->face(f)->get_dof_indices(dofs_1, 1);
                const auto x = node_positions(cell->face(f));
                for (unsigned int d = 0; d < dim; ++d)
                  for (unsigned int j = 0; j < n_nodes; ++j)
                    constrain(dofs_1[table[1][d][j]],
                              {{dofs_0[table[0][d][j]], 1.0}},
                              field_jump(x[j], d));
                continue;
              }
            // This cell is the finer side of a hanging fault face.
            const auto [coarse_face_no, subface_no] =
              cell->neighbor_of_coarser_neighbor(f);
            const auto coarse_face      = neighbor->face(coarse_face_no);
            const FullMatrix<double> &m = subface[subface_no];
            const auto                x = node_positions(cell->face(f));
            if (side == 1)
              {
                // Fine hanging wall: every node := the footwall's coarse
                // trace there.
                coarse_face->get_dof_indices(dofs_0, 0);
                cell->face(f)->get_dof_indices(dofs_1, 1);
                for (unsigned int d = 0; d < dim; ++d)
                  for (unsigned int j = 0; j < n_nodes; ++j)
                    {
                      std::vector<std::pair<types::global_dof_index, double>>
                        entries;
                      for (unsigned int i = 0; i < n_nodes; ++i)
                        if (std::abs(m(j, i)) > 1e-14)
                          entries.emplace_back(dofs_0[table[0][d][i]], m(j, i));
                      constrain(dofs_1[table[1][d][j]],
                                entries,
                                field_jump(x[j], d));
                    }
              }
            else
              {
                // Fine footwall: the coarse hanging-wall nodes := the
                // footwall nodes at the same points, the other footwall
                // nodes := the coarse trace's interpolation.
                coarse_face->get_dof_indices(dofs_1, 1);
                cell->face(f)->get_dof_indices(dofs_0, 0);
                for (unsigned int d = 0; d < dim; ++d)
                  for (unsigned int j = 0; j < n_nodes; ++j)
                    {
                      unsigned int i = 0;
                      if (unit_row(m, j, i))
                        constrain(dofs_1[table[1][d][i]],
                                  {{dofs_0[table[0][d][j]], 1.0}},
                                  field_jump(x[j], d));
                      else
                        {
                          std::vector<
                            std::pair<types::global_dof_index, double>>
                            entries;
                          for (unsigned int c = 0; c < n_nodes; ++c)
                            if (std::abs(m(j, c)) > 1e-14)
                              entries.emplace_back(dofs_1[table[1][d][c]],
                                                   m(j, c));
                          constrain(dofs_0[table[0][d][j]],
                                    entries,
                                    -field_jump(x[j], d));
                        }
                    }
              }
          }
      }
  }

  template class FaultInterface<2>;
} // namespace lithostress
