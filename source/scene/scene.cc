#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <fosls_contact/base/collective_error.h>
#include <fosls_contact/scene/boundary_manifolds.h>
#include <fosls_contact/scene/cell_shape_check.h>
#include <fosls_contact/scene/curved_body.h>
#include <fosls_contact/scene/data_expression.h>
#include <fosls_contact/scene/mesh_parts.h>
#include <fosls_contact/scene/scene.h>

#include <cmath>
#include <iostream>
#include <sstream>

namespace FoslsContact
{
  namespace
  {
    bool
    is_literal_zero(const std::string &expression)
    {
      for (const auto &c : Utilities::split_string_list(expression, ';'))
        {
          const std::string t = Utilities::trim(c);
          if (!(t == "0" || t == "0.0" || t == "0." || t == "-0"))
            return false;
        }
      return true;
    }
  } // namespace


  template <int dim>
  Scene<dim>::Scene(const Parameters::AllParameters &prm)
    : geometry(prm.geometry)
    , dirichlet_masks(prm.boundary_conditions.dirichlet_components)
  {
    read_mesh_file();
    set_reference_units(prm);
    const auto &bc = prm.boundary_conditions;
    dirichlet_ids.insert(bc.dirichlet_ids.begin(), bc.dirichlet_ids.end());
    neumann_ids.insert(bc.neumann_ids.begin(), bc.neumann_ids.end());
    contact_ids.insert(bc.contact_ids.begin(), bc.contact_ids.end());
    // (the first step of a load path, or the scene's one step)
    set_load_step(prm, 0);
  }


  template <int dim>
  void
  Scene<dim>::set_load_step(const Parameters::AllParameters &prm, const unsigned int step)
  {
    constants.clear();
    read_constants(prm.data.constants);
    for (const auto &[name, value] : prm.data.step_overrides(step))
      constants[name] = value;
    make_data_functions(prm);
  }


  template <int dim>
  void
  Scene<dim>::read_mesh_file()
  {
    // (every process reads the mesh file: one that cannot, on a node where
    // the file is not, stops them all, CollectiveError)
    if (geometry.shape == Parameters::Geometry::Shape::file)
      CollectiveError::run(MPI_COMM_WORLD, [&]() {
        mesh_file = std::make_unique<MeshFile<dim>>(geometry.mesh_file);
        // (as for the box and the half disc: a body far from the origin
        // against its size cannot be refined in double precision)
        const auto box      = mesh_file->bounding_box();
        double     size     = 0;
        double     distance = 0;
        for (unsigned int d = 0; d < dim; ++d)
          {
            size     = std::max(size, box.side_length(d));
            distance = std::max({distance,
                                 std::abs(box.get_boundary_points().first[d]),
                                 std::abs(box.get_boundary_points().second[d])});
          }
        Parameters::check_resolvable(size, distance, "the size of the " + mesh_file->name());
      });
  }


  template <int dim>
  void
  Scene<dim>::set_reference_units(const Parameters::AllParameters &prm)
  {
    reference.length = reference_length(prm);
    reference.stress =
      prm.scaling.reference_stress > 0 ? prm.scaling.reference_stress : prm.material.mu;
    // the output converts back with L^dim and S L^(dim-1) (areas, volumes,
    // forces): keep them far from overflow and underflow
    for (const auto &[value, name] :
         {std::make_pair(reference.length,
                         prm.scaling.reference_length > 0 ?
                           std::string("parameter 'Scaling/Reference length'") :
                           std::string("the size of the body (Geometry)")),
          std::make_pair(reference.stress,
                         prm.scaling.reference_stress > 0 ?
                           std::string("parameter 'Scaling/Reference stress'") :
                           prm.material.mu_source())})
      {
        std::ostringstream text;
        text << name << " = " << value
             << " is outside the range [1e-100, 1e100] the program supports (areas, "
                "volumes and forces computed from it would overflow double precision)";
        AssertThrow(value >= 1e-100 && value <= 1e100, ExcMessage(text.str()));
      }
    dimensionless_material = prm.material;
    dimensionless_material.mu /= reference.stress;
    dimensionless_material.lambda /= reference.stress;
    dimensionless_material.youngs_modulus /= reference.stress;
  }


