#include <deal.II/base/geometry_info.h>

#include <fosls_contact/solvers/contact_face_relations.h>

#include <map>
#include <set>

namespace FoslsContact
{
  namespace
  {
    /**
     * The fine DoFs of the children of @p cell (those with DoFs here) that
     * do not lie on one of its faces other than @p f, sorted. Child c of an
     * isotropically refined cell touches the parent's face 2d + s iff bit d
     * of c is s; its vertex v lies on that face iff bit d of v is s too.
     */
    template <int dim, typename Iterator>
    std::vector<types::global_dof_index>
    inside_dofs(const Iterator &cell, const unsigned int f, const LevelData<dim> &fine)
    {
      std::set<types::global_dof_index> inside;
      auto on_other_face = [&](const unsigned int c, const unsigned int d, const unsigned int s) {
        return ((c >> d) & 1u) == s && 2 * d + s != f;
      };
      for (unsigned int c = 0; c < cell->n_children(); ++c)
        {
          const auto child = cell->child(c);
          if (!Discretization<dim>::is_present(child))
            continue;
          for (const unsigned int v : child->vertex_indices())
            {
              bool outside = false;
              for (unsigned int d = 0; d < dim; ++d)
                outside |= ((v >> d) & 1u) == ((c >> d) & 1u) &&
                           on_other_face(c, d, (c >> d) & 1u);
              if (!outside)
                for (const auto dof : fine.vertex_dofs.at(child->vertex_index(v)))
                  inside.insert(dof);
            }
          for (const unsigned int cf : child->face_indices())
            if (!on_other_face(c, cf / 2, cf % 2))
              for (const auto dof : fine.face_dofs.at(child->face(cf)->index()))
                inside.insert(dof);
        }
      return {inside.begin(), inside.end()};
    }
  } // namespace


  template <int dim>
  ContactFaceRelations<dim>::ContactFaceRelations(const Discretization<dim> &coarse_mesh,
                                                  const unsigned int         coarse_index,
                                                  const Discretization<dim> &fine_mesh,
                                                  const unsigned int         fine_index)
  {
    // Contact relations between the coarse and the fine level, for the
    // coarse contact faces owned here; the entries the rerouting may give
    // for every coarse contact face with a cell here.
    const auto &scene      = coarse_mesh.get_scene();
    const auto &coarse     = coarse_mesh.level(coarse_index);
    const auto &fine       = fine_mesh.level(fine_index);
    const auto &fine_tria  = fine_mesh.get_triangulation();
    const bool  same_mesh  = &coarse_mesh == &fine_mesh;
    const bool         tangential = tangential_rows(scene);
    const unsigned int rows       = tangential ? dim : 1;
    auto        on_contact = [&](const auto &cell, const unsigned int f) {
      return cell->at_boundary(f) && scene.is_contact(cell->face(f)->boundary_id());
    };
    coarse.for_each_cell(coarse_mesh.get_dof_handler(), [&](const auto &cell) {
      // the coarse cell on the fine level's mesh: itself on one mesh
      const auto fine_cell =
        same_mesh ? typename Triangulation<dim>::cell_iterator(cell) :
                    fine_tria.create_cell_iterator(cell->id());
      for (const unsigned int f : cell->face_indices())
        if (on_contact(cell, f))
          {
            if (fine_cell->has_children())
              {
                const auto &dofs   = coarse.face_dofs.at(cell->face(f)->index());
                const auto  inside = inside_dofs(fine_cell, f, fine);
                for (unsigned int m = 0; m < rows; ++m)
                  for (const auto i : inside)
                    rerouting.emplace_back(i, dofs[m]);
              }
            if (coarse.owns(cell))
              faces.push_back(
                face_relation(cell, fine_cell, f, coarse, fine, tangential));
          }
    });
  }


