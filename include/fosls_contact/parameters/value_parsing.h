#ifndef fosls_contact_parameters_value_parsing_h
#define fosls_contact_parameters_value_parsing_h

#include <string>
#include <vector>

namespace FoslsContact
{
  /**
   * The value syntaxes that several subsections share and a Pattern cannot
   * check (numbers that may be `inf`, lists of doubles, coordinates that
   * must resolve the finest level), written once so that every subsection
   * reports a bad value with the same words.
   */
  namespace Parameters
  {
    /** Parse a double that may be written `inf`. */
    double parse_extended_double(const std::string &text, const std::string &name);
    /** Parse a comma separated list of doubles. */
    std::vector<double> parse_double_list(const std::string &text);
    /**
     * A body of size @p size at distance @p distance from the origin has
     * vertex coordinates that must resolve the cells of the finest level
     * (size / 2^13 with 14 levels) in double precision: refuse a size
     * below 1e-6 of the distance, naming @p what, instead of meeting
     * degenerate cells later. (Any size itself is fine: the program works
     * in units of the body's size, Scaling.)
     */
    void check_resolvable(const double size, const double distance, const std::string &what);
  } // namespace Parameters
} // namespace FoslsContact

#endif
