#ifndef lithostress_materials_material_h
#define lithostress_materials_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The properties of one rock type (thesis §3.6.2, tables 6.1 and 7.1):
   * isotropic elasticity, density, tensile strength for the Griffith test and
   * the Maxwell viscosity (0 = purely elastic; used by the visco-elastic loop).
   */
  struct Material
  {
    std::string        name;
    types::material_id id;
    /** Young's modulus E [Pa]. */
    double youngs_modulus;
    /** Poisson's ratio ν, −1 < ν < 1/2. */
    double poissons_ratio;
    /** Density ρ [kg m⁻³]. */
    double density;
    /** Tensile strength T [Pa]. */
    double tensile_strength;
    /** Viscosity η [Pa s]; 0 means elastic. */
    double viscosity;
    /** The name of its rock law (a registered Rheology; `automatic`
     * resolved: maxwell with a viscosity, elastic without). */
    std::string rheology;

    /** Shear modulus G = E / 2(1 + ν). */
    double
    shear_modulus() const;
    /** Lamé's first parameter λ = Eν / (1 + ν)(1 − 2ν) (3-D). */
    double
    lame_lambda() const;
  };

  /**
   * The materials of a model, by name and material id. Each material is a
   * subsection of `Materials` named by the user in `Materials/Names`. A
   * material's id is given explicitly or, for meshes whose regions are named
   * (Gmsh physical groups, layered boxes), found from its name.
   */
  class MaterialLibrary
  {
  public:
    /** Declare `Materials` with one subsection per name in @p names. */
    static void
    declare_parameters(ParameterHandler &prm, ParameterHandler *first_pass);

    /** Read and check all materials (E > 0, −1 < ν < 1/2, ρ, T, η ≥ 0). */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Give materials declared without an id the id of the mesh region of
     * the same name, then check that every id in @p ids_in_mesh has exactly
     * one material. Throws InputError naming the id or the material.
     */
    void
    resolve(const std::map<std::string, types::material_id> &named_regions,
            const std::set<types::material_id>              &ids_in_mesh);

    /** The material with id @p id. */
    const Material &
    operator()(const types::material_id id) const;

    /** All materials. */
    const std::vector<Material> &
    materials() const;

    /** The largest Young's modulus of the materials [Pa]: the rock's
     * stiffness that a spring's is measured against (RigidBodySupport). */
    double
    largest_youngs_modulus() const;

    /** Whether a material has id @p id. */
    bool
    has(const types::material_id id) const;

  private:
    std::vector<Material>                      all;
    std::vector<bool>                          id_given;
    std::map<types::material_id, unsigned int> index_of_id;
  };
} // namespace lithostress

#endif
