#ifndef lithostress_analysis_convergence_study_h
#define lithostress_analysis_convergence_study_h

#include <ostream>
#include <string>
#include <vector>

namespace lithostress
{
  /**
   * The table of a convergence study: one row per refinement cycle with
   * cells and DoFs, error columns with their convergence rate in DoFs
   * (rate = −Δlog e / Δlog N; for Q2 in 2-D the optimal L2 rate is 1.5 and
   * the energy rate 1, i.e. 3 and 2 in h), and functional columns (point
   * values, integrals) with their change from the previous cycle. Printed
   * on screen and written as CSV.
   */
  class ConvergenceStudy
  {
  public:
    enum class Kind
    {
      error,
      functional
    };

    /** Start a new row. */
    void
    start_row(const unsigned int       cycle,
              const unsigned long long cells,
              const unsigned long long dofs);

    /** Add a value to the current row; columns are created on first use. */
    void
    add(const std::string &column, const double value, const Kind kind);

    /** Whether the table has any row. */
    bool
    empty() const
    {
      return rows.empty();
    }

    /** The rate of @p column between the last two rows (NaN if undefined). */
    double
    last_rate(const std::string &column) const;

    /** Pretty-print with rates / changes. */
    void
    print(std::ostream &out) const;

    /** CSV with columns cycle, cells, dofs, then per column the value and
     * `rate_<column>` (errors) or `change_<column>` (functionals). */
    void
    write_csv(std::ostream &out) const;

  private:
    struct Column
    {
      std::string name;
      Kind        kind;
    };
    struct Row
    {
      unsigned int        cycle;
      unsigned long long  cells, dofs;
      std::vector<double> values;
    };
    /** Rate or change of column @p c in row @p r (NaN for the first). */
    double
    derived(const unsigned int r, const unsigned int c) const;

    std::vector<Column> columns;
    std::vector<Row>    rows;
  };
} // namespace lithostress

#endif
