// Viridis (van der Walt and Smith, matplotlib 2015) at eleven evenly spaced stops, for the 3D
// view's colour map and the study plot's heat map; linear RGB interpolation between them stays
// within a few levels of the full 256-entry table.
#pragma once

#include <array>

namespace maris::ui {

inline constexpr std::array<std::array<int, 3>, 11> kViridis{{{0x44, 0x01, 0x54},
                                                              {0x48, 0x24, 0x75},
                                                              {0x41, 0x44, 0x87},
                                                              {0x35, 0x5f, 0x8d},
                                                              {0x2a, 0x78, 0x8e},
                                                              {0x21, 0x91, 0x8c},
                                                              {0x22, 0xa8, 0x84},
                                                              {0x44, 0xbf, 0x70},
                                                              {0x7a, 0xd1, 0x51},
                                                              {0xbd, 0xdf, 0x26},
                                                              {0xfd, 0xe7, 0x25}}};

}  // namespace maris::ui
