#include <deal.II/base/memory_consumption.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_raviart_thomas.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <fosls_contact/base/collective_error.h>
#include <fosls_contact/discretization/boundary_face_conditions.h>
#include <fosls_contact/discretization/contact_entities.h>
#include <fosls_contact/discretization/discretization.h>
#include <fosls_contact/discretization/hanging_nodes.h>
#include <fosls_contact/discretization/level_dof_numbering.h>
#include <fosls_contact/discretization/refinement_marking.h>
#include <fosls_contact/discretization/refinement_transfer.h>
#include <fosls_contact/discretization/replicated_triangulation.h>

#include <algorithm>
#include <array>
#include <iomanip>
#include <set>
#include <sstream>
#include <tuple>

namespace FoslsContact
{
  namespace
  {
    /**
     * An empty mesh held as @p distribution says, with multigrid levels and
     * at most one level of difference at a vertex (distribute_mg_dofs()
     * needs it; on a replicated mesh it is also the 2:1 balance p4est
     * gives a partitioned one, so the two refine alike).
     */
    template <int dim>
    std::unique_ptr<parallel::TriangulationBase<dim>>
    make_triangulation(const typename Discretization<dim>::MeshDistribution distribution,
                       const MPI_Comm                                       comm)
    {
      const auto smoothing = Triangulation<dim>::limit_level_difference_at_vertices;
      if (distribution == Discretization<dim>::MeshDistribution::partitioned)
        return std::make_unique<parallel::distributed::Triangulation<dim>>(
          comm,
          smoothing,
          parallel::distributed::Triangulation<dim>::construct_multigrid_hierarchy);
      return std::make_unique<ReplicatedTriangulation<dim>>(comm, smoothing);
    }
  } // namespace


  template <int dim>
  Discretization<dim>::Discretization(const Scene<dim> &     scene,
                                      const unsigned int     n_levels,
                                      const MPI_Comm         comm,
                                      const MeshDistribution distribution)
    : scene(scene)
    , distribution(distribution)
    , triangulation(make_triangulation<dim>(distribution, comm))
    , fe(FE_Q<dim>(1), dim, FE_RaviartThomas<dim>(0), dim)
    , mapping(1)
  {
    {
      // the coarse mesh is built serially (on every process, identically)
      // and handed over by its description and manifolds, not by
      // copy_triangulation(): that would replace the mesh smoothing the
      // distributed mesh got above with the serial mesh's, and multigrid
      // DoFs need limit_level_difference_at_vertices (distribute_mg_dofs()
      // checks it), which a mesh cannot be given once it has cells
      Triangulation<dim> coarse;
      scene.make_coarse_mesh(coarse);
      coarse_ratio           = Scene<dim>::mesh_size_ratio(coarse);
      const auto description = GridTools::get_coarse_mesh_description(coarse);
      triangulation->create_triangulation(std::get<0>(description),
                                         std::get<1>(description),
                                         std::get<2>(description));
      for (const types::manifold_id id : coarse.get_manifold_ids())
        if (id != numbers::flat_manifold_id)
          triangulation->set_manifold(id, coarse.get_manifold(id));
    }
    triangulation->refine_global(n_levels - 1);
    scene.check_cell_shapes(*triangulation, comm);

    n_uniform = triangulation->n_global_levels();
    dof_handler.reinit(*triangulation);
    setup_dofs_and_levels();
  }


