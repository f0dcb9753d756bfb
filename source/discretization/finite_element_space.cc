#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <lithostress/discretization/finite_element_space.h>

namespace lithostress
{
  template <int dim>
  FiniteElementSpace<dim>::FiniteElementSpace(const unsigned int degree,
                                              const unsigned int mapping_degree,
                                              const unsigned int n_fields)
      : polynomial_degree(degree)
      , n_displacement_fields(n_fields)
      , mapping_q(std::make_unique<CachedMappingQ<dim>>(mapping_degree))
      , mappings(*mapping_q)
  {
    const FE_Q<dim> q(degree);
    scalar_support_points = q.get_unit_support_points();
    for (unsigned int f = 0; f < n_fields; ++f)
      {
        std::vector<const FiniteElement<dim> *> elements;
        std::vector<unsigned int>               multiplicities;
        for (unsigned int g = 0; g < n_fields; ++g)
          {
            if (g == f)
              elements.push_back(new FE_Q<dim>(degree));
            else
              elements.push_back(new FE_Nothing<dim>());
            multiplicities.push_back(dim);
          }
        fe.push_back(FESystem<dim>(elements, multiplicities));
        for (const auto *e : elements)
          delete e;
      }
  }

  template <int dim>
  hp::QCollection<dim>
  FiniteElementSpace<dim>::cell_quadrature(const unsigned int extra) const
  {
    hp::QCollection<dim> q;
    for (unsigned int f = 0; f < fe.size(); ++f)
      q.push_back(QGauss<dim>(polynomial_degree + 1 + extra));
    return q;
  }

  template <int dim>
  hp::QCollection<dim - 1>
  FiniteElementSpace<dim>::face_quadrature(const unsigned int extra) const
  {
    hp::QCollection<dim - 1> q;
    for (unsigned int f = 0; f < fe.size(); ++f)
      q.push_back(QGauss<dim - 1>(polynomial_degree + 1 + extra));
    return q;
  }

  template class FiniteElementSpace<2>;
} // namespace lithostress
