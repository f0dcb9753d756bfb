#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <lithostress/base/gather_on_all.h>
#include <lithostress/solvers/fault_zone_correction.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Import.h>
#include <Epetra_Map.h>
#include <Epetra_Vector.h>

#include <algorithm>
#include <numeric>
#include <unordered_map>

namespace lithostress
{
  namespace
  {
    /** An entry of the zone's matrix A_zz (zone indices). */
    struct ZoneEntry
    {
      unsigned int row, column;
      double       value;
    };

    /** Row @p row of @p a as (length, values, local columns). */
    struct RowView
    {
      int     length  = 0;
      double *values  = nullptr;
      int    *columns = nullptr;

      RowView(const Epetra_CrsMatrix &a, const int row)
      {
        a.ExtractMyRowView(row, length, values, columns);
      }
    };

    /** Whether each of @p a's local rows lies within @p layers layers of
     * the matrix graph from the local rows @p seeds: each layer adds the
     * rows the zone's rows reach, also across ranks (a rank's reached
     * columns sent to all, each taking its own). */
    std::vector<char>
    rows_within(const TrilinosWrappers::SparseMatrix &a,
                const std::vector<unsigned int>      &seeds,
                const unsigned int                    layers)
    {
      const Epetra_CrsMatrix &epetra = a.trilinos_matrix();
      const int               n_rows = epetra.NumMyRows();
      // A local column's local row (the vectors' index), -1 off this rank.
      std::vector<int> column_row(epetra.NumMyCols());
      for (int c = 0; c < epetra.NumMyCols(); ++c)
        column_row[c] = epetra.RowMap().LID(epetra.GCID64(c));
      std::vector<char> in_zone(n_rows, 0);
      for (const unsigned int seed : seeds)
        in_zone[seed] = 1;
      const MPI_Comm communicator = a.get_mpi_communicator();
      for (unsigned int layer = 0; layer < layers; ++layer)
        {
          std::vector<char>                              grown = in_zone;
          std::vector<TrilinosWrappers::types::int_type> elsewhere;
          for (int r = 0; r < n_rows; ++r)
            if (in_zone[r])
              {
                const RowView row(epetra, r);
                for (int e = 0; e < row.length; ++e)
                  if (column_row[row.columns[e]] >= 0)
                    grown[column_row[row.columns[e]]] = 1;
                  else
                    elsewhere.push_back(
                      static_cast<TrilinosWrappers::types::int_type>(
                        epetra.GCID64(row.columns[e])));
              }
          if (Utilities::MPI::n_mpi_processes(communicator) > 1)
            for (const auto gid : gather_on_all(communicator, elsewhere))
              if (const int r = epetra.RowMap().LID(gid); r >= 0)
                grown[r] = 1;
          in_zone.swap(grown);
        }
      return in_zone;
    }
  } // namespace

  FaultZoneCorrection::FaultZoneCorrection() = default;

  FaultZoneCorrection::~FaultZoneCorrection() = default;

