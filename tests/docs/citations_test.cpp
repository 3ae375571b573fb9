// Comments and docs cite the docs by section: (docs/architecture.md, "Motion blur").
// A reader of the repository alone must be able to follow every such reference, so
// each cited file must exist and hold a heading of that name.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace inkray {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = INKRAY_SOURCE_DIR;

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string collapse_spaces(const std::string& s) {
  std::string out;
  for (const char c : s) {
    const bool space = c == ' ' || c == '\n' || c == '\t';
    if (space && (out.empty() || out.back() == ' ')) continue;
    out += space ? ' ' : c;
  }
  if (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

// The headings of a Markdown file as a citation names them: the text without code
// marks and quotes, and for "`"graph"`: a material built from nodes" also the part
// after the colon.
std::set<std::string> headings_of(const fs::path& file) {
  std::set<std::string> names;
  std::istringstream in(read_text(file));
  bool fenced = false;
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("```")) fenced = !fenced;
    if (fenced || !line.starts_with("#")) continue;
    std::string name = line.substr(line.find_first_not_of('#'));
    std::erase_if(name, [](char c) { return c == '`' || c == '"'; });
    name = collapse_spaces(name);
    names.insert(name);
    if (const size_t colon = name.find(": "); colon != std::string::npos)
      names.insert(name.substr(colon + 2));
  }
  return names;
}

// What a file says in prose: the text of its // comments, a comment's lines joined, for
// C++; everything outside code fences for Markdown.
std::string prose_of(const fs::path& file) {
  const std::string text = read_text(file);
  std::istringstream in(text);
  std::string prose;
  bool fenced = false;
  const bool markdown = file.extension() == ".md";
  for (std::string line; std::getline(in, line);) {
    if (markdown) {
      if (line.starts_with("```")) fenced = !fenced;
      prose += fenced ? "\n\n" : line + "\n";
      continue;
    }
    const size_t slash = line.find("//");
    prose += slash == std::string::npos ? std::string("\n\n") : line.substr(slash + 2) + "\n";
  }
  return prose;
}

struct Citation {
  fs::path from;
  std::string doc, section;
};

// "docs/NAME.md" or "README.md", then "SECTION" (or ("A", "B") or "A" and "B"), line
// breaks of a comment or a paragraph allowed anywhere between. A section name starts
// with a letter, a digit or a code mark, so quoted punctuation is no citation.
std::vector<Citation> citations_in(const fs::path& file) {
  static const std::regex cite(
      R"re(((?:docs/[\w-]+|README)\.md)[,:]?\s*\(?((?:"[\w`][^"\n]*(?:\n[^"\n]+)?"(?:,\s*|\s+and\s+|\s+or\s+)?)+))re");
  static const std::regex quoted(R"re("([^"]+)")re");
  std::vector<Citation> found;
  const std::string prose = prose_of(file);
  for (auto m = std::sregex_iterator(prose.begin(), prose.end(), cite); m != std::sregex_iterator(); ++m) {
    const std::string list = (*m)[2];
    for (auto q = std::sregex_iterator(list.begin(), list.end(), quoted); q != std::sregex_iterator(); ++q)
      found.push_back({file, (*m)[1], collapse_spaces((*q)[1])});
  }
  return found;
}

std::vector<fs::path> cited_from() {
  std::vector<fs::path> files{kSource / "README.md"};
  for (const char* folder : {"core", "app", "ui", "tests", "bench", "docs"})
    for (const auto& entry : fs::recursive_directory_iterator(kSource / folder)) {
      const fs::path& p = entry.path();
      if (!entry.is_regular_file() || p.string().find("/fuzz/corpus/") != std::string::npos ||
          p.string().find("/fuzz/crashes/") != std::string::npos)
        continue;
      if (p.extension() == ".h" || p.extension() == ".cpp" || p.extension() == ".md") files.push_back(p);
    }
  return files;
}

TEST(DocCitations, EveryCitedSectionExists) {
  std::map<std::string, std::set<std::string>> headings;
  size_t checked = 0;
  for (const fs::path& file : cited_from())
    for (const Citation& c : citations_in(file)) {
      const fs::path doc = kSource / c.doc;
      if (!headings.contains(c.doc))
        headings[c.doc] = fs::exists(doc) ? headings_of(doc) : std::set<std::string>{};
      ++checked;
      EXPECT_TRUE(headings[c.doc].contains(c.section))
          << fs::relative(c.from, kSource).string() << " cites " << c.doc << ", \"" << c.section
          << "\", which has no such heading";
    }
  EXPECT_GT(checked, 100u);  // the pattern still finds the house's citations
  RecordProperty("citations", int(checked));
}

TEST(DocCitations, ThePatternReadsCommentsAndParagraphs) {
  const fs::path dir = fs::temp_directory_path() / "inkray_citations_test";
  fs::create_directories(dir);
  std::ofstream(dir / "a.cpp") << "int x;  // see (docs/architecture.md,\n"
                                  "        // \"Motion\n// blur\") and docs/benchmarks.md (\"A\", \"B\")\n"
                                  "const char* s = \"docs/x.md, \\\"not a comment\\\"\";\n";
  const std::vector<Citation> c = citations_in(dir / "a.cpp");
  fs::remove_all(dir);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].doc, "docs/architecture.md");
  EXPECT_EQ(c[0].section, "Motion blur");
  EXPECT_EQ(c[1].section, "A");
  EXPECT_EQ(c[2].section, "B");
}

}  // namespace
}  // namespace inkray
