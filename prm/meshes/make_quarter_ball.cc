// Writes the Gmsh mesh (format 2.2, ASCII) of a quarter of the half ball of
// a scene (prm/half_ball.prm): the cells of its coarse mesh with x > Center_x
// and y > Center_y, in the scene's units, with the physical tags
//   1 = the curved surface (contact), 2 = the flat top,
//   3 = the symmetry plane x = Center_x, 4 = the symmetry plane y = Center_y,
//   1 = the volume.
// The half ball is symmetric about both planes (CurvedBody keeps their
// points exactly on them), so the quarter is a quarter model of the half
// ball: with the same refinements and the sphere as its manifold it gives
// the same finest mesh, and a quarter of the contact force
// (prm/quarter_ball_file.prm, tests/solver/curved_bodies_ball.py).
//
//   make_quarter_ball prm/half_ball.prm > prm/meshes/quarter_ball.msh
//
// (built with the tests: make make_quarter_ball; the test
// meshes/quarter_ball checks that the committed file is its output)
#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>

#include <fosls_contact/parameters/parameters.h>
#include <fosls_contact/scene/curved_body.h>

#include <iomanip>
#include <iostream>
#include <map>
#include <vector>

using namespace dealii;
using namespace FoslsContact;

int
main(int argc, char *argv[])
{
  if (argc != 2)
    {
      std::cerr << "usage: make_quarter_ball HALF_BALL_SCENE.prm > quarter_ball.msh" << std::endl;
      return 1;
    }
  ParameterHandler prm;
  Parameters::AllParameters::declare_parameters(prm);
  prm.parse_input(argv[1]);
  Parameters::AllParameters parameters;
  parameters.parse_parameters(prm);
  const auto &geometry = parameters.geometry;
  if (geometry.shape != Parameters::Geometry::Shape::half_ball)
    {
      std::cerr << "make_quarter_ball: " << argv[1] << " is not a half ball" << std::endl;
      return 1;
    }

  // the coarse mesh in the scene's units (reference length 1)
  Triangulation<3> tria;
  CurvedBody::make(geometry, 1., tria);
  const Point<3> center(geometry.center[0], geometry.center[1], geometry.center[2]);
  const double   tolerance = 1e-10 * geometry.radius;
  auto in_quarter          = [&](const auto &cell) {
    return cell->center()[0] > center[0] && cell->center()[1] > center[1];
  };

  // the vertices of the quarter's cells, numbered from 1
  std::map<unsigned int, unsigned int> number;
  for (const auto &cell : tria.active_cell_iterators())
    if (in_quarter(cell))
      for (const unsigned int v : cell->vertex_indices())
        number.emplace(cell->vertex_index(v), 0);
  unsigned int n = 0;
  for (auto &[vertex, k] : number)
    k = ++n;

  // the quarter's boundary faces, tagged by position
  std::vector<std::pair<unsigned int, std::array<unsigned int, 4>>> faces;
  for (const auto &cell : tria.active_cell_iterators())
    if (in_quarter(cell))
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f) || !in_quarter(cell->neighbor(f)))
          {
            const auto face = cell->face(f);
            auto       on   = [&](const unsigned int d, const double value) {
              for (const unsigned int v : face->vertex_indices())
                if (std::abs(face->vertex(v)[d] - value) > tolerance)
                  return false;
              return true;
            };
            const unsigned int tag = on(0, center[0]) ? 3 :
                                     on(1, center[1]) ? 4 :
                                     on(2, center[2]) ? 2 :
                                                        1;
            // counterclockwise, as Gmsh numbers a quadrilateral
            faces.push_back({tag,
                             {{number[face->vertex_index(0)],
                               number[face->vertex_index(1)],
                               number[face->vertex_index(3)],
                               number[face->vertex_index(2)]}}});
          }

  std::cout << std::setprecision(17) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
            << "$PhysicalNames\n5\n2 1 \"contact\"\n2 2 \"top\"\n2 3 \"symmetry x\"\n"
            << "2 4 \"symmetry y\"\n3 1 \"body\"\n$EndPhysicalNames\n"
            << "$Nodes\n" << number.size() << "\n";
  for (const auto &[vertex, k] : number)
    std::cout << k << " " << tria.get_vertices()[vertex] << "\n";
  std::cout << "$EndNodes\n$Elements\n";
  unsigned int n_cells = 0;
  for (const auto &cell : tria.active_cell_iterators())
    n_cells += in_quarter(cell);
  std::cout << n_cells + faces.size() << "\n";
  unsigned int element = 0;
  for (const auto &[tag, vertices] : faces)
    std::cout << ++element << " 3 2 " << tag << " " << tag << " " << vertices[0] << " "
              << vertices[1] << " " << vertices[2] << " " << vertices[3] << "\n";
  for (const auto &cell : tria.active_cell_iterators())
    if (in_quarter(cell))
      {
        // Gmsh numbers a hexahedron's vertices as UCD does
        std::cout << ++element << " 5 2 1 1";
        for (const unsigned int v : cell->vertex_indices())
          std::cout << " " << number[cell->vertex_index(GeometryInfo<3>::ucd_to_deal[v])];
        std::cout << "\n";
      }
  std::cout << "$EndElements\n";
  return 0;
}
