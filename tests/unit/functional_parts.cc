// The assembled parts of J against their integrals. FoslsAssembler sums the
// equilibrium and complementarity parts of the functional on patterns of
// the couplings their terms have (FoslsAssembler::part_patterns()), not on
// the DoF coupling pattern; an entry missing from such a pattern would be
// dropped without a word (SparseMatrix::add() of an optimized build skips
// an entry outside its pattern). For a random vector x, whose function has
// nonzero residuals everywhere, the quadratic forms of the parts
// (ConstrainedQP::parts()) must equal the integrals of their residuals,
// C_eq ||div sigma + f||^2 and C_compl <u.n - g, (sigma n).n>, summed cell
// by cell (ErrorIndicators) with the same quadrature, to round-off; so must
// the constitutive part (J minus the two), which A alone carries.
// ConstrainedQP::measure(x, d), which the solvers' monitor calls after
// every iteration, must return exactly (bit for bit) what parts(x),
// energy_norm(d) and round_off_correction(x) return, for a random d.
//
// Cases: the half disc of prm/hertz.prm (curved boundary: faces of mixed
// orientation, rotated contact faces) uniform and refined once at the
// contact zone (hanging nodes, whose masters enter the patterns); the
// manufactured solution of prm/elasticity_mms.prm (a body force); the cube
// of prm/cube3d.prm (3D, rotated faces of three rows).
#include <deal.II/base/mpi.h>

#include <fosls_contact/assembly/error_indicators.h>
#include <fosls_contact/assembly/fosls_assembler.h>
#include <fosls_contact/qp/constrained_qp.h>

#include "tests.h"

#include <random>

using namespace FoslsContactTests;

template <int dim>
void
check_parts(const std::string &name,
            const std::string &file,
            const unsigned int levels,
            const bool         refine_contact_zone)
{
  std::cout << "--- " << name << std::endl;
  const Parameters::AllParameters parameters =
    make_parameters(scene_file(file), {{"Geometry/Levels", std::to_string(levels)}});
  const Scene<dim>    scene(parameters);
  // (adaptive refinement needs the mesh on every process whole)
  Discretization<dim> discretization(scene,
                                     levels,
                                     MPI_COMM_WORLD,
                                     refine_contact_zone ?
                                       Discretization<dim>::MeshDistribution::replicated :
                                       Discretization<dim>::MeshDistribution::partitioned);
  if (refine_contact_zone)
    {
      // the cells at Gamma_C (with a marked criterion, the others 0)
      const auto &  tria = discretization.get_triangulation();
      Vector<float> criteria(tria.n_active_cells());
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f) && scene.is_contact(cell->face(f)->boundary_id()))
            criteria[cell->active_cell_index()] = 1.;
      Parameters::Adaptivity adaptivity = parameters.adaptivity;
      adaptivity.marking                = Parameters::Adaptivity::Marking::bulk;
      adaptivity.fraction               = 1.;
      adaptivity.max_dofs               = 1000000;
      check(discretization.refine(criteria, adaptivity), "refined");
      check(!discretization.level(discretization.finest_level()).hanging.empty(),
            "the refined mesh has hanging DoFs");
    }
  const unsigned int L = discretization.finest_level();
  ConstrainedQP      qp;
  qp.reinit(discretization.level(L));
  FoslsAssembler<dim>(discretization, parameters.weights).assemble(L, qp);
  check(qp.matrix_eq.n_nonzero_elements() < qp.matrix.n_nonzero_elements(),
        "the equilibrium part has fewer entries than A");

  LevelVector        x = qp.new_vector();
  std::mt19937       random(7);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  for (unsigned int i = 0; i < x.locally_owned_size(); ++i)
    x.local_element(i) = uniform(random);
  // (an eliminated hanging DoF is fixed at zero, with a unit diagonal in
  // A that is in none of the parts: its function value comes from its
  // masters)
  for (const auto &hanging : discretization.level(L).hanging)
    x.local_element(hanging.first) = 0.;
  update_ghosts(x);

  const FunctionalValue    parts = qp.parts(x);
  ErrorIndicators<dim> indicators(discretization, parameters.weights);
  indicators.compute(x);
  double eq = 0, constitutive = 0, complementarity = 0;
  for (unsigned int c = 0; c < indicators.eq.size(); ++c)
    {
      eq += indicators.eq[c];
      constitutive += indicators.constitutive[c];
      complementarity += indicators.complementarity[c];
    }
  const double scale = std::abs(parts.eq) + std::abs(parts.constitutive) +
                       std::abs(parts.complementarity);
  const auto agree = [&](const double assembled, const double integrated) {
    return std::abs(assembled - integrated) <= 1e-10 * scale;
  };
  check(scene.has_contact() == (complementarity != 0.), "a complementarity part where Gamma_C is");
  check(agree(parts.eq, eq), "equilibrium part = its integral");
  check(agree(parts.constitutive, constitutive), "constitutive part = its integral");
  check(agree(parts.complementarity, complementarity), "complementarity part = its integral");

  LevelVector d = qp.new_vector();
  for (unsigned int i = 0; i < d.locally_owned_size(); ++i)
    d.local_element(i) = uniform(random);
  const IterateMeasures m = qp.measure(x, d);
  check(m.functional.total == parts.total && m.functional.eq == parts.eq &&
          m.functional.constitutive == parts.constitutive &&
          m.functional.complementarity == parts.complementarity &&
          m.correction == qp.energy_norm(d) && m.round_off == qp.round_off_correction(x) &&
          m.correction > 0 && m.round_off > 0,
        "measure(x, d) = parts(x), energy_norm(d), round_off_correction(x) exactly");
}


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_parts<2>("half disc, uniform", "hertz.prm", 3, false);
  check_parts<2>("half disc, refined at the contact zone", "hertz.prm", 3, true);
  check_parts<2>("manufactured solution with a body force", "elasticity_mms.prm", 3, false);
  check_parts<3>("cube", "cube3d.prm", 2, false);
  return exit_code();
}
