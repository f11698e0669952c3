#ifndef fosls_contact_parameters_unit_names_h
#define fosls_contact_parameters_unit_names_h

#include <string>

namespace FoslsContact
{
  namespace Parameters
  {
    /**
     * The names of the scene's units (Scaling/Unit names), e.g. 'length=mm,
     * force=N, stress=MPa'. The program computes in whatever consistent units
     * the scene is written in (Scaling); the names only label its answers, on
     * the screen, in summary.json and on the axes of scripts/plot.py, so that
     * "4089.4 N/mm" says what a bare 4089.4 does not. Empty names (the
     * default): the scene's units, unnamed. The names are labels only: that
     * they are consistent (stress = force / length^2) is the user's part, as
     * are the units themselves.
     */
    struct UnitNames
    {
      std::string length, force, stress;

      /**
       * Read @p text, the value of parameter @p name: empty, or each of
       * length, force and stress once, 'name=unit' separated by ','; a unit
       * is one word of printable ASCII characters other than , ; = " and \
       * (it goes into summary.json and CSV headers as it is).
       */
      void parse(const std::string &text, const std::string &name);

      /** Whether the units are named. */
      bool named() const { return !length.empty(); }

      /**
       * The unit of a force the program reports: the force's, in 2D per unit
       * length out of plane (plane strain: 'N/mm'). Empty if not named.
       */
      std::string reported_force(const unsigned int dim) const;
      /** The unit of a measure of the contact zone: a width in 2D, an area in 3D. */
      std::string contact_measure(const unsigned int dim) const;
      /** The unit of the functional J, length^dim. */
      std::string functional(const unsigned int dim) const;
    };
  } // namespace Parameters
} // namespace FoslsContact

#endif
