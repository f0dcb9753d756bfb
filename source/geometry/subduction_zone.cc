#include <deal.II/grid/manifold_lib.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/geometry/block_mesh.h>
#include <lithostress/geometry/subduction_zone.h>

#include <algorithm>
#include <cmath>

namespace lithostress
{
  template <int dim>
  void
  SubductionZone<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Subduction zone");
    prm.declare_entry("Width",
                      "920",
                      Patterns::Double(),
                      "x of the right edge [length unit] (the thesis does "
                      "not state it: 920 km fits the basal shear zone of "
                      "§7.6.1, 900 km the thermal anomaly of §7.6.2).");
    prm.declare_entry("Base", "-95", Patterns::Double(), "y of the base.");
    prm.declare_entry("Sea floor",
                      "-5",
                      Patterns::Double(),
                      "y of the undisturbed sea floor (the top of the "
                      "oceanic plate); the plate boundary's circle touches "
                      "it at its top.");
    prm.declare_entry("Plate boundary centre",
                      "445.456, -305",
                      Patterns::Anything(),
                      "Centre `x, y` of the plate boundary's circle (thesis "
                      "§7.2).");
    prm.declare_entry("Plate boundary radius",
                      "300",
                      Patterns::Double(),
                      "Radius of the plate boundary's circle.");
    prm.declare_entry("Trench position",
                      "500",
                      Patterns::Double(),
                      "x of the trench axis, where the continental surface "
                      "meets the circle (10 km deep with the defaults).");
    prm.declare_entry("Coast position",
                      "575",
                      Patterns::Double(),
                      "x where the continental surface, rising linearly "
                      "from the trench, reaches the Land height (the thesis "
                      "does not state it); between the trench and the right "
                      "edge. The continental layers follow the surface at "
                      "constant depth, so they kink below the coast.");
    prm.declare_entry("Land height",
                      "0",
                      Patterns::Double(),
                      "y of the continental surface beyond the coast.");
    prm.declare_entry("Oceanic crust thickness", "5", Patterns::Double(), "");
    prm.declare_entry("Oceanic elastic thickness",
                      "30",
                      Patterns::Double(),
                      "Thickness of the oceanic plate's elastic lid, crust "
                      "included, below the sea floor and, in the slab, "
                      "below the plate boundary.");
    prm.declare_entry("Continental elastic thickness",
                      "10",
                      Patterns::Double(),
                      "Depth of the upper (elastic) crust below the "
                      "continental surface.");
    prm.declare_entry("Continental crust thickness",
                      "35",
                      Patterns::Double(),
                      "Depth of the continental Moho below the surface.");
    prm.declare_entry("Coarse cell size",
                      "20",
                      Patterns::Double(),
                      "Target size of the coarse cells [length unit]; each "
                      "layer has at least one cell through it.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  SubductionZone<dim>::parse_parameters(ParameterHandler &prm,
                                        const double      scale)
  {
    const std::string where = "Geometry/Subduction zone/";
    length_scale            = scale;
    length_unit             = prm.get("Length unit");
    prm.enter_subsection("Subduction zone");
    width         = prm.get_double("Width") * scale;
    base          = prm.get_double("Base") * scale;
    sea_floor     = prm.get_double("Sea floor") * scale;
    radius        = prm.get_double("Plate boundary radius") * scale;
    trench_x      = prm.get_double("Trench position") * scale;
    coast_x       = prm.get_double("Coast position") * scale;
    land_height   = prm.get_double("Land height") * scale;
    oceanic_crust = prm.get_double("Oceanic crust thickness") * scale;
    oceanic_lid   = prm.get_double("Oceanic elastic thickness") * scale;
    continental_elastic =
      prm.get_double("Continental elastic thickness") * scale;
    continental_crust = prm.get_double("Continental crust thickness") * scale;
    cell_size         = prm.get_double("Coarse cell size") * scale;
    centre            = parse_point_list<2>(prm.get("Plate boundary centre"),
                                 where + "Plate boundary centre",
                                 scale)
               .at(0);
    prm.leave_subsection();

    const auto require =
      [&](const bool ok, const std::string &entry, const std::string &what) {
        if (!ok)
          throw_input_error(where + entry, what);
      };
    require(width > 0, "Width", "must be positive");
    require(sea_floor > base && land_height > base,
            "Base",
            "must lie below the sea floor and the land");
    require(radius > 0, "Plate boundary radius", "must be positive");
    require(std::abs(centre[1] + radius - sea_floor) <= 1e-6 * radius,
            "Plate boundary centre",
            "the circle must touch the sea floor at its top: centre y + "
            "radius = Sea floor");
    require(centre[0] > 0 && centre[1] + radius - base > 0 && base > centre[1],
            "Plate boundary centre",
            "the circle's top must lie inside the section and its centre "
            "below the base");
    require(oceanic_crust > 0 && oceanic_lid > oceanic_crust &&
              sea_floor - oceanic_lid > base,
            "Oceanic elastic thickness",
            "needs 0 < crust < elastic thickness < sea floor - base");
    require(continental_elastic > 0 &&
              continental_crust > continental_elastic &&
              land_height - continental_crust > base,
            "Continental crust thickness",
            "needs 0 < elastic thickness < crust thickness < land - base");
    require(cell_size > 0, "Coarse cell size", "must be positive");
    require(trench_x > centre[0] && trench_x < centre[0] + radius,
            "Trench position",
            "must lie on the circle right of its centre");
    const double trench_y = trench()[1];
    require(trench_y > base && trench_y < land_height,
            "Trench position",
            "the trench (on the circle) must lie between the base and the "
            "land");
    require(coast_x > trench_x && coast_x < width,
            "Coast position",
            "must lie between the trench and the right edge");
    const double deepest = crossing(continental_crust)[1];
    require(deepest > base && crossing(continental_elastic)[1] > deepest &&
              crossing(continental_elastic)[1] < trench_y,
            "Continental crust thickness",
            "the continental layers must cross the plate boundary between "
            "the trench and the base");
    for (const double x : {crossing(continental_elastic)[0],
                           crossing(continental_crust)[0],
                           x_on_circle(base, radius)})
      require(std::abs(coast_x - x) > 1e-3 * width,
              "Coast position",
              "lies where a continental layer boundary meets the plate "
              "boundary (x = " +
                std::to_string(x / scale) +
                "); move it off that point, the blocks there would be "
                "degenerate");
  }

