#pragma once
// Loads a shipped case file through the same schema and validation as the executable.
#include <string>
#include <vector>

#include "picdem/core/params.hpp"
#include "picdem/coupling/schema.hpp"

namespace picdem::test_support {

inline core::Params load_case(const core::Comm& comm, const std::string& relative_path,
                              const std::vector<std::string>& overrides = {}) {
  return core::read_case(comm, std::string(PICDEM_SOURCE_DIR) + "/" + relative_path, overrides,
                         coupling::case_schema());
}

}  // namespace picdem::test_support
