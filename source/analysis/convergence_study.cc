#include <lithostress/analysis/convergence_study.h>

#include <cmath>
#include <iomanip>
#include <limits>

namespace lithostress
{
  void
  ConvergenceStudy::start_row(const unsigned int       cycle,
                              const unsigned long long cells,
                              const unsigned long long dofs)
  {
    rows.push_back(Row{
      cycle, cells, dofs, std::vector<double>(columns.size(), std::nan(""))});
  }

  void
  ConvergenceStudy::add(const std::string &column,
                        const double       value,
                        const Kind         kind)
  {
    unsigned int c = 0;
    while (c < columns.size() && columns[c].name != column)
      ++c;
    if (c == columns.size())
      {
        columns.push_back(Column{column, kind});
        for (Row &row : rows)
          row.values.push_back(std::nan(""));
      }
    rows.back().values[c] = value;
  }

  double
  ConvergenceStudy::derived(const unsigned int r, const unsigned int c) const
  {
    if (r == 0)
      return std::nan("");
    const double now = rows[r].values[c], before = rows[r - 1].values[c];
    if (columns[c].kind == Kind::functional)
      return std::abs(now - before);
    if (rows[r].dofs == rows[r - 1].dofs || !(now > 0) || !(before > 0))
      return std::nan("");
    return -std::log(now / before) /
           std::log(double(rows[r].dofs) / double(rows[r - 1].dofs));
  }

  double
  ConvergenceStudy::last_rate(const std::string &column) const
  {
    for (unsigned int c = 0; c < columns.size(); ++c)
      if (columns[c].name == column && rows.size() > 1)
        return derived(rows.size() - 1, c);
    return std::nan("");
  }

  void
  ConvergenceStudy::print(std::ostream &out) const
  {
    // Errors in one table; functionals in blocks of a few columns so that
    // lines stay readable.
    std::vector<std::vector<unsigned int>> blocks(1);
    for (unsigned int c = 0; c < columns.size(); ++c)
      if (columns[c].kind == Kind::error)
        blocks[0].push_back(c);
    std::vector<unsigned int> functionals;
    for (unsigned int c = 0; c < columns.size(); ++c)
      if (columns[c].kind == Kind::functional)
        functionals.push_back(c);
    for (unsigned int k = 0; k < functionals.size(); k += 5)
      blocks.emplace_back(functionals.begin() + k,
                          functionals.begin() +
                            std::min<std::size_t>(k + 5, functionals.size()));
    bool first = true;
    for (const auto &block : blocks)
      {
        if (block.empty() && !first)
          continue;
        if (!first)
          out << '\n';
        first = false;
        out << std::setw(5) << "cycle" << std::setw(9) << "cells"
            << std::setw(10) << "DoFs";
        for (const unsigned int c : block)
          out << "  " << std::setw(std::max<int>(11, columns[c].name.size()))
              << columns[c].name << std::setw(8)
              << (columns[c].kind == Kind::error ? "rate" : "change");
        out << '\n';
        for (unsigned int r = 0; r < rows.size(); ++r)
          {
            out << std::setw(5) << rows[r].cycle << std::setw(9)
                << rows[r].cells << std::setw(10) << rows[r].dofs;
            for (const unsigned int c : block)
              {
                const double d = derived(r, c);
                out << "  "
                    << std::setw(std::max<int>(11, columns[c].name.size()))
                    << std::scientific << std::setprecision(4)
                    << rows[r].values[c];
                if (std::isnan(d))
                  out << std::setw(8) << "-";
                else if (columns[c].kind == Kind::error)
                  out << std::setw(8) << std::fixed << std::setprecision(2)
                      << d;
                else
                  out << std::setw(8) << std::scientific << std::setprecision(1)
                      << d;
              }
            out << '\n';
          }
      }
    out << std::defaultfloat;
  }

  void
  ConvergenceStudy::write_csv(std::ostream &out) const
  {
    out << "cycle,cells,dofs";
    for (const Column &column : columns)
      out << ',' << column.name << ','
          << (column.kind == Kind::error ? "rate_" : "change_") << column.name;
    out << '\n' << std::setprecision(std::numeric_limits<double>::max_digits10);
    for (unsigned int r = 0; r < rows.size(); ++r)
      {
        out << rows[r].cycle << ',' << rows[r].cells << ',' << rows[r].dofs;
        for (unsigned int c = 0; c < columns.size(); ++c)
          {
            const double d = derived(r, c);
            // Empty fields for values a cycle does not have.
            out << ',';
            if (!std::isnan(rows[r].values[c]))
              out << rows[r].values[c];
            out << ',';
            if (!std::isnan(d))
              out << d;
          }
        out << '\n';
      }
  }
} // namespace lithostress
