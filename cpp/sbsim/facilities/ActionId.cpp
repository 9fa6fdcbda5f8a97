#include "sbsim/facilities/ActionId.h"

namespace sbsim::facilities {

std::string ActionId::str() const { return station + ":" + std::to_string(sequence); }

}  // namespace sbsim::facilities
