#ifndef lithostress_geometry_subduction_zone_h
#define lithostress_geometry_subduction_zone_h

#include <lithostress/geometry/geometry_model.h>

namespace lithostress
{
  /**
   * The cross section of an active continental margin of thesis §7.2
   * (SPEC §5.2): an oceanic plate on the left (crust, elastic lid and
   * visco-elastic mantle under a flat sea floor) that bends down along the
   * plate boundary, a circle of radius R about c touching the sea floor
   * at its top (R = 300 km about (445.456, −305) km: the sea floor at
   * −5 km), and a continental plate on the right (upper and lower crust
   * and mantle, depths below its surface) that overlies it from the
   * trench, where its surface meets the circle (x = 500 km, 10 km deep),
   * rising linearly to the land height at the coast and flat beyond. The
   * oceanic layers follow the circle in the slab (concentric arcs R − 5
   * and R − 30 km); every layer boundary is a cell face. The plate
   * boundary from the trench to the base is the fault `plate_boundary`.
   *
   * The coarse mesh is a BlockMesh of 23 blocks. The circles' faces carry
   * one PolarManifold (id 1, centre c; every arc is concentric), the cells
   * next to them a TransfiniteInterpolationManifold (id 2), so refinement
   * keeps the plate boundary and the slab's layers exact.
   *
   * Material ids (and region names): 0 oceanic_crust, 1 oceanic_lid,
   * 2 oceanic_mantle, 3 upper_crust, 4 lower_crust, 5 continental_mantle.
   * Boundary parts: left, right, base, ocean_floor (the top seaward of
   * the trench), land (the continental surface).
   */
  template <int dim>
  class SubductionZone : public GeometryModel<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm, const double length_scale) override;
    void
    create_coarse_mesh(
      parallel::distributed::Triangulation<dim> &tria) const override;
    std::map<std::string, types::boundary_id>
    boundary_parts() const override;
    std::map<std::string, types::material_id>
    named_regions() const override;
    std::vector<FaultTrace>
    fault_traces() const override;

  private:
    /** The trench axis: the circle at the Trench position. */
    Point<2>
    trench() const;

    /** x where the circle of radius @p r about the centre has height
     * @p y (the branch right of the centre). */
    double
    x_on_circle(const double y, const double r) const;

    /** Height of the continental surface at @p x. */
    double
    land_surface(const double x) const;

    /** The point of the plate boundary (radius R, right of the centre)
     * where the continental layer boundary @p depth below the surface
     * crosses it. */
    Point<2>
    crossing(const double depth) const;

    double   width, base, sea_floor, radius, trench_x, coast_x, land_height;
    Point<2> centre;
    double   oceanic_crust, oceanic_lid, continental_elastic, continental_crust,
      cell_size;
  };
} // namespace lithostress

#endif