  template <int dim>
  Point<2>
  SubductionZone<dim>::trench() const
  {
    return Point<2>(trench_x,
                    centre[1] +
                      std::sqrt(radius * radius - (trench_x - centre[0]) *
                                                    (trench_x - centre[0])));
  }

  template <int dim>
  double
  SubductionZone<dim>::x_on_circle(const double y, const double r) const
  {
    const double dy = y - centre[1];
    return centre[0] + std::sqrt(std::max(0.0, r * r - dy * dy));
  }

  template <int dim>
  double
  SubductionZone<dim>::land_surface(const double x) const
  {
    const double trench_y = trench()[1];
    if (x >= coast_x)
      return land_height;
    return trench_y +
           (land_height - trench_y) * (x - trench_x) / (coast_x - trench_x);
  }

  template <int dim>
  Point<2>
  SubductionZone<dim>::crossing(const double depth) const
  {
    // Bisection in y along the circle: g(y) = y - (land(x(y)) - depth)
    // is positive at the trench and negative at the base.
    const double trench_y = trench()[1];
    const auto   g        = [&](const double y) {
      return y - (land_surface(x_on_circle(y, radius)) - depth);
    };
    double hi = trench_y, lo = base;
    // No crossing above the base: a point below it, which parse_parameters
    // refuses.
    if (g(hi) * g(lo) > 0)
      return Point<2>(x_on_circle(base, radius), base - 1);
    for (unsigned int i = 0; i < 200; ++i)
      {
        const double mid       = 0.5 * (hi + lo);
        (g(mid) > 0 ? hi : lo) = mid;
      }
    return Point<2>(x_on_circle(lo, radius), lo);
  }

  template <int dim>
  unsigned int
  SubductionZone<dim>::cells_along(const double length) const
  {
    return std::max(
      1u, static_cast<unsigned int>(std::lround(std::abs(length) / cell_size)));
  }

  template <int dim>
  Tensor<1, 2>
  SubductionZone<dim>::direction_to(const Point<2> &p) const
  {
    const Tensor<1, 2> d = p - centre;
    return d / d.norm();
  }

  template <int dim>
  Point<2>
  SubductionZone<dim>::at_base(const Tensor<1, 2> &u) const
  {
    return Point<2>(centre + ((base - centre[1]) / u[1]) * u);
  }

  template <int dim>
  std::vector<Tensor<1, 2>>
  SubductionZone<dim>::slab_stations() const
  {
    return {direction_to(Point<2>(centre[0], sea_floor)),
            direction_to(trench()),
            direction_to(crossing(continental_elastic)),
            direction_to(crossing(continental_crust))};
  }

