#pragma once
// The three kinds of failure a user can meet, each with its own exit code (see designer/).
#include <algorithm>
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
        key_(std::move(key)),
        message_(message) {}
  const std::string& where() const { return where_; }
  const std::string& key() const { return key_; }
  // What was wrong, without the file and key (to re-throw with a place added).
  const std::string& message() const { return message_; }

 private:
  static std::string compose(const std::string& where, const std::string& key,
                             const std::string& message) {
    std::string s;
    if (!where.empty()) s += where + ": ";
    if (!key.empty()) s += key + ": ";
    return shorten(s + message);
  }
  // A value echoed back may be huge (a 100 kB string in a case file): a word over 200 characters
  // keeps its first 60 and its length, and the whole message stays under 2 000 characters.
  static std::string shorten(const std::string& text) {
    std::string s;
    std::size_t i = 0;
    while (i < text.size()) {
      const std::size_t end = std::min(text.find_first_of(" \n", i), text.size());
      if (end - i > 200)
        s += text.substr(i, 60) + "...(" + std::to_string(end - i) + " characters)";
      else
        s += text.substr(i, end - i);
      if (end < text.size()) s += text[end];
      i = end + 1;
    }
    return s.size() > 2000 ? s.substr(0, 1900) + "... (message cut)" : s;
  }
  std::string where_;
  std::string key_;
  std::string message_;
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
