#include "picdem/dem/contact_law_registry.hpp"

#include "picdem/core/registry.hpp"

namespace picdem::dem {

const std::vector<ContactLawType>& contact_law_types() {
  // A new law adds one line here (doc/architecture.md, "Adding a contact law").
  static const std::vector<ContactLawType> types{linear_spring_dashpot_type(),
                                                 hertz_mindlin_type()};
  return types;
}

const ContactLawType& contact_law_type(const std::string& name) {
  return core::find_named(contact_law_types(), name, "dem/contact_law");
}

}  // namespace picdem::dem
