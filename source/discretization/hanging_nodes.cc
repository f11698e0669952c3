#include <deal.II/dofs/dof_tools.h>

#include <fosls_contact/discretization/hanging_nodes.h>

#include <algorithm>
#include <limits>

#include <map>

namespace FoslsContact
{
  template <int dim>
  void
  eliminate_hanging_dofs(const DoFHandler<dim> &    dof_handler,
                         AffineConstraints<double> &constraints,
                         LevelData<dim> &           data)
  {
    constraints.clear();
    constraints.reinit(DoFTools::extract_locally_relevant_dofs(dof_handler));
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    constraints.close();
    for (const auto &line : constraints.get_lines())
      if (data.partitioner->in_local_range(line.index) ||
          data.partitioner->is_ghost_entry(line.index))
        {
          const auto h       = data.partitioner->global_to_local(line.index);
          auto &     masters = data.hanging[h];
          for (const auto &[j, w] : line.entries)
            masters.emplace_back(data.partitioner->global_to_local(j), w);
          data.role[h]                       = DoFRole::fixed;
          data.fixed_values.local_element(h) = 0.;
          data.upper_bounds.local_element(h) = std::numeric_limits<double>::infinity();
        }
  }


  template <int dim>
  bool
  eliminate_hanging_dofs_of_cell(const LevelData<dim> &                   data,
                                 std::vector<types::global_dof_index> &   dofs,
                                 const std::vector<FullMatrix<double> *> &matrices,
                                 const std::vector<Vector<double> *> &    vectors)
  {
    const unsigned int n = dofs.size();
    bool               constrained = false;
    for (unsigned int i = 0; i < n; ++i)
      constrained |= data.hanging.count(dofs[i]) > 0;
    if (!constrained)
      return false;
    std::vector<types::global_dof_index> kept;
    const auto position = [&](const types::global_dof_index dof) {
      const auto it = std::find(kept.begin(), kept.end(), dof);
      if (it != kept.end())
        return static_cast<unsigned int>(it - kept.begin());
      kept.push_back(dof);
      return static_cast<unsigned int>(kept.size() - 1);
    };
    // row i of C: (column in kept, weight)
    std::vector<std::vector<std::pair<unsigned int, double>>> C(n);
    for (unsigned int i = 0; i < n; ++i)
      if (data.hanging.count(dofs[i]) == 0)
        C[i].emplace_back(position(dofs[i]), 1.);
    for (unsigned int i = 0; i < n; ++i)
      {
        const auto h = data.hanging.find(dofs[i]);
        if (h != data.hanging.end())
          for (const auto &[master, weight] : h->second)
            C[i].emplace_back(position(master), weight);
      }
    const unsigned int m = kept.size();
    FullMatrix<double> Cm(n, m), tmp(m, m);
    for (unsigned int i = 0; i < n; ++i)
      for (const auto &[j, w] : C[i])
        Cm(i, j) += w;
    for (FullMatrix<double> *k : matrices)
      {
        tmp = 0; // (triple_product() adds)
        tmp.triple_product(*k, Cm, Cm, true, false);
        *k = tmp;
      }
    Vector<double> tmp_v(m);
    for (Vector<double> *r : vectors)
      {
        Cm.Tvmult(tmp_v, *r);
        *r = tmp_v;
      }
    dofs = kept;
    return true;
  }


  template <int dim>
  void
  set_vertex_masters(LevelData<dim> &data, const unsigned int n_vertices)
  {
    data.vertex_masters_start.clear();
    data.vertex_masters.clear();
    if (data.hanging.empty())
      return;
    std::map<types::global_dof_index, unsigned int> vertex_of;
    for (const auto &[vertex, dofs] : data.vertex_dofs)
      vertex_of[dofs[0]] = vertex;
    data.vertex_masters_start.assign(n_vertices + 1, 0);
    for (const auto &[vertex, dofs] : data.vertex_dofs)
      if (const auto h = data.hanging.find(dofs[0]); h != data.hanging.end())
        data.vertex_masters_start[vertex + 1] = h->second.size();
    for (unsigned int v = 0; v < n_vertices; ++v)
      data.vertex_masters_start[v + 1] += data.vertex_masters_start[v];
    data.vertex_masters.resize(data.vertex_masters_start.back());
    for (const auto &[vertex, dofs] : data.vertex_dofs)
      if (const auto h = data.hanging.find(dofs[0]); h != data.hanging.end())
        for (std::size_t k = 0; k < h->second.size(); ++k)
          data.vertex_masters[data.vertex_masters_start[vertex] + k] =
            vertex_of.at(h->second[k].first);
  }


  template void eliminate_hanging_dofs<2>(const DoFHandler<2> &,
                                          AffineConstraints<double> &,
                                          LevelData<2> &);
  template void eliminate_hanging_dofs<3>(const DoFHandler<3> &,
                                          AffineConstraints<double> &,
                                          LevelData<3> &);
  template void set_vertex_masters<2>(LevelData<2> &, const unsigned int);
  template void set_vertex_masters<3>(LevelData<3> &, const unsigned int);
  template bool eliminate_hanging_dofs_of_cell<2>(const LevelData<2> &,
                                                  std::vector<types::global_dof_index> &,
                                                  const std::vector<FullMatrix<double> *> &,
                                                  const std::vector<Vector<double> *> &);
  template bool eliminate_hanging_dofs_of_cell<3>(const LevelData<3> &,
                                                  std::vector<types::global_dof_index> &,
                                                  const std::vector<FullMatrix<double> *> &,
                                                  const std::vector<Vector<double> *> &);
} // namespace FoslsContact
