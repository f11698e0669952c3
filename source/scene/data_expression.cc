#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <fosls_contact/scene/data_expression.h>

#include <muParser.h>

#include <cctype>
#include <iostream>
#include <sstream>

namespace FoslsContact
{
  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  DataExpression<dim>::parse(const std::string &                  expression,
                             const unsigned int                   n_components,
                             const std::string &                  name,
                             const std::map<std::string, double> &constants,
                             const double                         length)
  {
    std::vector<std::string> expressions;
    for (const auto &c : Utilities::split_string_list(expression, ';'))
      expressions.push_back(c);
    AssertThrow(expressions.size() == n_components,
                ExcMessage("parameter '" + name + "' = '" + expression +
                           "' has " + std::to_string(expressions.size()) +
                           " component(s) separated by ';', expected " +
                           std::to_string(n_components)));
    // (the step of its finite-difference gradients is relative to L, so
    // that they are equally accurate in every unit system)
    auto function =
      std::make_unique<FunctionParser<dim>>(n_components, 0., 1e-8 * length);
    const std::string variables = (dim == 2 ? "x,y" : "x,y,z");
    // deal.II parses lazily: initialize, then evaluate once so that a
    // malformed expression is reported here, with the parameter's name, and
    // not in the middle of the assembly.
    // muparser reports to std::cerr before deal.II throws: silence it, the
    // error is reported once, in one line, below.
    // (restored however the block below is left: a dangling std::cerr
    // buffer crashed the program's error report)
    std::ostringstream muted;
    struct CerrRestore
    {
      std::streambuf *buffer;
      ~CerrRestore() { std::cerr.rdbuf(buffer); }
    } restore{std::cerr.rdbuf(muted.rdbuf())};
    std::string reason;
    try
      {
        function->initialize(variables, expressions, constants);
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = (0.123 + 0.1 * d) * length;
        Vector<double> values(n_components);
        function->vector_value(p, values);
      }
    catch (const std::exception &e)
      {
        const std::string what = e.what();
        const auto        pos  = what.find("The parser said:");
        reason = pos == std::string::npos ? std::string("malformed expression") :
                                            what.substr(pos + 16);
        // deal.II wraps the text over several lines: join them
        std::string joined;
        for (const char c : reason)
          if (!std::isspace(static_cast<unsigned char>(c)))
            joined += c;
          else if (!joined.empty() && joined.back() != ' ')
            joined += ' ';
        reason = Utilities::trim(joined);
        // drop deal.II's trailing separator line
        const auto dashes = reason.find("---");
        if (dashes != std::string::npos)
          reason = Utilities::trim(reason.substr(0, dashes));
      }
    catch (const mu::ParserError &e)
      {
        // muparser's own exception (not a std::exception): e.g. a constant
        // name longer than muparser accepts
        reason = e.GetMsg();
      }
    AssertThrow(reason.empty(),
                ExcMessage("parameter '" + name + "' = '" + expression +
                           "' is not a valid expression: " + reason));
    return function;
  }


  template struct DataExpression<2>;
  template struct DataExpression<3>;
} // namespace FoslsContact
