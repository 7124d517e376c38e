// What a status in SDV 21 means (docs/model.md 9, docs/abaqus.md): the law's
// failure codes are positive (mortar::failure_name), the adapters' argument
// and property codes negative.
#pragma once

#include <string>

namespace mortar::harness {

std::string status_meaning(double status);

}  // namespace mortar::harness
