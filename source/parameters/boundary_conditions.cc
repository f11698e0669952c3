#include <deal.II/base/utilities.h>

#include <fosls_contact/parameters/boundary_conditions.h>
#include <fosls_contact/parameters/value_parsing.h>

#include <algorithm>
#include <set>
#include <string>

namespace FoslsContact
{
  namespace Parameters
  {
    namespace
    {
      std::vector<unsigned int>
      parse_id_list(const std::string &text)
      {
        std::vector<unsigned int> ids;
        for (const auto &entry :
             Utilities::split_string_list(text, ','))
          ids.push_back(Utilities::string_to_int(entry));
        return ids;
      }
    } // namespace

    void
    BoundaryConditions::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      prm.declare_entry("Dirichlet boundary ids",
                        "",
                        Patterns::List(Patterns::Integer(0, max_id)),
                        "Boundary ids with prescribed displacement.");
      prm.declare_entry("Dirichlet components",
                        "all",
                        Patterns::Anything(),
                        "'all' or a list of components (0 = x, 1 = y, 2 = z) "
                        "prescribed on the Dirichlet ids, or per id as "
                        "'id: components; ...' (e.g. '0: 0; 3: all'; ids not "
                        "named: all); the other components get the traction "
                        "of Data/Traction (a roller).");
      prm.declare_entry("Neumann boundary ids",
                        "",
                        Patterns::List(Patterns::Integer(0, max_id)),
                        "Boundary ids with prescribed traction.");
      prm.declare_entry("Contact boundary ids",
                        "",
                        Patterns::List(Patterns::Integer(0, max_id)),
                        "Boundary ids of the contact boundary Gamma_C. Empty: "
                        "the scene has no contact and no contact machinery is "
                        "set up.");
      prm.leave_subsection();
    }

    void
    BoundaryConditions::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      dirichlet_ids             = parse_id_list(prm.get("Dirichlet boundary ids"));
      dirichlet_components_text = Utilities::trim(prm.get("Dirichlet components"));
      neumann_ids               = parse_id_list(prm.get("Neumann boundary ids"));
      contact_ids               = parse_id_list(prm.get("Contact boundary ids"));
      prm.leave_subsection();

      AssertThrow(!dirichlet_ids.empty(),
                  ExcMessage("parameter 'Boundary conditions/Dirichlet boundary "
                             "ids' is empty: the problem needs a Dirichlet part "
                             "(Gamma_D nonempty, paper section 2)"));
      std::vector<unsigned int> all = dirichlet_ids;
      all.insert(all.end(), neumann_ids.begin(), neumann_ids.end());
      all.insert(all.end(), contact_ids.begin(), contact_ids.end());
      std::sort(all.begin(), all.end());
      const auto dup = std::adjacent_find(all.begin(), all.end());
      AssertThrow(dup == all.end(),
                  ExcMessage("boundary id " + std::to_string(*dup) +
                             " is named twice in 'Boundary conditions'"));
    }


    void
    BoundaryConditions::parse_components(const unsigned int dimension)
    {
      // 'all', a component list for every Dirichlet id, or per id
      // "id: components; id: components" (ids not named: all)
      const auto name = std::string("parameter 'Boundary conditions/Dirichlet components'");
      auto       parse_mask = [&](const std::string &text) {
        std::vector<bool> mask(dimension, text == "all");
        if (text != "all")
          for (const auto &c : Utilities::split_string_list(text, ','))
            {
              int k = -1;
              try
                {
                  k = Utilities::string_to_int(c);
                }
              catch (...)
                {}
              AssertThrow(k >= 0 && k < static_cast<int>(dimension),
                          ExcMessage(name + " has entry '" + c +
                                     "'; valid: all, or components 0.." +
                                     std::to_string(dimension - 1)));
              mask[k] = true;
            }
        AssertThrow(std::find(mask.begin(), mask.end(), true) != mask.end(),
                    ExcMessage(name + " = '" + text + "' prescribes no component"));
        return mask;
      };
      dirichlet_components.clear();
      if (dirichlet_components_text.find(':') == std::string::npos)
        {
          const auto mask = parse_mask(dirichlet_components_text);
          for (const unsigned int id : dirichlet_ids)
            dirichlet_components[id] = mask;
        }
      else
        {
          for (const unsigned int id : dirichlet_ids)
            dirichlet_components[id] = std::vector<bool>(dimension, true);
          std::set<unsigned int> named;
          for (const auto &entry : Utilities::split_string_list(dirichlet_components_text, ';'))
            {
              const auto pair = Utilities::split_string_list(entry, ':');
              int        id   = -1;
              try
                {
                  if (pair.size() == 2)
                    id = Utilities::string_to_int(pair[0]);
                }
              catch (...)
                {}
              AssertThrow(id >= 0,
                          ExcMessage(name + " has entry '" + entry +
                                     "'; expected 'id: components' (e.g. '0: 0; 3: all')"));
              AssertThrow(dirichlet_components.count(id),
                          ExcMessage(name + " names boundary id " + std::to_string(id) +
                                     ", which is not in 'Boundary conditions/Dirichlet "
                                     "boundary ids'"));
              AssertThrow(named.insert(id).second,
                          ExcMessage(name + " names boundary id " + std::to_string(id) +
                                     " twice"));
              dirichlet_components[id] = parse_mask(pair[1]);
            }
        }
    }
  } // namespace Parameters
} // namespace FoslsContact
