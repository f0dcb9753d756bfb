#ifndef lithostress_base_parameter_file_h
#define lithostress_base_parameter_file_h

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * Reads a `.prm` file in two passes so that subsections may be named by the
   * user (materials, boundary parts): the first pass reads only the lists of
   * names (undeclared entries are skipped), the second declares a subsection
   * for each name and parses the file strictly, so that a misspelt entry or
   * subsection is an error that names the line.
   *
   * Overrides of the form `Section/Subsection/Entry=value` (from the command
   * line, or a test) are applied after each pass.
   */
  class ParameterFile
  {
  public:
    /**
     * A function that declares all parameters. @p first_pass is null when
     * the declarations are made for documentation (then each list of names
     * gets one example name); otherwise it holds the first pass, from which
     * user-named subsections are read with names_from().
     */
    using Declaration =
      std::function<void(ParameterHandler &prm, ParameterHandler *first_pass)>;

    /**
     * Declare all parameters into @p prm and read @p filename into it.
     * Throws InputError with the parser's message on any problem.
     */
    static void
    read(const std::string              &filename,
         const std::vector<std::string> &overrides,
         const Declaration              &declare,
         ParameterHandler               &prm);

    /**
     * The list of names in entry @p entry of the current subsection of
     * @p first_pass, or @p example if @p first_pass is null (documentation).
     * The caller has entered the same subsection path in both handlers.
     */
    static std::vector<std::string>
    names_from(ParameterHandler               *first_pass,
               const std::vector<std::string> &path,
               const std::string              &entry,
               const std::vector<std::string> &example);

    /**
     * Apply one `Section/Entry=value` override to @p prm.
     */
    static void
    apply_override(ParameterHandler &prm, const std::string &assignment);

    /**
     * Throw InputError naming the first entry of @p prm whose pattern is a
     * double or an integer but whose value the conversion cannot hold
     * (`Width = 1e-308` matches Patterns::Double but underflows; deal.II's
     * get_double() would fail only where the entry is read, after output
     * has begun). Called by read(), before anything is written.
     */
    static void
    check_numbers(const ParameterHandler &prm);
  };

  /**
   * The number in @p text (surrounding blanks allowed, nothing else);
   * throws InputError naming @p entry otherwise.
   */
  double
  parse_number(const std::string &text, const std::string &entry);

  /** @p text with line breaks and runs of blanks turned into single spaces. */
  std::string
  one_line(const std::string &text);

  /**
   * The message of a deal.II exception as one line with single spaces
   * (deal.II's messages are indented over several lines).
   */
  std::string
  one_line_message(const ExceptionBase &exc);

  /**
   * Split a comma separated list, trimming white space; empty items dropped.
   */
  std::vector<std::string>
  split_list(const std::string &text, const char separator = ',');

  /**
   * Parse a list of points "x1, y1; x2, y2" (coordinates scaled by
   * @p scale). Throws InputError naming @p entry on malformed input.
   */
  template <int dim>
  std::vector<Point<dim>>
  parse_point_list(const std::string &text,
                   const std::string &entry,
                   const double       scale = 1.0);
} // namespace lithostress

#endif