  template <int dim>
  void
  Scene<dim>::read_constants(const std::string &definitions)
  {
    constants["pi"] = numbers::PI;
    for (const auto &entry : Utilities::split_string_list(definitions, ','))
      {
        const auto pair = Utilities::split_string_list(entry, '=');
        AssertThrow(pair.size() == 2,
                    ExcMessage("parameter 'Data/Constants' has entry '" + entry +
                               "'; expected name=value"));
        // (muparser crashes on a constant named like a variable, or with a
        // name that is not an identifier)
        const std::string name     = Utilities::trim(pair[0]);
        const bool        is_name  = !name.empty() &&
                             (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_') &&
                             std::all_of(name.begin(), name.end(), [](const char c) {
                               return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                             });
        const bool        variable = name == "x" || name == "y" || (dim == 3 && name == "z");
        AssertThrow(is_name && !variable && constants.count(name) == 0,
                    ExcMessage("parameter 'Data/Constants' has entry '" + entry + "': '" + name +
                               (variable         ? "' is a coordinate variable" :
                                !is_name         ? "' is not a name (letters, digits, _)" :
                                name == "pi"     ? "' is predefined" :
                                                   "' is defined twice")));
        try
          {
            constants[name] = Utilities::string_to_double(pair[1]);
          }
        catch (...)
          {
            AssertThrow(false,
                        ExcMessage("parameter 'Data/Constants': '" + pair[1] +
                                   "' is not a number"));
          }
      }
  }


  template <int dim>
  void
  Scene<dim>::make_data_functions(const Parameters::AllParameters &prm)
  {
    // A data expression is parsed, and its components counted, only where
    // the scene uses it: a scene copied from a 2D one keeps its 2D
    // traction where it has no Neumann boundary. The values and tractions
    // the scene does not use are zero.
    const auto &data = prm.data;
    if (!Utilities::trim(data.body_force).empty() &&
        !is_literal_zero(data.body_force))
      body_force_function = make_function(data.body_force, dim, "Data/Body force");
    std::string zero = "0";
    for (unsigned int d = 1; d < dim; ++d)
      zero += "; 0";
    // (tractions act on the Neumann boundary and on the components a
    // Dirichlet boundary leaves free)
    bool uses_traction = !neumann_ids.empty();
    for (const auto id : dirichlet_ids)
      for (const bool prescribed : dirichlet_masks.at(id))
        uses_traction = uses_traction || !prescribed;
    dirichlet_function = dirichlet_ids.empty() ?
                           make_function(zero, dim, "Data/Dirichlet values") :
                           make_function(data.dirichlet_values, dim, "Data/Dirichlet values");
    traction_function = uses_traction ? make_function(data.traction, dim, "Data/Traction") :
                                        make_function(zero, dim, "Data/Traction");
    if (has_contact())
      {
        gap_function    = make_function(data.gap, 1, "Data/Gap");
        normal_function = make_function(data.obstacle_normal, dim, "Data/Obstacle normal");
      }
    // (Tresca's bound or Coulomb's coefficient: the one the law reads)
    if (prm.friction.law == Parameters::Friction::Law::tresca)
      friction_function = make_function(prm.friction.bound, 1, "Friction/Bound");
    else if (prm.friction.law == Parameters::Friction::Law::coulomb)
      friction_function = make_function(prm.friction.coefficient, 1, "Friction/Coefficient");
    if (!Utilities::trim(data.exact_displacement).empty())
      exact_u_function =
        make_function(data.exact_displacement, dim, "Data/Exact displacement");
    if (!Utilities::trim(data.exact_stress).empty())
      exact_sigma_function =
        make_function(data.exact_stress, dim * dim, "Data/Exact stress");
    if (prm.solver.initial_guess ==
        Parameters::Solver::InitialGuess::expression)
      initial_u_function = make_function(data.initial_displacement,
                                         dim,
                                         "Data/Initial displacement");

    // the dimensionless data: f L/S, u/L, t/S, g/L
    const double L = reference.length, S = reference.stress;
    auto scaled = [L](const std::unique_ptr<FunctionParser<dim>> &f, const double factor) {
      return f ? std::make_unique<ScaledFunction<dim>>(*f, L, factor) : nullptr;
    };
    body_force_scaled = scaled(body_force_function, L / S);
    dirichlet_scaled  = scaled(dirichlet_function, 1. / L);
    traction_scaled   = scaled(traction_function, 1. / S);
    gap_scaled        = scaled(gap_function, 1. / L);
    initial_u_scaled  = scaled(initial_u_function, 1. / L);
    // (a bound is a stress, a coefficient a number)
    friction_scaled = scaled(friction_function,
                             prm.friction.law == Parameters::Friction::Law::tresca ? 1. / S : 1.);
    friction = prm.friction.law;
  }


  template <int dim>
  double
  Scene<dim>::reference_length(const Parameters::AllParameters &prm) const
  {
    if (prm.scaling.reference_length > 0)
      return prm.scaling.reference_length;
    // the largest side of the coarse mesh's bounding box (of the half
    // disc and the half ball: their diameter)
    double length = 0;
    switch (geometry.shape)
      {
        case Parameters::Geometry::Shape::box:
          for (unsigned int d = 0; d < dim; ++d)
            length = std::max(length, geometry.upper_corner[d] - geometry.lower_corner[d]);
          AssertThrow(std::isfinite(length),
                      ExcMessage("parameters 'Geometry/Box lower corner' and 'Box upper "
                                 "corner' span more than the largest double precision number"));
          break;
        case Parameters::Geometry::Shape::file:
          for (unsigned int d = 0; d < dim; ++d)
            length = std::max(length, mesh_file->bounding_box().side_length(d));
          break;
        case Parameters::Geometry::Shape::half_cylinder:
          length = std::max(2. * geometry.radius, geometry.length);
          break;
        default:
          length = 2. * geometry.radius;
      }
    return length;
  }


  template <int dim>
  void
  Scene<dim>::check_cell_shapes(const Triangulation<dim> &tria, const MPI_Comm comm) const
  {
    CellShapeCheck<dim>::check(tria, comm, geometry, mesh_file.get(), reference.length);
  }


  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  Scene<dim>::make_function(const std::string &expression,
                            const unsigned int n_components,
                            const std::string &name) const
  {
    return DataExpression<dim>::parse(expression, n_components, name, constants, reference.length);
  }


  template <int dim>
  bool
  Scene<dim>::is_dirichlet(const types::boundary_id id) const
  {
    return dirichlet_ids.count(id) > 0;
  }

  template <int dim>
  bool
  Scene<dim>::is_neumann(const types::boundary_id id) const
  {
    return neumann_ids.count(id) > 0;
  }

  template <int dim>
  bool
  Scene<dim>::is_contact(const types::boundary_id id) const
  {
    return contact_ids.count(id) > 0;
  }


  template <int dim>
  Tensor<1, dim>
  Scene<dim>::obstacle_normal(const Point<dim> &p) const
  {
    Tensor<1, dim> n;
    for (unsigned int d = 0; d < dim; ++d)
      n[d] = normal_function->value(reference.length * p, d);
    const double norm = n.norm();
    AssertThrow(norm > 1e-12 && std::isfinite(norm),
                ExcMessage("parameter 'Data/Obstacle normal' evaluates to a "
                           "zero or non-finite vector at a contact point"));
    return n / norm;
  }


  template <int dim>
  void
  Scene<dim>::make_coarse_mesh(Triangulation<dim> &tria) const
  {
    if (geometry.shape == Parameters::Geometry::Shape::box)
      {
        Point<dim>                p1, p2;
        std::vector<unsigned int> repetitions(dim);
        for (unsigned int d = 0; d < dim; ++d)
          {
            p1[d]          = geometry.lower_corner[d] / reference.length;
            p2[d]          = geometry.upper_corner[d] / reference.length;
            repetitions[d] = geometry.subdivisions[d];
          }
        GridGenerator::subdivided_hyper_rectangle(tria, repetitions, p1, p2, true);
      }
    else if (geometry.shape == Parameters::Geometry::Shape::file)
      {
        tria.copy_triangulation(mesh_file->triangulation());
        GridTools::scale(1. / reference.length, tria);
        BoundaryManifolds<dim>(geometry.manifolds, reference.length)
          .attach(tria, mesh_file->name());
        check_cell_shapes(tria, MPI_COMM_SELF);
      }
    else
      {
        CurvedBody::make(geometry, reference.length, tria);
        check_cell_shapes(tria, MPI_COMM_SELF);
      }

    // Every boundary id of the mesh needs exactly one condition, and every
    // named id must exist (a typo would otherwise silently drop a condition).
    std::set<types::boundary_id> mesh_ids;
    for (const auto id : tria.get_boundary_ids())
      mesh_ids.insert(id);
    const std::string mesh = mesh_file ? "the " + mesh_file->name() : "the mesh";
    // (deal.II's boundary ids go to 2^32 - 2, the parameters' to 255)
    for (const auto id : mesh_ids)
      AssertThrow(id <= Parameters::BoundaryConditions::max_id,
                  ExcMessage("boundary id " + std::to_string(id) + " of " + mesh +
                             " is out of the range 0 to " + std::to_string(Parameters::BoundaryConditions::max_id) +
                             " the program supports (the ids 'Boundary conditions' accepts): "
                             "renumber it in the mesh file"));
    for (const auto id : mesh_ids)
      AssertThrow(is_dirichlet(id) || is_neumann(id) || is_contact(id),
                  ExcMessage("boundary id " + std::to_string(id) + " of " + mesh +
                             " has no condition: name it in "
                             "'Boundary conditions' (Dirichlet, Neumann or "
                             "Contact boundary ids)"));
    std::string existing;
    for (const auto id : mesh_ids)
      existing += (existing.empty() ? "" : ", ") + std::to_string(id);
    for (const auto &ids : {dirichlet_ids, neumann_ids, contact_ids})
      for (const auto id : ids)
        AssertThrow(mesh_ids.count(id) > 0,
                    ExcMessage("boundary id " + std::to_string(id) +
                               " named in 'Boundary conditions' does not exist "
                               "on " + (mesh_file ? mesh : "this mesh") +
                               " (its boundary ids: " + existing + ")"));
    MeshParts<dim>::check(
      tria,
      [this](const types::boundary_id id) { return is_dirichlet(id); },
      [this](const types::boundary_id id) { return is_contact(id); },
      reference.length,
      mesh_file ? "the " + mesh_file->name() : std::string("the mesh"));
  }


  template <int dim>
  double
  Scene<dim>::mesh_size_ratio(const Triangulation<dim> &tria)
  {
    double h_max = 0, h_min = std::numeric_limits<double>::max();
    for (const auto &cell : tria.active_cell_iterators())
      {
        h_max = std::max(h_max, cell->diameter());
        h_min = std::min(h_min, cell->diameter());
      }
    return h_max / h_min;
  }

  template class Scene<2>;
  template class Scene<3>;
} // namespace FoslsContact
