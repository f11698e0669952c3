#include <deal.II/base/mpi.h>

#include <fosls_contact/discretization/normal_tangential_basis.h>
#include <fosls_contact/output/contact_table.h>

#include <algorithm>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

namespace FoslsContact
{
  template <int dim>
  ContactTable<dim>::ContactTable(const Discretization<dim> &discretization,
                                  const FrictionTerms *      friction)
    : discretization(discretization)
    , friction(friction)
  {}


  template <int dim>
  bool
  ContactTable<dim>::in_contact(const double u_n, const double gap)
  {
    constexpr double round_off = 1e-12;
    return u_n >= gap - round_off * std::max(1., std::abs(gap));
  }


  template <int dim>
  std::map<unsigned int, typename ContactRow<dim>::Values>
  ContactTable<dim>::local_rows(const LevelVector &x) const
  {
    using Row           = ContactRow<dim>;
    const ReferenceScales &scaling = discretization.get_scene().scaling();
    const auto &level = discretization.level(discretization.finest_level());
    update_ghosts(x);
    // the displacement in Cartesian coordinates, at the vertices
    LevelVector cartesian = x;
    discretization.rotate_to_cartesian(discretization.finest_level(), cartesian);
    // sigma_nn at a vertex: mean over the contact faces that contain it
    // (all of them are here for an owned vertex; a ghost face's entry is
    // read through LocalElements)
    const LocalElements                                     x_local(x), cartesian_local(cartesian);
    std::map<unsigned int, std::pair<double, unsigned int>> face_mean;
    std::map<unsigned int, double>                          share;
    level.for_each_cell(discretization.get_dof_handler(), [&](const auto &cell) {
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f) &&
              discretization.get_scene().is_contact(cell->face(f)->boundary_id()))
            {
              const auto   face = cell->face(f);
              const double s = x_local(level.face_dofs.at(face->index())[0]);
              // (a face of a ghost cell too: all faces at an owned vertex count)
              const double part = face->measure() / face->n_vertices();
              for (const unsigned int v : face->vertex_indices())
                {
                  auto &entry = face_mean[face->vertex_index(v)];
                  entry.first += s;
                  entry.second += 1;
                  share[face->vertex_index(v)] += part;
                }
            }
    });
    std::map<unsigned int, typename Row::Values> rows;
    for (const auto &cv : level.contact_vertices)
      {
          const double un = x_local(cv.normal_dof);
          const auto   it = face_mean.find(cv.vertex_index);
          const double snn =
            it == face_mean.end() ? 0. : it->second.first / it->second.second;
          typename Row::Values row;
          for (unsigned int d = 0; d < dim; ++d)
            {
              row[Row::x + d] = scaling.length * cv.point[d];
              // (the Cartesian displacement of the owned vertices, those
              // of contact.csv; the rotation need not reach ghost entries)
              row[Row::u + d] = cv.owned ? scaling.length *
                                             cartesian_local(level.vertex_dofs.at(
                                               cv.vertex_index)[d]) :
                                           std::numeric_limits<double>::quiet_NaN();
            }
          row[Row::u_n]      = scaling.length * un;
          row[Row::gap]           = scaling.length * cv.gap;
          row[Row::remaining_gap] = scaling.length * (cv.gap - un);
          row[Row::sigma_nn]      = scaling.stress * snn;
          row[Row::in_contact]    = in_contact(un, cv.gap) ? 1 : 0;
          row[Row::share]         = std::pow(scaling.length, dim - 1) * share[cv.vertex_index];
          rows[cv.vertex_index]   = row;
        }
    if (friction != nullptr)
      add_friction(x_local, rows);
    return rows;
  }


  template <int dim>
  void
  ContactTable<dim>::add_friction(const LocalElements &                          x_local,
                                  std::map<unsigned int, typename ContactRow<dim>::Values> &rows) const
  {
    using Row                      = ContactRow<dim>;
    const ReferenceScales &scaling = discretization.get_scene().scaling();
    const auto &           level   = discretization.level(discretization.finest_level());
    const LocalElements    reference(friction->slip_references);
    // the tangential traction of each contact face (the tangential part of
    // its mean traction H y, ContactEntities::add_rotations()), summed at
    // its vertices
    std::map<unsigned int, std::pair<Tensor<1, dim>, unsigned int>> traction;
    level.for_each_cell(discretization.get_dof_handler(), [&](const auto &cell) {
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f) &&
            discretization.get_scene().is_contact(cell->face(f)->boundary_id()))
          {
            const auto face = cell->face(f);
            const auto dofs = level.face_dofs.at(face->index());
            const auto H    = NormalTangentialBasis<dim>::householder(
              discretization.get_scene().obstacle_normal(face->center()));
            Tensor<1, dim> t;
            for (unsigned int k = 1; k < dim; ++k)
              for (unsigned int d = 0; d < dim; ++d)
                t[d] += H(d, k) * x_local(dofs[k]);
            for (const unsigned int v : face->vertex_indices())
              {
                auto &entry = traction[face->vertex_index(v)];
                entry.first += t;
                entry.second += 1;
              }
          }
    });
    for (auto &[vertex, row] : rows)
      {
        const auto &   dofs = level.vertex_dofs.at(vertex);
        const auto &   R    = level.rotations[level.rotation_of_dof[dofs[0]]].matrix;
        Tensor<1, dim> slip;
        bool           slips = false;
        for (unsigned int k = 1; k < dim; ++k)
          {
            const bool   free = level.role[dofs[k]] == DoFRole::slip;
            const double d    = free ? x_local(dofs[k]) - reference(dofs[k]) : 0.;
            slips             = slips || d != 0;
            for (unsigned int c = 0; c < dim; ++c)
              slip[c] += R(c, k) * d;
          }
        const auto t = traction.find(vertex);
        for (unsigned int c = 0; c < dim; ++c)
          {
            row[Row::slip + c] = scaling.length * slip[c];
            row[Row::traction_t + c] =
              t == traction.end() ? 0. : scaling.stress * t->second.first[c] / t->second.second;
          }
        row[Row::status] = row[Row::in_contact] == 0 ? 0 : slips ? 2 : 1;
      }
  }


  template <int dim>
  std::vector<typename ContactRow<dim>::Values>
  ContactTable<dim>::rows(const LevelVector &x) const
  {
    const auto &level = discretization.level(discretization.finest_level());
    const auto  local = local_rows(x);
    std::vector<typename ContactRow<dim>::Values> rows;
    for (const auto &cv : level.contact_vertices)
      if (cv.owned)
        rows.push_back(local.at(cv.vertex_index));
    const auto all = Utilities::MPI::gather(discretization.get_communicator(), rows, 0);
    rows.clear();
    for (const auto &part : all)
      rows.insert(rows.end(), part.begin(), part.end());
    std::sort(rows.begin(), rows.end(), [](const auto &a, const auto &b) {
      return std::lexicographical_compare(a.begin(), a.begin() + dim, b.begin(), b.begin() + dim);
    });
    return rows;
  }


  template <int dim>
  std::string
  ContactTable<dim>::csv(const LevelVector &x) const
  {
    const auto         rows = this->rows(x);
    std::ostringstream out;
    if (Utilities::MPI::this_mpi_process(discretization.get_communicator()) != 0)
      return out.str();
    using Row = ContactRow<dim>;
    out << (dim == 2 ? "x,y,u_x,u_y" : "x,y,z,u_x,u_y,u_z")
        << ",u_n,gap,remaining_gap,sigma_nn,boundary_share,in_contact";
    if (friction != nullptr)
      out << (dim == 2 ? ",slip_x,slip_y,traction_t_x,traction_t_y" :
                         ",slip_x,slip_y,slip_z,traction_t_x,traction_t_y,traction_t_z")
          << ",status";
    out << '\n' << std::setprecision(10);
    for (const auto &row : rows)
      {
        for (unsigned int d = 0; d < Row::in_contact; ++d)
          out << row[d] << ',';
        out << int(row[Row::in_contact]);
        if (friction != nullptr)
          {
            for (unsigned int d = Row::slip; d < Row::status; ++d)
              out << ',' << row[d];
            out << ',' << int(row[Row::status]);
          }
        out << '\n';
      }
    return out.str();
  }


  template class ContactTable<2>;
  template class ContactTable<3>;
} // namespace FoslsContact
