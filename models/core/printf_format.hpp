#pragma once
// printf-style text for messages, logs and plans: the whole text, however long.
#include <cstddef>
#include <cstdio>
#include <string>

namespace feedflow {

template <class... Args>
std::string format(const char* fmt, Args... args) {
  const int n = std::snprintf(nullptr, 0, fmt, args...);
  if (n <= 0) return {};
  std::string text(static_cast<std::size_t>(n) + 1, '\0');
  std::snprintf(text.data(), text.size(), fmt, args...);
  text.resize(static_cast<std::size_t>(n));
  return text;
}

}  // namespace feedflow
