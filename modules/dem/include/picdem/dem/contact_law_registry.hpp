#pragma once
// The contact laws a case file may choose with dem/contact_law. A law type declares its own
// case-file keys (under dem/) and builds the law from the validated case; a new law adds one
// line to contact_law_types() (doc/architecture.md, "Adding a contact law").
#include <functional>
#include <string>
#include <vector>

#include "picdem/core/params.hpp"
#include "picdem/dem/contact_law.hpp"

namespace picdem::dem {

struct ContactLawType {
  std::string name;  ///< the value of dem/contact_law
  std::string doc;   ///< one line for the parameter reference
  /// Declares the law's own keys (paths under dem/) on the case schema.
  std::function<void(core::ParamSchema&)> declare;
  /// The law of a validated case; `cfg` holds the DEM settings shared by all laws.
  std::function<ContactLawPtr(const core::Params&, const DemConfig& cfg)> build;
};

/// Every law, the default (the paper's) first.
const std::vector<ContactLawType>& contact_law_types();
/// The law type called `name`; core::InputError listing the known names otherwise.
const ContactLawType& contact_law_type(const std::string& name);

// The registered types, one function per law file; contact_law_registry.cpp lists them.
ContactLawType linear_spring_dashpot_type();  ///< contact_law.cpp
ContactLawType hertz_mindlin_type();          ///< hertz_mindlin.cpp

}  // namespace picdem::dem
