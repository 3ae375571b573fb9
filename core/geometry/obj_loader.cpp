// OBJ loading in two steps: a line check of our own, because tinyobjloader skips
// garbage silently and only warns about bad indices (then reads out of bounds), and
// tinyobjloader itself for parsing and ear-clipping triangulation.
#include "core/geometry/obj_loader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <istream>
#include <limits>
#include <map>
#include <new>
#include <streambuf>
#include <system_error>
#include <unordered_map>

namespace inkray {
namespace {

// Statements tinyobjloader reads or ignores harmlessly. Its "t" (tags) and "vw" (skin
// weights) extensions are left out: "t" sizes an allocation from the file.
constexpr std::string_view kOtherStatements[] = {
    "o",          "g",         "s",     "usemtl", "mtllib", "l",      "p",        "vp",       "cstype",
    "deg",        "bmat",      "step",  "curv",   "curv2",  "surf",   "parm",     "trim",     "hole",
    "scrv",       "sp",        "end",   "con",    "mg",     "bevel",  "c_interp", "d_interp", "lod",
    "shadow_obj", "trace_obj", "ctech", "stech",  "maplib", "usemap", "call",     "csh"};

struct Counts {
  long long positions = 0, uvs = 0, normals = 0, faces = 0;
};

// Shows a token in a message: printable, quoted, short.
std::string shown(std::string_view token) {
  std::string out = "\"";
  for (std::size_t i = 0; i < token.size() && i < 40; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f && c != '"') {
      out += static_cast<char>(c);
    } else {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      out += escaped;
    }
  }
  if (token.size() > 40) out += "...";
  return out + "\"";
}

bool parse_number(std::string_view token, double& out) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') token.remove_prefix(1);
  const auto result = std::from_chars(token.data(), token.data() + token.size(), out);
  return !token.empty() && result.ec == std::errc() && result.ptr == token.data() + token.size() &&
         std::isfinite(out) && std::fabs(out) < 0x1.ffffffp127;  // rounds to a finite float
}

// Empty when the token is a valid index into `count` elements defined so far.
std::string check_index(std::string_view token, long long count, std::string_view what) {
  std::string_view digits = token;
  if (digits.size() > 1 && digits[0] == '+') digits.remove_prefix(1);
  long long index = 0;
  const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), index);
  if (digits.empty() || result.ec != std::errc() || result.ptr != digits.data() + digits.size()) {
    return "expected an integer " + std::string(what) + " index, got " + shown(token);
  }
  if (index == 0) return std::string(what) + " index 0 is invalid (OBJ indices start at 1)";
  const long long resolved = index > 0 ? index : count + index + 1;  // -1 is the last one defined
  if (resolved < 1 || resolved > count) {
    return std::string(what) + " index " + std::to_string(index) + " is out of range (" +
           std::to_string(count) + " defined so far)";
  }
  return {};
}

// One corner of a face: "3", "3/1", "3//2" or "3/1/2".
std::string check_face_vertex(std::string_view token, const Counts& c) {
  std::string bad = "expected a face vertex like 3, 3/1, 3//2 or 3/1/2, got " + shown(token);
  const std::size_t slash1 = token.find('/');
  std::string problem = check_index(token.substr(0, slash1), c.positions, "position");
  if (slash1 == std::string_view::npos || !problem.empty()) return problem;
  const std::size_t slash2 = token.find('/', slash1 + 1);
  const std::string_view uv =
      token.substr(slash1 + 1, slash2 == std::string_view::npos ? slash2 : slash2 - slash1 - 1);
  if (slash2 == std::string_view::npos && uv.empty()) return bad;
  if (!uv.empty()) {
    problem = check_index(uv, c.uvs, "texture coordinate");
    if (!problem.empty()) return problem;
  }
  if (slash2 == std::string_view::npos) return {};
  const std::string_view normal = token.substr(slash2 + 1);
  if (normal.find('/') != std::string_view::npos) return bad;
  return check_index(normal, c.normals, "normal");
}

std::string check_numbers(const std::vector<std::string_view>& tokens, std::size_t min, std::size_t max,
                          std::string_view expected) {
  const std::size_t n = tokens.size() - 1;
  if (n < min || n > max) {
    return "expected " + std::string(expected) + " after \"" + std::string(tokens[0]) + "\", got " +
           std::to_string(n) + " values";
  }
  for (std::size_t i = 1; i < tokens.size(); ++i) {
    double x = 0.0;
    if (!parse_number(tokens[i], x)) {
      return "expected " + std::string(expected) + " after \"" + std::string(tokens[0]) + "\", got " +
             shown(tokens[i]);
    }
  }
  return {};
}

