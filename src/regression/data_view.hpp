// SPDX-License-Identifier: MIT
// A read-only view of feature columns (column-major, one pointer per feature) over a number of rows.
#pragma once

#include <cstddef>
#include <vector>

namespace hs::regression {

struct DataView {
  std::vector<const double*> columns;   // columns[j][i] = feature j at row i
  std::size_t rows = 0;
};

/// Column-major storage of a feature matrix with its view; rows can be picked by index (folds, splits).
class ColumnData {
 public:
  ColumnData() = default;
  explicit ColumnData(std::vector<std::vector<double>> columns) : columns_(std::move(columns)) {}

  /// The rows `index` of `columns`, in that order.
  [[nodiscard]] static ColumnData pick(const std::vector<std::vector<double>>& columns,
                                       const std::vector<std::size_t>& index) {
    std::vector<std::vector<double>> out(columns.size());
    for (std::size_t j = 0; j < columns.size(); ++j) {
      out[j].reserve(index.size());
      for (std::size_t i : index) out[j].push_back(columns[j][i]);
    }
    return ColumnData(std::move(out));
  }
  [[nodiscard]] DataView view() const {
    DataView v;
    for (const auto& c : columns_) v.columns.push_back(c.data());
    v.rows = columns_.empty() ? 0 : columns_[0].size();
    return v;
  }
  [[nodiscard]] const std::vector<std::vector<double>>& columns() const { return columns_; }
  [[nodiscard]] std::size_t rows() const { return columns_.empty() ? 0 : columns_[0].size(); }

 private:
  std::vector<std::vector<double>> columns_;
};

}  // namespace hs::regression
