#include <coaxfit/coupling/tied_pattern.h>

#include <vector>

namespace coaxfit
{
  void
  add_tied_pattern(DynamicSparsityPattern          &dsp,
                   const SparseMatrix<double>      &K,
                   const unsigned int               offset,
                   const AffineConstraints<double> &all_tied)
  {
    // A DoF and the DoFs its tie line names.
    const auto images = [&](const unsigned int i) {
      std::vector<unsigned int> result{i};
      if (const auto *line = all_tied.get_constraint_entries(i))
        for (const auto &entry : *line)
          result.push_back(entry.first);
      return result;
    };
    for (unsigned int row = 0; row < K.m(); ++row)
      for (auto e = K.begin(row); e != K.end(row); ++e)
        for (const unsigned int r : images(offset + row))
          for (const unsigned int c : images(offset + e->column()))
            dsp.add(r, c);
  }
} // namespace coaxfit
