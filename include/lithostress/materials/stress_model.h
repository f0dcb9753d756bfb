#ifndef lithostress_materials_stress_model_h
#define lithostress_materials_stress_model_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <lithostress/loads/load_collection.h>
#include <lithostress/materials/elastic_moduli.h>
#include <lithostress/materials/material.h>

#include <map>
#include <vector>

namespace lithostress
{
  /** The stress at a point: the in-plane tensor and σ_zz (tension positive). */
  template <int dim>
  struct StressState
  {
    SymmetricTensor<2, dim> in_plane;
    double                  zz = 0;
  };

  /**
   * The constitutive law as every result sees it (SPEC §3.1, σ = C(ε − ε0)):
   * the elastic stress of the cell's material in the model's plane state plus
   * the stresses of the initial strains carried by loads (thermal strain,
   * §3.8). Output, point values, stress–depth profiles, error norms and
   * refinement indicators all take their stress from here, so that an
   * initial strain enters every result once and in the same way.
   */
  template <int dim>
  class StressModel
  {
  public:
    StressModel(const MaterialLibrary     &materials,
                const PlaneState           plane_state,
                const LoadCollection<dim> &loads);

    /** The stress at @p p in a cell of material @p id with strain @p strain. */
    StressState<dim>
    stress(const types::material_id       id,
           const Point<dim>              &p,
           const SymmetricTensor<2, dim> &strain) const;

    /** The moduli of material @p id. */
    const ElasticModuli<dim> &
    moduli(const types::material_id id) const
    {
      return moduli_of.at(id);
    }

    /** Whether any load carries an initial strain. */
    bool
    has_initial_stress() const
    {
      return !initial_stress_loads.empty();
    }

    const MaterialLibrary &materials;
    const PlaneState       plane_state;

  private:
    std::map<types::material_id, ElasticModuli<dim>> moduli_of;
    std::vector<const Load<dim> *>                   initial_stress_loads;
  };
} // namespace lithostress

#endif
