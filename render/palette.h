// The Okabe-Ito colours, told apart with any colour vision (demos/README.md, "What a frame shows"): the marks, the
// plots and the overlay's highlight take theirs from here.
#pragma once
#include "render/draw_list.h"

namespace impulse::render::okabe_ito {

inline constexpr Colour orange{0.90f, 0.62f, 0.00f};
inline constexpr Colour sky_blue{0.34f, 0.71f, 0.91f};
inline constexpr Colour bluish_green{0.00f, 0.62f, 0.45f};
inline constexpr Colour yellow{0.94f, 0.89f, 0.26f};
inline constexpr Colour blue{0.00f, 0.45f, 0.70f};
inline constexpr Colour vermillion{0.84f, 0.37f, 0.00f};
inline constexpr Colour reddish_purple{0.80f, 0.47f, 0.65f};

}  // namespace impulse::render::okabe_ito
