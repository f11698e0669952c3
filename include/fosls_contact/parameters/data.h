#ifndef fosls_contact_parameters_data_h
#define fosls_contact_parameters_data_h

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <string>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  namespace Parameters
  {
    /**
     * subsection Data: the functions of a scene, as FunctionParser
     * expressions in x, y (, z). Components are separated by `;`. An empty
     * body force means the scene has none: no term is assembled for it.
     */
    struct Data
    {
      std::string body_force;
      std::string dirichlet_values;
      std::string traction;
      std::string gap;
      std::string obstacle_normal;
      std::string exact_displacement;
      std::string exact_stress;
      std::string initial_displacement;
      std::string constants;
      /**
       * Load steps: the constants each step gives new values (Load
       * steps, "push=0.005; push=0.01, shift=0.002"), in the order of the
       * steps; empty for one step with Data/Constants as they are. A
       * constant a step does not name keeps its value of the step before:
       * the list reads as a load path, each step changing what moves.
       */
      std::vector<std::map<std::string, double>> load_steps;

      /** The number of steps of the run: 1 without Load steps. */
      unsigned int n_load_steps() const
      {
        return load_steps.empty() ? 1 : load_steps.size();
      }
      /**
       * The constants load step @p step (0, 1, ...) gives values other
       * than Data/Constants: those of the steps 0 to @p step applied in
       * turn (Scene::set_load_step()).
       */
      std::map<std::string, double> step_overrides(const unsigned int step) const;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);

    private:
      /**
       * Read Load steps (@p text) and refuse an entry that is not
       * name=number or names a constant that Data/Constants does not
       * define, naming the step.
       */
      void parse_load_steps(const std::string &text);
    };
  } // namespace Parameters
} // namespace FoslsContact

#endif
