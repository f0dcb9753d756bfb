#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/loads/density_stripping.h>
#include <lithostress/loads/load_collection.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace lithostress
{
  template <int dim>
  void
  DensityStripping<dim>::declare_parameters(ParameterHandler &prm,
                                            ParameterHandler *)
  {
    prm.enter_subsection("Density stripping");
    prm.declare_entry(
      "Reference column",
      "",
      Patterns::Anything(),
      "The reference density-depth column: contiguous depth intervals "
      "[length unit] with their density [kg/m^3], from the top down: "
      "`0, 5: 1030; 5, 11: 2900; 11, 100: 3300`. Empty = no stripping. "
      "The body force is then -(rho - rho_ref(depth)) g in y, and stresses "
      "are relative to the reference column.");
    prm.leave_subsection();
  }

  template <int dim>
  bool
  DensityStripping<dim>::parse_parameters(ParameterHandler            &prm,
                                          const ModelDescription<dim> &model)
  {
    const std::string entry = "Loads/Density stripping/Reference column";
    length_scale            = model.length_scale;
    prm.enter_subsection("Density stripping");
    const std::string column = prm.get("Reference column");
    depth_origin             = model.gravity.depth_origin;
    acceleration             = model.gravity.acceleration;
    prm.leave_subsection();
    bottoms.clear();
    densities.clear();
    const auto intervals = split_list(column, ';');
    if (intervals.empty())
      return false;
    double previous_bottom = 0;
    for (unsigned int k = 0; k < intervals.size(); ++k)
      {
        const std::string &text  = intervals[k];
        const auto         colon = text.find(':');
        const auto         range =
          split_list(colon == std::string::npos ? "" : text.substr(0, colon));
        if (colon == std::string::npos || range.size() != 2)
          throw_input_error(entry,
                            "interval " + std::to_string(k + 1) + " <" + text +
                              "> is not `top, bottom: density`");
        const double top    = parse_number(range[0], entry) * length_scale;
        const double bottom = parse_number(range[1], entry) * length_scale;
        const double rho    = parse_number(text.substr(colon + 1), entry);
        if (!(bottom > top))
          throw_input_error(entry,
                            "interval " + std::to_string(k + 1) + " <" + text +
                              ">: the bottom must be deeper than the top");
        if (!(rho >= 0))
          throw_input_error(entry,
                            "interval " + std::to_string(k + 1) + " <" + text +
                              ">: the density must not be negative");
        if (k == 0)
          column_top = top;
        else if (std::abs(top - previous_bottom) >
                 1e-9 * std::max(std::abs(top), std::abs(previous_bottom)))
          throw_input_error(entry,
                            "interval " + std::to_string(k + 1) + " <" + text +
                              "> does not start where the one above ends (" +
                              (top > previous_bottom ? "a gap" : "an overlap") +
                              "): the column must be contiguous");
        bottoms.push_back(bottom);
        densities.push_back(rho);
        previous_bottom = bottom;
      }
    return true;
  }

  template <int dim>
  double
  DensityStripping<dim>::reference_density(const Point<dim> &p) const
  {
    const double depth = depth_origin - p[dim - 1];
    const auto   it = std::lower_bound(bottoms.begin(), bottoms.end(), depth);
    return densities[std::min<std::size_t>(it - bottoms.begin(),
                                           densities.size() - 1)];
  }

  template <int dim>
  double
  DensityStripping<dim>::reference_pressure(const Point<dim> &p) const
  {
    const double depth    = depth_origin - p[dim - 1];
    double       top      = column_top;
    double       pressure = 0;
    for (unsigned int k = 0; k < bottoms.size() && top < depth; ++k)
      {
        const bool   last   = k + 1 == bottoms.size();
        const double bottom = last ? std::max(depth, bottoms[k]) : bottoms[k];
        pressure += densities[k] * (std::min(depth, bottom) - top);
        top = bottom;
      }
    return acceleration * pressure;
  }

  template <int dim>
  void
  DensityStripping<dim>::check_against_mesh(const Triangulation<dim> &tria,
                                            const Mapping<dim> &) const
  {
    const double tolerance = 1e-8 * (bottoms.back() - column_top);
    for (const Point<dim> &v : tria.get_vertices())
      {
        const double depth = depth_origin - v[dim - 1];
        if (depth < column_top - tolerance ||
            depth > bottoms.back() + tolerance)
          {
            std::ostringstream out;
            out << "the mesh vertex (" << v[0] / length_scale << ", "
                << v[1] / length_scale << ") at depth " << depth / length_scale
                << " [length unit] lies outside the reference column ("
                << column_top / length_scale << " to "
                << bottoms.back() / length_scale << ")";
            throw_input_error("Loads/Density stripping/Reference column",
                              out.str());
          }
      }
  }

  template <int dim>
  void
  DensityStripping<dim>::add_cell_terms(
    const FEValues<dim>              &fe_values,
    const FEValuesExtractors::Vector &displacement,
    const Material                   &material,
    const ElasticModuli<dim> &,
    FullMatrix<double> &,
    Vector<double> &cell_rhs) const
  {
    // The reference column jumps at its interval bottoms; Gauss points
    // integrate a cell that a jump crosses with an O(h) error of the order
    // of the jump times the cell's area, which is the size of the whole
    // stripped load on coarse meshes (the stripped load is a small
    // difference of large weights). Such cells integrate the reference
    // part on 16 x 16 sub-cells (error 1/16 of that, and falling with h).
    const auto cell = fe_values.get_cell();
    double     top = std::numeric_limits<double>::max(), bottom = -top;
    for (const unsigned int v : cell->vertex_indices())
      {
        const double depth = depth_origin - cell->vertex(v)[dim - 1];
        top                = std::min(top, depth);
        bottom             = std::max(bottom, depth);
      }
    const double margin  = 1e-9 * (bottom - top);
    bool         crossed = false;
    for (unsigned int k = 0; k + 1 < bottoms.size(); ++k)
      crossed |= bottoms[k] > top + margin && bottoms[k] < bottom - margin;

    const auto add = [&](const FEValues<dim> &values,
                         const bool           with_material,
                         const bool           with_reference) {
      for (const unsigned int q : values.quadrature_point_indices())
        {
          const double rho =
            (with_material ? material.density : 0) -
            (with_reference ? reference_density(values.quadrature_point(q))
                            : 0);
          const double rho_g = rho * acceleration * values.JxW(q);
          for (const unsigned int i : values.dof_indices())
            cell_rhs(i) -= rho_g * values[displacement].value(i, q)[dim - 1];
        }
    };
    if (!crossed)
      {
        add(fe_values, true, true);
        return;
      }
    add(fe_values, true, false);
    FEValues<dim> &fine = sub_cell_values(fe_values);
    fine.reinit(cell);
    add(fine, false, true);
  }

  template <int dim>
  FEValues<dim> &
  DensityStripping<dim>::sub_cell_values(const FEValues<dim> &fe_values) const
  {
    // The assembly's mapping is FiniteElementSpace's CachedMappingQ.
    const auto *mapping =
      dynamic_cast<const MappingQ<dim> *>(&fe_values.get_mapping());
    AssertThrow(mapping != nullptr,
                ExcMessage("Density stripping integrates on a MappingQ."));
    for (const SubCellValues &s : sub_cells)
      if (s.mapping->get_degree() == mapping->get_degree() &&
          *s.fe == fe_values.get_fe())
        return *s.values;
    SubCellValues s;
    s.fe      = fe_values.get_fe().clone();
    s.mapping = std::make_unique<MappingQ<dim>>(mapping->get_degree());
    s.values =
      std::make_unique<FEValues<dim>>(*s.mapping,
                                      *s.fe,
                                      QIterated<dim>(QGauss<1>(2), 16),
                                      update_values | update_quadrature_points |
                                        update_JxW_values);
    sub_cells.push_back(std::move(s));
    return *sub_cells.back().values;
  }

  template <int dim>
  std::string
  DensityStripping<dim>::description() const
  {
    std::ostringstream out;
    out << "density stripping: body force -(rho - rho_ref) g, g = "
        << acceleration << " m/s^2, reference column";
    double top = column_top;
    for (unsigned int k = 0; k < bottoms.size(); ++k)
      {
        out << (k == 0 ? " " : "; ") << top / length_scale << "-"
            << bottoms[k] / length_scale << ": " << densities[k];
        top = bottoms[k];
      }
    out << " kg/m^3 (depth in length units). STRESSES ARE RELATIVE TO THE "
           "REFERENCE COLUMN.";
    return out.str();
  }

  template class DensityStripping<2>;
  LITHOSTRESS_REGISTER_LOAD(
    DensityStripping,
    "density stripping",
    "the body force of the densities less a reference column (thesis §3.7)",
    20)
} // namespace lithostress
