#include <deal.II/grid/manifold_lib.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/geometry/graded_axis.h>
#include <lithostress/geometry/layered_box.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace lithostress
{
  template <int dim>
  void
  LayeredBox<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Layered box");
    prm.declare_entry("Width",
                      "100",
                      Patterns::Double(),
                      "Width W of the box, x in [0, W] [length unit].");
    prm.declare_entry(
      "Layer interfaces",
      "0, -10, -20",
      Patterns::List(Patterns::Double(), 2),
      "Heights y of the top, of each interface and of the base, "
      "from the top down [length unit].");
    prm.declare_entry("Layer names",
                      "upper, lower",
                      Patterns::List(Patterns::Anything()),
                      "Name of each layer, top first; layer i has material "
                      "id i and is a region of this name.");
    prm.declare_entry("Cells per layer",
                      "1, 1",
                      Patterns::List(Patterns::Integer(1)),
                      "Coarse cells through each layer.");
    prm.declare_entry("Cells across",
                      "10",
                      Patterns::Integer(),
                      "Coarse cells across the width.");
    prm.declare_entry("Fault cell size",
                      "0",
                      Patterns::Double(0),
                      "Size of the coarse cells at the faults and from the "
                      "top down to the deepest end of a fault's own part "
                      "[length unit]; away from them the cells grow by "
                      "`Cell size growth` per cell up to the even division "
                      "of `Cells per layer` and `Cells across`, with a row "
                      "at every buried fault end. 0 = the even division "
                      "throughout. A buried tip needs cells of its own "
                      "size up to the surface for the surface displacement "
                      "to converge (doc/faults.md).");
    prm.declare_entry("Cell size growth",
                      "1.5",
                      Patterns::Double(1),
                      "Factor by which a graded coarse cell is larger than "
                      "its neighbour towards the faults (with a `Fault cell "
                      "size`), > 1.");
    prm.declare_entry("Fault names",
                      "fault",
                      Patterns::Anything(),
                      "Names of the faults through the box, one per entry "
                      "of `Fault surface x`; each needs a subsection of "
                      "that name in `Faults` with its interface law. The "
                      "entries below take one value for all faults or one "
                      "per fault (`Fault arc centre`: one `x, y` per fault, "
                      "separated by `;`, empty = planar).");
    prm.declare_entry("Fault surface x",
                      "",
                      Patterns::Anything(),
                      "x of the surface trace of each fault through the "
                      "whole box [length unit]; empty = no fault; `auto` "
                      "= where a fault with an arc implies it. Faults may "
                      "not meet or cross inside the box.");
    prm.declare_entry("Fault dip",
                      "63.43",
                      Patterns::Anything(),
                      "Dip of each fault's planar part [degrees], in (0, "
                      "90].");
    prm.declare_entry("Fault arc centre",
                      "",
                      Patterns::Anything(),
                      "A curved fault: below `Fault arc from depth` the "
                      "fault is the circle through this centre `x, y` "
                      "[length unit] with the `Fault arc radius` (thesis "
                      "§6.2 listric fault: 417.5, 0 and 21.25 km from 10 km "
                      "depth; §6.3.2: 315, -70 and 71 km from the surface), "
                      "carried by a manifold so that refinement stays on "
                      "it; empty = planar.");
    prm.declare_entry("Fault arc radius",
                      "0",
                      Patterns::Anything(),
                      "Radius of each fault's arc [length unit].");
    prm.declare_entry("Fault arc from depth",
                      "0",
                      Patterns::Anything(),
                      "Depth below the top where the planar part ends and "
                      "the arc begins [length unit]; it must be a row of "
                      "the coarse mesh (a layer interface or a cell row).");
    prm.declare_entry("Fault dips towards",
                      "right",
                      Patterns::Anything(),
                      "The side each fault dips towards (right | left): its "
                      "hanging wall.");
    prm.declare_entry("Fault top depth",
                      "0",
                      Patterns::Anything(),
                      "Depth below the top where each fault begins [length "
                      "unit]: 0 = at the surface; deeper, the fault's upper "
                      "end is a tip inside the body (a blind fault), and "
                      "its plane above it a welded extension. It must be a "
                      "row of the coarse mesh.");
    prm.declare_entry("Fault bottom depth",
                      "base",
                      Patterns::Anything(),
                      "Depth below the top where each fault ends [length "
                      "unit]: `base` = at the base of the box; shallower, "
                      "the fault's lower end is a tip inside the body. It "
                      "must be a row of the coarse mesh, below `Fault top "
                      "depth`.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  LayeredBox<dim>::parse_parameters(ParameterHandler &prm, const double scale)
  {
    const std::string where = "Geometry/Layered box/";
    prm.enter_subsection("Layered box");
    width = positive_length(prm, "Width", where, scale);
    interfaces =
      Utilities::string_to_double(split_list(prm.get("Layer interfaces")));
    for (double &y : interfaces)
      y *= scale;
    layer_names = split_list(prm.get("Layer names"));
    const auto counts =
      Utilities::string_to_int(split_list(prm.get("Cells per layer")));
    cells_across = positive_count(prm, "Cells across", where);
    fault_cell_size =
      parse_number(prm.get("Fault cell size"), where + "Fault cell size") *
      scale;
    cell_size_growth =
      parse_number(prm.get("Cell size growth"), where + "Cell size growth");
    if (!(cell_size_growth > 1 && cell_size_growth <= 4))
      throw_input_error(where + "Cell size growth",
                        "must lie in (1, 4], got " +
                          prm.get("Cell size growth"));
    if (!(fault_cell_size >= 0))
      throw_input_error(where + "Fault cell size", "must not be negative");
    parse_fault_geometry(prm, scale);
    prm.leave_subsection();

    const unsigned int n_layers = interfaces.size() - 1;
    for (unsigned int i = 0; i < n_layers; ++i)
      if (!(interfaces[i] > interfaces[i + 1]))
        throw_input_error(where + "Layer interfaces",
                          "heights must decrease from the top down");
    if (layer_names.size() != n_layers)
      throw_input_error(where + "Layer names",
                        "needs one name per layer (" +
                          std::to_string(n_layers) + ")");
    if (counts.size() != n_layers)
      throw_input_error(where + "Cells per layer",
                        "needs one count per layer (" +
                          std::to_string(n_layers) + ")");
    cells_per_layer.assign(counts.begin(), counts.end());
    if (fault_cell_size > 0 && fault_cell_size < 1e-6 * width)
      throw_input_error(where + "Fault cell size",
                        "is less than 1e-6 of the Width: the coarse mesh "
                        "would have more than a million cells across");
    set_rows();
    for (unsigned int k = 0; k < faults.size(); ++k)
      place_fault(k, scale);
    if (!faults.empty() && cells_across < faults.size() + 1)
      throw_input_error(where + "Cells across",
                        "needs at least one cell between two faults and "
                        "beside each (" +
                          std::to_string(faults.size() + 1) + ")");
    check_faults_apart(scale);
    // A graded coarse mesh is counted before it is made: p4est holds a
    // tree per coarse cell.
    if (fault_cell_size > 0)
      {
        std::size_t columns = 0;
        for (const auto &region : column_fractions())
          columns += region.size() - 1;
        const std::size_t cells = columns * (rows.size() - 1);
        if (cells > max_coarse_cells)
          throw_input_error(where + "Fault cell size",
                            "the graded coarse mesh would have " +
                              std::to_string(rows.size() - 1) + " rows of " +
                              std::to_string(columns) + " cells (" +
                              std::to_string(cells) + "), more than " +
                              std::to_string(max_coarse_cells) +
                              ": give a larger Fault cell size or Cell size "
                              "growth");
      }
  }

  template <int dim>
  void
  LayeredBox<dim>::parse_fault_geometry(ParameterHandler &prm,
                                        const double      scale)
  {
    const std::string              where = "Geometry/Layered box/";
    const std::vector<std::string> surface_xs =
      split_list(prm.get("Fault surface x"));
    const unsigned int n_faults = surface_xs.size();
    faults.assign(n_faults, FaultTrace());
    surface_x_given.assign(n_faults, 0);
    if (n_faults == 0)
      return;
    // One value for all faults or one per fault.
    const auto per_fault = [&](const std::string &entry, const char separator) {
      std::vector<std::string> items = split_list(prm.get(entry), separator);
      if (items.empty())
        items.emplace_back();
      if (items.size() == 1)
        items.resize(n_faults, items.front());
      if (items.size() != n_faults)
        throw_input_error(where + entry,
                          "needs one value, or one per fault (" +
                            std::to_string(n_faults) + ")");
      return items;
    };
    const auto names   = per_fault("Fault names", ',');
    const auto dips    = per_fault("Fault dip", ',');
    const auto towards = per_fault("Fault dips towards", ',');
    const auto centres =
      arc_centres(Utilities::trim(prm.get("Fault arc centre")), n_faults);
    const auto radii   = per_fault("Fault arc radius", ',');
    const auto depths  = per_fault("Fault arc from depth", ',');
    const auto tops    = per_fault("Fault top depth", ',');
    const auto bottoms = per_fault("Fault bottom depth", ',');
    top_depths.assign(n_faults, 0);
    bottom_depths.assign(n_faults, std::nan(""));
    for (unsigned int k = 0; k < n_faults; ++k)
      {
        FaultTrace &fault = faults[k];
        fault.name        = Utilities::trim(names[k]);
        for (unsigned int j = 0; j < k; ++j)
          if (faults[j].name == fault.name)
            throw_input_error(where + "Fault names",
                              "the name <" + fault.name + "> is given twice");
        const double dip_degrees = parse_number(dips[k], where + "Fault dip");
        if (!(dip_degrees > 0 && dip_degrees <= 90))
          throw_input_error(where + "Fault dip",
                            "must lie in (0, 90] degrees, got " + dips[k]);
        fault.dip              = dip_degrees * numbers::PI / 180;
        const std::string side = Utilities::trim(towards[k]);
        if (side != "right" && side != "left")
          throw_input_error(where + "Fault dips towards",
                            "<" + side + "> is neither right nor left");
        fault.direction          = side == "right" ? 1 : -1;
        const std::string centre = Utilities::trim(centres[k]);
        fault.has_arc            = !centre.empty();
        if (fault.has_arc)
          parse_fault_arc(fault, centre, radii[k], depths[k], scale);
        const std::string x = Utilities::trim(surface_xs[k]);
        if (x == "auto" && !fault.has_arc)
          throw_input_error(where + "Fault surface x",
                            "`auto` needs a Fault arc centre");
        surface_x_given[k] =
          x == "auto" ? std::nan("")
                      : parse_number(x, where + "Fault surface x") * scale;
        top_depths[k] =
          parse_number(tops[k], where + "Fault top depth") * scale;
        if (Utilities::trim(bottoms[k]) != "base")
          bottom_depths[k] =
            parse_number(bottoms[k], where + "Fault bottom depth") * scale;
      }
  }

  template <int dim>
  std::vector<std::string>
  LayeredBox<dim>::arc_centres(const std::string &entry,
                               const unsigned int n_faults)
  {
    std::vector<std::string> centres;
    std::istringstream       stream(entry);
    std::string              item;
    while (std::getline(stream, item, ';'))
      centres.push_back(Utilities::trim(item));
    if (entry.empty() || entry.back() == ';')
      centres.emplace_back();
    if (centres.size() == 1)
      centres.resize(n_faults, centres.front());
    if (centres.size() != n_faults)
      throw_input_error("Geometry/Layered box/Fault arc centre",
                        "needs one `x, y` (or nothing) per fault (" +
                          std::to_string(n_faults) + "), separated by `;`");
    return centres;
  }

  template <int dim>
  void
  LayeredBox<dim>::parse_fault_arc(FaultTrace        &fault,
                                   const std::string &centre,
                                   const std::string &radius,
                                   const std::string &from_depth,
                                   const double       scale)
  {
    const std::string where = "Geometry/Layered box/";
    const auto        c     = split_list(centre);
    if (c.size() != 2)
      throw_input_error(where + "Fault arc centre",
                        "<" + centre + "> is not `x, y`");
    fault.arc_centre =
      Point<2>(parse_number(c[0], where + "Fault arc centre"),
               parse_number(c[1], where + "Fault arc centre")) *
      scale;
    fault.arc_radius = parse_number(radius, where + "Fault arc radius") * scale;
    fault.arc_from_depth =
      parse_number(from_depth, where + "Fault arc from depth") * scale;
    if (!(fault.arc_radius > 0))
      throw_input_error(where + "Fault arc radius",
                        "must be positive for an arc");
    if (!(fault.arc_from_depth >= 0))
      throw_input_error(where + "Fault arc from depth", "must not be negative");
  }

  template <int dim>
  void
  LayeredBox<dim>::place_fault(const unsigned int k, const double scale)
  {
    const std::string where = "Geometry/Layered box/";
    FaultTrace       &fault = faults[k];
    fault.top_y             = interfaces.front();
    fault.surface_x         = surface_x_given[k];
    if (fault.has_arc)
      place_fault_arc(k, scale);
    // Below a buried lower tip whose plane would leave the box through a
    // side, the welded extension goes straight down to the base.
    const auto inside = [&](const double y) {
      return fault.x_at(y) > 0 && fault.x_at(y) < width;
    };
    const double tip_y = interfaces.front() - bottom_depths[k];
    if (!std::isnan(bottom_depths[k]) && tip_y > interfaces.back() &&
        tip_y < interfaces.front() && inside(tip_y) &&
        !inside(interfaces.back()))
      fault.vertical_below_depth = bottom_depths[k];
    for (const double y : {interfaces.front(), interfaces.back()})
      if (!inside(y))
        throw_input_error(where + "Fault surface x",
                          "the fault must cross the box from the top "
                          "to the base (or to its buried lower end), but "
                          "it leaves it at y = " +
                            std::to_string(y / scale) + " (x = " +
                            std::to_string(fault.x_at(y) / scale) + ")");
    place_fault_ends(k, scale);
  }

  template <int dim>
  void
  LayeredBox<dim>::place_fault_ends(const unsigned int k, const double scale)
  {
    const std::string where = "Geometry/Layered box/";
    FaultTrace       &fault = faults[k];
    const double      depth = interfaces.front() - interfaces.back();
    const double      top = top_depths[k], tolerance = 1e-9 * width;
    const double      bottom =
      std::isnan(bottom_depths[k]) ? depth : bottom_depths[k];
    const std::string of = " of the fault <" + fault.name + ">";
    if (!(top >= 0 && top < depth))
      throw_input_error(where + "Fault top depth",
                        "the upper end" + of +
                          " must lie in the box, from "
                          "0 to above the base, got " +
                          std::to_string(top / scale));
    if (!(bottom > 0 && bottom <= depth + tolerance))
      throw_input_error(where + "Fault bottom depth",
                        "the lower end" + of +
                          " must lie in the box, "
                          "below the top and at most at the base, got " +
                          std::to_string(bottom / scale));
    if (!(bottom > top + tolerance))
      throw_input_error(where + "Fault bottom depth",
                        "the lower end" + of +
                          " must lie below its upper "
                          "end (Fault top depth)");
    for (const auto &[end, entry] :
         {std::make_pair(top, "Fault top depth"),
          std::make_pair(bottom, "Fault bottom depth")})
      if (!on_coarse_row(interfaces.front() - end))
        throw_input_error(where + entry,
                          "the end" + of + " at the depth " +
                            std::to_string(end / scale) +
                            " must be a row of the coarse mesh (a layer "
                            "interface or a row of Cells per layer), so "
                            "that the fault is at least a cell of the "
                            "coarse mesh long and its tip is a vertex");
    fault.begin_s =
      top > 0 ? fault.trace_distance(fault.point_at_depth(top)) : 0;
    fault.end_s = bottom < depth - tolerance
                    ? fault.trace_distance(fault.point_at_depth(bottom))
                    : std::numeric_limits<double>::infinity();
  }

  template <int dim>
  bool
  LayeredBox<dim>::on_coarse_row(const double y) const
  {
    return std::any_of(rows.begin(), rows.end(), [&](const double row) {
      return std::abs(row - y) < 1e-9 * width;
    });
  }

  template <int dim>
  void
  LayeredBox<dim>::set_rows()
  {
    const double top = interfaces.front(), tolerance = 1e-9 * width;
    rows = {interfaces.back()};
    if (!(fault_cell_size > 0))
      {
        for (int layer = static_cast<int>(cells_per_layer.size()) - 1;
             layer >= 0;
             --layer)
          {
            const double thickness = interfaces[layer] - interfaces[layer + 1];
            for (unsigned int c = 1; c <= cells_per_layer[layer]; ++c)
              rows.push_back(interfaces[layer + 1] +
                             thickness * c / cells_per_layer[layer]);
          }
        return;
      }
    // Depths where a row must be, and the fine set from the top down to
    // the deepest end of a fault's own part.
    std::vector<double> breaks;
    double              deepest = 0;
    for (const double y : interfaces)
      breaks.push_back(top - y);
    for (unsigned int k = 0; k < faults.size(); ++k)
      {
        const double bottom = std::isnan(bottom_depths[k])
                                ? top - interfaces.back()
                                : bottom_depths[k];
        deepest             = std::max(deepest, bottom);
        breaks.push_back(top_depths[k]);
        breaks.push_back(bottom);
        if (faults[k].has_arc)
          breaks.push_back(faults[k].arc_from_depth);
      }
    std::sort(breaks.begin(), breaks.end(), std::greater<double>());
    GradedAxis axis;
    axis.fine     = fault_cell_size;
    axis.growth   = cell_size_growth;
    axis.fine_set = {{0.0, deepest}};
    for (int layer = static_cast<int>(cells_per_layer.size()) - 1; layer >= 0;
         --layer)
      {
        const double upper = top - interfaces[layer],
                     lower = top - interfaces[layer + 1];
        axis.coarsest      = (lower - upper) / cells_per_layer[layer];
        for (const double depth : breaks)
          {
            const double from = top - rows.back();
            if (depth > from - tolerance || depth < upper - tolerance)
              continue;
            const std::vector<double> nodes = axis.nodes(depth, from);
            for (auto d = nodes.rbegin() + 1; d != nodes.rend(); ++d)
              rows.push_back(top - *d);
          }
      }
  }

  template <int dim>
  std::vector<std::vector<double>>
  LayeredBox<dim>::column_fractions() const
  {
    std::vector<std::vector<double>> regions;
    if (!(fault_cell_size > 0))
      {
        // A number of cells between the left side, each fault (left to
        // right) and the right side, in proportion to their widths at
        // mid-depth.
        std::vector<unsigned int> first_column = {0};
        const double y_mid = 0.5 * (interfaces.front() + interfaces.back());
        for (unsigned int k = 0; k < faults.size(); ++k)
          {
            const unsigned int column = static_cast<unsigned int>(
              std::lround(cells_across * faults[k].x_at(y_mid) / width));
            first_column.push_back(
              std::clamp<unsigned int>(column,
                                       first_column.back() + 1,
                                       cells_across - (faults.size() - k)));
          }
        first_column.push_back(cells_across);
        for (unsigned int r = 0; r + 1 < first_column.size(); ++r)
          {
            const unsigned int n = first_column[r + 1] - first_column[r];
            regions.emplace_back();
            for (unsigned int i = 0; i <= n; ++i)
              regions.back().push_back(static_cast<double>(i) / n);
          }
        return regions;
      }
    // Graded from the faults, at the height of the middle of the own parts
    // of the faults that bound each region.
    const double top    = interfaces.front();
    const auto   middle = [&](const unsigned int k) {
      const double bottom = std::isnan(bottom_depths[k])
                                ? top - interfaces.back()
                                : bottom_depths[k];
      return top - 0.5 * (top_depths[k] + bottom);
    };
    GradedAxis axis;
    axis.fine     = fault_cell_size;
    axis.growth   = cell_size_growth;
    axis.coarsest = width / cells_across;
    for (unsigned int r = 0; r <= faults.size(); ++r)
      {
        const bool   left_fault = r > 0, right_fault = r < faults.size();
        const double y     = left_fault && right_fault
                               ? 0.5 * (middle(r - 1) + middle(r))
                             : left_fault  ? middle(r - 1)
                             : right_fault ? middle(r)
                                           : top;
        const double left  = left_fault ? faults[r - 1].x_at(y) : 0.0,
                     right = right_fault ? faults[r].x_at(y) : width;
        axis.fine_set.clear();
        if (left_fault)
          axis.fine_set.emplace_back(0.0, 0.0);
        if (right_fault)
          axis.fine_set.emplace_back(right - left, right - left);
        regions.push_back(axis.nodes(0.0, right - left));
        for (double &t : regions.back())
          t /= right - left;
      }
    return regions;
  }

  template <int dim>
  void
  LayeredBox<dim>::place_fault_arc(const unsigned int k, const double scale)
  {
    const std::string where = "Geometry/Layered box/";
    FaultTrace       &fault = faults[k];
    const std::string arc   = where + "Fault arc centre";
    const double      y_top = interfaces.front() - fault.arc_from_depth;
    const double      y_bot = interfaces.back();
    if (!(y_top > y_bot))
      throw_input_error(where + "Fault arc from depth",
                        "must lie above the base");
    // A graph x(y) that keeps its dip direction: the arc reaches both ends
    // and does not pass the height of its centre.
    const double cy = fault.arc_centre[1], r = fault.arc_radius;
    if (std::abs(y_top - cy) > r * (1 + 1e-12) ||
        std::abs(y_bot - cy) > r * (1 + 1e-12))
      throw_input_error(arc,
                        "the arc misses the box: the circle does not "
                        "reach from the depth where it begins to the "
                        "base");
    if (y_bot < cy - 1e-9 * width && cy < y_top - 1e-9 * width)
      throw_input_error(arc,
                        "the arc passes the height of its centre "
                        "between where it begins and the base, so "
                        "the fault would turn back");
    fault.choose_branch(0.5 *
                        (fault.arc_from_depth + interfaces.front() - y_bot));
    // The surface trace where the arc and the planar part imply it.
    const double x_junction =
      fault.arc_centre[0] +
      fault.branch *
        std::sqrt(std::max(0.0, r * r - (y_top - cy) * (y_top - cy)));
    const double implied =
      x_junction - fault.direction * fault.arc_from_depth / std::tan(fault.dip);
    if (std::isnan(surface_x_given[k]))
      fault.surface_x = implied;
    else if (std::abs(surface_x_given[k] - implied) > 1e-6 * width)
      throw_input_error(where + "Fault surface x",
                        "the arc and the planar part imply " +
                          std::to_string(implied / scale) +
                          "; give that or `auto`");
    // The arc must begin on a row of the coarse mesh.
    if (fault.arc_from_depth != 0 && !on_coarse_row(y_top))
      throw_input_error(where + "Fault arc from depth",
                        "must be a row of the coarse mesh (a layer "
                        "interface or a row of Cells per layer)");
  }

  template <int dim>
  void
  LayeredBox<dim>::check_faults_apart(const double scale)
  {
    // Left to right at mid-depth; they may not meet or cross in the box.
    const double y_mid = 0.5 * (interfaces.front() + interfaces.back());
    std::sort(faults.begin(),
              faults.end(),
              [y_mid](const FaultTrace &a, const FaultTrace &b) {
                return a.x_at(y_mid) < b.x_at(y_mid);
              });
    for (unsigned int k = 0; k + 1 < faults.size(); ++k)
      for (unsigned int i = 0; i <= 256; ++i)
        {
          const double y = interfaces.back() +
                           (interfaces.front() - interfaces.back()) * i / 256;
          if (!(faults[k].x_at(y) < faults[k + 1].x_at(y) - 1e-6 * width))
            throw_input_error("Geometry/Layered box/Fault surface x",
                              "the faults <" + faults[k].name + "> and <" +
                                faults[k + 1].name +
                                "> meet or cross in the box (at y = " +
                                std::to_string(y / scale) + ")");
        }
  }

  template <int dim>
  void
  LayeredBox<dim>::create_coarse_mesh(
    parallel::distributed::Triangulation<dim> &tria) const
  {
    // Rows of vertices from the base up; columns between the left side,
    // each fault (left to right) and the right side, so that each fault is
    // a column boundary.
    const std::vector<double>                   &ys      = rows;
    const std::vector<std::vector<double>>       regions = column_fractions();
    std::vector<std::pair<unsigned int, double>> columns = {{0, 0.0}};
    for (unsigned int r = 0; r < regions.size(); ++r)
      for (unsigned int i = 1; i < regions[r].size(); ++i)
        columns.emplace_back(r, regions[r][i]);
    auto x_of = [&](const unsigned int i, const double y) {
      const unsigned int k    = columns[i].first;
      const double       left = k == 0 ? 0.0 : faults[k - 1].x_at(y),
                   right      = k == faults.size() ? width : faults[k].x_at(y);
      return left + (right - left) * columns[i].second;
    };
    const unsigned int       cells_in_row = columns.size() - 1;
    const unsigned int       nx           = cells_in_row + 1;
    std::vector<Point<2>>    vertices;
    std::vector<CellData<2>> cells;
    for (const double y : ys)
      for (unsigned int i = 0; i < nx; ++i)
        vertices.emplace_back(x_of(i, y), y);
    for (unsigned int j = 0; j + 1 < ys.size(); ++j)
      for (unsigned int i = 0; i < cells_in_row; ++i)
        {
          CellData<2> cell;
          cell.vertices = {j * nx + i,
                           j * nx + i + 1,
                           (j + 1) * nx + i,
                           (j + 1) * nx + i + 1};
          cells.push_back(cell);
        }
    tria.create_triangulation(vertices, cells, SubCellData());
    const double tolerance = 1e-9 * width;
    // The faces of a fault's arc follow a polar manifold (id 2k + 1 for
    // fault k), their cells and those cells' other faces a transfinite
    // interpolation (id 2), so that refinement stays on the arc and the
    // cells next to it keep their shape.
    bool with_arc = false;
    for (unsigned int k = 0; k < faults.size(); ++k)
      {
        const FaultTrace &fault = faults[k];
        if (!fault.has_arc)
          continue;
        with_arc                = true;
        const auto on_fault_arc = [&](const Point<2> &p) {
          return fault.depth(p) >= fault.arc_from_depth - tolerance &&
                 std::abs(p[0] - fault.x_at(p[1])) < tolerance;
        };
        for (const auto &cell : tria.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (!face->at_boundary() && on_fault_arc(face->vertex(0)) &&
                on_fault_arc(face->vertex(1)))
              face->set_manifold_id(2 * k + 1);
        tria.set_manifold(2 * k + 1, PolarManifold<2>(fault.arc_centre));
      }
    if (with_arc)
      {
        for (const auto &cell : tria.active_cell_iterators())
          {
            bool next_to_arc = false;
            for (const auto &face : cell->face_iterators())
              next_to_arc = next_to_arc ||
                            (face->manifold_id() != numbers::flat_manifold_id &&
                             face->manifold_id() != 2);
            if (!next_to_arc)
              continue;
            cell->set_manifold_id(2);
            for (const auto &face : cell->face_iterators())
              if (face->manifold_id() == numbers::flat_manifold_id)
                face->set_manifold_id(2);
          }
        TransfiniteInterpolationManifold<2> transfinite;
        transfinite.initialize(tria);
        tria.set_manifold(2, transfinite);
      }
    for (const auto &cell : tria.active_cell_iterators())
      {
        const double y = cell->center()[1];
        for (unsigned int layer = 0; layer + 1 < interfaces.size(); ++layer)
          if (y < interfaces[layer] && y > interfaces[layer + 1])
            cell->set_material_id(layer);
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const Point<2> c = face->center();
              // The ids of GridGenerator's colorized rectangle.
              face->set_boundary_id(
                std::abs(c[1] - interfaces.back()) < tolerance    ? 2
                : std::abs(c[1] - interfaces.front()) < tolerance ? 3
                : c[0] < 0.5 * width                              ? 0
                                                                  : 1);
            }
      }
  }

  template <int dim>
  std::vector<FaultTrace>
  LayeredBox<dim>::fault_traces() const
  {
    return faults;
  }

  template <int dim>
  std::map<std::string, types::boundary_id>
  LayeredBox<dim>::boundary_parts() const
  {
    return rectangle_boundary_parts();
  }

  template <int dim>
  std::map<std::string, types::material_id>
  LayeredBox<dim>::named_regions() const
  {
    std::map<std::string, types::material_id> regions;
    for (unsigned int i = 0; i < layer_names.size(); ++i)
      regions[layer_names[i]] = i;
    return regions;
  }

  template class LayeredBox<2>;

  LITHOSTRESS_REGISTER_GEOMETRY(
    LayeredBox,
    "layered box",
    "horizontal layers, optionally cut by planar or listric faults "
    "(thesis chapters 6 and 7)")
} // namespace lithostress
