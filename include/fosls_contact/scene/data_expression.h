#ifndef fosls_contact_scene_data_expression_h
#define fosls_contact_scene_data_expression_h

#include <deal.II/base/function_parser.h>

#include <map>
#include <memory>
#include <string>

namespace FoslsContact
{
  using namespace dealii;

  /**
   * A data expression of the input file (Data/..., components separated by
   * ';') as a FunctionParser. deal.II parses lazily and muparser writes to
   * std::cerr and throws an exception of its own; this is where a
   * malformed expression becomes one error line that names the parameter,
   * at reading time and not in the middle of the assembly.
   */
  template <int dim>
  struct DataExpression
  {
    /**
     * The expression @p expression with @p n_components components, in
     * x, y (, z) and @p constants, for the parameter @p name; its
     * finite-difference gradients take steps relative to the reference
     * length @p length, so that they are equally accurate in every unit
     * system.
     */
    static std::unique_ptr<FunctionParser<dim>>
    parse(const std::string &                  expression,
          const unsigned int                   n_components,
          const std::string &                  name,
          const std::map<std::string, double> &constants,
          const double                         length);
  };
} // namespace FoslsContact

#endif
