#pragma once
// CSV time series (timeseries.csv, solids.csv): rank 0 writes, header row first, every row
// flushed (nothing lost on a crash), full precision (%.17g) so runs compare bitwise.
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "picdem/core/comm.hpp"

namespace picdem::io {

class CsvWriter {
 public:
  /// Collective (rank 0 opens the file; the others only check the arguments).
  /// append = false: the file is created (truncated) and the header written.
  /// append = true: an existing file is continued; its header must equal `columns` (else
  /// core::InputError); rows whose first column exceeds `keep_rows_up_to` are dropped first, so a
  /// restart from time t continues the series without duplicates. A missing file is created.
  CsvWriter(const core::Comm& comm, const std::string& path, std::vector<std::string> columns,
            bool append = false, double keep_rows_up_to = std::numeric_limits<double>::infinity());
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  /// Writes one row on rank 0 (not collective; a no-op elsewhere). The values must match the
  /// columns in number (else std::invalid_argument).
  void row(const std::vector<double>& values);

  const std::vector<std::string>& columns() const { return columns_; }

 private:
  std::string path_;
  std::vector<std::string> columns_;
  std::FILE* file_ = nullptr;
};

}  // namespace picdem::io
