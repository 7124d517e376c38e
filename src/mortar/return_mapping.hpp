// The backward-Euler return mapping's local problem and solver live in
// integration/local_problem.hpp; this header keeps the public name.
#pragma once

#include "mortar/integration/local_problem.hpp"
