#pragma once
// GSL's default error handler aborts the program. While a GslErrorsAsStatus is alive, GSL
// errors are returned as status codes instead, for the caller to turn into NumericalFailure.
// The handler is process-wide: do not hold one across threads that call GSL.
namespace feedflow {

class GslErrorsAsStatus {
 public:
  GslErrorsAsStatus();
  ~GslErrorsAsStatus();
  GslErrorsAsStatus(const GslErrorsAsStatus&) = delete;
  GslErrorsAsStatus& operator=(const GslErrorsAsStatus&) = delete;

 private:
  void (*previous_)(const char*, const char*, int, int);
};

}  // namespace feedflow
