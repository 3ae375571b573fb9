// The commands README.md and docs/*.md show that call an inkray executable: fenced code
// blocks and inline `code` spans, each with its file and line, split into shell words.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <optional>
#include <ostream>
#include <regex>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace inkray::doc_commands {

// One logical line of a block: continuation lines (ending in `\`) joined, the comment
// after ` #` removed.
struct DocLine {
  int line = 0;      // where it starts in the file
  std::string text;  // trimmed, without the comment or a leading "$ "
  std::vector<std::string> words;
  bool inkray = false;  // it calls an inkray executable (after any wrapper)
};

// A fenced block or an inline span holding at least one inkray command. The commands of a
// block run in order in one folder: later ones read what earlier ones wrote.
struct DocBlock {
  std::string file;  // relative to the repository: "README.md", "docs/farm.md"
  int line = 0;      // the opening fence, or the span's line
  bool inline_span = false;
  std::vector<DocLine> lines;  // commands and the other lines the block would run
  std::string name;            // a test name: README_md_124, docs_farm_md_67_span1
};

// How GoogleTest names a block in its output: where it is documented.
inline void PrintTo(const DocBlock& block, std::ostream* out) { *out << block.file << ":" << block.line; }

inline std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return std::string(s.substr(first, s.find_last_not_of(" \t") - first + 1));
}

// Shell words: quotes group and are removed; nothing is expanded (globs are the runner's).
inline std::vector<std::string> shell_words(std::string_view line) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false;
  char quote = 0;
  for (const char c : line) {
    if (quote) {
      if (c == quote)
        quote = 0;
      else
        word += c;
    } else if (c == '\'' || c == '"') {
      quote = c, in_word = true;
    } else if (c == ' ' || c == '\t') {
      if (in_word) words.push_back(word), word.clear(), in_word = false;
    } else {
      word += c, in_word = true;
    }
  }
  if (in_word) words.push_back(word);
  return words;
}

// The line up to a `#` that starts a word outside quotes (shot_####.png is not a comment).
inline std::string strip_comment(std::string_view line) {
  char quote = 0;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '#' && (i == 0 || line[i - 1] == ' ' || line[i - 1] == '\t')) {
      return trim(line.substr(0, i));
    }
  }
  return trim(line);
}

// build/bin/inkray, inkray-render, inkray-bench-outlines, scripts/farm, ...
inline bool is_inkray_program(const std::string& word) {
  static const std::regex program(R"((build/bin/)?inkray(-[a-z0-9]+)*|scripts/[A-Za-z0-9_.-]+)");
  return std::regex_match(word, program);
}

// The index of the word naming the program, past environment assignments and the wrappers
// the docs put in front of it (valgrind and xvfb-run, with their options); nullopt if none.
inline std::optional<size_t> program_index(const std::vector<std::string>& words) {
  static const std::regex assignment(R"([A-Za-z_][A-Za-z0-9_]*=.*)");
  size_t i = 0;
  while (i < words.size() && std::regex_match(words[i], assignment)) ++i;
  if (i < words.size() && (words[i] == "valgrind" || words[i] == "xvfb-run")) {
    const bool xvfb = words[i] == "xvfb-run";
    for (++i; i < words.size() && words[i].rfind("-", 0) == 0; ++i) {
      if (xvfb && (words[i] == "-s" || words[i] == "-n" || words[i] == "-f" || words[i] == "-e")) ++i;
    }
  }
  return i < words.size() ? std::optional<size_t>(i) : std::nullopt;
}

inline bool calls_inkray(const std::vector<std::string>& words) {
  const auto at = program_index(words);
  return at && is_inkray_program(words[*at]);
}

inline DocLine doc_line(int line, const std::string& text) {
  DocLine d{line, strip_comment(text), {}, false};
  d.words = shell_words(d.text);
  d.inkray = calls_inkray(d.words);
  return d;
}

inline std::string test_name(const std::string& file, int line, int span) {
  std::string name = file + "_" + std::to_string(line) + (span ? "_span" + std::to_string(span) : "");
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

// Every block and span of one Markdown text that calls an inkray executable. In a block
// whose commands are written `$ command`, the other lines are their output.
inline std::vector<DocBlock> extract_blocks(const std::string& file, const std::string& markdown) {
  std::vector<DocBlock> blocks;
  std::vector<std::string> lines;
  std::istringstream in(markdown);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  for (size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].rfind("```", 0) == 0) {
      DocBlock block{file, int(i + 1), false, {}, test_name(file, int(i + 1), 0)};
      std::vector<std::pair<int, std::string>> body;
      for (++i; i < lines.size() && lines[i].rfind("```", 0) != 0; ++i)
        body.emplace_back(int(i + 1), lines[i]);
      const bool prompts =
          std::any_of(body.begin(), body.end(), [](const auto& b) { return b.second.rfind("$ ", 0) == 0; });
      for (size_t k = 0; k < body.size(); ++k) {
        std::string text = body[k].second;
        if (prompts && text.rfind("$ ", 0) != 0) continue;
        if (prompts) text = text.substr(2);
        const int at = body[k].first;
        while (!text.empty() && text.back() == '\\' && k + 1 < body.size())
          text.pop_back(), text += body[++k].second;
        DocLine d = doc_line(at, text);
        if (!d.text.empty()) block.lines.push_back(std::move(d));
      }
      if (std::any_of(block.lines.begin(), block.lines.end(), [](const DocLine& d) { return d.inkray; }))
        blocks.push_back(std::move(block));
      continue;
    }
    // Inline spans: one with a program and at least one argument is a whole command.
    static const std::regex span("`([^`]+)`");
    int count = 0;
    for (auto m = std::sregex_iterator(lines[i].begin(), lines[i].end(), span); m != std::sregex_iterator();
         ++m) {
      DocLine d = doc_line(int(i + 1), (*m)[1].str());
      if (!d.inkray || d.words.size() < 2) continue;
      blocks.push_back({file, int(i + 1), true, {std::move(d)}, test_name(file, int(i + 1), ++count)});
    }
  }
  return blocks;
}

// The documented files: README.md and docs/*.md, in name order.
inline std::vector<std::string> documented_files() {
  std::vector<std::string> files = {"README.md"};
  std::vector<std::string> docs;
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(INKRAY_SOURCE_DIR) / "docs"))
    if (e.path().extension() == ".md") docs.push_back("docs/" + e.path().filename().string());
  std::sort(docs.begin(), docs.end());
  files.insert(files.end(), docs.begin(), docs.end());
  return files;
}

inline std::vector<DocBlock> all_documented_blocks() {
  std::vector<DocBlock> blocks;
  for (const std::string& file : documented_files()) {
    std::ifstream in(std::filesystem::path(INKRAY_SOURCE_DIR) / file);
    std::stringstream text;
    text << in.rdbuf();
    for (DocBlock& b : extract_blocks(file, text.str())) blocks.push_back(std::move(b));
  }
  return blocks;
}

}  // namespace inkray::doc_commands
