#ifndef lithostress_geometry_layered_box_h
#define lithostress_geometry_layered_box_h

#include <lithostress/geometry/fault_trace.h>
#include <lithostress/geometry/rectangular_geometries.h>

#include <vector>

namespace lithostress
{
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
     * layer interface, a row of `Cells per layer`, or of the graded rows). */
    bool
    on_coarse_row(const double y) const;

    /** The heights of the coarse mesh's rows of vertices from the base up
     * into `rows`: each layer divided evenly into its `Cells per layer`,
     * or, with a `Fault cell size`, graded from the top down to the
     * deepest end of a fault's own part, with a row at every layer
     * interface, every buried fault end and every arc's start (the
     * entries as given, in m). */
    void
    set_rows();

    /** The fractions of the width between the two boundaries of each
     * region between the box's sides and the faults (left to right) at
     * which the coarse mesh has its column boundaries: even (`Cells
     * across` shared by the regions), or graded from the faults with a
     * `Fault cell size`. Each region's list runs from 0 to 1. */
    std::vector<std::vector<double>>
    column_fractions() const;

    /** Sort the faults left to right at mid-depth; throw if two meet or
     * cross in the box. */
    void
    check_faults_apart(const double scale);

    double                    width;
    std::vector<double>       interfaces;
    std::vector<std::string>  layer_names;
    std::vector<unsigned int> cells_per_layer;
    unsigned int              cells_across;
    /** `Fault cell size` [m] (0: cells divided evenly) and `Cell size
     * growth` of the graded coarse mesh. */
    double fault_cell_size = 0, cell_size_growth = 1.5;
    /** The most cells a graded coarse mesh may have (a p4est tree each,
     * about a kilobyte; refinement gives the fine meshes). */
    static constexpr std::size_t max_coarse_cells = 1000000;
    /** The coarse mesh's rows of vertices, from the base up (set_rows). */
    std::vector<double> rows;
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
