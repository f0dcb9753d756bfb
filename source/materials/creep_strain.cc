#include <lithostress/materials/creep_strain.h>

namespace lithostress
{
  template <int dim>
  std::vector<std::string>
  CreepStrain<dim>::names()
  {
    if (dim == 2)
      return {"creep_xx", "creep_yy", "creep_xy", "creep_zz"};
    return {
      "creep_xx", "creep_yy", "creep_zz", "creep_xy", "creep_yz", "creep_xz"};
  }

  template <int dim>
  SymmetricTensor<2, 3>
  CreepStrain<dim>::tensor(const ArrayView<const double> &c)
  {
    AssertDimension(c.size(), n_components);
    SymmetricTensor<2, 3> t;
    if constexpr (dim == 2)
      {
        t[0][0] = c[0];
        t[1][1] = c[1];
        t[0][1] = c[2];
        t[2][2] = c[3];
      }
    else
      {
        t[0][0] = c[0];
        t[1][1] = c[1];
        t[2][2] = c[2];
        t[0][1] = c[3];
        t[1][2] = c[4];
        t[0][2] = c[5];
      }
    return t;
  }

  template <int dim>
  void
  CreepStrain<dim>::components(const SymmetricTensor<2, 3> &t,
                               const ArrayView<double>     &c)
  {
    AssertDimension(c.size(), n_components);
    if constexpr (dim == 2)
      {
        c[0] = t[0][0];
        c[1] = t[1][1];
        c[2] = t[0][1];
        c[3] = t[2][2];
      }
    else
      {
        c[0] = t[0][0];
        c[1] = t[1][1];
        c[2] = t[2][2];
        c[3] = t[0][1];
        c[4] = t[1][2];
        c[5] = t[0][2];
      }
  }

  template struct CreepStrain<2>;
} // namespace lithostress
