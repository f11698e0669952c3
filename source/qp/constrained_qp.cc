#include <fosls_contact/qp/constrained_qp.h>

#include <cmath>
#include <limits>

namespace FoslsContact
{
  template <int dim>
  void
  ConstrainedQP::reinit(const LevelData<dim> &level)
  {
    matrix.reinit(level.sparsity);
    matrix_eq.reinit(level.sparsity);
    matrix_compl.reinit(level.sparsity);
    rhs.reinit(level.n_dofs);
    rhs_eq.reinit(level.n_dofs);
    rhs_compl.reinit(level.n_dofs);
    constant = constant_eq = 0;
    role         = level.role;
    dimension    = dim;
    fixed_values = level.fixed_values;
    upper_bounds = level.upper_bounds;
  }

  template void ConstrainedQP::reinit(const LevelData<2> &);
  template void ConstrainedQP::reinit(const LevelData<3> &);


  double
  ConstrainedQP::value(const Vector<double> &x) const
  {
    return 0.5 * matrix.matrix_norm_square(x) - rhs * x + constant;
  }


  FunctionalValue
  ConstrainedQP::parts(const Vector<double> &x) const
  {
    FunctionalValue v;
    v.total = value(x);
    v.eq    = 0.5 * matrix_eq.matrix_norm_square(x) - rhs_eq * x + constant_eq;
    v.complementarity = 0.5 * matrix_compl.matrix_norm_square(x) - rhs_compl * x;
    v.constitutive    = v.total - v.eq - v.complementarity;
    return v;
  }


  void
  ConstrainedQP::project_to_feasible(Vector<double> &x) const
  {
    for (types::global_dof_index i = 0; i < x.size(); ++i)
      if (role[i] == DoFRole::fixed)
        x[i] = fixed_values[i];
      else if (role[i] == DoFRole::bounded)
        x[i] = std::min(x[i], upper_bounds[i]);
  }


  double
  ConstrainedQP::max_violation(const Vector<double> &x) const
  {
    double v = 0;
    for (types::global_dof_index i = 0; i < x.size(); ++i)
      if (role[i] == DoFRole::fixed)
        v = std::max(v, std::abs(x[i] - fixed_values[i]));
      else if (role[i] == DoFRole::bounded)
        v = std::max(v, x[i] - upper_bounds[i]);
    return v;
  }


  unsigned int
  ConstrainedQP::n_active(const Vector<double> &x) const
  {
    unsigned int n = 0;
    for (types::global_dof_index i = 0; i < x.size(); ++i)
      if (role[i] == DoFRole::bounded && x[i] >= upper_bounds[i])
        ++n;
    return n;
  }


  KKTResidual
  ConstrainedQP::kkt_residual(const Vector<double> &x) const
  {
    // For x_i <= ub_i the multiplier is mu_i = (b - A x)_i >= 0; it must
    // vanish where the bound is not attained.
    Vector<double> g(x.size());
    matrix.vmult(g, x);
    g -= rhs;
    // relative to the size of the terms of each row, sum_j |A_ij x_j|, so
    // that the residual is meaningful also when b = 0 (pure Dirichlet data)
    double scale = rhs.linfty_norm();
    for (types::global_dof_index i = 0; i < x.size(); ++i)
      if (role[i] != DoFRole::fixed)
        {
          double row = 0;
          for (auto e = matrix.begin(i); e != matrix.end(i); ++e)
            row += std::abs(e->value() * x[e->column()]);
          scale = std::max(scale, row);
        }
    scale = std::max(scale, 1e-300);
    double       bound_scale = 1;
    for (types::global_dof_index i = 0; i < x.size(); ++i)
      if (role[i] == DoFRole::bounded)
        bound_scale = std::max(bound_scale, std::abs(upper_bounds[i]));

    KKTResidual r;
    for (types::global_dof_index i = 0; i < x.size(); ++i)
      switch (role[i])
        {
          case DoFRole::free:
            r.stationarity = std::max(r.stationarity, std::abs(g[i]));
            break;
          case DoFRole::fixed:
            r.feasibility =
              std::max(r.feasibility, std::abs(x[i] - fixed_values[i]) / bound_scale);
            break;
          case DoFRole::bounded:
            {
              const double mu = std::max(0., -g[i]);
              r.stationarity  = std::max(r.stationarity, std::max(0., g[i]));
              r.feasibility =
                std::max(r.feasibility, std::max(0., x[i] - upper_bounds[i]) / bound_scale);
              r.complementarity =
                std::max(r.complementarity,
                         mu * std::abs(upper_bounds[i] - x[i]) / bound_scale);
              break;
            }
        }
    r.stationarity /= scale;
    r.complementarity /= scale;
    return r;
  }


  double
  ConstrainedQP::energy_norm(const Vector<double> &d) const
  {
    return std::sqrt(std::max(0., matrix.matrix_norm_square(d)));
  }


  double
  ConstrainedQP::round_off_correction(const Vector<double> &x) const
  {
    double sum = 0;
    for (types::global_dof_index i = 0; i < x.size(); ++i)
      if (role[i] != DoFRole::fixed && matrix.diag_element(i) > 0)
        {
          double s = std::abs(rhs[i]);
          for (auto e = matrix.begin(i); e != matrix.end(i); ++e)
            s += std::abs(e->value() * x[e->column()]);
          sum += s * s / matrix.diag_element(i);
        }
    return std::numeric_limits<double>::epsilon() * std::sqrt(sum) *
           std::pow(double(x.size()), 1. / dimension);
  }
} // namespace FoslsContact
