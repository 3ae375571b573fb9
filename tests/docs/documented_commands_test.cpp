// Every command README.md and docs/*.md show runs, shrunk (tests/docs/command_tables.h), in a
// folder of its own per block: it must exit 0 and write every file it names. A test per
// block, named after its file and line, so a broken example names where it is documented.
#include "tests/docs/command_plan.h"
#include "tests/support/editor_run.h"

#include <gtest/gtest.h>

#include <unistd.h>

namespace inkray::doc_commands {
namespace {

namespace fs = std::filesystem;

// The block's folder, with the repository's scenes, brushes, test data and benchmark scenes reachable
// by the relative paths the docs use; what the commands write stays in it.
class BlockFolder {
 public:
  explicit BlockFolder(const std::string& name)
      : path_(fs::temp_directory_path() / ("inkray_docs_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path_);
    fs::create_directories(path_ / "bench");
    fs::create_directories(path_ / "config");
    const fs::path source = INKRAY_SOURCE_DIR;
    fs::create_directory_symlink(source / "scenes", path_ / "scenes");
    fs::create_directory_symlink(source / "resources", path_ / "resources");
    fs::create_directory_symlink(source / "tests", path_ / "tests");
    fs::create_directory_symlink(source / "bench" / "scenes", path_ / "bench" / "scenes");
  }
  ~BlockFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  BlockFolder(const BlockFolder&) = delete;
  BlockFolder& operator=(const BlockFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string last_lines(const std::string& text, int count) {
  size_t at = text.size();
  for (int n = 0; n <= count && at != std::string::npos && at > 0; ++n) at = text.rfind('\n', at - 1);
  return at == std::string::npos ? text : text.substr(at + 1);
}

// Why a command cannot run on this machine (the test is skipped), or empty.
std::string unavailable(const CommandPlan& plan) {
  if (plan.editor) return testing::editor_unavailable();
  if (plan.farm) {
    int code = 0;
    testing::run_command("command -v sbatch", &code);
    return code == 0 ? "" : "scripts/farm needs sbatch on PATH (scripts/bootstrap installs Slurm's client)";
  }
  // The editor and the benchmarks are optional targets (INKRAY_BUILD_EDITOR, INKRAY_BUILD_BENCH).
  if ((plan.program == "inkray" || plan.program.rfind("inkray-bench", 0) == 0) && !fs::exists(plan.words[0]))
    return plan.program + " was not built";
  return {};
}

class DocumentedCommands : public ::testing::TestWithParam<DocBlock> {};

TEST_P(DocumentedCommands, RunAndWriteTheirFiles) {
  const DocBlock& block = GetParam();
  // A block whose every inkray command runs elsewhere (a cluster's, say) is skipped whole,
  // its other lines (sinfo, export ...) with it.
  std::string all_skipped;
  for (const DocLine& line : block.lines)
    if (line.inkray) {
      const std::string why = skip_reason(line.text);
      if (why.empty()) {
        all_skipped.clear();
        break;
      }
      all_skipped += "\n" + block.file + ":" + std::to_string(line.line) + ": `" + line.text + "`: " + why;
    }
  if (!all_skipped.empty()) GTEST_SKIP() << "every command is skipped:" << all_skipped;
  BlockFolder folder(block.name);
  int ran = 0;
  for (const DocLine& line : block.lines) {
    const std::string where = block.file + ":" + std::to_string(line.line) + ": `" + line.text + "`";
    const CommandPlan plan = plan_command(line, folder.path() / "config");
    if (!plan.skip.empty()) continue;
    ASSERT_TRUE(plan.error.empty()) << where << ": " << plan.error;
    if (const std::string why = unavailable(plan); !why.empty()) GTEST_SKIP() << where << ": " << why;
    ASSERT_TRUE(plan.program == "mkdir" || fs::exists(plan.words[0]))
        << where << ": no executable " << plan.words[0];
    int code = 0;
    const std::string out = testing::run_command(
        "cd " + shell_quote(folder.path().string()) + " && timeout -k 5 300 " + plan.shell, &code);
    ++ran;
    ASSERT_EQ(code, 0) << where << "\nran: " << plan.shell << "\nexit status " << code
                       << "; its output ends:\n"
                       << last_lines(out, 12);
    for (const std::string& file : plan.outputs) {
      std::error_code ec;
      const auto size = fs::file_size(folder.path() / file, ec);
      EXPECT_TRUE(!ec && size > 0) << where << "\nran: " << plan.shell << "\nexit status 0, but "
                                   << (ec ? "did not write " : "wrote an empty ") << file
                                   << "; its output ends:\n"
                                   << last_lines(out, 12);
    }
    if (::testing::Test::HasFailure()) return;  // later commands read what this one wrote
  }
  EXPECT_GT(ran, 0) << block.file << ":" << block.line << ": no command ran";
}

INSTANTIATE_TEST_SUITE_P(Docs, DocumentedCommands, ::testing::ValuesIn(all_documented_blocks()),
                         [](const ::testing::TestParamInfo<DocBlock>& block) { return block.param.name; });

}  // namespace
}  // namespace inkray::doc_commands
