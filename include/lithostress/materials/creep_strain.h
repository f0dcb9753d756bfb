#ifndef lithostress_materials_creep_strain_h
#define lithostress_materials_creep_strain_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/symmetric_tensor.h>

#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The deviatoric creep strain of a creeping law as components of its
   * history (thesis §3.9, doc/equations.md §10): the 3-D tensor — xx, yy,
   * xy and zz in 2-D, where plane strain keeps ε_zz = 0 but creep in z does
   * not vanish; the six of the symmetric tensor in 3-D. MaxwellRheology
   * keeps these as its history; a law that also creeps keeps them and adds
   * its own components after them.
   */
  template <int dim>
  struct CreepStrain
  {
    /** The number of components. */
    static constexpr unsigned int n_components = dim == 2 ? 4 : 6;

    /** The names of the components (creep_xx, creep_yy, creep_xy, creep_zz
     * in 2-D): the ParaView fields and the checkpoint's layout. */
    static std::vector<std::string>
    names();

    /** The 3-D tensor of the n_components values @p c. */
    static SymmetricTensor<2, 3>
    tensor(const ArrayView<const double> &c);

    /** The components of @p t into the n_components values @p c (the
     * inverse of tensor()). */
    static void
    components(const SymmetricTensor<2, 3> &t, const ArrayView<double> &c);
  };
} // namespace lithostress

#endif