  template <int dim>
  typename SubductionZone<dim>::CellCounts
  SubductionZone<dim>::cell_counts(
    const std::vector<Tensor<1, 2>> &station) const
  {
    const Point<2> trench = this->trench();
    const Point<2> p1     = crossing(continental_elastic),
                   p2     = crossing(continental_crust);
    // Cells through the layers. The continental layers' left sides are
    // the plate boundary's arc segments, which are also the slab's blocks
    // along it: their counts serve both (the larger of the two lengths).
    // The oceanic and continental mantles meet at the slab's end and need
    // equal, even counts.
    const auto arc_length = [&](const Point<2> &a, const Point<2> &b) {
      return radius *
             std::acos(
               std::clamp(direction_to(a) * direction_to(b), -1.0, 1.0));
    };
    const Point<2> slab_base(x_on_circle(base, radius), base);
    CellCounts     n;
    n.crust = cells_along(oceanic_crust);
    n.lid   = cells_along(oceanic_lid - oceanic_crust);
    // At least two cells through the upper crust: in the thesis's section
    // (10 km below land at sea level) their line lies 5 km down, at the
    // sea floor's depth, where the stripped load of density stripping
    // against the oceanic column jumps (water above, crust below). A jump
    // of the load inside a cell is invisible to the stress-recovery and
    // goal-oriented indicators, which would then never refine there.
    n.continental[0] = std::max({2u,
                                 cells_along(continental_elastic),
                                 cells_along(arc_length(trench, p1))});
    n.continental[1] =
      std::max(cells_along(continental_crust - continental_elastic),
               cells_along(arc_length(p1, p2)));
    n.continental[2] =
      std::max({cells_along(sea_floor - oceanic_lid - base),
                cells_along(land_height - continental_crust - base),
                cells_along(arc_length(p2, slab_base))});
    n.continental[2] += n.continental[2] % 2;
    n.wedge         = cells_along(coast_x - trench_x);
    n.along_slab[0] = cells_along(radius * std::acos(station[0] * station[1]));
    n.along_slab[1] = n.continental[0];
    n.along_slab[2] = n.continental[1];
    return n;
  }

  template <int dim>
  void
  SubductionZone<dim>::build_oceanic_plate(BlockMesh        &blocks,
                                           const CellCounts &n) const
  {
    const double       x0 = 0, x1 = centre[0];
    const double       ys[4]       = {sea_floor,
                                      sea_floor - oceanic_crust,
                                      sea_floor - oceanic_lid,
                                      base};
    const unsigned int n_across[3] = {n.crust, n.lid, n.continental[2]};
    for (unsigned int k = 0; k < 3; ++k)
      {
        const Point<2> a(x0, ys[k + 1]), b(x1, ys[k + 1]), c(x1, ys[k]),
          d(x0, ys[k]);
        blocks.add_block(SectionCurve::line(a, b),
                         SectionCurve::line(b, c),
                         SectionCurve::line(c, d),
                         SectionCurve::line(d, a),
                         cells_along(x1 - x0),
                         n_across[k],
                         k);
      }
  }

  template <int dim>
  void
  SubductionZone<dim>::build_slab_blocks(
    BlockMesh                       &blocks,
    const std::vector<Tensor<1, 2>> &station,
    const CellCounts                &n) const
  {
    using Curve          = SectionCurve;
    const double r_crust = radius - oceanic_crust, r_lid = radius - oceanic_lid;
    const auto   on = [&](const Tensor<1, 2> &u, const double r) {
      return Point<2>(centre + r * u);
    };
    const auto arc = [&](const Point<2> &a, const Point<2> &b) {
      return Curve::arc(centre, a, b);
    };
    for (unsigned int k = 0; k < 3; ++k)
      {
        const Tensor<1, 2> &ua = station[k], &ub = station[k + 1];
        const double        r[3]    = {radius, r_crust, r_lid};
        const unsigned int  n_in[2] = {n.crust, n.lid};
        for (unsigned int layer = 0; layer < 2; ++layer)
          {
            const double outer = r[layer], inner = r[layer + 1];
            blocks.add_block(arc(on(ua, inner), on(ub, inner)),
                             Curve::line(on(ub, inner), on(ub, outer)),
                             arc(on(ub, outer), on(ua, outer)),
                             Curve::line(on(ua, outer), on(ua, inner)),
                             n.along_slab[k],
                             n_in[layer],
                             layer);
          }
        blocks.add_block(Curve::line(at_base(ua), at_base(ub)),
                         Curve::line(at_base(ub), on(ub, r_lid)),
                         arc(on(ub, r_lid), on(ua, r_lid)),
                         Curve::line(on(ua, r_lid), at_base(ua)),
                         n.along_slab[k],
                         n.continental[2],
                         2);
      }
  }

