#include "picdem/io/csv_writer.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "picdem/core/error.hpp"

namespace picdem::io {
namespace {

std::string join(const std::vector<std::string>& columns) {
  std::string s;
  for (std::size_t n = 0; n < columns.size(); ++n) s += (n ? "," : "") + columns[n];
  return s;
}

// Keeps the header and the rows whose first value is <= keep_rows_up_to; rewrites the file
// (through a temporary and a rename) only if rows were dropped.
void continue_file(const std::string& path, const std::string& header, double keep_rows_up_to) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream all;
  all << in.rdbuf();
  const std::string text = all.str();
  std::istringstream lines(text);
  std::string first;
  std::getline(lines, first);
  if (first != header)
    throw core::InputError("CSV file '" + path + "' has header '" + first + "', expected '" +
                           header + "' to append to it");
  std::vector<std::string> kept;
  bool dropped = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.empty()) continue;
    if (lines.eof() && text.back() != '\n') {
      dropped = true;  // a row cut short by a crash while it was written
      continue;
    }
    if (std::strtod(line.c_str(), nullptr) <= keep_rows_up_to)
      kept.push_back(line);
    else
      dropped = true;
  }
  if (!dropped) return;
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << header << '\n';
    for (const auto& l : kept) out << l << '\n';
    if (!out) throw core::InputError("cannot write CSV file '" + tmp + "'");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0)
    throw core::InputError("cannot rename '" + tmp + "' to '" + path + "'");
}

}  // namespace

CsvWriter::CsvWriter(const core::Comm& comm, const std::string& path,
                     std::vector<std::string> columns, bool append, double keep_rows_up_to)
    : path_(path), columns_(std::move(columns)) {
  if (columns_.empty()) throw std::invalid_argument("CsvWriter '" + path + "': no columns");
  for (const auto& c : columns_)
    if (c.find_first_of(",\n\"") != std::string::npos)
      throw std::invalid_argument("CsvWriter '" + path + "': column name '" + c +
                                  "' contains a comma, quote or newline");
  std::string error;
  if (comm.is_root()) {
    const std::string header = join(columns_);
    bool exists = false;
    {
      std::ifstream probe(path_);
      exists = probe.good();
    }
    try {
      if (append && exists) continue_file(path_, header, keep_rows_up_to);
      file_ = std::fopen(path_.c_str(), append && exists ? "a" : "w");
      if (!file_) throw core::InputError("cannot open CSV file '" + path_ + "' for writing");
      if (!(append && exists)) {
        std::fprintf(file_, "%s\n", header.c_str());
        std::fflush(file_);
      }
    } catch (const core::InputError& e) {
      error = e.what();
    }
  }
  // Every rank throws the same error, so that no rank is left waiting in a collective.
  error = comm.broadcast(error);
  if (!error.empty()) throw core::InputError(error);
}

CsvWriter::~CsvWriter() {
  if (file_) std::fclose(file_);
}

void CsvWriter::row(const std::vector<double>& values) {
  if (values.size() != columns_.size())
    throw std::invalid_argument("CsvWriter '" + path_ + "': row of " +
                                std::to_string(values.size()) + " values for " +
                                std::to_string(columns_.size()) + " columns");
  if (!file_) return;
  for (std::size_t n = 0; n < values.size(); ++n)
    std::fprintf(file_, n ? ",%.17g" : "%.17g", values[n]);
  std::fputc('\n', file_);
  std::fflush(file_);
}

}  // namespace picdem::io
