// How the documented-commands test reads the docs and shrinks their commands: what it
// finds, what it writes in place of what, and that its tables hold nothing stale.
#include "tests/docs/command_plan.h"
#include "tests/support/file_helpers.h"

#include <gtest/gtest.h>

namespace inkray::doc_commands {
namespace {

std::vector<std::string> planned(const std::string& command) {
  const CommandPlan plan = plan_command(doc_line(1, command), "/tmp");
  EXPECT_TRUE(plan.error.empty()) << command << ": " << plan.error;
  return std::vector<std::string>(plan.words.begin() + 1, plan.words.end());
}

std::string joined_words(const std::vector<std::string>& words) {
  std::string s;
  for (const std::string& w : words) s += (s.empty() ? "" : " ") + w;
  return s;
}

TEST(DocCommands, BlocksKeepCommandsAndDropCommentsAndOutput) {
  const std::string md =
      "Text `inkray-render scenes/a.json -o x.png` and `inkray-render` alone.\n"
      "```\n"
      "build/bin/inkray-render s.json -o shot_####.png \\\n"
      "  --spp 4   # a comment\n"
      "```\n"
      "```\n"
      "$ xvfb-run -a -s \"-screen 0 1600x900x24\" build/bin/inkray x.json\n"
      "inkray-render printed this\n"
      "```\n"
      "```json\n"
      "{\"inkray\": 1}\n"
      "```\n";
  const std::vector<DocBlock> blocks = extract_blocks("docs/x.md", md);
  ASSERT_EQ(blocks.size(), 3u);
  EXPECT_EQ(blocks[0].name, "docs_x_md_1_span1");
  EXPECT_TRUE(blocks[0].inline_span);
  EXPECT_EQ(blocks[1].name, "docs_x_md_2");
  ASSERT_EQ(blocks[1].lines.size(), 1u);
  EXPECT_EQ(blocks[1].lines[0].line, 3);
  EXPECT_EQ(joined_words(blocks[1].lines[0].words),
            "build/bin/inkray-render s.json -o shot_####.png --spp 4");
  ASSERT_EQ(blocks[2].lines.size(), 1u);  // the output line is not a command
  EXPECT_TRUE(blocks[2].lines[0].inkray);
  EXPECT_EQ(blocks[2].lines[0].words[3], "-screen 0 1600x900x24");
}

TEST(DocCommands, FindsTheReadmeExamples) {
  const std::vector<DocBlock> blocks = all_documented_blocks();
  EXPECT_GT(blocks.size(), 30u);
  bool denoise = false, help = false;
  for (const DocBlock& b : blocks)
    for (const DocLine& l : b.lines) {
      denoise |= b.file == "README.md" && !b.inline_span &&
                 l.text.find("-o clean.png --time 4 --denoise") != std::string::npos;
      help |= b.file == "README.md" && b.inline_span && l.text == "inkray --help";
    }
  EXPECT_TRUE(denoise);
  EXPECT_TRUE(help);
}

TEST(DocCommandRewrites, SliceRangesStayContiguousAndRendersShrink) {
  const std::string bin = std::string(INKRAY_BINARY_DIR) + "/bin/";
  EXPECT_EQ(joined_words(planned("build/bin/inkray-render scenes/cornell.json --samples 0 512 -o a.exr")),
            "scenes/cornell.json --samples 0 8 -o a.exr --width 60 --height 60");
  EXPECT_EQ(joined_words(planned("inkray-render scenes/cornell.json --samples 512 1024 -o b.exr")),
            "scenes/cornell.json --samples 8 16 -o b.exr --width 60 --height 60");
  EXPECT_EQ(joined_words(planned("inkray-render scene.json --crop 480 0 960 270 --samples 0 256 -o t.exr")),
            "scenes/animation.json --crop 48 0 96 27 --samples 0 4 -o t.exr --width 96 --height 54");
  EXPECT_EQ(joined_words(planned("inkray-render shot.json --frames 1-240:10 -o p_####.png --width 480")),
            "tests/data/farm/anim12.json --frames 1-11:10 -o p_####.png --width 48");
  EXPECT_EQ(joined_words(planned("inkray-render scenes/mesh.json -o m.exr --time 30 --threads 8")),
            "scenes/mesh.json -o m.exr --time 2 --threads 2 --width 80 --height 60 --spp 1000000");
  EXPECT_EQ(plan_command(
                doc_line(1, "valgrind --tool=callgrind build/bin/inkray-render scenes/cornell.json --spp 16"),
                "/tmp")
                .words[0],
            bin + "inkray-render");
}

TEST(DocCommandRewrites, EveryWrittenFileIsChecked) {
  const auto outputs = [](const std::string& command) {
    return joined_words(plan_command(doc_line(1, command), "/tmp").outputs);
  };
  EXPECT_EQ(outputs("inkray-render scenes/cornell.json -o clean.png --time 4 --denoise --aov depth=z.exr"),
            "clean.png clean_raw.png z.exr");
  EXPECT_EQ(outputs("inkray-render shot.json --frames 1-240 -o out/s_####.png --aov depth=out/d_####.exr"),
            "out/s_0001.png out/s_0002.png out/d_0001.exr out/d_0002.exr");
  EXPECT_EQ(outputs("inkray-render scene.json --samples 0 64 -o p.exr --aov depth --denoise"), "p.exr");
  EXPECT_EQ(outputs("inkray-render scene.json --decide-lines d.bin"), "d.bin");
  EXPECT_EQ(outputs("inkray-render SCENE --write-scene OUT.json"), "out.json");
  EXPECT_EQ(outputs("inkray-merge image.png a.exr b.exr --aov depth=depth.exr --denoise"),
            "image.png image_raw.png depth.exr");
  EXPECT_EQ(outputs("build/bin/inkray scenes/cornell.json"), "editor_screenshot.png");
  EXPECT_EQ(outputs("inkray --help"), "");
}

TEST(DocCommandRewrites, UnmappedPlaceholdersAndUnknownLinesAreErrors) {
  EXPECT_NE(plan_command(doc_line(1, "inkray-render SCENE -o FILE"), "/tmp").error.find("`FILE`"),
            std::string::npos);
  EXPECT_NE(plan_command(doc_line(1, "inkray-merge OUT.(png|exr) a.exr"), "/tmp").error, "");
  EXPECT_NE(plan_command(doc_line(1, "sinfo"), "/tmp").error, "");
  EXPECT_EQ(plan_command(doc_line(1, "mkdir -p out"), "/tmp").error, "");
}

// A skip, placeholder or rewrite no documented command needs any more goes, so the tables
// say what the docs hold; a farm skip names what tests/farm/farm_test.sh runs instead.
TEST(DocCommands, EveryTableEntryIsUsed) {
  std::set<std::string> lines, words, programs_and_options;
  for (const DocBlock& b : all_documented_blocks())
    for (const DocLine& l : b.lines) {
      lines.insert(l.text);
      for (std::string w : l.words) {
        if (w.size() > 1 && w.front() == '[') w.erase(0, 1);
        if (w.size() > 1 && w.back() == ']' && w.find('[') == std::string::npos) w.pop_back();
        words.insert(w);
      }
      const CommandPlan plan = plan_command(l, "/tmp");
      for (const std::string& w : plan.words) programs_and_options.insert(plan.program + " " + w);
    }
  const std::string farm_test =
      testing::read_file(std::string(INKRAY_SOURCE_DIR) + "/tests/farm/farm_test.sh");
  for (const Skip& s : kSkips) {
    EXPECT_TRUE(lines.count(std::string(s.command)))
        << "kSkips: no documented command reads `" << s.command << "`";
    EXPECT_TRUE(s.covered_by.empty() || farm_test.find(s.covered_by) != std::string::npos)
        << "kSkips: `" << s.command << "` says it runs in tests/farm, whose farm_test.sh has no `"
        << s.covered_by << "`";
  }
  for (const Placeholder& p : kPlaceholders)
    EXPECT_TRUE(words.count(std::string(p.word)))
        << "kPlaceholders: no documented command uses `" << p.word << "`";
  for (const Rewrite& r : kRewrites) {
    if (r.option[0] == '#') continue;
    bool used = false;
    std::istringstream names{std::string(r.programs)};
    for (std::string name; names >> name;)
      used |= programs_and_options.count(name + " " + std::string(r.option)) > 0;
    EXPECT_TRUE(used) << "kRewrites: no documented command of " << r.programs << " has " << r.option;
  }
}

}  // namespace
}  // namespace inkray::doc_commands
