// The image filters a scene names, with their JSON names: the pixel filter that
// reconstructs samples and the painterly filter over the resolved image. Only enums,
// so the compiled view (core/world/view_settings.h) holds them without the document.
#pragma once

#include <array>
#include <string_view>

namespace inkray {

enum class PixelFilter { box, gaussian };
inline constexpr std::array<std::string_view, 2> kPixelFilterNames = {"box", "gaussian"};

enum class PainterlyFilter { none, kuwahara, anisotropic };
inline constexpr std::array<std::string_view, 3> kPainterlyFilterNames = {"none", "kuwahara", "anisotropic"};

}  // namespace inkray
