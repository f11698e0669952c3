#include <deal.II/base/utilities.h>

#include <fosls_contact/parameters/geometry.h>
#include <fosls_contact/parameters/value_parsing.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace FoslsContact
{
  namespace Parameters
  {
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
  } // namespace Parameters
} // namespace FoslsContact