  template <int dim>
  void
  Discretization<dim>::setup_dofs_and_levels()
  {
    dof_handler.distribute_dofs(fe);
    dof_handler.distribute_mg_dofs();
    // The geometric level numbering is for the smoother's memory access
    // only (LevelDoFNumbering); deal.II 9.4 renumbers no level of a
    // parallel::shared mesh (the level is left without DoFs), so the
    // levels of a replicated mesh keep deal.II's numbering.
    if (distribution == MeshDistribution::partitioned)
      for (unsigned int l = 0; l < n_uniform; ++l)
        dof_handler.renumber_dofs(l, LevelDoFNumbering<dim>(dof_handler).level_renumbering(l));
    active_partitioner = std::make_shared<const Utilities::MPI::Partitioner>(
      dof_handler.locally_owned_dofs(),
      DoFTools::extract_locally_relevant_dofs(dof_handler),
      get_communicator());

    const bool refined = triangulation->n_global_levels() > n_uniform;
    levels.clear();
    levels.resize(n_uniform + (refined ? 1 : 0));
    for (unsigned int l = 0; l < levels.size(); ++l)
      {
        levels[l].level       = l;
        levels[l].active_mesh = l == n_uniform;
        setup_level(l);
      }
  }


  template <int dim>
  void
  Discretization<dim>::update_data()
  {
    // (a level's data is filled from empty: setup_level() appends the
    // contact vertices, faces and rotations. The levels are swapped for
    // fresh ones, not assigned: assigning a LevelData copies its vectors,
    // and deal.II 9.4 updates the ghost values of a ghosted vector whose
    // local range equals the source's, which on a process that owns no
    // DoF of the level is a collective the other processes do not join)
    std::vector<LevelData<dim>> fresh(levels.size());
    for (unsigned int l = 0; l < levels.size(); ++l)
      {
        fresh[l].level       = levels[l].level;
        fresh[l].active_mesh = levels[l].active_mesh;
      }
    levels.swap(fresh);
    for (unsigned int l = 0; l < levels.size(); ++l)
      setup_level(l);
  }


  template <int dim>
  bool
  Discretization<dim>::refine(const Vector<float> &              criteria,
                              const Parameters::Adaptivity &     adaptivity,
                              const std::vector<LevelVector *> &carried)
  {
    AssertThrow(distribution == MeshDistribution::replicated,
                ExcMessage("Discretization::refine(): the mesh is not replicated"));
    if (!mark_for_refinement(dynamic_cast<ReplicatedTriangulation<dim> &>(*triangulation),
                             criteria, adaptivity, dof_handler.n_dofs()))
      return false;
    // (every cell's values are read, the ghost cells' too, through
    // deal.II's accessors, so in deal.II's ghost state; a copy of a vector,
    // as the steps' solutions kept for the reference are, has no ghost
    // values, so they are brought up to date here)
    std::vector<RefinementTransfer<dim>> carry(carried.size());
    for (unsigned int i = 0; i < carried.size(); ++i)
      {
        carried[i]->update_ghost_values();
        carry[i].prepare(dof_handler, *carried[i]);
      }
    triangulation->execute_coarsening_and_refinement();
    setup_dofs_and_levels();
    for (unsigned int i = 0; i < carried.size(); ++i)
      carry[i].interpolate(dof_handler, mapping, active_partitioner, *carried[i]);
    return true;
  }


  template <int dim>
  void
  Discretization<dim>::refine_as(const Triangulation<dim> &target)
  {
    AssertThrow(distribution == MeshDistribution::replicated,
                ExcMessage("Discretization::refine_as(): the mesh is not replicated"));
    for (;;)
      {
        bool flagged = false;
        for (const auto &cell : triangulation->active_cell_iterators())
          if (target.create_cell_iterator(cell->id())->has_children())
            {
              cell->set_refine_flag();
              flagged = true;
            }
        if (!flagged)
          break;
        triangulation->execute_coarsening_and_refinement();
      }
    AssertThrow(triangulation->n_active_cells() == target.n_active_cells(),
                ExcMessage("Discretization::refine_as(): the mesh smoothing refined cells "
                           "that the target mesh does not"));
    setup_dofs_and_levels();
  }


  template <int dim>
  std::vector<types::global_dof_index>
  Discretization<dim>::sweep_order(const unsigned int l) const
  {
    return LevelDoFNumbering<dim>(dof_handler).sweep_order(l);
  }


