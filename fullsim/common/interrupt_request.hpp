#pragma once
// Moved to models/os/interrupt_request.hpp (below every layer). This forward stays only until
// designer/simulate/ includes the new path; include models/os/interrupt_request.hpp instead.
#include "models/os/interrupt_request.hpp"