  template <int dim>
  template <typename Iterator, typename FineIterator>
  FaceRelation
  ContactFaceRelations<dim>::face_relation(const Iterator &      cell,
                                           const FineIterator &  fine_cell,
                                           const unsigned int    f,
                                           const LevelData<dim> &coarse,
                                           const LevelData<dim> &fine,
                                           const bool            tangential) const
  {
    auto fine_normal_dof = [&](const unsigned int vertex) {
      return fine.vertex_dofs.at(vertex)[0];
    };
    auto coarse_normal_dof = [&](const unsigned int vertex) {
      const auto dof = coarse.vertex_dofs.at(vertex)[0];
      return coarse.role[dof] == DoFRole::bounded ? dof : numbers::invalid_dof_index;
    };
    const auto   face      = cell->face(f);
    const auto   fine_face = fine_cell->face(f);
    FaceRelation frel;
    frel.coarse_dof = coarse.face_dofs.at(face->index())[0];
    for (unsigned int m = 1; tangential && m < dim; ++m)
      {
        FaceRelation::TangentialRow row{coarse.face_dofs.at(face->index())[m], {}};
        if (fine_cell->has_children())
          for (unsigned int c = 0; c < fine_face->n_children(); ++c)
            row.sons.push_back(fine.face_dofs.at(fine_face->child(c)->index())[m]);
        else
          row.sons.push_back(fine.face_dofs.at(fine_face->index())[m]);
        frel.tangential.push_back(row);
      }
    if (!fine_cell->has_children())
      {
        // not refined: the face is its own son, each vertex its own coarse
        // obstacle (an "edge" from the vertex to itself, with itself as
        // midpoint, gives the vertex's defect obstacle in every projection)
        frel.sons.push_back(fine.face_dofs.at(fine_face->index())[0]);
        for (const unsigned int v : face->vertex_indices())
          {
            const auto self = fine_normal_dof(fine_face->vertex_index(v));
            frel.edges.push_back({{{coarse_normal_dof(face->vertex_index(v)),
                                    numbers::invalid_dof_index}},
                                  {{self, self}},
                                  self});
          }
        return frel;
      }
    for (unsigned int c = 0; c < fine_face->n_children(); ++c)
      frel.sons.push_back(fine.face_dofs.at(fine_face->child(c)->index())[0]);
    // (all children of an owned cell are here)
    frel.inside = inside_dofs(fine_cell, f, fine);
    // coarse contact edges of this face (the face itself in 2D): the
    // coarse ends by the coarse mesh's vertex numbers, the fine ends and
    // the midpoint by the fine mesh's
    std::vector<std::array<unsigned int, 5>> edges; // a, b (coarse), a, b, midpoint (fine)
    if (dim == 2)
      edges.push_back({{face->vertex_index(0),
                        face->vertex_index(1),
                        fine_face->vertex_index(0),
                        fine_face->vertex_index(1),
                        fine_face->child(0)->vertex_index(1)}});
    else
      {
        for (unsigned int e = 0; e < GeometryInfo<dim>::lines_per_face; ++e)
          {
            const auto line      = face->line(e);
            const auto fine_line = fine_face->line(e);
            edges.push_back({{line->vertex_index(0),
                              line->vertex_index(1),
                              fine_line->vertex_index(0),
                              fine_line->vertex_index(1),
                              fine_line->child(0)->vertex_index(1)}});
          }
        // the face center is the one vertex all sons share
        std::map<unsigned int, unsigned int> count;
        for (unsigned int c = 0; c < fine_face->n_children(); ++c)
          for (const unsigned int v : fine_face->child(c)->vertex_indices())
            ++count[fine_face->child(c)->vertex_index(v)];
        for (const auto &[v, k] : count)
          if (k == fine_face->n_children())
            frel.fine_center = fine_normal_dof(v);
        for (const unsigned int v : face->vertex_indices())
          if (coarse_normal_dof(face->vertex_index(v)) != numbers::invalid_dof_index)
            frel.coarse_vertices.push_back(coarse_normal_dof(face->vertex_index(v)));
      }
    for (const auto &[a, b, fa, fb, m] : edges)
      frel.edges.push_back({{{coarse_normal_dof(a), coarse_normal_dof(b)}},
                            {{fine_normal_dof(fa), fine_normal_dof(fb)}},
                            fine_normal_dof(m)});
    return frel;
  }


  template struct ContactFaceRelations<2>;
  template struct ContactFaceRelations<3>;
} // namespace FoslsContact
