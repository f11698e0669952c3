#include <fosls_contact/qp/product_pattern.h>

#include <algorithm>

namespace FoslsContact
{
  ProductPattern::ProductPattern(const SparsityPattern &a,
                                 const SparsityPattern &b,
                                 const unsigned int     n_rows)
    : start(1, 0)
  {
    std::vector<unsigned int> last_row(b.n_cols(), numbers::invalid_unsigned_int);
    for (unsigned int i = 0; i < n_rows; ++i)
      {
        for (auto e = a.begin(i); e != a.end(i); ++e)
          for (auto f = b.begin(e->column()); f != b.end(e->column()); ++f)
            if (last_row[f->column()] != i)
              {
                last_row[f->column()] = i;
                columns.push_back(f->column());
              }
        std::sort(columns.begin() + start.back(), columns.end());
        start.push_back(columns.size());
      }
  }


  void
  ProductPattern::fill(SparsityPattern &pattern, const unsigned int n_columns) const
  {
    const unsigned int        n_rows = start.size() - 1;
    std::vector<unsigned int> row_lengths(n_rows);
    // (a square pattern stores the diagonal too: room for it in every row)
    for (unsigned int i = 0; i < n_rows; ++i)
      row_lengths[i] = row_length(i) + (n_rows == n_columns ? 1 : 0);
    pattern.reinit(n_rows, n_columns, row_lengths);
    for (unsigned int i = 0; i < n_rows; ++i)
      pattern.add_entries(i, columns.begin() + start[i], columns.begin() + start[i + 1], true);
    pattern.compress();
  }
} // namespace FoslsContact