  template <int dim>
  void
  SubductionZone<dim>::build_slab_end(BlockMesh          &blocks,
                                      const Tensor<1, 2> &u,
                                      const CellCounts   &n) const
  {
    using Curve          = SectionCurve;
    const double r_crust = radius - oceanic_crust, r_lid = radius - oceanic_lid;
    const auto   on  = [&](const double r) { return Point<2>(centre + r * u); };
    const auto   arc = [&](const Point<2> &a, const Point<2> &b) {
      return Curve::arc(centre, a, b);
    };
    const unsigned int n_mantle = n.continental[2];
    const double       r[3]     = {radius, r_crust, r_lid};
    const unsigned int n_in[2]  = {n.crust, n.lid};
    for (unsigned int layer = 0; layer < 2; ++layer)
      {
        const double   outer = r[layer], inner = r[layer + 1];
        const Point<2> b_outer(x_on_circle(base, outer), base),
          b_inner(x_on_circle(base, inner), base);
        blocks.add_block(arc(on(inner), b_inner),
                         Curve::line(b_inner, b_outer),
                         arc(b_outer, on(outer)),
                         Curve::line(on(outer), on(inner)),
                         n_mantle,
                         n_in[layer],
                         layer);
      }
    const Point<2> b_lid(x_on_circle(base, r_lid), base);
    blocks.add_triangle(Curve::line(on(r_lid), at_base(u)),
                        Curve::line(at_base(u), b_lid),
                        arc(b_lid, on(r_lid)),
                        n_mantle,
                        2);
  }

  template <int dim>
  void
  SubductionZone<dim>::build_continental_plate(BlockMesh        &blocks,
                                               const CellCounts &n) const
  {
    // Each layer (upper crust, lower crust, mantle) lies between the plate
    // boundary's arc from left[k] to left[k + 1] and the right edge; its
    // top and bottom follow the surface, which rises from the trench to
    // the coast and is flat beyond, so they kink below the coast. A layer
    // whose arc ends left of the coast is a wedge block to the coast and a
    // flat block beyond; the layer whose arc spans the coast is one block
    // whose top kinks (a vertex at the kink); the layers below it are one
    // block each, with as many cells along as the wedge and flat blocks
    // above together.
    using Curve    = SectionCurve;
    const auto arc = [&](const Point<2> &a, const Point<2> &b) {
      return Curve::arc(centre, a, b);
    };
    const Point<2> b_outer(x_on_circle(base, radius), base);
    const double   depth[3] = {0, continental_elastic, continental_crust};
    const Point<2> left[4]  = {trench(),
                               crossing(continental_elastic),
                               crossing(continental_crust),
                               b_outer};
    const auto     top_at   = [&](const unsigned int k, const double x) {
      return Point<2>(x, land_surface(x) - depth[k]);
    };
    const auto bottom_at = [&](const unsigned int k, const double x) {
      return k < 2 ? top_at(k + 1, x) : Point<2>(x, base);
    };
    const unsigned int n_flat  = cells_along(width - coast_x);
    const unsigned int n_wedge = n.wedge;
    for (unsigned int k = 0; k < 3; ++k)
      {
        const types::material_id material = 3 + k;
        if (coast_x > left[k + 1][0])
          {
            const Point<2> coast_top    = top_at(k, coast_x),
                           coast_bottom = bottom_at(k, coast_x);
            blocks.add_block(Curve::line(left[k + 1], coast_bottom),
                             Curve::line(coast_bottom, coast_top),
                             Curve::line(coast_top, left[k]),
                             arc(left[k], left[k + 1]),
                             n_wedge,
                             n.continental[k],
                             material);
            blocks.add_block(Curve::line(coast_bottom, bottom_at(k, width)),
                             Curve::line(bottom_at(k, width), top_at(k, width)),
                             Curve::line(top_at(k, width), coast_top),
                             Curve::line(coast_top, coast_bottom),
                             n_flat,
                             n.continental[k],
                             material);
          }
        else if (coast_x > left[k][0])
          {
            const Point<2> kink = top_at(k, coast_x);
            blocks.add_block(Curve::line(left[k + 1], bottom_at(k, width)),
                             Curve::line(bottom_at(k, width), top_at(k, width)),
                             Curve::join(Curve::line(top_at(k, width), kink),
                                         Curve::line(kink, left[k]),
                                         n_flat / double(n_flat + n_wedge)),
                             arc(left[k], left[k + 1]),
                             n_flat + n_wedge,
                             n.continental[k],
                             material);
          }
        else
          blocks.add_block(Curve::line(left[k + 1], bottom_at(k, width)),
                           Curve::line(bottom_at(k, width), top_at(k, width)),
                           Curve::line(top_at(k, width), left[k]),
                           arc(left[k], left[k + 1]),
                           n_flat + n_wedge,
                           n.continental[k],
                           material);
      }
  }

