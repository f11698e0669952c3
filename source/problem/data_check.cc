#include <deal.II/base/utilities.h>

#include <fosls_contact/base/error_line.h>
#include <fosls_contact/problem/data_check.h>

#include <cmath>
#include <sstream>
#include <vector>

namespace FoslsContact
{
  namespace
  {
    /** One data function as the check sees it. */
    template <int dim>
    struct Datum
    {
      std::string                             parameter;  // "Data/Traction"
      std::string                             expression; // its value
      std::string                             where;      // "on the Dirichlet boundary"
      std::string                             unit;       // "the reference length L = 1"
      typename ScaledFunction<dim>::Record    record;
      double                                  scale;      // to the dimensionless value
      bool                                    bound;      // a gap: loads only where negative
    };

    template <int dim>
    std::string
    format(const Point<dim> &p)
    {
      std::ostringstream text;
      text.precision(6);
      text << "(";
      for (unsigned int d = 0; d < dim; ++d)
        text << (d ? ", " : "") << p[d];
      text << ")";
      return text.str();
    }

    std::string
    number(const double value)
    {
      std::ostringstream text;
      text.precision(6);
      text << value;
      return text.str();
    }

    template <int dim>
    std::string
    named(const Datum<dim> &datum)
    {
      return "parameter '" + datum.parameter + "' = '" + ErrorLine::quote(datum.expression, 60) +
             "'";
    }

    /**
     * The first problem of this process's data: not finite, or too large;
     * "" if none.
     */
    template <int dim>
    std::string
    local_problem(const std::vector<Datum<dim>> &data)
    {
      for (const auto &datum : data)
        if (!datum.record.finite)
          return named(datum) + " is not finite (" + number(datum.record.not_finite) + ") at " +
                 format(datum.record.not_finite_at) + " " + datum.where;
      for (const auto &datum : data)
        if (!(datum.scale * datum.record.largest <= DataCheck<dim>::largest))
          return named(datum) + " reaches the size " + number(datum.record.largest) + " at " +
                 format(datum.record.largest_at) + " " + datum.where + ", " +
                 number(datum.scale * datum.record.largest) + " times " + datum.unit +
                 ": above " + number(DataCheck<dim>::largest) +
                 " times it the squares of the dimensionless problem overflow double precision; "
                 "give data of the order of the body's size and stresses, or set 'Scaling' to "
                 "their order";
      return "";
    }

    /** The dimensionless load of @p datum: its largest size, or for a gap its largest penetration. */
    template <int dim>
    double
    load(const Datum<dim> &datum)
    {
      return datum.scale * (datum.bound ? std::max(0., -datum.record.lowest) : datum.record.largest);
    }
  } // namespace


  template <int dim>
  void
  DataCheck<dim>::check(const Parameters::AllParameters &parameters,
                        const Scene<dim> &               scene,
                        const MPI_Comm                   comm)
  {
    const auto &  data  = parameters.data;
    const double  L     = scene.scaling().length, S = scene.scaling().stress;
    const std::string length = "the reference length L = " + number(L);
    const std::string stress = "the reference stress S = " + number(S);
    std::vector<Datum<dim>> checked;
    const auto add = [&](const std::string &parameter, const std::string &expression,
                         const std::string &where, const std::string &unit,
                         const ScaledFunction<dim> &function, const bool bound) {
      checked.push_back(
        {parameter, expression, where, unit, function.record(), std::abs(function.scale()), bound});
    };
    add("Data/Dirichlet values", data.dirichlet_values, "on the Dirichlet boundary", length,
        scene.dirichlet_values(), false);
    add("Data/Traction", data.traction, "on the boundary where it acts", stress,
        scene.traction(), false);
    if (scene.has_contact())
      add("Data/Gap", data.gap, "on the contact boundary", length, scene.gap(), true);
    if (scene.has_body_force())
      add("Data/Body force", data.body_force, "in the body",
          "S/L (S = " + number(S) + ", L = " + number(L) + ")", scene.body_force(), false);

    // (friction's bound or coefficient is no load: checked for the first
    // two problems and its sign, not for the smallness of the data)
    std::vector<Datum<dim>> friction;
    if (scene.has_friction())
      {
        const bool tresca = scene.friction_law() == Parameters::Friction::Law::tresca;
        friction.push_back({tresca ? "Friction/Bound" : "Friction/Coefficient",
                            tresca ? parameters.friction.bound : parameters.friction.coefficient,
                            "on the contact boundary",
                            tresca ? stress : std::string("1"),
                            scene.friction_data().record(),
                            std::abs(scene.friction_data().scale()),
                            false});
      }

    // not finite, too large or (friction) negative: the line of the first
    // process that has one
    const unsigned int rank  = Utilities::MPI::this_mpi_process(comm);
    std::string        why   = local_problem(checked);
    if (why.empty())
      why = local_problem(friction);
    if (why.empty() && !friction.empty() && friction[0].record.lowest < 0)
      why = named(friction[0]) + " is negative (" + number(friction[0].record.lowest) + ") at " +
            format(friction[0].record.lowest_at) + " " + friction[0].where +
            ": a slip bound or a friction coefficient is >= 0";
    const unsigned int first =
      Utilities::MPI::min(why.empty() ? numbers::invalid_unsigned_int : rank, comm);
    if (first != numbers::invalid_unsigned_int)
      {
        why = Utilities::MPI::broadcast(comm, why, first);
        AssertThrow(false, ExcMessage(why));
      }

    // too small: the largest load of all processes
    unsigned int largest_datum = 0;
    for (unsigned int i = 0; i < checked.size(); ++i)
      if (load(checked[i]) > load(checked[largest_datum]))
        largest_datum = i;
    const double local  = load(checked[largest_datum]);
    const double global = Utilities::MPI::max(local, comm);
    if (global == 0 || global >= smallest)
      return;
    const unsigned int owner = Utilities::MPI::min(local == global ? rank : numbers::invalid_unsigned_int, comm);
    const auto &datum = checked[largest_datum];
    const auto &at    = datum.bound ? datum.record.lowest_at : datum.record.largest_at;
    why = "the data are too small against the body for double precision: the largest load, " +
          named(datum) + ", " +
          (datum.bound ? "is " + number(datum.record.lowest) :
                         "has the size " + number(datum.record.largest)) +
          " at " + format(at) + " " + datum.where + ", " + number(global) + " times " +
          datum.unit + "; below " + number(smallest) +
          " times it the squares of the dimensionless solution underflow; scale all data "
          "(displacements, tractions, body force and gap) up by one factor and the answers "
          "down by it";
    why = Utilities::MPI::broadcast(comm, why, owner);
    AssertThrow(false, ExcMessage(why));
  }

  template struct DataCheck<2>;
  template struct DataCheck<3>;
} // namespace FoslsContact