  template <int dim>
  void
  Discretization<dim>::setup_level(const unsigned int l)
  {
    map_level_dofs(l);
    LevelData<dim> &data = levels[l];
    // (the data expressions are evaluated at the faces and vertices of this
    // process's cells: an error there, e.g. an obstacle normal that is zero
    // at one of them, is decided by all processes, CollectiveError)
    const MPI_Comm                                        comm = get_communicator();
    typename BoundaryFaceConditions<dim>::BoundaryData boundary;
    CollectiveError::run(comm, [&]() {
      boundary = BoundaryFaceConditions<dim>(scene, mapping, dof_handler).apply(l, data);
    });
    const ContactEntities<dim> contact(scene, *triangulation);
    contact.set_contact_vertices(data, boundary);
    if (data.active_mesh)
      eliminate_hanging_dofs(dof_handler, hanging_constraints, data);
    // The owner decides: a ghost vertex on the edge of the ghost layer may
    // miss a Dirichlet face of a cell that is not here.
    exchange_ghosts(data.partitioner, data.role);
    update_ghosts(data.fixed_values);
    update_ghosts(data.upper_bounds);
    CollectiveError::run(comm, [&]() { contact.add_rotations(data, boundary); });
    if (scene.has_friction())
      contact.add_friction_faces(data, boundary);
    set_coupling_pattern(l);
  }


