#include "models/numerics/gsl_errors_as_status.hpp"

#include <gsl/gsl_errno.h>

namespace feedflow {

GslErrorsAsStatus::GslErrorsAsStatus() : previous_(gsl_set_error_handler_off()) {}
GslErrorsAsStatus::~GslErrorsAsStatus() { gsl_set_error_handler(previous_); }

}  // namespace feedflow
