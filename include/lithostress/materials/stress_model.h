#ifndef lithostress_materials_stress_model_h
#define lithostress_materials_stress_model_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <lithostress/materials/creep_strain.h>
#include <lithostress/materials/elastic_moduli.h>
#include <lithostress/materials/initial_stress_source.h>
#include <lithostress/materials/material.h>
#include <lithostress/materials/maxwell_material.h>
#include <lithostress/materials/creep_strain.h>

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
   * The constitutive law as every result sees it (thesis eq. 3.38,
   * σ = C(ε − ε0)): the elastic stress of the cell's material in the model's
   * plane state plus the stresses of the initial strains carried by loads
   * (thermal strain, §3.8). Output, point values, stress–depth profiles, error
   * norms and refinement indicators all take their stress from here, so that
   * an initial strain enters every result once and in the same way.
   *
   * With Maxwell materials (thesis §3.9) the model also holds the creep-strain
   * history (attach_creep_strain()): every reported stress is then
   * σ = C (ε − c) + thermal stress, with the elastic moduli and the creep
   * strain c at the point, and a time step's linear system uses the relaxed
   * moduli of step_moduli() (set_time_step()).
   */
  template <int dim>
  class StressModel
  {
  public:
    /** The stress of @p materials in @p plane_state, with the initial
     * stresses of those @p sources that carry one (the model's loads). */
    StressModel(const MaterialLibrary                           &materials,
                const PlaneState                                 plane_state,
                const std::vector<const InitialStressSource<dim> *> &sources);

    /** The stress at @p p in a cell of material @p id with strain @p strain. */
    StressState<dim>
    stress(const types::material_id       id,
           const Point<dim>              &p,
           const SymmetricTensor<2, dim> &strain) const;

    /** The stress at @p p for strain @p strain and creep strain @p creep
     * (3-D, deviatoric). */
    StressState<dim>
    stress(const types::material_id       id,
           const Point<dim>              &p,
           const SymmetricTensor<2, dim> &strain,
           const SymmetricTensor<2, 3>   &creep) const;

    /**
     * The stress at the point @p p of @p cell whose unit-cell coordinates
     * are @p unit: the creep strain attached to the model, if any, is
     * evaluated there. What every reported stress goes through.
     */
    StressState<dim>
    stress(const typename Triangulation<dim>::active_cell_iterator &cell,
           const Point<dim>                                        &unit,
           const Point<dim>                                        &p,
           const SymmetricTensor<2, dim> &strain) const;

    /**
     * The stress of the current time step's law at @p p: the step moduli
     * (relaxed shear modulus) with the history strain @p history as initial
     * strain (MaxwellMaterial). Equal to stress() for elastic materials or
     * a step of length 0.
     */
    StressState<dim>
    step_stress(const types::material_id       id,
                const Point<dim>              &p,
                const SymmetricTensor<2, dim> &strain,
                const SymmetricTensor<2, 3>   &history) const;

    /** The elastic moduli of material @p id. */
    const ElasticModuli<dim> &
    moduli(const types::material_id id) const
    {
      return moduli_of.at(id);
    }

    /** The moduli of the current time step's linear system (assembly and
     * matrix-free operators): relaxed for Maxwell materials, elastic
     * before the first step. */
    const ElasticModuli<dim> &
    step_moduli(const types::material_id id) const
    {
      return step_moduli_of.at(id);
    }

    /** The Maxwell law of material @p id. */
    const MaxwellMaterial<dim> &
    maxwell(const types::material_id id) const
    {
      return maxwell_of.at(id);
    }

    /** Whether any material creeps. */
    bool
    has_viscous_material() const;

    /** Use the step moduli of a step of length @p dt with weight
     * @p theta (dt = 0: the elastic moduli). */
    void
    set_time_step(const double dt, const double theta);

    /** Changes whenever set_time_step() changes the step moduli. */
    unsigned long long
    moduli_version() const
    {
      return version;
    }

    /** Include the creep strain @p creep in every reported stress
     * (nullptr: none). */
    void
    attach_creep_strain(const CreepStrain<dim> *creep)
    {
      creep_strain = creep;
    }

    /** The attached creep strain, or nullptr. */
    const CreepStrain<dim> *
    attached_creep_strain() const
    {
      return creep_strain;
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
    std::map<types::material_id, ElasticModuli<dim>>   moduli_of;
    std::map<types::material_id, ElasticModuli<dim>>   step_moduli_of;
    std::map<types::material_id, MaxwellMaterial<dim>> maxwell_of;
    std::vector<const InitialStressSource<dim> *>      initial_stress_loads;
    const CreepStrain<dim>                            *creep_strain = nullptr;
    double             step_length = 0, step_theta = 1;
    unsigned long long version = 0;
  };
} // namespace lithostress

#endif
