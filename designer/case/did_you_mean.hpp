#pragma once
// Suggestions for misspelt keys and words: "semi_angel" -> "semi_angle".
#include <span>
#include <string>
#include <string_view>

namespace feedflow {

// The candidate closest to `word` by edit distance, if it is close enough to be a likely typo;
// otherwise empty.
std::string closest_match(std::string_view word, std::span<const std::string_view> candidates);

// " (did you mean \"x\"?)" or "".
std::string did_you_mean(std::string_view word, std::span<const std::string_view> candidates);

}  // namespace feedflow
