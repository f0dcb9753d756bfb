#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <limits>
#include <set>

#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/boundary_conditions/prescribed_displacement.h>
#include <lithostress/reference_solutions/reference_solution.h>

namespace lithostress
{
  namespace
  {
    const char *component_names[3] = {"x", "y", "z"};

    /** The prescribed displacement of one part, repeated for each field. */
    template <int dim>
    class PartDisplacement : public Function<dim>
    {
    public:
      PartDisplacement(
        const std::array<std::unique_ptr<ParsedExpression<dim>>, dim> &c,
        const std::array<bool, dim>  &from_reference,
        const ReferenceSolution<dim> *reference,
        const unsigned int            n_fields,
        const double                  time)
          : Function<dim>(dim * n_fields)
          , c(c)
          , from_reference(from_reference)
          , reference(reference)
          , t(time)
      {
      }

      double
      value(const Point<dim> &p, const unsigned int component) const override
      {
        const unsigned int d = component % dim;
        if (from_reference[d])
          return reference->displacement(p)[d];
        return c[d] ? c[d]->value(p, t) : 0.0;
      }

    private:
      const std::array<std::unique_ptr<ParsedExpression<dim>>, dim> &c;
      const std::array<bool, dim>  &from_reference;
      const ReferenceSolution<dim> *reference;
      const double                  t;
    };
  } // namespace

  template <int dim>
  void
  PrescribedDisplacement<dim>::declare_parameters(ParameterHandler &prm,
                                                  ParameterHandler *first_pass)
  {
    const std::vector<std::string> names =
      ParameterFile::names_from(first_pass,
                                {"Boundary conditions"},
                                "Prescribed displacement parts",
                                {"base"});
    prm.enter_subsection("Boundary conditions");
    prm.declare_entry("Prescribed displacement parts",
                      "",
                      Patterns::Anything(),
                      "Comma separated boundary parts with a prescribed "
                      "displacement component; each gets a subsection.");
    for (const std::string &name : names)
      {
        prm.enter_subsection(name);
        for (unsigned int d = 0; d < dim; ++d)
          prm.declare_entry(component_names[d],
                            "",
                            Patterns::Anything(),
                            std::string("Prescribed ") + component_names[d] +
                              " displacement [m] as a function of x, y [m] "
                              "and t [s]; empty = free; `reference` = the "
                              "reference solution's; `rigid` = the same "
                              "unknown value all along the part (a rigid "
                              "edge, loaded by a traction's resultant).");
        prm.declare_entry("Constants",
                          "",
                          Patterns::Anything(),
                          "Constants for the expressions: name=value, ...");
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }

  template <int dim>
  void
  PrescribedDisplacement<dim>::parse_parameters(
    ParameterHandler            &prm,
    const ModelDescription<dim> &model)
  {
    parts.clear();
    reference = model.reference;
    prm.enter_subsection("Boundary conditions");
    for (const std::string &name :
         split_list(prm.get("Prescribed displacement parts")))
      {
        Part part;
        part.name = name;
        part.id   = model.boundary_id(
          name, "Boundary conditions/Prescribed displacement parts");
        prm.enter_subsection(name);
        const std::string constants = prm.get("Constants");
        bool              any       = false;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const std::string entry =
              "Boundary conditions/" + name + "/" + component_names[d];
            const std::string text =
              Utilities::trim(prm.get(component_names[d]));
            part.from_reference[d] = (text == "reference");
            part.rigid[d]          = (text == "rigid");
            if (part.from_reference[d] && reference == nullptr)
              throw_input_error(entry,
                                "is `reference` but Convergence "
                                "study/Reference solution is none");
            if (!text.empty() && !part.from_reference[d] && !part.rigid[d])
              part.component[d] =
                std::make_unique<ParsedExpression<dim>>(text, constants, entry);
            any = any || !text.empty();
          }
        prm.leave_subsection();
        if (!any)
          throw_input_error("Boundary conditions/" + name,
                            "prescribes no component (set x and/or y)");
        parts.push_back(std::move(part));
      }
    prm.leave_subsection();
  }

  template <int dim>
  bool
  PrescribedDisplacement<dim>::has_rigid_components() const
  {
    for (const Part &part : parts)
      for (unsigned int d = 0; d < dim; ++d)
        if (part.rigid[d])
          return true;
    return false;
  }

