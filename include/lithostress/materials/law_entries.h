#ifndef lithostress_materials_law_entries_h
#define lithostress_materials_law_entries_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace lithostress
{
  using namespace dealii;

  /**
   * Refuse entries of a material's subsection (entered in @p prm) that
   * belong to a registered rock law other than the chosen @p law (its
   * `Rheology`) and are set to something other than their default: a
   * `Friction angle` under `Rheology = maxwell` would otherwise be read by
   * nobody, silently. @p where names the subsection (`Materials/<name>/`).
   * Values that parse as equal numbers count as the default. Throws the
   * InputError naming the first such entry and the law that reads it.
   */
  void
  refuse_entries_of_other_laws(ParameterHandler  &prm,
                               const std::string &law,
                               const std::string &where);
} // namespace lithostress

#endif
