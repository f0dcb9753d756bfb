#ifndef lithostress_base_renamed_entries_h
#define lithostress_base_renamed_entries_h

#include <string>
#include <vector>

namespace lithostress
{
  /**
   * An input entry that was renamed or moved since the first release, so
   * that a `.prm` file of the time is told where its entry went instead of
   * deal.II's "No entry with name ... was declared". A component of
   * @p old_path written `<name>` stands for any user-named subsection
   * (a fault, a material). doc/parameters.md lists the table.
   */
  struct RenamedEntry
  {
    std::string old_path;
    std::string new_path;
    /** The date of the change (and its commit). */
    std::string since;
  };

  /** A value of a selection that was renamed. */
  struct RenamedValue
  {
    std::string entry;
    std::string old_value;
    std::string new_value;
    std::string since;
  };

  /** Every renamed or moved entry. */
  const std::vector<RenamedEntry> &
  renamed_entries();

  /** Every renamed selection value. */
  const std::vector<RenamedValue> &
  renamed_values();

  /**
   * The one-line message for the first entry of the parameter text
   * @p contents (of file @p filename) that sets a renamed entry or a
   * renamed value and that the parser's message @p parser_message names
   * (its entry's last name or the old value in angle brackets, as deal.II
   * writes them), "file:line: ..."; empty if there is none, so that a
   * failure elsewhere keeps the parser's own message.
   */
  std::string
  renamed_entry_message(const std::string &contents,
                        const std::string &filename,
                        const std::string &parser_message);

  /** The same for one `Section/Entry=value` override; empty if it names
   * no renamed entry or value. */
  std::string
  renamed_override_message(const std::string &assignment);
} // namespace lithostress

#endif
