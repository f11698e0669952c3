#include <deal.II/base/utilities.h>

#include <fosls_contact/parameters.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

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

    double
    parse_extended_double(const std::string &text, const std::string &name)
    {
      const std::string t = Utilities::trim(text);
      if (t == "inf" || t == "infinity" || t == "+inf")
        return std::numeric_limits<double>::infinity();
      try
        {
          std::size_t  pos   = 0;
          const double value = std::stod(t, &pos);
          if (pos == t.size() && std::isfinite(value))
            return value;
        }
      catch (...)
        {}
      AssertThrow(false,
                  ExcMessage("parameter '" + name + "' has value '" + t +
                             "', which is neither a number nor 'inf'"));
      return 0;
    }

    void
    check_resolvable(const double size, const double distance, const std::string &what)
    {
      AssertThrow(std::isfinite(size) && std::isfinite(distance),
                  ExcMessage(what + " is too large for double precision"));
      std::ostringstream text;
      text << what << " (" << size << ") is too small against the distance of the body "
           << "from the origin (" << distance << ") to be resolved in double precision; "
           << "put the origin near the body";
      AssertThrow(size > 1e-6 * distance, ExcMessage(text.str()));
    }

    std::vector<double>
    parse_double_list(const std::string &text)
    {
      std::vector<double> values;
      for (const auto &entry : Utilities::split_string_list(text, ','))
        values.push_back(Utilities::string_to_double(entry));
      return values;
    }


    void
    Geometry::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      prm.declare_entry("Dimension",
                        "2",
                        Patterns::Integer(2, 3),
                        "Space dimension, 2 or 3.");
      prm.declare_entry("Shape",
                        "box",
                        Patterns::Selection("box|half disc|half ball|half cylinder|file"),
                        "box: an axis-parallel box (boundary ids 0/1 = x min/max, "
                        "2/3 = y min/max, 4/5 = z min/max). half disc (2D): the lower "
                        "half of a disc of Radius around Center, its flat side on top "
                        "(boundary id 0 = curved side, 1 = flat top). half ball (3D): "
                        "the lower half of a ball of Radius around Center, its flat "
                        "face on top (0 = curved surface, 1 = flat top). half cylinder "
                        "(3D): the lower half of a cylinder of Radius and Length whose "
                        "axis runs along z through Center (from z = Center_z - Length/2 "
                        "to Center_z + Length/2), its flat face on top (0 = curved "
                        "side, 1 = flat top, 2 = end face at the smaller z, 3 = end "
                        "face at the larger z). The curved boundaries of the three "
                        "stay curved under refinement. file: the mesh of 'Mesh file', "
                        "with the file's boundary ids.");
      prm.declare_entry("Box lower corner",
                        "0, 0",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Lower corner of the box.");
      prm.declare_entry("Box upper corner",
                        "1, 1",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Upper corner of the box.");
      prm.declare_entry("Box subdivisions",
                        "1, 1",
                        Patterns::List(Patterns::Integer(1, 1000), 2, 3),
                        "Cells per direction of the coarse mesh (level 1). "
                        "Unequal cell sizes give anisotropic cells.");
      prm.declare_entry("Radius",
                        "0.5",
                        Patterns::Double(0),
                        "Radius of the half disc, half ball or half cylinder.");
      prm.declare_entry("Center",
                        "0, 1",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Center of the half disc, half ball or half cylinder (the "
                        "middle of its flat top), with Dimension entries.");
      prm.declare_entry("Length",
                        "1",
                        Patterns::Double(0),
                        "Half cylinder: its length along z.");
      prm.declare_entry("Length subdivisions",
                        "2",
                        Patterns::Integer(1, 1000),
                        "Half cylinder: cells along its axis in the coarse mesh "
                        "(level 1).");
      prm.declare_entry("Coarse refinements",
                        "2",
                        Patterns::Integer(0, 6),
                        "Half disc, half ball, half cylinder: refinements of deal.II's "
                        "coarsest mesh of the shape (4 cells for the half disc and the "
                        "half cylinder's cross-section, 6 for the half ball) that make "
                        "the coarse mesh (level 1), before grading.");
      prm.declare_entry("Grading",
                        "1",
                        Patterns::Double(1, 10),
                        "Half disc, half ball, half cylinder: exponent of the grading "
                        "toward the lowest point (half disc, half ball) or line (half "
                        "cylinder), in polar coordinates around Center: the angle from "
                        "the downward direction and the distance to the curved "
                        "boundary are raised to this power (1 = no grading). The run "
                        "prints h_max/h_min of the coarse mesh.");
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::FileName(Patterns::FileName::input),
                        "Shape = file: the mesh file, relative to the scene file "
                        "that names it (to the current directory if given with "
                        "--set), in the scene's units. Read by its extension: .msh "
                        "(Gmsh, ASCII, format 1, 2 or 4), .inp (Abaqus), .ucd (AVS "
                        "UCD), .vtk (legacy VTK unstructured grid), .vtu (written by "
                        "deal.II with its triangulation serialized). Its cells must be "
                        "quadrilaterals (2D) or hexahedra (3D). The boundary ids are "
                        "the file's: in a Gmsh file the physical tag of the boundary "
                        "curves (2D) or surfaces (3D), in an Abaqus file the number in "
                        "the name of a *SURFACE; boundary faces in no group have id 0.");
      prm.declare_entry("Manifolds",
                        "",
                        Patterns::Anything(),
                        "Shape = file: the curved surfaces that the faces of a "
                        "boundary id lie on, so that refinement puts the new "
                        "vertices on them, in the scene's units: 'id: sphere X, Y(, "
                        "Z) radius R' (a circle in 2D) or 'id: cylinder X, Y, Z "
                        "direction DX, DY, DZ radius R' (3D: a point on the axis and "
                        "the axis' direction), separated by ';', e.g. '1: sphere 0, "
                        "0, 50 radius 50'. Every vertex of the id's faces must lie on "
                        "the surface (to 1e-3 R). Faces of ids not named stay flat.");
      prm.declare_entry("Levels",
                        "5",
                        Patterns::Integer(1, 14),
                        "Number of levels J: the coarse mesh is level 1 and "
                        "level J is the coarse mesh refined J-1 times.");
      prm.leave_subsection();
    }

    void
    Geometry::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      dimension               = prm.get_integer("Dimension");
      const std::string s     = prm.get("Shape");
      shape                   = s == "box"           ? Shape::box :
                                s == "half disc"     ? Shape::half_disc :
                                s == "half ball"     ? Shape::half_ball :
                                s == "half cylinder" ? Shape::half_cylinder :
                                                       Shape::file;
      lower_corner = parse_double_list(prm.get("Box lower corner"));
      upper_corner = parse_double_list(prm.get("Box upper corner"));
      subdivisions.clear();
      for (const auto &s :
           Utilities::split_string_list(prm.get("Box subdivisions"), ','))
        subdivisions.push_back(Utilities::string_to_int(s));
      radius              = prm.get_double("Radius");
      center              = parse_double_list(prm.get("Center"));
      length              = prm.get_double("Length");
      length_subdivisions = prm.get_integer("Length subdivisions");
      coarse_refinements  = prm.get_integer("Coarse refinements");
      grading             = prm.get_double("Grading");
      mesh_file           = prm.get("Mesh file");
      const std::string manifold_text = prm.get("Manifolds");
      levels              = prm.get_integer("Levels");
      prm.leave_subsection();

      if (shape == Shape::box)
        {
          AssertThrow(lower_corner.size() == dimension &&
                        upper_corner.size() == dimension &&
                        subdivisions.size() == dimension,
                      ExcMessage("Geometry/Box lower corner, Box upper corner "
                                 "and Box subdivisions need " +
                                 std::to_string(dimension) + " entries each"));
          for (unsigned int d = 0; d < dimension; ++d)
            AssertThrow(lower_corner[d] < upper_corner[d],
                        ExcMessage("Geometry/Box lower corner must be below "
                                   "Box upper corner in every coordinate"));
          for (unsigned int d = 0; d < dimension; ++d)
            check_resolvable(upper_corner[d] - lower_corner[d],
                             std::max(std::abs(lower_corner[d]), std::abs(upper_corner[d])),
                             "the side of 'Geometry/Box lower corner' to 'Box upper corner'");
        }
      else if (shape == Shape::file)
        {
          AssertThrow(!Utilities::trim(mesh_file).empty(),
                      ExcMessage("parameter 'Geometry/Mesh file' is empty: Shape = file "
                                 "needs the name of a mesh file"));
        }
      else
        {
          const unsigned int needed = shape == Shape::half_disc ? 2 : 3;
          AssertThrow(dimension == needed,
                      ExcMessage("Geometry/Shape = " + s + " needs Dimension = " +
                                 std::to_string(needed)));
          AssertThrow(radius > 0, ExcMessage("parameter 'Geometry/Radius' must be > 0"));
          AssertThrow(center.size() == dimension,
                      ExcMessage("parameter 'Geometry/Center' needs " +
                                 std::to_string(dimension) + " entries for Shape = " + s));
          double distance = 0;
          for (const double c : center)
            distance = std::max(distance, std::abs(c));
          check_resolvable(radius, distance, "parameter 'Geometry/Radius'");
          if (shape == Shape::half_cylinder)
            {
              AssertThrow(length > 0,
                          ExcMessage("parameter 'Geometry/Length' must be > 0"));
              check_resolvable(length,
                               std::abs(center[2]) + length / 2,
                               "parameter 'Geometry/Length'");
            }
        }
      parse_manifolds(manifold_text);
    }


    void
    Geometry::parse_manifolds(const std::string &text)
    {
      manifolds.clear();
      if (Utilities::trim(text).empty())
        return;
      const std::string name = "parameter 'Geometry/Manifolds'";
      AssertThrow(shape == Shape::file,
                  ExcMessage(name + " is for Shape = file (the built-in shapes "
                                    "describe their own curved boundaries)"));
      const std::string syntax =
        dimension == 2 ? "'id: sphere X, Y radius R'" :
                         "'id: sphere X, Y, Z radius R' or 'id: cylinder X, Y, Z "
                         "direction DX, DY, DZ radius R'";
      std::set<unsigned int> ids;
      for (const auto &entry : Utilities::split_string_list(text, ';'))
        {
          Manifold    m;
          std::string reason;
          m.text = entry;
          // the entry, cut at its keywords: id, kind, point [direction] radius
          const auto colon = entry.find(':');
          std::istringstream words(colon == std::string::npos ? "" : entry.substr(colon + 1));
          std::string        kind;
          words >> kind;
          std::vector<std::string> parts(1);
          for (std::string word; words >> word;)
            if (word == "direction" || word == "radius")
              parts.push_back(word), parts.emplace_back();
            else
              parts.back() += word + " ";
          const std::vector<std::string> expected =
            kind == "cylinder" ? std::vector<std::string>{"", "direction", "", "radius", ""} :
                                 std::vector<std::string>{"", "radius", ""};
          auto numbers = [&](const std::string &list, const unsigned int n, const char *what) {
            std::vector<double> values;
            try
              {
                values = parse_double_list(list);
              }
            catch (...)
              {}
            if (reason.empty() && (values.size() != n || !std::all_of(values.begin(),
                                                                     values.end(),
                                                                     [](const double v) {
                                                                       return std::isfinite(v);
                                                                     })))
              reason = std::string(what) + " '" + Utilities::trim(list) + "' is not " +
                       std::to_string(n) + " numbers";
            return values;
          };
          int id = -1;
          try
            {
              if (colon != std::string::npos)
                id = Utilities::string_to_int(Utilities::trim(entry.substr(0, colon)));
            }
          catch (...)
            {}
          if (id < 0 || id > 255)
            reason = "no boundary id (0 to 255) before ':'";
          else if (kind != "sphere" && kind != "cylinder")
            reason = "'" + kind + "' is neither sphere nor cylinder";
          else if (kind == "cylinder" && dimension == 2)
            reason = "a cylinder needs Dimension = 3";
          else if (parts.size() != expected.size() ||
                   !std::equal(parts.begin(), parts.end(), expected.begin(), [](const std::string &p, const std::string &e) {
                     return e.empty() ? !Utilities::trim(p).empty() : p == e;
                   }))
            reason = "it does not read as " + syntax;
          else
            {
              m.boundary_id = id;
              m.kind   = kind == "sphere" ? Manifold::Kind::sphere : Manifold::Kind::cylinder;
              m.point  = numbers(parts[0], dimension, kind == "sphere" ? "the center" : "the point");
              if (m.kind == Manifold::Kind::cylinder)
                m.direction = numbers(parts[2], 3, "the direction");
              const auto r = numbers(parts.back(), 1, "the radius");
              m.radius     = r.empty() ? 0. : r[0];
              if (reason.empty() && !(m.radius > 0))
                reason = "the radius must be > 0";
              if (reason.empty() && m.kind == Manifold::Kind::cylinder &&
                  std::sqrt(m.direction[0] * m.direction[0] + m.direction[1] * m.direction[1] +
                            m.direction[2] * m.direction[2]) == 0)
                reason = "the direction is zero";
              if (reason.empty() && !ids.insert(id).second)
                reason = "boundary id " + std::to_string(id) + " has a manifold already";
            }
          AssertThrow(reason.empty(),
                      ExcMessage(name + " has entry '" + Utilities::trim(entry) + "': " +
                                 reason + (reason.find("does not read") == std::string::npos ?
                                             "" :
                                             " (entries separated by ';')")));
          manifolds.push_back(m);
        }
    }


    void
    Material::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      prm.declare_entry("mu",
                        "",
                        Patterns::Anything(),
                        "Shear modulus mu > 0, given with lambda. The material is "
                        "given either by mu and lambda or by E and nu (exactly one "
                        "pair), in any consistent units.");
      prm.declare_entry("lambda",
                        "",
                        Patterns::Anything(),
                        "Lame's first parameter lambda, given with mu: a number "
                        "> -2 mu / dim (a positive bulk modulus), or 'inf' for an "
                        "incompressible material (exact, no penalty).");
      prm.declare_entry("E",
                        "",
                        Patterns::Anything(),
                        "Young's modulus E > 0, given with nu (instead of mu and "
                        "lambda).");
      prm.declare_entry("nu",
                        "",
                        Patterns::Anything(),
                        "Poisson's ratio nu, -1 < nu <= 0.5, given with E; 0.5 is the "
                        "incompressible material (lambda = inf). In 2D the body is "
                        "in plane strain.");
      prm.leave_subsection();
    }

    void
    Material::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      const std::string mu_text     = Utilities::trim(prm.get("mu"));
      const std::string lambda_text = Utilities::trim(prm.get("lambda"));
      const std::string e_text      = Utilities::trim(prm.get("E"));
      const std::string nu_text     = Utilities::trim(prm.get("nu"));
      prm.leave_subsection();

      const bool lame        = !mu_text.empty() || !lambda_text.empty();
      const bool engineering = !e_text.empty() || !nu_text.empty();
      AssertThrow(lame != engineering,
                  ExcMessage(std::string("subsection 'Material' needs exactly one pair of "
                                         "constants, 'mu' and 'lambda' or 'E' and 'nu'; ") +
                             (lame ? "both pairs are given" : "none is given")));
      if (lame)
        {
          AssertThrow(!mu_text.empty() && !lambda_text.empty(),
                      ExcMessage(std::string("parameter 'Material/") +
                                 (mu_text.empty() ? "lambda' is given without 'Material/mu'" :
                                                    "mu' is given without 'Material/lambda'")));
          mu     = parse_extended_double(mu_text, "Material/mu");
          lambda = parse_extended_double(lambda_text, "Material/lambda");
          AssertThrow(std::isfinite(mu) && mu > 0,
                      ExcMessage("parameter 'Material/mu' = " + mu_text +
                                 " must be a number > 0"));
          // (the bound on lambda, which depends on the dimension, is
          // checked by AllParameters::parse_parameters)
          youngs_modulus = std::isinf(lambda) ? 3. * mu :
                                                mu * (3. * lambda + 2. * mu) / (lambda + mu);
          poisson_ratio  = std::isinf(lambda) ? 0.5 : lambda / (2. * (lambda + mu));
        }
      else
        {
          AssertThrow(!e_text.empty() && !nu_text.empty(),
                      ExcMessage(std::string("parameter 'Material/") +
                                 (e_text.empty() ? "nu' is given without 'Material/E'" :
                                                   "E' is given without 'Material/nu'")));
          youngs_modulus = parse_extended_double(e_text, "Material/E");
          poisson_ratio  = parse_extended_double(nu_text, "Material/nu");
          AssertThrow(std::isfinite(youngs_modulus) && youngs_modulus > 0,
                      ExcMessage("parameter 'Material/E' = " + e_text +
                                 " must be a number > 0"));
          AssertThrow(poisson_ratio > -1 && poisson_ratio <= 0.5,
                      ExcMessage("parameter 'Material/nu' = " + nu_text +
                                 " must lie in (-1, 0.5]"));
          const double nu = poisson_ratio;
          mu              = youngs_modulus / (2. * (1. + nu));
          lambda          = nu == 0.5 ? std::numeric_limits<double>::infinity() :
                                        youngs_modulus * nu / ((1. + nu) * (1. - 2. * nu));
        }
    }


    void
    Scaling::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Scaling");
      prm.declare_entry("Reference length",
                        "auto",
                        Patterns::Anything(),
                        "The length L the program divides all lengths by, in the "
                        "scene's units: a number > 0, or auto: the largest side of "
                        "the bounding box of the coarse mesh. The problem is solved "
                        "in dimensionless form and every output is in the scene's "
                        "units; the functional weights mean the same functional in "
                        "every unit system for the same L (doc/method.md, section 1). "
                        "Models that are parts of one another (a symmetric half) "
                        "need the same L to have the same functional.");
      prm.declare_entry("Reference stress",
                        "auto",
                        Patterns::Anything(),
                        "The stress S the program divides all stresses by, in the "
                        "scene's units: a number > 0, or auto: the shear modulus mu.");
      prm.leave_subsection();
    }

    void
    Scaling::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Scaling");
      const std::string length_text = Utilities::trim(prm.get("Reference length"));
      const std::string stress_text = Utilities::trim(prm.get("Reference stress"));
      prm.leave_subsection();
      auto parse = [](const std::string &text, const std::string &name) {
        if (text == "auto")
          return 0.;
        const double value = parse_extended_double(text, name);
        AssertThrow(std::isfinite(value) && value > 0,
                    ExcMessage("parameter '" + name + "' = " + text +
                               " must be 'auto' or a number > 0"));
        return value;
      };
      reference_length = parse(length_text, "Scaling/Reference length");
      reference_stress = parse(stress_text, "Scaling/Reference stress");
    }


    void
    Weights::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Functional weights");
      prm.declare_entry("C_eq",
                        "1e2",
                        Patterns::Double(0),
                        "Weight of ||div sigma + f||^2 (paper eq. 1).");
      prm.declare_entry("C_const",
                        "1",
                        Patterns::Double(0),
                        "Weight of ||A sigma - eps(u)||^2 (paper eq. 1).");
      prm.declare_entry("C_compl",
                        "0.1",
                        Patterns::Double(0),
                        "Weight of the complementarity term <u.n - g, (sigma n).n> "
                        "(paper eq. 2). Too large a value makes the problem "
                        "indefinite; the program checks and refuses. The "
                        "paper's 1e1 is indefinite with C_const = 1 (see "
                        "doc/method.md, section 5), hence the default 0.1. The "
                        "three weights apply to the dimensionless terms "
                        "(Scaling), so they mean the same in every unit system.");
      prm.leave_subsection();
    }

    void
    Weights::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Functional weights");
      c_eq    = prm.get_double("C_eq");
      c_const = prm.get_double("C_const");
      c_compl = prm.get_double("C_compl");
      prm.leave_subsection();
      AssertThrow(c_eq > 0 && c_const > 0,
                  ExcMessage("parameters 'Functional weights/C_eq' and "
                             "'C_const' must be > 0"));
    }


    void
    Data::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Data");
      prm.declare_entry("Constants",
                        "",
                        Patterns::Anything(),
                        "Named constants for all expressions, e.g. "
                        "'push=0.01, R=0.5' (pi is always defined). Names: letters, "
                        "digits and _, not starting with a digit, not x, y (z in "
                        "3D) and each once.");
      prm.declare_entry("Body force",
                        "",
                        Patterns::Anything(),
                        "Body force f, components separated by ';'. Empty: the "
                        "scene has no body force and no term is assembled.");
      prm.declare_entry("Dirichlet values",
                        "0; 0",
                        Patterns::Anything(),
                        "Displacement u^D on the Dirichlet boundary.");
      prm.declare_entry("Traction",
                        "0; 0",
                        Patterns::Anything(),
                        "Traction t^N = sigma n on the Neumann boundary.");
      prm.declare_entry("Gap",
                        "0",
                        Patterns::Anything(),
                        "Gap g: the contact constraint is u.n <= g.");
      prm.declare_entry("Obstacle normal",
                        "0; -1",
                        Patterns::Anything(),
                        "Direction n of the contact constraints u.n <= g and "
                        "(sigma n_body).n <= 0: it points from the body into "
                        "the obstacle and is normalized by the program.");
      prm.declare_entry("Exact displacement",
                        "",
                        Patterns::Anything(),
                        "Optional exact u, for error norms.");
      prm.declare_entry("Exact stress",
                        "",
                        Patterns::Anything(),
                        "Optional exact sigma, row by row (dim*dim entries).");
      prm.declare_entry("Initial displacement",
                        "",
                        Patterns::Anything(),
                        "Used with Solver/Initial guess = expression: the "
                        "starting displacement, projected onto the feasible set.");
      prm.leave_subsection();
    }

    void
    Data::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Data");
      constants            = prm.get("Constants");
      body_force           = prm.get("Body force");
      dirichlet_values     = prm.get("Dirichlet values");
      traction             = prm.get("Traction");
      gap                  = prm.get("Gap");
      obstacle_normal      = prm.get("Obstacle normal");
      exact_displacement   = prm.get("Exact displacement");
      exact_stress         = prm.get("Exact stress");
      initial_displacement = prm.get("Initial displacement");
      prm.leave_subsection();
    }


    void
    BoundaryConditions::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      prm.declare_entry("Dirichlet boundary ids",
                        "",
                        Patterns::List(Patterns::Integer(0, 255)),
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
                        Patterns::List(Patterns::Integer(0, 255)),
                        "Boundary ids with prescribed traction.");
      prm.declare_entry("Contact boundary ids",
                        "",
                        Patterns::List(Patterns::Integer(0, 255)),
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
    Solver::declare_parameters(ParameterHandler &prm)
    {
      // the counts' defaults are the members' initial values
      const Solver defaults;
      prm.enter_subsection("Solver");
      prm.declare_entry("Type",
                        "monotone multigrid",
                        Patterns::Selection(
                          "monotone multigrid|active set|projected gauss seidel"),
                        "monotone multigrid: the paper's method (default). "
                        "active set: primal-dual active set with a sparse direct "
                        "solve (the reference). projected gauss seidel: the "
                        "classic baseline.");
      prm.declare_entry("Tolerance",
                        "1e-8",
                        Patterns::Double(0),
                        "Stop when the energy norm of the last correction, "
                        "times rho/(1-rho) where the rate rho of the last two "
                        "iterations is above 1/2 (the error of a slowly "
                        "converging run), is below Tolerance times that of the "
                        "first correction (an error reduction factor).");
      prm.declare_entry("Max iterations",
                        std::to_string(defaults.max_iterations),
                        Patterns::Integer(1),
                        "Maximal number of iterations (cycles, sweeps or "
                        "active-set steps).");
      prm.declare_entry("Stopping criterion",
                        "tolerance",
                        Patterns::Selection("tolerance|discretization accuracy"),
                        "tolerance: as above. discretization accuracy: stop when "
                        "the estimated algebraic error is below Discretization "
                        "fraction times the least-squares functional's "
                        "estimate of the discretization error (not for projected "
                        "Gauss-Seidel, whose rate is not steady enough for the "
                        "estimate).");
      prm.declare_entry("Discretization fraction",
                        "0.1",
                        Patterns::Double(0, 1),
                        "See Stopping criterion.");
      prm.declare_entry("Pre smoothing",
                        std::to_string(defaults.pre_smoothing),
                        Patterns::Integer(0, 100),
                        "Forward patch sweeps before the coarse correction (Pre and "
                        "Post smoothing must not both be 0).");
      prm.declare_entry("Post smoothing",
                        std::to_string(defaults.post_smoothing),
                        Patterns::Integer(0, 100),
                        "Backward patch sweeps after the coarse correction.");
      prm.declare_entry("Cycle",
                        "W",
                        Patterns::Selection("V|W|F"),
                        "Multigrid cycle: V, W, or F (an F-cycle on the coarser "
                        "level, then a V-cycle there).");
      prm.declare_entry("Projection",
                        "b",
                        Patterns::Selection("a|b|c|d"),
                        "Coarse obstacle for the normal displacement: a = eq. "
                        "(26), b = eq. (27), c = eq. (28), d = no coarse "
                        "constraint (infinity).");
      prm.declare_entry("Initial guess",
                        "coarse solution",
                        Patterns::Selection(
                          "zero|coarse solution|nested iteration|expression"),
                        "zero; coarse solution: the exact solution on level 1 "
                        "interpolated to level J (paper section 7); nested "
                        "iteration: solve on every level in turn; expression: "
                        "Data/Initial displacement.");
      prm.declare_entry("Krylov steps",
                        std::to_string(defaults.krylov_steps),
                        Patterns::Integer(0, 1000),
                        "0: the plain monotone multigrid cycle. k > 0: truncated "
                        "nonsmooth Newton multigrid: projected pre-smoothing on "
                        "the finest level, then conjugate gradient steps (at most k; "
                        "they stop at 1e-3 times the first residual of the Newton step) "
                        "preconditioned by the linear truncated cycle on the "
                        "current inactive set, a projected line search that "
                        "never increases J, and projected post-smoothing.");
      prm.declare_entry("Linear cycle",
                        "own",
                        Patterns::Selection("own|deal.II"),
                        "The linear truncated cycle that preconditions the Newton "
                        "step's CG (Krylov steps > 0): own (MonotoneCycle) or "
                        "deal.II (the same cycle run by deal.II's Multigrid with "
                        "the patch smoother, the truncated sign-correct transfer, "
                        "the Galerkin operators and the exact coarse solve as its "
                        "parts). The iterates are the same up to round-off.");
      prm.declare_entry("Threads",
                        std::to_string(defaults.threads),
                        Patterns::Integer(0, 1024),
                        "Threads per process for the patch smoother (patches of "
                        "one color are relaxed concurrently), the assembly and "
                        "deal.II's vector and matrix operations. 0: as many as "
                        "the machine has cores (or the environment variable "
                        "DEAL_II_NUM_THREADS says). The smoother's iterates do "
                        "not depend on the number of threads; deal.II's sums "
                        "(dot products in the Newton step's CG) are split by "
                        "thread count, so other results can differ in the last "
                        "digits (measured: the contact force to 2e-10 relative or "
                        "better, doc/parallel_results.md).");
      prm.declare_entry("Check coarse defects",
                        "false",
                        Patterns::Bool(),
                        "A diagnostic of the monotone multigrid for tests: the "
                        "second visit of a level in a W- or F-cycle takes its coarse "
                        "defect as r_H - alpha A_H c when the truncation is the first "
                        "visit's; with true, it is also recomputed as P~^T (r - A v) "
                        "and the largest difference, relative to |P~^T| (|A| |v| + "
                        "|r|) (max norms), is written to summary.json as "
                        "coarse_defect_difference (round-off: at most 1.4e-17 "
                        "measured), with the number of such visits as "
                        "coarse_defect_checks. The iterates are the same; the solve "
                        "time and, on several processes, the communication include "
                        "the check's products with the level's matrix and P~^T.");
      prm.declare_entry("Definiteness check max dofs",
                        std::to_string(defaults.definiteness_max_dofs),
                        Patterns::Integer(0),
                        "The definiteness check (paper eq. 10, section 7) forms "
                        "the Schur complement of the functional onto the contact "
                        "normal DoFs on the finest level with at most this many "
                        "DoFs; indefiniteness there implies indefiniteness on "
                        "every finer level (nested spaces). 0: skip the check.");
      prm.leave_subsection();
    }

    void
    Solver::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Solver");
      const std::string t = prm.get("Type");
      type = (t == "monotone multigrid" ? Type::monotone_multigrid :
              t == "active set"         ? Type::active_set :
                                          Type::projected_gauss_seidel);
      tolerance      = prm.get_double("Tolerance");
      max_iterations = prm.get_integer("Max iterations");
      stopping = prm.get("Stopping criterion") == "tolerance" ?
                   Stopping::tolerance :
                   Stopping::discretization_accuracy;
      discretization_fraction = prm.get_double("Discretization fraction");
      pre_smoothing           = prm.get_integer("Pre smoothing");
      post_smoothing          = prm.get_integer("Post smoothing");
      const std::string c     = prm.get("Cycle");
      cycle                   = (c == "V" ? Cycle::V : c == "W" ? Cycle::W : Cycle::F);
      const std::string p     = prm.get("Projection");
      projection              = (p == "a" ? Projection::a :
                                 p == "b" ? Projection::b :
                                 p == "c" ? Projection::c :
                                            Projection::d);
      const std::string g     = prm.get("Initial guess");
      initial_guess = (g == "zero"             ? InitialGuess::zero :
                       g == "coarse solution"  ? InitialGuess::coarse_solution :
                       g == "nested iteration" ? InitialGuess::nested_iteration :
                                                 InitialGuess::expression);
      definiteness_max_dofs = prm.get_integer("Definiteness check max dofs");
      krylov_steps          = prm.get_integer("Krylov steps");
      linear_cycle = prm.get("Linear cycle") == "own" ? LinearCycle::own : LinearCycle::dealii;
      threads               = prm.get_integer("Threads");
      check_coarse_defects  = prm.get_bool("Check coarse defects");
      prm.leave_subsection();
      // without smoothing the cycle never changes the finest level's
      // oscillating part: the first correction is the coarse one, and the
      // run stopped at once at the wrong answer (measured: the square's
      // level 5 ended at the level-1 contact force, 0.02572 against 0.02705)
      // (the estimate of the algebraic error takes the rate as steady; that
      // of projected Gauss-Seidel keeps growing: measured 0.94 after 34
      // sweeps on the square's level 5, which then stopped with the contact
      // force 5% off)
      AssertThrow(type != Type::projected_gauss_seidel ||
                    stopping != Stopping::discretization_accuracy,
                  ExcMessage("parameter 'Solver/Stopping criterion' = discretization accuracy "
                             "is not available for Solver/Type = projected gauss seidel, whose "
                             "rate is not steady: use Stopping criterion = tolerance"));
      AssertThrow(type != Type::monotone_multigrid || pre_smoothing + post_smoothing > 0,
                  ExcMessage("parameters 'Solver/Pre smoothing' and 'Solver/Post smoothing' are "
                             "both 0: the monotone multigrid needs at least one smoothing step"));
    }


    void
    Output::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Directory",
                        "output",
                        Patterns::Anything(),
                        "Directory for VTU, CSV and JSON output (created).");
      prm.declare_entry("Write vtu",
                        "true",
                        Patterns::Bool(),
                        "Write the solution as pvtu + vtu.");
      prm.declare_entry("Verbose",
                        "true",
                        Patterns::Bool(),
                        "Print one line per iteration and the timer summary.");
      prm.leave_subsection();
    }

    void
    Output::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      directory = prm.get("Directory");
      write_vtu = prm.get_bool("Write vtu");
      verbose   = prm.get_bool("Verbose");
      prm.leave_subsection();
      AssertThrow(!Utilities::trim(directory).empty(),
                  ExcMessage("parameter 'Output/Directory' is empty"));
    }


    void
    HertzComparison::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Hertz comparison");
      prm.declare_entry("Shape",
                        "none",
                        Patterns::Selection("none|cylinder|sphere"),
                        "none, or the Hertz contact this scene is: cylinder (a "
                        "cylinder of radius R on a plane, in plane strain, forces per "
                        "unit length: in 2D its cross-section, in 3D a cylinder of "
                        "Length along Axis) or sphere (3D: a sphere of radius R on a "
                        "plane). One of the two bodies is rigid, the other has the "
                        "scene's material. The run prints Hertz's contact half-width "
                        "(radius) a and peak pressure p0 for the computed force, "
                        "against the computed contact edge, peak pressure and the "
                        "relative l2 error of the pressure at the contact vertices, "
                        "and writes them to summary.json (\"hertz\"), which "
                        "scripts/plot.py draws.");
      prm.declare_entry("Radius",
                        "0",
                        Patterns::Double(0),
                        "R, in the scene's units.");
      prm.declare_entry("Contact point",
                        "0, 0",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "The first point of contact (the center of the contact zone; "
                        "in 3D for a cylinder a point of the contact line), in the "
                        "scene's coordinates; distances are measured from it in the "
                        "plane of contact (for a cylinder in 3D: from the contact "
                        "line).");
      prm.declare_entry("Force factor",
                        "1",
                        Patterns::Double(0),
                        "The force of the full contact per computed force, > 0: a "
                        "model of a symmetric part computes a part of the force, "
                        "Hertz's formulas need the whole: 4 for a quarter model of a "
                        "sphere (two symmetry planes through the contact point), 2 "
                        "for a half model. Hertz's F is the computed normal force "
                        "times this factor (divided by Length for a cylinder in 3D).");
      prm.declare_entry("Axis",
                        "0, 0, 1",
                        Patterns::List(Patterns::Double(), 3, 3),
                        "Cylinder in 3D: the direction of its axis (the contact "
                        "line).");
      prm.declare_entry("Length",
                        "0",
                        Patterns::Double(0),
                        "Cylinder in 3D: the length of the contact line of the full "
                        "model, in the scene's units: Hertz's force per unit length "
                        "is F times Force factor divided by it.");
      prm.leave_subsection();
    }

    void
    HertzComparison::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Hertz comparison");
      const std::string s = prm.get("Shape");
      shape         = s == "none" ? Shape::none : s == "cylinder" ? Shape::cylinder : Shape::sphere;
      radius        = prm.get_double("Radius");
      contact_point = parse_double_list(prm.get("Contact point"));
      force_factor  = prm.get_double("Force factor");
      axis          = parse_double_list(prm.get("Axis"));
      length        = prm.get_double("Length");
      prm.leave_subsection();
      if (shape == Shape::none)
        return;
      AssertThrow(radius > 0,
                  ExcMessage("parameter 'Hertz comparison/Radius' must be > 0 with a Shape"));
      AssertThrow(force_factor > 0,
                  ExcMessage("parameter 'Hertz comparison/Force factor' must be > 0"));
    }


    void
    AllParameters::declare_parameters(ParameterHandler &prm)
    {
      Geometry::declare_parameters(prm);
      Material::declare_parameters(prm);
      Scaling::declare_parameters(prm);
      Weights::declare_parameters(prm);
      Data::declare_parameters(prm);
      BoundaryConditions::declare_parameters(prm);
      Solver::declare_parameters(prm);
      Output::declare_parameters(prm);
      HertzComparison::declare_parameters(prm);
    }

    void
    AllParameters::parse_parameters(ParameterHandler &prm)
    {
      geometry.parse_parameters(prm);
      material.parse_parameters(prm);
      scaling.parse_parameters(prm);
      weights.parse_parameters(prm);
      // a positive bulk modulus: lambda + 2 mu / dim > 0 (always so for E
      // and nu in their ranges)
      {
        std::ostringstream text;
        text << "parameter 'Material/lambda' = " << material.lambda
             << " must be > -2 mu / dim = " << -2. * material.mu / geometry.dimension
             << " (a positive bulk modulus), or inf";
        AssertThrow(material.lambda > -2. * material.mu / geometry.dimension,
                    ExcMessage(text.str()));
      }
      data.parse_parameters(prm);
      boundary_conditions.parse_parameters(prm);
      solver.parse_parameters(prm);
      output.parse_parameters(prm);
      hertz.parse_parameters(prm);
      if (hertz.shape != HertzComparison::Shape::none)
        {
          AssertThrow(hertz.shape == HertzComparison::Shape::cylinder ||
                        geometry.dimension == 3,
                      ExcMessage("parameter 'Hertz comparison/Shape' = sphere needs "
                                 "Dimension = 3"));
          if (hertz.shape == HertzComparison::Shape::cylinder && geometry.dimension == 3)
            {
              AssertThrow(hertz.length > 0,
                          ExcMessage("parameter 'Hertz comparison/Length' must be > 0 "
                                     "for a cylinder in 3D (the length of its contact "
                                     "line)"));
              AssertThrow(hertz.axis[0] != 0 || hertz.axis[1] != 0 || hertz.axis[2] != 0,
                          ExcMessage("parameter 'Hertz comparison/Axis' is zero"));
            }
          AssertThrow(hertz.contact_point.size() == geometry.dimension,
                      ExcMessage("parameter 'Hertz comparison/Contact point' needs " +
                                 std::to_string(geometry.dimension) + " entries"));
        }

      // 'all', a component list for every Dirichlet id, or per id
      // "id: components; id: components" (ids not named: all)
      auto &     bc   = boundary_conditions;
      const auto name = std::string("parameter 'Boundary conditions/Dirichlet components'");
      auto       parse_mask = [&](const std::string &text) {
        std::vector<bool> mask(geometry.dimension, text == "all");
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
              AssertThrow(k >= 0 && k < static_cast<int>(geometry.dimension),
                          ExcMessage(name + " has entry '" + c +
                                     "'; valid: all, or components 0.." +
                                     std::to_string(geometry.dimension - 1)));
              mask[k] = true;
            }
        AssertThrow(std::find(mask.begin(), mask.end(), true) != mask.end(),
                    ExcMessage(name + " = '" + text + "' prescribes no component"));
        return mask;
      };
      bc.dirichlet_components.clear();
      if (bc.dirichlet_components_text.find(':') == std::string::npos)
        {
          const auto mask = parse_mask(bc.dirichlet_components_text);
          for (const unsigned int id : bc.dirichlet_ids)
            bc.dirichlet_components[id] = mask;
        }
      else
        {
          for (const unsigned int id : bc.dirichlet_ids)
            bc.dirichlet_components[id] = std::vector<bool>(geometry.dimension, true);
          std::set<unsigned int> named;
          for (const auto &entry : Utilities::split_string_list(bc.dirichlet_components_text, ';'))
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
              AssertThrow(bc.dirichlet_components.count(id),
                          ExcMessage(name + " names boundary id " + std::to_string(id) +
                                     ", which is not in 'Boundary conditions/Dirichlet "
                                     "boundary ids'"));
              AssertThrow(named.insert(id).second,
                          ExcMessage(name + " names boundary id " + std::to_string(id) +
                                     " twice"));
              bc.dirichlet_components[id] = parse_mask(pair[1]);
            }
        }
    }
  } // namespace Parameters
} // namespace FoslsContact
