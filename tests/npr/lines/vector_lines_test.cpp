// Lines as vector files: the SVG is well formed, a layer per line set in set order
// with each set's outlines, inside its view box; the outlines cover the pixels
// draw_strokes draws; the PDF is a PDF; and errors name the file.
#include "core/npr/lines/vector_lines.h"

#include "core/npr/lines/stroke_outline.h"
#include "core/npr/lines/stroke_raster.h"
#include "tests/npr/lines/line_fixtures.h"
#include "tests/support/file_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <map>
#include <regex>

namespace inkray {
namespace {

using namespace test;

// A small XML reader, enough for what write_lines_svg writes: elements, attributes
// in double quotes, the five entities. Fails the test on anything unbalanced.
struct Element {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::vector<Element> children;
};

std::string unescaped(const std::string& text) {
  static const std::pair<const char*, const char*> kEntities[] = {
      {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}};
  std::string out;
  for (size_t i = 0; i < text.size();) {
    bool matched = false;
    for (const auto& [entity, c] : kEntities) {
      if (text.compare(i, std::strlen(entity), entity) == 0) {
        out += c, i += std::strlen(entity), matched = true;
        break;
      }
    }
    if (!matched) {
      EXPECT_NE(text[i], '&') << "unknown entity in " << text;
      EXPECT_NE(text[i], '<') << "unescaped < in " << text;
      out += text[i++];
    }
  }
  return out;
}

Element parse_xml(const std::string& xml) {
  Element document;
  std::vector<Element*> open = {&document};
  size_t i = 0;
  while ((i = xml.find('<', i)) != std::string::npos) {
    const size_t end = xml.find('>', i);
    EXPECT_NE(end, std::string::npos);
    if (end == std::string::npos) break;
    std::string tag = xml.substr(i + 1, end - i - 1);
    i = end + 1;
    if (tag.starts_with("?")) continue;  // the XML declaration
    if (tag.starts_with("/")) {
      EXPECT_GT(open.size(), 1u) << "closing " << tag << " with nothing open";
      if (open.size() > 1) {
        EXPECT_EQ(open.back()->name, tag.substr(1));
        open.pop_back();
      }
      continue;
    }
    const bool self_closing = tag.ends_with("/");
    if (self_closing) tag.pop_back();
    Element e;
    size_t k = 0;
    while (k < tag.size() && !std::isspace(static_cast<unsigned char>(tag[k]))) e.name += tag[k++];
    // name="value" pairs, scanned by hand: libstdc++'s std::regex recurses once per
    // character of a repeat, and a path's d of thousands overflows the stack (it did under
    // AddressSanitizer, whose frames are larger).
    while (k < tag.size()) {
      while (k < tag.size() && std::isspace(static_cast<unsigned char>(tag[k]))) ++k;
      if (k == tag.size()) break;
      const size_t equals = tag.find("=\"", k);
      const size_t close = equals == std::string::npos ? equals : tag.find('"', equals + 2);
      EXPECT_NE(close, std::string::npos) << "malformed attribute in <" << tag << ">";
      if (close == std::string::npos) break;
      const std::string name = tag.substr(k, equals - k);
      EXPECT_TRUE(std::regex_match(name, std::regex("[A-Za-z_:][-A-Za-z0-9_:.]*"))) << name;
      e.attributes[name] = unescaped(tag.substr(equals + 2, close - equals - 2));
      k = close + 1;
    }
    open.back()->children.push_back(std::move(e));
    if (!self_closing) open.push_back(&open.back()->children.back());
  }
  EXPECT_EQ(open.size(), 1u) << "unclosed " << open.back()->name;
  return document;
}

using Polygon = std::vector<Vec2>;

// The rings of a path's d: M x y L x y ... Z, as write_lines_svg writes it.
std::vector<Polygon> rings_of(const std::string& d) {
  std::vector<Polygon> rings;
  std::vector<float> numbers;
  // By hand, not std::regex: see parse_xml.
  for (const char* c = d.c_str(); *c;) {
    if (*c == 'M') rings.emplace_back();
    if (*c == 'M' || *c == 'L' || *c == 'Z' || *c == ' ') {
      ++c;
      continue;
    }
    char* end = nullptr;
    numbers.push_back(std::strtof(c, &end));
    EXPECT_NE(end, c) << "not a number at " << c;
    if (end == c || rings.empty()) break;
    c = end;
    if (numbers.size() == 2) rings.back().push_back({numbers[0], numbers[1]}), numbers.clear();
  }
  return rings;
}

// Pixel centres inside the rings (even-odd), OR-ed into `mask`.
void fill_even_odd(const std::vector<Polygon>& rings, int width, int height, std::vector<bool>& mask) {
  for (int y = 0; y < height; ++y) {
    const float yc = float(y) + 0.5f;
    std::vector<float> crossings;
    for (const Polygon& ring : rings)
      for (size_t k = 0; k < ring.size(); ++k) {
        const Vec2 a = ring[k], b = ring[(k + 1) % ring.size()];
        if ((a.y <= yc) != (b.y <= yc)) crossings.push_back(a.x + (yc - a.y) * (b.x - a.x) / (b.y - a.y));
      }
    std::sort(crossings.begin(), crossings.end());
    for (size_t c = 0; c + 1 < crossings.size(); c += 2)
      for (int x = std::max(0, int(std::ceil(crossings[c] - 0.5f)));
           x < width && float(x) + 0.5f < crossings[c + 1]; ++x)
        mask[size_t(y) * size_t(width) + size_t(x)] = true;
  }
}

class VectorLines : public testing::InScratchFolder {};

// Two sets and one that selects nothing, with a name that needs escaping.
std::vector<LineSet> three_sets() {
  LineStyle ink;
  ink.color = Color(0.f);
  ink.width = 4.f;
  ink.taper_start = ink.taper_end = 0.2f;
  LineStyle red = ink;
  red.color = Color(1.f, 0.f, 0.f);
  red.opacity = 0.5f;
  return {line_set("ink & <lines> \"1\"", ink, 1u << int(LineType::silhouette)),
          line_set("creases", red, 1u << int(LineType::crease)), line_set("nothing", ink, 0u)};
}

TEST_F(VectorLines, SvgHasALayerPerSetInsideItsViewBox) {
  const int width = 200, height = 120;
  const std::vector<Chain> chains = {circle_chain(Vec2(60.f, 60.f), 40.f),
                                     straight_chain(Vec2(110.f, 20.f), Vec2(190.f, 100.f), LineType::crease),
                                     s_curve_chain(Vec2(150.f, 10.f), 25.f)};
  const std::vector<LineSet> sets = three_sets();
  const std::vector<LineStroke> strokes = stroke_chains(chains, sets, 1080);
  ASSERT_EQ(strokes.size(), 3u);
  const RgbImage background = filled_image(width, height, Color(0.5f));
  const auto file = dir / "lines.svg";
  ASSERT_TRUE(write_lines_svg(file, width, height, strokes, sets, &background, &error)) << error;
  EXPECT_EQ(dir.entries(), testing::Names{"lines.svg"});  // no temporary left
  const std::string text = testing::read_file(file);
  EXPECT_TRUE(text.starts_with("<?xml"));

  const Element document = parse_xml(text);
  ASSERT_EQ(document.children.size(), 1u);
  const Element& svg = document.children[0];
  EXPECT_EQ(svg.name, "svg");
  EXPECT_EQ(svg.attributes.at("viewBox"), "0 0 200 120");
  EXPECT_EQ(svg.attributes.at("version"), "1.1");
  ASSERT_EQ(svg.children.size(), 4u);  // the background, then a layer per set
  EXPECT_EQ(svg.children[0].attributes.at("inkscape:label"), "background");
  ASSERT_EQ(svg.children[0].children.size(), 1u);
  EXPECT_EQ(svg.children[0].children[0].name, "image");
  EXPECT_TRUE(
      svg.children[0].children[0].attributes.at("xlink:href").starts_with("data:image/png;base64,iVBOR"));

  size_t expected_paths[3] = {0, 0, 0};
  for (const LineStroke& s : strokes) expected_paths[s.set] += stroke_outline(s).size();
  EXPECT_GT(expected_paths[0], 0u);
  EXPECT_GT(expected_paths[1], 0u);
  std::vector<std::string> ids;
  static const std::regex two_decimals(R"(-?[0-9]+\.[0-9]{2})"), number(R"(-?[0-9.]+)");
  for (size_t s = 0; s < sets.size(); ++s) {
    const Element& layer = svg.children[s + 1];
    EXPECT_EQ(layer.name, "g");
    EXPECT_EQ(layer.attributes.at("inkscape:groupmode"), "layer");
    EXPECT_EQ(layer.attributes.at("inkscape:label"), sets[s].name);
    ids.push_back(layer.attributes.at("id"));
    ASSERT_EQ(layer.children.size(), expected_paths[s]) << sets[s].name;
    for (const Element& path : layer.children) {
      EXPECT_EQ(path.name, "path");
      EXPECT_TRUE(std::regex_match(path.attributes.at("fill"), std::regex("#[0-9a-f]{6}")));
      if (s == 1) {
        EXPECT_EQ(path.attributes.at("fill-opacity"), "0.50");
      }
      const std::string& d = path.attributes.at("d");
      for (std::sregex_iterator it(d.begin(), d.end(), number), done; it != done; ++it)
        EXPECT_TRUE(std::regex_match(it->str(), two_decimals)) << it->str();
      for (const Polygon& ring : rings_of(d))
        for (const Vec2& p : ring) {
          EXPECT_GE(p.x, 0.f);
          EXPECT_LE(p.x, float(width));
          EXPECT_GE(p.y, 0.f);
          EXPECT_LE(p.y, float(height));
        }
    }
  }
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(std::unique(ids.begin(), ids.end()), ids.end());
}

// Recall and precision of the SVG's outlines against draw_strokes' pixels over half.
void expect_outlines_cover_drawing(const std::vector<Chain>& chains, const LineStyle& style,
                                   const std::filesystem::path& file, const char* what) {
  const int width = 240, height = 160;
  const std::vector<LineSet> sets = {line_set("lines", style)};
  const std::vector<LineStroke> strokes = stroke_chains(chains, sets, 1080);
  RgbImage drawn = filled_image(width, height, Color(0.f));
  draw_strokes(strokes, DisplayEncoding{}, drawn);
  std::string error;
  ASSERT_TRUE(write_lines_svg(file, width, height, strokes, sets, nullptr, &error)) << error;
  const Element document = parse_xml(testing::read_file(file));
  std::vector<bool> filled(size_t(width) * size_t(height), false);
  for (const Element& path : document.children.at(0).children.at(0).children)
    fill_even_odd(rings_of(path.attributes.at("d")), width, height, filled);
  size_t both = 0, in_drawing = 0, in_outline = 0;
  for (size_t i = 0; i < filled.size(); ++i) {
    const bool d = drawn.pixels[i].r > 0.5f;
    both += d && filled[i], in_drawing += d, in_outline += filled[i];
  }
  ASSERT_GT(in_drawing, 100u) << what;
  EXPECT_GE(double(both) / double(in_drawing), 0.9) << what << ": recall";
  EXPECT_GE(double(both) / double(in_outline), 0.9) << what << ": precision";
}

TEST_F(VectorLines, OutlinesCoverWhatIsDrawn) {
  LineStyle style;
  style.color = Color(1.f);
  style.width = 5.f;
  style.taper_start = style.taper_end = 0.3f;
  style.jitter = 1.5f;
  expect_outlines_cover_drawing(
      {circle_chain(Vec2(60.f, 70.f), 45.f), s_curve_chain(Vec2(170.f, 20.f), 30.f)}, style,
      dir / "curves.svg", "tapered, jittered curves");

  LineStyle dashed;
  dashed.color = Color(1.f);
  dashed.width = 4.f;
  dashed.dash = 8.f;
  dashed.gap = 5.f;
  expect_outlines_cover_drawing(
      {circle_chain(Vec2(60.f, 70.f), 45.f), straight_chain(Vec2(120.f, 20.f), Vec2(230.f, 140.f))}, dashed,
      dir / "dashes.svg", "dashes");

  // Corners, a hairpin and a colour that changes along: joins and runs.
  LineStyle cornered;
  cornered.color = Color(1.f);
  cornered.color_end = Color(0.7f, 1.f, 0.9f);
  cornered.color_by = LineModulation::along;
  cornered.width = 8.f;
  Chain zigzag = straight_chain(Vec2(20.f, 20.f), Vec2(120.f, 20.f));
  for (const auto& [a, b] : {std::pair{Vec2(120.f, 20.f), Vec2(40.f, 60.f)},
                             {Vec2(40.f, 60.f), Vec2(200.f, 60.f)},
                             {Vec2(200.f, 60.f), Vec2(200.f, 140.f)},
                             {Vec2(200.f, 140.f), Vec2(30.f, 120.f)}}) {
    const Chain leg = straight_chain(a, b);
    zigzag.points.insert(zigzag.points.end(), leg.points.begin() + 1, leg.points.end());
  }
  expect_outlines_cover_drawing({zigzag}, cornered, dir / "corners.svg", "corners");
}

TEST_F(VectorLines, PdfIsAPageOfTheImagesSize) {
  const std::vector<LineSet> sets = three_sets();
  const std::vector<LineStroke> strokes =
      stroke_chains({circle_chain(Vec2(60.f, 60.f), 40.f),
                     straight_chain(Vec2(110.f, 20.f), Vec2(190.f, 100.f), LineType::crease)},
                    sets, 1080);
  const RgbImage background = filled_image(200, 120, Color(0.5f));
  const auto file = dir / "lines.pdf";
  ASSERT_TRUE(write_lines_pdf(file, 200, 120, strokes, &background, &error)) << error;
  EXPECT_EQ(dir.entries(), testing::Names{"lines.pdf"});
  const std::string pdf = testing::read_file(file);
  EXPECT_TRUE(pdf.starts_with("%PDF-"));
  EXPECT_NE(pdf.find("%%EOF"), std::string::npos);
  EXPECT_NE(pdf.find("/MediaBox [ 0 0 200 120 ]"), std::string::npos);
  const std::regex page(R"(/Type\s*/Page\b)");
  EXPECT_EQ(std::distance(std::sregex_iterator(pdf.begin(), pdf.end(), page), std::sregex_iterator()), 1);
  // Without a background too.
  ASSERT_TRUE(write_lines_pdf(file, 200, 120, strokes, nullptr, &error)) << error;
  EXPECT_TRUE(testing::read_file(file).starts_with("%PDF-"));
}

TEST_F(VectorLines, ErrorsNameTheFile) {
  const std::vector<LineSet> sets = three_sets();
  const std::vector<LineStroke> strokes = stroke_chains({circle_chain(Vec2(60.f), 40.f)}, sets, 1080);
  const auto missing = dir / "no such folder" / "lines.svg";
  EXPECT_FALSE(write_lines_svg(missing, 200, 120, strokes, sets, nullptr, &error));
  EXPECT_NE(error.find(missing.string()), std::string::npos) << error;
  error.clear();
  const auto missing_pdf = dir / "no such folder" / "lines.pdf";
  EXPECT_FALSE(write_lines_pdf(missing_pdf, 200, 120, strokes, nullptr, &error));
  EXPECT_NE(error.find(missing_pdf.string()), std::string::npos) << error;
  error.clear();
  EXPECT_FALSE(write_lines_svg(dir / "empty.svg", 0, 120, strokes, sets, nullptr, &error));
  EXPECT_NE(error.find("empty.svg"), std::string::npos) << error;
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace inkray
