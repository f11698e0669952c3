#ifndef fosls_contact_parameters_geometry_h
#define fosls_contact_parameters_geometry_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace FoslsContact
{
  using namespace dealii;

  namespace Parameters
  {
    /**
     * subsection Geometry: which mesh, how fine, how many levels. The
     * coarse mesh is a box, one of the built-in curved bodies (half disc,
     * half ball, half cylinder), or read from a mesh file.
     */
    struct Geometry
    {
      enum class Shape
      {
        box,
        half_disc,
        half_ball,
        half_cylinder,
        file,
      };

      /**
       * A curved surface that the faces of one boundary id lie on
       * (`Geometry/Manifolds`): refinement puts the new vertices of these
       * faces on it. In the scene's units.
       */
      struct Manifold
      {
        enum class Kind
        {
          sphere,   ///< a circle in 2D: center and radius
          cylinder, ///< 3D: a point on the axis, the axis' direction, radius
        };
        unsigned int        boundary_id = 0;
        Kind                kind        = Kind::sphere;
        std::vector<double> point;     ///< the center, or a point on the axis
        std::vector<double> direction; ///< the axis (cylinder only)
        double              radius = 0;
        /** The entry as written, for messages. */
        std::string text;
      };

      unsigned int        dimension = 2;
      Shape               shape     = Shape::box;
      std::vector<double> lower_corner;
      std::vector<double> upper_corner;
      std::vector<unsigned int> subdivisions;
      double              radius       = 0.5;
      std::vector<double> center;
      /** Length of the half cylinder (along z). */
      double              length = 1.;
      /** Cells of the half cylinder's coarse mesh along its axis. */
      unsigned int        length_subdivisions = 2;
      unsigned int        coarse_refinements  = 2;
      double              grading             = 1.0;
      /** The mesh file, resolved by ParameterReader (Shape = file). */
      std::string           mesh_file;
      std::vector<Manifold> manifolds;
      /** Number of multigrid levels J (the coarse mesh is level 1). */
      unsigned int levels = 5;

      static void declare_parameters(ParameterHandler &prm);
      void        parse_parameters(ParameterHandler &prm);

    private:
      void parse_manifolds(const std::string &text);
    };
  } // namespace Parameters
} // namespace FoslsContact

#endif