  bool
  FaultZoneCorrection::initialize(const TrilinosWrappers::SparseMatrix &a,
                                  const std::vector<unsigned int>      &seeds,
                                  const unsigned int                    layers,
                                  const double largest_fraction)
  {
    const Epetra_CrsMatrix &epetra       = a.trilinos_matrix();
    const int               n_rows       = epetra.NumMyRows();
    const MPI_Comm          communicator = a.get_mpi_communicator();
    const std::vector<char> in_zone      = rows_within(a, seeds, layers);
    rows.clear();
    offsets.assign(1, 0);
    columns.clear();
    values.clear();
    import.reset();
    column_values.reset();
    column_map.reset();
    local.reinit(0);
    factor.reset();
    factor_bytes = 0;
    // Each rank's number of zone rows: their sum is the whole zone's, and
    // the ranks' rows are numbered one rank after the other (this rank's
    // from `first`).
    const std::vector<unsigned int> counts = Utilities::MPI::all_gather(
      communicator,
      static_cast<unsigned int>(std::count(in_zone.begin(), in_zone.end(), 1)));
    const unsigned int rank = Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n    = std::accumulate(counts.begin(), counts.end(), 0u);
    first = std::accumulate(counts.begin(), counts.begin() + rank, 0u);
    if (n > largest_fraction * a.m())
      return false;
    // The zone's rows and their entries; their columns (this rank's and
    // other ranks') are read through a vector of just those columns.
    std::vector<TrilinosWrappers::types::int_type> needed;
    std::unordered_map<TrilinosWrappers::types::int_type, unsigned int>
      position;
    for (int r = 0; r < n_rows; ++r)
      {
        if (!in_zone[r])
          continue;
        rows.push_back(r);
        const RowView row(epetra, r);
        for (int e = 0; e < row.length; ++e)
          {
            const auto gid = static_cast<TrilinosWrappers::types::int_type>(
              epetra.GCID64(row.columns[e]));
            const auto [entry, added] = position.emplace(gid, needed.size());
            if (added)
              needed.push_back(gid);
            columns.push_back(entry->second);
            values.push_back(row.values[e]);
          }
        offsets.push_back(columns.size());
      }
    const Epetra_Map &source = a.trilinos_matrix().DomainMap();
    column_map               = std::make_unique<Epetra_Map>(
      -1, static_cast<int>(needed.size()), needed.data(), 0, source.Comm());
    import        = std::make_unique<Epetra_Import>(*column_map, source);
    column_values = std::make_unique<Epetra_Vector>(*column_map);

    // The whole zone on every rank, A_zz from all ranks' rows, so that the
    // correction is the same as on one rank.
    std::vector<TrilinosWrappers::types::int_type> mine;
    for (const unsigned int r : rows)
      mine.push_back(
        static_cast<TrilinosWrappers::types::int_type>(epetra.GRID64(r)));
    const auto all_rows = gather_on_all(communicator, mine);
    AssertDimension(all_rows.size(), n);
    std::unordered_map<TrilinosWrappers::types::int_type, unsigned int> zone_of;
    for (unsigned int z = 0; z < n; ++z)
      zone_of[all_rows[z]] = z;
    std::vector<ZoneEntry> entries;
    for (unsigned int i = 0; i < rows.size(); ++i)
      for (auto e = offsets[i]; e < offsets[i + 1]; ++e)
        if (const auto z = zone_of.find(needed[columns[e]]); z != zone_of.end())
          entries.push_back({first + i, z->second, values[e]});
    DynamicSparsityPattern zone_pattern(n, n);
    for (unsigned int i = 0; i < n; ++i)
      zone_pattern.add(i, i);
    const std::vector<ZoneEntry> all_entries =
      gather_on_all(communicator, entries);
    for (const ZoneEntry &entry : all_entries)
      zone_pattern.add(entry.row, entry.column);
    // (UMFPACK copies A_zz: the matrix is not kept.)
    SparsityPattern      pattern;
    SparseMatrix<double> block;
    pattern.copy_from(zone_pattern);
    block.reinit(pattern);
    for (const ZoneEntry &entry : all_entries)
      block.add(entry.row, entry.column, entry.value);
    // A row no function of the level reaches (a coarser level's hanging
    // node) is zero, and so is its residual: kept at zero.
    for (unsigned int i = 0; i < n; ++i)
      if (block.diag_element(i) == 0)
        block.set(i, i, 1.);
    if (n > 0)
      {
        factor = std::make_unique<SparseDirectUMFPACK>();
        factor->initialize(block);
        factor_bytes = block.memory_consumption();
      }
    local.reinit(n);
    return true;
  }

  void
  FaultZoneCorrection::correct(TrilinosWrappers::MPI::Vector       &x,
                               const TrilinosWrappers::MPI::Vector &b) const
  {
    Assert(import != nullptr,
           ExcMessage("FaultZoneCorrection::correct() needs a zone: "
                      "initialize() returned false or was not called"));
    // (Collective: every rank imports its zone's columns, also an empty
    // zone.)
    column_values->Import(x.trilinos_vector(), *import, Insert);
    if (local.size() == 0)
      return;
    const double *x_columns = column_values->Values();
    const double *b_values  = b.begin();
    local                   = 0;
    for (unsigned int i = 0; i < rows.size(); ++i)
      {
        double residual = b_values[rows[i]];
        for (auto e = offsets[i]; e < offsets[i + 1]; ++e)
          residual -= values[e] * x_columns[columns[e]];
        local[first + i] = residual;
      }
    const MPI_Comm communicator = b.get_mpi_communicator();
    if (Utilities::MPI::n_mpi_processes(communicator) > 1)
      Utilities::MPI::sum(local, communicator, local);
    factor->solve(local);
    double *x_values = x.begin();
    for (unsigned int i = 0; i < rows.size(); ++i)
      x_values[rows[i]] += local[first + i];
  }

  std::size_t
  FaultZoneCorrection::memory_consumption() const
  {
    return rows.capacity() * sizeof(unsigned int) +
           offsets.capacity() * sizeof(std::size_t) +
           columns.capacity() * sizeof(unsigned int) +
           values.capacity() * sizeof(double) +
           (column_values ? column_values->MyLength() * sizeof(double) : 0) +
           factor_bytes + local.memory_consumption();
  }
} // namespace lithostress