  template <int dim>
  void
  PrescribedDisplacement<dim>::apply_rigid_components(
    const DoFHandler<dim>         &dof_handler,
    const FiniteElementSpace<dim> &fe_space,
    AffineConstraints<double>     &constraints) const
  {
    const unsigned int n_components = fe_space.fe_collection().n_components();
    const MPI_Comm     comm         = dof_handler.get_communicator();
    std::vector<types::global_dof_index> face_dofs;
    for (const Part &part : parts)
      for (unsigned int d = 0; d < dim; ++d)
        {
          if (!part.rigid[d])
            continue;
          // The component's DoFs on the part, on owned and ghost cells
          // (every locally relevant one gets its constraint line).
          std::set<types::global_dof_index> dofs;
          for (const auto &cell : dof_handler.active_cell_iterators())
            {
              if (cell->is_artificial())
                continue;
              const auto &fe = cell->get_fe();
              if (fe.n_dofs_per_cell() == 0)
                continue;
              for (const auto &face : cell->face_iterators())
                if (face->at_boundary() && face->boundary_id() == part.id)
                  {
                    face_dofs.resize(fe.n_dofs_per_face());
                    face->get_dof_indices(face_dofs, cell->active_fe_index());
                    for (unsigned int i = 0; i < face_dofs.size(); ++i)
                      {
                        const unsigned int c =
                          fe.face_system_to_component_index(i).first;
                        if (c < n_components && c % dim == d)
                          dofs.insert(face_dofs[i]);
                      }
                  }
            }
          const std::string entry =
            "Boundary conditions/" + part.name + "/" + component_names[d];
          bool conflict = false;
          for (const auto i : dofs)
            conflict = conflict || constraints.is_constrained(i);
          if (Utilities::MPI::max(conflict ? 1 : 0, comm) == 1)
            throw_input_error(entry,
                              "is `rigid`, but another part already "
                              "prescribes this component at a point of "
                              "the part (a shared corner); a rigid edge "
                              "must be free to move as a whole");
          // The master: the smallest index on the part, the same on every
          // rank.
          const types::global_dof_index local_min =
            dofs.empty() ? std::numeric_limits<types::global_dof_index>::max()
                         : *dofs.begin();
          const types::global_dof_index master =
            Utilities::MPI::min(local_min, comm);
          for (const auto i : dofs)
            if (i != master)
              {
                constraints.add_line(i);
                constraints.add_entry(i, master, 1.0);
              }
        }
  }

  template <int dim>
  bool
  PrescribedDisplacement<dim>::constrains(const types::boundary_id id) const
  {
    for (const Part &part : parts)
      if (part.id == id)
        return true;
    return false;
  }

  template <int dim>
  void
  PrescribedDisplacement<dim>::apply(const DoFHandler<dim>         &dof_handler,
                                     const FiniteElementSpace<dim> &fe_space,
                                     AffineConstraints<double>     &constraints,
                                     const double                   time) const
  {
    const unsigned int n_components = fe_space.fe_collection().n_components();
    for (const Part &part : parts)
      {
        std::vector<bool> mask(n_components, false);
        for (unsigned int c = 0; c < n_components; ++c)
          {
            const unsigned int d = c % dim;
            mask[c] = part.from_reference[d] || part.component[d] != nullptr;
          }
        if (std::none_of(mask.begin(), mask.end(), [](bool m) { return m; }))
          continue;
        const PartDisplacement<dim> function(part.component,
                                             part.from_reference,
                                             reference,
                                             fe_space.n_fields(),
                                             time);
        std::map<types::boundary_id, const Function<dim> *> functions = {
          {part.id, &function}};
        VectorTools::interpolate_boundary_values(fe_space.mapping_collection(),
                                                 dof_handler,
                                                 functions,
                                                 constraints,
                                                 ComponentMask(mask));
      }
    apply_rigid_components(dof_handler, fe_space, constraints);
  }

  template <int dim>
  std::vector<std::pair<types::boundary_id, ComponentMask>>
  PrescribedDisplacement<dim>::constrained_components(
    const FiniteElementSpace<dim> &fe_space) const
  {
    const unsigned int n_components = fe_space.fe_collection().n_components();
    std::vector<std::pair<types::boundary_id, ComponentMask>> result;
    for (const Part &part : parts)
      {
        std::vector<bool> mask(n_components, false);
        for (unsigned int c = 0; c < n_components; ++c)
          mask[c] =
            part.from_reference[c % dim] || part.component[c % dim] != nullptr;
        result.emplace_back(part.id, ComponentMask(mask));
      }
    return result;
  }

  template <int dim>
  std::vector<std::pair<std::string, std::array<IndexSet, dim>>>
  PrescribedDisplacement<dim>::constrained_dofs(
    const DoFHandler<dim>         &dof_handler,
    const FiniteElementSpace<dim> &fe_space) const
  {
    const unsigned int n_components = fe_space.fe_collection().n_components();
    std::vector<std::pair<std::string, std::array<IndexSet, dim>>> result;
    IndexSet taken(dof_handler.n_dofs());
    for (const Part &part : parts)
      {
        std::array<IndexSet, dim> dofs;
        for (unsigned int d = 0; d < dim; ++d)
          {
            dofs[d].set_size(dof_handler.n_dofs());
            if (!part.from_reference[d] && part.component[d] == nullptr)
              continue;
            std::vector<bool> mask(n_components, false);
            for (unsigned int c = d; c < n_components; c += dim)
              mask[c] = true;
            dofs[d] = DoFTools::extract_boundary_dofs(dof_handler,
                                                      ComponentMask(mask),
                                                      {part.id});
            dofs[d].subtract_set(taken);
            taken.add_indices(dofs[d]);
          }
        result.emplace_back(part.name, dofs);
      }
    return result;
  }

  template class PrescribedDisplacement<2>;
} // namespace lithostress
