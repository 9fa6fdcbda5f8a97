#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/services/den/UseCase.h"

namespace sbsim::services {

/// The DEN use cases by name (short names, as Artery's without "artery.application.den.").
SBSIM_API std::vector<std::string> useCaseNames();
SBSIM_API bool isUseCase(const std::string& name);
/// Throws std::out_of_range naming the known use cases if `name` is none.
SBSIM_API std::unique_ptr<UseCase> makeUseCase(const std::string& name);

}  // namespace sbsim::services