  template <int dim>
  void
  SubductionZone<dim>::attach_circle_manifolds(
    parallel::distributed::Triangulation<dim> &tria) const
  {
    const double r_crust = radius - oceanic_crust, r_lid = radius - oceanic_lid;
    const double tolerance   = 1e-9 * width;
    const auto   on_a_circle = [&](const auto &face) {
      const double r0 = face->vertex(0).distance(centre),
                   r1 = face->vertex(1).distance(centre);
      if (std::abs(r0 - r1) > tolerance)
        return false;
      for (const double r : {radius, r_crust, r_lid})
        if (std::abs(r0 - r) < tolerance)
          return true;
      return false;
    };
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (on_a_circle(face))
          {
            cell->set_manifold_id(2);
            for (const auto &f : cell->face_iterators())
              if (f->manifold_id() == numbers::flat_manifold_id)
                f->set_manifold_id(2);
            face->set_manifold_id(1);
          }
    tria.set_manifold(1, PolarManifold<2>(centre));
    TransfiniteInterpolationManifold<2> transfinite;
    transfinite.initialize(tria);
    tria.set_manifold(2, transfinite);
  }

  template <int dim>
  void
  SubductionZone<dim>::set_boundary_ids(
    parallel::distributed::Triangulation<dim> &tria) const
  {
    const double tolerance = 1e-9 * width;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const Point<2> c = face->center();
            face->set_boundary_id(
              std::abs(c[0]) < tolerance           ? 0
              : std::abs(c[0] - width) < tolerance ? 1
              : std::abs(face->vertex(0)[1] - base) < tolerance &&
                  std::abs(face->vertex(1)[1] - base) < tolerance
                ? 2
              : c[0] < trench_x ? 3
                                : 4);
          }
  }

  template <int dim>
  void
  SubductionZone<dim>::create_coarse_mesh(
    parallel::distributed::Triangulation<dim> &tria) const
  {
    // Stations across the slab: radial lines through the apex, the
    // trench and the two crossings (unit directions from the centre).
    const std::vector<Tensor<1, 2>> station = slab_stations();
    const CellCounts                n       = cell_counts(station);
    BlockMesh                       blocks;
    build_oceanic_plate(blocks, n);
    build_slab_blocks(blocks, station, n);
    build_slab_end(blocks, station[3], n);
    build_continental_plate(blocks, n);

    Triangulation<2> serial(tria.get_mesh_smoothing());
    blocks.create(
      serial, 1e-9 * width, mesh_entry(), length_scale, length_unit);
    tria.copy_triangulation(serial);
    // Faces on the circles about the centre (the plate boundary, the
    // ocean floor's bend and the slab's layers) follow a polar manifold,
    // their cells a transfinite interpolation.
    attach_circle_manifolds(tria);
    set_boundary_ids(tria);
  }

  template <int dim>
  std::map<std::string, types::boundary_id>
  SubductionZone<dim>::boundary_parts() const
  {
    return {
      {"left", 0}, {"right", 1}, {"base", 2}, {"ocean_floor", 3}, {"land", 4}};
  }

  template <int dim>
  std::map<std::string, types::material_id>
  SubductionZone<dim>::named_regions() const
  {
    return {{"oceanic_crust", 0},
            {"oceanic_lid", 1},
            {"oceanic_mantle", 2},
            {"upper_crust", 3},
            {"lower_crust", 4},
            {"continental_mantle", 5}};
  }

  template <int dim>
  std::vector<FaultTrace>
  SubductionZone<dim>::fault_traces() const
  {
    FaultTrace trace;
    trace.name           = "plate_boundary";
    trace.top_y          = trench()[1];
    trace.surface_x      = trench_x;
    trace.direction      = 1;
    trace.dip            = std::asin((trench_x - centre[0]) / radius);
    trace.has_arc        = true;
    trace.arc_centre     = centre;
    trace.arc_radius     = radius;
    trace.arc_from_depth = 0;
    trace.choose_branch(0.5 * (trace.top_y - base));
    return {trace};
  }

  template class SubductionZone<2>;

  LITHOSTRESS_REGISTER_GEOMETRY(SubductionZone,
                                "subduction zone",
                                "the subduction zone of thesis chapter 7")
} // namespace lithostress
