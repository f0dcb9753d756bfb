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

  /** The integer entry @p entry, at least 1; else InputError naming
   * @p where + @p entry. */
  unsigned int
  positive_count(ParameterHandler  &prm,
                 const std::string &entry,
                 const std::string &where);

  /** The length entry @p entry times @p scale [m], positive; else
   * InputError naming @p where + @p entry. */
  double
  positive_length(ParameterHandler  &prm,
                  const std::string &entry,
                  const std::string &where,
                  const double       scale);

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

} // namespace lithostress

#endif
