#pragma once
// The particles module: everything the coupled step calls.
#include "picdem/particles/motion.hpp"
#include "picdem/particles/particle_set.hpp"
#include "picdem/particles/transfer.hpp"
