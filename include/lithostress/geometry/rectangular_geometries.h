#ifndef lithostress_geometry_rectangular_geometries_h
#define lithostress_geometry_rectangular_geometries_h

#include <lithostress/geometry/geometry_model.h>

#include <vector>

namespace lithostress
{
  /**
   * Boundary ids shared by all rectangular geometries: the sides of the
   * rectangle are named `left`, `right`, `base` and `top`.
   */
  std::map<std::string, types::boundary_id>
  rectangle_boundary_parts();

  /**
   * A rectangular block [x0, x1] × [y0, y1] with a given number of cells in
   * each direction, one material (id 0). Used for the lithostatic column
   * (thesis §4.4) and simple block tests.
   */
  template <int dim>
  class RectangularBlock : public GeometryModel<dim>
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
      return "Geometry/Rectangular block";
    }

  private:
    double       x0, x1, y0, y1;
    unsigned int nx, ny;
  };

  /**
   * The cantilever of thesis §4.3 (Timoshenko & Goodier §21): length l along
   * x ∈ [0, l], depth 2c with the neutral fibre on y = 0. The free end is
   * `left`, the supported end `right`.
   */
  template <int dim>
  class CantileverBeam : public GeometryModel<dim>
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
      return "Geometry/Cantilever beam";
    }

  private:
    double       length, depth;
    unsigned int cells_along, cells_through;
  };

  /**
   * A long thin plate x ∈ [0, L], y ∈ [−h, 0] (thesis §6.1.2 flexure): the
   * number of cells along the plate follows from the cells through the
   * thickness so that coarse cells are as square as possible.
   */
  template <int dim>
  class ThinPlate : public GeometryModel<dim>
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
      return "Geometry/Thin plate";
    }

  private:
    double       length, thickness;
    unsigned int cells_through;
  };

  /**
   * A box x ∈ [0, W] made of horizontal layers between given interface
   * heights (top first), each layer a material id and a named region; the
   * lithosphere columns of thesis chapters 6 and 7. Optionally cut by
   * faults from the top to the base, planar or listric (thesis §6.1-6.3):
   * the coarse cells are then trapezoids whose column boundaries follow
   * the faults, so that each fault is a curve of cell faces on every
   * refinement.
   */
  template <int dim>
  class LayeredBox : public GeometryModel<dim>
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
      return "Geometry/Layered box";
    }
    std::map<std::string, types::material_id>
    named_regions() const override;
    std::vector<FaultTrace>
    fault_traces() const override;

  private:
    /** The faults' entries (`Fault surface x`, `Fault names`, `Fault
     * dip`, `Fault dips towards`, the arc's and the buried ends'): each
     * fault's trace as given, planar or listric (thesis §6.1-6.3), into
     * `faults`, `surface_x_given`, `top_depths` and `bottom_depths`. One
     * value for all faults or one per fault. */
    void
    parse_fault_geometry(ParameterHandler &prm, const double scale);

    /** `Fault arc centre` (@p entry): one `x, y` per fault, separated by
     * `;`, an empty one for a planar fault, or one for all faults. */
    static std::vector<std::string>
    arc_centres(const std::string &entry, const unsigned int n_faults);

    /** The arc of a listric @p fault: its centre, radius and the depth
     * where it begins, as given (in the length unit). */
    static void
    parse_fault_arc(FaultTrace        &fault,
                    const std::string &centre,
                    const std::string &radius,
                    const std::string &from_depth,
                    const double       scale);

    /** Place fault @p k in the box of the parsed layers: its surface
     * trace (implied by its arc for `auto`), and check that it crosses the
     * box from the top to the base. */
    void
    place_fault(const unsigned int k, const double scale);

    /** The arc of fault @p k in the box: it must reach from where it
     * begins (a row of the coarse mesh) to the base without turning back;
     * it fixes or checks the surface trace. */
    void
    place_fault_arc(const unsigned int k, const double scale);

    /** The buried ends of fault @p k (`Fault top depth`, `Fault bottom
     * depth`): each on a row of the coarse mesh, the top above the
     * bottom, both in the box; sets the trace's own part. */
    void
    place_fault_ends(const unsigned int k, const double scale);

    /** Whether the height @p y is a row of the coarse mesh's vertices (a
     * layer interface or a row of `Cells per layer`). */
    bool
    on_coarse_row(const double y) const;

    /** Sort the faults left to right at mid-depth; throw if two meet or
     * cross in the box. */
    void
    check_faults_apart(const double scale);

    double                    width;
    std::vector<double>       interfaces;
    std::vector<std::string>  layer_names;
    std::vector<unsigned int> cells_per_layer;
    unsigned int              cells_across;
    /** The faults through the box (`Fault surface x`), left to right:
     * planar, or with a circular arc below a depth. */
    std::vector<FaultTrace> faults;
    /** `Fault surface x` as given [m] (NaN for `auto`). */
    std::vector<double> surface_x_given;
    /** `Fault top depth` and `Fault bottom depth` as given [m] (bottom:
     * NaN for `base`). */
    std::vector<double> top_depths, bottom_depths;
  };
} // namespace lithostress

#endif
