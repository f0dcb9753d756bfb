#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_q.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/parsed_expression.h>
#include <lithostress/loads/load.h>

#include <cmath>
#include <limits>

namespace lithostress
{
  template <int dim>
  types::boundary_id
  ModelDescription<dim>::boundary_id(const std::string &name,
                                     const std::string &entry) const
  {
    const auto it = boundary_parts.find(name);
    if (it == boundary_parts.end())
      {
        std::string known;
        for (const auto &part : boundary_parts)
          known += (known.empty() ? "" : ", ") + part.first;
        throw_input_error(entry,
                          "the mesh has no boundary part <" + name +
                            "> (it has: " + known + ")");
      }
    return it->second;
  }

  template <int dim>
  void
  Load<dim>::add_cell_terms(const FEValues<dim> &,
                            const FEValuesExtractors::Vector &,
                            const Material &,
                            const ElasticModuli<dim> &,
                            FullMatrix<double> &,
                            Vector<double> &) const
  {
  }

  template <int dim>
  bool
  Load<dim>::acts_on_boundary(const types::boundary_id) const
  {
    return false;
  }

  template <int dim>
  void
  Load<dim>::add_boundary_terms(const FEFaceValues<dim> &,
                                const types::boundary_id,
                                const FEValuesExtractors::Vector &,
                                FullMatrix<double> &,
                                Vector<double> &) const
  {
  }

  template <int dim>
  void
  Load<dim>::add_point_terms(const DoFHandler<dim> &,
                             const FiniteElementSpace<dim> &,
                             const AffineConstraints<double> &,
                             TrilinosWrappers::MPI::Vector &) const
  {
  }

  template <int dim>
  void
  Load<dim>::check_against_mesh(const Triangulation<dim> &,
                                const Mapping<dim> &) const
  {
  }

  template <int dim>
  void
  Load<dim>::prepare_for_mesh(const Triangulation<dim> &,
                              const Mapping<dim> &,
                              const Quadrature<dim - 1> &)
  {
  }

  template <int dim>
  void
  Load<dim>::add_initial_stress(const Point<dim> &,
                                const Material &,
                                const ElasticModuli<dim> &,
                                SymmetricTensor<2, dim> &,
                                double &) const
  {
  }

  template <int dim>
  bool
  point_in_mesh(const Triangulation<dim> &tria,
                const Mapping<dim>       &mapping,
                const Point<dim>         &p)
  {
    for (const auto &cell : tria.cell_iterators_on_level(0))
      {
        try
          {
            const Point<dim> unit =
              mapping.transform_real_to_unit_cell(cell, p);
            if (GeometryInfo<dim>::is_inside_unit_cell(unit, 1e-8))
              return true;
          }
        catch (const typename Mapping<dim>::ExcTransformationFailed &)
          {
          }
      }
    return false;
  }

  template <int dim>
  double
  boundary_profile_integral(const Triangulation<dim>    &tria,
                            const Mapping<dim>          &mapping,
                            const Quadrature<dim - 1>   &face_quadrature,
                            const types::boundary_id     id,
                            const ParsedExpression<dim> &profile,
                            const std::string           &entry)
  {
    const FE_Q<dim>   fe(1);
    FEFaceValues<dim> face_values(mapping,
                                  fe,
                                  face_quadrature,
                                  update_quadrature_points | update_JxW_values);
    const MPI_Comm    communicator = tria.get_communicator();
    double            integral     = 0;
    // Collected first and checked on every rank, so that no rank leaves
    // the collective sums below alone.
    double lowest = 0;
    on_all_ranks(communicator, [&]() {
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == id)
              {
                face_values.reinit(cell, f);
                for (const unsigned int q :
                     face_values.quadrature_point_indices())
                  {
                    const double w =
                      profile.value(face_values.quadrature_point(q));
                    if (!(w >= 0))
                      lowest = std::isnan(w)
                                 ? -std::numeric_limits<double>::infinity()
                                 : std::min(lowest, w);
                    integral += w * face_values.JxW(q);
                  }
              }
    });
    lowest = Utilities::MPI::min(lowest, communicator);
    if (lowest < 0 || std::isnan(lowest))
      throw_input_error(entry,
                        "is negative (" + std::to_string(lowest) +
                          ") on the part");
    integral = Utilities::MPI::sum(integral, communicator);
    if (!(integral > 0))
      throw_input_error(entry,
                        "integrates to zero over the part: the resultant "
                        "cannot be spread");
    return integral;
  }

  template double
  boundary_profile_integral<2>(const Triangulation<2> &,
                               const Mapping<2> &,
                               const Quadrature<1> &,
                               const types::boundary_id,
                               const ParsedExpression<2> &,
                               const std::string &);
  template bool
  point_in_mesh<2>(const Triangulation<2> &,
                   const Mapping<2> &,
                   const Point<2> &);
  template struct ModelDescription<2>;
  template <int dim>
  void
  Load<dim>::add_vertical_spring_terms(
    const FEFaceValues<dim>          &fe_face_values,
    const double                      k,
    const FEValuesExtractors::Vector &displacement,
    FullMatrix<double>               &cell_matrix)
  {
    const unsigned int  n = fe_face_values.dofs_per_cell;
    std::vector<double> phi_y(n);
    for (const unsigned int q : fe_face_values.quadrature_point_indices())
      {
        const double w = k *
                         std::abs(fe_face_values.normal_vector(q)[dim - 1]) *
                         fe_face_values.JxW(q);
        for (unsigned int i = 0; i < n; ++i)
          phi_y[i] = fe_face_values[displacement].value(i, q)[dim - 1];
        for (unsigned int i = 0; i < n; ++i)
          if (phi_y[i] != 0)
            for (unsigned int j = 0; j < n; ++j)
              cell_matrix(i, j) += w * phi_y[i] * phi_y[j];
      }
  }

  template class Load<2>;
} // namespace lithostress
