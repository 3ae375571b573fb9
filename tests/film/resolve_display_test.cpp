// Lines are composited in the display's space (core/film/resolve.h): a partly
// covered pixel over a light brighter than white is part line colour, not clipped
// white; a fully covered one shows the line colour at any exposure and view; the
// raw view at 0 EV is the linear compositing of radiance and line colour.
#include "core/compiler/compile_view.h"
#include "core/film/resolve.h"
#include "core/image/image_io.h"
#include "core/npr/outlines/outline_styles.h"
#include "core/render/display_encode.h"

#include <gtest/gtest.h>

#include <memory>
#include <random>

namespace inkray {
namespace {

constexpr size_t kSilhouette = size_t(LineType::silhouette);

OutlineDesc black_silhouettes() {
  OutlineDesc o;
  o.enabled = true;
  o.silhouette.color = Color(0.f);
  return o;
}

// A film of `radiance` everywhere whose pixel 0 has silhouette lines of `alpha`
// (line_opacity of its mean coverage), the others none.
std::unique_ptr<Film> film_with_line(const Color& radiance, float alpha, int width = 2) {
  auto made = std::make_unique<Film>(width, 1, AovSet{}, true);
  Film& film = *made;
  for (int x = 0; x < width; ++x) {
    film.add_sample(x, 0, 0, radiance);
    film.add_sample(x, 0, 1, radiance);
  }
  LineSample s;
  s.coverage[kSilhouette] = alpha / kLineGain;
  s.weight = s.coverage[kSilhouette];
  s.rays = 1.f;
  s.hit_rays = 1.f;
  film.add_lines(0, 0, s);
  for (int x = 1; x < width; ++x) film.add_lines(x, 0, LineSample{{}, 0.f, 0.f, Color(0.f), 1.f, 0.f});
  return made;
}

// The bug: lines mixed into the radiance of a light (20) gave 10 for a half-covered
// pixel, still white once encoded, and the light's outline was notched. Half black
// over display white is display-linear 0.5: 255 * linear_to_srgb(0.5) = 187.5, so
// 188 within one step of rounding.
TEST(ResolveDisplay, HalfCoveredLineOverAnEmitterIsHalfLineColour) {
  const auto film_ptr = film_with_line(Color(20.f), 0.5f);
  const Film& film = *film_ptr;
  const RgbImage image = resolve_final(film, compile_resolve_settings({}, black_silhouettes()));
  const std::vector<uint8_t> png = encode_srgb8(image);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(int(png[size_t(k)]), 188, 1) << "channel " << k;
    EXPECT_EQ(png[3 + size_t(k)], 255) << "the pixel without lines is the light, white";
  }
  EXPECT_EQ(image.at(1, 0), Color(20.f)) << "a pixel without lines keeps its radiance";
  // The viewport's encoding of the same image at the same display.
  const std::vector<uint8_t> shown = encode_display(image, DisplayEncoding{});
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(int(shown[size_t(k)]), 188, 1);
}

// At any exposure and view, the light stays a light: the half-covered pixel shows
// half the light's displayed value, mixed with the line colour.
TEST(ResolveDisplay, HalfCoveredLineIsHalfWayOnTheDisplayAtAnyExposure) {
  const auto film_ptr = film_with_line(Color(20.f), 0.5f);
  const Film& film = *film_ptr;
  OutlineDesc outlines = black_silhouettes();
  outlines.silhouette.color = Color(0.2f, 0.4f, 0.1f);
  for (ViewTransform t : {ViewTransform::standard, ViewTransform::filmic}) {
    for (float exposure : {-3.f, 0.f, 2.f}) {
      SCOPED_TRACE(std::string(kViewTransformNames[size_t(t)]) + " " + std::to_string(exposure));
      const DisplayEncoding display{exposure, t};
      const DisplayMapping mapping(display);
      const RgbImage image = resolve_final(film, compile_resolve_settings({}, outlines), display);
      const Color shown = mapping.to_display(image.at(0, 0));
      const Color expected = glm::mix(mapping.to_display(Color(20.f)), outlines.silhouette.color, 0.5f);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(shown[k], expected[k], 1e-5f);
    }
  }
}

TEST(ResolveDisplay, FullCoverageShowsExactlyTheLineColour) {
  OutlineDesc outlines = black_silhouettes();
  outlines.silhouette.color = Color(0.5f, 0.25f, 0.75f);
  for (const Color& radiance : {Color(0.f), Color(0.3f, 0.6f, 0.1f), Color(20.f)}) {
    const auto film_ptr = film_with_line(radiance, 1.f);
    const Film& film = *film_ptr;
    for (ViewTransform t : {ViewTransform::standard, ViewTransform::filmic, ViewTransform::raw}) {
      for (float exposure : {-2.f, 0.f, 1.5f}) {
        SCOPED_TRACE(std::string(kViewTransformNames[size_t(t)]) + " " + std::to_string(exposure));
        const DisplayEncoding display{exposure, t};
        const RgbImage image = resolve_final(film, compile_resolve_settings({}, outlines), display);
        const Color shown = DisplayMapping(display).to_display(image.at(0, 0));
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(shown[k], outlines.silhouette.color[k], 2e-6f);
      }
    }
  }
  // Standard at 0 EV, the PNG's display: the very bytes of the line colour.
  const auto film_ptr = film_with_line(Color(20.f), 1.f);
  const Film& film = *film_ptr;
  const RgbImage image = resolve_final(film, compile_resolve_settings({}, outlines));
  EXPECT_EQ(image.at(0, 0), outlines.silhouette.color);
  const RgbImage line{1, 1, {outlines.silhouette.color}};
  const std::vector<uint8_t> png = encode_srgb8(image), expected = encode_srgb8(line);
  EXPECT_TRUE(std::equal(expected.begin(), expected.end(), png.begin()));
}

// The compositing before display space: radiance and line colour mixed linearly.
Color linear_composite(const LineSample& m, const OutlineDesc& outlines, Color c) {
  const float override_share = std::clamp(m.override_weight / m.weight, 0.f, 1.f);
  const Color override_color = m.override_weight > 0.f ? m.override_color / m.override_weight : Color(0.f);
  for (int t = 0; t < kLineTypeCount; ++t) {
    const LineStyleDesc& style = line_style(outlines, LineType(t));
    const float alpha = style.opacity * line_opacity(m.coverage[size_t(t)]);
    if (alpha <= 0.f) continue;
    c = glm::mix(c, glm::mix(style.color, override_color, override_share), alpha);
  }
  return c;
}

// Raw at 0 EV maps nothing: its composite is the linear one, bit for bit, with
// several line types, override colours and radiance above 1.
TEST(ResolveDisplay, RawViewIsTheLinearComposite) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  OutlineDesc outlines = black_silhouettes();
  outlines.crease.enabled = true;
  outlines.crease.color = Color(0.8f, 0.1f, 0.1f);
  outlines.crease.opacity = 0.7f;
  outlines.silhouette.color = Color(0.1f, 0.2f, 0.9f);
  const int w = 16, h = 8;
  Film film(w, h, {}, true);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const Color radiance(4.f * unit(rng), 20.f * unit(rng), unit(rng));
      film.add_sample(x, y, 0, radiance);
      film.add_sample(x, y, 1, radiance);
      LineSample s;
      s.coverage[kSilhouette] = 0.3f * unit(rng);
      s.coverage[size_t(LineType::crease)] = x % 3 == 0 ? 0.f : 0.3f * unit(rng);
      s.weight = s.coverage[kSilhouette] + s.coverage[size_t(LineType::crease)];
      if (x % 2) {
        s.override_weight = 0.5f * s.weight;
        s.override_color = s.override_weight * Color(0.f, 1.f, 0.f);
      }
      s.rays = 1.f;
      film.add_lines(x, y, s);
    }
  }
  const RgbImage base = resolve_base(film, ResolveSettings{});
  const RgbImage raw =
      resolve_final(film, compile_resolve_settings({}, outlines), DisplayEncoding{0.f, ViewTransform::raw});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      ASSERT_EQ(raw.at(x, y), linear_composite(film.line_mean(x, y), outlines, base.at(x, y)))
          << x << "," << y;
}

// composite_lines over a cached base is resolve_final: what the viewport does on a
// display change without filtering again.
TEST(ResolveDisplay, CompositeOverTheBaseIsTheFinalImage) {
  const auto film_ptr = film_with_line(Color(3.f, 0.5f, 8.f), 0.6f, 4);
  const Film& film = *film_ptr;
  ResolveSettings settings = compile_resolve_settings({}, black_silhouettes());
  settings.painterly = PainterlyFilter::kuwahara;
  const RgbImage base = resolve_base(film, settings);
  for (const DisplayEncoding& d : {DisplayEncoding{}, DisplayEncoding{1.f, ViewTransform::filmic}}) {
    RgbImage a = base;
    composite_lines(gather_lines(film, settings), settings, d, a);
    const RgbImage b = resolve_final(film, settings, d);
    EXPECT_EQ(a.pixels, b.pixels);
  }
  EXPECT_TRUE(same_base(settings, settings));
  ResolveSettings wider = settings;
  wider.painterly_radius *= 2.f;
  EXPECT_FALSE(same_base(settings, wider));
}

}  // namespace
}  // namespace inkray
