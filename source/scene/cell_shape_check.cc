#include <deal.II/base/mpi.h>
#include <deal.II/base/geometry_info.h>

#include <fosls_contact/scene/cell_shape_check.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace FoslsContact
{
  template <int dim>
  double
  CellShapeCheck<dim>::aspect_ratio(const typename Triangulation<dim>::cell_iterator &cell)
  {
    double longest = 0;
    for (unsigned int l = 0; l < GeometryInfo<dim>::lines_per_cell; ++l)
      longest = std::max(longest, cell->line(l)->diameter());
    const double thickness = cell->measure() / std::pow(longest, double(dim - 1));
    return thickness > 0 ? longest / thickness : std::numeric_limits<double>::infinity();
  }


  template <int dim>
  void
  CellShapeCheck<dim>::check(const Triangulation<dim> &  tria,
                             const MPI_Comm              comm,
                             const Parameters::Geometry &geometry,
                             const MeshFile<dim> *       mesh_file,
                             const double                length)
  {
    // The Jacobian determinant of the bilinear map at every corner of every
    // cell, on every level: a corner at or below 0 is an inverted (or
    // degenerate) cell, where the FOSLS functional is no longer a sum of
    // squares: J can go negative and the answer far off while the area of
    // every coarse cell is positive (doc/performance.md, "Figures behind
    // the code"). Refinement moves the boundary vertices onto the circle,
    // so the finer levels are checked too.
    check_aspect_ratios(tria, geometry, mesh_file, length);
    unsigned int first_bad_level = numbers::invalid_unsigned_int;
    Point<dim>   bad_center;
    for (const auto &cell : tria.cell_iterators())
      {
        Point<dim> vertices[GeometryInfo<dim>::vertices_per_cell];
        double     diameter = cell->diameter();
        for (const unsigned int v : cell->vertex_indices())
          vertices[v] = cell->vertex(v);
        Tensor<0, dim> forms[GeometryInfo<dim>::vertices_per_cell];
        GeometryInfo<dim>::alternating_form_at_vertices(vertices, forms);
        for (const unsigned int v : cell->vertex_indices())
          if (!(double(forms[v]) > 1e-10 * std::pow(diameter, double(dim))) &&
              static_cast<unsigned int>(cell->level()) < first_bad_level)
            {
              first_bad_level = cell->level();
              bad_center      = cell->center();
            }
      }
    const unsigned int level = Utilities::MPI::min(first_bad_level, comm);
    if (level == numbers::invalid_unsigned_int)
      return;
    // where it is: the cell of the first process that has one on that level
    const unsigned int rank  = Utilities::MPI::this_mpi_process(comm);
    const unsigned int first = Utilities::MPI::min(first_bad_level == level ?
                                                     rank :
                                                     numbers::invalid_unsigned_int,
                                                   comm);
    bad_center               = Utilities::MPI::broadcast(comm, bad_center, first);
    std::ostringstream where_text;
    where_text << "an inverted or degenerate cell on level " << level + 1 << " at (";
    for (unsigned int d = 0; d < dim; ++d)
      where_text << (d ? ", " : "") << bad_center[d] * length;
    where_text << ") (a corner whose Jacobian is not positive)";
    const std::string where = where_text.str();
    switch (geometry.shape)
      {
        case Parameters::Geometry::Shape::box:
          AssertThrow(false, ExcMessage("the mesh has " + where + "; check 'Geometry'"));
          break;
        case Parameters::Geometry::Shape::file:
          AssertThrow(false,
                      ExcMessage("the " + mesh_file->name() + " has " + where +
                                 "; check the mesh and 'Geometry/Manifolds'" +
                                 (mesh_file->distance_in_cells() > 1e5 ?
                                    " (it lies far from the origin against the size of "
                                    "its cells: deal.II's reader can turn a cell inside "
                                    "out there; move the origin near the body)" :
                                    "")));
          break;
        default:
          {
            const auto s = geometry.shape;
            AssertThrow(false,
                        ExcMessage("parameter 'Geometry/Grading' = " +
                                   std::to_string(geometry.grading) + " distorts the " +
                                   (s == Parameters::Geometry::Shape::half_disc ? "half disc" :
                                    s == Parameters::Geometry::Shape::half_ball ? "half ball" :
                                                                                  "half cylinder") +
                                   ": the mesh has " + where + "; use a smaller grading"));
          }
      }
  }


  template <int dim>
  void
  CellShapeCheck<dim>::check_aspect_ratios(const Triangulation<dim> &  tria,
                                           const Parameters::Geometry &geometry,
                                           const MeshFile<dim> *       mesh_file,
                                           const double                length)
  {
    // (the coarse cells are the same on every process, and so the decision)
    double     worst = 0;
    Point<dim> where;
    for (const auto &cell : tria.cell_iterators_on_level(0))
      if (const double aspect = aspect_ratio(cell); aspect > worst)
        {
          worst = aspect;
          where = cell->center();
        }
    if (worst < aspect_limit)
      return;
    // (the cell shape check names an inverted cell, whose thickness is 0)
    if (!std::isfinite(worst))
      return;
    std::ostringstream text;
    text.precision(2);
    text << "has a cell of aspect ratio " << worst << " at (";
    for (unsigned int d = 0; d < dim; ++d)
      text << (d ? ", " : "") << where[d] * length;
    text << "): double precision does not resolve the functional on cells of "
         << aspect_limit << ":1 and more";
    AssertThrow(geometry.shape != Parameters::Geometry::Shape::file,
                ExcMessage("the " + (mesh_file ? mesh_file->name() : std::string("mesh file")) +
                           " " + text.str() + "; split the long edges of its cells"));
    AssertThrow(false,
                ExcMessage("the mesh " + text.str() +
                           "; check 'Geometry' (more 'Box subdivisions' along the long edges)"));
  }


  template struct CellShapeCheck<2>;
  template struct CellShapeCheck<3>;
} // namespace FoslsContact