std::string check_line(const std::vector<std::string_view>& tokens, Counts& c) {
  const std::string_view keyword = tokens[0];
  std::string problem;
  if (keyword == "v") {
    problem = check_numbers(tokens, 3, 7, "3 coordinates (x y z, optionally w or r g b)");
    ++c.positions;
  } else if (keyword == "vt") {
    problem = check_numbers(tokens, 1, 3, "1 to 3 texture coordinates");
    ++c.uvs;
  } else if (keyword == "vn") {
    problem = check_numbers(tokens, 3, 3, "3 normal components");
    ++c.normals;
  } else if (keyword == "f") {
    const std::size_t n = tokens.size() - 1;
    if (n < 3) return "expected a face with at least 3 vertices, got " + std::to_string(n);
    if (n > kMaxObjFaceVertices) {
      return "a face with " + std::to_string(n) + " vertices (at most " +
             std::to_string(kMaxObjFaceVertices) + " are supported)";
    }
    for (std::size_t i = 1; i < tokens.size() && problem.empty(); ++i) {
      problem = check_face_vertex(tokens[i], c);
    }
    ++c.faces;
  } else if (std::find(std::begin(kOtherStatements), std::end(kOtherStatements), keyword) ==
             std::end(kOtherStatements)) {
    problem = "unknown statement " + shown(keyword) + " (expected v, vt, vn, f or another OBJ statement)";
  }
  return problem;
}

// Empty when every line is well formed; else "line N: <problem>".
std::string check_obj_text(std::string_view text, Counts& counts) {
  std::size_t line_number = 0;
  std::vector<std::string_view> tokens;
  for (std::size_t pos = 0; pos < text.size();) {
    // "\n", "\r\n" and a lone "\r" each end a line, as in tinyobjloader.
    std::size_t end = text.find_first_of("\r\n", pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    if (end < text.size() && text[end] == '\r' && pos < text.size() && text[pos] == '\n') ++pos;
    ++line_number;

    line = line.substr(0, line.find('#'));
    tokens.clear();
    for (std::size_t i = 0; i < line.size();) {
      const std::size_t start = line.find_first_not_of(" \t", i);
      if (start == std::string_view::npos) break;
      const std::size_t stop = std::min(line.find_first_of(" \t", start), line.size());
      tokens.push_back(line.substr(start, stop - start));
      i = stop;
    }
    if (tokens.empty()) continue;
    const std::string problem = check_line(tokens, counts);
    if (!problem.empty()) return "line " + std::to_string(line_number) + ": " + problem;
  }
  return {};
}

// Lets tinyobjloader read the caller's text without copying it.
class ViewBuffer : public std::streambuf {
 public:
  explicit ViewBuffer(std::string_view text) {
    char* begin = const_cast<char*>(text.data());  // only ever read
    setg(begin, begin, begin + text.size());
  }
};

// A mesh takes its material from the scene, so "mtllib" files are never opened.
class NoMaterials final : public tinyobj::MaterialReader {
 public:
  bool operator()(const std::string&, std::vector<tinyobj::material_t>*, std::map<std::string, int>*,
                  std::string*, std::string*) override {
    return true;
  }
};

struct CornerKey {
  int position, uv, normal;
  bool operator==(const CornerKey&) const = default;
};
struct CornerHash {
  std::size_t operator()(const CornerKey& k) const noexcept {
    std::uint64_t h = static_cast<std::uint32_t>(k.position);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.uv);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.normal);
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

// Merges tinyobjloader's shapes into one indexed mesh; empty string on success.
std::string build_mesh(const tinyobj::attrib_t& attrib, const std::vector<tinyobj::shape_t>& shapes,
                       TriangleMeshData& mesh) {
  bool all_normals = true, all_uvs = true;
  std::size_t corners = 0;
  for (const tinyobj::shape_t& shape : shapes) {
    for (const tinyobj::index_t& index : shape.mesh.indices) {
      all_normals = all_normals && index.normal_index >= 0;
      all_uvs = all_uvs && index.texcoord_index >= 0;
    }
    corners += shape.mesh.indices.size();
  }
  if (corners == 0) return "no triangles after triangulation (are all faces degenerate?)";

  std::unordered_map<CornerKey, std::uint32_t, CornerHash> vertex_of;
  mesh.indices.reserve(corners);
  for (const tinyobj::shape_t& shape : shapes) {
    for (const tinyobj::index_t& index : shape.mesh.indices) {
      const CornerKey key{index.vertex_index, all_uvs ? index.texcoord_index : -1,
                          all_normals ? index.normal_index : -1};
      const auto [it, inserted] = vertex_of.emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
      if (inserted) {
        // The line check makes these hold; a mesh must never be read out of bounds regardless.
        const auto p = static_cast<std::size_t>(key.position), t = static_cast<std::size_t>(key.uv),
                   n = static_cast<std::size_t>(key.normal);
        if (key.position < 0 || 3 * p + 2 >= attrib.vertices.size() ||
            (all_uvs && (key.uv < 0 || 2 * t + 1 >= attrib.texcoords.size())) ||
            (all_normals && (key.normal < 0 || 3 * n + 2 >= attrib.normals.size()))) {
          return "a face refers to a vertex attribute that does not exist";
        }
        if (mesh.positions.size() >= std::numeric_limits<std::uint32_t>::max()) return "too many vertices";
        const auto& v = attrib.vertices;
        mesh.positions.emplace_back(float(v[3 * p]), float(v[3 * p + 1]), float(v[3 * p + 2]));
        if (all_uvs) {
          mesh.uvs.emplace_back(float(attrib.texcoords[2 * t]), float(attrib.texcoords[2 * t + 1]));
        }
        if (all_normals) {
          const auto& vn = attrib.normals;
          mesh.normals.emplace_back(float(vn[3 * n]), float(vn[3 * n + 1]), float(vn[3 * n + 2]));
        }
      }
      mesh.indices.push_back(it->second);
    }
  }
  return {};
}

// tinyobjloader's errors end in newlines and sometimes carry a line number of their own.
std::string first_line(std::string_view message) {
  message = message.substr(0, message.find('\n'));
  return message.empty() ? "tinyobjloader could not parse the file" : std::string(message);
}

}  // namespace

