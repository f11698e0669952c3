#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fosls_contact/solvers/flux_rerouting.h>
#include <fosls_contact/solvers/spd_inverse.h>

#include <algorithm>

namespace FoslsContact
{
  template <int dim>
  FluxRerouting<dim>::FluxRerouting(const MultilevelHierarchy<dim> &hierarchy,
                                    const SparsityPattern &         fine_sparsity,
                                    const bool                      enabled)
    : hierarchy(hierarchy)
    , is_enabled(enabled)
    , scale(hierarchy.finest_level() + 1)
    , imports(hierarchy.finest_level() + 1)
    , imported_entries(hierarchy.finest_level() + 1)
    , imported_values(hierarchy.finest_level() + 1)
  {
    const unsigned int finest = hierarchy.finest_level();
    for (unsigned int l = finest; l > 0; --l)
      {
        scale[l].assign(hierarchy.face_relations(l).size(), 1.);
        if (!is_enabled)
          continue;
        // the entries between the DoFs inside the coarse cells of the
        // contact faces (of the operator on fine_sparsity on the finest
        // level, on the level's coupling pattern below)
        const auto &           fine = hierarchy.level(l);
        const SparsityPattern &A    = l == finest ? fine_sparsity : fine.sparsity;
        const auto             asked = requests(l);
        imports[l].reinit(asked, A, fine.partitioner, true);
        for (const auto &[a, b] : asked)
          imported_entries[l].emplace_back(fine.partitioner->global_to_local(a),
                                           fine.partitioner->global_to_local(b));
      }
  }


  template <int dim>
  std::vector<MatrixEntryImport::Entry>
  FluxRerouting<dim>::requests(const unsigned int l) const
  {
    const auto &                          level = hierarchy.level(l);
    std::vector<MatrixEntryImport::Entry> result;
    for (const auto &face : hierarchy.face_relations(l))
      for (const auto a : face.inside)
        if (a >= level.n_owned())
          for (const auto b : face.inside)
            result.emplace_back(level.global(a), level.global(b));
    std::sort(result.begin(), result.end());
    result.erase(std::unique(result.begin(), result.end()), result.end());
    return result;
  }


  template <int dim>
  void
  FluxRerouting<dim>::import_values(const unsigned int l, const SparseMatrix<double> &A)
  {
    if (!is_enabled || l == 0)
      return;
    std::vector<double> values;
    imports[l].import(A, values);
    imported_values[l].clear();
    for (unsigned int k = 0; k < values.size(); ++k)
      imported_values[l][imported_entries[l][k]] = values[k];
  }


  template <int dim>
  double
  FluxRerouting<dim>::entry(const unsigned int            l,
                            const SparseMatrix<double> &  A,
                            const types::global_dof_index a,
                            const types::global_dof_index b) const
  {
    if (a < hierarchy.level(l).n_owned())
      return A.el(a, b);
    const auto it = imported_values[l].find({a, b});
    return it == imported_values[l].end() ? 0. : it->second;
  }


  template <int dim>
  void
  FluxRerouting<dim>::linear_columns(const unsigned int                    l,
                                     const SparseMatrix<double> &          A,
                                     const SparseMatrix<double> &          P,
                                     const std::vector<DoFRole> &          role,
                                     const std::vector<bool> &             truncated,
                                     std::vector<types::global_dof_index> &removed,
                                     std::vector<ColumnEntry> &            entries)
  {
    const auto &coarse = hierarchy.level(l - 1);
    std::fill(scale[l].begin(), scale[l].end(), 1.);
    for (const auto &face : hierarchy.face_relations(l))
      {
        if (std::any_of(face.sons.begin(), face.sons.end(), [&](const auto son) {
              return truncated[son];
            }))
          removed.push_back(coarse.global(face.coarse_dof));
        for (const auto &row : face.tangential)
          reroute_column(
            l, row.coarse_dof, row.sons, face.inside, A, P, role, truncated, removed, entries);
      }
  }


  template <int dim>
  void
  FluxRerouting<dim>::reroute(const unsigned int                    l,
                              const SparseMatrix<double> &          A,
                              const SparseMatrix<double> &          P,
                              const std::vector<DoFRole> &          role,
                              const std::vector<bool> &             truncated,
                              std::vector<types::global_dof_index> &removed,
                              std::vector<ColumnEntry> &            entries)
  {
    const auto &faces = hierarchy.face_relations(l);
    for (unsigned int k = 0; k < faces.size(); ++k)
      scale[l][k] = reroute_column(l,
                                   faces[k].coarse_dof,
                                   faces[k].sons,
                                   faces[k].inside,
                                   A,
                                   P,
                                   role,
                                   truncated,
                                   removed,
                                   entries);
  }


