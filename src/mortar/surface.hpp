// The yield surface, flow, work rates (physics/yield_surface.hpp) and the
// elasticity (physics/elasticity.hpp) of the law, for callers that want both.
#pragma once

#include "mortar/physics/elasticity.hpp"
#include "mortar/physics/yield_surface.hpp"