std::optional<TriangleMeshData> parse_obj(std::string_view text, std::string_view file_label,
                                          std::string* error) {
  const auto fail = [&](const std::string& reason) -> std::optional<TriangleMeshData> {
    if (error) *error = std::string(file_label) + ": " + reason;
    return std::nullopt;
  };
  try {
    Counts counts;
    if (const std::string problem = check_obj_text(text, counts); !problem.empty()) return fail(problem);
    if (counts.faces == 0) return fail("no faces (expected \"f\" lines)");

    ViewBuffer buffer(text);
    std::istream stream(&buffer);
    NoMaterials no_materials;
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warnings, errors;
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &errors, &stream, &no_materials,
                          /*triangulate=*/true, /*default_vcols_fallback=*/false)) {
      return fail(first_line(errors));
    }
    TriangleMeshData mesh;
    if (const std::string problem = build_mesh(attrib, shapes, mesh); !problem.empty()) return fail(problem);
    return mesh;
  } catch (const std::bad_alloc&) {
    return fail("out of memory while reading the mesh");
  } catch (const std::exception& e) {
    return fail(std::string("cannot read the mesh: ") + e.what());
  }
}

std::optional<TriangleMeshData> load_obj(const std::filesystem::path& file, std::string* error) {
  const std::string label = file.string();
  const auto fail = [&](const std::string& reason) -> std::optional<TriangleMeshData> {
    if (error) *error = label + ": " + reason;
    return std::nullopt;
  };
  try {
    std::error_code ec;
    const auto status = std::filesystem::status(file, ec);
    if (!std::filesystem::exists(status)) return fail("cannot open the mesh: no such file");
    if (!std::filesystem::is_regular_file(status)) return fail("cannot open the mesh: not a regular file");
    std::FILE* stream = std::fopen(file.c_str(), "rb");
    if (!stream) return fail("cannot open the mesh: " + std::generic_category().message(errno));
    std::string text;
    char chunk[1 << 16];
    for (std::size_t n; (n = std::fread(chunk, 1, sizeof chunk, stream)) > 0;) text.append(chunk, n);
    const bool failed = std::ferror(stream) != 0;
    std::fclose(stream);
    if (failed) return fail("cannot read the mesh");
    return parse_obj(text, label, error);
  } catch (const std::bad_alloc&) {
    return fail("out of memory while reading the mesh");
  } catch (const std::exception& e) {
    return fail(std::string("cannot read the mesh: ") + e.what());
  }
}

}  // namespace inkray
