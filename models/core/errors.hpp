#pragma once
// The three kinds of failure a user can meet, each with its own exit code (see designer/).
#include <stdexcept>
#include <string>

namespace feedflow {

// Bad input: a case file, a material, a command-line value. `where` is "file:line" or
// "--set" or empty; `key` is the dotted key ("hopper.semi_angle") or empty. Exit code 2.
class InputError : public std::runtime_error {
 public:
  InputError(std::string where, std::string key, const std::string& message)
      : std::runtime_error(compose(where, key, message)),
        where_(std::move(where)),
        key_(std::move(key)) {}
  const std::string& where() const { return where_; }
  const std::string& key() const { return key_; }

 private:
  static std::string compose(const std::string& where, const std::string& key,
                             const std::string& message) {
    std::string s;
    if (!where.empty()) s += where + ": ";
    if (!key.empty()) s += key + ": ";
    return s + message;
  }
  std::string where_;
  std::string key_;
};

// A capability that this build does not have yet. Exit code 3.
class NotAvailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A computation that failed numerically (no convergence, instability, NaN). The message says
// where and what would have helped. Exit code 4.
class NumericalFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace feedflow
