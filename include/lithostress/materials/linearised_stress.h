#ifndef lithostress_materials_linearised_stress_h
#define lithostress_materials_linearised_stress_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * Newton's linearisation of a non-linear law's step at one quadrature
   * point (doc/equations.md §12): around the iterate's strain ε_k the
   * stress of the step is σ(ε) ≈ C_k ε + σ₀ with the consistent tangent
   * C_k = dσ/dε(ε_k) and σ₀ = σ(ε_k) − C_k ε_k (the loads' initial
   * stresses left out: the loads add them). The next iterate solves the
   * linear problem of this law, so that the time loop's Newton step is one
   * linear solve of the kind every other step makes. Stored as a record of
   * a CellHistory: the tangent's independent components, then σ₀'s.
   */
  template <int dim>
  struct LinearisedStress
  {
    /** The tangent C_k. */
    SymmetricTensor<4, dim> tangent;
    /** σ₀ (in-plane). */
    SymmetricTensor<2, dim> stress;

    /** The number of values of a record. */
    static constexpr unsigned int n_components =
      SymmetricTensor<4, dim>::n_independent_components +
      SymmetricTensor<2, dim>::n_independent_components;

    /** Names of the values (not output; a CellHistory wants them). */
    static std::vector<std::string>
    names()
    {
      std::vector<std::string> result;
      for (unsigned int i = 0; i < n_components; ++i)
        result.push_back("linearisation_" + std::to_string(i));
      return result;
    }

    /** The linearisation of @p record. */
    static LinearisedStress
    from(const Vector<double> &record)
    {
      LinearisedStress l;
      unsigned int     k = 0;
      for (unsigned int i = 0;
           i < SymmetricTensor<4, dim>::n_independent_components;
           ++i)
        l.tangent.access_raw_entry(i) = record[k++];
      for (unsigned int i = 0;
           i < SymmetricTensor<2, dim>::n_independent_components;
           ++i)
        l.stress.access_raw_entry(i) = record[k++];
      return l;
    }

    /** Write this linearisation into @p record (sized n_components). */
    void
    to(Vector<double> &record) const
    {
      unsigned int k = 0;
      for (unsigned int i = 0;
           i < SymmetricTensor<4, dim>::n_independent_components;
           ++i)
        record[k++] = tangent.access_raw_entry(i);
      for (unsigned int i = 0;
           i < SymmetricTensor<2, dim>::n_independent_components;
           ++i)
        record[k++] = stress.access_raw_entry(i);
    }
  };
} // namespace lithostress

#endif
