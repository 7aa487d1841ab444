#pragma once
// The one style of every feedflow chart and report: font, sizes, colours.
#include <array>

namespace feedflow::style {

inline constexpr const char* kFont = "DejaVu Sans";
inline constexpr double kTitleSize = 10.5;  // pt
inline constexpr double kLabelSize = 8.5;
inline constexpr double kTickSize = 7.5;
inline constexpr double kLineWidth = 1.4;

struct Colour {
  double r, g, b;
};

// Okabe-Ito: distinguishable with common colour-vision deficiencies, and in grey print.
inline constexpr std::array<Colour, 7> kSeries{{{0.000, 0.447, 0.698},
                                                {0.835, 0.369, 0.000},
                                                {0.000, 0.620, 0.451},
                                                {0.800, 0.475, 0.655},
                                                {0.902, 0.624, 0.000},
                                                {0.337, 0.706, 0.914},
                                                {0.000, 0.000, 0.000}}};
inline constexpr Colour kText{0.10, 0.10, 0.10};
inline constexpr Colour kGrid{0.88, 0.88, 0.88};
inline constexpr Colour kAxis{0.30, 0.30, 0.30};
inline constexpr Colour kPass{0.000, 0.560, 0.300};
inline constexpr Colour kMarginal{0.850, 0.550, 0.000};
inline constexpr Colour kFail{0.800, 0.150, 0.100};
inline constexpr Colour kUnknown{0.450, 0.450, 0.450};

}  // namespace feedflow::style
