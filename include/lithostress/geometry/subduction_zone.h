#ifndef lithostress_geometry_subduction_zone_h
#define lithostress_geometry_subduction_zone_h

#include <lithostress/geometry/geometry_model.h>

namespace lithostress
{
  class BlockMesh;

  /**
   * The cross section of an active continental margin of thesis §7.2
   * (doc/subduction.md): an oceanic plate on the left (crust, elastic lid and
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
    std::string
    mesh_entry() const override
    {
      return "Geometry/Subduction zone";
    }
    std::map<std::string, types::material_id>
    named_regions() const override;
    std::vector<FaultTrace>
    fault_traces() const override;

  private:
    /** The numbers of coarse cells of the blocks. */
    struct CellCounts
    {
      /** Through the oceanic crust and through the rest of the lid. */
      unsigned int crust, lid;
      /** Through the continental upper crust, lower crust and mantle; the
       * mantle's count (even) also through the oceanic mantle, which it
       * meets at the slab's end. */
      unsigned int continental[3];
      /** Along the continental surface from the trench to the coast. */
      unsigned int wedge;
      /** Along the slab between consecutive stations. */
      unsigned int along_slab[3];
    };

    /** Cells along @p length: the Coarse cell size, at least one. */
    unsigned int
    cells_along(const double length) const;

    /** The unit vector from the circle's centre towards @p p. */
    Tensor<1, 2>
    direction_to(const Point<2> &p) const;

    /** Where the ray from the centre in direction @p u meets the base. */
    Point<2>
    at_base(const Tensor<1, 2> &u) const;

    /** The stations across the slab: the directions from the centre of
     * the circle's top, the trench and the two crossings of the
     * continental layer boundaries with the plate boundary. */
    std::vector<Tensor<1, 2>>
    slab_stations() const;

    /** The cell counts: the Coarse cell size through each layer and along
     * the slab between the stations @p station, the arcs along the plate
     * boundary counted for the continental layers beside them. */
    CellCounts
    cell_counts(const std::vector<Tensor<1, 2>> &station) const;

    /** The oceanic plate seaward of the circle's top: flat layers of crust,
     * lid and mantle (material ids 0, 1, 2). */
    void
    build_oceanic_plate(BlockMesh &blocks, const CellCounts &n) const;

    /** The slab between consecutive stations: crust and lid between the
     * concentric arcs, the mantle below them down to the base. */
    void
    build_slab_blocks(BlockMesh                       &blocks,
                      const std::vector<Tensor<1, 2>> &station,
                      const CellCounts                &n) const;

    /** The slab's end, from the last station @p u to the base: crust and
     * lid along the arcs, the mantle below as a three-sided region. */
    void
    build_slab_end(BlockMesh          &blocks,
                   const Tensor<1, 2> &u,
                   const CellCounts   &n) const;

    /** The continental plate's upper crust, lower crust and mantle
     * (material ids 3, 4, 5) between the plate boundary and the right
     * edge, their tops following the surface, which kinks at the coast. */
    void
    build_continental_plate(BlockMesh &blocks, const CellCounts &n) const;

    /** A PolarManifold (id 1) on the faces on the plate boundary's circle
     * and the slab's concentric arcs, a TransfiniteInterpolationManifold
     * (id 2) on their cells. */
    void
    attach_circle_manifolds(
      parallel::distributed::Triangulation<dim> &tria) const;

    /** The boundary parts: left, right, base, ocean_floor (the top
     * seaward of the trench) and land. */
    void
    set_boundary_ids(parallel::distributed::Triangulation<dim> &tria) const;

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
    /** The `Length unit` (m or km) and its length [m], for messages. */
    double      length_scale;
    std::string length_unit;
  };
} // namespace lithostress

#endif
