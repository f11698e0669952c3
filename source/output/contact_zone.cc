#include <fosls_contact/output/contact_zone.h>

namespace FoslsContact
{
  template <int dim>
  ContactZone<dim>::ContactZone(const std::vector<typename ContactRow<dim>::Values> &rows)
    : n_vertices(rows.size())
  {
    using Row       = ContactRow<dim>;
    double integral = 0;
    for (const auto &row : rows)
      {
        const double pressure = -row[Row::sigma_nn];
        if (row[Row::in_contact] == 1)
          {
            zone_measure += row[Row::share];
            integral += row[Row::share] * pressure;
            ++n_in_contact;
          }
        // (the rows are sorted by position: the first of equal peaks)
        if (pressure > peak)
          {
            peak = pressure;
            for (unsigned int d = 0; d < dim; ++d)
              peak_point[d] = row[Row::x + d];
          }
      }
    mean = zone_measure > 0 ? integral / zone_measure : 0.;
  }


  template class ContactZone<2>;
  template class ContactZone<3>;
} // namespace FoslsContact