  template <int dim>
  void
  Discretization<dim>::map_level_dofs(const unsigned int l)
  {
    LevelData<dim> &data = levels[l];
    if (data.active_mesh)
      {
        data.n_dofs      = dof_handler.n_dofs();
        data.partitioner = active_partitioner;
        int coarsest = triangulation->n_global_levels();
        for (const auto &cell : triangulation->active_cell_iterators())
          if (cell->is_locally_owned())
            coarsest = std::min(coarsest, cell->level());
        coarsest = Utilities::MPI::min(coarsest, get_communicator());
        data.refinement_ratio = std::pow(2., triangulation->n_global_levels() - 1 - coarsest);
      }
    else
      {
        data.n_dofs      = dof_handler.n_dofs(l);
        data.partitioner = std::make_shared<const Utilities::MPI::Partitioner>(
          dof_handler.locally_owned_mg_dofs(l),
          DoFTools::extract_locally_relevant_level_dofs(dof_handler, l),
          get_communicator());
      }
    const unsigned int n_local = data.n_local();
    data.role.assign(n_local, DoFRole::free);
    data.fixed_values.reinit(data.partitioner);
    data.upper_bounds.reinit(data.partitioner);
    // no upper bound until a contact DoF gets one; assigned, not add()ed:
    // add() takes finite numbers only (deal.II's debug build checks it)
    data.upper_bounds = std::numeric_limits<double>::infinity();
    data.rotation_of_dof.assign(n_local, numbers::invalid_unsigned_int);

    // Which DoF is which: the base element (0 = Q1^d, 1 = RT0^d), its copy
    // (displacement component or stress row) and the vertex or face, for
    // the cells with DoFs here (owned and ghost). A cell holds all DoFs of
    // its vertices and faces; the first cell at one enters it.
    using Entry = typename LevelData<dim>::DofsAt::value_type;
    typename LevelData<dim>::DofsAt::sequence_type vertices, faces;
    std::vector<bool> vertex_entered(triangulation->n_vertices(), false);
    std::vector<bool> face_entered(triangulation->n_raw_faces(), false);
    std::vector<types::global_dof_index> dofs;
    std::array<Entry, GeometryInfo<dim>::vertices_per_cell> cell_vertices;
    std::array<Entry, GeometryInfo<dim>::faces_per_cell>    cell_faces;
    data.for_each_cell(dof_handler, [&](const auto &cell) {
      data.get_local_dofs(cell, dofs);
      for (const unsigned int v : cell->vertex_indices())
        cell_vertices[v].first = cell->vertex_index(v);
      for (const unsigned int f : cell->face_indices())
        cell_faces[f].first = cell->face(f)->index();
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          const auto base = fe.system_to_base_index(i);
          if (base.first.first == 0)
            cell_vertices[base.second].second[base.first.second] = dofs[i];
          else
            cell_faces[base.second].second[base.first.second] = dofs[i];
        }
      for (const auto &entry : cell_vertices)
        if (!vertex_entered[entry.first])
          {
            vertex_entered[entry.first] = true;
            vertices.push_back(entry);
          }
      for (const auto &entry : cell_faces)
        if (!face_entered[entry.first])
          {
            face_entered[entry.first] = true;
            faces.push_back(entry);
          }
    });
    for (auto *const entries : {&vertices, &faces})
      std::sort(entries->begin(), entries->end(), [](const Entry &a, const Entry &b) {
        return a.first < b.first;
      });
    data.vertex_dofs.adopt_sequence(boost::container::ordered_unique_range, std::move(vertices));
    data.face_dofs.adopt_sequence(boost::container::ordered_unique_range, std::move(faces));
  }


  template <int dim>
  void
  Discretization<dim>::set_coupling_pattern(const unsigned int l)
  {
    // The rows held here: the owned DoFs, and the DoFs of the patches
    // this process relaxes (LevelData::relaxed_vertices: the vertex's
    // displacement, the faces at it, and at a master vertex those at its
    // hanging vertices), whose cells are all here.
    LevelData<dim> &   data       = levels[l];
    const unsigned int n_local    = data.n_local();
    const unsigned int n_owned    = data.n_owned();
    const unsigned int n_vertices = triangulation->n_vertices();
    std::vector<bool>  held(n_local, false);
    for (unsigned int i = 0; i < n_owned; ++i)
      held[i] = true;
    set_vertex_masters(data, n_vertices);
    std::vector<bool> owned_vertex(n_vertices, false);
    data.for_each_cell(dof_handler, [&](const auto &cell) {
      if (data.owns(cell))
        for (const unsigned int v : cell->vertex_indices())
          owned_vertex[cell->vertex_index(v)] = true;
    });
    data.relaxed_vertices = owned_vertex;
    if (!data.vertex_masters.empty())
      for (unsigned int vertex = 0; vertex < n_vertices; ++vertex)
        if (owned_vertex[vertex])
          for (std::size_t k = data.vertex_masters_start[vertex];
               k < data.vertex_masters_start[vertex + 1];
               ++k)
            data.relaxed_vertices[data.vertex_masters[k]] = true;
    const PatchDofsInCell<dim>           patch_dofs = patch_dofs_in_cell(fe);
    std::vector<types::global_dof_index> columns;
    data.for_each_cell(dof_handler, [&](const auto &cell) {
      data.get_local_dofs(cell, columns);
      for (const unsigned int v : cell->vertex_indices())
        data.for_patches_at(cell->vertex_index(v), [&](const unsigned int) {
          for_patch_dofs_in_cell(patch_dofs, columns, v, [&](const auto dof) { held[dof] = true; });
        });
    });
    {
      // a cell couples its DoFs, and, with hanging nodes eliminated, the
      // masters of its constrained DoFs (C^T A C), which may lie on the
      // coarse neighbour
      DynamicSparsityPattern dsp(n_local, n_local);
      data.for_each_cell(dof_handler, [&](const auto &cell) {
        // a row takes the cell's columns at once, sorted (one merge
        // instead of a search per entry)
        data.get_local_dofs(cell, columns);
        sort_with_masters(data, columns);
        for (const auto i : columns)
          if (held[i])
            dsp.add_entries(i, columns.begin(), columns.end(), true);
      });
      data.sparsity.copy_from(dsp);
    }
    std::vector<MatrixEntryImport::Entry> requests;
    for (unsigned int i = n_owned; i < n_local; ++i)
      if (held[i])
        for (auto e = data.sparsity.begin(i); e != data.sparsity.end(i); ++e)
          requests.emplace_back(data.global(i), data.global(e->column()));
    data.ghost_rows.reinit(requests, data.sparsity, data.partitioner);
  }


  template <int dim>
  void
  Discretization<dim>::apply_rotations(const unsigned int l,
                                       LevelVector &      x,
                                       const bool         inverse) const
  {
    Vector<double> in(dim), out(dim);
    for (const auto &block : levels[l].rotations)
      {
        for (unsigned int k = 0; k < dim; ++k)
          in[k] = x.local_element(block.dofs[k]);
        (inverse ? block.inverse : block.matrix).vmult(out, in);
        for (unsigned int k = 0; k < dim; ++k)
          x.local_element(block.dofs[k]) = out[k];
      }
  }


  template <int dim>
  void
  Discretization<dim>::rotate_to_cartesian(const unsigned int l, LevelVector &x) const
  {
    apply_rotations(l, x, false);
  }


  template <int dim>
  void
  Discretization<dim>::rotate_to_normal_tangential(const unsigned int l,
                                                   LevelVector &      x) const
  {
    apply_rotations(l, x, true);
  }


  template <int dim>
  LevelVector
  Discretization<dim>::to_active(const LevelVector &level_vector) const
  {
    // every owned active DoF is a DoF of an owned active cell, whose level
    // DoFs (owned or ghost) are here
    const unsigned int                   L = finest_level();
    if (levels[L].active_mesh)
      {
        // the same numbering; the eliminated DoFs from their masters
        LevelVector active(active_partitioner);
        active.copy_locally_owned_data_from(level_vector);
        hanging_constraints.distribute(active);
        active.update_ghost_values();
        return active;
      }
    const auto &                         level_partitioner = *levels[L].partitioner;
    LevelVector                          active(active_partitioner);
    std::vector<types::global_dof_index> level_dofs(fe.n_dofs_per_cell()),
      active_dofs(fe.n_dofs_per_cell());
    update_ghosts(level_vector);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const typename DoFHandler<dim>::level_cell_iterator level_cell(
            triangulation.get(), cell->level(), cell->index(), &dof_handler);
          level_cell->get_mg_dof_indices(level_dofs);
          cell->get_dof_indices(active_dofs);
          for (unsigned int i = 0; i < level_dofs.size(); ++i)
            if (active_partitioner->in_local_range(active_dofs[i]))
              active[active_dofs[i]] = level_vector.local_element(
                level_partitioner.global_to_local(level_dofs[i]));
        }
    // (kept ghosted: for FEValues and DataOut)
    active.update_ghost_values();
    return active;
  }

  template <int dim>
  std::size_t
  Discretization<dim>::mesh_memory_consumption() const
  {
    return triangulation->memory_consumption() + dof_handler.memory_consumption();
  }


  template <int dim>
  LevelBytes
  Discretization<dim>::level_memory_consumption() const
  {
    using MemoryConsumption::memory_consumption;
    LevelBytes bytes(levels.size(), 0);
    for (const LevelData<dim> &data : levels)
      {
        std::size_t &level = bytes[data.level];
        level += data.sparsity.memory_consumption() + data.role.capacity() * sizeof(DoFRole) +
                 data.fixed_values.memory_consumption() + data.upper_bounds.memory_consumption() +
                 memory_consumption(data.rotation_of_dof) +
                 (data.vertex_dofs.capacity() + data.face_dofs.capacity()) *
                   sizeof(typename LevelData<dim>::DofsAt::value_type);
        for (const RotationBlock<dim> &block : data.rotations)
          level += sizeof(block) + block.matrix.memory_consumption() +
                   block.inverse.memory_consumption();
      }
    return bytes;
  }

  template <int dim>
  void
  Discretization<dim>::release_coupling_pattern(const unsigned int l)
  {
    // (a pattern of no rows holds no arrays)
    levels[l].sparsity.reinit(0, 0, 0);
  }


  template class Discretization<2>;
  template class Discretization<3>;
} // namespace FoslsContact
