// Lines as SVG, written by hand: a flat list of filled paths needs no library.
#include "core/image/image_io.h"
#include "core/io/atomic_file.h"
#include "core/npr/lines/stroke_outline.h"
#include "core/npr/lines/vector_lines.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>

namespace inkray {
namespace {

void append_number(std::string& out, float value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, 2);
  out.append(buffer, result.ptr);
}

void append_escaped(std::string& out, std::string_view text) {
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        // Control characters other than tab and newlines are not allowed in XML 1.0.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') c = ' ';
        out += c;
    }
  }
}

void append_base64(std::string& out, std::string_view bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  size_t i = 0;
  for (; i + 3 <= bytes.size(); i += 3) {
    const uint32_t v =
        uint32_t(uint8_t(bytes[i])) << 16 | uint32_t(uint8_t(bytes[i + 1])) << 8 | uint8_t(bytes[i + 2]);
    for (int k = 18; k >= 0; k -= 6) out += kDigits[(v >> k) & 63];
  }
  const size_t rest = bytes.size() - i;
  if (rest == 0) return;
  uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
  if (rest == 2) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
  out += kDigits[(v >> 18) & 63];
  out += kDigits[(v >> 12) & 63];
  out += rest == 2 ? kDigits[(v >> 6) & 63] : '=';
  out += '=';
}

void append_colour(std::string& out, const Color& display) {
  static constexpr char kHex[] = "0123456789abcdef";
  out += '#';
  for (int c = 0; c < 3; ++c) {
    const int byte = int(std::lround(linear_to_srgb(std::clamp(display[c], 0.f, 1.f)) * 255.f));
    out += kHex[byte >> 4];
    out += kHex[byte & 15];
  }
}

void append_shape(std::string& out, const OutlineShape& shape) {
  out += "<path d=\"";
  for (const std::vector<Vec2>& ring : shape.rings) {
    for (size_t k = 0; k < ring.size(); ++k) {
      out += k == 0 ? 'M' : 'L';
      append_number(out, ring[k].x);
      out += ' ';
      append_number(out, ring[k].y);
    }
    out += 'Z';
  }
  out += "\" fill=\"";
  append_colour(out, shape.color);
  out += '"';
  if (shape.opacity < 1.f) {
    out += " fill-opacity=\"";
    append_number(out, std::clamp(shape.opacity, 0.f, 1.f));
    out += '"';
  }
  out += "/>\n";
}

}  // namespace

bool encode_lines_svg(int width, int height, const std::vector<LineStroke>& strokes,
                      const std::vector<LineSet>& sets, const RgbImage* background, std::string* bytes,
                      std::string* error) {
  if (width <= 0 || height <= 0) {
    *error = "cannot write lines of an empty image";
    return false;
  }
  const std::string w = std::to_string(width), h = std::to_string(height);
  std::string svg =
      "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\"\n"
      "     xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\"\n"
      "     version=\"1.1\" width=\"" +
      w + "\" height=\"" + h + "\" viewBox=\"0 0 " + w + " " + h + "\">\n";
  if (background && background->width > 0 && background->height > 0) {
    std::string png, reason;
    if (!encode_image("background.png", *background, &png, &reason)) {
      *error = "cannot encode the background image: " + reason;
      return false;
    }
    svg += "<g id=\"background\" inkscape:groupmode=\"layer\" inkscape:label=\"background\">\n";
    svg += "<image x=\"0\" y=\"0\" width=\"" + w + "\" height=\"" + h +
           "\" preserveAspectRatio=\"none\" xlink:href=\"data:image/png;base64,";
    append_base64(svg, png);
    svg += "\"/>\n</g>\n";
  }
  // Strokes by set, each set's in drawing order.
  std::vector<std::vector<const LineStroke*>> by_set(sets.size());
  for (const LineStroke& stroke : strokes)
    if (stroke.set >= 0 && size_t(stroke.set) < sets.size()) by_set[size_t(stroke.set)].push_back(&stroke);
  for (size_t s = 0; s < sets.size(); ++s) {
    svg += "<g id=\"lines-" + std::to_string(s) + "\" inkscape:groupmode=\"layer\" inkscape:label=\"";
    append_escaped(svg, sets[s].name);
    svg += "\">\n";
    for (const LineStroke* stroke : by_set[s])
      for (const OutlineShape& shape : stroke_outline(*stroke)) append_shape(svg, shape);
    svg += "</g>\n";
  }
  svg += "</svg>\n";
  *bytes = std::move(svg);
  return true;
}

bool write_lines_svg(const std::filesystem::path& file, int width, int height,
                     const std::vector<LineStroke>& strokes, const std::vector<LineSet>& sets,
                     const RgbImage* background, std::string* error) {
  std::string svg;
  if (!encode_lines_svg(width, height, strokes, sets, background, &svg, error)) {
    *error = file.string() + ": " + *error;
    return false;
  }
  return write_file_atomically(file, svg, error);
}

}  // namespace inkray