  template <int dim>
  double
  FluxRerouting<dim>::reroute_column(const unsigned int                          l,
                                     const types::global_dof_index               j,
                                     const std::vector<types::global_dof_index> &sons,
                                     const std::vector<types::global_dof_index> &inside,
                                     const SparseMatrix<double> &                A,
                                     const SparseMatrix<double> &                P,
                                     const std::vector<DoFRole> &                role,
                                     const std::vector<bool> &                   truncated,
                                     std::vector<types::global_dof_index> &      removed,
                                     std::vector<ColumnEntry> &                  entries) const
  {
    const auto &                         fine   = hierarchy.level(l);
    const auto &                         coarse = hierarchy.level(l - 1);
    std::vector<types::global_dof_index> free_sons;
    double                               lost = 0;
    for (const auto son : sons)
      if (truncated[son])
        lost += P.el(son, j);
      else
        free_sons.push_back(son);
    if (free_sons.size() == sons.size())
      return 1.;
    if (free_sons.empty())
      {
        // no flux can pass: the father goes (a coarse function cut at
        // all its sons would only carry divergence)
        removed.push_back(coarse.global(j));
        return 1.;
      }

    // d: the change of the column at the sons
    std::map<types::global_dof_index, double> d;
    for (const auto son : sons)
      d[son] = truncated[son] ? -P.el(son, j) : lost / free_sons.size();
    double scale = 1.;
    for (const auto son : free_sons)
      scale = std::max(scale, P.el(son, j) + d[son]);
    for (const auto &[son, value] : d)
      if (!truncated[son])
        entries.push_back({{double(fine.global(son)), double(coarse.global(j)), value}});
    correct_column(l, j, sons, inside, A, role, truncated, d, entries);
    return scale;
  }


  template <int dim>
  void
  FluxRerouting<dim>::correct_column(const unsigned int                               l,
                                     const types::global_dof_index                    j,
                                     const std::vector<types::global_dof_index> &     sons,
                                     const std::vector<types::global_dof_index> &     inside,
                                     const SparseMatrix<double> &                     A,
                                     const std::vector<DoFRole> &                     role,
                                     const std::vector<bool> &                        truncated,
                                     const std::map<types::global_dof_index, double> &d,
                                     std::vector<ColumnEntry> &entries) const
  {
    // the local correction e on the free, unbounded DoFs coupled to the
    // sons inside the coarse cell (so that the column, and the Galerkin
    // operator, stay on the coupling pattern of the coarse cells; with the
    // DoFs on the cell's other faces too, 38 to 114 entries of the coarse
    // operators fell outside it on the square, with the same iterations)
    const auto &                         fine = hierarchy.level(l);
    std::vector<types::global_dof_index> local;
    for (const auto i : inside)
      if (!truncated[i] && role[i] == DoFRole::free && d.count(i) == 0 &&
          std::any_of(sons.begin(), sons.end(), [&](const auto son) {
            return entry(l, A, son, i) != 0.;
          }))
        local.push_back(i);
    // (in the global order of the DoFs, the same on every process)
    std::sort(local.begin(), local.end(), [&](const auto a, const auto b) {
      return fine.global(a) < fine.global(b);
    });
    if (local.empty())
      return;
    const unsigned int n = local.size();
    FullMatrix<double> A_local(n, n);
    Vector<double>     rhs(n), e(n);
    for (unsigned int a = 0; a < n; ++a)
      {
        for (unsigned int b = 0; b < n; ++b)
          A_local(a, b) = entry(l, A, local[a], local[b]);
        for (const auto &[son, value] : d)
          rhs[a] -= entry(l, A, local[a], son) * value;
      }
    invert_spd(A_local);
    A_local.vmult(e, rhs);
    const double column = hierarchy.level(l - 1).global(j);
    for (unsigned int a = 0; a < n; ++a)
      entries.push_back({{double(fine.global(local[a])), column, e[a]}});
  }

  template class FluxRerouting<2>;
  template class FluxRerouting<3>;
} // namespace FoslsContact
